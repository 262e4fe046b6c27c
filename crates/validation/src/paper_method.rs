//! The paper's own numbers explained: its tables 4.2 and its spring 4.6 re-run with the
//! method it used — explicit Euler (position moved with the old velocity) at a fixed step —
//! beside the closed form of that method and the exact theory.
//!
//! Inferred from the printed digits, not from the text (the paper names no method):
//! - 4.2: explicit Euler at h = 0.1 s. For constant acceleration it gives exactly
//!   x₀ + v₀t + a·t(t − h)/2, off by a·t·h/2, so its relative error falls as t grows,
//!   as the paper's Cartesian column does (0.400 % → 0.345 %).
//! - 4.6: explicit Euler at h = 1/60 s (a frame). On the oscillator u'' = −ω²u it maps
//!   z = u + i·u'/ω to (1 − iωh)·z each step, so uₙ = u₀ (1 + ω²h²)^(n/2) cos(n·atan ωh):
//!   the energy grows by the factor 1 + (ωh)² per step, and the peak of 15.000 m becomes
//!   15.850 m within 20 s.
//! - 4.7 (decaying bounces): the heights depend on how the paper's program detected
//!   contact, which it does not describe; no method reproduces them without fitting, so
//!   none is claimed.
//!
//! Each row is two checks: NewtonLab's `euler` against the method's closed form (to the
//! tolerance, like every check), and the paper's printed value against NewtonLab's
//! `euler` (to the paper's rounding, ±0.002 where it prints three decimals).

use physics::{Integrator, Scene};

use crate::experiments::{Outcome, load, start, step_to};
use crate::figures::{Figure, Panel};
use crate::report::{Report, Table, error, value};
use crate::theory;

/// The paper's printed rounding: three decimals, with a unit in the last place to spare
/// for its frame timer.
const PRINTED: f64 = 0.002;
/// The Cartesian 4.2 rows from t = 5.5 s on differ from explicit Euler at 0.1 s by more
/// than the rounding, by 0.0020–0.0035 m, growing in proportion to t: a term a·t·h/2 with
/// h = 0.0994 s instead of 0.1 s fits all ten rows to ±0.0005. The paper's program ran on
/// a real-time timer, whose ticks were evidently not exactly the 0.1 s its physics used;
/// rather than fit that, those rows are held to this wider bound and the table says so.
const TIMER_DRIFT: f64 = 0.004;

/// The paper's 4.2 step, seconds.
const KINEMATICS_STEP: f64 = 0.1;
/// The paper's 4.6 step, seconds: one frame at 60 Hz; its 20 s are 1,200 of them.
const SPRING_STEP: f64 = 1.0 / 60.0;
const SPRING_STEPS: u32 = 1200;

/// The paper's 4.2 values: (t, x or |r| as printed).
const CARTESIAN: [(f64, f64); 10] = [
    (1.4, 21.961),
    (2.2, 30.957),
    (3.4, 45.755),
    (4.5, 60.695),
    (5.5, 75.418),
    (6.2, 86.371),
    (7.2, 102.942),
    (8.1, 118.785),
    (9.3, 141.279),
    (10.2, 159.176),
];
const POLAR: [(f64, f64); 10] = [
    (1.0, 34.629),
    (2.2, 35.990),
    (3.3, 36.292),
    (4.1, 36.166),
    (5.1, 36.148),
    (6.4, 37.879),
    (7.2, 40.893),
    (8.4, 49.215),
    (9.0, 55.186),
    (10.2, 70.570),
];
/// The paper's 4.6 largest position of the undamped spring within 20 s, metres.
const SPRING_PEAK: f64 = 15.850;

fn with_euler(mut scene: Scene, time_step: f64) -> Scene {
    scene.simulation.integrator = Integrator::Euler;
    scene.simulation.time_step = time_step;
    scene
}

/// 4.2 and 4.6 with the paper's method and step.
pub(crate) fn paper_method(report: &mut Report, figures: &mut Vec<Figure>) -> Outcome {
    let mut rows = Vec::new();
    for (name, label, times, polar) in [
        ("kinematics-cartesian", "4.2 Cartesian x", CARTESIAN, false),
        ("kinematics-polar", "4.2 polar |r|", POLAR, true),
    ] {
        let scene = with_euler(load(name)?, KINEMATICS_STEP);
        let particle = &scene.particles[0];
        let field = scene.world.gravity.to_dvec2() + particle.acceleration.to_dvec2();
        let (x0, v0) = (particle.position.to_dvec2(), particle.velocity.to_dvec2());
        let mut simulation = start(&scene)?;
        for (t, paper) in times {
            step_to(&mut simulation, t)?;
            let euler =
                theory::explicit_euler_constant_acceleration(x0, v0, field, t, KINEMATICS_STEP);
            let exact = theory::constant_acceleration(x0, v0, field, t);
            let measure = |r: physics::DVec2| if polar { r.length() } else { r.x };
            let (simulated, euler, exact) = (
                measure(simulation.positions()[0]),
                measure(euler),
                measure(exact),
            );
            let e = report.check(
                format!("{label} at t = {t}: euler against its closed form"),
                simulated,
                euler,
                exact.abs(),
            );
            let drifts = !polar && t > 5.0;
            let printed = report.check_printed(
                format!("{label} at t = {t}: the paper's value against euler"),
                paper,
                simulated,
                if drifts { TIMER_DRIFT } else { PRINTED },
            );
            rows.push(vec![
                label.to_owned(),
                format!("{t}"),
                format!("{paper:.3}"),
                value(simulated),
                error(e),
                value(exact),
                format!("{printed:+.4}"),
                if drifts {
                    "timer drift, ±0.004"
                } else {
                    "±0.002"
                }
                .to_owned(),
            ]);
        }
    }
    spring(report, figures, &mut rows)?;
    report.tables.push(Table {
        section: "4.2, 4.6",
        title: "The paper's numbers, explained: its experiments re-run with its own method, explicit Euler at a fixed step".to_owned(),
        theory: "explicit Euler (x moved with the old v) at h = 0.1 s gives x₀ + v₀t + a·t(t − h)/2 for constant acceleration, off by a·t·h/2; \
                 on the spring (ω = 1) at h = 1/60 s it gives uₙ = 5 (1 + ω²h²)^(n/2) cos(n·atan ωh): energy × (1 + (ωh)²) per step. \
                 'euler error' is NewtonLab's euler against that closed form; 'paper − euler' must lie within ±0.002, the paper's rounding, \
                 except the Cartesian rows after 5 s, which drift in proportion to t (a step of 0.0994 s instead of 0.1 s fits every row to ±0.0005: the paper's real-time timer) and are held to ±0.004. \
                 The 4.7 bounce heights depend on an unstated contact rule and are not re-created",
        header: vec![
            "experiment",
            "t (s)",
            "paper",
            "NewtonLab euler (paper's step)",
            "euler error",
            "exact theory",
            "paper − euler",
            "within",
        ],
        rows,
    });
    Ok(())
}

/// 4.6: the undamped spring's largest position within 20 s, with explicit Euler at a
/// frame's step, and the figure of its growth beside NewtonLab's default `rk4`.
fn spring(report: &mut Report, figures: &mut Vec<Figure>, rows: &mut Vec<Vec<String>>) -> Outcome {
    let exact_scene = load("spring-undamped")?;
    let (particle, link) = (&exact_scene.particles[0], &exact_scene.springs[0]);
    let equilibrium = link.natural_length;
    let start_offset = particle.position.to_dvec2().x - equilibrium;
    let omega = (link.stiffness / particle.mass).sqrt();
    let scene = with_euler(exact_scene.clone(), SPRING_STEP);
    let mut simulation = start(&scene)?;
    let mut exact = start(&exact_scene)?;
    let (mut paper_method, mut default_method) = (
        Panel::new("explicit Euler, h = 1/60 s (the paper's): x (m)"),
        Panel::new("rk4, h = 1 ms (NewtonLab's default): x (m)"),
    );
    let (mut peak, mut peak_theory, mut worst) = (f64::NEG_INFINITY, f64::NEG_INFINITY, 0.0_f64);
    for n in 0..=SPRING_STEPS {
        if n > 0 {
            simulation
                .step()
                .map_err(|e| crate::Failure::Simulation(e.to_string()))?;
        }
        let t = simulation.time();
        let x = simulation.positions()[0].x;
        let closed_form =
            equilibrium + theory::explicit_euler_oscillator(start_offset, omega, SPRING_STEP, n);
        worst = worst.max((x - closed_form).abs());
        peak = peak.max(x);
        peak_theory = peak_theory.max(closed_form);
        let cosine = equilibrium + start_offset * (omega * t).cos();
        paper_method.add(t, x, cosine);
        step_to(&mut exact, t)?;
        default_method.add(t, exact.positions()[0].x, cosine);
    }
    let e = report.check(
        "4.6 undamped spring: euler at 1/60 s against its closed form over 20 s",
        worst,
        0.0,
        start_offset.abs(),
    );
    let printed = report.check_printed(
        "4.6 undamped spring: the paper's peak against euler's",
        SPRING_PEAK,
        peak,
        PRINTED,
    );
    let e_peak = report.check(
        "4.6 undamped spring: euler's peak against its closed form",
        peak,
        peak_theory,
        start_offset.abs(),
    );
    rows.push(vec![
        "4.6 spring, largest x".to_owned(),
        "0–20".to_owned(),
        format!("{SPRING_PEAK:.3}"),
        value(peak),
        error(e.max(e_peak)),
        value(equilibrium + start_offset.abs()),
        format!("{printed:+.4}"),
        "±0.002".to_owned(),
    ]);
    figures.push(Figure {
        file: "paper-method-spring.png".to_owned(),
        title: "The paper's spring (4.6): its method gains energy every step; NewtonLab's default does not".to_owned(),
        panels: [paper_method, default_method],
    });
    Ok(())
}
