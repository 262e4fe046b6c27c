//! Events located in time against theory: a projectile's landing against the kinematics'
//! square root, a large-amplitude pendulum's turning points and passes through the
//! vertical against the elliptic-integral period, a spring's maxima against the cosine, a
//! bounce's reversal against the impact's own instant; an event exactly at a step's end
//! counted once; and a watched run that steps with the same bits as an unwatched one.

mod common;

use physics::{
    DVec2, Event, Integrator, Located, Particle, Scene, Simulation, Spring, Tie, Watch, World,
};

use common::{elliptic_k, start};

const G: f64 = 9.81;

/// The events `texts` of `scene` located up to `until`, in time order.
fn located(scene: &Scene, texts: &[&str], until: f64) -> Vec<Located> {
    let events: Vec<Event> = texts.iter().map(|t| t.parse().expect("an event")).collect();
    let mut simulation = start(scene);
    let mut watch = Watch::new(&events, &simulation).expect("its objects exist");
    simulation
        .step_to_watching(until, &mut watch)
        .expect("the run stays finite")
}

fn times(events: &[Located]) -> Vec<f64> {
    events.iter().map(Located::time).collect()
}

/// A ball thrown from 10 m at (3, 4) m/s lands on y = 0 at t = (v + √(v² + 2 g h)) / g,
/// 1.9058… s, between two steps. Under every integrator exact for a constant acceleration
/// (verlet, rk4, pefrl, dopri5) the instant is the closed form's to 1e-12 s, and so is
/// the state there: y = 0 and x = 3 t to 1e-10 m (the ball moves 15 m/s × 1e-12 s in
/// the instant's uncertainty). (Euler's methods follow their own parabolas:
/// `kinematics.rs`.)
#[test]
fn a_projectile_lands_at_the_kinematics_instant() {
    let (h, vx, vy) = (10.0, 3.0, 4.0);
    let landing = (vy + (vy * vy + 2.0 * G * h).sqrt()) / G;
    for integrator in [
        Integrator::Verlet,
        Integrator::Rk4,
        Integrator::Pefrl,
        Integrator::Dopri5,
    ] {
        let scene = Scene::new()
            .with_world(World::gravity_only())
            .with_integrator(integrator, 1e-3)
            .with_particle(
                Particle::new("Ball", 1.0)
                    .radius(0.1)
                    .position([0.0, h])
                    .velocity([vx, vy]),
            );
        let events = located(&scene, &["Ball.y crosses 0 down"], 3.0);
        assert_eq!(events.len(), 1, "{integrator:?}: one landing");
        let at = &events[0].at;
        assert!(
            (at.time() - landing).abs() < 1e-12,
            "{integrator:?}: landed at {} s, theory {landing} s",
            at.time()
        );
        let x = at.positions()[0];
        assert!(
            x.y.abs() < 1e-10 && (x.x - vx * landing).abs() < 1e-10,
            "{x}"
        );
    }
}

/// A bob on a 1 m rod released at rest 60° from the vertical, and its period
/// 4 √(L/g) K(sin 30°).
fn pendulum() -> (Scene, f64) {
    let (length, angle) = (1.0, 60.0_f64);
    let (sin, cos) = angle.to_radians().sin_cos();
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("Bob", 1.0)
                .radius(0.05)
                .position([length * sin, -length * cos]),
        )
        .with_tie(Tie::rod("rod", [0.0, 0.0], "Bob", length));
    let period = 4.0 * (length / G).sqrt() * elliptic_k((angle.to_radians() / 2.0).sin());
    (scene, period)
}

/// A bob on a 1 m rod released at rest 60° from the vertical turns at every half period
/// T/2 = 2 √(L/g) K(sin 30°) and passes the vertical at T/4 + k T/2; rk4 at 1 ms finds
/// the first eight of each to 1e-8 s (its error over a period is some 1e-12 s: the
/// tolerance is what a located event promises at a 1 ms step). The release itself, at rest, is not a
/// turning point (a start on the value is not a crossing). The rod's angle crosses 0
/// going counter-clockwise (up) and clockwise (down) by turns, starting down.
#[test]
fn a_pendulum_turns_and_passes_the_vertical_at_the_elliptic_instants() {
    let (scene, period) = pendulum();
    let until = 4.0 * period + 0.1;
    let turns = times(&located(&scene, &["Bob.vx crosses 0"], until));
    let passes = located(
        &scene,
        &["rod.angle crosses 0 down", "rod.angle crosses 0 up"],
        until,
    );
    assert_eq!(turns.len(), 8, "{turns:?}");
    assert_eq!(passes.len(), 8, "{:?}", times(&passes));
    for (k, &t) in turns.iter().enumerate() {
        let expected = (k + 1) as f64 * period / 2.0;
        assert!(
            (t - expected).abs() < 1e-8,
            "turn {k}: {t} s against {expected} s"
        );
    }
    for (k, pass) in passes.iter().enumerate() {
        let expected = period / 4.0 + k as f64 * period / 2.0;
        assert!(
            (pass.time() - expected).abs() < 1e-8,
            "pass {k}: {} s against {expected} s",
            pass.time()
        );
        assert_eq!(pass.event, k % 2, "down first, then up, by turns");
    }
}

/// A bob on an undamped spring (k = 4 N/m, m = 1 kg, 0.5 m stretched, released at rest)
/// is at its maxima at t = 2π k / ω, ω = 2 rad/s: its velocity crosses 0 downwards there
/// (and upwards at the minima, half a period later). rk4 at 1 ms: to 1e-9 s.
#[test]
fn a_springs_maxima_are_at_the_cosines() {
    let omega: f64 = 2.0;
    let scene = Scene::new()
        .with_world(World::no_forces())
        .with_particle(Particle::new("bob", 1.0).radius(0.05).position([1.5, 0.0]))
        .with_spring(Spring::new("s", "bob", [0.0, 0.0], 4.0, 1.0));
    let events = located(
        &scene,
        &["bob.vx crosses 0 down", "bob.vx crosses 0 up"],
        10.0,
    );
    let period = std::f64::consts::TAU / omega;
    let (maxima, minima): (Vec<&Located>, Vec<&Located>) =
        events.iter().partition(|e| e.event == 0);
    assert_eq!((maxima.len(), minima.len()), (3, 3), "{:?}", times(&events));
    for (k, max) in maxima.iter().enumerate() {
        let expected = (k + 1) as f64 * period;
        assert!(
            (max.time() - expected).abs() < 1e-9,
            "maximum {k}: {}",
            max.time()
        );
        assert!((max.at.positions()[0].x - 1.5).abs() < 1e-9, "at the top");
    }
    for (k, min) in minima.iter().enumerate() {
        let expected = (k as f64 + 0.5) * period;
        assert!(
            (min.time() - expected).abs() < 1e-9,
            "minimum {k}: {}",
            min.time()
        );
    }
}

/// A quantity that jumps crosses at its jump: a ball dropped from 1.25 m onto the floor of
/// its box reverses its velocity at the impact, and `Ball.vy crosses 0 up` is located at
/// the impact's own instant (from the impact log) to 1e-9 s, its velocity there already
/// upward.
#[test]
fn a_bounce_reverses_the_velocity_at_the_impacts_instant() {
    let mut world = World::gravity_only();
    world.bounds = Some(physics::Bounds {
        min: [-5.0, 0.0].into(),
        max: [5.0, 10.0].into(),
        friction: 0.0,
        static_friction: None,
    });
    let scene = Scene::new()
        .with_world(world)
        .with_particle(Particle::new("Ball", 1.0).radius(0.25).position([0.0, 1.5]));
    let events = located(&scene, &["Ball.vy crosses 0 up"], 0.8);
    let mut simulation = start(&scene);
    simulation.record_impacts();
    simulation.step_to(0.8).expect("finite");
    let impact = simulation.take_impacts()[0].time;
    assert_eq!(events.len(), 1);
    assert!(
        (events[0].time() - impact).abs() < 1e-9,
        "reversed at {} s, struck at {impact} s",
        events[0].time()
    );
    assert!(events[0].at.velocities()[0].y > 0.0, "moving up");
}

/// A particle gliding at 1 m/s from x = −0.5 m with steps of 0.125 s (every number
/// exact in binary) reaches x = 0 exactly at the end of its fourth step: the event is
/// found once, at 0.5 s, not again at the start of the fifth (a start on the value is not
/// a crossing). Nor is a run that starts on the value a crossing, either way.
#[test]
fn an_event_at_a_steps_end_is_found_once_and_a_start_on_the_value_is_none() {
    let glider = |x: f64| {
        Scene::new()
            .with_world(World::no_forces())
            .with_integrator(Integrator::Rk4, 0.125)
            .with_particle(
                Particle::new("p", 1.0)
                    .radius(0.01)
                    .position([x, 0.0])
                    .velocity([1.0, 0.0]),
            )
    };
    let mut exact = start(&glider(-0.5));
    exact.step_to(0.5).expect("finite");
    assert_eq!(
        exact.positions()[0].x.to_bits(),
        0.0_f64.to_bits(),
        "the value itself, at a step's end"
    );
    let events = located(&glider(-0.5), &["p.x crosses 0"], 1.0);
    assert_eq!(times(&events).len(), 1);
    assert_eq!(events[0].time().to_bits(), 0.5_f64.to_bits());
    for event in ["p.x crosses 0", "p.x crosses 0 up", "p.x crosses 0 down"] {
        let events = located(&glider(0.0), &[event], 1.0);
        assert!(events.is_empty(), "{event}: {:?}", times(&events));
    }
}

/// Watching events changes nothing of the run: after 3 s of a pendulum whose turning
/// points are located every second or so, the state is the unwatched run's, bit for bit.
#[test]
fn a_watched_run_takes_the_same_steps() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("Bob", 1.0).radius(0.05).position([0.8, -0.6]))
        .with_tie(Tie::rod("rod", [0.0, 0.0], "Bob", 1.0));
    let mut plain = start(&scene);
    plain.step_to(3.0).expect("finite");
    let mut watched = start(&scene);
    let events = ["Bob.vx crosses 0".parse().expect("an event")];
    let mut watch = Watch::new(&events, &watched).expect("Bob exists");
    let found = watched.step_to_watching(3.0, &mut watch).expect("finite");
    assert!(found.len() >= 2, "it did locate");
    let bits = |s: &Simulation| -> Vec<u64> {
        s.positions()
            .iter()
            .chain(s.velocities())
            .flat_map(|v: &DVec2| [v.x.to_bits(), v.y.to_bits()])
            .chain([s.time().to_bits()])
            .collect()
    };
    assert_eq!(bits(&watched), bits(&plain));
}

/// Naming what is not there is refused with the name and what is there.
#[test]
fn an_event_on_an_unknown_object_is_refused_by_name() {
    let scene = Scene::new().with_particle(Particle::new("Ball", 1.0));
    let simulation = start(&scene);
    for (text, names) in [("Bal.y crosses 0", "Ball"), ("rod.angle crosses 0", "rod")] {
        let event: Event = text.parse().expect("well formed");
        let error = Watch::new(&[event], &simulation).expect_err("refused");
        assert!(error.contains(names), "{text}: {error}");
    }
}

/// A bob on a 1 m rod released 60° from the vertical is at its extremes at the elliptic
/// instants: between 0.3 T and 0.7 T its x is smallest at T/2 (found where vx crosses 0,
/// as the events above) at −sin 60° m, and between 0.8 T and 1.2 T largest at T, to
/// 1e-10 s (golden section on x itself would give only some 1e-8 s); between 0.6 T and 0.9 T its speed is
/// largest at the vertical, 3T/4 (found by golden section on the speed itself: a smooth
/// maximum is flat to its square, so the instant to 1e-7 s, some 1e-8 s seen) at
/// √(2 g L (1 − cos 60°)) to 1e-9 m/s. The rod's angle, with no exact rate, is smallest
/// at T/2, to 1e-7 s, at −60° to 1e-9°.
#[test]
fn a_pendulums_extremes_are_located_at_the_elliptic_instants() {
    let (scene, period) = pendulum();
    let (length, angle) = (1.0, 60.0_f64);
    let (sin, cos) = angle.to_radians().sin_cos();
    let from = common::simulation_at(&scene, 0.3 * period);
    let until = 0.7 * period;
    let reading = |text: &str| {
        physics::Quantity::parse(text)
            .unwrap()
            .reading(&from)
            .unwrap()
    };
    let left = from
        .extreme_until(reading("Bob.x"), until, physics::Turn::Minimum)
        .unwrap();
    assert!((left.time() - period / 2.0).abs() < 1e-8, "{}", left.time());
    assert!((left.positions()[0].x + sin).abs() < 1e-9);
    let right = common::simulation_at(&scene, 0.8 * period)
        .extreme_until(reading("Bob.x"), 1.2 * period, physics::Turn::Maximum)
        .unwrap();
    assert!((right.time() - period).abs() < 1e-10, "{}", right.time());
    let bottom = 0.75 * period;
    let from = common::simulation_at(&scene, 0.6 * period);
    let fastest = from
        .extreme_until(reading("Bob.speed"), 0.9 * period, physics::Turn::Maximum)
        .unwrap();
    assert!((fastest.time() - bottom).abs() < 1e-7, "{}", fastest.time());
    let top_speed = (2.0 * G * length * (1.0 - cos)).sqrt();
    assert!((fastest.velocities()[0].length() - top_speed).abs() < 1e-9);
    let from = common::simulation_at(&scene, 0.3 * period);
    let widest = from
        .extreme_until(reading("rod.angle"), until, physics::Turn::Minimum)
        .unwrap();
    assert!((widest.read(reading("rod.angle")) + angle).abs() < 1e-9);
    assert!(
        (widest.time() - period / 2.0).abs() < 1e-7,
        "{}",
        widest.time()
    );
}

/// A link's angle is read in (−180, 180], and its jump by 360° across the top is no
/// crossing: a bob whirled on a 1 m rod from the bottom at 8 m/s (enough to go over the
/// top: 8² > 4 g L) passes the vertical at the bottom, angle 0, only there (every pass
/// at y = −1 to 1e-9 m, once a turn), passes 180° at the top (y = +1), and passes −170°
/// only going up (counter-clockwise from −180), never "down".
#[test]
fn an_angle_wrapping_past_180_degrees_is_no_crossing() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("bob", 1.0)
                .radius(0.05)
                .position([0.0, -1.0])
                .velocity([8.0, 0.0]),
        )
        .with_tie(Tie::rod("rod", [0.0, 0.0], "bob", 1.0));
    let found = located(
        &scene,
        &[
            "rod.angle crosses 0",
            "rod.angle crosses 180",
            "rod.angle crosses -170 down",
            "rod.angle crosses -170 up",
        ],
        3.0,
    );
    let count = |k: usize| found.iter().filter(|l| l.event == k).count();
    let when: Vec<(usize, f64)> = found.iter().map(|l| (l.event, l.time())).collect();
    assert!(count(0) >= 3 && count(1) >= 3, "whole turns: {when:?}");
    for located in &found {
        let y = located.at.positions()[0].y;
        match located.event {
            0 => assert!((y + 1.0).abs() < 1e-9, "angle 0 at the bottom, not y = {y}"),
            1 => assert!((y - 1.0).abs() < 1e-9, "180° at the top, not y = {y}"),
            2 => panic!("−170° passed downward at t = {}", located.time()),
            _ => {}
        }
    }
    assert_eq!(count(3), count(1), "−170° once a turn, going up");
}

/// An event on a quantity held constant does not fire on its rounding: a pendulum's rod
/// is held at 2 m (its length wanders in the last bits), and `rod.length crosses 2` never
/// happens in 4 s, while `rod.length crosses 1.5` (never reached) does not either, and
/// the bob's passes through the vertical still do, at every half period.
#[test]
fn a_quantity_held_constant_crosses_nothing_on_its_rounding() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("bob", 1.0)
                .radius(0.05)
                .position([1.0, -3.0_f64.sqrt()]),
        )
        .with_tie(Tie::rod("rod", [0.0, 0.0], "bob", 2.0));
    let found = located(
        &scene,
        &[
            "rod.length crosses 2",
            "rod.length crosses 1.5",
            "bob.x crosses 0",
        ],
        4.0,
    );
    let when: Vec<(usize, f64)> = found.iter().map(|l| (l.event, l.time())).collect();
    assert!(when.iter().all(|&(event, _)| event == 2), "{when:?}");
    assert!(when.len() >= 3, "the passes through the vertical: {when:?}");
}
