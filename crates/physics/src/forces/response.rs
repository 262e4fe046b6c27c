//! How the smooth forces answer a small displacement of one particle: the columns of
//! their Jacobian, ∂a/∂x. A coupled particle struck inside a step moves off its path by
//! Δv (t − τ); to first order every particle it pulls then feels a change of acceleration
//! of that Jacobian times the displacement ([`crate::simulation`]'s coupled impacts).
//!
//! Both pair laws read F = c d / r³ on a body from a partner `d` away (r² = d² + ε²,
//! c = G m m′ − k q q′), and a spring pulls its ends together with k (L − L0) along its
//! axis; for either, moving one end by δ changes the force on the other end by M δ and
//! on itself by −M δ, with M symmetric:
//!   pair:   M = c (I / r³ − 3 d dᵀ / r⁵),
//!   spring: M = k ((1 − L0/L) I + (L0/L) u uᵀ)   (u the axis, L its length).
//! The uniform field does not depend on position; damping (a velocity's force) and
//! the surfaces' answers are not here (the caller handles a surface's support).

use glam::DVec2;

use super::pair;
use super::{ForceModel, SpringLink};
use crate::constraints::End;

impl ForceModel {
    /// Particle `k`'s partners under the pair laws, each with the law's strength c
    /// (G m m′ − k q q′, N·m²): every other interacting particle, when `k` interacts.
    fn pair_partners(&self, k: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let g = self.gravitational_constant.unwrap_or(0.0);
        let coulomb = self.coulomb_constant.unwrap_or(0.0);
        let (mk, qk) = (self.mass[k], self.charge[k]);
        let interacts = self.interacting.binary_search(&k).is_ok();
        self.interacting
            .iter()
            .filter(move |&&j| interacts && j != k)
            .map(move |&j| {
                let c = pair::pair_strength(g, coulomb, (mk, qk), (self.mass[j], self.charge[j]));
                (j, c)
            })
            .filter(|&(_, c)| c != 0.0)
    }

    /// The springs at particle `k`, each with its other end.
    pub fn spring_partners(&self, k: usize) -> impl Iterator<Item = (&SpringLink, End)> + '_ {
        self.springs_at[k].iter().filter_map(move |&index| {
            let spring = &self.springs[index as usize];
            match (spring.from, spring.to) {
                (End::Particle(a), other) if a == k => Some((spring, other)),
                (other, End::Particle(b)) if b == k => Some((spring, other)),
                _ => None,
            }
        })
    }

    /// Whether a spring turns its ends within a step of `h` by more than (ω h)² = 1e-2,
    /// ω² = k (1/m₁ + 1/m₂): there the motion between the step's ends is too far from a
    /// short series for an impact's answer (`simulation/coupled/response.rs`).
    pub fn has_stiff_springs(&self, h: f64) -> bool {
        let inverse_mass = |end: End| match end {
            End::Particle(i) => self.inverse_mass[i],
            End::Point(_) => 0.0,
        };
        self.springs.iter().any(|spring| {
            spring.stiffness * (inverse_mass(spring.from) + inverse_mass(spring.to)) * h * h > 1e-2
        })
    }

    /// Particle `k`'s acceleration, m/s², at positions `x` and velocities `v`: what
    /// [`Self::accelerations`] gives it (to rounding), from one pass over its partners.
    /// The pair laws are summed directly (a tree's sum differs by its approximation).
    pub fn acceleration_of(&self, x: &[DVec2], v: &[DVec2], k: usize) -> DVec2 {
        let mut a = self.free_acceleration_of(x, v, k);
        for contact in self.surface_contacts.iter().filter(|c| c.particle == k) {
            contact.apply(&mut a);
        }
        a
    }

    /// [`Self::acceleration_of`] without the surfaces' answer: what the fields, the pair
    /// laws and the springs alone give particle `k`.
    pub fn free_acceleration_of(&self, x: &[DVec2], v: &[DVec2], k: usize) -> DVec2 {
        let pairs = self.pair_partners(k).fold(DVec2::ZERO, |force, (j, c)| {
            force + pair::force(x[j] - x[k], c, self.softening2)
        });
        let springs = self
            .spring_partners(k)
            .fold(DVec2::ZERO, |force, (spring, _)| {
                let f = spring.force_on_from(x, v);
                match spring.from {
                    End::Particle(i) if i == k => force + f,
                    _ => force - f,
                }
            });
        super::uniform::acceleration(self.uniform[k]) + (pairs + springs) * self.inverse_mass[k]
    }

    /// Adds to `out` the change of every particle's acceleration, m/s², when particle `k`
    /// alone moves by `delta` from positions `x`, to first order in `delta`: the pair laws
    /// (summed directly, also when a tree sums their forces: the tree approximates this
    /// sum) and the springs' elastic forces.
    pub fn displacement_response(&self, x: &[DVec2], k: usize, delta: DVec2, out: &mut [DVec2]) {
        let mut own = DVec2::ZERO;
        for (j, c) in self.pair_partners(k) {
            let change = pair_matrix(x[j] - x[k], self.softening2, delta) * c;
            out[j] += change * self.inverse_mass[j];
            own -= change;
        }
        for (spring, other) in self.spring_partners(k) {
            let change = spring_matrix(spring, x, delta);
            if let End::Particle(o) = other {
                out[o] += change * self.inverse_mass[o];
            }
            own -= change;
        }
        out[k] += own * self.inverse_mass[k];
    }

    /// The rate of change of particle `k`'s acceleration, m/s³, at positions `x` moving
    /// at velocities `v`: its row of the Jacobian times the velocities (each pair's and
    /// spring's M times the partner's velocity relative to `k`'s), for the same laws.
    pub fn acceleration_rate(&self, x: &[DVec2], v: &[DVec2], k: usize) -> DVec2 {
        let pairs = self.pair_partners(k).fold(DVec2::ZERO, |rate, (j, c)| {
            rate + pair_matrix(x[j] - x[k], self.softening2, v[j] - v[k]) * c
        });
        let springs = self
            .spring_partners(k)
            .fold(DVec2::ZERO, |rate, (spring, other)| {
                rate + spring_matrix(spring, x, other.velocity(v) - v[k])
            });
        (pairs + springs) * self.inverse_mass[k]
    }

    /// Adds to `out` the change of every particle's acceleration, m/s², when particle `k`
    /// alone moves by `delta` from positions `x`, exactly (the difference of the forces,
    /// not their derivative): the same laws as [`Self::displacement_response`].
    pub fn displacement_change(&self, x: &[DVec2], k: usize, delta: DVec2, out: &mut [DVec2]) {
        let mut own = DVec2::ZERO;
        let moved = x[k] + delta;
        let law = |d: DVec2| pair::per_unit_strength(d, self.softening2);
        for (j, c) in self.pair_partners(k) {
            // The force on k from j is c d / r³ with d = x_j − x_k; on j, its opposite.
            let change = (law(x[j] - moved) - law(x[j] - x[k])) * c;
            out[j] -= change * self.inverse_mass[j];
            own += change;
        }
        for (spring, other) in self.spring_partners(k) {
            // The pull on k towards its other end when stretched, k (1 − L0/L) d.
            let pull = |from: DVec2| {
                let d = other.position(x) - from;
                let length = d.length();
                if length > 0.0 {
                    d * (spring.stiffness * (1.0 - spring.natural_length / length))
                } else {
                    DVec2::ZERO
                }
            };
            let change = pull(moved) - pull(x[k]);
            if let End::Particle(o) = other {
                out[o] -= change * self.inverse_mass[o];
            }
            own += change;
        }
        out[k] += own * self.inverse_mass[k];
    }
}

/// A pair law's M w for a partner `d` away (M = I/r³ − 3 d dᵀ/r⁵, r² = d² + ε²), per
/// unit strength.
fn pair_matrix(d: DVec2, softening2: f64, w: DVec2) -> DVec2 {
    let plain = pulp::Scalar::new();
    let r2 = pair::softened_square(plain, d.x, d.y, softening2);
    (w - d * (3.0 * d.dot(w) / r2)) / pair::cube(plain, r2)
}

/// A spring's M w at positions `x` (M = k ((1 − L0/L) I + (L0/L) u uᵀ)).
fn spring_matrix(spring: &SpringLink, x: &[DVec2], w: DVec2) -> DVec2 {
    let d = spring.to.position(x) - spring.from.position(x);
    let length = d.length();
    if length > 0.0 {
        let axis = d / length;
        let ratio = spring.natural_length / length;
        (w * (1.0 - ratio) + axis * (ratio * axis.dot(w))) * spring.stiffness
    } else if spring.natural_length == 0.0 {
        w * spring.stiffness
    } else {
        // Ends at one point with a natural length: the force has no direction there,
        // and no derivative either.
        DVec2::ZERO
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A model of `n` bodies with masses and charges of both signs, gravitation and
    /// electrostatics on (softened), three springs (one to a fixed point, one of zero
    /// natural length) and one fixed body.
    fn model(n: usize, uniform: &mut impl FnMut() -> f64) -> (ForceModel, Vec<DVec2>) {
        let mass: Vec<f64> = (0..n).map(|_| 0.5 + uniform() * 2.0).collect();
        let mut inverse_mass: Vec<f64> = mass.iter().map(|m| 1.0 / m).collect();
        inverse_mass[3] = 0.0;
        let charge: Vec<f64> = (0..n)
            .map(|i| if i % 3 == 0 { 0.0 } else { uniform() - 0.5 })
            .collect();
        let x: Vec<DVec2> = (0..n)
            .map(|_| DVec2::new(uniform(), uniform()) * 4.0)
            .collect();
        let spring = |from, to, natural_length| SpringLink {
            from,
            to,
            stiffness: 30.0,
            natural_length,
            damping: 0.0,
        };
        let springs = vec![
            spring(End::Particle(0), End::Particle(1), 0.8),
            spring(End::Point(DVec2::new(1.0, 1.0)), End::Particle(0), 0.3),
            spring(End::Particle(2), End::Particle(5), 0.0),
        ];
        let model = ForceModel {
            mass: mass.into(),
            inverse_mass: inverse_mass.into(),
            charge: charge.into(),
            uniform: vec![DVec2::new(0.0, -9.81); n].into(),
            gravitational_constant: Some(0.7),
            coulomb_constant: Some(3.0),
            softening2: 0.01,
            interacting: (0..n).collect(),
            charged: (0..n).filter(|i| i % 3 != 0).collect(),
            tree: None,
            springs_at: crate::forces::spring::each_particles(&springs, n),
            springs,
            constraints: crate::constraints::Constraints::default(),
            workers: crate::parallel::Workers::default(),
            surface_contacts: Vec::new(),
            drag: Vec::new(),
            magnetic: Vec::new(),
            own: Vec::new(),
        };
        (model, x)
    }

    /// The accelerations of `model`'s fields, pair laws and springs at positions `x`, at rest.
    fn free_accelerations(model: &ForceModel, x: &[DVec2]) -> Vec<DVec2> {
        let mut a = vec![DVec2::ZERO; x.len()];
        model.free_accelerations(0.0, x, &vec![DVec2::ZERO; x.len()], &mut a);
        a
    }

    /// (plus − minus) / 2ε, element by element.
    fn central_difference(plus: &[DVec2], minus: &[DVec2], eps: f64) -> Vec<DVec2> {
        plus.iter()
            .zip(minus)
            .map(|(p, m)| (*p - *m) / (2.0 * eps))
            .collect()
    }

    /// The exact change equals the difference of the accelerations themselves for a
    /// displacement of 3 cm of each particle in turn (to rounding: 1e-12 of their scale),
    /// and approaches the response for a small one.
    #[test]
    fn the_change_is_the_difference_of_the_accelerations() {
        let mut uniform = crate::testing::uniform(11);
        let n = 9;
        let (model, x) = model(n, &mut uniform);
        let accelerations = |x: &[DVec2]| free_accelerations(&model, x);
        let before = accelerations(&x);
        let scale = before.iter().map(|a| a.length()).fold(1.0, f64::max);
        for k in 0..n {
            let delta = DVec2::new(0.03, -0.02);
            let mut moved = x.clone();
            moved[k] += delta;
            let after = accelerations(&moved);
            let mut change = vec![DVec2::ZERO; n];
            model.displacement_change(&x, k, delta, &mut change);
            for j in 0..n {
                let expected = after[j] - before[j];
                assert!(
                    (change[j] - expected).length() <= 1e-12 * scale,
                    "particle {j} for a move of {k}: {} against {expected}",
                    change[j]
                );
            }
            let small = delta * 1e-7;
            let (mut change, mut response) = (vec![DVec2::ZERO; n], vec![DVec2::ZERO; n]);
            model.displacement_change(&x, k, small, &mut change);
            model.displacement_response(&x, k, small, &mut response);
            for j in 0..n {
                assert!(
                    (change[j] - response[j]).length() <= 1e-6 * response[j].length().max(1e-9)
                );
            }
        }
    }

    /// One particle's acceleration is the whole evaluation's, to 1e-12 of its scale.
    #[test]
    fn one_particles_acceleration_is_the_evaluations() {
        let mut uniform = crate::testing::uniform(3);
        let n = 9;
        let (model, x) = model(n, &mut uniform);
        let v: Vec<DVec2> = (0..n).map(|_| DVec2::new(uniform(), uniform())).collect();
        let mut a = vec![DVec2::ZERO; n];
        model.accelerations(0.0, &x, &v, &mut a);
        let scale = a.iter().map(|a| a.length()).fold(1.0, f64::max);
        for (k, expected) in a.iter().enumerate() {
            let one = model.acceleration_of(&x, &v, k);
            assert!(
                (one - *expected).length() <= 1e-12 * scale,
                "particle {k}: {one} against {expected}"
            );
        }
    }

    /// The rate of each particle's acceleration equals the central difference of the
    /// accelerations along the motion x + v t over ±1e-6 s, to 1e-6 of the rates' scale.
    #[test]
    fn the_rate_is_the_derivative_along_the_motion() {
        let mut uniform = crate::testing::uniform(5);
        let n = 9;
        let (model, x) = model(n, &mut uniform);
        let v: Vec<DVec2> = (0..n)
            .map(|_| DVec2::new(uniform() - 0.5, uniform() - 0.5) * 3.0)
            .collect();
        let at = |t: f64| {
            let moved: Vec<DVec2> = x.iter().zip(&v).map(|(x, v)| *x + *v * t).collect();
            free_accelerations(&model, &moved)
        };
        let eps = 1e-6;
        let difference = central_difference(&at(eps), &at(-eps), eps);
        let scale = difference.iter().map(|d| d.length()).fold(1e-3, f64::max);
        for (k, expected) in difference.iter().enumerate() {
            let rate = model.acceleration_rate(&x, &v, k);
            assert!(
                (rate - *expected).length() <= 1e-6 * scale,
                "particle {k}: {rate} against {expected}"
            );
        }
    }

    /// Each particle's response to a displacement of each of the others (a spring's ends,
    /// a fixed body, a charged and an uncharged one among them) equals the central
    /// difference of the accelerations themselves over ±1e-6 m, to 1e-6 of the
    /// difference's scale (its own error is of order 1e-12 relative to the third
    /// derivative's scale: a sign, a factor of three or a missing term is of order one).
    #[test]
    fn the_response_is_the_derivative_of_the_accelerations() {
        let mut uniform = crate::testing::uniform(7);
        let n = 9;
        let (model, x) = model(n, &mut uniform);
        let accelerations = |x: &[DVec2]| free_accelerations(&model, x);
        let eps = 1e-6;
        for k in 0..n {
            for delta in [DVec2::X, DVec2::new(0.6, -0.8)] {
                let mut response = vec![DVec2::ZERO; n];
                model.displacement_response(&x, k, delta, &mut response);
                let (mut plus, mut minus) = (x.clone(), x.clone());
                plus[k] += delta * eps;
                minus[k] -= delta * eps;
                let difference =
                    central_difference(&accelerations(&plus), &accelerations(&minus), eps);
                let scale = difference.iter().map(|d| d.length()).fold(1e-3, f64::max);
                for (j, (r, d)) in response.iter().zip(&difference).enumerate() {
                    assert!(
                        (*r - *d).length() <= 1e-6 * scale,
                        "particle {j} for a move of {k}: {r} against {d}"
                    );
                }
            }
        }
    }
}
