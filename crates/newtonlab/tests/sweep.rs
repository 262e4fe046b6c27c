//! `newtonlab sweep` on the real binary: the range of a projectile against its launch
//! angle to the sine law, the same bytes on one thread and two, a measure without a
//! number left empty with the reason on stderr, bad input refused (exit 2) and a series
//! whose every run fails (exit 1).

mod common;

use common::{newtonlab, scene_file, stderr, stdout};

const THROW: &str = r#"version = 1
[world]
gravity = [0.0, -9.81]
gravitation = false
electrostatics = false
[simulation]
integrator = "rk4"
time_step = 0.001
[[particle]]
name = "Ball"
mass = 1.0
radius = 0.1
position = [0.0, 0.0]
velocity = { magnitude = 20.0, angle = 45.0 }
"#;

/// Ranges at 10°…80° by 10°: the header is the field and the measure as typed, each row
/// the angle and the range v₀² sin 2a / g to 1e-9 relative; `--threads 1` and
/// `--threads 2` write the same bytes.
#[test]
fn the_range_against_the_angle_is_the_sine_law_on_any_number_of_threads() {
    let (_dir, scene) = scene_file("throw.toml", THROW);
    let args = |threads: &'static str| {
        [
            "sweep",
            scene.as_str(),
            "--vary",
            "Ball.velocity.angle=10:80:10",
            "--until",
            "5",
            "--measure",
            "Ball.x at Ball.y crosses 0 down",
            "--threads",
            threads,
        ]
    };
    let one = newtonlab(&args("1"));
    assert!(one.status.success(), "{}", stderr(&one));
    let text = stdout(&one);
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("Ball.velocity.angle,Ball.x at Ball.y crosses 0 down")
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 8);
    for row in &rows {
        let range = 400.0 * (2.0 * row[0].to_radians()).sin() / 9.81;
        assert!(
            (row[1] - range).abs() < 1e-9 * range,
            "{row:?} against {range}"
        );
    }
    let two = newtonlab(&args("2"));
    assert_eq!(one.stdout, two.stdout, "the same bytes on two threads");
}

/// A measure that finds nothing is an empty field, and stderr names the run, the
/// measure and why; the exit code stays 0 while some run measured something.
#[test]
fn a_measure_without_a_number_is_empty_and_explained() {
    let (_dir, scene) = scene_file("throw.toml", THROW);
    let output = newtonlab(&[
        "sweep",
        &scene,
        "--vary",
        "Ball.velocity.angle=30:60:30",
        "--until",
        "5",
        "--measure",
        "t at Ball.y crosses 0 down #2",
        "--measure",
        "max Ball.y",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let first = text.lines().nth(1).unwrap();
    assert!(first.starts_with("30,,"), "{first}");
    let said = stderr(&output);
    assert!(
        said.contains("Ball.velocity.angle = 30") && said.contains("#2") && said.contains("not 2"),
        "{said}"
    );
}

/// Bad input exits 2 with the problem named; a series whose every run fails exits 1.
#[test]
fn bad_input_and_failed_series_exit_as_documented() {
    let (_dir, scene) = scene_file("throw.toml", THROW);
    let run = |vary: &str, measure: &str| {
        newtonlab(&[
            "sweep",
            &scene,
            "--vary",
            vary,
            "--until",
            "2",
            "--measure",
            measure,
        ])
    };
    for (vary, measure, words) in [
        ("Bal.mass=1:2:1", "max Ball.y", "names no object"),
        ("Ball.mass=1:2:0", "max Ball.y", "no values"),
        ("Ball.mass=1:2:1", "highest Ball.y", "not a measure"),
        ("Ball.mass=1:2:1", "max Bob.y", "no particle named 'Bob'"),
        ("Ball.mass=1:2:1", "Ball.x at 3", "outside the run"),
    ] {
        let output = run(vary, measure);
        assert_eq!(output.status.code(), Some(2), "{vary} {measure}");
        assert!(stderr(&output).contains(words), "{}", stderr(&output));
    }
    let output = run("Ball.mass=-2:0:1", "max Ball.y");
    assert_eq!(output.status.code(), Some(1), "every run failed");
    assert!(stderr(&output).contains("every run"), "{}", stderr(&output));
}

/// A series' work is bounded as `run`'s is, and said at once (exit 2), never a silent
/// hour: runs to 3e5 s (3e8 steps each), a time step of 1e-9 s varied in, 1e7 values
/// (said as too many, not as a step leading nowhere), a grid of 1000 × 1000 runs of
/// 10⁵ steps (10¹¹ particle-steps); and `check` of a scene whose `[[series]]` runs to
/// 1e308 s.
#[test]
fn a_series_too_large_is_refused_with_its_size() {
    let (_dir, scene) = scene_file("throw.toml", THROW);
    for (args, words) in [
        (
            vec!["--vary", "Ball.velocity.angle=10:80:10", "--until", "3e5"],
            "would take 3.0e8 steps",
        ),
        (
            vec![
                "--vary",
                "simulation.time_step=1e-9:2e-9:1e-9",
                "--until",
                "1",
            ],
            "would take 1.0e9 steps",
        ),
        (
            vec!["--vary", "Ball.mass=1:1e7:1", "--until", "1"],
            "more than a million",
        ),
        (
            vec![
                "--vary",
                "Ball.mass=1:1000:1",
                "--vary",
                "Ball.radius=0.001:1:0.001",
                "--until",
                "100",
            ],
            "1.0e11 particle-steps",
        ),
    ] {
        let mut all = vec!["sweep", scene.as_str(), "--measure", "max Ball.y"];
        all.extend(args.iter().copied());
        let output = newtonlab(&all);
        common::assert_refused(&output, words, &args);
    }
    let text = format!(
        "{THROW}[[series]]\nvary = \"Ball.velocity.angle\"\nfrom = 10.0\nto = 80.0\nstep = 10.0\nuntil = 1e308\nmeasure = [\"max Ball.y\"]\n"
    );
    let (_dir, far) = scene_file("far.toml", &text);
    let output = newtonlab(&["check", &far]);
    assert_eq!(output.status.code(), Some(2), "{}", stdout(&output));
    let said = stdout(&output) + &stderr(&output);
    assert!(said.contains("steps, more than"), "{said}");
}
