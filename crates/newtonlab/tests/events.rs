//! `newtonlab run --events` on the real binary: rows at the located instants against the
//! closed forms, regular rows untouched by the events, and bad events refused by name.

mod common;

use common::{newtonlab, pendulum_period, scene_file, stderr, stdout, table};

/// A ball thrown from 10 m at (3, 4) m/s: `--events "Ball.y crosses 0 down"` writes one
/// row, run's columns, at t = (v + √(v² + 2 g h)) / g to 1e-9 s, y there 0 to 1e-9 m.
#[test]
fn a_landing_is_one_row_at_its_instant() {
    let (_dir, path) = scene_file(
        "throw.toml",
        r#"version = 1
[world]
gravity = [0.0, -9.81]
[[particle]]
name = "Ball"
mass = 1.0
radius = 0.1
position = [0.0, 10.0]
velocity = [3.0, 4.0]
"#,
    );
    let output = newtonlab(&[
        "run",
        &path,
        "--until",
        "3",
        "--events",
        "Ball.y crosses 0 down",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let (header, rows) = table(&stdout(&output));
    let run = newtonlab(&["run", &path, "--until", "0"]);
    let (run_header, _) = table(&stdout(&run));
    assert_eq!(header, run_header, "run's columns");
    assert_eq!(rows.len(), 1, "{rows:?}");
    let g = 9.81_f64;
    let landing = (4.0 + (16.0 + 2.0 * g * 10.0_f64).sqrt()) / g;
    let t: f64 = rows[0][0].parse().expect("a number");
    let y: f64 = rows[0][2].parse().expect("a number");
    assert!((t - landing).abs() < 1e-9, "t = {t}, theory {landing}");
    assert!(y.abs() < 1e-9, "y = {y}");
}

/// With --every too, both kinds of rows come in time order with a last column `event`;
/// the regular rows are a plain run's, bit for bit (as text), and the pendulum's turning
/// points (`bob.vx crosses 0`) are at the half periods 2 √(L/g) K(sin 30°) k of the
/// 60° pendulum on its 2 m rod to 1e-8 s.
#[test]
fn events_among_regular_rows_leave_them_as_they_were() {
    let plain = newtonlab(&["run", "example:pendulum", "--until", "4", "--every", "0.05"]);
    let both = newtonlab(&[
        "run",
        "example:pendulum",
        "--until",
        "4",
        "--every",
        "0.05",
        "--events",
        "bob.vx crosses 0",
        "--events",
        "rod.angle crosses 0",
    ]);
    assert!(both.status.success(), "{}", stderr(&both));
    let (plain_header, plain_rows) = table(&stdout(&plain));
    let (header, rows) = table(&stdout(&both));
    assert_eq!(header.last().map(String::as_str), Some("event"));
    assert_eq!(header[..header.len() - 1], plain_header[..]);
    let regular: Vec<&[String]> = rows
        .iter()
        .filter(|r| r.last().is_some_and(String::is_empty))
        .map(|r| &r[..r.len() - 1])
        .collect();
    let plain_rows: Vec<&[String]> = plain_rows.iter().map(Vec::as_slice).collect();
    assert_eq!(regular, plain_rows, "regular rows unchanged");
    let times: Vec<f64> = rows.iter().map(|r| r[0].parse().expect("t")).collect();
    assert!(times.windows(2).all(|w| w[0] <= w[1]), "in time order");
    let period = pendulum_period(2.0, 60.0);
    let turns: Vec<f64> = rows
        .iter()
        .filter(|r| r.last().is_some_and(|e| e == "bob.vx crosses 0"))
        .map(|r| r[0].parse().expect("t"))
        .collect();
    assert_eq!(turns.len(), 2, "{turns:?}");
    for (k, t) in turns.iter().enumerate() {
        let expected = (k + 1) as f64 * period / 2.0;
        assert!(
            (t - expected).abs() < 1e-8,
            "turn {k}: {t} against {expected}"
        );
    }
    let passes = rows
        .iter()
        .filter(|r| r.last().is_some_and(|e| e == "rod.angle crosses 0"))
        .count();
    assert_eq!(passes, 3, "at T/4, 3T/4, 5T/4");
}

/// An event on an unknown object or quantity, or one that is not an event, exits 2 with
/// the problem named and writes no table.
#[test]
fn bad_events_exit_2_naming_the_problem() {
    for (event, says) in [
        ("Bob.vx crosses 0", "no particle named 'Bob'"),
        ("bob.q crosses 0", "a particle's quantity is one of"),
        (
            "cord.angle crosses 0",
            "no rod, string or spring named 'cord'",
        ),
        ("bob.vx crosses", "is not an event"),
        ("", "is not an event"),
        ("bob.vx crosses 1e999", "not a finite number"),
    ] {
        let output = newtonlab(&["run", "example:pendulum", "--until", "1", "--events", event]);
        assert_eq!(output.status.code(), Some(2), "{event:?}");
        assert!(
            stderr(&output).contains(says),
            "{event:?}: {}",
            stderr(&output)
        );
        assert!(stdout(&output).is_empty(), "{event:?}: no table");
    }
}
