//! Rigid bodies against theory: mass properties from their outlines against the
//! textbook's formulas, free flight (the centroid's parabola, the steady turn, the
//! energy) under the methods with the events located on a body's angle, and contacts with
//! the walls and ramps (holding, sliding, tipping, landing, striking, bouncing).

use std::f64::consts::PI;

use physics::{Body, Bounds, DVec2, Integrator, Located, Ramp, Scene, Vector, World};

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
    free_flight(report)?;
    contacts(report)
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

/// A ramp at `slope` degrees from the origin, 6 m long, 0.1 m thick, of kinetic and
/// static friction `mu` and `mu_s`,
/// and a box `width` × `height` of 2 kg resting on its upper face 2 m along it, turned to
/// the slope.
fn on_incline(slope: f64, (mu, mu_s): (f64, f64), (width, height): (f64, f64)) -> Scene {
    let ramp = Ramp::new("incline", [0.0, 0.0], [0.0, 0.0]).friction(mu);
    let ramp = Ramp {
        to: ramp.end_for(slope, 6.0),
        static_friction: Some(mu_s),
        ..ramp
    };
    let at = ramp.touching(2.0, height / 2.0);
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_ramp(ramp)
        .with_body(
            Body::rectangle("block", width, height, 2.0)
                .position([at.x, at.y])
                .angle(slope),
        )
}

/// Contacts with the walls and ramps against their closed forms: a block on a 25° incline
/// with μs = 0.5 (tan 25° = 0.47) and μk = 0.3 stays where it was put, to 1e-9 m over
/// 10 s (rounding alone moves it); on a 30° incline with μ = 0.2 it slides
/// g (sin θ − μ cos θ) t²/2 in 1 s, to 1e-9 relative; half a degree either side of
/// arctan μs it holds or slides with μk; a tall
/// box (0.2 × 1 m, μ = 1) stands at 10° and tips at 13°, either side of arctan(w/h) =
/// 11.3°; a box dropped flat on the floor (e = 0) lands on both corners at once and rests
/// without turning, its spin 0 to 1e-12 rad/s; a spinning box striking a wall (e = 1, no
/// friction, no field) keeps its kinetic energy to 1e-12 and its velocity along the wall
/// exactly, and strikes it at (x₀ − w/2 − wall)/v when it does not spin, to 1e-9 s; a
/// board dropped turning onto an elastic floor keeps its total energy through its bounces,
/// to 1e-9 (each impact located and struck by its closed form, the flight between exact).
/// Bodies meeting bodies: two boxes of 2 and 1 kg face to face, e the smaller of 0.5 and
/// 0.8, leave at (m₁v₁ + m₂v₂ ∓ m₂,₁ e (v₁ − v₂))/(m₁ + m₂) to 1e-12 and lie on their new
/// lines at 0.8 s to 1e-9 m (the impact located in time); a square turned 45° strikes a
/// standing board 0.3 m above its centroid and turns it at
/// `ω = −r j/I`, `j = 2u/(1/mₐ + 1/m_b + r²/I)`, to 1e-12; a box dropped on another rests on
/// it, both where statics puts them after 10 s, to 1e-9 m; a block on a fixed wedge
/// slides g (sin θ − μ cos θ) t²/2 with μ the geometric mean of the two bodies' kinetic
/// frictions, to 1e-9 m.
fn contacts(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("bodies");
    inclines(report, &mut checks)?;
    landings(report, &mut checks)?;
    bouncing(report, &mut checks)?;
    meeting(report, &mut checks)?;
    resting_on_bodies(report, &mut checks)?;
    report.tables.push(checks.table(
        "Rigid bodies: resting, sliding, tipping and striking",
        "a block holds while tan θ ≤ μs and slides g(sin θ − μk cos θ)t²/2 beyond; a tall box tips past arctan(w/h); a box dropped flat lands without turning; an elastic wall keeps the kinetic energy and the velocity along it, a bouncing board its total energy; bodies meeting bodies by the law of restitution with the angular impulse, resting on each other, sliding with the two frictions' geometric mean; errors relative to the scale shown (movement in metres)",
    ));
    Ok(())
}

/// The blocks and tall boxes on inclines of [`contacts`].
fn inclines(report: &mut Report, checks: &mut Checks) -> Outcome {
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, scale, limit| {
        checks.check(report, what.to_owned(), (simulated, theory, scale), limit);
    };
    let scene = on_incline(25.0, (0.3, 0.5), (0.4, 0.2));
    let put = scene.bodies[0].position.to_dvec2();
    let mut simulation = start(&scene)?;
    step_to(&mut simulation, 10.0)?;
    row(
        report,
        "block on 25°, μs = 0.5, μk = 0.3: moved in 10 s (m)",
        simulation.body(0).position.distance(put),
        0.0,
        1.0,
        1e-9,
    );
    let (slope, mu, t) = (30.0_f64, 0.2, 1.0);
    let scene = on_incline(slope, (mu, mu), (0.4, 0.2));
    let put = scene.bodies[0].position.to_dvec2();
    let mut simulation = start(&scene)?;
    step_to(&mut simulation, t)?;
    let theta = slope.to_radians();
    let slid = 0.5 * G * (theta.sin() - mu * theta.cos()) * t * t;
    row(
        report,
        "block on 30°, μ = 0.2: slid in 1 s (m)",
        simulation.body(0).position.distance(put),
        slid,
        slid,
        1e-9,
    );
    let threshold = 0.5_f64.atan().to_degrees();
    for (offset, holds) in [(-0.5, true), (0.5, false)] {
        let slope = threshold + offset;
        let scene = on_incline(slope, (0.3, 0.5), (0.4, 0.2));
        let put = scene.bodies[0].position.to_dvec2();
        let mut simulation = start(&scene)?;
        step_to(&mut simulation, 1.0)?;
        let theta = slope.to_radians();
        let expected = if holds {
            0.0
        } else {
            0.5 * G * (theta.sin() - 0.3 * theta.cos())
        };
        row(
            report,
            &format!("block at arctan μs {offset:+}° (μk = 0.3): moved in 1 s (m)"),
            simulation.body(0).position.distance(put),
            expected,
            expected.max(1.0),
            1e-9,
        );
    }
    for (slope, tips) in [(10.0, false), (13.0, true)] {
        let scene = on_incline(slope, (1.0, 1.0), (0.2, 1.0));
        let mut simulation = start(&scene)?;
        step_to(&mut simulation, 1.0)?;
        let turned = (simulation.body(0).angle - slope).abs();
        row(
            report,
            &format!("tall box on {slope}°: tips (1) or stands (0)"),
            if turned > 1.0 {
                1.0
            } else if turned < 1e-9 {
                0.0
            } else {
                0.5
            },
            if tips { 1.0 } else { 0.0 },
            1.0,
            0.0,
        );
    }
    tipping(report, checks)
}

/// A tall box (0.2 × 1 m) tipping over the lower corner of a 13° incline that grips it
/// (μ = 1), against a body turning about a fixed corner: I θ̈ = −m g rₓ(θ), with
/// I = m (w² + h²)/3 about the corner, integrated here apart (rk4, 1e-5 s). At 0.6 s its spin, and its
/// acceleration read from that instant's own angle and spin, α ẑ × r − ω² r. The spin
/// lags the ideal pivot's by some 0.5 %: each step holds the corner with constant
/// accelerations, the corner leaves the surface by some 1e-8 m/s, and the next step's
/// impact stops it, each taking a little of the energy (the impacts' share of the books).
fn tipping(report: &mut Report, checks: &mut Checks) -> Outcome {
    let (m, w, h, slope) = (2.0, 0.2, 1.0, 13.0_f64);
    let scene = on_incline(slope, (1.0, 1.0), (w, h));
    let mut simulation = start(&scene)?;
    let until = 0.6;
    step_to(&mut simulation, until)?;
    let inertia = m * (w * w + h * h) / 3.0;
    let arm = |angle: f64| DVec2::from_angle(angle).rotate(DVec2::new(w / 2.0, h / 2.0));
    let alpha = |angle: f64| -m * G * arm(angle).x / inertia;
    let (mut angle, mut spin, dt) = (slope.to_radians(), 0.0, 1e-5);
    for _ in 0..60_000 {
        let (a1, v1) = (alpha(angle), spin);
        let (a2, v2) = (alpha(angle + 0.5 * dt * v1), spin + 0.5 * dt * a1);
        let (a3, v3) = (alpha(angle + 0.5 * dt * v2), spin + 0.5 * dt * a2);
        let (a4, v4) = (alpha(angle + dt * v3), spin + dt * a3);
        angle += dt * (v1 + 2.0 * v2 + 2.0 * v3 + v4) / 6.0;
        spin += dt * (a1 + 2.0 * a2 + 2.0 * a3 + a4) / 6.0;
    }
    let body = simulation.body(0);
    checks.check(
        report,
        "tall box tipping on 13°: spin at 0.6 s against a fixed pivot's (rad/s)".to_owned(),
        (body.spin, spin, spin),
        1e-2,
    );
    let r = arm(body.angle.to_radians());
    let theory = alpha(body.angle.to_radians()) * r.perp() - body.spin * body.spin * r;
    checks.check(
        report,
        "its acceleration at 0.6 s, read from that instant's angle and spin (m/s²)".to_owned(),
        (body.acceleration.distance(theory), 0.0, theory.length()),
        2e-3,
    );
    Ok(())
}

/// The landing, striking and bouncing boxes of [`contacts`].
fn landings(report: &mut Report, checks: &mut Checks) -> Outcome {
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, scale, limit| {
        checks.check(report, what.to_owned(), (simulated, theory, scale), limit);
    };
    let mut world = World::gravity_only();
    world.restitution = 0.0;
    world.bounds = Some(Bounds {
        min: Vector::cartesian(-2.0, 0.0),
        max: Vector::cartesian(2.0, 3.0),
        friction: 0.0,
        static_friction: None,
    });
    let dropped = Scene::new()
        .with_world(world.clone())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(Body::rectangle("box", 0.4, 0.2, 1.0).position([0.3, 1.0]));
    let mut simulation = start(&dropped)?;
    step_to(&mut simulation, 1.0)?;
    let landed = simulation.body(0);
    row(
        report,
        "box dropped flat, e = 0: spin after landing (rad/s)",
        landed.spin,
        0.0,
        1.0,
        1e-12,
    );
    row(
        report,
        "box dropped flat: centroid's height at rest (m)",
        landed.position.y,
        0.1,
        0.1,
        1e-12,
    );
    world.gravity = Vector::ZERO;
    world.restitution = 1.0;
    let thrown = |spin: f64| {
        Scene::new()
            .with_world(world.clone())
            .with_integrator(Integrator::Rk4, 1e-3)
            .with_body(
                Body::rectangle("box", 0.4, 0.2, 1.0)
                    .position([0.0, 1.5])
                    .moving([-2.0, 0.5], spin),
            )
    };
    let mut simulation = start(&thrown(3.0))?;
    let before = simulation.body(0);
    step_to(&mut simulation, 1.5)?;
    let after = simulation.body(0);
    row(
        report,
        "spinning box off a wall, e = 1: kinetic energy (J)",
        after.kinetic_energy,
        before.kinetic_energy,
        before.kinetic_energy,
        1e-12,
    );
    row(
        report,
        "spinning box off a wall: velocity along the wall (m/s)",
        after.velocity.y,
        before.velocity.y,
        0.5,
        0.0,
    );
    let strikes = (0.0 - 0.2 - (-2.0)) / 2.0;
    let found = instants(&thrown(0.0), "box.vx crosses 0 up", 1.5)?;
    let at = found.first().map_or(f64::NAN, Located::time);
    row(
        report,
        "box striking a wall: the instant (s)",
        at,
        strikes,
        1.0,
        1e-9,
    );
    Ok(())
}

/// The bouncing board of [`contacts`].
fn bouncing(report: &mut Report, checks: &mut Checks) -> Outcome {
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, scale, limit| {
        checks.check(report, what.to_owned(), (simulated, theory, scale), limit);
    };
    let mut world = World::gravity_only();
    world.bounds = Some(Bounds {
        min: Vector::cartesian(-3.0, 0.0),
        max: Vector::cartesian(3.0, 4.0),
        friction: 0.0,
        static_friction: None,
    });
    let board = Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(
            Body::rectangle("board", 1.0, 0.1, 1.0)
                .position([0.0, 2.0])
                .angle(20.0)
                .moving([0.0, 0.0], 1.0),
        );
    let mut simulation = start(&board)?;
    let energy = simulation.diagnostics().energy.total();
    step_to(&mut simulation, 6.0)?;
    row(
        report,
        "board bouncing on the floor, e = 1: total energy after 6 s (J)",
        simulation.diagnostics().energy.total(),
        energy,
        energy,
        1e-9,
    );
    Ok(())
}

fn coefficients(mut body: Body, restitution: f64, friction: f64) -> Body {
    body.restitution = restitution;
    body.friction = friction;
    body
}

/// The bodies meeting bodies of [`contacts`].
fn meeting(report: &mut Report, checks: &mut Checks) -> Outcome {
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, scale, limit| {
        checks.check(report, what.to_owned(), (simulated, theory, scale), limit);
    };
    let mut weightless = World::gravity_only();
    weightless.gravity = Vector::cartesian(0.0, 0.0);
    let (m1, m2, v1, v2, e) = (2.0, 1.0, 3.0, -1.0, 0.5);
    let head_on = Scene::new()
        .with_world(weightless.clone())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(
            coefficients(Body::rectangle("a", 0.4, 0.2, m1), 0.5, 0.0)
                .position([-1.0, 0.0])
                .moving([v1, 0.0], 0.0),
        )
        .with_body(
            coefficients(Body::rectangle("b", 0.2, 0.2, m2), 0.8, 0.0)
                .position([0.5, 0.0])
                .moving([v2, 0.0], 0.0),
        );
    let mut simulation = start(&head_on)?;
    let t = 0.8;
    step_to(&mut simulation, t)?;
    let contact = (0.5 - 0.1 - (-1.0 + 0.2)) / (v1 - v2);
    let after1 = (m1 * v1 + m2 * v2 - m2 * e * (v1 - v2)) / (m1 + m2);
    let after2 = (m1 * v1 + m2 * v2 + m1 * e * (v1 - v2)) / (m1 + m2);
    let (a, b) = (simulation.body(0), simulation.body(1));
    row(
        report,
        "boxes face to face, 2 and 1 kg, e = 0.5: v₁ after (m/s)",
        a.velocity.x,
        after1,
        v1,
        1e-12,
    );
    row(
        report,
        "boxes face to face: v₂ after (m/s)",
        b.velocity.x,
        after2,
        v1,
        1e-12,
    );
    row(
        report,
        "boxes face to face: x₂ at 0.8 s, impact located (m)",
        b.position.x,
        0.5 + v2 * contact + after2 * (t - contact),
        1.0,
        1e-9,
    );
    let (ma, mb, (w, h), arm) = (0.5, 1.0, (0.2, 1.0), 0.3);
    let inertia = mb * (w * w + h * h) / 12.0;
    let strike = Scene::new()
        .with_world(weightless)
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(
            coefficients(Body::rectangle("a", 0.2, 0.2, ma), 1.0, 0.0)
                .position([-1.0, arm])
                .angle(45.0)
                .moving([2.0, 0.0], 0.0),
        )
        .with_body(coefficients(Body::rectangle("board", w, h, mb), 1.0, 0.0));
    let mut simulation = start(&strike)?;
    step_to(&mut simulation, 0.5)?;
    let j = 2.0 * 2.0 / (1.0 / ma + 1.0 / mb + arm * arm / inertia);
    row(
        report,
        "corner strikes a board 0.3 m off centre, e = 1: board's spin (rad/s)",
        simulation.body(1).spin,
        -arm * j / inertia,
        arm * j / inertia,
        1e-12,
    );
    Ok(())
}

/// The bodies resting on bodies of [`contacts`].
fn resting_on_bodies(report: &mut Report, checks: &mut Checks) -> Outcome {
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, scale, limit| {
        checks.check(report, what.to_owned(), (simulated, theory, scale), limit);
    };
    let mut floor = World::gravity_only();
    floor.restitution = 0.0;
    floor.bounds = Some(Bounds {
        min: Vector::cartesian(-2.0, 0.0),
        max: Vector::cartesian(2.0, 4.0),
        friction: 0.5,
        static_friction: None,
    });
    let stack = Scene::new()
        .with_world(floor)
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(
            coefficients(Body::rectangle("lower", 0.6, 0.3, 2.0), 0.0, 0.5).position([0.1, 0.15]),
        )
        .with_body(
            coefficients(Body::rectangle("upper", 0.3, 0.2, 1.0), 0.0, 0.5).position([0.0, 0.9]),
        );
    let mut simulation = start(&stack)?;
    step_to(&mut simulation, 10.0)?;
    row(
        report,
        "box dropped on a box, e = 0: its height after 10 s (m)",
        simulation.body(1).position.y,
        0.4,
        1.0,
        1e-9,
    );
    let slope = 30.0_f64.to_radians();
    let mut wedge = coefficients(
        Body::polygon(
            "wedge",
            vec![
                DVec2::new(0.0, 0.0),
                DVec2::new(3.0, 0.0),
                DVec2::new(3.0, 3.0 * slope.tan()),
            ],
            10.0,
        ),
        0.0,
        0.32,
    )
    .position([2.0, slope.tan()]);
    wedge.fixed = true;
    let (along, normal) = (
        DVec2::new(slope.cos(), slope.sin()),
        DVec2::new(-slope.sin(), slope.cos()),
    );
    let centre = along * 2.0 + normal * 0.1;
    let mut world = World::gravity_only();
    world.restitution = 0.0;
    let on_wedge = Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(wedge)
        .with_body(
            coefficients(Body::rectangle("block", 0.4, 0.2, 1.0), 0.0, 0.5)
                .position([centre.x, centre.y])
                .angle(30.0),
        );
    let mut simulation = start(&on_wedge)?;
    step_to(&mut simulation, 1.0)?;
    let mu = (0.32_f64 * 0.5).sqrt();
    let slid = (simulation.body(1).position - centre).length();
    row(
        report,
        "block on a wedge body, μ = √(0.32 × 0.5): distance slid in 1 s (m)",
        slid,
        0.5 * G * (slope.sin() - mu * slope.cos()),
        1.0,
        1e-9,
    );
    Ok(())
}
