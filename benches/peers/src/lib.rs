//! What the peer comparisons share: NewtonLab's side of the ball pit, timed, and the
//! median of the runs.

use std::time::Instant;

use physics::{Scene, Simulation};

/// Every engine's time step, seconds.
pub const TIME_STEP: f64 = 1e-3;

/// Steps per second of NewtonLab over `seconds` of simulated time, on `threads` threads.
pub fn newtonlab(scene: &Scene, seconds: f64, threads: usize) -> f64 {
    let mut simulation = Simulation::new(scene).expect("the generated pit is valid");
    simulation.set_threads(threads);
    let steps = (seconds / TIME_STEP).round() as u64;
    let start = Instant::now();
    for _ in 0..steps {
        simulation.step().expect("the pit runs");
    }
    steps as f64 / start.elapsed().as_secs_f64()
}

/// The middle value (the upper of the two middle ones for an even count).
pub fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}
