//! What a fuzzing campaign broke, on the real binary: each input exits with its problem
//! named (exit 2), never a panic (101), a hang, or NaN with exit 0.

mod common;

use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use common::{scene_file, stderr};

/// The binary with `args`, killed after `seconds` (a hang is a failure, not a stuck test).
fn within(seconds: u64, args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_newtonlab"))
        .args(args)
        .env("LC_ALL", "C")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let deadline = Instant::now() + Duration::from_secs(seconds);
    while child.try_wait().expect("waits").is_none() {
        if Instant::now() > deadline {
            let _ = child.kill();
            panic!("{args:?} still running after {seconds} s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("its output")
}

/// Two particles that attract each other at one point (gravitation on by default, no
/// softening) above a ramp with friction: the force between them is infinite, so the
/// scene is refused — by `check`, and by `run` under every integrator — naming both;
/// before, `run --until 0` panicked in the surface's friction. Charged particles alone
/// likewise; uncharged ones without gravitation simply overlap and are pushed apart.
#[test]
fn coincident_attracting_particles_are_refused_not_a_panic() {
    let scene = |world: &str, integrator: &str| {
        format!(
            "version = 1\n{world}\n[simulation]\nintegrator = \"{integrator}\"\n\
             [[particle]]\nname = \"A\"\nmass = 1.0\nposition = [0.0, 0.0]\ncharge = 1e-6\n\
             [[particle]]\nname = \"B\"\nmass = 1.0\nposition = [-0.0, 0.0]\ncharge = 1e-6\n\
             [[ramp]]\nname = \"r\"\nfrom = [-1.0, -0.5]\nto = [1.0, -0.5]\nfriction = 1.0\n"
        )
    };
    for integrator in [
        "euler",
        "semi-implicit-euler",
        "verlet",
        "rk4",
        "pefrl",
        "dopri5",
    ] {
        for world in ["", "[world]\ngravitation = false"] {
            let (_dir, path) = scene_file("same.toml", &scene(world, integrator));
            for args in [vec!["check", &path], vec!["run", &path, "--until", "0"]] {
                let output = within(20, &args);
                assert_eq!(
                    output.status.code(),
                    Some(2),
                    "{integrator} {world:?} {args:?}"
                );
                let said = stderr(&output);
                assert!(
                    said.contains("particle 'B'") && said.contains("same point as particle 'A'"),
                    "{said}"
                );
            }
        }
    }
    let apart = scene(
        "[world]\ngravitation = false\nelectrostatics = false",
        "rk4",
    );
    let (_dir, path) = scene_file("apart.toml", &apart);
    let output = within(20, &["run", &path, "--until", "0.2"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(!String::from_utf8_lossy(&output.stdout).contains("NaN"));
}

/// A clock that cannot advance is refused, not run for ever: a start time of 1e17 s (or
/// 1e16 s, where t + 1 ms == t) with a 1 ms step, and rows every 1e-19 s at t = 1 s.
#[test]
fn a_clock_that_cannot_tell_its_instants_apart_is_refused() {
    for start in ["1e17", "1e16"] {
        let (_dir, path) = scene_file(
            "late.toml",
            &format!("version = 1\n[simulation]\nstart_time = {start}\n"),
        );
        let output = within(10, &["run", &path, "--until", start]);
        assert_eq!(output.status.code(), Some(2), "{start}");
        assert!(
            stderr(&output).contains("too fine for a clock"),
            "{}",
            stderr(&output)
        );
    }
    let (_dir, path) = scene_file("one.toml", "version = 1\n[simulation]\nstart_time = 1.0\n");
    let output = within(10, &["run", &path, "--until", "1", "--every", "1e-19"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("too fine"), "{}", stderr(&output));
}

/// A saved state always reopens: a run from 1e-100 m at −1e-100 m/s saves a position of
/// some 1e-114 m, which `check` accepts (a coordinate multiplies into no overflow, so only
/// numbers, not coordinates, must be at least 1e-100), and a subnormal one too; a state
/// flung beyond 1e100 m is not written but said, exit 1.
#[test]
fn a_saved_state_reopens_or_is_not_written() {
    let (dir, path) = scene_file(
        "tiny.toml",
        "version = 1\n[world]\ngravity = [0.0, 0.0]\n[[particle]]\nname = \"a\"\nmass = 1.0\n\
         position = [1e-100, 0.0]\nvelocity = [-1e-100, 4e-312]\n",
    );
    let saved = dir.path.join("saved.toml");
    let saved = saved.to_string_lossy();
    let output = within(10, &["run", &path, "--until", "1", "--save-state", &saved]);
    assert!(output.status.success(), "{}", stderr(&output));
    let check = within(10, &["check", &saved]);
    assert!(check.status.success(), "{}", stderr(&check));
    let (dir, path) = scene_file(
        "far.toml",
        "version = 1\n[world]\ngravity = [0.0, 0.0]\n[[particle]]\nname = \"a\"\nmass = 1.0\n\
         position = [9.9e99, 0.0]\nvelocity = [1e99, 0.0]\n",
    );
    let saved = dir.path.join("far-saved.toml");
    let output = within(
        10,
        &[
            "run",
            &path,
            "--until",
            "1",
            "--save-state",
            &saved.to_string_lossy(),
        ],
    );
    assert_eq!(output.status.code(), Some(1));
    assert!(stderr(&output).contains("cannot be saved as a scene that reopens"));
    assert!(!saved.exists(), "nothing written that would not reopen");
}

/// Arguments the fuzzing campaign broke, each now its own message, exit 2: a negative
/// number with an exponent (`--until -1e+99`, `--every -1e-3`: clap took "-1" for a
/// flag), one file for two outputs (their rows interleaved, exit 0), a device or a
/// directory as the scene (`/dev/zero` was read until memory ran out), `bench` with no
/// particles (NaN printed) or more than memory holds (an abort).
#[test]
fn bad_arguments_are_named() {
    let (dir, scene) = scene_file(
        "one.toml",
        "version = 1\n[[particle]]\nname = \"a\"\nmass = 1.0\nposition = [0.0, 0.0]\n",
    );
    let same = dir.path.join("x.csv");
    let same = same.to_string_lossy();
    for (args, words) in [
        (vec!["run", scene.as_str(), "--until", "-1e+99"], "until"),
        (
            vec!["run", scene.as_str(), "--until", "1", "--every", "-1e-3"],
            "--every",
        ),
        (
            vec![
                "run",
                scene.as_str(),
                "--until",
                "1",
                "--out",
                &same,
                "--impacts",
                &same,
            ],
            "both name",
        ),
        (vec!["check", "/dev/zero"], "not a file"),
        (vec!["check", "/tmp"], "not a file"),
        (
            vec!["bench", "--scene", "cluster", "--particles", "0"],
            "--particles",
        ),
        (vec!["bench", "--particles", "1000000000"], "--particles"),
    ] {
        let output = within(20, &args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(
            stderr(&output).contains(words),
            "{args:?}: {}",
            stderr(&output)
        );
    }
}
