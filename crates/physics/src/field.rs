//! The fields at a point of space: what a small test mass or charge placed there would
//! feel, from the same laws the particles feel (the paper's 25–26) and the uniform field.
//! The app's probe and field view read it.

use glam::DVec2;

use crate::forces::{coulomb, gravitation};
use crate::scene::Scene;

/// The fields at one point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FieldReadout {
    /// The gravitational field g, N/kg (= m/s²): the uniform field plus every
    /// particle's attraction G m / r² towards it (when gravitation is on).
    pub gravity: DVec2,
    /// The electric field E, N/C (= V/m): k q / r² away from each charge (when
    /// electrostatics is on).
    pub electric: DVec2,
    /// The gravitational potential, J/kg: −g·r of the uniform field plus −G m / r of
    /// each particle.
    pub gravitational_potential: f64,
    /// The electric potential, V: k q / r of each charge.
    pub electric_potential: f64,
}

/// The fields of `scene`'s world and particles, the particles at `positions` (the
/// scene's own, or a running simulation's), at `point`, with the world's softening. A
/// particle exactly at `point` is left out when there is none: its own field there has
/// no value.
pub fn field_at(scene: &Scene, positions: &[DVec2], point: DVec2) -> FieldReadout {
    let world = &scene.world;
    let uniform = world.gravity.to_dvec2();
    let mut readout = FieldReadout {
        gravity: uniform,
        gravitational_potential: -uniform.dot(point),
        ..FieldReadout::default()
    };
    let g = if world.gravitation {
        world.gravitational_constant
    } else {
        0.0
    };
    let k = if world.electrostatics {
        world.coulomb_constant
    } else {
        0.0
    };
    // Softened as the pair laws are: √(r² + ε²), the plain distance without.
    let softening2 = world.softening * world.softening;
    for (particle, &x) in scene.particles.iter().zip(positions) {
        let d = x - point;
        let r = (d.length_squared() + softening2).sqrt();
        if r == 0.0 {
            continue;
        }
        // The laws the particles feel, with a unit test mass and a unit test charge.
        let r3 = r * r * r;
        if g != 0.0 {
            readout.gravity += d * (gravitation::strength(g, particle.mass, 1.0) / r3);
            readout.gravitational_potential += gravitation::potential(g, particle.mass, 1.0, r);
        }
        if k != 0.0 && particle.charge != 0.0 {
            readout.electric -= d * (coulomb::strength(k, particle.charge, 1.0) / r3);
            readout.electric_potential += coulomb::potential(k, particle.charge, 1.0, r);
        }
    }
    readout
}
