//! Fuzzing scene files: mutated TOML and JSON never panic and never hang. The corpus is
//! every built-in scene in both encodings; each input applies one to eight mutations
//! (a token from a dictionary of keys, numbers and punctuation put in place of a random
//! span, a span deleted, a line repeated, random bytes inserted). Each input is parsed;
//! one that loads is run for 20 steps on another thread, which must finish within a
//! second. A load error is a fine answer; a panic or a timeout fails.
//!
//! `NEWTONLAB_FUZZ_INPUTS` sets the number of inputs (default 5,000, a few seconds; the
//! long run in the README used 1,000,000). The same count always gives the same inputs.

use std::cell::Cell;
use std::sync::mpsc;
use std::time::Duration;

use physics::{EXAMPLES, Scene, SceneFormat, Simulation};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

/// Longest wall time for parsing and 20 steps of one input.
const PATIENCE: Duration = Duration::from_secs(1);

/// Pieces a mutation puts in: the format's own words, and numbers at the edges of f64.
const DICTIONARY: &[&str] = &[
    "[[particle]]",
    "[[spring]]",
    "[[ramp]]",
    "[[graph]]",
    "[world]",
    "[simulation]",
    "[view]",
    "name",
    "mass",
    "radius",
    "charge",
    "position",
    "velocity",
    "acceleration",
    "fixed",
    "color",
    "from",
    "to",
    "stiffness",
    "natural_length",
    "damping",
    "thickness",
    "restitution",
    "friction",
    "gravity",
    "bounds",
    "integrator",
    "time_step",
    "tolerance",
    "time_scale",
    "x",
    "y",
    "follow",
    "width",
    "center",
    "magnitude",
    "angle",
    "min",
    "max",
    "\"dopri5\"",
    "\"euler\"",
    "\"all\"",
    "\"A.x\"",
    "\"t\"",
    "0",
    "-0.0",
    "1",
    "-1",
    "0.5",
    "1e308",
    "-1e308",
    "1e-308",
    "5e-324",
    "1e100",
    "1e-100",
    "1e101",
    "nan",
    "inf",
    "-inf",
    "true",
    "false",
    "=",
    ",",
    "[",
    "]",
    "{",
    "}",
    "\"",
    "\n",
    " ",
    "#",
    ".",
    "\"\"\"",
    "\u{0}",
    "\u{1F600}",
    "\\u0000",
    ":",
    "null",
];

/// Every built-in scene as TOML and as JSON (the ball pits and the generated clusters are
/// left out: their size
/// would make each input slow, and the other scenes cover every key).
fn corpus() -> Vec<(String, SceneFormat)> {
    EXAMPLES
        .iter()
        .filter(|e| !e.name.starts_with("ball-pit") && e.file_text().is_some())
        .flat_map(|e| {
            let scene = e.scene().expect("valid");
            [
                (scene.to_toml(), SceneFormat::Toml),
                (scene.to_json(), SceneFormat::Json),
            ]
        })
        .collect()
}

#[derive(Clone, Debug)]
enum Mutation {
    /// Put a dictionary word in place of `len` bytes at `at` (fractions of the text).
    Replace {
        at: f64,
        len: usize,
        word: usize,
    },
    Delete {
        at: f64,
        len: usize,
    },
    /// Repeat the line around `at`.
    Repeat {
        at: f64,
    },
    Insert {
        at: f64,
        bytes: Vec<u8>,
    },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (0.0..1.0, 0usize..12, 0..DICTIONARY.len())
            .prop_map(|(at, len, word)| Mutation::Replace { at, len, word }),
        2 => (0.0..1.0, 1usize..40).prop_map(|(at, len)| Mutation::Delete { at, len }),
        1 => (0.0..1.0).prop_map(|at| Mutation::Repeat { at }),
        1 => (0.0..1.0, prop::collection::vec(any::<u8>(), 1..8))
            .prop_map(|(at, bytes)| Mutation::Insert { at, bytes }),
    ]
}

/// Byte `i` of `text` (at most its end), moved back to a character boundary.
fn back_to_boundary(text: &str, i: usize) -> usize {
    let mut i = i.min(text.len());
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// The position `at` (a fraction of the length) in `text`, on a character boundary.
fn boundary(text: &str, at: f64) -> usize {
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        clippy::cast_precision_loss,
        reason = "a fraction of a length"
    )]
    back_to_boundary(text, ((text.len() as f64) * at) as usize)
}

fn apply(text: &mut String, mutation: &Mutation) {
    match mutation {
        Mutation::Replace { at, len, word } => {
            let start = boundary(text, *at);
            let end = back_to_boundary(text, start + len).max(start);
            text.replace_range(start..end, DICTIONARY[*word]);
        }
        Mutation::Delete { at, len } => {
            let start = boundary(text, *at);
            let end = back_to_boundary(text, start + len).max(start);
            text.replace_range(start..end, "");
        }
        Mutation::Repeat { at } => {
            let i = boundary(text, *at);
            let start = text[..i].rfind('\n').map_or(0, |k| k + 1);
            let end = text[i..].find('\n').map_or(text.len(), |k| i + k + 1);
            let line = text[start..end].to_owned();
            text.insert_str(end, &line);
        }
        Mutation::Insert { at, bytes } => {
            let i = boundary(text, *at);
            text.insert_str(i, &String::from_utf8_lossy(bytes));
        }
    }
}

/// Parses and, when it loads, runs 20 steps; within [`PATIENCE`], without a panic.
fn survive(text: &str, format: SceneFormat) -> Result<(), String> {
    let (done, wait) = mpsc::channel();
    let input = text.to_owned();
    std::thread::spawn(move || {
        if let Ok(scene) = Scene::parse(&input, format)
            && let Ok(mut simulation) = Simulation::new(&scene)
        {
            for _ in 0..20 {
                if simulation.step().is_err() {
                    break;
                }
            }
        }
        let _ = done.send(());
    });
    wait.recv_timeout(PATIENCE).map_err(|error| match error {
        mpsc::RecvTimeoutError::Timeout => format!("took more than {PATIENCE:?}:\n{text}"),
        mpsc::RecvTimeoutError::Disconnected => format!("panicked:\n{text}"),
    })
}

#[test]
fn mutated_scene_files_never_panic_or_hang() {
    let inputs: u32 = std::env::var("NEWTONLAB_FUZZ_INPUTS")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(5_000);
    let corpus = corpus();
    let config = Config {
        cases: inputs,
        failure_persistence: None,
        ..Config::default()
    };
    let rng = TestRng::deterministic_rng(RngAlgorithm::ChaCha);
    let mut runner = TestRunner::new_with_rng(config, rng);
    let strategy = (0..corpus.len(), prop::collection::vec(mutation(), 1..=8));
    let (loaded, total) = (Cell::new(0_u64), Cell::new(0_u64));
    let result = runner.run(&strategy, |(pick, mutations)| {
        let (mut text, format) = corpus[pick].clone();
        for m in &mutations {
            apply(&mut text, m);
        }
        total.set(total.get() + 1);
        if Scene::parse(&text, format).is_ok() {
            loaded.set(loaded.get() + 1);
        }
        survive(&text, format).map_err(TestCaseError::fail)
    });
    eprintln!(
        "{} inputs, {} of them loaded and ran",
        total.get(),
        loaded.get()
    );
    if let Err(failure) = result {
        panic!("{failure}");
    }
}
