//! Plummer softening (`[world] softening = ε`): both pair laws read r² + ε² where they
//! read r², so a pair at distance r pulls with G m₁ m₂ r / (r² + ε²)^{3/2} and its
//! potential energy is −G m₁ m₂ / √(r² + ε²). Tested against closed forms: circular
//! orbits whose rate the softened law gives (a pair, summed one pair at a time, and a
//! ring of 24, summed in SIMD lanes), the energy of a close pass through the softened
//! core, the probe's fields, and the tree against the softened direct sum.

use std::f64::consts::PI;

use physics::{DVec2, Integrator, PairForces, Particle, Scene, Simulation, World, field_at};

/// A world of gravitation alone, G = 1, softened by `softening`.
fn softened_world(softening: f64) -> World {
    let mut world = World::weightless();
    world.gravitational_constant = 1.0;
    world.electrostatics = false;
    world.softening = softening;
    world
}

/// Runs `scene` under RK4 at `time_step` to `until` and returns the positions.
fn positions_at(mut scene: Scene, time_step: f64, until: f64) -> Vec<DVec2> {
    scene.simulation.integrator = Integrator::Rk4;
    scene.simulation.time_step = time_step;
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    simulation.step_to(until).expect("no failure");
    simulation.positions().to_vec()
}

/// Two stars of 1 kg, 1 m apart, ε = 0.5 m, each on the circle about their centre at
/// the speed the softened law gives: the relative orbit turns at ω² = G (m₁ + m₂) /
/// (d² + ε²)^{3/2} (1.196 rad/s; the exact law's √2 would put them 1.4 m off after a
/// period). After one period both are back where they started, to 1e-8 m (RK4 at
/// 1 ms: its error over a period is some 1e-12 m).
#[test]
fn a_softened_pair_circles_at_the_softened_rate() {
    let (d, softening) = (1.0_f64, 0.5_f64);
    let omega = (2.0 / (d * d + softening * softening).powf(1.5)).sqrt();
    let speed = omega * d / 2.0;
    let scene = Scene::new()
        .with_world(softened_world(softening))
        .with_particle(
            Particle::new("a", 1.0)
                .radius(1e-6)
                .position([-d / 2.0, 0.0])
                .velocity([0.0, -speed]),
        )
        .with_particle(
            Particle::new("b", 1.0)
                .radius(1e-6)
                .position([d / 2.0, 0.0])
                .velocity([0.0, speed]),
        );
    let period = 2.0 * PI / omega;
    let half = positions_at(scene.clone(), 1e-3, period / 2.0);
    assert!(
        half[1].distance(DVec2::new(-d / 2.0, 0.0)) < 1e-8,
        "half a period: b at {}",
        half[1]
    );
    let end = positions_at(scene, 1e-3, period);
    assert!(
        end[0].distance(DVec2::new(-d / 2.0, 0.0)) < 1e-8
            && end[1].distance(DVec2::new(d / 2.0, 0.0)) < 1e-8,
        "one period: {end:?}"
    );
}

/// 24 stars of 1 kg on a circle of 1 m, ε = 0.4 m (more than the 0.26 m between
/// neighbours), turning as a rigid ring: each is pulled to the centre by
/// G m Σₖ R (1 − cos θₖ) / (cₖ² + ε²)^{3/2}, cₖ = 2R sin(θₖ/2) its distance to the star
/// at angle θₖ, so the ring turns at ω² = that / R. After a quarter turn every star is
/// a quarter turn on, to 1e-8 m (RK4 at T/4000; a ring is unstable, but rounding has
/// no time to grow in a quarter turn). 24 stars are summed in SIMD lanes (more than
/// 16) with padded tails; the tree at a tiny opening angle opens everything and sums
/// the same pairs, also with `collisions = false` (a step with nothing to strike skips
/// the impact search).
#[test]
fn a_softened_ring_turns_rigidly_at_the_softened_rate() {
    let (n, radius, softening) = (24_u32, 1.0_f64, 0.4_f64);
    let inward: f64 = (1..n)
        .map(|k| {
            let theta = 2.0 * PI * f64::from(k) / f64::from(n);
            let chord2 = 2.0 * radius * radius * (1.0 - theta.cos());
            radius * (1.0 - theta.cos()) / (chord2 + softening * softening).powf(1.5)
        })
        .sum();
    let omega = (inward / radius).sqrt();
    let mut scene = Scene::new().with_world(softened_world(softening));
    let at = |k: u32, turned: f64| {
        let theta = 2.0 * PI * f64::from(k) / f64::from(n) + turned;
        DVec2::new(radius * theta.cos(), radius * theta.sin())
    };
    for k in 0..n {
        let p = at(k, 0.0);
        scene.particles.push(
            Particle::new(format!("s{k}"), 1.0)
                .radius(1e-6)
                .position([p.x, p.y])
                .velocity([-omega * p.y, omega * p.x]),
        );
    }
    let quarter = PI / 2.0 / omega;
    for (pair_forces, collisions) in [
        (PairForces::Direct, true),
        (PairForces::Tree, true),
        (PairForces::Tree, false),
    ] {
        let mut scene = scene.clone();
        scene.simulation.pair_forces = pair_forces;
        scene.world.collisions = collisions;
        scene.simulation.opening_angle = 1e-9;
        let end = positions_at(scene, quarter / 1000.0, quarter);
        for (k, p) in (0..n).zip(&end) {
            let expected = at(k, PI / 2.0);
            assert!(
                p.distance(expected) < 1e-8,
                "{pair_forces:?}: star {k} at {p}, expected {expected}"
            );
        }
    }
}

/// Two stars pass 0.2 m apart, inside each other's softened core (ε = 0.3 m): the
/// energy the diagnostics report, kinetic plus −G m₁ m₂ / √(r² + ε²), stays what it
/// was to 1e-9 of the kinetic energy through the pass (RK4 at 0.1 ms; the exact law's
/// −1/r would be off by 1.6 J at the closest point against 1 J of motion), with the
/// direct sum and with the tree.
#[test]
fn the_energy_of_a_pass_through_the_softened_core_is_conserved() {
    for pair_forces in [PairForces::Direct, PairForces::Tree] {
        let mut scene = Scene::new()
            .with_world(softened_world(0.3))
            .with_particle(
                Particle::new("a", 1.0)
                    .radius(1e-6)
                    .position([-2.0, 0.1])
                    .velocity([1.0, 0.0]),
            )
            .with_particle(
                Particle::new("b", 1.0)
                    .radius(1e-6)
                    .position([2.0, -0.1])
                    .velocity([-1.0, 0.0]),
            );
        scene.simulation.pair_forces = pair_forces;
        scene.simulation.time_step = 1e-4;
        let mut simulation = Simulation::new(&scene).expect("a valid scene");
        let start = simulation.diagnostics().energy;
        let expected_potential = -1.0 / (4.0_f64 * 4.0 + 0.2 * 0.2 + 0.3 * 0.3).sqrt();
        assert!(
            (start.gravitation - expected_potential).abs() < 1e-15,
            "{pair_forces:?}: {} against {expected_potential}",
            start.gravitation
        );
        assert_the_pass_keeps_its_energy(&mut simulation, 0.3, &format!("{pair_forces:?}"));
    }
}

/// Coulomb's law is softened as gravitation is, in the force, the potential energy and the
/// probe alike: a pair of ±1e-5 C (1 kg each, ε = 0.3 m) passing 0.2 m apart attract
/// with k q₁ q₂ r / (r² + ε²)^{3/2}, and the energy the diagnostics report, kinetic plus
/// k q₁ q₂ / √(r² + ε²), stays what it was to 1e-9 of the kinetic energy through the pass
/// (RK4 at 0.1 ms). A potential left unsoftened would read −3.8 J too much in the core
/// against 1 J of motion. The starting potential is the closed form's to 1e-15 J, and the
/// probe between them reads the softened field and potential of both charges to 1e-15 of
/// their size.
#[test]
fn coulombs_law_is_softened_in_force_energy_and_probe_alike() {
    let softening = 0.3;
    let mut world = World::weightless();
    world.gravitation = false;
    world.softening = softening;
    let k = world.coulomb_constant;
    let q = 1e-5;
    let mut scene = Scene::new()
        .with_world(world)
        .with_particle(
            Particle::new("a", 1.0)
                .radius(1e-6)
                .charge(q)
                .position([-2.0, 0.1])
                .velocity([1.0, 0.0]),
        )
        .with_particle(
            Particle::new("b", 1.0)
                .radius(1e-6)
                .charge(-q)
                .position([2.0, -0.1])
                .velocity([-1.0, 0.0]),
        );
    scene.simulation.time_step = 1e-4;
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    let start = simulation.diagnostics().energy;
    let expected_potential =
        -k * q * q / (4.0_f64 * 4.0 + 0.2 * 0.2 + softening * softening).sqrt();
    assert!(
        (start.electrostatic - expected_potential).abs() < 1e-15,
        "{} J against {expected_potential} J",
        start.electrostatic
    );
    // The probe at the midpoint, 2.0025 m from each (√(2² + 0.1²)): both charges' fields
    // point from a (+q) towards b (−q), each k q d / (d² + ε²)^{3/2}.
    let probe = field_at(
        &scene,
        &[DVec2::new(-2.0, 0.1), DVec2::new(2.0, -0.1)],
        DVec2::ZERO,
    );
    let d = DVec2::new(2.0, -0.1);
    let softened = (d.length_squared() + softening * softening).sqrt();
    let expected_field = d * (2.0 * k * q / softened.powi(3));
    assert!(
        probe.electric.distance(expected_field) < 1e-15 * expected_field.length(),
        "field {} against {expected_field}",
        probe.electric
    );
    assert!(
        probe.electric_potential.abs() < 1e-15 * k * q / softened,
        "potential {} V at the midpoint",
        probe.electric_potential
    );
    assert_the_pass_keeps_its_energy(&mut simulation, softening, "Coulomb");
}

/// Runs a pair's pass through the softened core (4 s, sampled every 0.1 s): the energy
/// the diagnostics report stays what it was to 1e-9 of the kinetic energy, and the pair
/// comes closer than `core`.
fn assert_the_pass_keeps_its_energy(simulation: &mut Simulation, core: f64, what: &str) {
    let start = simulation.diagnostics().energy;
    let mut closest = f64::INFINITY;
    for k in 1..=40 {
        simulation.step_to(0.1 * f64::from(k)).expect("no failure");
        let x = simulation.positions();
        closest = closest.min(x[0].distance(x[1]));
        let energy = simulation.diagnostics().energy;
        assert!(
            (energy.total() - start.total()).abs() < 1e-9 * start.kinetic,
            "{what}, t = {}: {} J against {} J",
            simulation.time(),
            energy.total(),
            start.total()
        );
    }
    assert!(
        closest < core,
        "{what}: the pass reached the core ({closest} m)"
    );
}

/// The probe reads the softened laws: one body of 2 kg (G = 1, ε = 1 m) seen from 1 m
/// away pulls with G m r / (r² + ε²)^{3/2} = 2/2^{3/2} and has the potential −G m /
/// √(r² + ε²) = −2/√2; at the body itself the field is 0 and the potential −G m/ε, as
/// for a smeared-out body. To 1e-15.
#[test]
fn the_probe_reads_the_softened_laws() {
    let scene = Scene::new()
        .with_world(softened_world(1.0))
        .with_particle(Particle::new("a", 2.0).radius(1e-6));
    let here = field_at(&scene, &[DVec2::ZERO], DVec2::new(1.0, 0.0));
    assert!(
        (here.gravity.x + 2.0 / 2.0_f64.powf(1.5)).abs() < 1e-15,
        "{}",
        here.gravity
    );
    assert!((here.gravitational_potential + 2.0 / 2.0_f64.sqrt()).abs() < 1e-15);
    let on = field_at(&scene, &[DVec2::ZERO], DVec2::ZERO);
    assert_eq!(on.gravity, DVec2::ZERO);
    assert!(
        (on.gravitational_potential + 2.0).abs() < 1e-15,
        "{}",
        on.gravitational_potential
    );
}

/// The tree follows the softened law near and far: on a cluster of 3,000 bodies in a
/// disc of 10 m with ε = 0.3 m (about the distance between neighbours at the edge), its
/// normalised RMS force error against the softened direct sum is under 1e-3, as without
/// softening, and its potential energy is within 1e-4 of the softened pair sum.
#[test]
fn the_tree_follows_the_softened_direct_sum() {
    let mut scene = Scene::new().with_world(softened_world(0.3));
    for i in 0..3000_u32 {
        let f = f64::from(i);
        let r = 10.0 * (f / 3000.0).powf(0.75) + 1e-3;
        let angle = f * 2.399_963_229_728_653;
        scene.particles.push(
            Particle::new(format!("b{i}"), 1.0 + (f * 0.618_034).fract())
                .radius(1e-6)
                .position([r * angle.cos(), r * angle.sin()]),
        );
    }
    let mut tree_scene = scene.clone();
    tree_scene.simulation.pair_forces = PairForces::Tree;
    let (direct, tree) = (
        Simulation::new(&scene).expect("valid"),
        Simulation::new(&tree_scene).expect("valid"),
    );
    let (a, b) = (direct.accelerations(), tree.accelerations());
    let error: f64 = a.iter().zip(&b).map(|(a, b)| a.distance_squared(*b)).sum();
    let size: f64 = a.iter().map(|a| a.length_squared()).sum();
    let rms = (error / size).sqrt();
    eprintln!("softened tree against direct: {rms:e}");
    assert!(rms < 1e-3, "normalised RMS error {rms}");
    let (exact, summed) = (
        direct.diagnostics().energy.gravitation,
        tree.diagnostics().energy.gravitation,
    );
    let energy_error = ((summed - exact) / exact).abs();
    eprintln!("softened tree potential energy: {energy_error:e}");
    assert!(energy_error < 1e-4, "{summed} J against {exact} J");
}

/// The two cluster examples, softened: each disc is built with no momentum of its own
/// (the colliding discs' cancel), to rounding of Σ m|v|; and the colliding discs keep
/// their total energy within 1e-3 over their first 5 s (measured: 4.6e-5; over 40 s,
/// 4e-4, and the 20,000-star cluster 1.1e-3). With the exact law (no softening) the
/// same 5 s multiply the kinetic energy by 359 and the total energy by 273: close
/// passes fling stars out.
#[test]
fn the_cluster_examples_have_no_drift_and_keep_their_energy() {
    for name in ["star-cluster", "colliding-discs"] {
        let scene = physics::example(name)
            .expect("the example exists")
            .scene()
            .expect("it loads");
        assert!(
            scene.world.softening > 0.0 && !scene.world.collisions,
            "{name}"
        );
        let simulation = Simulation::new(&scene).expect("valid");
        let scale: f64 = scene
            .particles
            .iter()
            .map(|p| p.mass * p.velocity.to_dvec2().length())
            .sum();
        let momentum = simulation.diagnostics().momentum;
        assert!(
            momentum.length() < 1e-12 * scale,
            "{name}: momentum {momentum} against Σ m|v| = {scale}"
        );
    }
    let scene = physics::example("colliding-discs")
        .expect("the example exists")
        .scene()
        .expect("it loads");
    let mut simulation = Simulation::new(&scene).expect("valid");
    let start = simulation.diagnostics().energy;
    simulation.step_to(5.0).expect("no failure");
    let end = simulation.diagnostics().energy;
    let drift = (end.total() - start.total()).abs() / start.total().abs();
    eprintln!("colliding discs: energy drift {drift:e} over 5 s");
    assert!(
        drift < 1e-3,
        "{} J against {} J",
        end.total(),
        start.total()
    );
}
