//! Experiment series (`physics::series`) against theory: a drag-free projectile's range
//! against its launch angle (v₀² sin 2a / g), a rod pendulum's period against its
//! amplitude (the elliptic integral), an instant read between steps, the Nth event; the
//! same bits on one thread and on two; bad settings and measures refused by name.

mod common;

use physics::series::{Measure, MeasureError, Sweep, Vary, range_values};
use physics::{Particle, Scene, Tie, World};

use common::{elliptic_k, relative};

const G: f64 = 9.81;

fn projectile() -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("Ball", 1.0)
                .radius(0.1)
                .velocity(physics::Vector::Polar {
                    magnitude: 20.0,
                    angle: 45.0,
                }),
        )
}

fn sweep(scene: &Scene, vary: &[&str], until: f64, measures: &[&str]) -> Sweep {
    Sweep {
        varies: vary
            .iter()
            .map(|v| Vary::parse(v, scene).expect("a setting"))
            .collect(),
        until,
        measures: measures
            .iter()
            .map(|m| Measure::parse(m).expect("a measure"))
            .collect(),
        trace: false,
    }
}

/// The measured numbers of every run, which must all have them.
fn numbers(sweep: &Sweep, scene: &Scene, threads: usize) -> Vec<(Vec<f64>, Vec<f64>)> {
    sweep
        .run(scene, threads, &|| {})
        .into_iter()
        .map(|row| {
            let measured = row.measured.expect("the run succeeds");
            let measured = measured.into_iter().map(|m| m.expect("measured")).collect();
            (row.values, measured)
        })
        .collect()
}

/// A ball launched at 20 m/s from the ground at 10°, 15°, …, 80°: where it comes down
/// again (`Ball.x at Ball.y crosses 0 down`) is v₀² sin 2a / g, its flight
/// (`t at …`) 2 v₀ sin a / g, its highest point (`max Ball.y`) (v₀ sin a)²/2g, each to
/// 1e-9 relative (rk4 is exact for a constant field; the landing is located to 1e-12 s
/// and the top where vy crosses 0). The same bits on one thread and on two.
#[test]
fn a_projectiles_range_against_its_angle_is_the_sine_law() {
    let scene = projectile();
    let series = sweep(
        &scene,
        &["Ball.velocity.angle=10:80:5"],
        5.0,
        &[
            "Ball.x at Ball.y crosses 0 down",
            "t at Ball.y crosses 0 down",
            "max Ball.y",
        ],
    );
    let one = numbers(&series, &scene, 1);
    assert_eq!(one.len(), 15, "10° to 80° by 5°");
    for (values, measured) in &one {
        let a = values[0].to_radians();
        let v0: f64 = 20.0;
        let range = v0 * v0 * (2.0 * a).sin() / G;
        let flight = 2.0 * v0 * a.sin() / G;
        let top = (v0 * a.sin()).powi(2) / (2.0 * G);
        assert!(
            relative(measured[0], range) < 1e-9,
            "{values:?}: range {}",
            measured[0]
        );
        assert!(
            relative(measured[1], flight) < 1e-9,
            "{values:?}: flight {}",
            measured[1]
        );
        assert!(
            relative(measured[2], top) < 1e-9,
            "{values:?}: top {}",
            measured[2]
        );
    }
    let bits = |rows: &[(Vec<f64>, Vec<f64>)]| -> Vec<u64> {
        rows.iter()
            .flat_map(|(v, m)| v.iter().chain(m).map(|x| x.to_bits()))
            .collect()
    };
    assert_eq!(
        bits(&one),
        bits(&numbers(&series, &scene, 2)),
        "the same bits"
    );
}

/// A bob on a 1 m rod released at rest at 10°, 30°, 50°, 70°, 90° from the vertical
/// (its position's angle −80°, …, 0° from +x): `period Bob.x` (the mean interval between
/// its located maxima) is 4 √(L/g) K(sin(θ₀/2)), to 1e-9 relative over four periods;
/// `max Bob.speed` (no exact rate: golden section) is √(2 g L (1 − cos θ₀)) to 1e-9;
/// `t at Bob.vx crosses 0 #3` is the third turning point, 3T/2, to 1e-9 relative.
#[test]
fn a_pendulums_period_against_its_amplitude_is_the_elliptic_integral() {
    let scene =
        Scene::new()
            .with_world(World::gravity_only())
            .with_particle(Particle::new("Bob", 1.0).radius(0.05).position(
                physics::Vector::Polar {
                    magnitude: 1.0,
                    angle: -60.0,
                },
            ))
            .with_tie(Tie::rod("rod", [0.0, 0.0], "Bob", 1.0));
    let series = sweep(
        &scene,
        &["Bob.position.angle=-80:0:20"],
        9.0,
        &["period Bob.x", "max Bob.speed", "t at Bob.vx crosses 0 #3"],
    );
    for (values, measured) in numbers(&series, &scene, 2) {
        let amplitude = (values[0] + 90.0).to_radians();
        let period = 4.0 * (1.0 / G).sqrt() * elliptic_k((amplitude / 2.0).sin());
        let fastest = (2.0 * G * (1.0 - amplitude.cos())).sqrt();
        assert!(
            relative(measured[0], period) < 1e-9,
            "{values:?}: period {}",
            measured[0]
        );
        assert!(
            relative(measured[1], fastest) < 1e-9,
            "{values:?}: speed {}",
            measured[1]
        );
        assert!(
            relative(measured[2], 1.5 * period) < 1e-9,
            "{values:?}: third turn {}",
            measured[2]
        );
    }
}

/// Past 90° a bob's x has three maxima a swing (at 90° rising, at 90° falling, and a
/// local one below zero at the far turn), and the mean gap between maxima is a third of
/// the period. `period Bob.x` is the swing's period 4 √(L/g) K(sin(θ₀/2)) at 95°, 110°,
/// …, 170° all the same, to 1e-8 relative (rk4 at 1 ms: some 1e-10 at 170°, where the
/// bob lingers near the top), and the rod's second upward pass through the vertical,
/// at 7T/4 (released on the right, it passes down at T/4 and up at 3T/4), agrees.
#[test]
fn a_period_past_ninety_degrees_is_the_swing_not_the_gap_between_maxima() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("Bob", 1.0).radius(0.05).position([1.0, 0.0]))
        .with_tie(Tie::rod("rod", [0.0, 0.0], "Bob", 1.0));
    let series = sweep(
        &scene,
        &["Bob.position.angle=5:80:15"],
        16.0,
        &["period Bob.x", "t at rod.angle crosses 0 up #2"],
    );
    for (values, measured) in numbers(&series, &scene, 1) {
        let amplitude = (values[0] + 90.0).to_radians();
        let period = 4.0 * (1.0 / G).sqrt() * elliptic_k((amplitude / 2.0).sin());
        assert!(
            relative(measured[0], period) < 1e-8,
            "{values:?}: period {} against {period}",
            measured[0]
        );
        assert!(
            relative(measured[1], 1.75 * period) < 1e-8,
            "{values:?}: second upward pass {} against {}",
            measured[1],
            1.75 * period
        );
    }
}

/// Too few maxima, or maxima that repeat at no cycle, give no period and say which —
/// never a number: two maxima of a spring within 1.5 periods; a double pendulum's chaotic
/// lower bob over 20 s.
#[test]
fn a_period_that_cannot_be_told_is_said_in_words() {
    let spring = Scene::new()
        .with_world(World::weightless())
        .with_particle(Particle::new("Bob", 1.0).position([1.5, 0.0]))
        .with_spring(physics::Spring::new("s", "Bob", [0.0, 0.0], 1.0, 1.0));
    let measure = [Measure::parse("period Bob.x").expect("a measure")];
    // ω = 1: maxima at 0 (the start, not located), 2π, 4π.
    let found = physics::series::measure(&spring, 14.0, &measure).expect("a run");
    let why = found[0].as_ref().expect_err("two maxima are no period");
    assert!(
        matches!(why, MeasureError::NoPeriod { count: 2, until } if until.to_bits() == 14.0_f64.to_bits()),
        "{why:?}"
    );
    assert!(why.to_string().contains("three"), "{why}");
    let found = physics::series::measure(&spring, 20.0, &measure).expect("a run");
    let period = found[0].as_ref().expect("three maxima");
    assert!(relative(*period, std::f64::consts::TAU) < 1e-9, "{period}");

    let chaos = physics::example("double-pendulum")
        .expect("an example")
        .scene()
        .expect("it loads");
    let measure = [Measure::parse("period B1.x").expect("a measure")];
    let found = physics::series::measure(&chaos, 20.0, &measure).expect("a run");
    let why = found[0].as_ref().expect_err("chaos has no period");
    assert!(
        matches!(why, MeasureError::IrregularPeriod { .. }),
        "{why:?}"
    );
    assert!(why.to_string().contains("no regular cycle"), "{why}");
}

/// An instant between two steps is read off a copy stepped on to it, the run itself
/// untouched: `Ball.x at 1.0005` is v₀ cos a × 1.0005 exactly (to 1e-12), and the
/// landing measured beside it is the landing measured alone, bit for bit.
#[test]
fn an_instant_between_steps_leaves_the_run_alone() {
    let scene = projectile();
    let beside = sweep(
        &scene,
        &["Ball.velocity.angle=30:30:1"],
        5.0,
        &["Ball.x at 1.0005", "Ball.x at Ball.y crosses 0 down"],
    );
    let alone = sweep(
        &scene,
        &["Ball.velocity.angle=30:30:1"],
        5.0,
        &["Ball.x at Ball.y crosses 0 down"],
    );
    let (with, without) = (numbers(&beside, &scene, 1), numbers(&alone, &scene, 1));
    let x = 20.0 * 30_f64.to_radians().cos() * 1.0005;
    assert!((with[0].1[0] - x).abs() < 1e-12, "{}", with[0].1[0]);
    assert_eq!(with[0].1[1].to_bits(), without[0].1[0].to_bits());
}

/// What cannot be measured says why, and the rest of the row stands: an event that
/// happens once, asked for its second time; a period with one maximum.
#[test]
fn a_measure_without_a_number_says_why() {
    let scene = projectile();
    let series = sweep(
        &scene,
        &["Ball.velocity.angle=45:45:1"],
        5.0,
        &[
            "t at Ball.y crosses 0 down #2",
            "period Ball.y",
            "t at Ball.y crosses 0 down",
        ],
    );
    let row = series.run(&scene, 1, &|| {}).remove(0);
    let measured = row.measured.unwrap();
    let why = measured[0].as_ref().unwrap_err();
    assert!(
        matches!(
            why,
            MeasureError::NoEvent {
                count: 1,
                nth: 2,
                ..
            }
        ),
        "{why:?}"
    );
    let words = why.to_string();
    assert!(
        words.contains("1 times") && words.contains("not 2"),
        "{why}"
    );
    let why = measured[1].as_ref().unwrap_err();
    assert!(matches!(why, MeasureError::NoPeriod { .. }), "{why:?}");
    assert!(why.to_string().contains("fewer than three maxima"));
    assert!(measured[2].is_ok());
}

/// A varied value the scene's rules refuse fails that run, by the rule's words.
#[test]
fn a_value_the_rules_refuse_fails_its_run() {
    let scene = projectile();
    let series = sweep(&scene, &["Ball.mass=-1:1:1"], 1.0, &["max Ball.y"]);
    let rows = series.run(&scene, 1, &|| {});
    for row in &rows[..2] {
        let why = row.measured.as_ref().unwrap_err();
        assert!(matches!(why, MeasureError::Scene(_)), "{why:?}");
        assert!(why.to_string().contains("mass"), "{why}");
    }
    assert!(rows[2].measured.is_ok());
}

/// Ranges: FROM to TO inclusive (to a billionth of a step), downwards too; none for a
/// step of 0 or one leading away.
#[test]
fn ranges_reach_their_end() {
    assert_eq!(range_values(10.0, 80.0, 35.0), Some(vec![10.0, 45.0, 80.0]));
    assert_eq!(range_values(0.0, 0.3, 0.1).map(|v| v.len()), Some(4));
    assert_eq!(range_values(5.0, 1.0, -2.0), Some(vec![5.0, 3.0, 1.0]));
    assert_eq!(range_values(1.0, 1.0, 1.0), Some(vec![1.0]));
    assert_eq!(range_values(0.0, 1.0, 0.0), None);
    assert_eq!(range_values(0.0, 1.0, -1.0), None);
}

/// Bad settings and measures are refused with the problem named.
#[test]
fn bad_settings_and_measures_are_named() {
    let scene = projectile();
    for (text, words) in [
        ("Bal.mass=1:2:1", "names no object"),
        ("Ball.weight=1:2:1", "no number of that name"),
        ("Ball.velocity=1:2:1", "one part"),
        ("Ball.mass.x=1:2:1", "one part"),
        ("Ball.velocity.z=1:2:1", "one part"),
        ("Ball.color=1:2:1", "no number of that name"),
        ("Ball.mass=1:2", "not a range"),
        ("Ball.mass=1:2:0", "no values"),
        ("Ball.mass=2:1:1", "no values"),
    ] {
        let error = Vary::parse(text, &scene).unwrap_err();
        assert!(error.contains(words), "{text}: {error}");
    }
    for (text, words) in [
        ("Ball.x", "not a measure"),
        ("Ball.x at Ball.y crosses", "not an event"),
        ("Ball.x at Ball.y crosses 0 #0", "not a measure"),
        ("maximum Ball.y", "not a measure"),
    ] {
        let error = Measure::parse(text).unwrap_err();
        assert!(error.contains(words), "{text}: {error}");
    }
    for (measure, words) in [
        ("max Bob.y", "no particle named 'Bob'"),
        ("Ball.x at 7", "outside the run"),
    ] {
        let series = sweep(&scene, &["Ball.mass=1:1:1"], 5.0, &[measure]);
        let error = series.check(&scene).unwrap_err();
        assert!(error.contains(words), "{measure}: {error}");
    }
    let world = Vary::parse("world.gravity.y=-9.81:-1.62:1", &scene).unwrap();
    assert_eq!(world.values.len(), 9);
    assert!(Vary::parse("simulation.time_step=0.001:0.002:0.001", &scene).is_ok());
}

const SCENE_WITH_SERIES: &str = r#"version = 1
[world]
gravity = [0.0, -9.81]
[[particle]]
name = "Ball"
mass = 1.0
radius = 0.1
position = [0.0, 0.0]
velocity = { magnitude = 20.0, angle = 45.0 }
[[series]]
vary = "Ball.velocity.angle"
from = 10.0
to = 80.0
step = 5.0
until = 5.0
measure = ["Ball.x at Ball.y crosses 0 down"]
theory = "v0^2*sin(2*a)/g"
"#;

/// `[[series]]` reads, writes back and reads again to the same scene; its theory is the
/// sine law at the varied angle (degrees turned to radians), and the series measures it.
#[test]
fn a_series_in_a_scene_file_round_trips_and_follows_its_theory() {
    let scene = Scene::from_toml(SCENE_WITH_SERIES).expect("a valid scene");
    assert_eq!(scene.series.len(), 1);
    let again = Scene::from_toml(&scene.to_toml()).expect("written back");
    assert_eq!(again, scene);
    let series = &scene.series[0];
    let theory =
        physics::series::Theory::parse(series.theory.as_deref().unwrap(), &scene, &series.vary)
            .unwrap();
    let expected = 400.0 * (60_f64.to_radians()).sin() / G;
    assert!(relative(theory.at(30.0), expected) < 1e-15);
    let sweep = series.sweep(&scene).unwrap();
    for (values, measured) in numbers(&sweep, &scene, 2) {
        assert!(
            relative(measured[0], theory.at(values[0])) < 1e-9,
            "{values:?}"
        );
    }
}

/// A series that names what the scene lacks is refused where it says so: each problem
/// with its line.
#[test]
fn a_bad_series_is_refused_at_its_line() {
    for (from, to, words) in [
        (
            "vary = \"Ball.velocity.angle\"",
            "vary = \"Bal.velocity.angle\"",
            "names no object",
        ),
        ("step = 5.0", "step = 0.0", "no values"),
        ("until = 5.0", "until = -1.0", "until must be"),
        (
            "measure = [\"Ball.x at Ball.y crosses 0 down\"]",
            "measure = [\"Bob.x at Ball.y crosses 0 down\"]",
            "no particle named 'Bob'",
        ),
        (
            "theory = \"v0^2*sin(2*a)/g\"",
            "theory = \"v0^2*sin(2*q)/g\"",
            "not 'q'",
        ),
    ] {
        let text = SCENE_WITH_SERIES.replace(from, to);
        let error = Scene::from_toml(&text).expect_err("refused");
        let problem = &error.problems[0];
        assert!(problem.message.contains(words), "{to}: {}", problem.message);
        let line = text.lines().position(|l| l == to).map(|l| l + 1);
        assert_eq!(problem.line, line, "{to}: at its line");
    }
}

/// Renaming the ball renames it in the series; deleting it drops the series.
#[test]
fn a_series_follows_its_particle() {
    let mut scene = Scene::from_toml(SCENE_WITH_SERIES).unwrap();
    scene.rename(physics::Section::Particle(0), "Shot");
    assert_eq!(scene.series[0].vary, "Shot.velocity.angle");
    assert_eq!(
        scene.series[0].measure,
        ["Shot.x at Shot.y crosses 0.0 down"]
    );
    assert!(scene.validate().is_empty(), "{:?}", scene.validate());
    scene.remove(physics::Section::Particle(0));
    assert!(scene.series.is_empty());
}

/// Every example's series with a theory follows it: each run's first measure against the
/// law at its value, to 1e-8 relative (the projectile's range, the pendulum's elliptic
/// period at 5°–90°, the terminal speed's tanh at 5 s).
#[test]
fn the_examples_series_follow_their_theories() {
    let mut checked = 0;
    for example in physics::EXAMPLES {
        let Some(scene) = example.scene().ok() else {
            continue;
        };
        for series in &scene.series {
            let Some(text) = &series.theory else {
                continue;
            };
            let theory = physics::series::Theory::parse(text, &scene, &series.vary).unwrap();
            let sweep = series.sweep(&scene).unwrap();
            for (values, measured) in numbers(&sweep, &scene, 2) {
                let expected = theory.at(values[0]);
                assert!(
                    relative(measured[0], expected) < 1e-8,
                    "{}: {values:?}: {} against {expected}",
                    example.name,
                    measured[0]
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 3, "{checked} series with a theory");
}

/// A theory reads `pi` as the app's fields do (exmex's own constant is `PI`): a spring's
/// period against its mass, `2*pi*sqrt(m/k)`, is `2*PI*sqrt(m/k)`, and both are
/// 2π √(m/k) at m = 2 kg, k = 8 N/m.
#[test]
fn a_theory_reads_pi() {
    let scene = Scene::new()
        .with_world(World::weightless())
        .with_particle(Particle::new("Bob", 2.0).position([1.5, 0.0]))
        .with_spring(physics::Spring::new("s", "Bob", [0.0, 0.0], 8.0, 1.0));
    for text in ["2*pi*sqrt(x/8)", "2*PI*sqrt(x/8)"] {
        let theory = physics::series::Theory::parse(text, &scene, "Bob.mass")
            .unwrap_or_else(|why| panic!("{text}: {why}"));
        let expected = std::f64::consts::TAU * (2.0_f64 / 8.0).sqrt();
        assert!(relative(theory.at(2.0), expected) < 1e-15, "{text}");
    }
}
