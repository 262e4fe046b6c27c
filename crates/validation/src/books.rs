//! Where energy goes and where a run resumes: the energy ledger against the damped
//! oscillator, friction's work and a pile's books; friction on ramps against the inclined
//! plane; a saved state continued against the run it was saved from.

use physics::{Integrator, Particle, Ramp, Scene, Simulation, World};

use crate::Failure;
use crate::experiments::{Outcome, load, start, step_to};
use crate::report::{Report, Table, bound, error, value};
use crate::theory::DampedOscillator;

const G: f64 = 9.81;

fn ledger_of(simulation: &Simulation) -> Result<physics::Ledger, Failure> {
    simulation
        .ledger()
        .ok_or_else(|| Failure::Simulation("the ledger was not kept".to_owned()))
}

/// A 2 kg block sliding at 3 m/s on a level floor with μ = 0.5.
fn sliding_block() -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_ramp(
            Ramp::new("floor", [-50.0, 0.0], [50.0, 0.0])
                .thickness(0.0)
                .friction(0.5),
        )
        .with_particle(
            Particle::new("block", 2.0)
                .radius(0.1)
                .position([0.0, 0.1])
                .velocity([3.0, 0.0]),
        )
}

/// The books close: spring damping takes what the damped oscillator loses (E₀ − E(t) of
/// the closed form, 1e-9 J: Simpson's rule over each step); friction takes μ m g × the
/// distance slid (1e-9 J: the power is linear in t, which Simpson's rule integrates
/// exactly); a pile of 150 balls dropped into a box closes kinetic + potential +
/// dissipated = E₀ to 1e-11 of E₀ through the crash and the settling.
pub(crate) fn ledger(report: &mut Report) -> Outcome {
    let mut rows = Vec::new();
    let scene = load("spring-damped-light")?;
    let (particle, spring) = (&scene.particles[0], &scene.springs[0]);
    let oscillator = DampedOscillator {
        mass: particle.mass,
        stiffness: spring.stiffness,
        damping: spring.damping,
        start: particle.position.to_dvec2().x - spring.natural_length,
    };
    let mut simulation = start(&scene)?;
    simulation.keep_ledger();
    let initial = 0.5 * oscillator.stiffness * oscillator.start * oscillator.start;
    for t in [5.0, 20.0] {
        step_to(&mut simulation, t)?;
        let u = oscillator.displacement(t);
        // The velocity from the acceleration: m a = −k u − b u̇.
        let velocity = -(oscillator.mass * oscillator.acceleration(t) + oscillator.stiffness * u)
            / oscillator.damping;
        let lost = initial
            - 0.5 * oscillator.stiffness * u * u
            - 0.5 * oscillator.mass * velocity * velocity;
        let taken = ledger_of(&simulation)?.damping;
        let e = report.check_within(
            format!("ledger: damping by t = {t} s"),
            (taken, lost, 1.0),
            1e-9,
        );
        rows.push(vec![
            format!(
                "damped spring (b = {} N·s/m): damping's take by t = {t} s (J)",
                oscillator.damping
            ),
            value(taken),
            value(lost),
            format!("{e:.2e} J"),
            bound(1e-9),
        ]);
    }
    let mut simulation = start(&sliding_block())?;
    simulation.keep_ledger();
    let mu_g = 0.5 * G;
    for t in [0.1, 0.3, 0.5] {
        step_to(&mut simulation, t)?;
        let slid = 3.0 * t - 0.5 * mu_g * t * t;
        let taken = ledger_of(&simulation)?.friction;
        let e = report.check_within(
            format!("ledger: friction by t = {t} s"),
            (taken, 2.0 * mu_g * slid, 1.0),
            1e-9,
        );
        rows.push(vec![
            format!("2 kg block sliding at 3 m/s, μ = 0.5: friction's take by t = {t} s (J)"),
            value(taken),
            value(2.0 * mu_g * slid),
            format!("{e:.2e} J"),
            bound(1e-9),
        ]);
    }
    let pile = physics::generated::ball_pit(150);
    let mut simulation = start(&pile)?;
    simulation.keep_ledger();
    let initial = simulation.diagnostics().energy.total();
    let mut worst: f64 = 0.0;
    for k in 1..=300 {
        step_to(&mut simulation, 0.01 * f64::from(k))?;
        let residual =
            simulation.diagnostics().energy.total() + ledger_of(&simulation)?.total() - initial;
        // NaN must fail: `f64::max` would pass it by.
        worst = if residual.is_nan() {
            f64::NAN
        } else {
            worst.max(residual.abs())
        };
    }
    let e = report.check_within(
        "ledger: a pile's books over 3 s",
        (worst, 0.0, initial.abs()),
        1e-11,
    );
    rows.push(vec![
        "150 balls dropped into a box, 3 s: largest |E + dissipated − E₀| (J)".to_owned(),
        format!("{worst:.2e}"),
        "0".to_owned(),
        error(e),
        bound(1e-11),
    ]);
    report.tables.push(Table {
        section: "ledger",
        title: "The energy ledger: where the energy went, and the books closing".to_owned(),
        theory: "damped oscillator E₀ − ½ k u² − ½ m u̇²; friction μ m g d with d = v₀t − ½ μ g t²; kinetic + potential + dissipated = E₀",
        header: vec!["quantity", "simulated", "theory", "error", "tolerance"],
        rows,
    });
    Ok(())
}

/// Friction on ramps: a block released at rest on a ramp of angle θ with μ = 0.4 slides
/// at g(sin θ − μ cos θ) when tan θ > μ and is held (a = 0) when tan θ ≤ μ; a block
/// sliding along a level floor stops after v₀/(μ g) at v₀²/(2 μ g). Accelerations to
/// 1e-9 of g; the stopping point to 3e-6 of the distance: the last sliver of motion,
/// slower than μ g h, is stopped by static friction at a step's start, which may leave it
/// short by up to ½ μ g h² = 2.5e-6 m at the 1 ms step (measured 9.5e-7 m).
pub(crate) fn friction(report: &mut Report) -> Outcome {
    let mu = 0.4_f64;
    let mut rows = Vec::new();
    for angle in [10.0_f64, 20.0, 30.0, 45.0, 60.0] {
        let theta = angle.to_radians();
        let along = physics::DVec2::from_angle(-theta);
        let normal = along.perp();
        let radius = 0.1;
        let scene = Scene::new()
            .with_world(World::gravity_only())
            .with_ramp(
                Ramp::new(
                    "ramp",
                    [-along.x * 50.0, -along.y * 50.0],
                    [along.x * 50.0, along.y * 50.0],
                )
                .thickness(0.0)
                .friction(mu),
            )
            .with_particle(
                Particle::new("block", 1.0)
                    .radius(radius)
                    .position([normal.x * radius, normal.y * radius]),
            );
        let mut simulation = start(&scene)?;
        step_to(&mut simulation, 0.5)?;
        let a = simulation.accelerations()[0].dot(along);
        let expected = if theta.tan() > mu {
            G * (theta.sin() - mu * theta.cos())
        } else {
            0.0
        };
        let e = report.check_within(
            format!("friction: a on the {angle}° ramp"),
            (a, expected, G),
            1e-9,
        );
        rows.push(vec![
            format!(
                "block released on a {angle}° ramp, μ = {mu}: acceleration down the ramp (m/s²)"
            ),
            value(a),
            value(expected),
            error(e),
            bound(1e-9),
            if theta.tan() > mu {
                "slides"
            } else {
                "held: tan θ ≤ μ"
            }
            .to_owned(),
        ]);
    }
    let mut simulation = start(&sliding_block())?;
    step_to(&mut simulation, 1.0)?;
    let stopped = simulation.positions()[0].x;
    let expected = 9.0 / (2.0 * 0.5 * G);
    let e = report.check_within(
        "friction: where a sliding block stops",
        (stopped, expected, expected),
        3e-6,
    );
    rows.push(vec![
        "2 kg block sliding at 3 m/s on a level floor, μ = 0.5: where it stops (m)".to_owned(),
        value(stopped),
        value(expected),
        error(e),
        bound(3e-6),
        "stops at t = 0.612 s".to_owned(),
    ]);
    report.tables.push(Table {
        section: "friction",
        title: "Friction on ramps: sliding, held, stopping".to_owned(),
        theory: "inclined plane with Coulomb friction: a = g(sin θ − μ cos θ) while tan θ > μ, held otherwise; a block stops at v₀²/(2 μ g)",
        header: vec!["quantity", "simulated", "theory", "error", "tolerance", "note"],
        rows,
    });
    Ok(())
}

/// A saved state continues its run: each built-in scene below is run to 1 s, saved
/// (`--save-state`), reopened from its text and run on to 2 s, against the run that went
/// straight to 2 s. Every fixed-step integrator on the pendulum and the damped spring,
/// and the collision and orbit examples as they ship; to 1e-9 of the scene's size (a
/// continued run agrees to rounding: loading re-projects rods by an ulp, and the contact
/// solver's warm start is not saved).
pub(crate) fn saved_state(report: &mut Report) -> Outcome {
    let mut rows = Vec::new();
    let mut cases: Vec<(String, Scene)> = Vec::new();
    for name in ["pendulum", "spring-damped-light"] {
        let scene = load(name)?;
        for integrator in Integrator::ALL {
            let mut scene = scene.clone();
            scene.simulation.integrator = integrator;
            cases.push((format!("{name}, {integrator}"), scene));
        }
    }
    for name in ["collision", "orbit", "newtons-cradle", "double-pendulum"] {
        cases.push((name.to_owned(), load(name)?));
    }
    for (label, scene) in cases {
        let mut straight = start(&scene)?;
        step_to(&mut straight, 2.0)?;
        let mut first = start(&scene)?;
        step_to(&mut first, 1.0)?;
        let saved = first.saved_state(&scene);
        let text = saved.to_toml();
        let reopened = Scene::from_toml(&text).map_err(|e| {
            Failure::Simulation(format!("{label}: the saved state does not reopen: {e}"))
        })?;
        let mut continued = start(&reopened)?;
        step_to(&mut continued, 2.0)?;
        let size = straight
            .positions()
            .iter()
            .map(|x| x.length())
            .fold(1.0, f64::max);
        let apart = straight
            .positions()
            .iter()
            .zip(continued.positions())
            .map(|(a, b)| a.distance(*b))
            .fold(0.0, f64::max);
        let e = report.check_within(format!("saved-state: {label}"), (apart, 0.0, size), 1e-9);
        rows.push(vec![label, format!("{apart:.2e}"), error(e), bound(1e-9)]);
    }
    report.tables.push(Table {
        section: "saved-state",
        title: "A saved state continues its run: saved at 1 s, reopened, run to 2 s".to_owned(),
        theory: "the run that went straight to 2 s (the claim is that saving changes nothing but rounding)",
        header: vec!["scene", "largest distance at 2 s (m)", "error (of the scene's size)", "tolerance"],
        rows,
    });
    Ok(())
}
