//! Air resistance against its closed forms: a projectile under linear drag, a fall from
//! rest under quadratic drag, and the energy it takes in the ledger.

use physics::{Integrator, Particle, Scene, World};

use crate::Failure;
use crate::experiments::{Outcome, start, step_to};
use crate::report::{Checks, Report};

const G: f64 = 9.81;

fn ball(mass: f64, (b, c): (f64, f64), velocity: [f64; 2]) -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_particle(
            Particle::new("Ball", mass)
                .radius(0.1)
                .position([0.0, 100.0])
                .velocity(velocity)
                .drag(b, c),
        )
}

/// rk4 at 1 ms against the closed forms, each to 1e-8 relative (rk4's error here is
/// some 1e-13): a 2.5 kg ball thrown at (12, 9) m/s with b = 0.8 kg/s at 1 and 3 s,
/// x = (m v₀ₓ/b)(1 − e^(−bt/m)) and y = y₀ + (m/b)(v₀ᵧ + m g/b)(1 − e^(−bt/m)) − m g t/b;
/// a 0.7 kg ball dropped with c = 0.02 kg/m at 1 and 4 s, v = −vₜ tanh(g t/vₜ) and
/// y = y₀ − (vₜ²/g) ln cosh(g t/vₜ) with vₜ = √(m g/c); what drag took,
/// m g (y₀ − y) − ½ m v², and the books' residual, to 1e-9 of the energy at the start.
pub(crate) fn drag(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("drag");
    let mut row = |report: &mut Report, what: String, simulated, theory, scale, limit| {
        checks.check(report, what, (simulated, theory, scale), limit);
    };
    let (m, b, v0) = (2.5, 0.8, [12.0, 9.0]);
    let mut simulation = start(&ball(m, (b, 0.0), v0))?;
    for t in [1.0, 3.0] {
        step_to(&mut simulation, t)?;
        let decay = 1.0 - (-b * t / m).exp();
        let x = m * v0[0] / b * decay;
        let y = 100.0 + m / b * (v0[1] + m * G / b) * decay - m * G / b * t;
        let p = simulation.positions()[0];
        row(
            report,
            format!("linear, x at {t} s (m)"),
            p.x,
            x,
            x.abs(),
            1e-8,
        );
        row(
            report,
            format!("linear, y at {t} s (m)"),
            p.y,
            y,
            y.abs(),
            1e-8,
        );
    }
    let (m, c) = (0.7, 0.02);
    let terminal = (m * G / c).sqrt();
    let mut simulation = start(&ball(m, (0.0, c), [0.0, 0.0]))?;
    simulation.keep_ledger();
    let start_energy = simulation.diagnostics().energy.total();
    for t in [1.0, 4.0] {
        step_to(&mut simulation, t)?;
        let v = -terminal * (G * t / terminal).tanh();
        let y = 100.0 - terminal * terminal / G * (G * t / terminal).cosh().ln();
        let (p, u) = (simulation.positions()[0], simulation.velocities()[0]);
        row(
            report,
            format!("quadratic, v at {t} s (m/s)"),
            u.y,
            v,
            v.abs(),
            1e-8,
        );
        row(
            report,
            format!("quadratic, y at {t} s (m)"),
            p.y,
            y,
            y.abs(),
            1e-8,
        );
        let ledger = simulation
            .ledger()
            .ok_or_else(|| Failure::Simulation("no ledger".to_owned()))?;
        let taken = m * G * (100.0 - y) - 0.5 * m * v * v;
        row(
            report,
            format!("quadratic, drag took by {t} s (J)"),
            ledger.drag,
            taken,
            start_energy,
            1e-9,
        );
        let residual = simulation.diagnostics().energy.total() + ledger.total() - start_energy;
        row(
            report,
            format!("quadratic, books' residual at {t} s (J)"),
            residual,
            0.0,
            start_energy,
            1e-9,
        );
    }
    report.tables.push(checks.table(
        "Air resistance: linear and quadratic drag",
        "linear: x = (m v₀ₓ/b)(1 − e^(−bt/m)), y = y₀ + (m/b)(v₀ᵧ + mg/b)(1 − e^(−bt/m)) − mgt/b; quadratic from rest: v = −vₜ tanh(gt/vₜ), y = y₀ − (vₜ²/g) ln cosh(gt/vₜ), vₜ = √(mg/c); errors relative (the books' to the energy at the start)",
    ));
    Ok(())
}
