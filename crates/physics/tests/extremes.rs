//! Extreme but representable numbers never hang and never panic. Each case takes a
//! built-in scene, sets one to three numbers of its field table (a mass, a radius, a stiffness, a
//! constant, a time step, a velocity component…) to a value anywhere in the f64 range,
//! and then either validation refuses the scene with a reason, or 50 steps run, each in
//! bounded time, ending in a state or in a `SimulationError` that names what went wrong.
//! A step that takes more than a few seconds is a hang, and fails the test.

mod common;

use std::sync::mpsc;
use std::time::Duration;

use common::example_scene;
use physics::fields::{self, Field, Kind, Value};
use physics::{EXAMPLES, Scene, Simulation, Vector};
use proptest::prelude::*;

/// Longest wall time for the 50 steps of one case (they take milliseconds).
const PATIENCE: Duration = Duration::from_secs(10);

/// The small built-in scenes (the ball pits have their own tests; the generated clusters
/// are thousands of bodies).
fn scenes() -> Vec<Scene> {
    EXAMPLES
        .iter()
        .filter(|e| !e.name.starts_with("ball-pit") && e.file_text().is_some())
        .map(|e| e.scene().expect("valid"))
        .collect()
}

/// Sets the `k`-th numeric entry of a section's fields (numbers and vector components)
/// to `value`; returns whether there was one.
fn set_number<T>(fields: &[Field<T>], target: &mut T, k: usize, value: f64) -> bool {
    let mut slots = Vec::new();
    for f in fields {
        match f.kind {
            Kind::Number(_) => slots.push((f, None)),
            Kind::Vector => slots.extend([(f, Some(0)), (f, Some(1))]),
            _ => {}
        }
    }
    let Some(&(f, component)) = slots.get(k % slots.len().max(1)) else {
        return false;
    };
    let new = match ((f.get)(target), component) {
        (Value::Number(_), None) => Value::Number(value),
        (Value::Vector(v), Some(c)) => {
            let mut v = v.to_dvec2();
            v[c] = value;
            Value::Vector(Vector::Cartesian(v))
        }
        _ => return false,
    };
    (f.set)(target, new);
    true
}

/// One number, anywhere in the f64 range, often at the extremes.
fn extreme() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
        Just(f64::MAX),
        Just(1e-100),
        Just(1e100),
        Just(-1e100),
        (-320i32..=308, any::<bool>()).prop_map(|(e, negative)| {
            let v = 10f64.powi(e);
            if negative { -v } else { v }
        }),
    ]
}

/// Runs 50 steps on another thread; `Err` with the scene when they take too long or panic.
fn run_bounded(scene: Scene) -> Result<(), String> {
    let (done, wait) = mpsc::channel();
    let text = scene.to_toml();
    std::thread::spawn(move || {
        if let Ok(mut simulation) = Simulation::new(&scene) {
            for _ in 0..50 {
                if simulation.step().is_err() {
                    break; // a failure is an answer: a message, not a hang
                }
            }
        }
        let _ = done.send(());
    });
    wait.recv_timeout(PATIENCE).map_err(|error| match error {
        mpsc::RecvTimeoutError::Timeout => format!("50 steps took more than {PATIENCE:?}:\n{text}"),
        mpsc::RecvTimeoutError::Disconnected => format!("the simulation panicked:\n{text}"),
    })
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 400,
        max_global_rejects: 1_000_000,
        ..ProptestConfig::default()
    })]

    #[test]
    fn extreme_numbers_are_refused_or_run_in_bounded_time(
        scene in 0usize..14,
        changes in prop::collection::vec((0usize..5, 0usize..8, 0usize..16, extreme()), 1..=3),
    ) {
        let scenes = scenes();
        let mut scene = scenes[scene % scenes.len()].clone();
        let mut changed = false;
        for (section, object, slot, value) in changes {
            changed |= match section {
                0 => set_number(fields::WORLD, &mut scene.world, slot, value),
                1 => set_number(fields::SIMULATION, &mut scene.simulation, slot, value),
                2 => {
                    let n = scene.particles.len();
                    n > 0 && set_number(fields::PARTICLE, &mut scene.particles[object % n], slot, value)
                }
                3 => {
                    let n = scene.springs.len();
                    n > 0 && set_number(fields::SPRING, &mut scene.springs[object % n], slot, value)
                }
                _ => {
                    let n = scene.ramps.len();
                    n > 0 && set_number(fields::RAMP, &mut scene.ramps[object % n], slot, value)
                }
            };
        }
        prop_assume!(changed);
        // Refused with reasons, or run: never a panic, never a hang.
        if scene.validate().is_empty()
            && let Err(failure) = run_bounded(scene)
        {
            prop_assert!(false, "{}", failure);
        }
    }
}

/// The cases the random search started from, kept by name: a mass too small to compute
/// with is refused, with its position and reason; a velocity of 1e100 m/s (the largest
/// allowed) runs without a panic in the broad phase (whose grid size once overflowed); a
/// dopri5 step of 1e100 s on an orbit stops with a message instead of taking forever.
#[test]
fn the_cases_that_once_failed() {
    let collision = || example_scene("collision");
    let text = collision()
        .to_toml()
        .replacen("mass = 1.0", "mass = 1e-300", 1);
    let error = Scene::from_toml(&text).expect_err("refused");
    assert!(
        error.problems[0]
            .message
            .contains("mass 1e-300 is too small to simulate reliably"),
        "{error}"
    );
    assert!(error.problems[0].line.is_some(), "with its position");

    let mut fast = collision();
    fast.particles[0].velocity = Vector::cartesian(1e100, 0.0);
    assert!(fast.validate().is_empty());
    run_bounded(fast).expect("runs");

    let mut orbit = example_scene("orbit");
    orbit.simulation.time_step = 1e100;
    let mut simulation = Simulation::new(&orbit).unwrap();
    let error = simulation.step().expect_err("stops");
    assert!(
        matches!(error, physics::SimulationError::TooManySteps { .. }),
        "{error}"
    );
}
