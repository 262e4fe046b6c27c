//! Events located in time against theory: the instants `run --events` writes, for a
//! projectile's landing, a pendulum's turning points and a spring's maxima.

use physics::{Event, Integrator, Located, Particle, Scene, Spring, Tie, Watch, World};

use crate::Failure;
use crate::experiments::{Outcome, start};
use crate::report::{Checks, Report};
use crate::theory;

const G: f64 = 9.81;

/// The instants of `event` in `scene` up to `until`.
pub(crate) fn instants(scene: &Scene, event: &str, until: f64) -> Result<Vec<Located>, Failure> {
    let event = Event::parse(event).map_err(Failure::Input)?;
    let mut simulation = start(scene)?;
    let mut watch = Watch::new(&[event], &simulation).map_err(Failure::Input)?;
    simulation
        .step_to_watching(until, &mut watch)
        .map_err(|e| Failure::Simulation(e.to_string()))
}

/// Three events against their closed forms, each to the tolerance its integrator's error
/// allows: a ball thrown from 10 m at (3, 4) m/s lands (`Ball.y crosses 0 down`) at
/// (v + √(v² + 2 g h)) / g, exactly for verlet, rk4, pefrl and dopri5 (a constant
/// acceleration), so to 1e-12 s; a bob on a 1 m rod released at 60° turns
/// (`Bob.vx crosses 0`) at every half of the elliptic-integral period, rk4 at 1 ms, to
/// 1e-8 s; a bob on a spring (ω = 2 rad/s) is at its maxima (`bob.vx crosses 0 down`) at
/// 2π k / ω, to 1e-9 s.
pub(crate) fn events(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("events");
    let mut row = |report: &mut Report, what: String, simulated, theory, limit| {
        checks.check(report, what, (simulated, theory, 1.0), limit);
    };
    let (h, vx, vy) = (10.0, 3.0, 4.0);
    let landing = (vy + (vy * vy + 2.0 * G * h).sqrt()) / G;
    for integrator in [
        Integrator::Verlet,
        Integrator::Rk4,
        Integrator::Pefrl,
        Integrator::Dopri5,
    ] {
        let scene = Scene::new()
            .with_world(World::gravity_only())
            .with_integrator(integrator, 1e-3)
            .with_particle(
                Particle::new("Ball", 1.0)
                    .radius(0.1)
                    .position([0.0, h])
                    .velocity([vx, vy]),
            );
        let found = instants(&scene, "Ball.y crosses 0 down", 3.0)?;
        let t = found.first().map_or(f64::NAN, Located::time);
        row(
            report,
            format!("landing, {integrator} (s)"),
            t,
            landing,
            1e-12,
        );
    }
    // The same at a coarse step, 0.05 s, dropped from rest: the instant is located inside
    // a step some thirty times the landing's own scale of error, √(2h/g) to 1e-9 s.
    let coarse = Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 0.05)
        .with_particle(Particle::new("Ball", 1.0).radius(0.1).position([0.0, h]));
    let found = instants(&coarse, "Ball.y crosses 0 down", 3.0)?;
    let t = found.first().map_or(f64::NAN, Located::time);
    row(
        report,
        "landing from rest, rk4 at 0.05 s (s)".to_owned(),
        t,
        (2.0 * h / G).sqrt(),
        1e-9,
    );
    let theta = 60.0_f64.to_radians();
    let pendulum = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("Bob", 1.0)
                .radius(0.05)
                .position([theta.sin(), -theta.cos()]),
        )
        .with_tie(Tie::rod("rod", [0.0, 0.0], "Bob", 1.0));
    let period = theory::pendulum_period(1.0, G, theta);
    let turns = instants(&pendulum, "Bob.vx crosses 0", 2.0 * period + 0.1)?;
    for k in 0..4 {
        let t = turns.get(k).map_or(f64::NAN, Located::time);
        let expected = (k + 1) as f64 * period / 2.0;
        row(
            report,
            format!("pendulum at 60°: turn {} (s)", k + 1),
            t,
            expected,
            1e-8,
        );
    }
    let spring = Scene::new()
        .with_world(World::no_forces())
        .with_particle(Particle::new("bob", 1.0).radius(0.05).position([1.5, 0.0]))
        .with_spring(Spring::new("s", "bob", [0.0, 0.0], 4.0, 1.0));
    let maxima = instants(&spring, "bob.vx crosses 0 down", 10.0)?;
    for k in 0..3 {
        let t = maxima.get(k).map_or(f64::NAN, Located::time);
        let expected = (k + 1) as f64 * std::f64::consts::PI;
        row(
            report,
            format!("spring: maximum {} (s)", k + 1),
            t,
            expected,
            1e-9,
        );
    }
    report.tables.push(checks.table(
        "Events: instants located inside a step",
        "landing (v + √(v² + 2gh))/g; a pendulum turns every half period 2 √(L/g) K(sin(θ₀/2)); a spring's maxima at 2πk/ω",
    ));
    Ok(())
}
