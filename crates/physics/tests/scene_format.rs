//! Scene files: every problem reported at once, each with its line and column, in words a
//! student understands; load → save → load gives an equal scene.

#![expect(
    clippy::float_cmp,
    reason = "defaults are exact decimal values, compared exactly"
)]

use physics::{EXAMPLES, Endpoint, Integrator, Scene, SceneFormat, Vector};

/// The messages of a failed load, as "line:column message".
fn problems(text: &str) -> Vec<String> {
    let error = Scene::from_toml(text).expect_err("the scene is invalid");
    error
        .problems
        .iter()
        .map(|p| match (p.line, p.column) {
            (Some(l), Some(c)) => format!("{l}:{c} {}", p.message),
            _ => format!("-:- {}", p.message),
        })
        .collect()
}

const BROKEN: &str = r#"version = 1
[world]
restitution = 1.5
gravty = [0.0, -9.81]
[simulation]
integrator = "rk5"
time_step = -0.1
[[particle]]
name = "A"
mass = 1
position = [0, 0]
[[particle]]
name = "B"
mass = -2
radius = 0
position = [1, nan]
color = "red"
[[particle]]
name = "A"
mass = 1
[[spring]]
from = "A"
to = "Z"
stiffness = -1
natural_length = 1
damping = "lots"
[[ramp]]
name = ""
from = [0, 0]
to = [1, 1]
thickness = -0.2
restitution = 2
"#;

#[test]
fn every_problem_is_reported_at_once_with_its_position() {
    let found = problems(BROKEN);
    let expected = [
        "3:15 [world]: restitution must be between 0 and 1, got 1.5",
        "4:1 [world]: unknown key 'gravty'; did you mean 'gravity'?",
        "6:14 [simulation]: integrator 'rk5' is not an integrator; choose one of euler, semi-implicit-euler, verlet, rk4, pefrl, dopri5",
        "7:13 [simulation]: time_step must be greater than 0, got -0.1",
        "14:8 particle 'B': mass must be greater than 0, got -2",
        "15:10 particle 'B': radius must be greater than 0, got 0",
        "16:12 particle 'B': position must be a finite number, got NaN",
        "17:9 particle 'B': color must be a colour like \"#d94f4f\", got \"red\"",
        "19:8 particle 'A': the name 'A' is already used by particle #1; names must be unique",
        "23:6 spring 's1': to: there is no particle named 'Z'",
        "24:13 spring 's1': stiffness must be 0 or more, got -1",
        "26:11 spring 's1': damping must be a number, got text",
        "28:8 ramp #1: name must not be empty",
        "31:13 ramp #1: thickness must be 0 or more, got -0.2",
        "32:15 ramp #1: restitution must be between 0 and 1, got 2",
        "18:1 particle 'A': position is required",
    ];
    for line in &expected {
        assert!(
            found.contains(&(*line).to_owned()),
            "missing: {line}\nfound:\n{}",
            found.join("\n")
        );
    }
    assert_eq!(found.len(), expected.len(), "found:\n{}", found.join("\n"));
}

#[test]
fn syntax_errors_have_positions() {
    let found = problems("version = 1\n[[particle]]\nmass = = 2\n");
    assert!(found[0].starts_with("3:"), "{found:?}");
    assert!(found[0].contains("not valid TOML"), "{found:?}");
    let error = Scene::from_json("{\n  \"version\": 1,\n  \"particle\": [\n}").unwrap_err();
    assert_eq!(error.problems[0].line, Some(4), "{error}");
    assert!(
        error.problems[0].message.contains("not valid JSON"),
        "{error}"
    );
}

/// JSON's problems are told as TOML's are: at the line and column of the value or key
/// (the JSON reader keeps ranges), a `null` as null, a key given twice refused rather
/// than the last kept, a byte-order mark passed over; in both formats a number no f64
/// holds is named as written, not as 0 or NaN, and an integer beyond i64 is the number it
/// says.
#[test]
fn json_is_read_as_exactly_as_toml() {
    let at = |text: &str| {
        let error = Scene::from_json(text).expect_err("refused");
        let p = &error.problems[0];
        (p.line, p.column, p.message.clone())
    };
    let (line, column, message) = at(
        "{\n  \"version\": 1,\n  \"particle\": [{\"name\": \"a\", \"mass\": -1, \"position\": [0, 0]}]\n}",
    );
    assert_eq!((line, column), (Some(3), Some(38)), "{message}");
    assert!(
        message.contains("mass must be greater than 0, got -1"),
        "{message}"
    );
    let (_, _, message) = at(
        "{\"version\": 1, \"particle\": [{\"name\": \"a\", \"mass\": null, \"position\": [0, 0]}]}",
    );
    assert!(message.ends_with("got null"), "{message}");
    let (line, column, message) = at("{\"version\": 1,\n \"version\": 1}");
    assert_eq!((line, column), (Some(2), Some(2)), "{message}");
    assert!(message.contains("'version' appears twice"), "{message}");
    assert!(
        Scene::from_json("\u{feff}{\"version\": 1}").is_ok(),
        "a byte-order mark"
    );
    for (text, format) in [
        (
            "{\"version\": 1, \"simulation\": {\"time_step\": 1e-400}}",
            physics::SceneFormat::Json,
        ),
        (
            "version = 1\n[simulation]\ntime_step = 1e-400\n",
            physics::SceneFormat::Toml,
        ),
        (
            "version = 1\n[simulation]\ntime_step = 1e400\n",
            physics::SceneFormat::Toml,
        ),
    ] {
        let error = Scene::parse(text, format).expect_err("refused");
        let message = &error.problems[0].message;
        assert!(
            message.contains("is beyond what a 64-bit number holds"),
            "{message}"
        );
        assert!(
            message.contains("1e-400") || message.contains("1e400"),
            "{message}"
        );
    }
    let scene = Scene::from_toml(
        "version = 1\n[[particle]]\nname = \"a\"\nmass = 99999999999999999999\nposition = [0.0, 0.0]\n",
    )
    .expect("an integer beyond i64 is still a number");
    assert_eq!(scene.particles[0].mass, 1e20, "its value");
}

/// A section that is not a table is one problem, not three (the defaults read in its
/// place are not checked); a problem of a field left out is placed at its section.
#[test]
fn a_wrong_section_is_one_problem_and_a_missing_field_has_a_place() {
    let error = Scene::from_toml("version = 1\nrod = [\"x\"]\n").expect_err("refused");
    assert_eq!(error.problems.len(), 1, "{error}");
    assert!(
        error.problems[0].message.contains("must be a table"),
        "{error}"
    );
    let error = Scene::from_toml(
        "version = 1\n[world]\ngravitation = false\n[[particle]]\nname = \"a\"\nmass = 1.0\nposition = [0.0, 0.0]\n\
         [[particle]]\nname = \"b\"\nmass = 1.0\nposition = [0.0, 0.0]\n\
         [[rod]]\nname = \"r\"\nfrom = \"a\"\nto = \"b\"\n",
    )
    .expect_err("refused");
    let length = error
        .problems
        .iter()
        .find(|p| p.message.contains("length"))
        .expect("the rod's length");
    assert_eq!((length.line, length.column), (Some(12), Some(1)), "{error}");
}

#[test]
fn version_is_required_and_must_be_1() {
    assert!(
        problems("name = \"x\"\n")[0].contains("version is required"),
        "missing version"
    );
    assert!(
        problems("version = 2\n")[0].contains("version 2 is not supported"),
        "version 2"
    );
}

#[test]
fn structural_mistakes_are_explained() {
    let found = problems("version = 1\n[particle]\nmass = 1\n");
    assert!(
        found[0].contains("'particle' must be a list of [[particle]] tables"),
        "{found:?}"
    );
    let found = problems("version = 1\n[[particle]]\nmass = 1\nposition = [1, 2, 3]\n");
    assert!(
        found[0].contains("position must be [x, y] or { magnitude = m, angle = degrees }"),
        "{found:?}"
    );
    let found = problems("version = 1\n[[particle]]\nmass = 1\nposition = { magnitude = 1 }\n");
    assert!(
        found[0].contains("needs both magnitude and angle"),
        "{found:?}"
    );
    let found = problems(
        "version = 1\n[[spring]]\nfrom = [0, 0]\nto = [1, 1]\nstiffness = 1\nnatural_length = 1\n",
    );
    assert!(found[0].contains("both ends are fixed points"), "{found:?}");
    let found = problems("version = 1\n[world]\nbounds = { min = [1, 1], max = [0, 5] }\n");
    assert!(
        found[0].contains("min must be below and left of max"),
        "{found:?}"
    );
    let found = problems("version = 1\n[world]\ngravitational_constant = inf\n");
    assert!(
        found[0].contains("gravitational_constant must be a finite number, got inf"),
        "{found:?}"
    );
}

#[test]
fn defaults_follow_the_design() {
    let scene = Scene::from_toml("version = 1\n[[particle]]\nmass = 2\nposition = [1, 2]\n[[particle]]\nmass = 1\nposition = [0, 0]\n[[spring]]\nfrom = \"p1\"\nto = [0, 0]\nstiffness = 1\nnatural_length = 1\n").unwrap();
    assert_eq!(scene.particles[0].name, "p1", "default names in file order");
    assert_eq!(scene.particles[1].name, "p2", "default names in file order");
    assert_eq!(scene.springs[0].name, "s1", "springs too");
    assert_eq!(scene.particles[0].radius, 0.5, "default radius");
    assert_eq!(
        scene.world.gravity,
        Vector::cartesian(0.0, -9.81),
        "default gravity"
    );
    assert_eq!(
        scene.world.gravitational_constant, 6.6742e-11,
        "the paper's G"
    );
    assert_eq!(
        scene.simulation.integrator,
        Integrator::Rk4,
        "default integrator"
    );
    assert_eq!(scene.simulation.time_step, 0.001, "default time step");
}

/// A scene with every kind of field in both vector forms survives TOML and JSON.
fn everything() -> Scene {
    Scene::from_toml(
        r##"version = 1
name = "Everything \"quoted\""
description = """two
lines"""
[world]
gravity = { magnitude = 9.81, angle = -90 }
gravitation = false
gravitational_constant = 1e-3
electrostatics = true
coulomb_constant = 0.1
softening = 0.125
collisions = false
restitution = 0.25
bounds = { min = [-5.5, -1e3], max = [55.5, 100.1] }
[simulation]
integrator = "dopri5"
time_step = 0.1
tolerance = 1e-12
time_scale = 0.3333333333333333
[[particle]]
name = "A, the first"
mass = 0.1
radius = 0.2
charge = -1.6e-19
position = { magnitude = 32.725, angle = 45 }
velocity = [1e-100, -0.0]
acceleration = [0.1, 0.2]
fixed = true
color = "#A1b2C3"
[[particle]]
mass = 3
position = [1, 2]
[[spring]]
from = [1, 1]
to = "p2"
stiffness = 1
natural_length = 0
[[ramp]]
from = [0, 0]
to = { magnitude = 10, angle = 30 }
thickness = 0
restitution = 0
friction = 0.5
[[graph]]
title = "Phase of A"
x = "A, the first.x"
y = ["A, the first.vx", "p2.kinetic_energy"]
[[graph]]
y = ["total_energy", "momentum_y"]
[view]
center = [0.5, -2]
width = 30
follow = "p2"
"##,
    )
    .expect("the scene is valid")
}

/// `softening` and `collisions`, added to version 1 for star clusters: read and checked
/// like every number (0 or more, with its position), and written only when not at their
/// defaults, so that a file which does not use them saves exactly as it did before the
/// keys existed.
#[test]
fn softening_is_checked_and_written_only_when_used() {
    let plain = "version = 1\n[[particle]]\nmass = 1\nposition = [0, 0]\n";
    let scene = Scene::from_toml(plain).expect("valid");
    assert_eq!(scene.world.softening, 0.0, "the exact laws by default");
    for format in [SceneFormat::Toml, SceneFormat::Json] {
        let text = scene.to_text(format);
        assert!(
            !text.contains("softening") && !text.contains("collisions"),
            "{format:?}"
        );
    }
    let soft = Scene::from_toml(
        &plain.replace("version = 1\n", "version = 1\n[world]\nsoftening = 0.05\n"),
    )
    .expect("valid");
    assert_eq!(soft.world.softening, 0.05);
    assert!(
        soft.to_toml().contains("\nsoftening = 0.05\n"),
        "{}",
        soft.to_toml()
    );
    assert_eq!(
        problems("version = 1\n[world]\nsoftening = -0.5\n"),
        ["3:13 [world]: softening must be 0 or more, got -0.5"]
    );
}

#[test]
fn load_save_load_gives_an_equal_scene() {
    let mut scenes: Vec<Scene> = EXAMPLES.iter().map(|e| e.scene().unwrap()).collect();
    scenes.push(everything());
    for scene in scenes {
        for format in [SceneFormat::Toml, SceneFormat::Json] {
            let text = scene.to_text(format);
            let again = Scene::parse(&text, format).unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_eq!(again, scene, "{format:?} round trip:\n{text}");
            // Saving again gives the same text: nothing drifts from save to save.
            assert_eq!(again.to_text(format), text, "{format:?} is stable");
        }
    }
}

#[test]
fn forms_are_kept_as_typed() {
    let scene = everything();
    assert!(
        matches!(scene.particles[0].position, Vector::Polar { .. }),
        "polar stays polar"
    );
    assert!(
        matches!(scene.particles[0].velocity, Vector::Cartesian(_)),
        "Cartesian stays"
    );
    assert_eq!(
        scene.springs[0].from,
        Endpoint::Point(Vector::cartesian(1.0, 1.0)),
        "fixed point"
    );
    assert_eq!(
        scene.particles[0].color.unwrap().to_hex(),
        "#a1b2c3",
        "colour"
    );
    assert!(
        scene
            .to_toml()
            .contains("position = { magnitude = 32.725, angle = 45.0 }"),
        "{}",
        scene.to_toml()
    );
}

#[test]
fn every_example_is_valid() {
    // The registry is exactly the scene files shipped in `examples/scenes`: a file
    // added without registering it (or a name registered twice) fails here.
    let directory = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes");
    let mut on_disk: Vec<String> = std::fs::read_dir(&directory)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "toml"))
        .map(|path| path.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    on_disk.sort();
    let mut registered: Vec<String> = EXAMPLES
        .iter()
        .filter(|e| e.file_text().is_some())
        .map(|e| e.name.to_owned())
        .collect();
    registered.sort();
    assert_eq!(
        registered, on_disk,
        "the registry lists every example file once"
    );
    for example in EXAMPLES {
        let scene = example
            .scene()
            .unwrap_or_else(|e| panic!("{}: {e}", example.name));
        assert!(scene.name.is_some(), "{} has a title", example.name);
        physics::Simulation::new(&scene).unwrap();
    }
}

/// `[[graph]]` and `[view]` are checked like everything else: every wrong name or form
/// reported with its position, in the app's words.
#[test]
fn graphs_and_views_are_checked_with_positions() {
    let found = problems(
        r#"version = 1
[[particle]]
name = "A"
mass = 1
position = [0, 0]
[[graph]]
x = "A.vx"
y = ["B.x", "A.z", "t", 3]
[[graph]]
title = "energy"
y = ["energy", "A.speed"]
colour = "red"
[view]
width = -1
follow = "B"
"#,
    );
    assert_eq!(
        found,
        [
            "8:5 graph #1: y must be a list of quantities in quotes, like [\"A.x\", \"total_energy\"], got a number",
            "11:5 graph 'energy': y: 'energy' is not a quantity: write t, NAME.x (or .y, .vx, .vy, .speed, .ax, .ay, .kinetic_energy; turning: .angle, .spin), ROD.angle (or .length, .tension), or one of kinetic_energy, potential_energy, total_energy, momentum_x, momentum_y, angular_momentum",
            "12:1 graph 'energy': unknown key 'colour'; the keys here are title, x, y",
            "14:9 [view]: width must be greater than 0, got -1",
            "15:10 [view]: follow: there is no particle 'B'; follow a particle's name, or \"all\"",
        ]
    );
    let found = problems(
        r#"version = 1
[[particle]]
name = "A"
mass = 1
position = [0, 0]
[[graph]]
x = "B.vx"
y = ["B.x", "A.z", "t"]
"#,
    );
    assert_eq!(
        found,
        [
            "7:5 graph #1: x: 'B.vx' names no particle; there is no particle 'B'",
            // A name that is no quantity is found as the file is read, before the checks.
            "8:5 graph #1: y: 'A.z': a particle's quantity is one of x, y, vx, vy, speed, ax, ay, kinetic_energy, angle, spin, angular_momentum; a rod's, string's or spring's is angle or length, and a rod's or string's also tension",
            "8:5 graph #1: y: 'B.x' names no particle; there is no particle 'B'",
            "8:5 graph #1: y: time goes on the x axis (x = \"t\")",
        ]
    );
    // A link's angle and length name a rod, string or spring; its tension a rod or string.
    let found = problems(
        r#"version = 1
[[particle]]
name = "A"
mass = 1
position = [0, -1]
[[spring]]
name = "s"
from = "A"
to = [0, 0]
stiffness = 1
natural_length = 1
[[graph]]
y = ["s.angle", "s.length", "cord.angle", "s.tension"]
"#,
    );
    assert_eq!(
        found,
        [
            "13:5 graph #1: y: 'cord.angle' names no rod, string or spring; there is none named 'cord'",
            "13:5 graph #1: y: 's.tension' names no rod or string; there is none named 's'",
        ]
    );
}

/// Every default in the field table is the default: a file that writes it out loads to
/// the same scene as a file that leaves it out.
#[test]
fn the_field_tables_defaults_are_the_defaults() {
    use physics::fields::{self, Field};
    fn check<T>(header: &str, required: &str, fields: &[Field<T>]) {
        let bare = format!("version = 1\n{header}\n{required}");
        let expected = Scene::from_toml(&bare).expect("valid");
        for f in fields {
            let Some(default) = f.default.filter(|d| {
                d.starts_with(['[', '"', '-'])
                    || d.starts_with(|c: char| c.is_ascii_digit())
                    || *d == "true"
                    || *d == "false"
            }) else {
                continue; // "none", "a palette colour": no value to write
            };
            let text = format!("version = 1\n{header}\n{required}{} = {default}\n", f.key);
            let written = Scene::from_toml(&text).unwrap_or_else(|e| panic!("{}: {e}", f.key));
            assert_eq!(written, expected, "{header} {} = {default}", f.key);
        }
    }
    check("[world]", "", fields::WORLD);
    check("[simulation]", "", fields::SIMULATION);
    check(
        "[[particle]]",
        "mass = 1.0\nposition = [0.0, 0.0]\n",
        fields::PARTICLE,
    );
    check(
        "[[particle]]\nname = \"A\"\nmass = 1.0\nposition = [0.0, 0.0]\n[[spring]]",
        "from = \"A\"\nto = [1.0, 0.0]\nstiffness = 1.0\nnatural_length = 1.0\n",
        fields::SPRING,
    );
    check(
        "[[ramp]]",
        "from = [0.0, 0.0]\nto = [1.0, 0.0]\n",
        fields::RAMP,
    );
}

/// The reference in docs/scene-format.md is the field table's: change a field and this
/// fails until the docs say the same (the message has the text to paste).
#[test]
fn the_docs_reference_is_the_field_table() {
    let docs = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/scene-format.md"
    ))
    .expect("docs/scene-format.md");
    let reference = physics::fields::reference();
    assert!(
        docs.contains(&reference),
        "docs/scene-format.md should contain the field reference:\n\n{reference}"
    );
}

/// A particle must lie inside the world's bounds, save for a press into a wall of up to a
/// tenth of its radius: a ball resting on the floor of a pile sits about 1 % into it, and
/// a saved state of that pile must open again.
#[test]
fn particles_lie_inside_the_bounds_up_to_a_press_into_a_wall() {
    let scene = |x: f64, y: f64| {
        format!(
            "version = 1\n[world]\nbounds = {{ min = [0, 0], max = [10, 10] }}\n\
             [[particle]]\nname = \"A\"\nmass = 1\nradius = 1\nposition = [{x}, {y}]\n"
        )
    };
    for (x, y) in [
        (5.0, 5.0),
        (1.0, 1.0),
        (9.0, 9.0),
        (0.95, 5.0),
        (5.0, 9.05),
        (0.905, 9.095),
    ] {
        assert!(
            Scene::from_toml(&scene(x, y)).is_ok(),
            "a ball at ({x}, {y}) is inside, or pressed less than a tenth of its radius into a wall"
        );
    }
    for (x, y) in [
        (0.85, 5.0),
        (5.0, 9.2),
        (5.0, -3.0),
        (12.0, 5.0),
        (0.5, 0.5),
    ] {
        assert_eq!(
            problems(&scene(x, y)),
            [format!(
                "8:12 particle 'A': position [{x}, {y}] puts the particle (radius 1) outside the world bounds"
            )],
            "a ball at ({x}, {y}) reaches out of the box"
        );
    }
}

/// The table of particles by name gives each name the index a search by name finds: the
/// first particle of a repeated name (which the scene's checks report), and none for a
/// name no particle has.
#[test]
fn the_table_of_names_finds_what_a_search_finds() {
    let scene = physics::Scene::new()
        .with_particle(physics::Particle::new("a", 1.0))
        .with_particle(physics::Particle::new("b", 1.0))
        .with_particle(physics::Particle::new("a", 2.0))
        .with_particle(physics::Particle::new("c", 1.0));
    let names = scene.particle_indices();
    for name in ["a", "b", "c", "d"] {
        assert_eq!(
            names.get(name).copied(),
            scene.particle_index(name),
            "{name}"
        );
    }
    assert_eq!(names.get("a"), Some(&0));
    assert_eq!(names.len(), 3);
}
