//! The command-line contract (`docs/cli.md`), exercised on the real binary.

mod common;

use std::process::{Command, Output};

use common::{newtonlab, scene_file, stderr, stdout, tempdir};

/// The README's example command: the undamped spring for 20 s sampled every 0.1 s, and
/// its x against the closed form 10 + 5 cos t.
#[test]
fn run_prints_the_undamped_spring_as_csv() {
    let output = newtonlab(&[
        "run",
        "example:spring-undamped",
        "--until",
        "20",
        "--every",
        "0.1",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "t,P.x,P.y,P.vx,P.vy,P.ax,P.ay,kinetic_energy,potential_energy,total_energy,momentum_x,momentum_y",
        "header"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 201, "rows at 0, 0.1, …, 20");
    for (k, row) in rows.iter().enumerate() {
        let t = k as f64 * 0.1;
        // The instant k·DT is written as the grid names it: 0.6, not 0.6000000000000001.
        let named = k as f64 / 10.0;
        assert_eq!(row[0].to_bits(), named.to_bits(), "row {k} is named k·DT");
        assert!(
            (row[1] - (10.0 + 5.0 * t.cos())).abs() < 1e-9,
            "x at t = {t}: {}",
            row[1]
        );
        assert!(
            (row[5] - (-5.0 * t.cos())).abs() < 1e-9,
            "ax at t = {t}: {}",
            row[5]
        );
    }
}

#[test]
fn every_number_parses_back_to_the_same_f64() {
    let output = newtonlab(&["run", "example:orbit", "--until", "1", "--every", "0.25"]);
    assert!(output.status.success(), "{}", stderr(&output));
    for line in stdout(&output).lines().skip(1) {
        for field in line.split(',') {
            let value: f64 = field.parse().unwrap();
            assert_eq!(
                format!("{value:?}"),
                field,
                "printed as its shortest round-trip form"
            );
        }
    }
}

#[test]
fn the_same_run_gives_bit_identical_csv() {
    let args = [
        "run",
        "example:charged-pair",
        "--until",
        "3",
        "--every",
        "0.05",
    ];
    assert_eq!(
        newtonlab(&args).stdout,
        newtonlab(&args).stdout,
        "two runs differ"
    );
}

/// `--threads` changes no bit: the ball pit through its crash (the contact search and the
/// resting solver's work shared out) and the paper's Coulomb pair, on 1, 2, 3 and 7
/// threads and on every core (no `--threads`).
#[test]
fn run_gives_the_same_bits_on_any_number_of_threads() {
    for (example, until) in [("ball-pit", "0.4"), ("paper-coulomb", "1")] {
        let scene = format!("example:{example}");
        let base = ["run", scene.as_str(), "--until", until, "--every", "0.05"];
        let everywhere = newtonlab(&base);
        assert!(everywhere.status.success(), "{}", stderr(&everywhere));
        for threads in ["1", "2", "3", "7"] {
            let mut args = base.to_vec();
            args.extend(["--threads", threads]);
            let output = newtonlab(&args);
            assert!(
                output.stdout == everywhere.stdout,
                "{example} on {threads} threads differs from every core"
            );
        }
    }
    let refused = newtonlab(&[
        "run",
        "example:ball-pit",
        "--until",
        "0.1",
        "--threads",
        "0",
    ]);
    assert_eq!(refused.status.code(), Some(2), "0 threads");
}

#[test]
fn run_ends_with_a_row_at_until_and_writes_to_a_file() {
    let dir = tempdir::Dir::new();
    let out = dir.path.join("out.csv");
    let out = out.to_string_lossy();
    let output = newtonlab(&[
        "run",
        "example:kinematics-cartesian",
        "--until",
        "0.25",
        "--every",
        "0.1",
        "--out",
        &out,
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(output.stdout.is_empty(), "nothing on stdout with --out");
    let text = std::fs::read_to_string(&*out).unwrap();
    let times: Vec<&str> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap())
        .collect();
    assert_eq!(times, ["0.0", "0.1", "0.2", "0.25"], "the last row is at T");
    let last: Vec<f64> = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|f| f.parse().unwrap())
        .collect();
    let theory = 7.893 + 9.342 * 0.25 + 0.5 * 1.087 * 0.25 * 0.25;
    assert!(
        (last[1] - theory).abs() < 1e-12,
        "x(0.25) = {} vs {theory}",
        last[1]
    );
}

#[test]
fn a_bad_scene_exits_2_listing_every_problem_with_its_position() {
    let (_dir, path) = scene_file(
        "bad.toml",
        "version = 1\n[[particle]]\nname = \"B\"\nmass = -2\nposition = [0, 0]\ncharge = \"x\"\n",
    );
    for command in ["check", "run"] {
        let mut args = vec![command, path.as_str()];
        if command == "run" {
            args.extend(["--until", "1"]);
        }
        let output = newtonlab(&args);
        assert_eq!(output.status.code(), Some(2), "{command}");
        let message = stderr(&output);
        assert!(
            message.contains(&format!(
                "{path}:4:8: particle 'B': mass must be greater than 0, got -2"
            )),
            "{message}"
        );
        assert!(
            message.contains(&format!(
                "{path}:6:10: particle 'B': charge must be a number, got text"
            )),
            "{message}"
        );
        assert!(!message.contains("panicked"), "{message}");
    }
}

/// The same problems in German with `--lang de`, in Spanish from the locale alone
/// (`LC_ALL=es_ES.UTF-8`), with the same places and exit code; an unknown language is
/// refused by name.
#[test]
fn messages_follow_lang_and_the_locale() {
    let (_dir, path) = scene_file(
        "bad.toml",
        "version = 1\n[[particle]]\nname = \"B\"\nmass = -2\nposition = [0, 0]\n",
    );
    let german = newtonlab(&["check", &path, "--lang", "de"]);
    assert_eq!(german.status.code(), Some(2));
    let message = stderr(&german);
    assert!(
        message.contains(&format!(
            "{path}:4:8: Teilchen 'B': mass muss größer als 0 sein, nicht -2"
        )) && message.contains("1 Problem gefunden"),
        "{message}"
    );
    let spanish = Command::new(env!("CARGO_BIN_EXE_newtonlab"))
        .args(["check", &path])
        .env("LC_ALL", "es_ES.UTF-8")
        .output()
        .expect("the binary runs");
    assert_eq!(spanish.status.code(), Some(2));
    let message = stderr(&spanish);
    assert!(
        message.contains(&format!(
            "{path}:4:8: partícula 'B': mass debe ser mayor que 0, no -2"
        )),
        "{message}"
    );
    let ok = newtonlab(&["check", "example:collision", "--lang", "es"]);
    assert!(
        stdout(&ok).contains("correcto (2 partículas"),
        "{}",
        stdout(&ok)
    );
    let unknown = newtonlab(&["check", "example:collision", "--lang", "fr"]);
    assert_eq!(unknown.status.code(), Some(2));
    assert!(
        stderr(&unknown).contains("choose en, de, es"),
        "{}",
        stderr(&unknown)
    );
}

#[test]
fn bad_arguments_exit_2() {
    for args in [
        vec!["run", "example:orbit", "--until", "-1"],
        vec!["run", "example:orbit", "--until", "1", "--every", "0"],
        vec!["run", "example:orbit", "--until", "nan"],
        vec!["run", "example:orbit"],
        vec!["run", "example:no-such-scene", "--until", "1"],
        vec!["run", "/no/such/file.toml", "--until", "1"],
        vec!["check", "example:no-such-scene"],
        vec!["frobnicate"],
    ] {
        let output = newtonlab(&args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(!stderr(&output).is_empty(), "{args:?} says why");
    }
}

/// A spring of k = 10¹² N/m on 1 kg stepped by explicit Euler at 0.1 s multiplies the
/// amplitude by about ωh = 10⁵ per step: it overflows within a few dozen steps.
#[test]
fn a_simulation_that_blows_up_exits_1_naming_the_particle_and_time() {
    let (_dir, path) = scene_file(
        "unstable.toml",
        "version = 1\n[simulation]\nintegrator = \"euler\"\ntime_step = 0.1\n\
         [[particle]]\nname = \"Wobbly\"\nmass = 1\nposition = [1.5, 0]\n\
         [[spring]]\nfrom = [0, 0]\nto = \"Wobbly\"\nstiffness = 1e12\nnatural_length = 1\n",
    );
    let output = newtonlab(&["run", &path, "--until", "100", "--every", "1"]);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let message = stderr(&output);
    assert!(message.contains("particle 'Wobbly'"), "{message}");
    assert!(message.contains("at t = "), "{message}");
    // The rows before the failure were written.
    assert!(
        stdout(&output).lines().count() >= 2,
        "header and the row at t = 0"
    );
}

#[test]
fn examples_lists_every_built_in_scene() {
    let output = newtonlab(&["examples"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    for example in physics::EXAMPLES {
        assert!(
            text.contains(&format!("example:{}", example.name)),
            "{text}"
        );
    }
    let listed = text.lines().filter(|l| l.contains("example:")).count();
    assert_eq!(
        listed,
        physics::EXAMPLES.len(),
        "one line per example:\n{text}"
    );
    let check = newtonlab(&["check", "example:spring-undamped"]);
    assert!(check.status.success(), "{}", stderr(&check));
}

#[test]
fn json_scenes_run_too() {
    let (_dir, path) = scene_file(
        "drop.json",
        r#"{ "version": 1, "particle": [ { "name": "Ball", "mass": 1, "position": [0, 10] } ] }"#,
    );
    let output = newtonlab(&["run", &path, "--until", "1", "--every", "1"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let last: Vec<f64> = stdout(&output)
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|f| f.parse().unwrap())
        .collect();
    // Free fall: y = 10 − g t²/2.
    assert!(
        (last[2] - (10.0 - 9.81 / 2.0)).abs() < 1e-12,
        "y(1) = {}",
        last[2]
    );
}

/// `validate` reproduces the paper's section 4 within the default 1e-6 and every later
/// group within its stated tolerances, summarises each group first, writes the report
/// and the figures, and fails (exit 1, naming what failed) when the tolerance is tighter
/// than rounding allows.
#[test]
fn validate_passes_writes_a_report_and_fails_an_impossible_tolerance() {
    let dir = tempdir::Dir::new();
    let out = dir.path.to_string_lossy().into_owned();
    let output = newtonlab(&["validate", "--out", &out]);
    assert!(
        output.status.success(),
        "{}\n{}",
        stdout(&output),
        stderr(&output)
    );
    let text = stdout(&output);
    for section in ["4.1", "4.2", "4.3", "4.4", "4.5", "4.6", "4.7"] {
        assert!(
            text.contains(&format!("\n{section} ")),
            "section {section} printed"
        );
    }
    assert!(text.contains("checks within the tolerance"), "{text}");
    let summary = text.find("\nsummary ").expect("a summary");
    let tables = summary + text[summary..].find("\n\n").expect("the summary ends");
    for group in [
        "paper",
        "rods",
        "strings",
        "integrators",
        "tree",
        "softening",
        "ledger",
        "friction",
        "saved-state",
    ] {
        // After the summary, each group's tables (the paper's are its sections 4.1–4.7).
        let heading = if group == "paper" { "4.1" } else { group };
        assert!(
            text[tables..].contains(&format!("\n{heading} ")),
            "{group}: summarised first, then its table"
        );
        assert!(
            text[summary..]
                .lines()
                .any(|l| l.trim_start().starts_with(group) && l.ends_with("pass")),
            "{group} passes in the summary"
        );
    }
    let report = std::fs::read_to_string(dir.path.join("report.md")).expect("report.md written");
    assert!(report.contains("## 4.7"), "the report has every table");
    assert!(
        report.contains("## saved-state"),
        "the later groups' tables too"
    );
    for figure in [
        "string-flight.png",
        "convergence.png",
        "spring-b0.png",
        "spring-b0.25.png",
        "spring-b0.5.png",
        "gravitation.png",
        "coulomb.png",
    ] {
        let bytes = std::fs::read(dir.path.join(figure)).expect("figure written");
        assert!(
            bytes.starts_with(b"\x89PNG") && bytes.len() > 10_000,
            "{figure} is a drawn PNG"
        );
        assert!(report.contains(figure), "{figure} linked from the report");
    }
    let only = newtonlab(&["validate", "--only", "rods", "--only", "softening"]);
    assert!(only.status.success(), "{}", stderr(&only));
    let text = stdout(&only);
    assert!(
        text.contains("\nrods ") && text.contains("\nsoftening "),
        "{text}"
    );
    assert!(
        !text.contains("\n4.2 ") && !text.contains("\ntree "),
        "only those: {text}"
    );
    let unknown = newtonlab(&["validate", "--only", "rod"]);
    assert_eq!(
        unknown.status.code(),
        Some(2),
        "an unknown group is bad input"
    );
    let output = newtonlab(&["validate", "--tolerance", "1e-18"]);
    assert_eq!(
        output.status.code(),
        Some(1),
        "an impossible tolerance fails"
    );
    assert!(
        stderr(&output).contains("exceed the tolerance"),
        "{}",
        stderr(&output)
    );
}

/// With no display the app cannot open: a clear message and exit 1, not a panic, and a
/// pointer to the commands that need none.
#[test]
fn the_app_without_a_display_explains_itself() {
    let output = Command::new(env!("CARGO_BIN_EXE_newtonlab"))
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("WAYLAND_SOCKET")
        .output()
        .expect("the binary runs");
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let message = stderr(&output);
    assert!(message.contains("could not open a window"), "{message}");
    assert!(message.contains("newtonlab --help"), "{message}");
    assert!(!message.contains("panicked"), "{message}");
}

/// A fixed-step run sampled at an interval that is not a whole number of steps says so on
/// stderr (its samples shorten steps); a multiple says nothing.
#[test]
fn sampling_off_the_step_grid_gives_a_note() {
    let off = newtonlab(&[
        "run",
        "example:spring-undamped",
        "--until",
        "0.01",
        "--every",
        "0.0015",
    ]);
    assert!(off.status.success(), "{}", stderr(&off));
    assert!(
        stderr(&off).contains("not a whole number of time steps"),
        "{}",
        stderr(&off)
    );
    let on = newtonlab(&[
        "run",
        "example:spring-undamped",
        "--until",
        "0.01",
        "--every",
        "0.002",
    ]);
    assert!(on.status.success(), "{}", stderr(&on));
    assert!(stderr(&on).is_empty(), "no note: {}", stderr(&on));
}

/// `--impacts FILE` against the impulse formulas. A (2 kg, 3 m/s) meets B (1 kg, at rest)
/// head on at t = 1 s with restitution 0.5: effective mass μ = 2/3 kg, approach u = 3 m/s,
/// impulse μ (1 + e) u = 3 N·s, separation e u = 1.5 m/s, kinetic energy lost
/// ½ μ (1 − e²) u² = 2.25 J. B leaves at 3 m/s and meets a ramp standing at x = 10 (0.1 m
/// thick: its centre stops at 9.45) at t = 1 + 5.45/3 s with the ramp's restitution 0.8:
/// μ = 1 kg, impulse 5.4 N·s, 2.4 m/s after, 1.62 J lost. The log's losses add up to the
/// kinetic energy the trajectory lost, to rounding.
#[test]
fn the_impact_log_gives_each_impulse_and_the_energy_it_took() {
    let (dir, scene) = scene_file(
        "impacts.toml",
        r#"version = 1
[world]
gravity = [0.0, 0.0]
gravitation = false
electrostatics = false
restitution = 0.5
[[ramp]]
name = "right wall"
from = [10.0, -5.0]
to = [10.0, 5.0]
restitution = 0.8
[[particle]]
name = "A"
mass = 2.0
radius = 0.5
position = [0.0, 0.0]
velocity = [3.0, 0.0]
[[particle]]
name = "B, the target"
mass = 1.0
radius = 0.5
position = [4.0, 0.0]
"#,
    );
    let log = dir.path.join("impacts.csv");
    let log_path = log.to_string_lossy().into_owned();
    let output = newtonlab(&[
        "run",
        &scene,
        "--until",
        "3.5",
        "--every",
        "3.5",
        "--impacts",
        &log_path,
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = std::fs::read_to_string(&log).expect("the log is written");
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("t,particle,other,impulse,normal_speed_before,normal_speed_after,kinetic_energy_lost")
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 2, "two impacts in 3.5 s:\n{text}");
    let expected = [
        (1.0, "A", "\"B, the target\"", [3.0, 3.0, 1.5, 2.25]),
        (
            1.0 + 5.45 / 3.0,
            "\"B, the target\"",
            "right wall",
            [5.4, 3.0, 2.4, 1.62],
        ),
    ];
    let mut lost = 0.0;
    for (row, (time, particle, other, numbers)) in rows.iter().zip(expected) {
        // The name with a comma is quoted: split on the fields' own commas.
        let (t, rest) = row.split_once(',').expect("a time");
        assert!((t.parse::<f64>().unwrap() - time).abs() < 1e-9, "{row}");
        assert!(rest.starts_with(&format!("{particle},{other},")), "{row}");
        let values: Vec<f64> = rest[particle.len() + other.len() + 2..]
            .split(',')
            .map(|v| v.parse().expect("a number"))
            .collect();
        for (got, want) in values.iter().zip(numbers) {
            assert!(
                (got - want).abs() < 1e-9 * want,
                "{row}: {got} against {want}"
            );
        }
        lost += values[3];
    }
    // The trajectory's kinetic energy: ½ m v² from its first and last rows.
    let csv = stdout(&output);
    let kinetic = |line: &str| {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        // t, then x, y, vx, vy, ax, ay per particle.
        0.5 * 2.0 * (v[3] * v[3] + v[4] * v[4]) + 0.5 * (v[9] * v[9] + v[10] * v[10])
    };
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    let drop = kinetic(rows[0]) - kinetic(rows[rows.len() - 1]);
    assert!(
        (drop - lost).abs() < 1e-9,
        "the trajectory lost {drop} J, the log {lost} J"
    );
}

/// `--save-state` writes the state at T as a scene with `start_time = T`, and a run from it
/// continues the clock: the spring (x = 10 + 5 cos t) saved at t = 10.05 (off the --every
/// grid) and run on to 20 starts with a row at 10.05, then the grid of a run from 0
/// (10.1, 10.2, …, each k × 0.1, written as the grid names it), and matches the theory to 1e-9 and the run that
/// never stopped to 1e-12 (the state is saved exactly; only step boundaries round
/// differently). A --until before the start time is refused.
#[test]
fn a_saved_state_continues_the_run_and_its_clock() {
    let dir = tempdir::Dir::new();
    let saved = dir.path.join("saved.toml").to_string_lossy().into_owned();
    let first = newtonlab(&[
        "run",
        "example:spring-undamped",
        "--until",
        "10.05",
        "--save-state",
        &saved,
    ]);
    assert!(first.status.success(), "{}", stderr(&first));
    let text = std::fs::read_to_string(&saved).expect("the state is written");
    assert!(text.contains("start_time = 10.05"), "{text}");
    let parse = |output: &Output| -> Vec<Vec<f64>> {
        stdout(output)
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
            .collect()
    };
    let continued = newtonlab(&["run", &saved, "--until", "20", "--every", "0.1"]);
    assert!(continued.status.success(), "{}", stderr(&continued));
    let continued = parse(&continued);
    let whole = parse(&newtonlab(&[
        "run",
        "example:spring-undamped",
        "--until",
        "20",
        "--every",
        "0.1",
    ]));
    assert_eq!(continued.len(), 1 + 100, "10.05, then 10.1 to 20");
    assert_eq!(
        continued[0][0].to_bits(),
        10.05_f64.to_bits(),
        "the first row at the start time"
    );
    for (k, row) in continued.iter().enumerate().skip(1) {
        let t = (100 + k) as f64 * 0.1;
        let named = (100 + k) as f64 / 10.0;
        assert_eq!(
            row[0].to_bits(),
            named.to_bits(),
            "row {k} on the grid, named"
        );
        assert!((row[1] - (10.0 + 5.0 * t.cos())).abs() < 1e-9, "x at {t}");
        let same = &whole[100 + k];
        assert_eq!(same[0].to_bits(), row[0].to_bits());
        assert!(
            (row[1] - same[1]).abs() < 1e-12,
            "x at {t}: {} and {}",
            row[1],
            same[1]
        );
        assert!((row[3] - same[3]).abs() < 1e-12, "vx at {t}");
    }
    let backwards = newtonlab(&["run", &saved, "--until", "5"]);
    assert_eq!(backwards.status.code(), Some(2));
    assert!(
        stderr(&backwards).contains("start_time"),
        "{}",
        stderr(&backwards)
    );
}

/// `--ledger` appends `dissipated_damping`, `dissipated_friction`, `dissipated_impacts`
/// and `energy_residual` to every row. A 2 kg block sliding at 3 m/s on a level floor with
/// μ = 0.5: by t friction has taken μ m g (3t − ½ μ g t²) (the ledger integrates the
/// linear friction power exactly: 1e-9 J), nothing else is lost, and the residual
/// kinetic + potential + dissipated − the starting energy stays within 1e-9 J.
#[test]
fn the_ledger_columns_account_for_the_energy_friction_takes() {
    let (_dir, scene) = scene_file(
        "slide.toml",
        r#"version = 1
[world]
gravitation = false
electrostatics = false
[[ramp]]
name = "floor"
from = [-50.0, 0.0]
to = [50.0, 0.0]
thickness = 0.0
friction = 0.5
[[particle]]
name = "block"
mass = 2.0
radius = 0.1
position = [0.0, 0.1]
velocity = [3.0, 0.0]
"#,
    );
    let output = newtonlab(&[
        "run", &scene, "--until", "0.5", "--every", "0.1", "--ledger",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let mut lines = text.lines();
    assert!(
        lines.next().unwrap().ends_with(
            ",momentum_x,momentum_y,dissipated_damping,dissipated_friction,dissipated_impacts,energy_residual,dissipated_drag"
        ),
        "header: drag's column after the residual, so that older readers keep theirs"
    );
    let mu_g = 0.5 * 9.81;
    for line in lines {
        let row: Vec<f64> = line.split(',').map(|f| f.parse().unwrap()).collect();
        let (t, n) = (row[0], row.len());
        let theory = 2.0 * mu_g * (3.0 * t - 0.5 * mu_g * t * t);
        assert!((row[n - 4] - theory).abs() < 1e-9, "t = {t}: {line}");
        assert_eq!(
            (row[n - 5], row[n - 3], row[n - 1]),
            (0.0, 0.0, 0.0),
            "t = {t}: {line}"
        );
        assert!(row[n - 2].abs() < 1e-9, "t = {t}: residual in {line}");
    }
}

/// The time machine's exactness on the command line: with a fixed-step integrator and
/// no resting contact, `run A --until 4` and `run A --until 1.5 --save-state S` followed
/// by `run S --until 4` give bit-identical rows from 1.5 s on (the state is saved to the
/// bit and the steps fall on the same instants); here for a damped spring and a double
/// pendulum on rods under every fixed-step method (a saved state's rods are not
/// projected again, and Verlet takes a velocity-dependent force at the velocity reached),
/// a pendulum, a ball swung on a string, an orbit, a charged pair and a collision (its
/// impact at 0.21 s, before the save).
#[test]
fn a_run_continued_from_a_saved_state_is_bit_identical() {
    let dir = tempdir::Dir::new();
    let fixed = ["euler", "semi-implicit-euler", "verlet", "rk4", "pefrl"];
    let mut cases: Vec<(&str, &str)> = Vec::new();
    for method in fixed {
        cases.extend([("spring-damped-light", method), ("double-pendulum", method)]);
    }
    cases.extend([
        ("pendulum", "pefrl"),
        ("pendulum", "euler"),
        ("string-circle", "verlet"),
        ("orbit", "rk4"),
        ("charged-pair", "rk4"),
        ("collision", "rk4"),
    ]);
    for (example, method) in cases {
        let path = |name: &str| {
            dir.path
                .join(format!("{example}-{method}-{name}.toml"))
                .to_string_lossy()
                .into_owned()
        };
        let (start, saved) = (path("start"), path("saved"));
        common::example_under(example, method, &start);
        let whole = newtonlab(&["run", &start, "--until", "4", "--every", "0.01"]);
        let first = newtonlab(&[
            "run",
            &start,
            "--until",
            "1.5",
            "--every",
            "0.01",
            "--save-state",
            &saved,
        ]);
        assert!(first.status.success(), "{}", stderr(&first));
        let rest = newtonlab(&["run", &saved, "--until", "4", "--every", "0.01"]);
        assert!(rest.status.success(), "{}", stderr(&rest));
        let from = |text: String| -> Vec<String> {
            text.lines()
                .skip(1)
                .filter(|line| line.split(',').next().unwrap().parse::<f64>().unwrap() >= 1.5)
                .map(str::to_owned)
                .collect()
        };
        let (whole, rest) = (from(stdout(&whole)), from(stdout(&rest)));
        assert_eq!(whole.len(), 251, "{example}, {method}: rows from 1.5 to 4");
        assert_eq!(whole, rest, "{example}, {method}: the continued run");
    }
}

/// `check` says how a tree scene's pair forces are summed: gravitation by the tree,
/// Coulomb directly.
#[test]
fn check_says_coulomb_stays_direct_under_the_tree() {
    let (_dir, scene) = scene_file(
        "tree.toml",
        "version = 1\n[simulation]\npair_forces = \"tree\"\n[[particle]]\nname = \"a\"\nmass = 1.0\ncharge = 1e-6\nposition = [0.0, 0.0]\n[[particle]]\nname = \"b\"\nmass = 1.0\nposition = [1.0, 0.0]\n",
    );
    let output = newtonlab(&["check", &scene]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    assert!(
        text.contains("Barnes–Hut tree")
            && text.contains("between its 1 charged particle(s) are summed directly"),
        "{text}"
    );
}
