//! Scenes made by code rather than typed: the large scenes of the benchmarks and the
//! processing-time table, where listing a thousand particles in a file would help nobody.
//! Layouts are deterministic (no random numbers), so every run measures the same scene.

use glam::DVec2;

use crate::scene::{Particle, Scene, Vector, World};

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

/// A star cluster of `n` bodies for the tree benchmark: 1 to 2 kg each on a sunflower
/// spiral in a disc of radius 10 m, denser towards the middle, G = 1 (so the motion is
/// seen within seconds), each on a circular orbit about the centre at the speed the mass
/// inside its radius gives, and summed with the Barnes–Hut tree at the default opening
/// angle. The bodies are 0.1 µm across (as the examples' stars), so that impacts (each
/// of which integrates the whole system again to its instant) stay rare and the
/// benchmark measures the forces: at 10 µm, 100,000 bodies met several times a step.
#[must_use]
pub fn cluster(n: usize) -> Scene {
    let mut scene = Scene::new().with_world(galaxy_world(1.0));
    scene.name = Some(format!("Cluster of {n}"));
    scene.simulation.pair_forces = crate::scene::PairForces::Tree;
    scene.particles = disc(n, "s", DVec2::ZERO, DVec2::ZERO, 1.0);
    scene
}

/// The world of the clusters: no uniform field, gravitation with G = `g`, no charges.
fn galaxy_world(g: f64) -> World {
    let mut world = World::weightless();
    world.gravitational_constant = g;
    world.electrostatics = false;
    world
}

/// The disc of [`cluster`] with `n` bodies named `prefix`1, `prefix`2, …, centred on
/// `centre` and moving with `velocity` as a whole, each on the circular orbit that
/// gravitation with G = `g` gives it.
fn disc(n: usize, prefix: &str, centre: DVec2, velocity: DVec2, g: f64) -> Vec<Particle> {
    let total: f64 = (0..n).map(|i| 1.0 + (i as f64 * 0.618_034).fract()).sum();
    let mut bodies: Vec<Particle> = (0..n)
        .map(|i| {
            let f = i as f64;
            let radius = 10.0 * (f / n as f64).powf(0.75) + 1e-2;
            let angle = f * GOLDEN_ANGLE;
            // The mass inside: the bodies are placed in order of radius.
            let inside = total * (f / n as f64);
            let speed = (g * inside / radius).sqrt();
            let at = centre + DVec2::new(radius * angle.cos(), radius * angle.sin());
            let orbit = DVec2::new(-speed * angle.sin(), speed * angle.cos());
            Particle::new(format!("{prefix}{}", i + 1), 1.0 + (f * 0.618_034).fract())
                .radius(1e-7)
                .position(at)
                .velocity(orbit)
        })
        .collect();
    // The orbits' momenta do not cancel: the masses follow i·0.618… as the angles follow
    // i times the golden angle, so the heavier bodies lean to one side (7,700 kg·m/s for
    // the 20,000 stars). The disc as a whole is given `velocity` exactly, no drift of its
    // own.
    let momentum: DVec2 = bodies.iter().map(|b| b.velocity.to_dvec2() * b.mass).sum();
    let drift = momentum / total;
    for body in &mut bodies {
        let v = body.velocity.to_dvec2() - drift + velocity;
        body.velocity = Vector::cartesian(v.x, v.y);
    }
    bodies
}

/// The examples' gravitational constant: a four-hundredth of the benchmark's G = 1, which
/// slows every motion by √400 = 20, so the edge of a disc goes round in about 23 s and
/// its middle in a few, which the eye can follow and a step of 50 ms resolves.
const GALAXY_G: f64 = 0.0025;

/// The examples' clusters: stepped by Verlet (one tree evaluation a step, symplectic, so
/// orbits neither spiral in nor out) at 50 ms; gravitation softened over 0.2 m (about
/// the distance between neighbours at a disc's edge), so that close passes of two stars
/// are resolved rather than flinging them out at thousands of metres per second, as the
/// point laws did at any affordable step; and the stars pass through each other
/// (`collisions = false`), as the softened points they are, so no step looks for
/// impacts among 20,000 of them. The total energy stays within 0.11 % over 40 s
/// (`newtonlab run example:star-cluster --until 40 --every 5`; a 100 ms step gave 4 %,
/// a softening of 0.1 m 6 %).
fn galaxy_example(mut scene: Scene) -> Scene {
    scene.simulation.integrator = crate::Integrator::Verlet;
    scene.simulation.time_step = 0.05;
    scene.world.softening = 0.2;
    scene.world.collisions = false;
    for star in &mut scene.particles {
        star.radius = 1e-7;
    }
    scene
}

/// The `star-cluster` example: 20,000 stars in the disc of [`cluster`], at the
/// examples' G.
#[must_use]
pub fn star_cluster() -> Scene {
    let mut scene = Scene::new().with_world(galaxy_world(GALAXY_G));
    scene.simulation.pair_forces = crate::scene::PairForces::Tree;
    scene.particles = disc(20_000, "s", DVec2::ZERO, DVec2::ZERO, GALAXY_G);
    let mut scene = galaxy_example(scene);
    scene.name = Some("Star cluster of 20,000".to_owned());
    scene.description = Some(
        "20,000 stars of 1 to 2 kg in a disc, G = 0.0025, each on the circular orbit of the mass inside it; gravitation by the Barnes–Hut tree, softened over 0.2 m."
            .to_owned(),
    );
    scene
}

/// The `colliding-discs` example: two discs of 5,000 bodies each, 28 m apart and 6 m
/// off a head-on line, closing at 1.2 m/s: they fall together, pass through each
/// other, tear into tails and fall back together.
#[must_use]
pub fn colliding_discs() -> Scene {
    let mut scene = Scene::new().with_world(galaxy_world(GALAXY_G));
    scene.name = Some("Two colliding discs".to_owned());
    scene.description = Some(
        "Two discs of 5,000 stars each meet off-centre; gravitation by the Barnes–Hut tree, softened over 0.2 m."
            .to_owned(),
    );
    scene.simulation.pair_forces = crate::scene::PairForces::Tree;
    let (centre, velocity) = (DVec2::new(14.0, 3.0), DVec2::new(0.6, 0.0));
    scene.particles = disc(5_000, "a", -centre, velocity, GALAXY_G);
    scene
        .particles
        .extend(disc(5_000, "b", centre, -velocity, GALAXY_G));
    galaxy_example(scene)
}

/// `n` balls of radius 0.1 m and 1 kg dropped into a box with restitution 0.5 under
/// gravity: a grid 0.3 m apart, each with a small sideways velocity that differs ball to
/// ball so the pile does not stack in columns. The box is as wide as a square of the
/// balls would be tall, and tall enough for the grid.
#[must_use]
pub fn ball_pit(n: usize) -> Scene {
    const SPACING: f64 = 0.3;
    const RADIUS: f64 = 0.1;
    let per_row = n.isqrt() + usize::from(n.isqrt() * n.isqrt() < n);
    let per_row = per_row.max(1);
    let width = per_row as f64 * SPACING;
    let rows = n.div_ceil(per_row);
    let height = rows as f64 * SPACING + 2.0;
    let mut world = World {
        gravitation: false,
        electrostatics: false,
        restitution: 0.5,
        ..World::default()
    };
    world.bounds = Some(crate::scene::Bounds {
        min: Vector::cartesian(-width / 2.0, 0.0),
        max: Vector::cartesian(width / 2.0, height),
        friction: 0.0,
        static_friction: None,
    });
    let mut scene = Scene::new().with_world(world);
    // Framed on the box, with a margin.
    scene.view = Some(crate::scene::View {
        center: Some(glam::DVec2::new(0.0, height / 2.0)),
        width: Some(1.25 * width.max(height)),
        ..crate::scene::View::default()
    });
    scene.name = Some(format!("Ball pit of {n}"));
    scene.description = Some(format!(
        "{n} balls of 0.1 m dropped into a box; impacts lose energy (restitution 0.5) until the pile rests."
    ));
    for i in 0..n {
        let (row, column) = (i / per_row, i % per_row);
        let x = -width / 2.0 + SPACING * (column as f64 + 0.5);
        let y = 1.0 + SPACING * row as f64;
        let sideways = (i as f64 * GOLDEN_ANGLE).sin() * 0.5;
        let mut ball = Particle::new(format!("b{}", i + 1), 1.0)
            .radius(RADIUS)
            .position([x, y])
            .velocity([sideways, 0.0]);
        ball.color = Some(crate::scene::Color::palette(i));
        scene.particles.push(ball);
    }
    scene
}

/// The ball pit of `n` with more going on, for the processing-time table: every tenth
/// ball carries ±1 µC (Coulomb on, gravitation off), and every fifth pair of neighbours
/// is joined by a spring of 50 N/m.
#[must_use]
pub fn mixed(n: usize) -> Scene {
    let mut scene = ball_pit(n);
    scene.name = Some(format!("Mixed scene of {n}"));
    scene.description = Some(format!(
        "{n} balls in a box with charges, springs and collisions."
    ));
    scene.world.electrostatics = true;
    for (i, ball) in scene
        .particles
        .iter_mut()
        .enumerate()
        .filter(|(i, _)| i % 10 == 0)
    {
        ball.charge = if i % 20 == 0 { 1e-6 } else { -1e-6 };
    }
    for i in (0..n.saturating_sub(1)).step_by(10) {
        let (a, b) = (
            scene.particles[i].name.clone(),
            scene.particles[i + 1].name.clone(),
        );
        scene.springs.push(crate::scene::Spring::new(
            format!("s{}", i / 10 + 1),
            a.as_str(),
            b.as_str(),
            50.0,
            0.3,
        ));
    }
    scene
}
