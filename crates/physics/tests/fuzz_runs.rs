//! Fuzzing runs: scenes generated from the scene format's grammar — particles, springs,
//! rods, strings and ramps with values drawn from the edges of f64 (0, −0, 1e±100,
//! 1e±300, 5e-324, 1e12, 1e13, NaN, inf, a 20-digit integer) and from ordinary
//! numbers, every integrator, bounds, coincident particles — each checked as `check`
//! does and, when valid, run as `newtonlab run --until 0.5 --every 0.05` does (the same
//! `physics::Trajectory`, with its limits on work). What must hold, for every scene:
//!
//! - no panic, and no hang (each scene runs on a thread that must finish within
//!   [`PATIENCE`]);
//! - a refusal or a failure says why in words;
//! - a run that ends well has only finite numbers in its rows (a NaN with exit 0 is a
//!   silent wrong answer);
//! - its particles stay inside the world's bounds, and each rod holds its length and each
//!   string its limit (to a billionth of the length: silent wrong answers that a fuzzing
//!   campaign found, a string stretched to twice its length, a ball out of its box);
//! - its saved state reopens: it is refused in words, or it reads back as a scene.
//!
//! `NEWTONLAB_FUZZ_SCENES` sets the number of scenes (default 300, a few seconds; the
//! figure in docs/testing.md is of 100,000). The same count gives the same scenes. The
//! cases the campaign found are the seed corpus (`SEEDS`), run first every time.

use std::cell::Cell;
use std::fmt::Write as _;
use std::sync::mpsc;
use std::time::Duration;

use physics::{Plan, Scene, Trajectory};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

/// Longest wall time for checking and running one scene: the run's work is bounded by
/// the trajectory's limits, so only a hang takes longer.
const PATIENCE: Duration = Duration::from_mins(1);

/// The scenes the fuzzing campaign broke (`issues`: "Unbreakable, round two"), kept so
/// that every run of the harness tries them first.
const SEEDS: &[&str] = &[
    // Found by the generator: two charges 1e-100 m apart, whose Coulomb acceleration
    // overflows to infinity at t = 0 while their positions are finite. The run must fail
    // in words, not write a row of inf.
    r#"version = 1
[world]
gravity = [0.0, 0.0]
gravitation = false
collisions = false
[[particle]]
name = "a"
mass = 0.01
position = { magnitude = 1e-100, angle = 0.0 }
charge = 6.509064164016301
[[particle]]
name = "b"
mass = 0.01
position = [0.0, 0.0]
charge = -0.9539060574896102
"#,
    // A panic in the friction of a surface contact: two particles at one point above a
    // ramp with friction.
    r#"version = 1
[[particle]]
name = "a"
mass = 1.0
position = [0.0, 0.0]
[[particle]]
name = "b"
mass = 1.0
position = [0.0, 0.0]
[[ramp]]
name = "r"
from = [-1.0, -0.5]
to = [1.0, -0.5]
friction = 1.0
"#,
    // The same without gravitation, so that the pair is not refused as coincident and
    // attracting, with each integrator in turn below.
    r#"version = 1
[world]
gravitation = false
[simulation]
integrator = "pefrl"
[[particle]]
name = "a"
mass = 1.0
position = [0.0, 0.0]
[[particle]]
name = "b"
mass = 1.0
position = [0.0, 0.0]
[[ramp]]
name = "r"
from = [-1.0, -0.5]
to = [1.0, -0.5]
friction = 1.0
"#,
    // A hang: a clock that cannot advance.
    "version = 1\n[simulation]\nstart_time = 1e17\n",
    // A string between 1 kg and 1e12 kg stretched to twice its length.
    r#"version = 1
[world]
gravitation = false
[[particle]]
name = "light"
mass = 1.0
radius = 0.1
position = [0.0, 0.0]
[[particle]]
name = "heavy"
mass = 1e12
radius = 0.1
position = [0.0, 5.0]
[[particle]]
name = "pivot"
mass = 1.0
radius = 0.1
position = [2.0, 0.0]
[[rod]]
name = "rod"
from = "light"
to = "pivot"
[[string]]
name = "string"
from = "light"
to = "heavy"
"#,
    // A ball on a string inside a ramp 1e100 thick.
    r#"version = 1
[[particle]]
name = "ball"
mass = 1.0
radius = 0.1
position = [0.0, 0.0]
[[string]]
name = "s"
from = "ball"
to = [0.0, 1.0]
[[ramp]]
name = "r"
from = [-1.0, 0.0]
to = [1.0, 0.0]
thickness = 1e100
"#,
    // A particle at 1e13 m/s in a box of 10 m.
    r#"version = 1
[world]
bounds = { min = [-5.0, -5.0], max = [5.0, 5.0] }
[[particle]]
name = "fast"
mass = 1.0
radius = 0.1
position = [0.0, 0.0]
velocity = [1e13, 3e12]
"#,
    // A state that saved 4.999999999999938e-101, which the checker refused.
    r#"version = 1
[world]
gravity = [0.0, 0.0]
[[particle]]
name = "tiny"
mass = 1.0
position = [1e-100, 0.0]
velocity = [-1e-100, 0.0]
"#,
];

/// Numbers from the edges of f64 and of the checker's range, and ordinary ones.
const EDGES: &[&str] = &[
    "0.0",
    "-0.0",
    "1.0",
    "-1.0",
    "0.5",
    "2.0",
    "1e-100",
    "1e100",
    "-1e100",
    "1e-300",
    "1e300",
    "5e-324",
    "1e12",
    "-1e12",
    "1e13",
    "1e-9",
    "1e-3",
    "nan",
    "inf",
    "-inf",
    "99999999999999999999",
    "1e-400",
];

fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        12 => (-10.0f64..10.0).prop_map(|x| format!("{x:?}")),
        1 => (0usize..EDGES.len()).prop_map(|k| EDGES[k].to_owned()),
    ]
}

fn positive() -> impl Strategy<Value = String> {
    prop_oneof![
        12 => (0.01f64..5.0).prop_map(|x| format!("{x:?}")),
        1 => number(),
    ]
}

fn vector() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (number(), number()).prop_map(|(x, y)| format!("[{x}, {y}]")),
        1 => (positive(), number()).prop_map(|(m, a)| format!("{{ magnitude = {m}, angle = {a} }}")),
    ]
}

/// A small coordinate, so that generated particles often meet.
fn near() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (-3i32..=3, -3i32..=3).prop_map(|(x, y)| format!("[{x}.0, {y}.0]")),
        1 => vector(),
    ]
}

const NAMES: &[&str] = &["a", "b", "c", "d"];

fn endpoint() -> impl Strategy<Value = String> {
    prop_oneof![
        // The first two names most often: scenes have them more often than the others.
        4 => (0..2usize).prop_map(|k| format!("\"{}\"", NAMES[k])),
        1 => (2..NAMES.len()).prop_map(|k| format!("\"{}\"", NAMES[k])),
        1 => near(),
    ]
}

const INTEGRATORS: &[&str] = &[
    "euler",
    "semi-implicit-euler",
    "verlet",
    "rk4",
    "pefrl",
    "dopri5",
];

fn world() -> impl Strategy<Value = String> {
    (
        vector(),
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
        prop::option::of(prop_oneof![
            4 => Just("{ min = [-5.0, -5.0], max = [5.0, 5.0] }".to_owned()),
            1 => Just("{ min = [-5.0, -5.0], max = [5.0, 5.0], friction = 0.6 }".to_owned()),
            1 => (near(), near()).prop_map(|(min, max)| format!("{{ min = {min}, max = {max} }}")),
        ]),
        prop_oneof![20 => (0.0f64..=1.0).prop_map(|e| format!("{e:?}")), 1 => number()],
        prop_oneof![2 => Just("0.0".to_owned()), 1 => positive()],
    )
        .prop_map(|(gravity, gravitation, electrostatics, collisions, bounds, restitution, friction)| {
            let mut text = format!(
                "[world]\ngravity = {gravity}\ngravitation = {gravitation}\nelectrostatics = {electrostatics}\ncollisions = {collisions}\nrestitution = {restitution}\nfriction = {friction}\n"
            );
            if let Some(bounds) = bounds {
                let _ = writeln!(text, "bounds = {bounds}");
            }
            text
        })
}

fn simulation() -> impl Strategy<Value = String> {
    (
        0..INTEGRATORS.len(),
        prop_oneof![4 => Just("0.001".to_owned()), 1 => Just("0.01".to_owned()), 1 => positive()],
        prop_oneof![4 => Just("0.0".to_owned()), 1 => number()],
    )
        .prop_map(|(k, step, start)| {
            format!(
                "[simulation]\nintegrator = \"{}\"\ntime_step = {step}\nstart_time = {start}\n",
                INTEGRATORS[k]
            )
        })
}

/// A particle, named `{}` for its name to be put in.
fn particle() -> impl Strategy<Value = String> {
    (
        Just(()),
        positive(),
        prop::option::of(positive()),
        prop::option::of(number()),
        near(),
        prop::option::of(vector()),
        prop::bool::weighted(0.15),
        prop::option::of(positive()),
        // Turning: a disc, a ring or any inertia, with any spin.
        prop::option::of((
            prop_oneof![Just("0.5".to_owned()), Just("1.0".to_owned()), positive()],
            number(),
        )),
    )
        .prop_map(|((), mass, radius, charge, position, velocity, fixed, drag, turning)| {
            let mut text = format!(
                "[[particle]]\nname = \"{{}}\"\nmass = {mass}\nposition = {position}\nfixed = {fixed}\n"
            );
            if let Some(radius) = radius {
                let _ = writeln!(text, "radius = {radius}");
            }
            if let Some(charge) = charge {
                let _ = writeln!(text, "charge = {charge}");
            }
            if let Some(velocity) = velocity {
                let _ = writeln!(text, "velocity = {velocity}");
            }
            if let Some(drag) = drag {
                let _ = writeln!(text, "quadratic_drag = {drag}");
            }
            if let Some((inertia, spin)) = turning {
                let _ = writeln!(text, "inertia = {inertia}\nspin = {spin}");
            }
            text
        })
}

fn link() -> impl Strategy<Value = String> {
    (0..4usize, endpoint(), endpoint(), positive(), positive(), prop::option::of(positive()))
        .prop_map(|(kind, from, to, a, b, length)| match kind {
            0 => format!(
                "[[spring]]\nname = \"s\"\nfrom = {from}\nto = {to}\nstiffness = {a}\nnatural_length = {b}\n"
            ),
            1 | 2 => {
                let kind = if kind == 1 { "rod" } else { "string" };
                let mut text = format!("[[{kind}]]\nname = \"{kind}\"\nfrom = {from}\nto = {to}\n");
                if let Some(length) = length {
                    let _ = writeln!(text, "length = {length}");
                }
                text
            }
            _ => format!(
                "[[ramp]]\nname = \"r\"\nfrom = {from}\nto = {to}\nthickness = {a}\nfriction = {b}\n"
            )
            .replace("from = \"", "from = [0.0, -1.0] #")
            .replace("to = \"", "to = [2.0, -1.5] #"),
        })
}

fn scene() -> impl Strategy<Value = String> {
    (
        world(),
        simulation(),
        prop::collection::vec(particle(), 0..=NAMES.len()),
        prop::collection::vec(link(), 0..3),
    )
        .prop_map(|(world, simulation, particles, links)| {
            let mut text = format!("version = 1\n{world}{simulation}");
            // Distinct names (the ones links name), so that scenes are not all refused
            // for a duplicate.
            for (k, p) in particles.iter().enumerate() {
                text.push_str(&p.replacen("{}", NAMES[k], 1));
            }
            for (k, l) in links.iter().enumerate() {
                // Distinct names, so that links are not all refused as duplicates.
                text.push_str(&l.replacen("name = \"", &format!("name = \"{k}"), 1));
            }
            text
        })
}

/// Checks `text` as `check` does and runs it as `run --until 0.5 --every 0.05` does:
/// `Ok` with what happened, or why a property failed.
fn run(text: &str) -> Result<&'static str, String> {
    let Ok(scene) = Scene::from_toml(text) else {
        return Ok("refused");
    };
    let start = scene.simulation.start_time;
    let plan = Plan {
        until: start + 0.5,
        every: Some(0.05),
        ..Plan::default()
    };
    let mut trajectory = match Trajectory::new(&scene, &plan) {
        Ok(trajectory) => trajectory,
        Err(why) if !why.trim().is_empty() => return Ok("refused to run"),
        Err(_) => return Err("refused without a word".to_owned()),
    };
    let columns = trajectory.columns();
    let mut problem = None;
    let outcome = loop {
        let stepped = trajectory.advance(&mut |row| {
            if problem.is_none()
                && let Some(k) = row.values.iter().position(|v| !v.is_finite())
            {
                problem = Some(format!(
                    "{} = {} at t = {}",
                    columns[k], row.values[k], row.values[0]
                ));
            }
        });
        match stepped {
            None => break Ok(()),
            Some(Ok(())) => {}
            Some(Err(error)) => break Err(error.to_string()),
        }
    };
    if let Some(problem) = problem {
        return Err(format!(
            "a number that is not finite in a good run: {problem}"
        ));
    }
    if let Err(why) = outcome {
        return if why.trim().is_empty() {
            Err("failed without a word".to_owned())
        } else {
            Ok("failed")
        };
    }
    let simulation = trajectory.simulation();
    let positions = simulation.positions();
    if let Some(bounds) = scene.world.bounds {
        let (min, max) = (bounds.min.to_dvec2(), bounds.max.to_dvec2());
        for (i, x) in positions.iter().enumerate() {
            let slack = 1e-6 * (max - min).length().max(simulation.radii()[i]);
            if x.x < min.x - slack
                || x.y < min.y - slack
                || x.x > max.x + slack
                || x.y > max.y + slack
            {
                return Err(format!("{} left the bounds: at {x}", simulation.names()[i]));
            }
        }
    }
    for (k, tie) in scene.ties.iter().enumerate() {
        let (from, to) = simulation.link_ends(physics::Link::Tie(k));
        let length = from.distance(to);
        let limit = simulation_tie_length(&scene, k);
        let stretched = (length - limit) / limit;
        let broken = match tie.kind {
            physics::TieKind::Rod => stretched.abs() > 1e-9,
            physics::TieKind::String => stretched > 1e-9,
        };
        if broken {
            return Err(format!(
                "tie '{}' is {length} m long, held to {limit} m",
                tie.name
            ));
        }
    }
    let saved = simulation.saved_state(&scene);
    if saved.validate().is_empty() {
        Scene::from_toml(&saved.to_toml())
            .map_err(|e| format!("the saved state does not reopen: {e}"))?;
    }
    Ok("ran")
}

/// The length tie `k` keeps: its own, or the distance at the start.
fn simulation_tie_length(scene: &Scene, k: usize) -> f64 {
    let tie = &scene.ties[k];
    if tie.length > 0.0 {
        return tie.length;
    }
    let at = |end: &physics::Endpoint| match end {
        physics::Endpoint::Particle(name) => scene.particles
            [scene.particle_index(name).expect("valid")]
        .position
        .to_dvec2(),
        physics::Endpoint::Point(p) => p.to_dvec2(),
    };
    at(&tie.from).distance(at(&tie.to))
}

/// [`run`] on a thread of its own, within [`PATIENCE`].
fn survive(text: &str) -> Result<&'static str, String> {
    let (done, wait) = mpsc::channel();
    let input = text.to_owned();
    std::thread::spawn(move || {
        let _ = done.send(run(&input));
    });
    match wait.recv_timeout(PATIENCE) {
        Ok(Ok(what)) => Ok(what),
        Ok(Err(why)) => Err(format!("{why}:\n{text}")),
        Err(mpsc::RecvTimeoutError::Timeout) => {
            Err(format!("took more than {PATIENCE:?}:\n{text}"))
        }
        Err(mpsc::RecvTimeoutError::Disconnected) => Err(format!("panicked:\n{text}")),
    }
}

#[test]
fn the_campaigns_cases_hold() {
    for seed in SEEDS {
        if let Err(why) = survive(seed) {
            panic!("{why}");
        }
    }
}

#[test]
fn generated_scenes_never_panic_hang_or_answer_wrong_in_silence() {
    let scenes: u32 = std::env::var("NEWTONLAB_FUZZ_SCENES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(300);
    let config = Config {
        cases: scenes,
        failure_persistence: None,
        ..Config::default()
    };
    let rng = TestRng::deterministic_rng(RngAlgorithm::ChaCha);
    let mut runner = TestRunner::new_with_rng(config, rng);
    let counts: [Cell<u64>; 4] = Default::default();
    let result = runner.run(&scene(), |text| {
        let what = survive(&text).map_err(TestCaseError::fail)?;
        let k = ["refused", "refused to run", "failed", "ran"]
            .iter()
            .position(|w| *w == what)
            .unwrap_or(0);
        counts[k].set(counts[k].get() + 1);
        Ok(())
    });
    eprintln!(
        "{scenes} scenes: {} refused by the checker, {} by the run's limits, {} failed in words, {} ran",
        counts[0].get(),
        counts[1].get(),
        counts[2].get(),
        counts[3].get()
    );
    if let Err(failure) = result {
        panic!("{failure}");
    }
}
