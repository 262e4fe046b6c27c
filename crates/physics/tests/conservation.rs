//! Conservation laws that hold exactly in theory: momentum of an isolated system with
//! only internal (pairwise and spring) forces.

use physics::{DVec2, Integrator, Particle, Scene, Simulation, Spring, World};

fn isolated_system(integrator: Integrator) -> Scene {
    let mut world = World::weightless();
    world.gravitational_constant = 0.05; // strong enough to matter between kg bodies
    let particles = [
        ("A", 1.0, 4e-6, [0.0, 0.0], [0.3, 0.1]),
        ("B", 2.5, -2e-6, [3.0, 0.5], [-0.2, 0.4]),
        ("C", 0.7, 3e-6, [-1.0, 2.5], [0.0, -0.5]),
        ("D", 4.0, 0.0, [1.5, -2.0], [0.1, 0.0]),
        ("E", 1.3, -4e-6, [-2.5, -1.5], [0.25, 0.2]),
    ];
    let mut scene = Scene::new()
        .with_world(world)
        .with_integrator(integrator, 1e-3);
    for (name, mass, charge, position, velocity) in particles {
        scene = scene.with_particle(
            Particle::new(name, mass)
                .radius(0.05)
                .charge(charge)
                .position(position)
                .velocity(velocity),
        );
    }
    scene
        .with_spring(Spring::new("AB", "A", "B", 1.0, 2.5).damping(0.4))
        .with_spring(Spring::new("CD", "C", "D", 0.5, 4.0))
}

/// Every internal force is applied equal and opposite, so Σ m v changes only by rounding:
/// within 1e-12 of Σ m|v| after 10 s (10⁴ steps), for every integrator.
#[test]
fn momentum_of_an_isolated_system_is_conserved_to_rounding() {
    for integrator in physics::Integrator::ALL {
        let mut simulation = Simulation::new(&isolated_system(integrator)).unwrap();
        let start = simulation.diagnostics().momentum;
        let scale: f64 = (0..simulation.len())
            .map(|i| simulation.particle(i, &[]).momentum.length())
            .sum();
        simulation.step_to(10.0).unwrap();
        let drift = (simulation.diagnostics().momentum - start).length();
        assert!(
            drift <= 1e-12 * scale,
            "{integrator}: momentum moved by {drift} (scale {scale})"
        );
        // The system did move: the test is not passing on a frozen scene.
        let moved = simulation.positions()[0].distance(DVec2::ZERO);
        assert!(moved > 0.5, "{integrator}: A moved only {moved} m");
    }
}

/// Without damping or impacts, total energy (kinetic + all potentials) is conserved by
/// the exact motion; rk4 at 1e-3 keeps it within 1e-9 relative over 10 s. This checks
/// that every potential matches its force (a wrong sign or factor would break it).
#[test]
fn energy_matches_the_forces() {
    let mut scene = isolated_system(Integrator::Rk4);
    scene.springs[0].damping = 0.0;
    scene.world.gravity = physics::Vector::cartesian(0.3, -2.0);
    let mut simulation = Simulation::new(&scene).unwrap();
    let start = simulation.diagnostics().energy;
    simulation.step_to(10.0).unwrap();
    let end = simulation.diagnostics().energy;
    let scale = start.kinetic.abs() + start.potential().abs();
    assert!(
        (end.total() - start.total()).abs() < 1e-9 * scale,
        "energy moved from {start:?} to {end:?}"
    );
    for part in [end.uniform, end.spring, end.gravitation, end.electrostatic] {
        assert!(
            part != 0.0,
            "every kind of potential energy takes part: {end:?}"
        );
    }
}

/// The same scene gives the same state, bit for bit.
#[test]
fn runs_are_bit_identical() {
    let run = || {
        let mut simulation = Simulation::new(&isolated_system(Integrator::Dopri5)).unwrap();
        simulation.step_to(3.0).unwrap();
        simulation
            .positions()
            .iter()
            .flat_map(|p| [p.x.to_bits(), p.y.to_bits()])
            .collect::<Vec<_>>()
    };
    assert_eq!(run(), run(), "two runs differ");
}
