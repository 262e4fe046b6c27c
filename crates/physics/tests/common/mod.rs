//! What the physics crate's tests share: scenes by name, runs, and the closed forms that
//! more than one test file reads (each written here apart from the simulation's code).

// Each test file is a crate of its own that uses some of these.
#![allow(
    dead_code,
    reason = "each test binary uses a part of the shared fixtures"
)]

use physics::{Scene, Simulation};

/// The built-in example `name`, as a scene.
pub fn example_scene(name: &str) -> Scene {
    physics::example(name)
        .unwrap_or_else(|| panic!("no example {name}"))
        .scene()
        .unwrap_or_else(|e| panic!("example {name} does not load: {e}"))
}

/// A simulation of `scene` at its start.
pub fn start(scene: &Scene) -> Simulation {
    Simulation::new(scene).expect("a valid scene")
}

/// Steps `simulation` on to `t`.
pub fn run_to(simulation: &mut Simulation, t: f64) {
    simulation.step_to(t).expect("the run stays finite");
}

/// A simulation of `scene` run from its start to `t`.
pub fn simulation_at(scene: &Scene, t: f64) -> Simulation {
    let mut simulation = start(scene);
    run_to(&mut simulation, t);
    simulation
}

/// |actual − expected| / |expected|.
pub fn relative(actual: f64, expected: f64) -> f64 {
    (actual - expected).abs() / expected.abs()
}

/// The complete elliptic integral of the first kind K(k), by the arithmetic–geometric
/// mean (quadratic convergence: 20 rounds are far past f64's digits).
pub fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..20 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

/// ∫ₐᵇ f by Simpson's rule on `n` (even) intervals.
pub fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let h = (b - a) / n as f64;
    let inner: f64 = (1..n)
        .map(|i| f(a + h * i as f64) * if i % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}
