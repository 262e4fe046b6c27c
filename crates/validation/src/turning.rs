//! Bodies that turn, against the closed forms of rigid discs and rings (k = I/(m r²)):
//! Galileo's inclined plane, a bowled ball's slip-to-roll instant, a spinning bounce.

use physics::{Bounds, Integrator, Located, Particle, Ramp, Scene, Simulation, Vector, World};

use crate::Failure;
use crate::events::instants;
use crate::experiments::{Outcome, load, start, step_to};
use crate::report::{Checks, Report};

const G: f64 = 9.81;

fn world() -> World {
    World {
        gravity: Vector::cartesian(0.0, -G),
        ..World::gravity_only()
    }
}

/// Galileo's inclined plane as a table, from the `galileo-incline` example: the times a
/// frictionless slider (k = 0), a solid disc (½) and a ring (1) take to go 5 m down a 20°
/// incline from rest, located as events, beside t = √(2 L (1 + k)/(g sin θ)); rk4
/// integrates the constant accelerations exactly, so 1e-9 s is rounding. Then a disc
/// bowled at 6 m/s on a lane with μ = 0.2: it rolls on at 2 v₀/3, friction took
/// ½ m v₀² − ½ m (1 + k) v², and angular momentum about the lane is kept; and a disc
/// spinning at 12 rad/s dropped on a gripping floor, which leaves at −ω₀ r/3 with ω₀/3;
/// a backspun disc that reverses, then rolls ([`backspun`]); and a disc pushing a ring
/// along a gripping floor ([`pushed`]).
pub(crate) fn turning(report: &mut Report) -> Outcome {
    let mut galileo = Checks::new("turning");
    let scene = load("galileo-incline")?;
    let theta = 20.0_f64.to_radians();
    let length = 5.0;
    for (i, particle) in scene.particles.iter().enumerate() {
        let k = particle.inertia;
        let x = particle.position.to_dvec2().x + length * theta.cos();
        let event = format!("{}.x crosses {x} up", particle.name);
        let found = instants(&scene, &event, 4.0)?;
        let t = found.first().map_or(f64::NAN, Located::time);
        let theory = (2.0 * length * (1.0 + k) / (G * theta.sin())).sqrt();
        let what = ["slider (k = 0)", "solid disc (k = ½)", "ring (k = 1)"][i.min(2)];
        galileo.check(
            report,
            format!("{what}: 5 m in (s)"),
            (t, theory, 1.0),
            1e-9,
        );
    }
    report.tables.push(galileo.table(
        "Galileo's inclined plane: a slider, a disc and a ring down 5 m of a 20° incline",
        "t = √(2 L (1 + k)/(g sin θ)), k = I/(m r²): the slider wins, the ring is last",
    ));
    let mut checks = Checks::new("turning");
    bowled(report, &mut checks)?;
    backspun(report, &mut checks)?;
    bounce(report, &mut checks)?;
    pushed(report, &mut checks)?;
    report.tables.push(checks.table(
        "Rolling and slipping, spin at impacts, a push met by the floor's grip",
        "a bowled disc rolls on at v₀/(1 + k) from t* = v₀ k/((1 + k) μ g), a backspun one at (v₀ − k ω₀ r)/(1 + k) from (v₀ + ω₀ r)/(μ g (1 + 1/k)); a spinning disc on a gripping floor leaves at −ω₀ r/3 with ω₀/3, friction taking m r² ω₀²/6; a disc pushing a ring rolls with it at (m₁ + m₂) gₓ/(m₁(1 + k₁) + m₂(1 + k₂))",
    ));
    Ok(())
}

/// A ball of `mass` and `radius` on a lane of friction `friction` along the x axis (from
/// −1 m), sent from the origin at `(speed, k, spin)`: v₀ along the lane, k = I/(m r²),
/// ω₀ (counter-clockwise). rk4 at 1 ms.
fn on_a_lane(friction: f64, mass: f64, radius: f64, (speed, k, spin): (f64, f64, f64)) -> Scene {
    Scene::new()
        .with_world(world())
        .with_ramp(
            Ramp::new("lane", [-1.0, 0.0], [100.0, 0.0])
                .thickness(0.0)
                .friction(friction),
        )
        .with_particle(
            Particle::new("Ball", mass)
                .radius(radius)
                .position([0.0, radius])
                .velocity([speed, 0.0])
                .turning(k, spin),
        )
        .with_integrator(Integrator::Rk4, 1e-3)
}

fn bowled(report: &mut Report, checks: &mut Checks) -> Outcome {
    let (m, r, v0, mu, k) = (2.0, 0.3, 6.0, 0.2, 0.5);
    let mut simulation = start(&on_a_lane(mu, m, r, (v0, k, 0.0)))?;
    simulation.keep_ledger();
    let about_lane = |s: &Simulation| k * m * r * r * s.spins()[0] - m * r * s.velocities()[0].x;
    let before = about_lane(&simulation);
    step_to(&mut simulation, 2.0)?;
    let (v, t_star) = (v0 / (1.0 + k), v0 * k / ((1.0 + k) * mu * G));
    let x = v0 * t_star - 0.5 * mu * G * t_star * t_star + v * (2.0 - t_star);
    let ledger = simulation
        .ledger()
        .ok_or_else(|| Failure::Simulation("no ledger".to_owned()))?;
    let lost = 0.5 * m * v0 * v0 - 0.5 * m * (1.0 + k) * v * v;
    for (what, simulated, theory, scale, limit) in [
        (
            "bowled: speed rolling (m/s)",
            simulation.velocities()[0].x,
            v,
            v0,
            1e-12,
        ),
        (
            "bowled: x at 2 s (m)",
            simulation.positions()[0].x,
            x,
            x,
            1e-9,
        ),
        (
            "bowled: friction took (J)",
            ledger.friction,
            lost,
            lost,
            1e-9,
        ),
        (
            "bowled: angular momentum about the lane (kg·m²/s)",
            about_lane(&simulation),
            before,
            before.abs(),
            1e-12,
        ),
    ] {
        checks.check(report, what.to_owned(), (simulated, theory, scale), limit);
    }
    Ok(())
}

fn bounce(report: &mut Report, checks: &mut Checks) -> Outcome {
    let (m, r, omega, drop) = (2.0, 0.25, 12.0, 1.0);
    let mut world = world();
    world.restitution = 0.8;
    world.bounds = Some(Bounds {
        min: Vector::cartesian(-10.0, 0.0),
        max: Vector::cartesian(10.0, 10.0),
        friction: 5.0,
        static_friction: None,
    });
    let scene = Scene::new()
        .with_world(world)
        .with_particle(
            Particle::new("Ball", m)
                .radius(r)
                .position([0.0, r + drop])
                .turning(0.5, omega),
        )
        .with_integrator(Integrator::Rk4, 1e-2);
    let mut simulation = start(&scene)?;
    simulation.keep_ledger();
    step_to(&mut simulation, (2.0 * drop / G).sqrt() + 0.01)?;
    let ledger = simulation
        .ledger()
        .ok_or_else(|| Failure::Simulation("no ledger".to_owned()))?;
    let lost = m * r * r * omega * omega / 6.0;
    for (what, simulated, theory, scale) in [
        (
            "spinning bounce: vx after (m/s)",
            simulation.velocities()[0].x,
            -omega * r / 3.0,
            omega * r,
        ),
        (
            "spinning bounce: spin after (rad/s)",
            simulation.spins()[0],
            omega / 3.0,
            omega,
        ),
        (
            "spinning bounce: friction took (J)",
            ledger.friction,
            lost,
            lost,
        ),
    ] {
        checks.check(report, what.to_owned(), (simulated, theory, scale), 1e-12);
    }
    Ok(())
}

/// A ring (k = 1, 1 kg) ahead of a disc (k = ½, 3 kg) touching it on a gripping floor,
/// pulled sideways by gravity's gₓ = 2 m/s²: the disc would roll faster alone, so it
/// pushes the ring through the resting solver, whose pushes the floor's friction meets,
/// and they roll as one roller at a = (m₁ + m₂) gₓ/(m₁(1 + k₁) + m₂(1 + k₂)). After 1 s
/// each moves at a to 1e-5 (the resting solver's settling, 1e-4 of 2 g h a step), and
/// the books close (rk4 integrates the constant forces exactly).
fn pushed(report: &mut Report, checks: &mut Checks) -> Outcome {
    let (g_x, m, k, r) = (2.0, [1.0, 3.0], [1.0, 0.5], 0.2);
    let a = (m[0] + m[1]) * g_x / (m[0] * (1.0 + k[0]) + m[1] * (1.0 + k[1]));
    let mut world = world();
    world.gravity = Vector::cartesian(g_x, -G);
    world.bounds = Some(Bounds {
        min: Vector::cartesian(-5.0, 0.0),
        max: Vector::cartesian(50.0, 5.0),
        friction: 1.0,
        static_friction: None,
    });
    let scene = Scene::new()
        .with_world(world)
        .with_particle(
            Particle::new("Ring", m[0])
                .radius(r)
                .position([r, r])
                .turning(k[0], 0.0),
        )
        .with_particle(
            Particle::new("Disc", m[1])
                .radius(r)
                .position([-r, r])
                .turning(k[1], 0.0),
        )
        .with_integrator(Integrator::Rk4, 1e-3);
    let mut simulation = start(&scene)?;
    simulation.keep_ledger();
    let start_energy = simulation.diagnostics().energy.total();
    step_to(&mut simulation, 1.0)?;
    let ledger = simulation
        .ledger()
        .ok_or_else(|| Failure::Simulation("no ledger".to_owned()))?;
    let energy = simulation.diagnostics().energy;
    let residual = energy.total() + ledger.total() - start_energy;
    let v = simulation.velocities();
    for (what, simulated, theory) in [
        ("pushed: the ring's speed at 1 s (m/s)", v[0].x, a),
        ("pushed: the disc's speed at 1 s (m/s)", v[1].x, a),
    ] {
        checks.check(report, what.to_owned(), (simulated, theory, a), 1e-5);
    }
    checks.check(
        report,
        "pushed: the books' residual over the kinetic energy".to_owned(),
        (residual, 0.0, energy.kinetic),
        1e-9,
    );
    Ok(())
}

/// A second slip-to-roll geometry: a disc (k ½, r 0.2 m) sent at 2 m/s along a floor
/// with μ = 0.3 and a backspin of 30 rad/s. Its contact point slips forward at v₀ + ω₀ r,
/// so friction slows it and unwinds the spin until it rolls, at t* = (v₀ + ω₀ r)/(μ g
/// (1 + 1/k)), on at (v₀ − k ω₀ r)/(1 + k) = −2/3 m/s: it has reversed and rolls back. rk4
/// at 1 ms, the instant located inside its step: the speed to 1e-12, the position at 2 s
/// to 1e-9 m.
fn backspun(report: &mut Report, checks: &mut Checks) -> Outcome {
    let (m, r, v0, spin, mu, k) = (1.5, 0.2, 2.0, 30.0, 0.3, 0.5);
    let mut simulation = start(&on_a_lane(mu, m, r, (v0, k, spin)))?;
    step_to(&mut simulation, 2.0)?;
    let t_star = (v0 + spin * r) / (mu * G * (1.0 + 1.0 / k));
    let v = (v0 - k * spin * r) / (1.0 + k);
    let x = v0 * t_star - 0.5 * mu * G * t_star * t_star + v * (2.0 - t_star);
    checks.check(
        report,
        "backspin: rolls back at (m/s)".to_owned(),
        (simulation.velocities()[0].x, v, v0),
        1e-12,
    );
    checks.check(
        report,
        "backspin: x at 2 s (m)".to_owned(),
        (simulation.positions()[0].x, x, x.abs()),
        1e-9,
    );
    Ok(())
}
