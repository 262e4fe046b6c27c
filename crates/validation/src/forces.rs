//! Forces from what a student knows, against closed forms: air resistance from a drag
//! coefficient, the cyclotron orbit of the magnetic field, and forces of one's own — a
//! force that varies in time under every method, an anharmonic oscillator's quarter
//! period against its quadrature and its books.

use physics::{Force, Integrator, Particle, Scene, World};

use crate::Failure;
use crate::experiments::{Outcome, start, step_to};
use crate::report::{Checks, Report};

const G: f64 = 9.81;

fn one(particle: Particle, world: World, method: Integrator) -> Scene {
    Scene::new()
        .with_world(world)
        .with_integrator(method, 1e-3)
        .with_particle(particle)
}

/// Each to the tolerance beside it, relative to the quantity's scale:
/// - a ball of radius 0.11 m, 0.6 kg, `C_d` 0.47 in air of 1.2 kg/m³ dropped from rest (rk4,
///   1 ms): v = −vₜ tanh(g t/vₜ) with vₜ = √(m g/c), c = ½ ρ `C_d` π r², to 1e-8 (rk4's own
///   error is some 1e-13; a wrong area, r² for π r², is 3 % off);
/// - an ion of 2 kg and 0.5 C at 3 m/s in B = 1.5 T (rk4, 1 ms): the circle of radius
///   m v/(q B) = 8 m about its centre, clockwise at ω = q B/m, at 1 and 5 s, to 1e-9
///   (rk4's error over 5 s: 1e-12; the opposite sense or a lost factor is of order one);
/// - a free 2 kg particle pushed by `0.5*cos(3*t)` N under each method: x = (F₀/(m ω²))
///   (1 − cos ωt) at 2.5 s, to 1e-9 under rk4, pefrl and dopri5 and 1e-6 under Verlet
///   (second order: (ωh)² ≈ 1e-5 of the swing); a stage evaluated at the step's start
///   instead of its own instant is 1e-3 off;
/// - `-2*x - 0.5*x^3` on 1 kg from x = 1.5 m at rest (rk4, 1 ms): x = 0 at a quarter
///   period, T/4 = ∫₀^{π/2} dθ/√((2/m)(1 + A² (1 + sin² θ)/8)) (x = A sin θ in the energy
///   integral), by Simpson's rule over 2,000 panels here, to 1e-9 of A; and the books
///   with its potential x² + x⁴/8 closing to 1e-9 of the energy.
pub(crate) fn forces(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("forces");
    drag_and_field(&mut checks, report)?;
    own_forces(&mut checks, report)?;
    report.tables.push(checks.table(
        "Forces: drag from C_d, the magnetic field, forces of one's own",
        "C_d: v = −vₜ tanh(gt/vₜ), vₜ = √(mg/c), c = ½ ρ C_d π r²; cyclotron: r = m v/(qB), clockwise at ω = qB/m; F₀ cos ωt: x = F₀(1 − cos ωt)/(m ω²); anharmonic: T/4 by quadrature of the energy integral; errors relative to each scale",
    ));
    Ok(())
}

/// Drag from a coefficient and the cyclotron.
fn drag_and_field(checks: &mut Checks, report: &mut Report) -> Outcome {
    let mut row = |report: &mut Report, what: String, simulated, theory, scale, limit| {
        checks.check(report, what, (simulated, theory, scale), limit);
    };
    // Air resistance from C_d.
    let (m, r, cd, rho) = (0.6, 0.11, 0.47, 1.2);
    let c = 0.5 * rho * cd * std::f64::consts::PI * r * r;
    let terminal = (m * G / c).sqrt();
    let mut ball = Particle::new("Ball", m).radius(r).position([0.0, 500.0]);
    ball.drag_coefficient = cd;
    let mut simulation = start(&one(ball, World::gravity_only(), Integrator::Rk4))?;
    for t in [1.0, 4.0] {
        step_to(&mut simulation, t)?;
        let v = -terminal * (G * t / terminal).tanh();
        row(
            report,
            format!("C_d 0.47, ρ 1.2: v at {t} s (m/s)"),
            simulation.velocities()[0].y,
            v,
            v.abs(),
            1e-8,
        );
    }
    // The cyclotron.
    let (m, q, b, v) = (2.0, 0.5, 1.5, 3.0);
    let (radius, omega) = (m * v / (q * b), q * b / m);
    let world = World {
        magnetic_field: b,
        ..World::no_forces()
    };
    let ion = Particle::new("Ion", m)
        .radius(0.1)
        .charge(q)
        .position([0.0, radius])
        .velocity([v, 0.0]);
    let mut simulation = start(&one(ion, world, Integrator::Rk4))?;
    for t in [1.0, 5.0] {
        step_to(&mut simulation, t)?;
        let p = simulation.positions()[0];
        let (x, y) = (radius * (omega * t).sin(), radius * (omega * t).cos());
        row(
            report,
            format!("cyclotron, x at {t} s (m)"),
            p.x,
            x,
            radius,
            1e-9,
        );
        row(
            report,
            format!("cyclotron, y at {t} s (m)"),
            p.y,
            y,
            radius,
            1e-9,
        );
    }
    Ok(())
}

/// Forces of one's own: in time under each method, and the anharmonic oscillator.
fn own_forces(checks: &mut Checks, report: &mut Report) -> Outcome {
    let mut row = |report: &mut Report, what: String, simulated, theory, scale, limit| {
        checks.check(report, what, (simulated, theory, scale), limit);
    };
    // A force that varies in time, under each method.
    let (m, f0, w, t) = (2.0, 0.5, 3.0, 2.5);
    let swing = f0 / (m * w * w);
    for (method, limit) in [
        (Integrator::Rk4, 1e-9),
        (Integrator::Pefrl, 1e-9),
        (Integrator::Dopri5, 1e-9),
        (Integrator::Verlet, 1e-6),
    ] {
        let pushed = one(
            Particle::new("P", m).radius(0.1),
            World::no_forces(),
            method,
        )
        .with_force(Force::new("push", "0.5*cos(3*t)", "0"));
        let mut simulation = start(&pushed)?;
        step_to(&mut simulation, t)?;
        let x = swing * (1.0 - (w * t).cos());
        row(
            report,
            format!("0.5 cos 3t N on 2 kg, {method}: x at {t} s (m)"),
            simulation.positions()[0].x,
            x,
            2.0 * swing,
            limit,
        );
    }
    // The anharmonic oscillator.
    let (m, a) = (1.0, 1.5);
    let quarter = simpson(
        |theta: f64| 1.0 / ((2.0 / m) * (1.0 + a * a * (1.0 + theta.sin().powi(2)) / 8.0)).sqrt(),
        std::f64::consts::FRAC_PI_2,
        2000,
    );
    let spring = one(
        Particle::new("Bob", m).radius(0.1).position([a, 0.0]),
        World::no_forces(),
        Integrator::Rk4,
    )
    .with_force(Force::new("anharmonic", "-2*x - 0.5*x^3", "0").potential("x^2 + 0.125*x^4"));
    let mut simulation = start(&spring)?;
    simulation.keep_ledger();
    let energy = simulation.diagnostics().energy.total();
    step_to(&mut simulation, quarter)?;
    row(
        report,
        format!("anharmonic from {a} m: x at T/4 = {quarter:.6} s (m)"),
        simulation.positions()[0].x,
        0.0,
        a,
        1e-9,
    );
    step_to(&mut simulation, 10.0)?;
    let ledger = simulation
        .ledger()
        .ok_or_else(|| Failure::Simulation("no ledger".to_owned()))?;
    let residual = simulation.diagnostics().energy.total() + ledger.total() - energy;
    row(
        report,
        "anharmonic: books' residual at 10 s (J)".to_owned(),
        residual,
        0.0,
        energy,
        1e-9,
    );
    Ok(())
}

/// ∫₀^`end` f by Simpson's rule over `panels` (even) panels.
fn simpson(f: impl Fn(f64) -> f64, end: f64, panels: usize) -> f64 {
    let h = end / panels as f64;
    let inner: f64 = (1..panels)
        .map(|k| f(k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(0.0) + inner + f(end)) * h / 3.0
}
