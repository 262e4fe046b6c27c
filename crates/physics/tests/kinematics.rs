//! Constant-acceleration motion against x = x0 + v0 t + a t²/2 (the paper's 4.2).

mod common;

use common::{example_scene, relative};
use physics::{DVec2, Integrator, Particle, Scene, Simulation, World};

fn kinematics(x0: DVec2, v0: DVec2, a: DVec2, t: f64) -> DVec2 {
    x0 + v0 * t + 0.5 * a * t * t
}

/// Verlet, RK4 and PEFRL are exact for constant acceleration: what remains is rounding. Error is
/// measured relative to the size of the motion, |x0| + |v0 t| + |a t²/2| per component:
/// y here is 120 + 400 − 490 = 30 at t = 10, and rounding of the large terms is what
/// 10⁴ steps accumulate (about 10⁴ × 1e-16 of them). Any truncation error of a
/// non-exact method would be ~1e-3 of the motion.
#[test]
fn constant_acceleration_is_exact_with_verlet_rk4_and_pefrl() {
    let (x0, v0, a) = (
        DVec2::new(-3.25, 120.5),
        DVec2::new(17.5, 40.0),
        DVec2::new(0.75, -9.81),
    );
    for integrator in [Integrator::Verlet, Integrator::Rk4, Integrator::Pefrl] {
        let scene = Scene::new()
            .with_integrator(integrator, 0.001)
            .with_particle(
                Particle::new("P", 2.0)
                    .position(x0)
                    .velocity(v0)
                    .acceleration([0.75, 0.0]),
            );
        let mut simulation = Simulation::new(&scene).unwrap();
        for t in [0.5, 1.7, 4.0, 10.0] {
            simulation.step_to(t).unwrap();
            let expected = kinematics(x0, v0, a, t);
            let size = x0.abs() + v0.abs() * t + a.abs() * (0.5 * t * t);
            let actual = simulation.positions()[0];
            for (got, want, size) in [
                (actual.x, expected.x, size.x),
                (actual.y, expected.y, size.y),
            ] {
                assert!(
                    (got - want).abs() < 1e-12 * size,
                    "{integrator} at t = {t}: {got} vs {want}"
                );
            }
            let velocity = simulation.velocities()[0];
            let expected_velocity = v0 + a * t;
            assert!(
                (velocity - expected_velocity).length() < 1e-12 * expected_velocity.length(),
                "{integrator} velocity at t = {t}: {velocity} vs {expected_velocity}"
            );
        }
    }
}

/// The paper's Cartesian table: x at its times, theory from the constant-acceleration
/// formula; the paper reached 0.3–0.4 %, we require 1e-9 relative.
#[test]
fn paper_cartesian_table_within_1e_9() {
    let scene = example_scene("kinematics-cartesian");
    let mut simulation = Simulation::new(&scene).unwrap();
    for t in [1.4, 2.2, 3.4, 4.5, 5.5, 6.2, 7.2, 8.1, 9.3, 10.2] {
        simulation.step_to(t).unwrap();
        let theory = 7.893 + 9.342 * t + 0.5 * 1.087 * t * t;
        let x = simulation.positions()[0].x;
        assert!(
            relative(x, theory) < 1e-9,
            "t = {t}: x = {x}, theory {theory}"
        );
    }
}

/// The paper's polar table: |r| at its times (its errors reached 1.02 %).
#[test]
fn paper_polar_table_within_1e_9() {
    let scene = example_scene("kinematics-polar");
    let mut simulation = Simulation::new(&scene).unwrap();
    let polar = |m: f64, degrees: f64| DVec2::from_angle(degrees.to_radians()) * m;
    let (r0, v0, a) = (
        polar(32.725, 45.0),
        polar(7.834, 120.0),
        polar(2.087, 240.0),
    );
    let paper_theory = [
        34.525, 35.764, 35.974, 35.805, 35.782, 37.627, 40.781, 49.369, 55.476, 71.116,
    ];
    let times = [1.0, 2.2, 3.3, 4.1, 5.1, 6.4, 7.2, 8.4, 9.0, 10.2];
    for (t, paper) in times.into_iter().zip(paper_theory) {
        simulation.step_to(t).unwrap();
        let theory = kinematics(r0, v0, a, t).length();
        let r = simulation.positions()[0].length();
        assert!(
            relative(r, theory) < 1e-9,
            "t = {t}: |r| = {r}, theory {theory}"
        );
        // Our theory agrees with the paper's printed theory column to its 3 decimals.
        assert!(
            (theory - paper).abs() < 6e-4,
            "t = {t}: theory {theory} vs paper's {paper}"
        );
    }
}

/// Samples land exactly on the requested instant, whatever the step.
#[test]
fn step_to_lands_exactly_on_the_requested_time() {
    let scene = Scene::new()
        .with_world(World::weightless())
        .with_integrator(Integrator::Rk4, 0.003)
        .with_particle(Particle::new("P", 1.0).velocity([1.0, 0.0]));
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.step_to(0.1).unwrap();
    assert_eq!(
        simulation.time().to_bits(),
        0.1_f64.to_bits(),
        "time is exactly 0.1"
    );
    assert!(
        (simulation.positions()[0].x - 0.1).abs() < 1e-15,
        "x = v t at exactly t = 0.1"
    );
}

/// A particle under constant acceleration stepped `h` at a time by `integrator` is, at
/// every multiple t of the step, at x₀ + v₀t + a·t(t + `sign`·h)/2 — the closed form of
/// the Euler methods. To 1e-12 relative (rounding of 100 steps).
fn assert_euler_closed_form(integrator: Integrator, sign: f64) {
    let h = 0.1;
    let (x0, v0, a) = (
        DVec2::new(7.893, -2.0),
        DVec2::new(9.342, 4.0),
        DVec2::new(1.087, -9.81),
    );
    let scene = Scene::new()
        .with_world(World::weightless())
        .with_integrator(integrator, h)
        .with_particle(
            Particle::new("P", 1.0)
                .position(x0)
                .velocity(v0)
                .acceleration(a),
        );
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    for n in 1..=100 {
        simulation.step().expect("a step");
        let t = f64::from(n) * h;
        let theory = x0 + v0 * t + a * (0.5 * t * (t + sign * h));
        let x = simulation.positions()[0];
        assert!(
            x.distance(theory) < 1e-12 * theory.length(),
            "{integrator}, t = {t}: x = {x}, the closed form {theory}"
        );
    }
}

/// Explicit Euler (position moved with the old velocity), the paper's method, at its step
/// of 0.1 s: x₀ + v₀t + a·t(t − h)/2 — the exact path less a·t·h/2, the paper's 0.3–1 %
/// error.
#[test]
fn explicit_euler_follows_its_own_closed_form() {
    assert_euler_closed_form(Integrator::Euler, -1.0);
}

/// Semi-implicit Euler (velocity first, then the position with the new velocity):
/// x₀ + v₀t + a·t(t + h)/2, the exact path plus a·t·h/2, the mirror image.
#[test]
fn semi_implicit_euler_follows_its_own_closed_form() {
    assert_euler_closed_form(Integrator::SemiImplicitEuler, 1.0);
}

/// What the inspector shows of one particle: a 2 kg ball thrown at (3, 4) m/s under
/// g = 9.81 m/s² reads, after 0.5 s, v = (3, 4 − g/2), speed |v|, kinetic energy ½ m |v|²,
/// momentum m v and acceleration (0, −g), each to 1e-12; a fixed particle has no kinetic
/// energy or momentum. (The system's totals are tested elsewhere; the per-particle
/// readout had no test of its own.)
#[test]
fn a_particle_reads_half_m_v_squared_and_m_v() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("ball", 2.0).velocity([3.0, 4.0]))
        .with_particle(Particle::new("post", 5.0).position([10.0, 0.0]).fixed());
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    simulation.step_to(0.5).expect("finite");
    let accelerations = simulation.accelerations();
    let ball = simulation.particle(0, &accelerations);
    let v = DVec2::new(3.0, 4.0 - 9.81 * 0.5);
    assert!(ball.velocity.distance(v) < 1e-12, "{}", ball.velocity);
    assert!(
        (ball.speed - v.length()).abs() < 1e-12,
        "speed {}",
        ball.speed
    );
    let kinetic = 0.5 * 2.0 * v.length_squared();
    assert!(
        (ball.kinetic_energy - kinetic).abs() < 1e-12,
        "kinetic energy {} J against {kinetic} J",
        ball.kinetic_energy
    );
    assert!(
        ball.momentum.distance(v * 2.0) < 1e-12,
        "momentum {}",
        ball.momentum
    );
    assert!(
        ball.acceleration.distance(DVec2::new(0.0, -9.81)) < 1e-12,
        "{}",
        ball.acceleration
    );
    let post = simulation.particle(1, &accelerations);
    assert_eq!(
        (post.kinetic_energy, post.momentum),
        (0.0, DVec2::ZERO),
        "a fixed particle"
    );
}
