//! Pins, hinges and motors against theory: the physical pendulum's period (the small-
//! amplitude formula and the elliptic integral), a seesaw balanced by m₁d₁ = m₂d₂ and one
//! that is not, the pin's reaction, and a motor's spin-up and the work it books.

use physics::{Body, Integrator, Joint, Motor, Scene, Simulation, World};

use crate::events::instants;
use crate::experiments::{Outcome, start, step_to};
use crate::report::{Checks, Report};
use crate::theory::elliptic_k;

const G: f64 = 9.81;

/// A uniform rod `length` m long, `thickness` m thick, 0.5 kg, on a pin at its left end
/// (the origin), turned `amplitude` degrees from hanging straight down, at rest.
fn ruler(length: f64, thickness: f64, amplitude: f64, integrator: Integrator) -> Scene {
    let down = (amplitude - 90.0).to_radians();
    let centre = [0.5 * length * down.cos(), 0.5 * length * down.sin()];
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(integrator, 1e-3)
        .with_body(
            Body::rectangle("ruler", length, thickness, 0.5)
                .position(centre)
                .angle(amplitude - 90.0),
        )
        .with_joint(Joint::pin("nail", "ruler", [0.0, 0.0]))
}

/// The period of a body of `inertia` about its pin (kg·m²), `mass` kg with its centroid
/// `d` m from the pin, released at rest `amplitude` radians from hanging: 4 √(I/(m g d))
/// K(sin(θ₀/2)).
fn physical_period(inertia: f64, mass: f64, d: f64, amplitude: f64) -> f64 {
    4.0 * (inertia / (mass * G * d)).sqrt() * elliptic_k((0.5 * amplitude).sin())
}

/// Seconds between the ruler's first two turning points (its spin crossing 0 downwards),
/// each located inside its step.
fn measured_period(scene: &Scene, until: f64) -> Result<f64, crate::Failure> {
    let turns = instants(scene, "ruler.spin crosses 0 down", until)?;
    match turns.as_slice() {
        [first, second, ..] => Ok(second.time() - first.time()),
        _ => Err(crate::Failure::Simulation(
            "the ruler did not swing twice".to_owned(),
        )),
    }
}

/// A 2.4 m, 1 kg board on a pin at its middle, with a block of `left` kg hung from a
/// hinge 0.5 m to the left and one of `right` kg 1 m to the right.
fn seesaw(left: f64, right: f64) -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(Body::rectangle("board", 2.4, 0.05, 1.0).position([0.0, 1.0]))
        .with_body(Body::rectangle("heavy", 0.1, 0.2, left).position([-0.5, 0.8]))
        .with_body(Body::rectangle("light", 0.1, 0.2, right).position([1.0, 0.8]))
        .with_joint(Joint::pin("pivot", "board", [0.0, 1.0]))
        .with_joint(Joint::hinge("left", "board", "heavy", [-0.5, 1.0]))
        .with_joint(Joint::hinge("right", "board", "light", [1.0, 1.0]))
}

/// The checks, each with its tolerance and why:
/// - a thin ruler (1 m × 0.1 mm) swinging 0.5°: T = 2π √(2L/3g) to 1e-5 relative, the
///   formula's own neglect (θ₀²/16 = 5e-6 of the period, and (h/L)² of the inertia);
/// - the same ruler, and a 2 cm thick one released at 90° and 150°: the period 4 √(I/(m g
///   d)) K(sin(θ₀/2)) with the box's exact inertia, to 1e-9 s (rk4's error over a period
///   at 1 ms is some 1e-12 s; each turning point is located to 1e-12 s);
/// - the balanced seesaw (2 kg at 0.5 m, 1 kg at 1 m) still after 10 s to 1e-9 rad, and
///   its pin's reaction the whole weight to 1e-12 relative (both exact in the arithmetic:
///   the torques cancel to rounding);
/// - the unbalanced seesaw (1.2 kg at 1 m): its starting angular acceleration τ/I with I
///   the board's plus m d² of each block (the blocks hang from their hinges and start
///   without turning), read as ω(t)/t at t = 0.1 ms, to 1e-6 relative (ω = α₀ t +
///   O(t³), the correction some 1e-8 here);
/// - a 3 kg box 0.4 m square on a pin at its centroid under a motor of 2 N·m: ω = τ t/I
///   after 1 s to 1e-12 relative, the ledger's motor work τθ equal to its kinetic energy
///   ½ I ω² to 1e-12 relative (a constant acceleration: every method is exact to
///   rounding);
/// - a board under a motor of target spin 5 rad/s and at most 0.5 N·m: the instant it
///   reaches the target, I ω/τ, to 1e-9 s, and the spin held there to 1e-12 after 1 s;
/// - the ruler released at 90° onto a limit at the bottom: it arrives at a quarter of the
///   elliptic period (to 1e-9 s: the event 1e-7° before the limit is 3e-10 s early), the
///   stop takes the energy fallen, m g d (to 1e-9 relative: the kinetic energy it removes
///   carries rk4's energy error over the fall, some 1e-11), and the pin then bears the
///   weight.
pub(crate) fn joints(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("joints");
    let mut row = |report: &mut Report, what: &str, simulated: f64, theory: f64, scale, limit| {
        checks.check(report, what.to_owned(), (simulated, theory, scale), limit);
    };
    let (mass, length) = (0.5, 1.0);
    let thin = ruler(length, 1e-4, 0.5, Integrator::Rk4);
    let small = measured_period(&thin, 5.0)?;
    let formula = 2.0 * std::f64::consts::PI * (2.0 * length / (3.0 * G)).sqrt();
    row(
        report,
        "thin ruler 1 m at 0.5°: period (s), 2π√(2L/3g)",
        small,
        formula,
        formula,
        1e-5,
    );
    for (thickness, amplitude) in [(1e-4, 0.5_f64), (0.02, 90.0), (0.02, 150.0)] {
        let scene = ruler(length, thickness, amplitude, Integrator::Rk4);
        let inertia = scene.bodies[0].inertia() + mass * 0.25 * length * length;
        let theory = physical_period(inertia, mass, 0.5 * length, amplitude.to_radians());
        let simulated = measured_period(&scene, 3.0 * theory)?;
        row(
            report,
            &format!(
                "ruler 1 m × {} cm at {amplitude}°: period (s), 4√(I/mgd) K",
                thickness * 100.0
            ),
            simulated,
            theory,
            1.0,
            1e-9,
        );
    }
    let balanced = seesaw(2.0, 1.0);
    let mut simulation = start(&balanced)?;
    step_to(&mut simulation, 10.0)?;
    row(
        report,
        "seesaw 2 kg × 0.5 m = 1 kg × 1 m: board's angle after 10 s (rad)",
        simulation.body(0).angle.to_radians(),
        0.0,
        1.0,
        1e-9,
    );
    let weight = (1.0 + 2.0 + 1.0) * G;
    row(
        report,
        "balanced seesaw: the pin's reaction (N), the whole weight",
        simulation.joint(0).force.y,
        weight,
        weight,
        1e-12,
    );
    let unbalanced = seesaw(2.0, 1.2);
    let torque = (2.0 * 0.5 - 1.2 * 1.0) * G;
    let inertia = unbalanced.bodies[0].inertia() + 2.0 * 0.25 + 1.2 * 1.0;
    let mut simulation = start(&unbalanced)?;
    let t = 1e-4;
    step_to(&mut simulation, t)?;
    row(
        report,
        "seesaw 1.2 kg × 1 m: starting α = τ/I (rad/s²)",
        simulation.body(0).spin / t,
        torque / inertia,
        (torque / inertia).abs(),
        1e-6,
    );
    motors(report, &mut row)?;
    limits(report, &mut row)?;
    pulleys(report, &mut row)?;
    report.tables.push(checks.table(
        "Joints: pins, hinges and motors",
        "a physical pendulum's period 2π√(2L/3g) and 4√(I/mgd) K(sin(θ₀/2)); a seesaw balanced by m₁d₁ = m₂d₂, its pin bearing the whole weight, and one turning at α = τ/I; a motor's ω = τt/I and work τθ = ½Iω², a target spin reached at Iω/τ and held; a limit stopping a swing dead, taking m g d; Atwood machines a = (m₁ − m₂)g/(m₁ + m₂ + I/r²), T = 2m₁m₂g/(m₁ + m₂) over a massless wheel",
    ));
    Ok(())
}

/// The motors' checks of [`joints`].
fn motors(
    report: &mut Report,
    row: &mut impl FnMut(&mut Report, &str, f64, f64, f64, f64),
) -> Outcome {
    let wheel = Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(Body::rectangle("wheel", 0.4, 0.4, 3.0).position([0.0, 1.0]))
        .with_joint(Joint::pin("axle", "wheel", [0.0, 1.0]).motor(Motor::Torque(2.0)));
    let inertia = wheel.bodies[0].inertia();
    let mut simulation =
        Simulation::new(&wheel).map_err(|e| crate::Failure::Input(e.to_string()))?;
    simulation.keep_ledger();
    step_to(&mut simulation, 1.0)?;
    let spin = simulation.body(0).spin;
    let theory = 2.0 * 1.0 / inertia;
    row(
        report,
        "motor 2 N·m on a 3 kg box: ω after 1 s (rad/s)",
        spin,
        theory,
        theory,
        1e-12,
    );
    let work = simulation.ledger().map_or(f64::NAN, |l| l.motors);
    let kinetic = 0.5 * inertia * spin * spin;
    row(
        report,
        "the ledger's motor work τθ (J) = ½Iω²",
        work,
        kinetic,
        kinetic,
        1e-12,
    );
    let fan = Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(Body::rectangle("fan", 0.6, 0.1, 1.0).position([0.0, 1.0]))
        .with_joint(Joint::pin("drive", "fan", [0.0, 1.0]).motor(Motor::Spin {
            spin: 5.0,
            max_torque: 0.5,
        }));
    let inertia = fan.bodies[0].inertia();
    let reached = instants(&fan, "fan.spin crosses 4.999999 up", 1.0)?;
    let theory = 4.999_999 * inertia / 0.5;
    row(
        report,
        "motor to 5 rad/s at most 0.5 N·m: spin 4.999999 rad/s at Iω/τ (s)",
        reached.first().map_or(f64::NAN, physics::Located::time),
        theory,
        1.0,
        1e-9,
    );
    let mut simulation = start(&fan)?;
    step_to(&mut simulation, 1.0)?;
    row(
        report,
        "the same after 1 s: the spin held (rad/s)",
        simulation.body(0).spin,
        5.0,
        5.0,
        1e-12,
    );
    Ok(())
}

/// The limit's checks of [`joints`]: the ruler from 90° onto a limit at the bottom.
fn limits(
    report: &mut Report,
    row: &mut impl FnMut(&mut Report, &str, f64, f64, f64, f64),
) -> Outcome {
    let mut stopped = ruler(1.0, 0.02, 90.0, Integrator::Rk4);
    stopped.joints[0] = stopped.joints[0].clone().limits(-90.0, 0.0);
    // The 0.5 kg, 1 m ruler about its end: I + m (L/2)², its centroid 0.5 m away.
    let inertia = stopped.bodies[0].inertia() + 0.5 * 0.25;
    let quarter = physical_period(inertia, 0.5, 0.5, std::f64::consts::FRAC_PI_2) / 4.0;
    let bottom = instants(&stopped, "nail.angle crosses -89.9999999 down", 1.0)?;
    row(
        report,
        "ruler from 90° onto a limit at the bottom: the stop's instant (s), T/4",
        bottom.first().map_or(f64::NAN, physics::Located::time),
        quarter,
        1.0,
        1e-9,
    );
    let mut simulation = start(&stopped)?;
    simulation.keep_ledger();
    step_to(&mut simulation, 2.0)?;
    let fallen = 0.5 * G * 0.5;
    row(
        report,
        "the limit's stop takes the energy fallen, m g d (J)",
        simulation.ledger().map_or(f64::NAN, |l| l.impacts),
        fallen,
        fallen,
        1e-9,
    );
    row(
        report,
        "resting on the limit: the pin bears the weight (N)",
        simulation.joint(0).force.y,
        0.5 * G,
        0.5 * G,
        1e-12,
    );
    Ok(())
}

/// An Atwood machine: blocks of 3 and 2 kg hanging straight down from a wheel of radius
/// 0.2 m at (0, 3) m, of `wheel` kg (a disc).
fn atwood(wheel: f64) -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(Body::rectangle("heavy", 0.2, 0.3, 3.0).position([-0.2, 0.0]))
        .with_body(Body::rectangle("light", 0.2, 0.2, 2.0).position([0.2, 0.0]))
        .with_joint(Joint::pulley(
            "wheel",
            ("heavy", "light"),
            [0.0, 3.0],
            0.2,
            wheel,
        ))
}

/// The pulleys' checks of [`joints`], each after 1 s (the blocks rise 1 m of the 2.7 m
/// they have): over a massless wheel the heavy block's velocity −(m₁ − m₂) g t/(m₁ + m₂)
/// and the tension 2 m₁ m₂ g/(m₁ + m₂) on both sides; over a 2 kg disc (I/r² = 1 kg) the
/// velocity −(m₁ − m₂) g t/(m₁ + m₂ + I/r²), the wheel turning with the string (a t/r,
/// counter-clockwise as the heavy side, on the left, falls) and the two sides' tensions
/// differing by (I/r²) a, what turns the wheel. The accelerations are constant: rk4 is exact to
/// rounding, so 1e-12 relative.
fn pulleys(
    report: &mut Report,
    row: &mut impl FnMut(&mut Report, &str, f64, f64, f64, f64),
) -> Outcome {
    let (m1, m2, t) = (3.0, 2.0, 1.0);
    for (wheel, extra) in [(0.0, 0.0), (2.0, 1.0)] {
        let mut simulation = start(&atwood(wheel))?;
        step_to(&mut simulation, t)?;
        let a = (m1 - m2) * G / (m1 + m2 + extra);
        row(
            report,
            &format!(
                "Atwood 3 kg and 2 kg over a {wheel} kg wheel: the heavy block's vy after 1 s (m/s)"
            ),
            simulation.body(0).velocity.y,
            -a * t,
            a * t,
            1e-12,
        );
        let [tension_a, tension_b] = simulation.joint(0).tensions;
        if wheel == 0.0 {
            let tension = 2.0 * m1 * m2 * G / (m1 + m2);
            row(
                report,
                "the string's tension (N), 2m₁m₂g/(m₁ + m₂), on the heavy side",
                tension_a,
                tension,
                tension,
                1e-12,
            );
            row(
                report,
                "and on the light side",
                tension_b,
                tension,
                tension,
                1e-12,
            );
        } else {
            row(
                report,
                "the wheel's spin (rad/s), a t / r, counter-clockwise as the heavy side falls",
                simulation.joint(0).wheel_spin,
                a * t / 0.2,
                a * t / 0.2,
                1e-12,
            );
            row(
                report,
                "the two sides' tensions differ by (I/r²) a (N), turning the wheel",
                tension_a - tension_b,
                extra * a,
                extra * a,
                1e-12,
            );
        }
    }
    Ok(())
}
