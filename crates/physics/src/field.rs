//! The fields at a point of space: what a small test mass or charge placed there would
//! feel, from the same laws the particles feel (the paper's 25–26) and the uniform field.
//! The app's probe and field view read it.

use glam::DVec2;

use crate::forces::pair;
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
    let softening2 = world.softening * world.softening;
    for (particle, &x) in scene.particles.iter().zip(positions) {
        // The laws the particles feel ([`pair`]), on a unit test mass and a unit test
        // charge at `point`.
        let r = pair::distance(point, x, softening2);
        if r == 0.0 {
            continue;
        }
        let d = x - point;
        if g != 0.0 {
            let c = pair::pair_strength(g, 0.0, (1.0, 0.0), (particle.mass, 0.0));
            readout.gravity += pair::force(d, c, softening2);
            readout.gravitational_potential +=
                pair::gravitation_potential(g, 1.0, particle.mass, r);
        }
        if k != 0.0 && particle.charge != 0.0 {
            let c = pair::pair_strength(0.0, k, (0.0, 1.0), (0.0, particle.charge));
            readout.electric += pair::force(d, c, softening2);
            readout.electric_potential += pair::coulomb_potential(k, 1.0, particle.charge, r);
        }
    }
    readout
}
