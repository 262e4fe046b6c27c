//! The numerical methods against theory: each integrator's order of convergence, the
//! Barnes–Hut tree against a direct sum written here, and softening of both pair laws.

use std::f64::consts::PI;

use physics::{DVec2, Integrator, PairForces, Particle, Scene, Spring, World, field_at};

use crate::Failure;
use crate::experiments::{Outcome, start, step_to};
use crate::figures::{Figure, Panel};
use crate::report::{Report, Table, bound, error, value};
use crate::theory::DampedOscillator;

/// A world of pair forces alone: gravitation with G = `g` (or none), Coulomb with the
/// default constant when `electrostatics`, softened by `softening`.
fn pair_world(g: Option<f64>, electrostatics: bool, softening: f64) -> World {
    let mut world = World::weightless();
    world.gravitation = g.is_some();
    world.gravitational_constant = g.unwrap_or(world.gravitational_constant);
    world.electrostatics = electrostatics;
    world.softening = softening;
    world
}

/// |x − closed form| after `until` of a body of 1 kg on a circular orbit of 1 m about a
/// fixed body with G M = 1 (1 rad/s), integrated by `integrator` at `time_step`.
fn orbit_error(integrator: Integrator, time_step: f64, until: f64) -> Result<f64, Failure> {
    let mut scene = Scene::new()
        .with_world(pair_world(Some(1.0), false, 0.0))
        .with_integrator(integrator, time_step)
        .with_particle(Particle::new("sun", 1.0).radius(1e-3).fixed())
        .with_particle(
            Particle::new("planet", 1.0)
                .radius(1e-3)
                .position([1.0, 0.0])
                .velocity([0.0, 1.0]),
        );
    // dopri5 at a step it never rejects: its fifth-order solution at a fixed step.
    scene.simulation.tolerance = 1e3;
    let mut simulation = start(&scene)?;
    step_to(&mut simulation, until)?;
    Ok(simulation.positions()[1].distance(DVec2::from_angle(until)))
}

/// |x − closed form| after 2 s of 1 kg on a spring (k = 4 N/m, b = 0.4 N·s/m) released
/// 1 m from its natural length of 1 m.
fn damped_spring_error(integrator: Integrator, time_step: f64) -> Result<f64, Failure> {
    let oscillator = DampedOscillator {
        mass: 1.0,
        stiffness: 4.0,
        damping: 0.4,
        start: 1.0,
    };
    let mut scene = Scene::new()
        .with_world(pair_world(None, false, 0.0))
        .with_integrator(integrator, time_step)
        .with_particle(Particle::new("bob", oscillator.mass).position([2.0, 0.0]))
        .with_spring(
            Spring::new("spring", [0.0, 0.0], "bob", oscillator.stiffness, 1.0)
                .damping(oscillator.damping),
        );
    scene.simulation.tolerance = 1e3;
    let mut simulation = start(&scene)?;
    step_to(&mut simulation, 2.0)?;
    Ok((simulation.positions()[0].x - 1.0 - oscillator.displacement(2.0)).abs())
}

/// Each integrator's order of convergence: the error at h, h/2 and h/4 on a circular
/// orbit (a quarter turn; ten turns for dopri5, whose fifth-order term is small enough
/// that the sixth shows over a quarter turn) and, for the fixed-step methods, on a
/// damped spring (a force that depends on the velocity); each ratio of successive errors
/// within 10 % of 2^order. Steps where the leading term dominates and rounding is far
/// below the error.
pub(crate) fn integrators(report: &mut Report, figures: &mut Vec<Figure>) -> Outcome {
    let (quarter, ten_turns) = (PI / 2.0, 20.0 * PI);
    let mut rows = Vec::new();
    let mut panels = [
        Panel::against("log₂(1/h), circular orbit", "log₁₀ error (m)"),
        Panel::against("log₂(1/h), damped spring", "log₁₀ error (m)"),
    ];
    let methods = [
        (Integrator::Euler, 1, 1.0 / 4096.0, quarter),
        (Integrator::SemiImplicitEuler, 1, 1.0 / 4096.0, quarter),
        (Integrator::Verlet, 2, 1.0 / 256.0, quarter),
        (Integrator::Rk4, 4, 1.0 / 16.0, quarter),
        (Integrator::Pefrl, 4, 1.0 / 16.0, quarter),
        (Integrator::Dopri5, 5, 1.0 / 32.0, ten_turns),
    ];
    for (integrator, order, h, until) in methods {
        for (problem, panel) in ["circular orbit", "damped spring"]
            .into_iter()
            .zip(&mut panels)
        {
            let spring = problem == "damped spring";
            if spring && integrator == Integrator::Dopri5 {
                continue;
            }
            let steps = [h, h / 2.0, h / 4.0];
            let mut errors = [0.0; 3];
            for (e, &step) in errors.iter_mut().zip(&steps) {
                *e = if spring {
                    damped_spring_error(integrator, step)?
                } else {
                    orbit_error(integrator, step, until)?
                };
            }
            let expected = 2.0_f64.powi(order);
            let ratios = [errors[0] / errors[1], errors[1] / errors[2]];
            let mut worst: f64 = 0.0;
            for (k, ratio) in ratios.iter().enumerate() {
                let e = report.check_within(
                    format!(
                        "integrators: {integrator} on the {problem}, ratio {}",
                        k + 1
                    ),
                    (*ratio, expected, expected),
                    0.1,
                );
                worst = worst.max(e);
            }
            // Drawn beside a line of slope −order through the first error.
            panel.new_curve();
            for (k, (&step, &e)) in steps.iter().zip(&errors).enumerate() {
                let halvings = f64::from(u8::try_from(k).unwrap_or(0));
                let line = errors[0].log10() - f64::from(order) * halvings * 2.0_f64.log10();
                panel.add((1.0 / step).log2(), e.log10(), line);
            }
            rows.push(vec![
                integrator.to_string(),
                problem.to_owned(),
                format!("1/{:.0}", 1.0 / h),
                format!("{:.3e}, {:.3e}, {:.3e}", errors[0], errors[1], errors[2]),
                format!("{:.2}, {:.2}", ratios[0], ratios[1]),
                format!("{expected}"),
                error(worst),
                bound(0.1),
            ]);
        }
    }
    energy_bounds(report, &mut rows)?;
    report.tables.push(Table {
        section: "integrators",
        title: "Order of convergence: halving the step divides the error by 2^order".to_owned(),
        theory: "circular orbit x = (cos t, sin t) (G M = 1, r = 1 m); damped spring u = e^(−γt)(cos ωt + (γ/ω) sin ωt); orders 1, 1, 2, 4, 4, 5; on an ellipse (e = 0.5) the energy E = −G M/2a is kept by the symplectic methods within a bounded error, and explicit Euler's grows",
        header: vec!["method", "problem", "h", "errors at h, h/2, h/4 (m)", "ratios", "2^order", "error (relative)", "tolerance"],
        rows,
    });
    figures.push(Figure {
        file: "convergence.png".to_owned(),
        title: "Error against step: each method along its order's slope (validate: integrators)"
            .to_owned(),
        panels,
    });
    Ok(())
}

/// The largest |E − E₀| / |E₀| of a body on an ellipse (e = 0.5, a = 1 m, about a fixed
/// body with G M = 1, period 2π s) integrated by `integrator` at 2,000 steps a period,
/// over the periods `from..to`, sampled twenty times a period.
fn orbit_energy_drift(integrator: Integrator, (from, to): (u32, u32)) -> Result<f64, Failure> {
    let mut scene = Scene::new()
        .with_world(pair_world(Some(1.0), false, 0.0))
        .with_integrator(integrator, 2.0 * PI / 2000.0)
        .with_particle(Particle::new("sun", 1.0).radius(1e-3).fixed())
        .with_particle(
            Particle::new("planet", 1.0)
                .radius(1e-3)
                .position([0.5, 0.0])
                .velocity([0.0, 3.0_f64.sqrt()]),
        );
    scene.simulation.tolerance = 1e3;
    let mut simulation = start(&scene)?;
    // E = v²/2 − 1/r per unit mass: −1/(2a) = −0.5.
    let energy = |s: &physics::Simulation| {
        let (x, v) = (s.positions()[1], s.velocities()[1]);
        0.5 * v.length_squared() - 1.0 / x.length()
    };
    let mut worst: f64 = 0.0;
    for k in 20 * from..=20 * to {
        step_to(&mut simulation, 2.0 * PI * f64::from(k) / 20.0)?;
        worst = worst.max((energy(&simulation) + 0.5).abs() / 0.5);
    }
    Ok(worst)
}

/// What the integrators table says each method conserves: the symplectic methods'
/// energy error on an eccentric orbit stays bounded (its largest over orbits 90–100 no
/// more than 1.5 times its largest over orbits 0–10); explicit Euler's grows (more than
/// that: measured 0.41 of E₀ over the first ten orbits, 0.83 over the last).
fn energy_bounds(report: &mut Report, rows: &mut Vec<Vec<String>>) -> Outcome {
    for (integrator, bounded) in [
        (Integrator::Euler, false),
        (Integrator::SemiImplicitEuler, true),
        (Integrator::Verlet, true),
        (Integrator::Pefrl, true),
    ] {
        let early = orbit_energy_drift(integrator, (0, 10))?;
        let late = orbit_energy_drift(integrator, (90, 100))?;
        let growth = late / early;
        let (theory, passed) = if bounded {
            ("≤ 1.5 (bounded)", growth <= 1.5)
        } else {
            ("> 1.5 (grows)", growth > 1.5)
        };
        report.check_within(
            format!("integrators: {integrator}'s energy error over 100 orbits"),
            (f64::from(u8::from(passed)), 1.0, 1.0),
            0.0,
        );
        rows.push(vec![
            integrator.to_string(),
            "eccentric orbit, 100 periods".to_owned(),
            "2π/2000".to_owned(),
            format!("{early:.3e} (orbits 0–10), {late:.3e} (90–100)"),
            format!("{growth:.2}"),
            theory.to_owned(),
            if passed { "holds" } else { "FAILS" }.to_owned(),
            "as stated".to_owned(),
        ]);
    }
    Ok(())
}

/// Accelerations by a direct sum written here, G m r / (r² + ε²)^{3/2} over every pair,
/// and the potential energy −Σ G m m / √(r² + ε²), of `scene`'s bodies at `positions`.
fn direct_sum(scene: &Scene, positions: &[DVec2]) -> (Vec<DVec2>, f64) {
    let (g, softening2) = (
        scene.world.gravitational_constant,
        scene.world.softening * scene.world.softening,
    );
    let bodies: Vec<(DVec2, f64)> = positions
        .iter()
        .zip(&scene.particles)
        .map(|(&x, p)| (x, p.mass))
        .collect();
    let mut potential = 0.0;
    let accelerations = bodies
        .iter()
        .enumerate()
        .map(|(i, &(x, _))| {
            let mut a = DVec2::ZERO;
            for (j, &(y, m)) in bodies.iter().enumerate() {
                if i != j {
                    let d = y - x;
                    let r = (d.length_squared() + softening2).sqrt();
                    a += d * (g * m / (r * r * r));
                    if j > i {
                        potential -= g * bodies[i].1 * m / r;
                    }
                }
            }
            a
        })
        .collect();
    (accelerations, potential)
}

/// The Barnes–Hut tree (opening angle 0.5) on a cluster of 3,000 bodies, exact and
/// softened: its forces against the direct sum (normalised RMS error under 1e-3, the
/// median body's under 2e-3, the worst under 2e-2: the accuracy docs/physics.md states) and its
/// potential energy within 1e-4.
pub(crate) fn tree(report: &mut Report) -> Outcome {
    let mut rows = Vec::new();
    for softening in [0.0, 0.3] {
        let mut scene = physics::generated::cluster(3000);
        scene.world.softening = softening;
        scene.simulation.pair_forces = PairForces::Tree;
        let simulation = start(&scene)?;
        let tree = simulation.accelerations();
        let (direct, potential) = direct_sum(&scene, simulation.positions());
        let mut relative: Vec<f64> = tree
            .iter()
            .zip(&direct)
            .map(|(t, d)| t.distance(*d) / d.length())
            .collect();
        let squared: f64 = tree
            .iter()
            .zip(&direct)
            .map(|(t, d)| t.distance_squared(*d))
            .sum();
        let norm: f64 = direct.iter().map(|d| d.length_squared()).sum();
        relative.sort_by(f64::total_cmp);
        let rms = (squared / norm).sqrt();
        let median = relative[relative.len() / 2];
        let worst = relative.last().copied().unwrap_or(f64::NAN);
        let energy = simulation.diagnostics().energy.gravitation;
        let label = format!("ε = {softening} m");
        for (what, simulated, theory, scale, tolerance) in [
            ("normalised RMS force error", rms, 0.0, 1.0, 1e-3),
            ("median body's force error", median, 0.0, 1.0, 2e-3),
            ("worst body's force error", worst, 0.0, 1.0, 2e-2),
            (
                "potential energy (J)",
                energy,
                potential,
                potential.abs(),
                1e-4,
            ),
        ] {
            let e = report.check_within(
                format!("tree, {label}: {what}"),
                (simulated, theory, scale),
                tolerance,
            );
            rows.push(vec![
                label.clone(),
                what.to_owned(),
                if theory == 0.0 {
                    format!("{simulated:.2e}")
                } else {
                    value(simulated)
                },
                if theory == 0.0 {
                    "0".to_owned()
                } else {
                    value(theory)
                },
                error(e),
                bound(tolerance),
            ]);
        }
    }
    report.tables.push(Table {
        section: "tree",
        title: "The Barnes–Hut tree against the direct sum: a cluster of 3,000 bodies".to_owned(),
        theory: "the direct pair sum G m r/(r² + ε²)^{3/2} and −G m m/√(r² + ε²), written in validate apart from the simulation's code",
        header: vec!["softening", "quantity", "tree", "direct sum", "error", "tolerance"],
        rows,
    });
    Ok(())
}

/// Softening, both laws: a gravitating pair circles at the softened rate; a pass through
/// the softened core keeps its energy (gravitation and Coulomb); the potential energy
/// and the probe read the softened law.
pub(crate) fn softening(report: &mut Report) -> Outcome {
    let mut rows = Vec::new();
    // A pair of 1 kg, 1 m apart, ε = 0.5 m, G = 1: ω² = G (m₁ + m₂)/(d² + ε²)^{3/2}.
    let (d, epsilon) = (1.0_f64, 0.5_f64);
    let omega = (2.0 / (d * d + epsilon * epsilon).powf(1.5)).sqrt();
    let speed = omega * d / 2.0;
    let pair = Scene::new()
        .with_world(pair_world(Some(1.0), false, epsilon))
        .with_particle(
            Particle::new("a", 1.0)
                .radius(1e-6)
                .position([-0.5, 0.0])
                .velocity([0.0, -speed]),
        )
        .with_particle(
            Particle::new("b", 1.0)
                .radius(1e-6)
                .position([0.5, 0.0])
                .velocity([0.0, speed]),
        );
    let period = 2.0 * PI / omega;
    let mut simulation = start(&pair)?;
    step_to(&mut simulation, period)?;
    let miss = simulation.positions()[1].distance(DVec2::new(0.5, 0.0));
    let e = report.check_within(
        "softening: a pair back after one softened period",
        (miss, 0.0, 1.0),
        1e-8,
    );
    rows.push(vec![
        "gravitation".to_owned(),
        format!("pair 1 m apart, ε = 0.5 m: distance from the start after T = {period:.6} s (m)"),
        format!("{miss:.2e}"),
        "0".to_owned(),
        error(e),
        bound(1e-8),
    ]);

    for coulomb in [false, true] {
        softened_law(report, &mut rows, coulomb)?;
    }
    report.tables.push(Table {
        section: "softening",
        title: "Softening (Plummer), both pair laws alike in motion, energy and probe".to_owned(),
        theory: "r² + ε² for r²: force s r/(r² + ε²)^{3/2}, potential s/√(r² + ε²) (s = −G m₁m₂ or k q₁q₂); a pair circles at ω² = G(m₁ + m₂)/(d² + ε²)^{3/2}",
        header: vec!["law", "quantity", "simulated", "theory", "error", "tolerance"],
        rows,
    });
    Ok(())
}

/// The rows of one softened law (Coulomb's when `coulomb`, else gravitation): a pass's
/// starting potential and its energy through the core, and the probe beside one body.
fn softened_law(report: &mut Report, rows: &mut Vec<Vec<String>>, coulomb: bool) -> Outcome {
    let law = if coulomb { "Coulomb" } else { "gravitation" };
    let epsilon = 0.3;
    let world = if coulomb {
        pair_world(None, true, epsilon)
    } else {
        pair_world(Some(1.0), false, epsilon)
    };
    // k q₁ q₂ (negative: opposite charges attract) or −G m m.
    let strength = if coulomb {
        -world.coulomb_constant * 1e-10
    } else {
        -1.0
    };
    let charge = if coulomb { 1e-5 } else { 0.0 };
    let mut scene = Scene::new()
        .with_world(world)
        .with_particle(
            Particle::new("a", 1.0)
                .radius(1e-6)
                .charge(charge)
                .position([-2.0, 0.1])
                .velocity([1.0, 0.0]),
        )
        .with_particle(
            Particle::new("b", 1.0)
                .radius(1e-6)
                .charge(-charge)
                .position([2.0, -0.1])
                .velocity([-1.0, 0.0]),
        );
    scene.simulation.time_step = 1e-4;
    let mut simulation = start(&scene)?;
    let energy = simulation.diagnostics().energy;
    let potential = if coulomb {
        energy.electrostatic
    } else {
        energy.gravitation
    };
    let r0 = (16.0_f64 + 0.04).sqrt();
    let expected = strength / (r0 * r0 + epsilon * epsilon).sqrt();
    let e = report.check_within(
        format!("softening, {law}: starting potential"),
        (potential, expected, 1.0),
        1e-15,
    );
    rows.push(vec![
        law.to_owned(),
        "pass 0.2 m apart, ε = 0.3 m: starting potential energy (J)".to_owned(),
        value(potential),
        value(expected),
        format!("{e:.2e} J"),
        bound(1e-15),
    ]);
    let mut drift: f64 = 0.0;
    let mut closest = f64::INFINITY;
    for k in 1..=40 {
        step_to(&mut simulation, 0.1 * f64::from(k))?;
        let x = simulation.positions();
        closest = closest.min(x[0].distance(x[1]));
        drift = drift.max((simulation.diagnostics().energy.total() - energy.total()).abs());
    }
    let e = report.check_within(
        format!("softening, {law}: energy through the pass"),
        (drift, 0.0, energy.kinetic),
        1e-9,
    );
    rows.push(vec![
        law.to_owned(),
        format!(
            "largest energy change through the pass, closest {closest:.3} m (of the kinetic energy)"
        ),
        format!("{drift:.2e} J"),
        "0".to_owned(),
        error(e),
        bound(1e-9),
    ]);
    softened_probe(report, rows, coulomb);
    Ok(())
}

/// The probe 1 m from a body of 2 kg (or 1e-6 C) at the origin with ε = 1 m: field
/// s/2^{3/2}, potential s/√2, s = −G m or k q per unit test mass or charge.
fn softened_probe(report: &mut Report, rows: &mut Vec<Vec<String>>, coulomb: bool) {
    let law = if coulomb { "Coulomb" } else { "gravitation" };
    let one = Scene::new()
        .with_world(if coulomb {
            pair_world(None, true, 1.0)
        } else {
            pair_world(Some(1.0), false, 1.0)
        })
        .with_particle(Particle::new("a", 2.0).radius(1e-6).charge(if coulomb {
            1e-6
        } else {
            0.0
        }));
    let probe = field_at(&one, &[DVec2::ZERO], DVec2::new(1.0, 0.0));
    let source = if coulomb {
        one.world.coulomb_constant * 1e-6
    } else {
        -2.0
    };
    let (field, potential) = if coulomb {
        (probe.electric.x, probe.electric_potential)
    } else {
        (probe.gravity.x, probe.gravitational_potential)
    };
    for (what, simulated, theory) in [
        (
            "probe 1 m from a body, ε = 1 m: field",
            field,
            source / 2.0_f64.powf(1.5),
        ),
        (
            "probe 1 m from a body, ε = 1 m: potential",
            potential,
            source / 2.0_f64.sqrt(),
        ),
    ] {
        let e = report.check_within(
            format!("softening, {law}: {what}"),
            (simulated, theory, theory.abs()),
            1e-15,
        );
        rows.push(vec![
            law.to_owned(),
            what.to_owned(),
            value(simulated),
            value(theory),
            error(e),
            bound(1e-15),
        ]);
    }
}
