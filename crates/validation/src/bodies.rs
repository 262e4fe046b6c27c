//! Rigid bodies against theory: mass properties from their outlines against the
//! textbook's formulas, and free flight (the centroid's parabola, the steady turn, the
//! energy) under the methods, with the events located on a body's angle.

use std::f64::consts::PI;

use physics::{Body, DVec2, Integrator, Located, Scene, World};

use crate::events::instants;
use crate::experiments::{Outcome, start, step_to};
use crate::report::{Checks, Report};

const G: f64 = 9.81;

/// A 1.5 kg board 0.6 × 0.1 m thrown from (0, 1) m at (3, 4) m/s, turned 10° and
/// spinning at 6 rad/s.
fn thrown_board(integrator: Integrator, h: f64) -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(integrator, h)
        .with_body(
            Body::rectangle("board", 0.6, 0.1, 1.5)
                .position([0.0, 1.0])
                .angle(10.0)
                .moving([3.0, 4.0], 6.0),
        )
}

/// Mass properties (each to 1e-13 relative: the shoelace sums' rounding is some 1e-16
/// per term): a 2 kg box 0.4 × 0.2 m, I = m (w² + h²)/12; a right triangle with legs 3
/// and 4 m placed 1e3 m from the origin, I = m (a² + b²)/18 about its centroid (a/3, b/3)
/// from the right angle; a regular hexagon of side s, I = 5 m s²/12; a triangle's mass
/// from a density, ρ a b / 2. Free flight of a thrown, spinning board: its centroid on
/// x₀ + v₀ t + g t²/2 and its angle θ₀ + ω t at 1.2 s, to 1e-12 relative, under rk4,
/// verlet, pefrl and dopri5 (exact for a constant acceleration) and under euler on its own
/// closed form x₀ + n h v₀ + g h² n (n − 1)/2 (the method's sum, to show a body follows
/// the scene's method as a particle does); its total energy, translational, rotational
/// and potential, constant to 1e-12 of itself; the instant its angle crosses 45°,
/// (45° − θ₀)/ω, to 1e-9 s.
pub(crate) fn bodies(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("bodies");
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, limit| {
        checks.check(
            report,
            what.to_owned(),
            (simulated, theory, theory.abs()),
            limit,
        );
    };
    let rectangle = Body::rectangle("b", 0.4, 0.2, 2.0);
    row(
        report,
        "box 0.4 × 0.2 m, 2 kg: I (kg·m²)",
        rectangle.inertia(),
        2.0 * (0.16 + 0.04) / 12.0,
        1e-13,
    );
    let far = DVec2::new(1e3, -1e3);
    let legs = [DVec2::ZERO, DVec2::new(3.0, 0.0), DVec2::new(0.0, 4.0)];
    let triangle = Body::polygon("t", legs.iter().map(|&v| v + far).collect(), 6.0);
    row(
        report,
        "right triangle 3-4-5 m, 6 kg, 1 km away: I (kg·m²)",
        triangle.inertia(),
        6.0 * (9.0 + 16.0) / 18.0,
        1e-10,
    );
    let side = 0.25;
    let hexagon: Vec<DVec2> = (0..6)
        .map(|k| DVec2::from_angle(f64::from(k) * PI / 3.0) * side)
        .collect();
    row(
        report,
        "regular hexagon, side 0.25 m, 3 kg: I (kg·m²)",
        Body::polygon("h", hexagon, 3.0).inertia(),
        5.0 * 3.0 * side * side / 12.0,
        1e-13,
    );
    let mut dense = Body::polygon("d", legs.to_vec(), 0.0);
    dense.density = 2.5;
    row(
        report,
        "triangle 3-4-5 m at 2.5 kg/m²: mass (kg)",
        dense.total_mass(),
        2.5 * 3.0 * 4.0 / 2.0,
        1e-15,
    );
    report.tables.push(checks.table(
        "Rigid bodies: mass properties",
        "I of a box m(w² + h²)/12, a right triangle m(a² + b²)/18, a regular hexagon 5ms²/12; the mass of a density ρ a b/2; errors relative",
    ));
    free_flight(report)
}

/// The thrown board's flight, as [`bodies`] says.
fn free_flight(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("bodies");
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, limit| {
        checks.check(
            report,
            what.to_owned(),
            (simulated, theory, theory.abs()),
            limit,
        );
    };
    let (t, h) = (1.2, 1e-3);
    let (x0, v0): (DVec2, DVec2) = (DVec2::new(0.0, 1.0), DVec2::new(3.0, 4.0));
    let (theta0, spin): (f64, f64) = (10.0, 6.0);
    let g = DVec2::new(0.0, -G);
    let angle = theta0 + (spin * t).to_degrees();
    for integrator in [
        Integrator::Rk4,
        Integrator::Verlet,
        Integrator::Pefrl,
        Integrator::Dopri5,
    ] {
        let mut simulation = start(&thrown_board(integrator, h))?;
        step_to(&mut simulation, t)?;
        let board = simulation.body(0);
        let x = x0 + v0 * t + 0.5 * g * t * t;
        row(
            report,
            &format!("thrown board, {integrator}: y at {t} s (m)"),
            board.position.y,
            x.y,
            1e-12,
        );
        row(
            report,
            &format!("thrown board, {integrator}: angle at {t} s (°)"),
            board.angle,
            angle,
            1e-12,
        );
    }
    let mut simulation = start(&thrown_board(Integrator::Euler, h))?;
    step_to(&mut simulation, t)?;
    let n = (t / h).round();
    let euler = x0 + v0 * (n * h) + g * (h * h * n * (n - 1.0) / 2.0);
    row(
        report,
        &format!("thrown board, euler: y at {t} s (m)"),
        simulation.body(0).position.y,
        euler.y,
        1e-12,
    );
    let mut simulation = start(&thrown_board(Integrator::Rk4, h))?;
    let energy = simulation.diagnostics().energy.total();
    step_to(&mut simulation, t)?;
    row(
        report,
        "thrown board, rk4: total energy at 1.2 s (J)",
        simulation.diagnostics().energy.total(),
        energy,
        1e-12,
    );
    let crossing = (45.0 - theta0).to_radians() / spin;
    let found = instants(
        &thrown_board(Integrator::Rk4, h),
        "board.angle crosses 45",
        1.0,
    )?;
    let at = found.first().map_or(f64::NAN, Located::time);
    checks.check(
        report,
        "thrown board: board.angle crosses 45 (s)".to_owned(),
        (at, crossing, 1.0),
        1e-9,
    );
    report.tables.push(checks.table(
        "Rigid bodies: free flight",
        "x₀ + v₀t + gt²/2 and θ₀ + ωt (euler: its own sum, x₀ + nhv₀ + gh²n(n − 1)/2); the total energy constant; errors relative (the instant's in seconds)",
    ));
    Ok(())
}
