//! Rods and strings against theory: the rod pendulum's period at large amplitudes, rods
//! between unequal masses, and a string going slack and flying on a parabola.

use physics::{DVec2, Particle, Scene, Simulation, Tie, World};

use crate::experiments::{Outcome, start, step_to};
use crate::figures::{Figure, Panel};
use crate::report::{Report, Table, bound, error, value};
use crate::theory;

const G: f64 = 9.81;

/// The tangential velocity and acceleration of a bob circling the origin.
fn tangential(simulation: &Simulation) -> (f64, f64) {
    let x = simulation.positions()[0];
    let along = x.perp().normalize();
    (
        simulation.velocities()[0].dot(along),
        simulation.accelerations()[0].dot(along),
    )
}

/// The rod pendulum (1 kg on 1 m, rk4 at 1 ms) at amplitudes from 10° to 170°: the period
/// against the elliptic integral, to 1e-9 of it (rk4's error over a period is some
/// 1e-12). The simulated period is where the bob next stops: after the theory's period
/// its tangential speed v and acceleration a put the stop at T − v/a. Then rods between a
/// 1 kg and a 3 kg body: started moving along the rod, both ends must move on at the
/// centre of mass's speed (momentum kept to 1e-12), and a spinning dumbbell's centre of
/// mass must stay still to 1e-12 m over 10 s.
pub(crate) fn rods(report: &mut Report) -> Outcome {
    let mut rows = Vec::new();
    pendulum_periods(report, &mut rows)?;
    unequal_masses(report, &mut rows)?;
    report.tables.push(Table {
        section: "rods",
        title: "Rods: the pendulum's period at large amplitudes; unequal masses".to_owned(),
        theory: "period 4 √(L/g) K(sin(θ₀/2)) (K by the arithmetic–geometric mean); a rod's blow conserves momentum, so both ends move on at the centre of mass's speed m₁v/(m₁ + m₂)",
        header: vec!["quantity", "simulated", "theory", "error", "tolerance", "note"],
        rows,
    });
    Ok(())
}

/// The rows of the rod pendulum's periods.
fn pendulum_periods(report: &mut Report, rows: &mut Vec<Vec<String>>) -> Outcome {
    for amplitude in [10.0_f64, 45.0, 90.0, 120.0, 170.0] {
        let theta = amplitude.to_radians();
        let scene = Scene::new()
            .with_world(World::gravity_only())
            .with_particle(
                Particle::new("bob", 1.0)
                    .radius(0.05)
                    .position([theta.sin(), -theta.cos()]),
            )
            .with_tie(Tie::rod("rod", [0.0, 0.0], "bob", 1.0));
        let period = theory::pendulum_period(1.0, G, theta);
        let mut simulation = start(&scene)?;
        step_to(&mut simulation, period)?;
        let (v, a) = tangential(&simulation);
        let simulated = period - v / a;
        let e = report.check_within(
            format!("rods: period at {amplitude}°"),
            (simulated, period, period),
            1e-9,
        );
        let small_angle = 2.0 * std::f64::consts::PI * (1.0 / G).sqrt();
        rows.push(vec![
            format!("pendulum released at {amplitude}°: period (s)"),
            value(simulated),
            value(period),
            error(e),
            bound(1e-9),
            format!("small-angle law {small_angle:.6} s"),
        ]);
    }
    Ok(())
}

/// The rows of the rods between a 1 kg and a 3 kg body.
fn unequal_masses(report: &mut Report, rows: &mut Vec<Vec<String>>) -> Outcome {
    let dumbbell = |light: Particle, heavy: Particle| {
        Scene::new()
            .with_world(World::no_forces())
            .with_particle(light)
            .with_particle(heavy)
            .with_tie(Tie::rod("rod", "light", "heavy", 1.0))
    };
    let pushed = dumbbell(
        Particle::new("light", 1.0)
            .radius(0.05)
            .velocity([1.0, 0.0]),
        Particle::new("heavy", 3.0)
            .radius(0.05)
            .position([1.0, 0.0]),
    );
    let mut simulation = start(&pushed)?;
    let speeds = [simulation.velocities()[0].x, simulation.velocities()[1].x];
    step_to(&mut simulation, 10.0)?;
    let momentum = simulation.diagnostics().momentum.x;
    for (what, simulated, theory) in [
        ("light end's speed at the start (m/s)", speeds[0], 0.25),
        ("heavy end's speed at the start (m/s)", speeds[1], 0.25),
        ("momentum after 10 s (kg·m/s)", momentum, 1.0),
    ] {
        let e = report.check_within(
            format!("rods: 1 + 3 kg, {what}"),
            (simulated, theory, 1.0),
            1e-12,
        );
        rows.push(vec![
            format!("1 + 3 kg rod, light end pushed along it at 1 m/s: {what}"),
            value(simulated),
            value(theory),
            error(e),
            bound(1e-12),
            "weighting the ends equally: 0.5 and 2".to_owned(),
        ]);
    }
    let omega = 2.0;
    let spinning = dumbbell(
        Particle::new("light", 1.0)
            .radius(0.05)
            .position([-0.75, 0.0])
            .velocity([0.0, -0.75 * omega]),
        Particle::new("heavy", 3.0)
            .radius(0.05)
            .position([0.25, 0.0])
            .velocity([0.0, 0.25 * omega]),
    );
    let mut simulation = start(&spinning)?;
    let mut wander: f64 = 0.0;
    for k in 1..=100 {
        step_to(&mut simulation, 0.1 * f64::from(k))?;
        let x = simulation.positions();
        wander = wander.max(((x[0] + x[1] * 3.0) / 4.0).length());
    }
    let e = report.check_within(
        "rods: spinning 1 + 3 kg dumbbell's centre of mass",
        (wander, 0.0, 1.0),
        1e-12,
    );
    rows.push(vec![
        "1 + 3 kg dumbbell spinning at 2 rad/s: centre of mass's largest distance from rest over 10 s (m)".to_owned(),
        format!("{wander:.2e}"),
        "0".to_owned(),
        error(e),
        bound(1e-12),
        String::new(),
    ]);
    Ok(())
}

/// The `string-circle` set-up (1 kg on a 2 m string, started at the bottom at √(3.5 g L)):
/// the string goes slack where m v²/L + m g cos φ = 0 (φ = 120°, at the instant the
/// circular motion's closed form gives by Simpson's rule), carries nothing a microsecond
/// later (the ball's acceleration g to 1e-12), and the ball flies on the parabola to
/// 1e-9 m until it is 2 m from the pivot again, where the string snaps taut within 1e-9 s.
/// `scene` run to `t`.
fn simulation_at(scene: &Scene, t: f64) -> Result<Simulation, crate::Failure> {
    let mut simulation = start(scene)?;
    step_to(&mut simulation, t)?;
    Ok(simulation)
}

/// The rows of the string's slack instant `t_slack`: pulling a microsecond before it,
/// nothing a microsecond after, the ball falling freely.
fn slack_instant(
    report: &mut Report,
    rows: &mut Vec<Vec<String>>,
    scene: &Scene,
    t_slack: f64,
) -> Outcome {
    let before = simulation_at(scene, t_slack - 1e-6)?;
    let after = simulation_at(scene, t_slack + 1e-6)?;
    let fall = after.accelerations()[0] - DVec2::new(0.0, -G);
    let pulling = before.tensions()[0];
    report.check_within(
        "strings: still pulling 1 µs before the slack instant",
        (f64::from(u8::from(pulling > 0.0)), 1.0, 1.0),
        0.0,
    );
    rows.push(vec![
        format!("tension 1 µs before the slack instant t = {t_slack:.9} s (N)"),
        format!("{pulling:.3e}"),
        "> 0".to_owned(),
        if pulling > 0.0 { "—" } else { "wrong sign" }.to_owned(),
        "> 0".to_owned(),
    ]);
    for (what, simulated, tolerance) in [
        (
            "tension 1 µs after the slack instant (N)",
            after.tensions()[0].abs(),
            0.0,
        ),
        (
            "|a − g| 1 µs after the slack instant (m/s²)",
            fall.length(),
            1e-12,
        ),
    ] {
        let e = report.check_within(format!("strings: {what}"), (simulated, 0.0, 1.0), tolerance);
        rows.push(vec![
            what.to_owned(),
            format!("{simulated:.2e}"),
            "0".to_owned(),
            error(e),
            bound(tolerance),
        ]);
    }
    Ok(())
}

pub(crate) fn strings(report: &mut Report, figures: &mut Vec<Figure>) -> Outcome {
    let length = 2.0_f64;
    let v0 = (3.5 * G * length).sqrt();
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(0.15)
                .position([0.0, -length])
                .velocity([v0, 0.0]),
        )
        .with_tie(Tie::string("string", [0.0, 0.0], "ball", length));
    let phi_slack = (-0.5_f64).acos();
    let speed = |phi: f64| (v0 * v0 - 2.0 * G * length * (1.0 - phi.cos())).sqrt();
    let t_slack = theory::simpson(|phi| length / speed(phi), 0.0, phi_slack, 200_000);
    let (sin, cos) = phi_slack.sin_cos();
    let p_slack = DVec2::new(length * sin, -length * cos);
    let v_slack = DVec2::new(cos, sin) * speed(phi_slack);
    let flight = |t: f64| {
        let s = t - t_slack;
        p_slack + v_slack * s + DVec2::new(0.0, -0.5 * G * s * s)
    };
    let t_taut = theory::bisect(
        |t| flight(t).length() > length,
        (t_slack + 1e-3, t_slack + 2.0),
    );
    let at = |t: f64| simulation_at(&scene, t);
    let mut rows = Vec::new();
    slack_instant(report, &mut rows, &scene, t_slack)?;
    let (mut x_panel, mut y_panel) = (
        Panel::new("ball's x in flight (m)"),
        Panel::new("ball's y in flight (m)"),
    );
    let mut simulation = start(&scene)?;
    let mut worst: f64 = 0.0;
    for k in 1..=100 {
        let t = t_slack + (t_taut - t_slack) * f64::from(k) / 101.0;
        step_to(&mut simulation, t)?;
        let (x, theory) = (simulation.positions()[0], flight(t));
        worst = worst.max(x.distance(theory));
        x_panel.add(t, x.x, theory.x);
        y_panel.add(t, x.y, theory.y);
    }
    let e = report.check_within(
        "strings: largest distance from the parabola in flight",
        (worst, 0.0, 1.0),
        1e-9,
    );
    rows.push(vec![
        "largest distance from the parabola in flight, 100 samples (m)".to_owned(),
        format!("{worst:.2e}"),
        "0".to_owned(),
        error(e),
        bound(1e-9),
    ]);
    let radial = |s: &Simulation| s.velocities()[0].dot(s.positions()[0].normalize());
    let (before, after) = (at(t_taut - 1e-9)?, at(t_taut + 1e-9)?);
    let outward = radial(&before);
    report.check_within(
        "strings: still flying outward 1 ns before the taut instant",
        (f64::from(u8::from(outward > 1.0)), 1.0, 1.0),
        0.0,
    );
    rows.push(vec![
        format!("radial speed 1 ns before the taut instant t = {t_taut:.9} s (m/s)"),
        value(outward),
        "> 1".to_owned(),
        if outward > 1.0 {
            "—"
        } else {
            "not yet flying"
        }
        .to_owned(),
        "> 1".to_owned(),
    ]);
    let taken = radial(&after);
    let e = report.check_within(
        "strings: radial speed 1 ns after the taut instant",
        (taken, 0.0, outward),
        1e-6,
    );
    rows.push(vec![
        "radial speed 1 ns after the taut instant (m/s), restitution 0".to_owned(),
        format!("{taken:.2e}"),
        "0".to_owned(),
        error(e),
        bound(1e-6),
    ]);
    report.tables.push(Table {
        section: "strings",
        title: "A string going slack and snapping taut (1 kg on 2 m, started at √(3.5 g L))".to_owned(),
        theory: "slack where m v²/L + m g cos φ = 0 (φ = 120°, t from ∫ L dφ / v(φ)), then the parabola from there; taut where the parabola is L from the pivot (bisection)",
        header: vec!["quantity", "simulated", "theory", "error", "tolerance"],
        rows,
    });
    figures.push(Figure {
        file: "string-flight.png".to_owned(),
        title: "A ball flying free of its slack string (validate: strings)".to_owned(),
        panels: [x_panel, y_panel],
    });
    Ok(())
}
