//! Fuzzing the command line: random argument lists for `run`, `check` and `examples`,
//! from a vocabulary of the real flags, scene names, paths that do not exist and numbers
//! at the edges of f64, never panic (Rust's panic exit code 101) and always end within a
//! few seconds with 0, 1 or 2. The runs asked for are short (--until at most 10 s of the
//! built-in scenes); a long run asked for on purpose is allowed to take long, and the
//! absurd ones are refused up front (tested in cli.rs).

use std::process::Command;
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::strategy::ValueTree as _;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

const WORDS: &[&str] = &[
    "run",
    "check",
    "examples",
    "--until",
    "--every",
    "--out",
    "-",
    "--help",
    "-h",
    "example:collision",
    "example:orbit",
    "example:newtons-cradle",
    "example:nothing",
    "example:",
    "no-such-file.toml",
    "/",
    "",
    " ",
    "0",
    "-0",
    "1",
    "10",
    "-1",
    "0.05",
    "1e-300",
    "5e-324",
    "nan",
    "inf",
    "-inf",
    "1e308",
    "0x10",
    "--",
    "--until=1",
    "--every=0",
    "--unknown",
    "\u{e9}",
    "run run",
];

#[test]
fn random_command_lines_never_panic() {
    let config = Config {
        cases: 300,
        failure_persistence: None,
        ..Config::default()
    };
    let mut generator =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let lines = prop::collection::vec(0..WORDS.len(), 0..7);
    let out = std::env::temp_dir().join(format!("newtonlab-fuzz-{}.csv", std::process::id()));
    for _ in 0..300 {
        let mut args: Vec<String> = lines
            .new_tree(&mut generator)
            .expect("generated")
            .current()
            .into_iter()
            .map(|k| WORDS[k].to_owned())
            .collect();
        // Never open the window, and keep the file system untouched but for one file.
        if args
            .first()
            .is_none_or(|a| !["run", "check", "examples"].contains(&a.as_str()))
        {
            args.insert(0, "check".to_owned());
        }
        for k in 0..args.len() {
            if args[k] == "--out" && k + 1 < args.len() {
                args[k + 1] = out.to_string_lossy().into_owned();
            }
        }
        let started = Instant::now();
        let output = Command::new(env!("CARGO_BIN_EXE_newtonlab"))
            .args(&args)
            .output()
            .expect("runs");
        let code = output.status.code();
        assert!(
            matches!(code, Some(0..=2)),
            "{args:?} exited with {code:?}:\n{}",
            String::from_utf8_lossy(&output.stderr)
        );
        assert!(
            started.elapsed() < Duration::from_secs(20),
            "{args:?} took {:?}",
            started.elapsed()
        );
    }
    std::fs::remove_file(&out).ok();
}
