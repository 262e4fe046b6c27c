//! The paper's springs (4.6) against the damped harmonic oscillator.
//!
//! m ü = −k u − b u̇ with u = x − L0, u(0) = 5, u̇(0) = 0, m = k = 1:
//! u(t) = 5 e^(−γt) (cos ωt + (γ/ω) sin ωt), γ = b/2, ω = √(1 − γ²).

use physics::{Integrator, Simulation, example};

fn analytic(b: f64, t: f64) -> f64 {
    let gamma = b / 2.0;
    let omega = (1.0 - gamma * gamma).sqrt();
    10.0 + 5.0 * (-gamma * t).exp() * ((omega * t).cos() + gamma / omega * (omega * t).sin())
}

/// The largest |x − theory| over 20 s, sampled every 0.01 s.
fn worst_error(example_name: &str, b: f64) -> f64 {
    let scene = example(example_name)
        .expect("the example exists")
        .scene()
        .expect("the example scene loads and runs");
    assert_eq!(
        scene.simulation.integrator,
        Integrator::Rk4,
        "the examples use rk4"
    );
    assert!(
        (scene.simulation.time_step - 1e-3).abs() < 1e-18,
        "at dt = 1e-3"
    );
    let mut simulation = Simulation::new(&scene).expect("the example scene loads and runs");
    (0..=2000)
        .map(|k| {
            let t = f64::from(k) * 0.01;
            simulation
                .step_to(t)
                .expect("the example scene loads and runs");
            (simulation.positions()[0].x - analytic(b, t)).abs()
        })
        .fold(0.0, f64::max)
}

/// RK4's global error is about T·h⁴·ω⁵·A/120 ≈ 1e-12 here; 1e-9 leaves room for rounding
/// while failing any lower-order method (Verlet would be off by 1e-6).
#[test]
fn undamped_spring_follows_the_cosine_within_1e_9() {
    let error = worst_error("spring-undamped", 0.0);
    assert!(error < 1e-9, "largest error {error}");
}

/// Peaks of the undamped spring are at t = 2πk; the paper's Euler reached 15.850.
#[test]
fn undamped_spring_peaks_stay_at_15() {
    let scene = example("spring-undamped").unwrap().scene().unwrap();
    let mut simulation = Simulation::new(&scene).unwrap();
    for k in 1..=3 {
        let t = 2.0 * std::f64::consts::PI * f64::from(k);
        simulation.step_to(t).unwrap();
        let x = simulation.positions()[0].x;
        assert!((x - 15.0).abs() < 1e-9, "peak {k} at t = {t}: {x}");
    }
}

#[test]
fn damped_springs_follow_the_damped_oscillator_within_1e_8() {
    for (name, b) in [("spring-damped-light", 0.25), ("spring-damped-heavy", 0.5)] {
        let error = worst_error(name, b);
        assert!(error < 1e-8, "{name}: largest error {error}");
    }
}

/// The paper's defect, reproduced on purpose: explicit Euler multiplies an undamped
/// oscillator's energy by 1 + (ωh)² each step, so after 20 s at h = 1e-3 the energy has
/// grown by the factor (1 + 1e-6)^20000 ≈ e^0.02 ≈ 1.0202, within 1e-4.
#[test]
fn explicit_euler_makes_the_undamped_spring_gain_energy() {
    let mut scene = example("spring-undamped").unwrap().scene().unwrap();
    scene.simulation.integrator = Integrator::Euler;
    let mut simulation = Simulation::new(&scene).unwrap();
    let start = simulation.diagnostics().energy.total();
    simulation.step_to(20.0).unwrap();
    let ratio = simulation.diagnostics().energy.total() / start;
    let theory = (1.0 + 1e-6_f64).powi(20_000);
    assert!(ratio > 1.01, "energy grew by {ratio}");
    assert!(
        (ratio - theory).abs() < 1e-4,
        "growth {ratio} vs theory {theory}"
    );
}
