//! Random scenes against the conservation laws of elastic impacts.

use physics::{DVec2, Particle, Scene, Simulation, World};
use proptest::prelude::*;

/// Up to 30 particles of random mass, radius and velocity on a jittered 6 × 5 grid one
/// metre apart (so none touch at the start), with e = 1 and no forces of any kind.
fn scenes() -> impl Strategy<Value = Scene> {
    let particle = (
        0.5..5.0_f64,
        0.1..0.4_f64,
        -5.0..5.0_f64,
        -5.0..5.0_f64,
        -0.08..0.08_f64,
        -0.08..0.08_f64,
    );
    (2..=30_usize, proptest::collection::vec(particle, 30)).prop_map(|(n, particles)| {
        let world = World {
            restitution: 1.0,
            ..World::no_forces()
        };
        let mut scene = Scene::new().with_world(world);
        for (k, &(mass, radius, vx, vy, jx, jy)) in particles.iter().take(n).enumerate() {
            let slot = DVec2::new((k % 6) as f64, (k / 6) as f64);
            scene.particles.push(
                Particle::new(format!("p{k}"), mass)
                    .radius(radius)
                    .position(slot + DVec2::new(jx, jy))
                    .velocity([vx, vy]),
            );
        }
        scene
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// Elastic impulses conserve kinetic energy and momentum exactly; what remains is
    /// rounding and the locating of each impact (to ~1e-13 of a step). Over 10 s: energy
    /// within 1e-6 relative, momentum within 1e-9 of Σ m|v|.
    #[test]
    fn elastic_scenes_conserve_energy_and_momentum(scene in scenes()) {
        let mut simulation = Simulation::new(&scene).unwrap();
        let start = simulation.diagnostics();
        let scale: f64 = scene.particles.iter().map(|p| p.mass * p.velocity.to_dvec2().length()).sum();
        for k in 1..=100 {
            simulation.step_to(f64::from(k) * 0.1).unwrap();
            let now = simulation.diagnostics();
            let energy_error = (now.energy.total() - start.energy.total()).abs() / start.energy.total();
            prop_assert!(energy_error < 1e-6, "t = {}: energy off by {energy_error}", now.time);
            let momentum_error = (now.momentum - start.momentum).length();
            prop_assert!(momentum_error < 1e-9 * scale, "t = {}: momentum off by {momentum_error}", now.time);
        }
    }
}
