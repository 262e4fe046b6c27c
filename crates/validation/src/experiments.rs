//! The paper's section 4, experiment by experiment: each runs built-in scenes, compares
//! them with [`crate::theory`], and adds a table (and, for 4.6 and 4.7, a figure).

use std::time::{Duration, Instant};

use physics::{DVec2, ImpactTarget, Scene, Simulation};

use crate::Failure;
use crate::figures::{Figure, Panel};
use crate::report::{Report, Table, degrees, error, value};
use crate::theory::{self, DampedOscillator, RadialFall};

pub(super) type Outcome = Result<(), Failure>;

pub(super) fn load(name: &str) -> Result<Scene, Failure> {
    physics::example(name)
        .ok_or_else(|| Failure::Input(format!("the built-in scene '{name}' is missing")))?
        .scene()
        .map_err(|e| Failure::Input(format!("example:{name}: {e}")))
}

pub(super) fn start(scene: &Scene) -> Result<Simulation, Failure> {
    let mut simulation = Simulation::new(scene).map_err(|e| Failure::Input(e.to_string()))?;
    simulation.set_threads(crate::THREADS.load(std::sync::atomic::Ordering::Relaxed));
    Ok(simulation)
}

pub(super) fn step_to(simulation: &mut Simulation, t: f64) -> Outcome {
    simulation
        .step_to(t)
        .map_err(|e| Failure::Simulation(e.to_string()))
}

/// 4.1: how fast the simulation runs, measured on this machine, on one thread and on
/// every core (as the app runs it). Informs, never fails.
pub(crate) fn processing_time(report: &mut Report) -> Outcome {
    const PAPER: [(usize, &str); 5] = [
        (1, "7.77"),
        (5, "6.93"),
        (10, "5.66"),
        (50, "5.68"),
        (100, "6.91"),
    ];
    let cores = physics::every_core();
    let mut rows = Vec::new();
    for n in [1, 5, 10, 50, 100, 1000, 10_000] {
        let scene = physics::generated::mixed(n);
        let time_step = scene.simulation.time_step;
        let one = steps_per_second(&scene, 1)?;
        let all = if cores > 1 {
            steps_per_second(&scene, cores)?
        } else {
            one
        };
        let paper = PAPER.iter().find(|(k, _)| *k == n).map_or("—", |(_, e)| e);
        rows.push(vec![
            n.to_string(),
            format!("{one:.0}"),
            format!("{:.2}×", one * time_step),
            format!("{all:.0}"),
            format!("{:.2}×", all * time_step),
            if all * time_step >= 1.0 { "yes" } else { "no" }.to_owned(),
            paper.to_owned(),
        ]);
    }
    report.tables.push(Table {
        section: "4.1",
        title: format!(
            "Processing time: the largest time scale that keeps up with real time (1 ms steps; springs, charges, collisions), on one thread and on all {cores} cores"
        ),
        theory: "measured on this machine (steps per second × time step); informative, never a failure",
        header: vec![
            "n",
            "steps/s, 1 thread",
            "time scale, 1 thread",
            "steps/s, all cores",
            "time scale, all cores",
            "1× holds",
            "paper's % error",
        ],
        rows,
    });
    Ok(())
}

/// Steps per second of `scene` from its first step on, over 0.4 s of wall clock, on
/// `threads` threads.
fn steps_per_second(scene: &Scene, threads: usize) -> Result<f64, Failure> {
    let fail = |e: physics::SimulationError| Failure::Simulation(e.to_string());
    let mut simulation = start(scene)?;
    simulation.set_threads(threads);
    simulation.step().map_err(fail)?;
    let (budget, clock) = (Duration::from_millis(400), Instant::now());
    let mut steps = 0_u32;
    while steps < 2 || clock.elapsed() < budget {
        simulation.step().map_err(fail)?;
        steps += 1;
    }
    Ok(f64::from(steps) / clock.elapsed().as_secs_f64())
}

/// 4.2: constant-acceleration kinematics, Cartesian and polar.
pub(crate) fn kinematics(report: &mut Report) -> Outcome {
    const CARTESIAN: [(f64, &str); 10] = [
        (1.4, "0.345"),
        (2.2, "0.383"),
        (3.4, "0.400"),
        (4.5, "0.399"),
        (5.5, "0.392"),
        (6.2, "0.386"),
        (7.2, "0.376"),
        (8.1, "0.367"),
        (9.3, "0.354"),
        (10.2, "0.345"),
    ];
    const POLAR: [(f64, &str); 10] = [
        (1.0, "0.302"),
        (2.2, "0.631"),
        (3.3, "0.884"),
        (4.1, "1.008"),
        (5.1, "1.021"),
        (6.4, "0.670"),
        (7.2, "0.275"),
        (8.4, "-0.311"),
        (9.0, "-0.523"),
        (10.2, "-0.768"),
    ];
    for (name, times, polar) in [
        ("kinematics-cartesian", CARTESIAN, false),
        ("kinematics-polar", POLAR, true),
    ] {
        let scene = load(name)?;
        let particle = &scene.particles[0];
        let field = scene.world.gravity.to_dvec2() + particle.acceleration.to_dvec2();
        let (x0, v0) = (particle.position.to_dvec2(), particle.velocity.to_dvec2());
        let mut simulation = start(&scene)?;
        let mut rows = Vec::new();
        for (t, paper) in times {
            step_to(&mut simulation, t)?;
            let exact = theory::constant_acceleration(x0, v0, field, t);
            let (simulated, theory) = if polar {
                (simulation.positions()[0].length(), exact.length())
            } else {
                (simulation.positions()[0].x, exact.x)
            };
            let e = report.check(
                format!("4.2 {name} at t = {t}"),
                simulated,
                theory,
                theory.abs(),
            );
            rows.push(vec![
                format!("{t}"),
                value(simulated),
                value(theory),
                error(e),
                paper.to_owned(),
            ]);
        }
        let (title, quantity) = if polar {
            ("Kinematics, polar: |r| at the paper's times", "|r| (m)")
        } else {
            ("Kinematics, Cartesian: x at the paper's times", "x (m)")
        };
        report.tables.push(Table {
            section: "4.2",
            title: format!("{title} ({quantity})"),
            theory: "constant acceleration, r = r0 + v0 t + a t²/2",
            header: vec![
                "t (s)",
                "simulated",
                "theory",
                "relative error",
                "paper's % error",
            ],
            rows,
        });
    }
    Ok(())
}

/// 4.3: the two-ball collision, before and after.
pub(crate) fn collision(report: &mut Report) -> Outcome {
    let scene = load("collision")?;
    let (a, b) = (&scene.particles[0], &scene.particles[1]);
    let masses = (a.mass, b.mass);
    let (xa, xb) = (a.position.to_dvec2(), b.position.to_dvec2());
    let (va, vb) = (a.velocity.to_dvec2(), b.velocity.to_dvec2());
    // Contact when |Δx + Δv t| = rA + rB: the smaller root of a quadratic.
    let (dx, dv, reach) = (xb - xa, vb - va, a.radius + b.radius);
    let (qa, qb, qc) = (dv.dot(dv), 2.0 * dx.dot(dv), dx.dot(dx) - reach * reach);
    let contact = (-qb - (qb * qb - 4.0 * qa * qc).sqrt()) / (2.0 * qa);
    let normal = (dx + dv * contact) / reach;
    let (va_after, vb_after) = theory::impact(masses, (va, vb), normal, scene.world.restitution);

    let mut simulation = start(&scene)?;
    step_to(&mut simulation, contact + 0.1)?;
    let (sa, sb) = (simulation.velocities()[0], simulation.velocities()[1]);
    let speed = va.length().max(vb.length());
    for (what, simulated, expected) in [
        ("A' x", sa.x, va_after.x),
        ("A' y", sa.y, va_after.y),
        ("B' x", sb.x, vb_after.x),
        ("B' y", sb.y, vb_after.y),
    ] {
        report.check(format!("4.3 {what}"), simulated, expected, speed);
    }
    let kinetic = |m: f64, v: DVec2| 0.5 * m * v.length_squared();
    let (ke_before, ke_after) = (
        kinetic(a.mass, va) + kinetic(b.mass, vb),
        kinetic(a.mass, sa) + kinetic(b.mass, sb),
    );
    let (p_before, p_after) = (va * a.mass + vb * b.mass, sa * a.mass + sb * b.mass);
    let momentum_scale = a.mass * va.length() + b.mass * vb.length();
    report.check("4.3 Σp x", p_after.x, p_before.x, momentum_scale);
    report.check("4.3 Σp y", p_after.y, p_before.y, momentum_scale);
    let energy_error = report.check("4.3 ΣKE", ke_after, ke_before, ke_before);
    let pair = |v: DVec2| format!("({:.6}, {:.6})", v.x, v.y);
    let object = |name: &str, m: f64, before: DVec2, after: DVec2, theory: DVec2, paper: &str| {
        vec![
            name.to_owned(),
            pair(before),
            pair(before * m),
            format!("{:.6}", kinetic(m, before)),
            pair(after),
            pair(theory),
            pair(after * m),
            format!("{:.6}", kinetic(m, after)),
            paper.to_owned(),
        ]
    };
    let rows = vec![
        object("A", a.mass, va, sa, va_after, "(5.618, -8.989)"),
        object("B", b.mass, vb, sb, vb_after, "(14.382, 8.989)"),
        vec![
            "Σ".into(),
            String::new(),
            pair(p_before),
            format!("{ke_before:.6}"),
            String::new(),
            String::new(),
            pair(p_after),
            format!("{ke_after:.6}"),
            format!("ΣKE error {}", error(energy_error)),
        ],
    ];
    report.tables.push(Table {
        section: "4.3",
        title: "Two objects before and after the collision".to_owned(),
        theory: "impulse j = −(1 + e)(v_A − v_B)·n / (1/m_A + 1/m_B) along the contact normal n (the paper's 8–10)",
        header: vec!["object", "v", "p", "KE", "v' simulated", "v' theory", "p'", "KE'", "paper's v'"],
        rows,
    });
    Ok(())
}

const RAMP_ANGLES: [f64; 7] = [-60.0, -45.0, -30.0, 0.0, 30.0, 45.0, 60.0];

/// An angle folded to (−90°, 90°]: the direction of a line, as the paper reports it.
fn line_direction(v: DVec2) -> f64 {
    let mut angle = v.y.atan2(v.x).to_degrees();
    while angle > 90.0 {
        angle -= 180.0;
    }
    while angle <= -90.0 {
        angle += 180.0;
    }
    angle
}

/// An angle normalised to (−180°, 180°].
fn normalised(mut angle: f64) -> f64 {
    while angle > 180.0 {
        angle -= 360.0;
    }
    while angle <= -180.0 {
        angle += 360.0;
    }
    angle
}

/// 4.4: sliding down ramps. 4.5: bouncing off them.
pub(crate) fn ramps(report: &mut Report) -> Outcome {
    let scene = load("ramp-slides")?;
    let gravity = scene.world.gravity.to_dvec2();
    let mut simulation = start(&scene)?;
    step_to(&mut simulation, 0.5)?;
    let accelerations = simulation.accelerations();
    let mut rows = Vec::new();
    for (k, angle) in RAMP_ANGLES.into_iter().enumerate() {
        let (a, expected) = (accelerations[k], theory::inclined_plane(gravity, angle));
        let e = report.check(
            format!("4.4 |a| on the {angle}° ramp"),
            a.length(),
            expected.length(),
            gravity.length(),
        );
        let direction = if a.length() > 1e-9 {
            degrees(line_direction(a))
        } else {
            "— (a = 0)".to_owned()
        };
        report.check(
            format!("4.4 a on the {angle}° ramp"),
            a.distance(expected),
            0.0,
            gravity.length(),
        );
        rows.push(vec![
            format!("{angle}"),
            direction,
            format!("{angle}"),
            value(a.length()),
            value(expected.length()),
            error(e),
            format!("{angle}"),
        ]);
    }
    report.tables.push(Table {
        section: "4.4",
        title: "Acceleration of a projectile sliding down ramps (direction of the line, magnitude in m/s²)".to_owned(),
        theory: "inclined plane without friction: a = (g·u) u along the ramp's direction u, |a| = g |sin θ|",
        header: vec!["θ ramp", "θ a simulated", "θ a theory", "|a| simulated", "|a| theory", "error (of g)", "paper's θ a"],
        rows,
    });

    let paper = ["-30.0", "0.0", "30.0", "90.0", "150.0", "180.0", "-150.0"];
    let scene = load("ramp-bounces")?;
    let mut simulation = start(&scene)?;
    let incoming: Vec<DVec2> = simulation.velocities().to_vec();
    step_to(&mut simulation, 0.3)?;
    let mut rows = Vec::new();
    for (k, angle) in RAMP_ANGLES.into_iter().enumerate() {
        let normal = DVec2::from_angle(angle.to_radians()).perp();
        let expected = theory::reflection(incoming[k], normal, scene.ramps[k].restitution);
        let v = simulation.velocities()[k];
        let direction = normalised(v.y.atan2(v.x).to_degrees());
        let expected_direction = normalised(expected.y.atan2(expected.x).to_degrees());
        let speed = incoming[k].length();
        report.check(
            format!("4.5 v' x on the {angle}° ramp"),
            v.x,
            expected.x,
            speed,
        );
        report.check(
            format!("4.5 v' y on the {angle}° ramp"),
            v.y,
            expected.y,
            speed,
        );
        let incidence = (-incoming[k]).angle_to(normal).to_degrees().abs();
        let reflection = v.angle_to(normal).to_degrees().abs();
        report.check(
            format!("4.5 reflection angle on the {angle}° ramp"),
            reflection,
            incidence,
            90.0,
        );
        rows.push(vec![
            format!("{angle}"),
            degrees(direction),
            degrees(expected_direction),
            degrees(90.0 - incidence),
            degrees(90.0 - reflection),
            value(v.length()),
            paper[k].to_owned(),
        ]);
    }
    report.tables.push(Table {
        section: "4.5",
        title: "Angles of incidence and reflection, 10 m/s straight down onto ramps (degrees from the surface)".to_owned(),
        theory: "reflection v' = v − (1 + e)(v·n) n: v∥ kept, v⊥ reversed (the paper's 17–22), so θ'v = 2θ + 90°",
        header: vec!["θ ramp", "θ'v simulated", "θ'v theory", "θ i", "θ r", "speed after (m/s)", "paper's θ'v"],
        rows,
    });
    Ok(())
}

/// 4.6: the three springs over 20 s against the damped oscillator.
pub(crate) fn springs(report: &mut Report, figures: &mut Vec<Figure>) -> Outcome {
    let mut rows = Vec::new();
    for (name, file) in [
        ("spring-undamped", "spring-b0"),
        ("spring-damped-light", "spring-b0.25"),
        ("spring-damped-heavy", "spring-b0.5"),
    ] {
        let scene = load(name)?;
        let (particle, spring) = (&scene.particles[0], &scene.springs[0]);
        let equilibrium = spring.natural_length;
        let oscillator = DampedOscillator {
            mass: particle.mass,
            stiffness: spring.stiffness,
            damping: spring.damping,
            start: particle.position.to_dvec2().x - equilibrium,
        };
        let mut simulation = start(&scene)?;
        let (mut position, mut acceleration) = (
            Panel::new("position x (m)"),
            Panel::new("acceleration a (m/s²)"),
        );
        let mut worst: f64 = 0.0;
        for k in 0..=2000 {
            let t = f64::from(k) * 0.01;
            step_to(&mut simulation, t)?;
            let (x, a) = (simulation.positions()[0].x, simulation.accelerations()[0].x);
            let (x_theory, a_theory) = (
                equilibrium + oscillator.displacement(t),
                oscillator.acceleration(t),
            );
            worst = worst.max((x - x_theory).abs());
            position.add(t, x, x_theory);
            acceleration.add(t, a, a_theory);
        }
        let amplitude = oscillator.start.abs();
        let e = report.check(
            format!("4.6 {name}: largest position error over 20 s"),
            worst,
            0.0,
            amplitude,
        );
        let mut peaks = Vec::new();
        let mut simulation = start(&scene)?;
        for k in 1..=3 {
            let (t, u) = oscillator.peak(k);
            step_to(&mut simulation, t)?;
            let x = simulation.positions()[0].x;
            report.check(
                format!("4.6 {name}: peak {k}"),
                x,
                equilibrium + u,
                amplitude,
            );
            peaks.push(format!("{:.9} ({:.9})", x, equilibrium + u));
        }
        let paper = if spring.damping == 0.0 {
            "peak 15.850 (5.7 %)"
        } else {
            "—"
        };
        rows.push(vec![
            format!("{}", spring.damping),
            format!("{:.3e} m", worst),
            error(e),
            peaks.join(", "),
            paper.to_owned(),
        ]);
        figures.push(Figure {
            file: format!("{file}.png"),
            title: format!(
                "Object on a spring, b = {} N·s/m (paper 4.6)",
                spring.damping
            ),
            panels: [position, acceleration],
        });
    }
    report.tables.push(Table {
        section: "4.6",
        title: "Springs over 20 s (k = 1 N/m, natural length 10 m, released at x = 15 m)".to_owned(),
        theory: "damped harmonic oscillator x = 10 + 5 e^(−γt)(cos ωt + (γ/ω) sin ωt), γ = b/2m, ω = √(k/m − γ²); peaks at t = 2πk/ω",
        header: vec!["b (N·s/m)", "largest |x − theory|", "error (of 5 m)", "peaks 1–3 simulated (theory), m", "paper"],
        rows,
    });
    Ok(())
}

/// The 4.7 rows for the turning points of body 1 (released at rest at `start`, `distance`
/// from body 2): how many were found against how many the period 2 × `fall_time` puts in
/// 20 s, and where each is. Counting them makes a run that finds none, or misses a
/// bounce, fail instead of passing with fewer rows.
fn turning_point_rows(
    report: &mut Report,
    rows: &mut Vec<Vec<String>>,
    label: &str,
    turning_points: &[(f64, f64)],
    (start, distance): (f64, f64),
    fall_time: f64,
) {
    let expected = (20.0 / (2.0 * fall_time)).floor();
    let found = turning_points.len() as f64;
    let e = report.check(
        format!("4.7 {label}: number of turning points in 20 s"),
        found,
        expected,
        1.0,
    );
    rows.push(vec![
        label.to_owned(),
        "turning points in 20 s".into(),
        format!("{found}"),
        format!("{expected} (every {:.4} s)", 2.0 * fall_time),
        error(e),
    ]);
    for (n, (t, x)) in turning_points.iter().enumerate() {
        let e = report.check(
            format!("4.7 {label}: turning point {}", n + 1),
            *x,
            start,
            distance,
        );
        rows.push(vec![
            label.to_owned(),
            format!("turning point {} at t ≈ {t:.2} s, x (m)", n + 1),
            value(*x),
            value(start),
            error(e),
        ]);
    }
}

/// 4.7: bodies falling together under gravitation or Coulomb attraction, bouncing
/// elastically and rising back to where they started.
pub(crate) fn inverse_square(report: &mut Report, figures: &mut Vec<Figure>) -> Outcome {
    let mut rows = Vec::new();
    for (name, file, label) in [
        ("paper-gravitation", "gravitation", "Gravitation"),
        ("paper-coulomb", "coulomb", "Coulomb"),
    ] {
        let scene = load(name)?;
        let (one, two) = (&scene.particles[0], &scene.particles[1]);
        let (m1, m2) = (one.mass, two.mass);
        let (x1, x2) = (one.position.to_dvec2().x, two.position.to_dvec2().x);
        // The attraction of the relative coordinate r = x2 − x1, and body 1's share.
        let (strength, pull_on_one) = if scene.world.gravitation {
            let g = scene.world.gravitational_constant;
            (g * (m1 + m2), g * m2)
        } else {
            let k = scene.world.coulomb_constant * (one.charge * two.charge).abs();
            (k * (1.0 / m1 + 1.0 / m2), k / m1)
        };
        let fall = RadialFall {
            strength,
            start: x2 - x1,
        };
        let contact = one.radius + two.radius;
        let centre = (m1 * x1 + m2 * x2) / (m1 + m2);
        let theory_x1 = |t: f64| centre - m2 / (m1 + m2) * fall.bouncing_separation(contact, t);
        let theory_a1 = |t: f64| pull_on_one / fall.bouncing_separation(contact, t).powi(2);

        let mut simulation = start(&scene)?;
        simulation.record_impacts();
        let (mut position, mut acceleration) = (
            Panel::new("position of body 1, x (m)"),
            Panel::new("acceleration of body 1 (m/s²)"),
        );
        let mut turning_points = Vec::new();
        let mut previous_v = 0.0;
        for k in 0..=2000 {
            let t = f64::from(k) * 0.01;
            step_to(&mut simulation, t)?;
            let (x, v, a) = (
                simulation.positions()[0].x,
                simulation.velocities()[0].x,
                simulation.accelerations()[0].x,
            );
            position.add(t, x, theory_x1(t));
            acceleration.add(t, a, theory_a1(t));
            // Body 1 turns where it stops moving away (−x) from body 2: the vertex of the
            // local parabola, x − v²/2a, between samples.
            if previous_v < 0.0 && v >= 0.0 {
                turning_points.push((t, x - v * v / (2.0 * a)));
            }
            previous_v = v;
        }
        let first_contact = simulation
            .take_impacts()
            .into_iter()
            .find(|i| i.particle == 0 && i.other == ImpactTarget::Particle(1))
            .map_or(f64::NAN, |i| i.time);
        let fall_time = fall.time_to(contact);
        let e = report.check(
            format!("4.7 {label}: time of first contact"),
            first_contact,
            fall_time,
            fall_time,
        );
        rows.push(vec![
            label.to_owned(),
            "first contact (s)".into(),
            value(first_contact),
            value(fall_time),
            error(e),
        ]);
        turning_point_rows(
            report,
            &mut rows,
            label,
            &turning_points,
            (x1, fall.start),
            fall_time,
        );
        figures.push(Figure {
            file: format!("{file}.png"),
            title: format!("{label}: body 1 falling, bouncing and rising back (paper 4.7)"),
            panels: [position, acceleration],
        });
    }
    report.tables.push(Table {
        section: "4.7",
        title: "Inverse-square forces: first contact and the turning points after each bounce (restitution 1)".to_owned(),
        theory: "radial free fall t = √(r0³/2μ)(√(u(1−u)) + arccos √u), u = r/r0, μ = G(m1 + m2) or k|q1q2|(1/m1 + 1/m2); energy conservation returns each body to its start",
        header: vec!["experiment", "quantity", "simulated", "theory", "error"],
        rows,
    });
    Ok(())
}
