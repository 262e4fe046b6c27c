//! Particles that turn: a disc or a ring of moment of inertia I = k m r², with a spin ω
//! and an orientation. Only friction turns them, and friction acts at a contact point:
//! - at an impact, Coulomb's law on the contact points' relative velocity: the
//!   tangential impulse that brings it to zero (sticking) when that needs at most μ times
//!   the normal impulse, otherwise μ times the normal impulse against the slip
//!   ([`Grip::at_impact`]); its angular impulse is r × J;
//! - resting on a ramp or a wall, rolling without slipping while the friction it needs
//!   stays within μN, and slipping otherwise, with a friction of μN against the slip
//!   (`forces/normal.rs`). The instant slipping stops is located like an impact
//!   (`simulation.rs`), so a bowled ball starts to roll when theory says it does.
//!
//! A particle of inertia 0 is the paper's point: it never turns, and friction at its
//! impacts would spin it up instantly at no cost, so there is none (its tangential
//! inverse mass w/k is infinite): its motion is the same, bit for bit, as before
//! particles could turn.
//!
//! Spins change only by the impulses of impacts and by the friction of the surface each
//! rests on, whose torque over a step is known from the step's linear motion, so the
//! integrators never see a spin: each step's start sets how each particle turns through
//! it ([`Mode`]), and its end adds the turning ([`Turning::end_step`]).

use std::sync::Arc;

use glam::DVec2;

use crate::scene::Scene;
use crate::state::State;

/// An impact applied to a particle inside a step, as its turning sees it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Kick {
    /// Seconds into the step.
    pub time: f64,
    pub particle: usize,
    /// The change of its velocity, m/s.
    pub velocity: DVec2,
    /// The change of its spin, rad/s.
    pub spin: f64,
}

/// Every particle's mass (kg) and radius (m).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sizes<'a> {
    pub mass: &'a [f64],
    pub radius: &'a [f64],
}

/// The spins and orientations of a scene's particles, for scenes with any particle that
/// turns.
#[derive(Clone, Debug)]
pub(crate) struct Turning {
    /// k = I/(m r²) of each particle; 0 for one that never turns.
    pub inertia: Arc<[f64]>,
    /// Radians per second, counter-clockwise: at the step's start, plus the impulses
    /// applied inside it so far.
    pub spin: Vec<f64>,
    /// Degrees, counter-clockwise, unwrapped: in the unit a scene file writes it, so that
    /// a saved state holds it to the bit (radians written as degrees do not all read back:
    /// some 13 % of values come back an ulp off).
    pub angle: Vec<f64>,
    /// How each particle turns through the current step.
    pub mode: Vec<Mode>,
    /// The spins once the step's start had applied its impacts: what the step's
    /// orientation change is integrated from.
    pub start_spin: Vec<f64>,
    /// The coefficient of friction between particles.
    pub friction: f64,
}

/// How surface friction turns a particle through one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) enum Mode {
    /// Not on a surface with friction: only impacts change its spin.
    #[default]
    Free,
    /// Rolling without slipping along `tangent` (the surface normal turned a quarter
    /// counter-clockwise), with the speed `speed` along it at the step's start: its spin
    /// follows its speed along the surface, ω = v·t / r.
    Rolls { tangent: DVec2, speed: f64 },
    /// Slipping, with a friction acceleration of `friction` m/s² along `tangent` and the
    /// angular acceleration `angular` rad/s² it gives, both fixed for the step.
    Slips {
        tangent: DVec2,
        friction: f64,
        angular: f64,
    },
}

impl Turning {
    /// The turning state at the scene's start, or `None` when no particle turns.
    pub fn new(scene: &Scene) -> Option<Self> {
        let particles = &scene.particles;
        if !particles.iter().any(crate::scene::Particle::turns) {
            return None;
        }
        let spin: Vec<f64> = particles
            .iter()
            .map(|p| if p.turns() { p.spin } else { 0.0 })
            .collect();
        Some(Self {
            inertia: particles.iter().map(|p| p.inertia).collect(),
            start_spin: spin.clone(),
            spin,
            angle: particles.iter().map(|p| p.angle).collect(),
            mode: vec![Mode::Free; particles.len()],
            friction: scene.world.friction,
        })
    }

    /// Particle `p`'s spin `time` seconds into the step, moving at `velocity` then
    /// (impulses already applied count from the instant they were).
    pub fn spin_at(&self, p: usize, time: f64, velocity: DVec2, radius: f64) -> f64 {
        match self.mode[p] {
            Mode::Free => self.spin[p],
            Mode::Rolls { tangent, speed } => {
                self.spin[p] + (velocity.dot(tangent) - speed) / radius
            }
            Mode::Slips { angular, .. } => self.spin[p] + angular * time,
        }
    }

    /// Σ ½ I ω², joules; `mass` each particle's (fixed ones count nothing).
    pub fn kinetic_energy(&self, mass: &[f64], inverse_mass: &[f64], radius: &[f64]) -> f64 {
        (0..self.spin.len())
            .filter(|&i| inverse_mass[i] > 0.0)
            .map(|i| 0.5 * self.moment(i, mass, radius) * self.spin[i] * self.spin[i])
            .sum()
    }

    /// Particle `i`'s moment of inertia about its centre, kg·m².
    pub fn moment(&self, i: usize, mass: &[f64], radius: &[f64]) -> f64 {
        self.inertia[i] * mass[i] * radius[i] * radius[i]
    }

    /// Sets the spins the step starts from, once its start's impacts are applied.
    pub fn begin_step(&mut self) {
        self.start_spin.clone_from(&self.spin);
    }

    /// The step's end, `taken` seconds after its `start` state, now at `end`: adds each
    /// particle's turning through the step to its orientation, and surface friction's
    /// share to its spin. `kicks` are the impacts applied inside the step. Returns the
    /// energy slipping friction took, joules: with its force fixed for the step, its work
    /// on the slip, −m f ∫ (v·t − ω r) dt, is exact.
    pub fn end_step(
        &mut self,
        taken: f64,
        start: &State,
        end: &State,
        particles: Sizes<'_>,
        kicks: &[Kick],
    ) -> f64 {
        let Sizes { mass, radius } = particles;
        let (start, start_velocity) = (&start.position, &start.velocity);
        let (end, end_velocity) = (&end.position, &end.velocity);
        // Each particle's turn through the step, radians.
        let mut turned: Vec<f64> = self.start_spin.iter().map(|spin| spin * taken).collect();
        for kick in kicks {
            turned[kick.particle] += kick.spin * (taken - kick.time);
        }
        let mut lost = 0.0;
        for p in 0..self.spin.len() {
            match self.mode[p] {
                Mode::Free => {}
                Mode::Rolls { tangent, speed } => {
                    // The friction that keeps it rolling turns it as the smooth forces
                    // change its speed along the surface: dω/dt = (dv/dt)·t / r. The
                    // impacts' own changes of speed are not the friction's.
                    let (mut moved, mut gained) = (
                        (end[p] - start[p]).dot(tangent) - speed * taken,
                        end_velocity[p].dot(tangent) - start_velocity[p].dot(tangent),
                    );
                    for kick in kicks.iter().filter(|kick| kick.particle == p) {
                        moved -= kick.velocity.dot(tangent) * (taken - kick.time);
                        gained -= kick.velocity.dot(tangent);
                    }
                    self.spin[p] += gained / radius[p];
                    turned[p] += moved / radius[p];
                }
                Mode::Slips {
                    tangent,
                    friction,
                    angular,
                } => {
                    self.spin[p] += angular * taken;
                    turned[p] += 0.5 * angular * taken * taken;
                    let slid = (end[p] - start[p]).dot(tangent) - turned[p] * radius[p];
                    lost -= mass[p] * friction * slid;
                }
            }
        }
        for (angle, turned) in self.angle.iter_mut().zip(turned) {
            *angle += turned.to_degrees();
        }
        lost
    }

    /// The particles slipping on a surface through this step, each with the slip of its
    /// contact point (v·t − ω r, m/s) `time` seconds into the step, where they move at
    /// `velocity`.
    pub fn slips(&self, velocity: &[DVec2], radius: &[f64], time: f64) -> Vec<(usize, f64)> {
        (0..self.mode.len())
            .filter_map(|p| match self.mode[p] {
                Mode::Slips {
                    tangent, angular, ..
                } => Some((
                    p,
                    velocity[p].dot(tangent) - (self.start_spin[p] + angular * time) * radius[p],
                )),
                _ => None,
            })
            .collect()
    }

    /// Σ I ω, kg·m²/s: the particles' own angular momentum, about their centres.
    pub fn angular_momentum(&self, mass: &[f64], inverse_mass: &[f64], radius: &[f64]) -> f64 {
        (0..self.spin.len())
            .filter(|&i| inverse_mass[i] > 0.0)
            .map(|i| self.moment(i, mass, radius) * self.spin[i])
            .sum()
    }
}

/// The tangential part of an impact between turning bodies.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Grip {
    /// The velocity changes of the first and the second body, m/s.
    pub dv: (DVec2, DVec2),
    /// Their spin changes, rad/s.
    pub spin: (f64, f64),
    /// The kinetic energy friction took, J.
    pub lost: f64,
}

/// One body of an impact, as friction sees it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Body {
    /// 1/m (0: fixed, or a surface).
    pub inverse_mass: f64,
    /// k = I/(m r²).
    pub inertia: f64,
    pub radius: f64,
    pub velocity: DVec2,
    pub spin: f64,
}

impl Body {
    /// A surface: it does not move, turn or give.
    pub const SURFACE: Self = Self {
        inverse_mass: 0.0,
        inertia: 0.0,
        radius: 0.0,
        velocity: DVec2::ZERO,
        spin: 0.0,
    };

    /// The rotational part of the tangential inverse mass, r²/I = (1/m)/k: 0 for what
    /// cannot move, `None` (infinite) for a moving point.
    fn turning_inverse(&self) -> Option<f64> {
        if self.inverse_mass == 0.0 {
            Some(0.0)
        } else if self.inertia > 0.0 {
            Some(self.inverse_mass / self.inertia)
        } else {
            None
        }
    }
}

impl Grip {
    /// The tangential impulse of an impact of coefficient of friction `friction` between
    /// `first` and `second`, whose normal (unit, from `first` towards `second`) impulse
    /// is `normal_impulse` N·s: Coulomb's law on the contact points' relative velocity.
    /// `None` when there is no friction, or a moving point takes part.
    pub fn at_impact(
        friction: f64,
        normal: DVec2,
        normal_impulse: f64,
        (first, second): (Body, Body),
    ) -> Option<Self> {
        if friction <= 0.0 || normal_impulse <= 0.0 {
            return None;
        }
        let tangent = normal.perp();
        // The first body's contact point is r₁ = +r₁ n from its centre and the second's
        // r₂ = −r₂ n; ω × r = ω r⊥, and n⊥ = t: their velocities along t differ by
        let slip = (first.velocity - second.velocity).dot(tangent)
            + first.spin * first.radius
            + second.spin * second.radius;
        // An impulse P t on the first (−P t on the second) changes the slip by P times
        // Σ 1/m + r²/I.
        let inverse = first.inverse_mass
            + second.inverse_mass
            + first.turning_inverse()?
            + second.turning_inverse()?;
        if inverse == 0.0 || slip == 0.0 {
            return None;
        }
        let sticking = -slip / inverse;
        let limit = friction * normal_impulse;
        let impulse = if sticking.abs() <= limit {
            sticking
        } else {
            -limit * slip.signum()
        };
        let spin = |body: &Body| {
            if body.inverse_mass == 0.0 {
                0.0
            } else {
                impulse * body.inverse_mass / (body.inertia * body.radius)
            }
        };
        Some(Self {
            dv: (
                tangent * (impulse * first.inverse_mass),
                -tangent * (impulse * second.inverse_mass),
            ),
            spin: (spin(&first), spin(&second)),
            // The work of the impulse on the slip, which changes linearly with it.
            lost: -impulse * (slip + 0.5 * inverse * impulse),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn disc(velocity: DVec2, spin: f64) -> Body {
        Body {
            inverse_mass: 0.5,
            inertia: 0.5,
            radius: 0.25,
            velocity,
            spin,
        }
    }

    /// A disc (k = ½, m = 2, r = ¼) spinning at ω₀ on a gripping floor leaves with the
    /// speed ω₀ r/3 and the spin ω₀/3, and friction takes m r² ω₀²/6 — worked by hand
    /// from the impulse P: m Δv = P, I Δω = r P, v + ω r → 0.
    #[test]
    fn a_spinning_disc_on_a_sticking_floor_keeps_a_third_of_its_spin() {
        let omega = 12.0;
        // The floor first, the disc above it: the normal points up, into the disc.
        let grip = Grip::at_impact(
            10.0,
            DVec2::Y,
            1.0,
            (Body::SURFACE, disc(DVec2::ZERO, omega)),
        )
        .unwrap();
        let (m, r) = (2.0, 0.25);
        let v = grip.dv.1;
        let spin = omega + grip.spin.1;
        assert!((v.x - (-omega * r / 3.0)).abs() < 1e-15, "{v}");
        assert!(v.y.abs() < 1e-15);
        assert!((spin - omega / 3.0).abs() < 1e-14, "{spin}");
        // The contact point then rests: v + ω × (−r ŷ) = v + ω r x̂.
        assert!((v.x + spin * r).abs() < 1e-14);
        assert!((grip.lost - m * r * r * omega * omega / 6.0).abs() < 1e-13);
    }

    /// Beyond μ times the normal impulse it slides: the tangential impulse is exactly
    /// μ J against the slip; a moving point, or no friction, gives nothing.
    #[test]
    fn sliding_takes_mu_times_the_normal_impulse_and_points_take_none() {
        let grip =
            Grip::at_impact(0.1, DVec2::Y, 1.0, (Body::SURFACE, disc(DVec2::ZERO, 12.0))).unwrap();
        assert!((grip.dv.1.x - (-0.1 * 0.5)).abs() < 1e-15, "{:?}", grip.dv);
        let point = Body {
            inertia: 0.0,
            ..disc(DVec2::ZERO, 0.0)
        };
        assert_eq!(
            Grip::at_impact(1.0, DVec2::Y, 1.0, (Body::SURFACE, point)),
            None
        );
        assert_eq!(
            Grip::at_impact(0.0, DVec2::Y, 1.0, (Body::SURFACE, disc(DVec2::X, 1.0))),
            None
        );
    }
}
