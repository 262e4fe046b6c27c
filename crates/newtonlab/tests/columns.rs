//! `newtonlab run --column QUANTITY` on the real binary: a quantity the standard columns
//! do not hold gets a column of its own, after the others and before `event`, held to
//! Newton's laws; the standard columns are untouched; a quantity that names nothing is
//! refused by name.

mod common;

use common::{newtonlab, scene_file, stderr, stdout, table};

/// A 2 kg bob on a 1.5 m rod from a pivot at the origin, let go at 50° from the vertical.
const PENDULUM: &str = r#"version = 1
[world]
gravity = [0.0, -9.81]
[[particle]]
name = "bob"
mass = 2.0
radius = 0.05
position = { magnitude = 1.5, angle = -40.0 }
[[rod]]
name = "rod"
from = [0.0, 0.0]
to = "bob"
"#;

/// The CSV's header and rows of numbers (a text field, the `event`, as NaN).
fn numbers(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let (header, rows) = table(text);
    let parse = |row: Vec<String>| row.iter().map(|v| v.parse().unwrap_or(f64::NAN)).collect();
    (header, rows.into_iter().map(parse).collect())
}

/// The rod's tension in its own column is what holds the bob on its circle: along the
/// rod, T − m g cos θ = m v² / L, read off each row's own position and velocity (θ from
/// the downward vertical). To 1e-7 of m g: the rod holds its length to a billionth, and
/// the row's velocity is tangent to that. The bob's speed and kinetic energy are its
/// velocity's, and every standard column is what a run without `--column` writes.
#[test]
fn a_rods_tension_is_a_column_that_holds_the_bob_on_its_circle() {
    let (_dir, path) = scene_file("pendulum.toml", PENDULUM);
    let base = ["run", &path, "--until", "3", "--every", "0.05"];
    let plain = newtonlab(&base);
    let mut with = base.to_vec();
    with.extend([
        "--column",
        "rod.tension",
        "--column",
        " bob.speed ",
        "--column",
        "bob.kinetic_energy",
    ]);
    let output = newtonlab(&with);
    assert!(output.status.success(), "{}", stderr(&output));
    let (header, rows) = numbers(&stdout(&output));
    let (plain_header, plain_rows) = numbers(&stdout(&plain));
    let n = plain_header.len();
    assert_eq!(header[..n], plain_header[..]);
    assert_eq!(
        header[n..],
        ["rod.tension", "bob.speed", "bob.kinetic_energy"]
    );
    assert_eq!(rows.len(), plain_rows.len());
    let (m, g, length) = (2.0, 9.81, 1.5);
    let mut largest_tension = 0.0_f64;
    for (row, plain) in rows.iter().zip(&plain_rows) {
        let same = row[..n]
            .iter()
            .zip(plain)
            .all(|(a, b)| a.to_bits() == b.to_bits());
        assert!(same, "standard columns changed at t = {}", row[0]);
        let (x, y, vx, vy) = (row[1], row[2], row[3], row[4]);
        let cos_theta = -y / length;
        let v2 = vx * vx + vy * vy;
        let tension = m * g * cos_theta + m * v2 / length;
        assert!(
            (row[n] - tension).abs() < 1e-7 * m * g,
            "t = {}: tension {} against {tension} (x = {x})",
            row[0],
            row[n]
        );
        assert!(
            (row[n + 1] - v2.sqrt()).abs() < 1e-12,
            "speed at t = {}",
            row[0]
        );
        assert!(
            (row[n + 2] - 0.5 * m * v2).abs() < 1e-12,
            "energy at t = {}",
            row[0]
        );
        largest_tension = largest_tension.max(row[n]);
    }
    // Through the bottom: m g (3 − 2 cos θ₀), the swing's largest pull.
    let bottom = m * g * (3.0 - 2.0 * 50_f64.to_radians().cos());
    assert!(largest_tension > 0.99 * bottom && largest_tension < bottom * (1.0 + 1e-9));
}

/// With the ledger and events, the asked columns come after the ledger's and before
/// `event`, on the events' rows too, and the ledger keeps its shortest form (`0`).
#[test]
fn asked_columns_follow_the_ledger_and_precede_the_event() {
    let (_dir, path) = scene_file("pendulum.toml", PENDULUM);
    let output = newtonlab(&[
        "run",
        &path,
        "--until",
        "2",
        "--every",
        "0.5",
        "--ledger",
        "--events",
        "bob.vx crosses 0",
        "--column",
        "rod.angle",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let tail = &header[header.len() - 4..];
    assert_eq!(
        tail,
        ["energy_residual", "dissipated_drag", "rod.angle", "event"]
    );
    // The start: the ledger's `0`s, then the rod at 50° from straight down (the bob at
    // −40° from +x, to the right of the pivot: counter-clockwise from down is positive).
    let first = text.lines().nth(1).unwrap();
    let fields: Vec<&str> = first.split(',').collect();
    assert_eq!(
        fields[fields.len() - 4..fields.len() - 2],
        ["0", "0"],
        "{first}"
    );
    let start: f64 = fields[fields.len() - 2].parse().unwrap();
    assert!((start - 50.0).abs() < 1e-12, "{first}");
    // A turning point of the swing, at ±50° (no energy lost).
    let event = text
        .lines()
        .find(|l| l.ends_with(",bob.vx crosses 0"))
        .expect("an event row");
    let angle: f64 = event.split(',').rev().nth(1).unwrap().parse().unwrap();
    assert!((angle.abs() - 50.0).abs() < 1e-6, "{event}");
}

/// A quantity that does not parse or names nothing in the scene is refused, exit 2,
/// naming it and the flag.
#[test]
fn a_column_that_names_nothing_is_refused() {
    let (_dir, path) = scene_file("pendulum.toml", PENDULUM);
    for (column, words) in [
        ("nobody.x", "nobody"),
        ("bob.weight", "bob.weight"),
        ("spring.tension", "spring"),
    ] {
        let output = newtonlab(&[
            "run", &path, "--until", "1", "--column", column, "--lang", "en",
        ]);
        assert_eq!(output.status.code(), Some(2), "{column}");
        let message = stderr(&output);
        assert!(
            message.contains("--column") && message.contains(words),
            "{message}"
        );
        assert!(stdout(&output).is_empty(), "{column}: rows written");
    }
}
