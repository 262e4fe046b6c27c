//! What the command line's tests share: the real binary, its output, scene files in
//! temporary directories.

// Each test file is a crate of its own that uses some of these.
#![allow(
    dead_code,
    reason = "each test binary uses a part of the shared fixtures"
)]

use std::process::{Command, Output};

/// The binary, speaking English whatever the machine's locale (the messages follow
/// `LC_ALL`, `LC_MESSAGES` and `LANG`; "C" names no language, so English).
pub fn newtonlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_newtonlab"))
        .args(args)
        .env("LC_ALL", "C")
        .output()
        .expect("the binary runs")
}

pub fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).expect("UTF-8 output")
}

pub fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).expect("UTF-8 output")
}

/// A CSV's header and rows, split at commas (no field of `run`'s is quoted).
pub fn table(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("a header")
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    (header, rows)
}

/// A scene file in a fresh temporary directory.
pub fn scene_file(name: &str, text: &str) -> (tempdir::Dir, String) {
    let dir = tempdir::Dir::new();
    let path = dir.path.join(name);
    std::fs::write(&path, text).expect("the temporary directory is writable");
    let path = path.to_string_lossy().into_owned();
    (dir, path)
}

/// Asserts that `output` is a refusal of bad input (exit 2) whose message holds `words`.
pub fn assert_refused(output: &Output, words: &str, context: &dyn std::fmt::Debug) {
    assert_eq!(
        output.status.code(),
        Some(2),
        "{context:?}: {}",
        stderr(output)
    );
    assert!(
        stderr(output).contains(words),
        "{context:?}: {}",
        stderr(output)
    );
}

/// Writes to `path` the built-in scene `example` as a scene file (its state at the start,
/// every key spelled out) under the integration `method`.
pub fn example_under(example: &str, method: &str, path: &str) {
    let written = newtonlab(&[
        "run",
        &format!("example:{example}"),
        "--until",
        "0",
        "--save-state",
        path,
    ]);
    assert!(written.status.success(), "{}", stderr(&written));
    let text = std::fs::read_to_string(path).expect("the state is written");
    let changed: Vec<String> = text
        .lines()
        .map(|line| {
            if line.starts_with("integrator = ") {
                format!("integrator = \"{method}\"")
            } else {
                line.to_owned()
            }
        })
        .collect();
    std::fs::write(path, changed.join("\n")).expect("the scene is written");
}

pub mod tempdir {
    /// A directory removed when dropped.
    pub struct Dir {
        pub path: std::path::PathBuf,
    }

    impl Dir {
        pub fn new() -> Self {
            use std::sync::atomic::{AtomicU32, Ordering};
            static COUNTER: AtomicU32 = AtomicU32::new(0);
            let n = COUNTER.fetch_add(1, Ordering::Relaxed);
            let path =
                std::env::temp_dir().join(format!("newtonlab-cli-{}-{n}", std::process::id()));
            std::fs::create_dir_all(&path).expect("the temporary directory can be made");
            Self { path }
        }
    }

    impl Drop for Dir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.path);
        }
    }
}

/// The period of a pendulum of `length` m released at rest `amplitude` degrees from the
/// vertical, g = 9.81: 4 √(L/g) K(sin(θ₀/2)), K by the arithmetic–geometric mean (written
/// apart from the program, as the theory the tests hold them to).
pub fn pendulum_period(length: f64, amplitude: f64) -> f64 {
    let k = (amplitude.to_radians() / 2.0).sin();
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..20 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    4.0 * (length / 9.81).sqrt() * std::f64::consts::PI / (2.0 * a)
}
