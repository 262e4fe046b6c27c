//! Resting and sliding contact on ramps (the paper's 4.4) against the inclined plane:
//! along a frictionless ramp at θ a particle accelerates at g sin θ; with friction μ at
//! g (sin θ − μ cos θ) while sliding, and not at all while |tan θ| ≤ μ.

mod common;

use common::example_scene;
use physics::{DVec2, Particle, Ramp, Scene, Simulation, World};

const G: f64 = 9.81;

/// A 6 m ramp at `angle` degrees centred on the origin, 0.1 m thick, and a 0.25 m ball at
/// rest touching its top face at the middle.
fn ball_on_ramp(angle: f64, friction: f64) -> Scene {
    let world = World::gravity_only();
    ball_on_ramp_in(world, angle, friction)
}

fn ball_on_ramp_in(world: World, angle: f64, friction: f64) -> Scene {
    let direction = DVec2::from_angle(angle.to_radians());
    Scene::new()
        .with_world(world)
        .with_ramp(
            Ramp::new("ramp", direction * -3.0, direction * 3.0)
                .thickness(0.1)
                .friction(friction),
        )
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(0.25)
                .position(direction.perp() * 0.3),
        )
}

/// Table 4.4: the ramps at −60…60° of the example. After 0.5 s each ball has moved
/// ½ (g·u) u t² along its ramp (u its direction): |a| = g |sin θ|, directed along the
/// ramp, to 1e-9.
#[test]
fn paper_table_4_4_accelerations() {
    let scene = example_scene("ramp-slides");
    let mut simulation = Simulation::new(&scene).unwrap();
    let start: Vec<DVec2> = simulation.positions().to_vec();
    let t = 0.5;
    simulation.step_to(t).unwrap();
    let accelerations = simulation.accelerations();
    for (k, angle) in [-60.0_f64, -45.0, -30.0, 0.0, 30.0, 45.0, 60.0]
        .into_iter()
        .enumerate()
    {
        let along = DVec2::from_angle(angle.to_radians());
        let theory = along * DVec2::new(0.0, -G).dot(along);
        let a = accelerations[k];
        assert!(
            a.distance(theory) < 1e-9,
            "{angle}°: a = {a}, theory {theory}"
        );
        assert!(
            (a.length() - G * angle.to_radians().sin().abs()).abs() < 1e-9,
            "{angle}°: |a|"
        );
        let moved = simulation.positions()[k] - start[k];
        assert!(
            moved.distance(theory * (0.5 * t * t)) < 1e-9,
            "{angle}°: moved {moved}"
        );
    }
}

/// Sliding neither sinks into the ramp nor leaves it, and the normal force does no work.
#[test]
fn a_sliding_ball_stays_on_the_surface_and_conserves_energy() {
    let mut simulation = Simulation::new(&ball_on_ramp(-35.0, 0.0)).unwrap();
    let energy = simulation.diagnostics().energy.total();
    let normal = DVec2::from_angle((-35.0_f64).to_radians()).perp();
    for k in 1..=50 {
        simulation.step_to(f64::from(k) * 0.01).unwrap();
        let height = simulation.positions()[0].dot(normal);
        assert!(
            (height - 0.3).abs() < 1e-12,
            "t = {}: {height} m from the ramp's line",
            simulation.time()
        );
        assert!(
            simulation.velocities()[0].dot(normal).abs() < 1e-12,
            "no normal velocity"
        );
    }
    let drift = (simulation.diagnostics().energy.total() - energy).abs();
    assert!(drift < 1e-9 * energy.abs(), "energy changed by {drift}");
}

/// Friction: sliding at g (sin θ − μ cos θ) when tan θ > μ, held still when tan θ ≤ μ.
#[test]
fn friction_slows_or_holds() {
    for (angle, friction) in [
        (30.0_f64, 0.5),
        (30.0, 0.6),
        (-45.0, 1.01),
        (-45.0, 0.2),
        (60.0, 1.5),
        (10.0, 0.0),
    ] {
        let mut simulation = Simulation::new(&ball_on_ramp(angle, friction)).unwrap();
        let start = simulation.positions()[0];
        let t = 0.4;
        simulation.step_to(t).unwrap();
        let theta = angle.to_radians();
        let slope = theta.tan().abs();
        let moved = simulation.positions()[0] - start;
        if slope <= friction {
            assert!(
                moved.length() < 1e-12,
                "{angle}° μ = {friction}: held, but moved {moved}"
            );
            assert!(
                simulation.accelerations()[0].length() < 1e-12,
                "{angle}° μ = {friction}: no acceleration"
            );
        } else {
            let magnitude = G * (theta.sin().abs() - friction * theta.cos());
            let downhill = DVec2::from_angle(theta) * -theta.sin().signum();
            let theory = downhill * (0.5 * magnitude * t * t);
            assert!(
                moved.distance(theory) < 1e-9,
                "{angle}° μ = {friction}: moved {moved}, theory {theory}"
            );
        }
    }
}

/// A ball dropped onto a level ramp with restitution 0 comes to rest on it and stays.
#[test]
fn a_dropped_ball_comes_to_rest_without_jitter() {
    let mut scene = ball_on_ramp(0.0, 0.3);
    scene.ramps[0].restitution = 0.0;
    scene.particles[0].position = [0.5, 2.0].into();
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.step_to(2.0).unwrap();
    for k in 0..100 {
        simulation.step_to(2.0 + f64::from(k) * 0.01).unwrap();
        let (x, v) = (simulation.positions()[0], simulation.velocities()[0]);
        assert!((x.y - 0.3).abs() < 1e-12, "resting on top: y = {}", x.y);
        assert!(v.length() < 1e-12, "still: v = {v}");
    }
}

/// Kinetic friction is the same for a coupled particle (pairwise gravitation on: a single
/// particle takes part in pairwise forces but has no partner, so its motion is the
/// field's) as for a free one: on a 30° ramp with μ = 0.3 it slides at
/// g (sin θ − μ cos θ), ½ a t² along the ramp after t, to 1e-9.
#[test]
fn sliding_friction_is_the_same_free_or_coupled() {
    let (angle, friction, t) = (-30.0_f64, 0.3, 0.5);
    for coupled in [false, true] {
        let world = World {
            gravitation: coupled,
            electrostatics: false,
            ..World::default()
        };
        let mut simulation = Simulation::new(&ball_on_ramp_in(world, angle, friction)).unwrap();
        let start = simulation.positions()[0];
        simulation.step_to(t).unwrap();
        let theta = angle.to_radians();
        let magnitude = G * (theta.sin().abs() - friction * theta.cos());
        let theory = DVec2::from_angle(theta) * (0.5 * magnitude * t * t);
        let moved = simulation.positions()[0] - start;
        assert!(
            moved.distance(theory) < 1e-9,
            "coupled = {coupled}: moved {moved}, theory {theory}"
        );
    }
}

/// A ball of radius r on a straight line hits a still ramp (a segment a–b thickened to
/// a capsule of half-thickness h) with restitution 1, no gravity: the impact is where the
/// centre first comes within r + h of the segment, and the velocity reflects about the
/// surface's normal there, v' = v − 2 (v·n) n. Returns (the impact's time, the velocity
/// after it).
fn bounce_off_ramp(start: DVec2, velocity: DVec2) -> (f64, DVec2) {
    bounce_off(Ramp::new("ramp", [0.0, 0.0], [2.0, 0.0]), start, velocity)
}

/// [`bounce_off_ramp`] off any ramp of thickness 0.2 m.
fn bounce_off(ramp: Ramp, start: DVec2, velocity: DVec2) -> (f64, DVec2) {
    let scene = Scene::new()
        .with_world(World::no_forces())
        .with_ramp(ramp.thickness(0.2).restitution(1.0))
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(0.1)
                .position(start.to_array())
                .velocity(velocity.to_array()),
        );
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    simulation.record_impacts();
    simulation.step_to(2.0).expect("steps");
    let impacts = simulation.take_impacts();
    assert_eq!(impacts.len(), 1, "one impact: {impacts:?}");
    (impacts[0].time, simulation.velocities()[0])
}

/// The ramp's other faces: from below, the normal points down (the ball comes back
/// down); at a rounded end, the normal points from the end's centre through the
/// contact, so a ball along the ramp's axis comes straight back and one offset by
/// (r + h)/√2 meets the end at 45° and leaves at right angles, v' = (0, v). Each against
/// the closed-form contact instant (distance to go / speed) to 1e-9 s and the reflected
/// velocity to 1e-9 m/s. The other ramp tests strike the top face; this one holds the
/// underside and the ends to the impulse formula. It kills a mutant the mutation run
/// found alive: the ramp's bounding box shrunk on its low side (`a.min(b) − r → + r`),
/// which let a ball from below pass straight through the ramp; a normal flipped under
/// the ramp fails it too.
#[test]
fn a_ball_bounces_off_a_ramps_underside_and_its_rounded_ends() {
    let reach = 0.1 + 0.1; // r + h
    let (t, v) = bounce_off_ramp(DVec2::new(1.0, -1.0), DVec2::new(0.0, 2.0));
    assert!((t - (1.0 - reach) / 2.0).abs() < 1e-9, "underside at {t}");
    assert!(v.distance(DVec2::new(0.0, -2.0)) < 1e-9, "underside: {v}");
    let (t, v) = bounce_off_ramp(DVec2::new(-1.0, 0.0), DVec2::new(2.0, 0.0));
    assert!((t - (1.0 - reach) / 2.0).abs() < 1e-9, "end on axis at {t}");
    assert!(v.distance(DVec2::new(-2.0, 0.0)) < 1e-9, "end on axis: {v}");
    let offset = reach / 2.0_f64.sqrt();
    let (t, v) = bounce_off_ramp(DVec2::new(3.0, offset), DVec2::new(-2.0, 0.0));
    assert!(
        (t - (3.0 - 2.0 - offset) / 2.0).abs() < 1e-9,
        "end at 45° at {t}"
    );
    assert!(v.distance(DVec2::new(0.0, 2.0)) < 1e-9, "end at 45°: {v}");
}

/// A ramp of zero length is a round post (a disc of radius h, which the scene allows):
/// a ball meets it where the centres are r + h apart and reflects about the line of
/// centres, head-on straight back, and at 45° off it leaving at right angles, to 1e-9.
/// A degenerate segment has no direction: the distance must not divide by its zero
/// length (with `length² ≥ 0` in place of `> 0` it gives NaN, a mutant the mutation run
/// left alive).
#[test]
fn a_ball_bounces_off_a_round_post() {
    let post = || Ramp::new("post", [0.0, 0.0], [0.0, 0.0]);
    let reach: f64 = 0.1 + 0.1;
    let (t, v) = bounce_off(post(), DVec2::new(-1.0, 0.0), DVec2::new(2.0, 0.0));
    assert!((t - (1.0 - reach) / 2.0).abs() < 1e-9, "head-on at {t}");
    assert!(v.distance(DVec2::new(-2.0, 0.0)) < 1e-9, "head-on: {v}");
    let offset = reach / 2.0_f64.sqrt();
    let (t, v) = bounce_off(post(), DVec2::new(1.0, offset), DVec2::new(-2.0, 0.0));
    assert!((t - (1.0 - offset) / 2.0).abs() < 1e-9, "at 45° at {t}");
    assert!(v.distance(DVec2::new(0.0, 2.0)) < 1e-9, "at 45°: {v}");
}

/// A surface catches a falling ball and holds it, under each integrator (Verlet and
/// dopri5 carry the acceleration at a step's end into the next step, rk4 does not): a
/// 0.25 m ball dropped from rest 1 m above a level ramp's top face (at y = 0.05) with
/// restitution 0 lands at √(2 · 1 m / g) = 0.4515 s and then lies still: at every step
/// after 0.46 s it is at y = 0.3 and at rest, to 1e-9 (a step of free fall left in it
/// would put it g h²/2 = 4.9e-6 m into the ramp; without the catch's "sit exactly on
/// the surface" it is 1.1e-6 m in).
#[test]
fn a_ball_caught_by_a_ramp_lies_still_under_every_integrator() {
    let world = World::gravity_only();
    for integrator in [
        physics::Integrator::Rk4,
        physics::Integrator::Verlet,
        physics::Integrator::Dopri5,
    ] {
        let scene = Scene::new()
            .with_world(world.clone())
            .with_integrator(integrator, 1e-3)
            .with_ramp(Ramp::new("ramp", [-3.0, 0.0], [3.0, 0.0]).restitution(0.0))
            .with_particle(Particle::new("ball", 1.0).radius(0.25).position([0.0, 1.3]));
        let mut simulation = Simulation::new(&scene).expect("a valid scene");
        for k in 460..=700 {
            simulation
                .step_to(f64::from(k) * 1e-3)
                .expect("the ball stays finite");
            let (x, v) = (simulation.positions()[0], simulation.velocities()[0]);
            assert!(
                (x.y - 0.3).abs() < 1e-9 && v.length() < 1e-9,
                "{integrator:?} at t = {} s: at {x}, moving at {v}",
                f64::from(k) * 1e-3
            );
        }
    }
}

/// A ball sliding off the end of a level ramp under Verlet, which carries each step's end
/// acceleration into the next. While on the ramp that acceleration includes the ramp's
/// normal force; once the ball is clear of the ramp's rounded end it is in free flight,
/// and Verlet is exact for a constant acceleration: from the first step that starts clear
/// of the ramp, the ball follows x₀ + v₀t + ½gt² to rounding (1e-9 m over 0.3 s). An
/// acceleration carried over from the ramp (the surface contact gone, the step's start
/// not saying the forces changed) would hold it up for a step, g·h/2 = 5e-3 m/s slow,
/// 1.5e-3 m off the parabola by the end.
#[test]
fn a_ball_sliding_off_a_ramps_end_falls_on_its_parabola_under_verlet() {
    let (radius, half_thickness, g) = (0.1, 0.01, 9.81);
    let reach = radius + half_thickness;
    let world = World {
        restitution: 0.0,
        bounds: None,
        ..World::gravity_only()
    };
    let scene = Scene::new()
        .with_world(world)
        .with_ramp(Ramp::new("ledge", [-1.0, 0.0], [0.0, 0.0]).thickness(2.0 * half_thickness))
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(radius)
                .position([-0.5, reach])
                .velocity([2.0, 0.0]),
        )
        .with_integrator(physics::Integrator::Verlet, 1e-3);
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    // The first step's start with the ball clear of the ramp's end by more than its
    // touching band (1e-6 of the reach): the first step without the surface.
    while simulation.positions()[0].x <= 0.0
        || simulation.positions()[0].length() <= reach * (1.0 + 2e-6)
    {
        simulation.step().expect("a step");
        assert!(simulation.time() < 1.0, "the ball never left the ramp");
    }
    let (t0, x0, v0) = (
        simulation.time(),
        simulation.positions()[0],
        simulation.velocities()[0],
    );
    let mut worst: f64 = 0.0;
    while simulation.time() < t0 + 0.3 {
        simulation.step().expect("a step");
        let t = simulation.time() - t0;
        let theory = x0 + v0 * t + DVec2::new(0.0, -0.5 * g * t * t);
        worst = worst.max(simulation.positions()[0].distance(theory));
    }
    eprintln!("left at {t0} s from {x0} at {v0}; {worst:e} m off the parabola");
    assert!(worst < 1e-9, "{worst} m off the parabola");
}
