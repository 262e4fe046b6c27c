//! Rigid bodies meeting each other: impacts against the closed-form impulse (Newton's law
//! of restitution with the angular terms), located in time; resting on each other
//! without creep; friction between two bodies by the geometric mean of theirs.

use physics::{Body, Bounds, DVec2, Integrator, Scene, Simulation, Vector, World};

const G: f64 = 9.81;

fn weightless() -> World {
    let mut world = World::gravity_only();
    world.gravity = [0.0, 0.0].into();
    world
}

fn with(mut body: Body, restitution: f64, friction: f64) -> Body {
    body.restitution = restitution;
    body.friction = friction;
    body
}

/// Two boxes of unequal mass meet face to face: the smaller restitution of the two
/// (0.5), momentum kept, v₁' = (m₁v₁ + m₂v₂ − m₂e(v₁ − v₂))/(m₁ + m₂), no spin; the
/// instant of impact is gap/(v₁ − v₂), and the rows after it lie on the new lines, under
/// every method (the motion is free but for the impact).
#[test]
fn boxes_meeting_face_to_face_obey_the_law_of_restitution() {
    let (m1, m2, v1, v2, e) = (2.0, 1.0, 3.0, -1.0, 0.5);
    let a = with(Body::rectangle("a", 0.4, 0.2, m1), 0.5, 0.0)
        .position([-1.0, 0.0])
        .moving([v1, 0.0], 0.0);
    let b = with(Body::rectangle("b", 0.2, 0.2, m2), 0.8, 0.0)
        .position([0.5, 0.0])
        .moving([v2, 0.0], 0.0);
    let contact = (0.5 - 0.1 - (-1.0 + 0.2)) / (v1 - v2);
    let after1 = (m1 * v1 + m2 * v2 - m2 * e * (v1 - v2)) / (m1 + m2);
    let after2 = (m1 * v1 + m2 * v2 + m1 * e * (v1 - v2)) / (m1 + m2);
    let t = 0.8;
    for integrator in Integrator::ALL {
        let scene = Scene::new()
            .with_world(weightless())
            .with_integrator(integrator, 1e-3)
            .with_body(a.clone())
            .with_body(b.clone());
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.step_to(t).expect("runs");
        let (ra, rb) = (simulation.body(0), simulation.body(1));
        assert!(
            (ra.velocity.x - after1).abs() < 1e-12,
            "{integrator}: {ra:?}"
        );
        assert!(
            (rb.velocity.x - after2).abs() < 1e-12,
            "{integrator}: {rb:?}"
        );
        assert!(ra.spin.abs() < 1e-12 && rb.spin.abs() < 1e-12);
        // Located to 1e-9 s: the positions then lie on the lines to 1e-9 times the speeds.
        let xa = -1.0 + v1 * contact + after1 * (t - contact);
        let xb = 0.5 + v2 * contact + after2 * (t - contact);
        assert!(
            (ra.position.x - xa).abs() < 1e-9,
            "{integrator}: {}",
            ra.position.x
        );
        assert!(
            (rb.position.x - xb).abs() < 1e-9,
            "{integrator}: {}",
            rb.position.x
        );
    }
}

/// A square turned 45° strikes a standing board off its centre with a corner, 0.3 m
/// above the board's centroid: one point, frictionless, e = 1, so the impulse is
/// `j = −(1 + e) u / (1/mₐ + 1/m_b + (r_b × n)²/I_b)` (the corner's arm is along the
/// normal); momentum, angular momentum and energy are kept.
#[test]
fn an_off_centre_strike_turns_the_board_by_the_angular_impulse() {
    let (ma, mb, (w, h)) = (0.5, 1.0, (0.2, 1.0));
    let ib = mb * (w * w + h * h) / 12.0;
    let a = with(Body::rectangle("a", 0.2, 0.2, ma), 1.0, 0.0)
        .position([-1.0, 0.3])
        .angle(45.0)
        .moving([2.0, 0.0], 0.0);
    let b = with(Body::rectangle("b", w, h, mb), 1.0, 0.0).position([0.0, 0.0]);
    let scene = Scene::new()
        .with_world(weightless())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(a)
        .with_body(b);
    let mut simulation = Simulation::new(&scene).expect("valid");
    let before = simulation.diagnostics();
    simulation.step_to(0.5).expect("runs");
    let (ra, rb) = (simulation.body(0), simulation.body(1));
    let (u, arm) = (-2.0, 0.3);
    let j = -(1.0 + 1.0) * u / (1.0 / ma + 1.0 / mb + arm * arm / ib);
    assert!(
        (ra.velocity - DVec2::new(2.0 - j / ma, 0.0)).length() < 1e-12,
        "{ra:?}"
    );
    assert!(
        (rb.velocity - DVec2::new(j / mb, 0.0)).length() < 1e-12,
        "{rb:?}"
    );
    assert!((rb.spin + arm * j / ib).abs() < 1e-12, "{rb:?}");
    assert!(ra.spin.abs() < 1e-12);
    let after = simulation.diagnostics();
    assert!((after.momentum - before.momentum).length() < 1e-12);
    assert!((after.angular_momentum - before.angular_momentum).abs() < 1e-12);
    assert!((after.energy.kinetic - before.energy.kinetic).abs() < 1e-12);
}

fn floor_box(friction: f64) -> World {
    let mut world = World::gravity_only();
    world.restitution = 0.0;
    world.bounds = Some(Bounds {
        min: Vector::cartesian(-2.0, 0.0),
        max: Vector::cartesian(2.0, 4.0),
        friction,
        static_friction: None,
    });
    world
}

/// A box dropped flat on another with e = 0 comes to rest on it, and the two rest on
/// the floor without creeping or sinking: after 10 s each stands where statics puts it,
/// to 1e-9 m, still; the lower box's free-body diagram is its weight, the floor's
/// (m₁ + m₂) g and the upper box's m₂ g down.
#[test]
fn a_box_dropped_on_a_box_comes_to_rest_on_it() {
    let lower = with(Body::rectangle("lower", 0.6, 0.3, 2.0), 0.0, 0.5).position([0.1, 0.15]);
    let upper = with(Body::rectangle("upper", 0.3, 0.2, 1.0), 0.0, 0.5).position([0.0, 0.9]);
    for integrator in Integrator::ALL {
        let scene = Scene::new()
            .with_world(floor_box(0.5))
            .with_integrator(integrator, 1e-3)
            .with_body(lower.clone())
            .with_body(upper.clone());
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.step_to(10.0).expect("runs");
        let (l, u) = (simulation.body(0), simulation.body(1));
        assert!(
            (l.position - DVec2::new(0.1, 0.15)).length() < 1e-9,
            "{integrator}: {l:?}"
        );
        assert!(
            (u.position - DVec2::new(0.0, 0.4)).length() < 1e-9,
            "{integrator}: {u:?}"
        );
        assert!(
            u.velocity.length() < 1e-9 && u.spin.abs() < 1e-9,
            "{integrator}: {u:?}"
        );
        assert!(l.angle.abs() < 1e-9 && u.angle.abs() < 1e-9, "{integrator}");
        let forces = simulation.body_forces(0);
        let up: f64 = forces
            .iter()
            .filter(|f| f.force.y > 0.0)
            .map(|f| f.force.y)
            .sum();
        let down: f64 = forces
            .iter()
            .filter(|f| f.force.y < 0.0)
            .map(|f| f.force.y)
            .sum();
        assert!((up - 3.0 * G).abs() < 1e-9, "{integrator}: {forces:?}");
        assert!((down + 3.0 * G).abs() < 1e-9, "{integrator}: {forces:?}");
    }
}

/// A block on a fixed wedge (a body): it holds while tan θ < μs and slides with
/// a = g (sin θ − μk cos θ) when it does not, μ the geometric mean of the two bodies'
/// (0.5 × 0.32 → 0.4 and 0.5 × 0.5 → 0.5 static).
#[test]
fn a_block_on_a_wedge_holds_or_slides_with_the_two_frictions() {
    let wedge = |degrees: f64| {
        let slope = degrees.to_radians();
        let (run, rise) = (3.0, 3.0 * slope.tan());
        let mut body = Body::polygon(
            "wedge",
            vec![
                DVec2::new(0.0, 0.0),
                DVec2::new(run, 0.0),
                DVec2::new(run, rise),
            ],
            10.0,
        );
        body.fixed = true;
        body.friction = 0.32;
        body.static_friction = Some(0.5);
        body.position = Vector::cartesian(2.0 * run / 3.0, rise / 3.0);
        body
    };
    for (degrees, slides) in [(25.0_f64, false), (30.0, true)] {
        let slope = degrees.to_radians();
        let (along, normal) = (
            DVec2::new(slope.cos(), slope.sin()),
            DVec2::new(-slope.sin(), slope.cos()),
        );
        // The block's centre 0.1 m above the slope, 2 m along it, turned with it.
        let centre = along * 2.0 + normal * 0.1;
        let mut block = with(Body::rectangle("block", 0.4, 0.2, 1.0), 0.0, 0.5)
            .position([centre.x, centre.y])
            .angle(degrees);
        block.static_friction = Some(0.5);
        let mut world = World::gravity_only();
        world.restitution = 0.0;
        let scene = Scene::new()
            .with_world(world)
            .with_integrator(Integrator::Rk4, 1e-3)
            .with_body(wedge(degrees))
            .with_body(block);
        let mut simulation = Simulation::new(&scene).expect("valid");
        let t = 1.0;
        simulation.step_to(t).expect("runs");
        let b = simulation.body(1);
        let mu = (0.32_f64 * 0.5).sqrt();
        let a = if slides {
            G * (slope.sin() - mu * slope.cos())
        } else {
            0.0
        };
        let expected = centre - along * (0.5 * a * t * t);
        assert!(
            (b.position - expected).length() < 1e-9,
            "{degrees}°: {} against {expected}",
            b.position
        );
        assert!((b.angle - degrees).abs() < 1e-9);
    }
}

/// With `[world] collisions = false` bodies pass through each other, as particles do.
#[test]
fn bodies_pass_through_each_other_without_collisions() {
    let mut world = weightless();
    world.collisions = false;
    let scene = Scene::new()
        .with_world(world)
        .with_body(
            Body::rectangle("a", 0.2, 0.2, 1.0)
                .position([-1.0, 0.0])
                .moving([2.0, 0.0], 0.0),
        )
        .with_body(Body::rectangle("b", 0.2, 0.2, 1.0).position([1.0, 0.0]));
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(2.0).expect("runs");
    assert!((simulation.body(0).position.x - 3.0).abs() < 1e-12);
}

/// Boxes tossed about a closed box with e = 1 and no friction keep their energy: the
/// impulses of simultaneous points, solved together, make none (held to 1e-9 of it).
#[test]
fn elastic_boxes_in_a_box_keep_their_energy() {
    let mut world = floor_box(0.0);
    world.restitution = 1.0;
    world.gravity = [0.0, 0.0].into();
    let mut scene = Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Rk4, 1e-3);
    for k in 0..6 {
        let (col, row) = (f64::from(k % 3), f64::from(k / 3));
        let turn = 17.0 * f64::from(k);
        scene = scene.with_body(
            with(
                Body::rectangle(format!("b{k}"), 0.3, 0.2, 1.0 + 0.3 * f64::from(k)),
                1.0,
                0.0,
            )
            .position([-1.2 + 1.2 * col, 1.0 + 1.5 * row])
            .angle(turn)
            .moving([3.0 - col * 2.0, 1.0 - row * 2.5], 2.0 - f64::from(k)),
        );
    }
    let mut simulation = Simulation::new(&scene).expect("valid");
    let energy = simulation.diagnostics().energy.total();
    simulation.step_to(3.0).expect("runs");
    let after = simulation.diagnostics().energy.total();
    assert!(
        (after - energy).abs() < 1e-9 * energy,
        "{after} against {energy}"
    );
}

/// The lesson's block slides off its incline, tumbles over the ramp's end and comes to
/// rest on the floor, still: its rows must not keep a velocity while it stands.
#[test]
fn a_tumbled_block_comes_to_rest_on_the_floor() {
    let scene = physics::example("lesson-block-slide")
        .expect("an example")
        .scene()
        .expect("valid");
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(3.0).expect("runs");
    let block = simulation.body(0);
    assert!(
        block.velocity.length() < 1e-9 && block.spin.abs() < 1e-9,
        "{block:?}"
    );
    assert!((block.position.y - 0.1).abs() < 1e-9, "{block:?}");
}

/// A state saved while a box falls onto another, and while two blocks close in, continues
/// the straight run bit for bit through the impacts and the resting that follow, under
/// every fixed-step method.
#[test]
fn bodies_meeting_continue_from_a_saved_state_bit_for_bit() {
    for (name, saved_at) in [("stacked-boxes", 0.3), ("colliding-blocks", 0.25)] {
        for integrator in Integrator::ALL {
            if integrator == Integrator::Dopri5 {
                continue;
            }
            let mut scene = physics::example(name)
                .expect("an example")
                .scene()
                .expect("valid");
            scene.simulation.integrator = integrator;
            let mut straight = Simulation::new(&scene).expect("valid");
            straight.step_to(saved_at).expect("runs");
            let saved = Scene::from_toml(&straight.saved_state(&scene).to_toml()).expect("reads");
            let mut continued = Simulation::new(&saved).expect("valid");
            straight.step_to(2.0).expect("runs");
            continued.step_to(2.0).expect("runs");
            for i in 0..2 {
                let (a, b) = (straight.body(i), continued.body(i));
                assert_eq!(a.position, b.position, "{name}, {integrator}");
                assert_eq!(a.velocity, b.velocity, "{name}, {integrator}");
                assert_eq!(a.angle.to_bits(), b.angle.to_bits(), "{name}, {integrator}");
            }
        }
    }
}
