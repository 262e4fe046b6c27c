//! Every integrator converges at its order: halving the step divides the error by 2^order.
//!
//! A bound on the error at one step size catches a wrong method only when the bound is
//! tight; an order test catches a typo in a coefficient whatever the bound, because a
//! broken method falls to a lower order (a PEFRL coefficient off in its fourth digit
//! still integrates, to second order). Two problems with closed forms: a circular orbit
//! about a fixed body (an inverse-square force, nonlinear in the position) and a lightly
//! damped spring (a force that depends on the velocity too). The error is measured after
//! a fixed time at a step h and at h/2 (and h/4), and the ratio of successive errors must
//! be within 10 % of 2^order. The steps are chosen where the leading error term dominates
//! and rounding (some 1e-15 per step) is far below the error.

use std::f64::consts::PI;

use physics::{DVec2, Integrator, Particle, Scene, Simulation, Spring, Tie, World};

/// The circular orbit: a body of 1 kg at 1 m from a fixed body with G M = 1, moving at
/// 1 m/s, turns at 1 rad/s.
fn orbit(integrator: Integrator, time_step: f64) -> Scene {
    let mut world = World::weightless();
    world.gravitational_constant = 1.0;
    world.electrostatics = false;
    let mut scene = Scene::new()
        .with_world(world)
        .with_integrator(integrator, time_step)
        .with_particle(Particle::new("sun", 1.0).radius(1e-3).fixed())
        .with_particle(
            Particle::new("planet", 1.0)
                .radius(1e-3)
                .position([1.0, 0.0])
                .velocity([0.0, 1.0]),
        );
    // dopri5 at a step it never rejects: its fifth-order solution at a fixed step.
    scene.simulation.tolerance = 1e3;
    scene
}

/// |position − closed form| of the orbiting body after `until` seconds.
fn orbit_error(integrator: Integrator, time_step: f64, until: f64) -> f64 {
    let mut simulation = Simulation::new(&orbit(integrator, time_step)).expect("a valid scene");
    simulation.step_to(until).expect("the orbit stays finite");
    let exact = DVec2::from_angle(until);
    simulation.positions()[1].distance(exact)
}

/// The damped spring: 1 kg on a spring of k = 4 N/m and b = 0.4 N·s/m, released at rest
/// 1 m from its natural length: u = e^(−γt)(cos ωt + (γ/ω) sin ωt), γ = b/2m,
/// ω = √(k/m − γ²).
fn damped_spring_error(integrator: Integrator, time_step: f64, until: f64) -> f64 {
    let (mass, stiffness, damping, natural_length) = (1.0_f64, 4.0_f64, 0.4_f64, 1.0_f64);
    let mut scene = Scene::new()
        .with_world(World::weightless())
        .with_integrator(integrator, time_step)
        .with_particle(Particle::new("bob", mass).position([natural_length + 1.0, 0.0]))
        .with_spring(
            Spring::new("spring", [0.0, 0.0], "bob", stiffness, natural_length).damping(damping),
        );
    scene.world.gravitation = false;
    scene.simulation.tolerance = 1e3;
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    simulation.step_to(until).expect("the spring stays finite");
    let gamma = damping / (2.0 * mass);
    let omega = (stiffness / mass - gamma * gamma).sqrt();
    let u =
        (-gamma * until).exp() * ((omega * until).cos() + gamma / omega * (omega * until).sin());
    (simulation.positions()[0].x - natural_length - u).abs()
}

/// Errors at h, h/2 and h/4; each successive ratio within 10 % of 2^order.
fn assert_order(
    what: &str,
    integrator: Integrator,
    order: i32,
    time_step: f64,
    error: impl Fn(Integrator, f64) -> f64,
) {
    let errors: Vec<f64> = (0..3)
        .map(|k| error(integrator, time_step / f64::from(1 << k)))
        .collect();
    let expected = 2.0_f64.powi(order);
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!(
            (ratio / expected - 1.0).abs() < 0.1,
            "{what}, {integrator}: errors {errors:?} at h = {time_step}, h/2, h/4: ratio {ratio:.3}, order {order} wants {expected}"
        );
    }
}

/// The orders of the table in `integrators/mod.rs` on the orbit: a quarter turn, and
/// ten turns for dopri5, whose fifth-order error constant is so small (Dormand and Prince
/// chose the coefficients to make it so) that over a quarter turn the sixth-order term
/// still shows at every step above rounding (ratios 38 and 35 for 32).
#[test]
fn every_integrator_converges_at_its_order_on_a_circular_orbit() {
    let (quarter, ten_turns) = (PI / 2.0, 20.0 * PI);
    for (integrator, order, time_step, until) in [
        (Integrator::Euler, 1, 1.0 / 4096.0, quarter),
        (Integrator::SemiImplicitEuler, 1, 1.0 / 4096.0, quarter),
        (Integrator::Verlet, 2, 1.0 / 256.0, quarter),
        (Integrator::Rk4, 4, 1.0 / 16.0, quarter),
        (Integrator::Pefrl, 4, 1.0 / 16.0, quarter),
        (Integrator::Dopri5, 5, 1.0 / 32.0, ten_turns),
    ] {
        assert_order("orbit", integrator, order, time_step, |i, h| {
            orbit_error(i, h, until)
        });
    }
}

/// The same on the damped spring, whose force depends on the velocity: each fixed-step
/// method keeps its order there too (PEFRL only because its kicks are solved to fourth
/// order; one Euler kick per stage made it first order). Not dopri5: on this spring the
/// sixth-order term shows down to rounding (ratios 42, 38, 35, 35 from h = 1/16), so no
/// step pair gives its order cleanly; the orbit holds it.
#[test]
fn every_integrator_converges_at_its_order_on_a_damped_spring() {
    for (integrator, order, time_step) in [
        (Integrator::Euler, 1, 1.0 / 4096.0),
        (Integrator::SemiImplicitEuler, 1, 1.0 / 4096.0),
        (Integrator::Verlet, 2, 1.0 / 256.0),
        (Integrator::Rk4, 4, 1.0 / 32.0),
        (Integrator::Pefrl, 4, 1.0 / 16.0),
    ] {
        assert_order("damped spring", integrator, order, time_step, |i, h| {
            damped_spring_error(i, h, 2.0)
        });
    }
}

/// |x − closed form| after 1 s of a 1 kg ball whirled at 2 rad/s on a 1 m rod about a
/// fixed point, with no field: x = (cos 2t, sin 2t). The rod's pull, m ω² L, holds the
/// centripetal v²/L, so it depends on the velocity as damping does.
fn whirl_error(integrator: Integrator, time_step: f64) -> f64 {
    let mut scene = Scene::new()
        .with_world(World::no_forces())
        .with_integrator(integrator, time_step)
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(0.05)
                .position([1.0, 0.0])
                .velocity([0.0, 2.0]),
        )
        .with_tie(Tie::rod("rod", [0.0, 0.0], "ball", 1.0));
    scene.simulation.tolerance = 1e3;
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    simulation.step_to(1.0).expect("the whirl stays finite");
    simulation.positions()[0].distance(DVec2::from_angle(2.0))
}

/// The same on a rod, whose pull depends on the velocity: the methods above first order
/// keep their order (the projection onto the rod's length after each step takes the
/// radial error; what is left is the phase, at the method's order).
#[test]
fn the_higher_order_integrators_keep_their_order_on_a_rod() {
    for (integrator, order, time_step) in [
        (Integrator::Verlet, 2, 1.0 / 256.0),
        (Integrator::Rk4, 4, 1.0 / 32.0),
        (Integrator::Pefrl, 4, 1.0 / 64.0),
    ] {
        assert_order("whirl on a rod", integrator, order, time_step, whirl_error);
    }
}
