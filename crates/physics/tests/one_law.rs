//! One law for everything that reads the pair forces: the motion (the direct sum and the
//! tree), the energy books and the field probe all follow the same gravitation and
//! Coulomb law, here with constants that are not the defaults and with softening, where a
//! copy of the law that forgot a constant or the softening would show.
//!
//! The law, written here apart from the simulation's code: on body i from body j,
//! F = (G mᵢ mⱼ − k qᵢ qⱼ) d / (r² + ε²)^{3/2} with d = xⱼ − xᵢ, and the pair's potential
//! energy U = (−G mᵢ mⱼ + k qᵢ qⱼ) / √(r² + ε²).

use physics::{DVec2, PairForces, Particle, Scene, Simulation, World, field_at};

/// G and k, neither the default, and the softening ε, m.
const G: f64 = 0.37;
const K: f64 = 2.3e9;
const SOFTENING: f64 = 0.45;

/// 21 bodies (more than the 16 summed one pair at a time, and not a multiple of the SIMD
/// lanes) of unequal masses, 0.5–5 kg, and charges of both signs up to 2e-5 C, so that
/// gravitation and Coulomb are of one size (≈ 0.3–1 N between neighbours), scattered
/// over 6 m with some pairs inside each other's softened core.
fn bodies() -> Vec<(DVec2, f64, f64)> {
    (0..21)
        .map(|i| {
            let t = f64::from(i);
            let x = DVec2::new((t * 1.7).sin() * 3.0, (t * 0.83).cos() * 3.0 + 0.1 * t);
            let mass = 0.5 + 4.5 * (t * 0.618_034).fract();
            let charge = 2e-5 * (t * 2.3).sin();
            (x, mass, charge)
        })
        .collect()
}

fn world() -> World {
    let mut world = World::weightless();
    world.gravitational_constant = G;
    world.coulomb_constant = K;
    world.softening = SOFTENING;
    world
}

fn scene_of(bodies: &[(DVec2, f64, f64)], pair_forces: PairForces) -> Scene {
    let mut scene = Scene::new().with_world(world());
    scene.simulation.pair_forces = pair_forces;
    // Small enough that the tree opens every cell: its sum is then the direct one.
    scene.simulation.opening_angle = 1e-3;
    for (i, &(x, mass, charge)) in bodies.iter().enumerate() {
        scene.particles.push(
            Particle::new(format!("b{i}"), mass)
                .radius(1e-6)
                .charge(charge)
                .position([x.x, x.y]),
        );
    }
    scene
}

/// The force on body `i` from every other, N, by the law above, and the sum of the
/// magnitudes of those pair forces (the scale rounding works at).
fn force_on(bodies: &[(DVec2, f64, f64)], i: usize) -> (DVec2, f64) {
    let (xi, mi, qi) = bodies[i];
    let (mut force, mut scale) = (DVec2::ZERO, 0.0);
    for (j, &(xj, mj, qj)) in bodies.iter().enumerate() {
        if j != i {
            let d = xj - xi;
            let softened = (d.length_squared() + SOFTENING * SOFTENING).sqrt();
            let pull = d * ((G * mi * mj - K * qi * qj) / softened.powi(3));
            force += pull;
            scale += pull.length();
        }
    }
    (force, scale)
}

/// The potential energy of every pair, J, by the law above: (gravitation, Coulomb).
fn potential_energy(bodies: &[(DVec2, f64, f64)]) -> (f64, f64) {
    let (mut gravitation, mut coulomb) = (0.0, 0.0);
    for (i, &(xi, mi, qi)) in bodies.iter().enumerate() {
        for &(xj, mj, qj) in &bodies[i + 1..] {
            let softened = (xi.distance_squared(xj) + SOFTENING * SOFTENING).sqrt();
            gravitation -= G * mi * mj / softened;
            coulomb += K * qi * qj / softened;
        }
    }
    (gravitation, coulomb)
}

/// The motion follows the law: every body's acceleration at the start is the law's
/// force over its mass, to 1e-12 of the scale of its pair forces (rounding over 20
/// terms), summed directly and by the tree opened everywhere (gravitation through the
/// tree, Coulomb directly among the charged).
#[test]
fn the_motion_follows_the_law_with_its_constants_and_softening() {
    let bodies = bodies();
    for pair_forces in [PairForces::Direct, PairForces::Tree] {
        let simulation = Simulation::new(&scene_of(&bodies, pair_forces)).expect("a valid scene");
        let accelerations = simulation.accelerations();
        for (i, &(_, mass, _)) in bodies.iter().enumerate() {
            let (force, scale) = force_on(&bodies, i);
            let error = (accelerations[i] * mass).distance(force);
            assert!(
                error < 1e-12 * scale,
                "{pair_forces:?}, body {i}: m a = {} N against the law's {force} N",
                accelerations[i] * mass
            );
        }
    }
}

/// The energy books follow the law: the gravitational and electrostatic potential
/// energies the diagnostics report are the law's sums to 1e-12 of their size (with the
/// tree opened everywhere too), and the motion is their gradient: moving one body by
/// ±1e-6 m changes the books' potential energy by −F·δ, the force of the motion, to 1e-6
/// of the force (a central difference: its error is of order δ² times the third
/// derivative, some 1e-9 here, and rounding's 1e-15 J / 1e-6 m = 1e-9 N).
#[test]
fn the_books_follow_the_law_and_the_motion_is_their_gradient() {
    let bodies = bodies();
    let (gravitation, coulomb) = potential_energy(&bodies);
    assert!(
        gravitation.abs() > 1.0 && coulomb.abs() > 0.1,
        "both laws matter"
    );
    for pair_forces in [PairForces::Direct, PairForces::Tree] {
        let energy = Simulation::new(&scene_of(&bodies, pair_forces))
            .expect("a valid scene")
            .diagnostics()
            .energy;
        for (what, books, law) in [
            ("gravitation", energy.gravitation, gravitation),
            ("Coulomb", energy.electrostatic, coulomb),
        ] {
            assert!(
                (books - law).abs() < 1e-12 * law.abs(),
                "{pair_forces:?}, {what}: the books' {books} J against the law's {law} J"
            );
        }
    }
    let potential_with = |bodies: &[(DVec2, f64, f64)]| {
        let energy = Simulation::new(&scene_of(bodies, PairForces::Direct))
            .expect("a valid scene")
            .diagnostics()
            .energy;
        energy.gravitation + energy.electrostatic
    };
    let simulation = Simulation::new(&scene_of(&bodies, PairForces::Direct)).expect("valid");
    let accelerations = simulation.accelerations();
    let delta = 1e-6;
    for i in [0, 7, 20] {
        let force = accelerations[i] * bodies[i].1;
        for axis in [DVec2::X, DVec2::Y] {
            let moved = |sign: f64| {
                let mut moved = bodies.clone();
                moved[i].0 += axis * (sign * delta);
                potential_with(&moved)
            };
            let gradient = (moved(1.0) - moved(-1.0)) / (2.0 * delta);
            assert!(
                (-gradient - force.dot(axis)).abs() < 1e-6 * force.length(),
                "body {i} along {axis}: −∂U/∂x = {} N against the motion's {} N",
                -gradient,
                force.dot(axis)
            );
        }
    }
}

/// The probe follows the law: at a point among the bodies, the fields it reads act on a
/// test body of 0.8 kg and 3e-6 C with the force that body feels when placed there (to
/// 1e-12 of the scale of its pair forces), and its potentials times the test body's mass
/// and charge are what the body adds to the books' potential energy (to 1e-12 of the
/// books' sums, whose difference that is).
#[test]
fn the_probe_follows_the_law() {
    let bodies = bodies();
    let positions: Vec<DVec2> = bodies.iter().map(|b| b.0).collect();
    let (point, mass, charge) = (DVec2::new(0.3, 1.1), 0.8, 3e-6);
    let probe = field_at(&scene_of(&bodies, PairForces::Direct), &positions, point);
    let mut with_test = bodies.clone();
    with_test.push((point, mass, charge));
    let (force, scale) = force_on(&with_test, bodies.len());
    let felt = probe.gravity * mass + probe.electric * charge;
    assert!(
        felt.distance(force) < 1e-12 * scale,
        "the probe's fields give {felt} N, the law {force} N"
    );
    let books = |bodies: &[(DVec2, f64, f64)]| {
        Simulation::new(&scene_of(bodies, PairForces::Direct))
            .expect("a valid scene")
            .diagnostics()
            .energy
    };
    let (before, after) = (books(&bodies), books(&with_test));
    for (what, probed, before, after) in [
        (
            "gravitation",
            probe.gravitational_potential * mass,
            before.gravitation,
            after.gravitation,
        ),
        (
            "Coulomb",
            probe.electric_potential * charge,
            before.electrostatic,
            after.electrostatic,
        ),
    ] {
        // The difference of two sums keeps the digits of the larger, not of itself.
        let added = after - before;
        assert!(
            (probed - added).abs() < 1e-12 * (before.abs() + after.abs()),
            "{what}: the probe's potential gives {probed} J, the books add {added} J"
        );
    }
}
