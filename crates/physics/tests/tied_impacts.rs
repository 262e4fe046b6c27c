//! Impacts of particles tied by rods: the surface (or the other particle) and the rods
//! answer together, so what a tied ball carries stops with it — never a ball bouncing
//! alone and pulled back through the wall by its rod.

use physics::{Integrator, Particle, Ramp, Scene, Simulation, Tie, World};

/// A 0.14 kg ball on a 1.5 m rod ahead of a 5,265 kg ball, both moving at 2.2 m/s
/// towards a vertical ramp at x = −4.28 (restitution `e`).
fn heavy_partner(e: f64, method: Integrator) -> Scene {
    let mut wall = Ramp::new("wall", [-4.28, -3.0], [-4.28, 3.0]);
    wall.restitution = e;
    Scene::new()
        .with_world(World::no_forces())
        .with_integrator(method, 1e-3)
        .with_particle(
            Particle::new("A", 0.14)
                .radius(0.1)
                .position([-3.0, 0.0])
                .velocity([-2.2, 0.0]),
        )
        .with_particle(
            Particle::new("B", 5265.0)
                .radius(0.3)
                .position([-1.5, 0.0])
                .velocity([-2.2, 0.0]),
        )
        .with_tie(Tie::rod("rod", "A", "B", 1.5))
        .with_ramp(wall)
}

/// The pair meets the wall as one body of 5,265.14 kg: one impact, of impulse
/// (1 + e) M v, after which both move at −e v; the ball never passes the wall, and the
/// books close (the kinetic energy ½ M v² (1 − e²) booked under impacts, to 1e-9 of it).
#[test]
fn a_ball_tied_to_a_heavy_partner_stops_it_at_the_wall() {
    for method in [Integrator::Rk4, Integrator::Verlet, Integrator::Dopri5] {
        for e in [1.0, 0.5] {
            let scene = heavy_partner(e, method);
            let mut simulation = Simulation::new(&scene).expect("valid");
            simulation.keep_ledger();
            simulation.record_impacts();
            let start = simulation.diagnostics().energy.total();
            let mut nearest = f64::INFINITY;
            for k in 1..=200 {
                simulation.step_to(f64::from(k) * 0.01).expect("runs");
                nearest = nearest.min(simulation.positions()[0].x);
            }
            // The ball's surface reaches the ramp's (the slab is 0.05 m thick each side).
            assert!(
                nearest > -4.28 - 0.05 - 1e-9,
                "{method}, e {e}: the ball reached x = {nearest}"
            );
            let impacts = simulation.take_impacts();
            assert_eq!(impacts.len(), 1, "{method}, e {e}: {impacts:?}");
            let (m, v) = (0.14 + 5265.0, 2.2);
            let impulse = impacts[0].impulse;
            assert!(
                (impulse - (1.0 + e) * m * v).abs() < 1e-9 * m * v,
                "{method}, e {e}: impulse {impulse} against {}",
                (1.0 + e) * m * v
            );
            for u in simulation.velocities() {
                assert!(
                    (u.x - e * v).abs() < 1e-9 * v && u.y.abs() < 1e-12,
                    "{method}, e {e}: {u}"
                );
            }
            let ledger = simulation.ledger().expect("kept");
            let lost = 0.5 * m * v * v * (1.0 - e * e);
            assert!(
                (ledger.impacts - lost).abs() <= 1e-9 * start,
                "{method}, e {e}: {} against {lost}",
                ledger.impacts
            );
            let residual = simulation.diagnostics().energy.total() + ledger.total() - start;
            assert!(
                residual.abs() <= 1e-9 * start,
                "{method}, e {e}: residual {residual}"
            );
        }
    }
}

/// A ball whirled on a rod about a fixed pivot strikes a wall: its one freedom is along
/// the circle, so it comes back along the circle at e times its speed (1e-12), whatever
/// the angle at which the circle meets the wall.
#[test]
fn a_pendulum_striking_a_wall_comes_back_at_e_times_its_speed() {
    for e in [1.0, 0.5, 0.0] {
        let mut wall = Ramp::new("wall", [3.95, -3.0], [3.95, 3.0]);
        wall.restitution = e;
        let scene = Scene::new()
            .with_world(World::no_forces())
            .with_particle(
                Particle::new("ball", 0.25)
                    .radius(0.05)
                    .position([3.0, -1.5])
                    .velocity([6.0, 0.0]),
            )
            .with_tie(Tie::rod("rod", [3.0, 0.0], "ball", 1.5))
            .with_ramp(wall);
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.record_impacts();
        let mut struck = None;
        for k in 1..=300 {
            simulation.step_to(f64::from(k) * 0.001).expect("runs");
            let impacts = simulation.take_impacts();
            if let Some(first) = impacts.first() {
                struck = Some(first.time);
                break;
            }
        }
        let time = struck.expect("it reaches the wall");
        assert!(time > 0.0);
        let speed = simulation.velocities()[0].length();
        // No force acts along the circle: the speed before is the 6 m/s it started with.
        assert!((speed - e * 6.0).abs() < 1e-9 * 6.0, "e {e}: {speed}");
        let p = simulation.positions()[0];
        assert!(p.x + 0.05 <= 3.90 + 1e-9, "e {e}: inside the wall at {p}");
        // Along the circle: no velocity along the rod.
        let along = (p - glam::DVec2::new(3.0, 0.0))
            .normalize()
            .dot(simulation.velocities()[0]);
        assert!(along.abs() < 1e-9, "e {e}: {along}");
    }
}

/// A pendulum that a sideways field presses against a wall of restitution 0 (with
/// friction) stops there and rests: the wall takes what the rod does not (they answer
/// together), and the ball keeps still to 1e-12 m/s and m for 2.5 s. The impact took the
/// kinetic energy the fall gave it, m g Δx, to the method's own error over the swing
/// (rk4 1e-9; Verlet, second order, 1e-5; semi-implicit Euler, first order, 1e-2).
#[test]
fn a_pendulum_pressed_against_a_wall_rests_there() {
    for (method, limit) in [
        (Integrator::Rk4, 1e-9),
        (Integrator::Verlet, 1e-5),
        (Integrator::SemiImplicitEuler, 1e-2),
    ] {
        let mut wall = Ramp::new("wall", [4.0, -3.0], [4.0, 3.0]);
        wall.restitution = 0.0;
        wall.friction = 0.3;
        let scene = Scene::new()
            .with_world(World {
                gravity: physics::Vector::cartesian(9.81, 0.0),
                ..World::no_forces()
            })
            .with_integrator(method, 1e-3)
            .with_particle(
                Particle::new("ball", 0.25)
                    .radius(0.1)
                    .position([3.0, -1.5]),
            )
            .with_tie(Tie::rod("rod", [3.0, 0.0], "ball", 1.5))
            .with_ramp(wall);
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.keep_ledger();
        simulation.step_to(0.5).expect("runs");
        let rest = simulation.positions()[0];
        // The ball's surface on the wall's face (the slab 0.05 m each side of x = 4), to
        // the resting contacts' correction.
        assert!((rest.x - 3.85).abs() < 1e-8, "{method}: {rest}");
        for k in 1..=25 {
            simulation.step_to(0.5 + f64::from(k) * 0.1).expect("runs");
            let (p, u) = (simulation.positions()[0], simulation.velocities()[0]);
            assert!(
                u.length() < 1e-12,
                "{method}: moving at {u} at {}",
                simulation.time()
            );
            assert!(p.distance(rest) < 1e-12, "{method}: moved to {p}");
        }
        let ledger = simulation.ledger().expect("kept");
        let fall = 0.25 * 9.81 * (3.85 - 3.0);
        assert!(
            (ledger.impacts - fall).abs() < limit * fall,
            "{method}: {} against {fall}",
            ledger.impacts
        );
        assert!(
            ledger.friction.abs() < 1e-12,
            "{method}: friction took {}",
            ledger.friction
        );
    }
}
