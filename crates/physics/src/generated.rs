//! Scenes made by code rather than typed: the large scenes of the benchmarks and the
//! processing-time table, where listing a thousand particles in a file would help nobody.
//! Layouts are deterministic (no random numbers), so every run measures the same scene.

use crate::scene::{Particle, Scene, World};

/// The golden angle, radians: successive points of a sunflower spiral never line up.
const GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// `n` particles of 1 kg and alternating charge ±1 µC on a sunflower spiral 1 m apart,
/// attracting each other by gravitation and by or against each other by Coulomb's law,
/// in a world with no uniform field: the pairwise-force benchmark.
#[must_use]
pub fn charged_cloud(n: usize) -> Scene {
    let mut scene = Scene::new().with_world(World::weightless());
    scene.name = Some(format!("Charged cloud of {n}"));
    for i in 0..n {
        let radius = (i as f64 + 0.5).sqrt();
        let angle = i as f64 * GOLDEN_ANGLE;
        let charge = if i % 2 == 0 { 1e-6 } else { -1e-6 };
        scene.particles.push(
            Particle::new(format!("q{}", i + 1), 1.0)
                .radius(0.1)
                .charge(charge)
                .position([radius * angle.cos(), radius * angle.sin()]),
        );
    }
    scene
}
