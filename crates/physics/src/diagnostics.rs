//! What can be measured at an instant: energies by kind, momentum, and per-particle
//! readouts. Conventions (`docs/scene-format.md`): uniform field and applied acceleration
//! −m (g + a)·r, spring k (L − L0)²/2, gravitation −G m1 m2 / r, Coulomb k q1 q2 / r (softened: [`crate::forces::pair`]).
//!
//! Fixed particles have no kinetic energy or momentum and no potential energy in the
//! uniform field (they never move, so it would be a constant); pairs in which both are
//! fixed are left out for the same reason.

use glam::DVec2;

use crate::forces::{ForceModel, pair, uniform};
use crate::state::State;

/// Energies at an instant, joules.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Energy {
    /// Σ m v²/2 over moving particles.
    pub kinetic: f64,
    /// Potential of the uniform field and applied accelerations.
    pub uniform: f64,
    /// Elastic potential of the springs.
    pub spring: f64,
    /// Gravitational potential of the pairs.
    pub gravitation: f64,
    /// Electrostatic potential of the pairs.
    pub electrostatic: f64,
    /// Potential of the forces of one's own that have one (`[[force]]`'s `potential`).
    pub own: f64,
}

impl Energy {
    /// All potential energy, joules.
    pub fn potential(&self) -> f64 {
        self.uniform + self.spring + self.gravitation + self.electrostatic + self.own
    }

    /// Kinetic plus potential, joules.
    pub fn total(&self) -> f64 {
        self.kinetic + self.potential()
    }
}

/// System-wide quantities at an instant.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Diagnostics {
    /// Seconds.
    pub time: f64,
    /// Joules.
    pub energy: Energy,
    /// Σ m v over moving particles, kg·m/s.
    pub momentum: DVec2,
    /// Σ m x × v + I ω over moving particles, about the origin, kg·m²/s.
    pub angular_momentum: f64,
}

/// One particle at an instant.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ParticleReadout {
    /// Metres.
    pub position: DVec2,
    /// Metres per second.
    pub velocity: DVec2,
    /// From the smooth forces, metres per second squared.
    pub acceleration: DVec2,
    /// |v|, metres per second.
    pub speed: f64,
    /// Joules.
    pub kinetic_energy: f64,
    /// kg·m/s.
    pub momentum: DVec2,
    /// Radians per second, counter-clockwise (0 for a particle that does not turn).
    pub spin: f64,
    /// Degrees, counter-clockwise, unwrapped.
    pub angle: f64,
    /// ½ I ω², joules (included in `kinetic_energy`).
    pub rotational_energy: f64,
    /// m x × v + I ω about the origin, kg·m²/s.
    pub angular_momentum: f64,
}

pub(crate) fn measure(forces: &ForceModel, state: &State) -> Diagnostics {
    let mut energy = Energy::default();
    let mut momentum = DVec2::ZERO;
    let mut angular_momentum = 0.0;
    for i in 0..state.len() {
        if forces.is_fixed(i) {
            continue;
        }
        let (m, v) = (forces.mass[i], state.velocity[i]);
        energy.kinetic += 0.5 * m * v.length_squared();
        energy.uniform += uniform::potential(m, forces.uniform[i], state.position[i]);
        momentum += m * v;
        angular_momentum += m * state.position[i].perp_dot(v);
    }
    // A fold from +0: `sum` of no springs is −0, which shows as "-0".
    energy.spring = forces
        .springs
        .iter()
        .map(|s| s.potential(&state.position))
        .fold(0.0, |sum, e| sum + e);
    energy.own = forces
        .own
        .iter()
        .map(|f| f.potential(&state.position, forces))
        .fold(0.0, |sum, e| sum + e);
    let g = forces.gravitational_constant.unwrap_or(0.0);
    let k = forces.coulomb_constant.unwrap_or(0.0);
    let mut ids = forces.interacting.as_slice();
    if let Some(theta) = forces.tree {
        // Gravitation through the tree, as the forces are; then the charged pairs
        // directly, and less the pairs of two fixed particles the tree counted.
        energy.gravitation = tree_gravitation(forces, state, g, theta);
        ids = &forces.charged;
    }
    for (n, &i) in ids.iter().enumerate() {
        for &j in &ids[n + 1..] {
            if forces.is_fixed(i) && forces.is_fixed(j) {
                continue;
            }
            let r = forces.pair_distance(state.position[i], state.position[j]);
            if forces.tree.is_none() {
                energy.gravitation +=
                    pair::gravitation_potential(g, forces.mass[i], forces.mass[j], r);
            }
            energy.electrostatic +=
                pair::coulomb_potential(k, forces.charge[i], forces.charge[j], r);
        }
    }
    Diagnostics {
        time: state.time,
        energy,
        momentum,
        angular_momentum,
    }
}

/// The gravitational potential energy summed by the Barnes–Hut tree (opening angle
/// `theta`), without the pairs of two fixed particles, which the direct sum leaves out.
fn tree_gravitation(forces: &ForceModel, state: &State, g: f64, theta: f64) -> f64 {
    if g == 0.0 {
        return 0.0;
    }
    let x = &state.position;
    let all = crate::forces::tree::potential_energy(
        (g, forces.softening2),
        theta,
        &forces.interacting,
        (x, &forces.mass),
        &forces.workers,
    );
    let fixed: Vec<usize> = forces
        .interacting
        .iter()
        .copied()
        .filter(|&i| forces.is_fixed(i))
        .collect();
    let mut both_fixed = 0.0;
    for (n, &i) in fixed.iter().enumerate() {
        for &j in &fixed[n + 1..] {
            let r = forces.pair_distance(x[i], x[j]);
            both_fixed += pair::gravitation_potential(g, forces.mass[i], forces.mass[j], r);
        }
    }
    all - both_fixed
}

pub(crate) fn particle(
    forces: &ForceModel,
    state: &State,
    accelerations: &[DVec2],
    i: usize,
) -> ParticleReadout {
    let (position, velocity) = (state.position[i], state.velocity[i]);
    let mass = if forces.is_fixed(i) {
        0.0
    } else {
        forces.mass[i]
    };
    ParticleReadout {
        position,
        velocity,
        acceleration: accelerations.get(i).copied().unwrap_or_default(),
        speed: velocity.length(),
        kinetic_energy: 0.5 * mass * velocity.length_squared(),
        momentum: mass * velocity,
        spin: 0.0,
        angle: 0.0,
        rotational_energy: 0.0,
        angular_momentum: mass * position.perp_dot(velocity),
    }
}

/// The change of potential energy when positions go from `before` to `after` (the same
/// particles; most of them unmoved), joules: what a contact's position correction or a
/// surface's catch does to the books. Summed over what moved, pair by pair, so the
/// difference keeps its digits (the difference of two totals of 10⁴ J would lose ten of
/// them), and a few moved particles in a large gravitating scene cost O(moved × n), not
/// O(n²). Pairs are summed directly also in a tree scene: this is an exact change.
pub(crate) fn potential_change(forces: &ForceModel, before: &[DVec2], after: &[DVec2]) -> f64 {
    let moved: Vec<usize> = (0..after.len())
        .filter(|&i| before[i] != after[i] && !forces.is_fixed(i))
        .collect();
    if moved.is_empty() {
        return 0.0;
    }
    let mut change = 0.0;
    for &i in &moved {
        let (m, field) = (forces.mass[i], forces.uniform[i]);
        change += uniform::potential(m, field, after[i]) - uniform::potential(m, field, before[i]);
    }
    for spring in &forces.springs {
        change += spring.potential(after) - spring.potential(before);
    }
    for own in &forces.own {
        change += own.potential(after, forces) - own.potential(before, forces);
    }
    let g = forces.gravitational_constant.unwrap_or(0.0);
    let k = forces.coulomb_constant.unwrap_or(0.0);
    let is_moved = |j: usize| moved.binary_search(&j).is_ok();
    for &i in &moved {
        if forces.interacting.binary_search(&i).is_err() {
            continue; // no pairwise forces on it
        }
        for &j in &forces.interacting {
            // A pair of two moved particles is counted once, from its lower index (a moved
            // particle is never fixed, so no pair here is of two fixed ones).
            if j == i || (is_moved(j) && j < i) {
                continue;
            }
            let pair = |x: &[DVec2]| {
                let r = forces.pair_distance(x[i], x[j]);
                pair::gravitation_potential(g, forces.mass[i], forces.mass[j], r)
                    + pair::coulomb_potential(k, forces.charge[i], forces.charge[j], r)
            };
            change += pair(after) - pair(before);
        }
    }
    change
}
