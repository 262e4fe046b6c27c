//! Rigid bodies through the command line: the contract's columns, `check`'s mass
//! properties, bad bodies refused with line and column, `sweep` varying a body, the
//! `bodies` group of `validate`.

mod common;

use common::{assert_refused, newtonlab, scene_file, stderr, stdout};

const BLOCK: &str = r#"version = 1

[[particle]]
name = "ball"
mass = 1.0
radius = 0.1
position = [-3.0, 2.0]

[[body]]
name = "block"
shape = "box"
width = 0.4
height = 0.2
mass = 2.0
position = [0.0, 1.0]
angle = 20.0
spin = 1.0
"#;

#[test]
fn run_writes_each_body_s_columns_after_the_particles() {
    let (_dir, path) = scene_file("block.toml", BLOCK);
    let output = newtonlab(&["run", &path, "--until", "0.5", "--every", "0.5"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let text = stdout(&output);
    let header: Vec<&str> = text.lines().next().expect("a header").split(',').collect();
    let block: Vec<&str> = header[7..15].to_vec();
    assert_eq!(
        block,
        [
            "block.x",
            "block.y",
            "block.vx",
            "block.vy",
            "block.ax",
            "block.ay",
            "block.angle",
            "block.spin"
        ]
    );
    assert_eq!(header.last(), Some(&"angular_momentum"));
    // The last row: the block fell freely for 0.5 s and turned 0.5 rad.
    let last: Vec<f64> = text
        .lines()
        .last()
        .expect("rows")
        .split(',')
        .map(|v| v.parse().expect("a number"))
        .collect();
    assert!(
        (last[8] - (1.0 - 0.5 * 9.81 * 0.25)).abs() < 1e-12,
        "{}",
        last[8]
    );
    assert!((last[13] - (20.0 + 0.5_f64.to_degrees())).abs() < 1e-12);
}

#[test]
fn check_says_a_body_s_mass_properties() {
    let (_dir, path) = scene_file("block.toml", BLOCK);
    let output = newtonlab(&["check", &path]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let text = stdout(&output);
    assert!(
        text.contains("body 'block': box 0.4 × 0.2 m, area 0.08 m², mass 2 kg, moment of inertia 0.0333333333 kg·m²"),
        "{text}"
    );
}

#[test]
fn a_wrong_body_is_refused_at_its_line_and_column() {
    let text = BLOCK.replace(
        "shape = \"box\"",
        "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]]",
    );
    let text = text.replace("width = 0.4\nheight = 0.2\n", "");
    let (_dir, path) = scene_file("clockwise.toml", &text);
    let output = newtonlab(&["check", &path]);
    assert_refused(
        &output,
        "clockwise.toml:12:12: body 'block': the vertices go clockwise",
        &text,
    );
}

#[test]
fn sweep_varies_a_body_s_start_angle() {
    let (_dir, path) = scene_file("block.toml", BLOCK);
    let output = newtonlab(&[
        "sweep",
        &path,
        "--vary",
        "block.angle=10:30:10",
        "--until",
        "1",
        "--measure",
        "block.angle at 1",
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let text = stdout(&output);
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().expect("a number")).collect())
        .collect();
    assert_eq!(rows.len(), 3, "{text}");
    for row in rows {
        assert!(
            (row[1] - (row[0] + 1_f64.to_degrees())).abs() < 1e-9,
            "{row:?}"
        );
    }
}

#[test]
fn validate_runs_the_bodies_group() {
    let output = newtonlab(&["validate", "--only", "bodies"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(stdout(&output).contains("Rigid bodies: resting, sliding, tipping and striking"));
}
