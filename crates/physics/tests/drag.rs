//! Air resistance against its closed forms: a projectile under linear drag
//! (exponential approach to the terminal velocity), a fall from rest under quadratic drag
//! (tanh and ln cosh), the energy it takes booked by the ledger, and a fixed particle
//! untouched. Masses other than 1 kg, so that a force not divided by the mass shows.

mod common;

use physics::{Integrator, Particle, Scene, Simulation, World};

use common::{relative, start};

const G: f64 = 9.81;

fn projectile(integrator: Integrator, mass: f64, b: f64, c: f64, v0: [f64; 2]) -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(integrator, 1e-3)
        .with_particle(
            Particle::new("Ball", mass)
                .radius(0.1)
                .position([0.0, 100.0])
                .velocity(v0)
                .drag(b, c),
        )
}

/// A 2.5 kg ball thrown at (12, 9) m/s with b = 0.8 kg/s: x(t) = (m v0x/b)(1 − e^(−bt/m)),
/// y(t) = y0 + (m/b)(v0y + m g/b)(1 − e^(−bt/m)) − (m g/b) t. At t = 0.5, 1, …, 3 s under
/// rk4 and dopri5 at 1 ms, x and y to 1e-10 relative and the velocity to 1e-9
/// (rk4's error here is some 1e-13); under pefrl to 1e-8 and verlet
/// to 1e-5 (second order: (b/m · dt)² over the run).
#[test]
fn a_projectile_under_linear_drag_follows_the_exponential() {
    let (m, b) = (2.5, 0.8);
    let (v0x, v0y) = (12.0, 9.0);
    for (integrator, tolerance) in [
        (Integrator::Rk4, 1e-10),
        (Integrator::Dopri5, 1e-10),
        (Integrator::Pefrl, 1e-8),
        (Integrator::Verlet, 1e-5),
    ] {
        let mut simulation = start(&projectile(integrator, m, b, 0.0, [v0x, v0y]));
        for k in 1..=6 {
            let t = 0.5 * f64::from(k);
            simulation.step_to(t).unwrap();
            let decay = 1.0 - (-b * t / m).exp();
            let x = m * v0x / b * decay;
            let y = 100.0 + m / b * (v0y + m * G / b) * decay - m * G / b * t;
            let vx = v0x * (-b * t / m).exp();
            let vy = (v0y + m * G / b) * (-b * t / m).exp() - m * G / b;
            let (p, v) = (simulation.positions()[0], simulation.velocities()[0]);
            assert!(
                relative(p.x, x) < tolerance && relative(p.y, y) < tolerance,
                "{integrator:?} at {t} s: ({}, {}) against ({x}, {y})",
                p.x,
                p.y
            );
            assert!(
                relative(v.x, vx) < 10.0 * tolerance && relative(v.y, vy) < 10.0 * tolerance,
                "{integrator:?} at {t} s: v = {v} against ({vx}, {vy})"
            );
        }
    }
}

/// A 0.7 kg ball dropped from rest with c = 0.02 kg/m falls towards its terminal speed
/// vₜ = √(m g / c) = 18.53 m/s: v(t) = −vₜ tanh(g t / vₜ) and
/// y(t) = y0 − (vₜ²/g) ln cosh(g t / vₜ); under rk4 at 1 ms, at 1, 2, 3, 4 s, both to
/// 1e-9 relative. The ledger books what drag took,
/// m g (y0 − y) − ½ m v², to 1e-9 of the energy at the start, and the residual is
/// below 1e-9 of it.
#[test]
fn a_fall_under_quadratic_drag_follows_the_tanh() {
    let (m, c) = (0.7, 0.02);
    let terminal = (m * G / c).sqrt();
    let mut simulation = start(&projectile(Integrator::Rk4, m, 0.0, c, [0.0, 0.0]));
    simulation.keep_ledger();
    let start_energy = simulation.diagnostics().energy.total();
    for k in 1..=4 {
        let t = f64::from(k);
        simulation.step_to(t).unwrap();
        let v = -terminal * (G * t / terminal).tanh();
        let y = 100.0 - terminal * terminal / G * (G * t / terminal).cosh().ln();
        let (p, u) = (simulation.positions()[0], simulation.velocities()[0]);
        assert!(relative(u.y, v) < 1e-9, "at {t} s: vy {} against {v}", u.y);
        assert!(relative(p.y, y) < 1e-9, "at {t} s: y {} against {y}", p.y);
        assert!(p.x == 0.0 && u.x == 0.0, "straight down");
        let taken = m * G * (100.0 - y) - 0.5 * m * v * v;
        let ledger = simulation.ledger().unwrap();
        assert!(
            (ledger.drag - taken).abs() < 1e-9 * start_energy,
            "at {t} s: drag took {} J, theory {taken} J",
            ledger.drag
        );
        let residual = simulation.diagnostics().energy.total() + ledger.total() - start_energy;
        assert!(
            residual.abs() < 1e-9 * start_energy,
            "residual {residual} J"
        );
        assert_eq!(
            (ledger.damping, ledger.friction, ledger.impacts),
            (0.0, 0.0, 0.0)
        );
    }
}

/// Both laws at once on a thrown ball: the ledger still closes (every integrator's
/// residual within its own accuracy: rk4 1e-9 of E₀), and drag took energy.
#[test]
fn the_ledger_closes_with_both_laws() {
    let mut simulation = start(&projectile(Integrator::Rk4, 1.3, 0.4, 0.05, [15.0, 20.0]));
    simulation.keep_ledger();
    let start_energy = simulation.diagnostics().energy.total();
    simulation.step_to(3.0).unwrap();
    let ledger = simulation.ledger().unwrap();
    let residual = simulation.diagnostics().energy.total() + ledger.total() - start_energy;
    assert!(ledger.drag > 0.1 * start_energy, "{} J", ledger.drag);
    assert!(
        residual.abs() < 1e-9 * start_energy,
        "residual {residual} J"
    );
}

/// A fixed particle with drag stays put, and a scene without the keys means what it
/// meant: the same bits as before drag existed (no drag entry, the same path).
#[test]
fn a_fixed_particle_feels_no_drag_and_old_scenes_are_unchanged() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("Post", 1.0)
                .fixed()
                .drag(1.0, 1.0)
                .velocity([3.0, 0.0]),
        )
        .with_particle(
            Particle::new("Ball", 1.0)
                .position([5.0, 0.0])
                .velocity([1.0, 2.0]),
        );
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.step_to(1.0).unwrap();
    assert_eq!(
        simulation.positions()[0],
        physics::DVec2::ZERO,
        "the post stays"
    );
    let p = simulation.positions()[1];
    assert!((p.x - 6.0).abs() < 1e-12 && (p.y - (2.0 - 0.5 * G)).abs() < 1e-12);
}
