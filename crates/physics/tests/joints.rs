//! Pins and hinges: the scene format, bad input, the joints held, the methods' periods,
//! and continuation from a saved state.

use physics::{Body, Integrator, Joint, Motor, Scene, Simulation, World};

const G: f64 = 9.81;

/// A 1 m × 2 cm ruler of 0.5 kg on a nail at its left end (the origin), released at rest
/// `amplitude` degrees from hanging.
fn ruler(amplitude: f64, integrator: Integrator) -> Scene {
    let down = (amplitude - 90.0).to_radians();
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(integrator, 1e-3)
        .with_body(
            Body::rectangle("ruler", 1.0, 0.02, 0.5)
                .position([0.5 * down.cos(), 0.5 * down.sin()])
                .angle(amplitude - 90.0),
        )
        .with_joint(Joint::pin("nail", "ruler", [0.0, 0.0]))
}

/// K(k) by the arithmetic–geometric mean, written apart from the library's.
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..40 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

/// Where the ruler's end on the nail is in the world.
fn nail_end(simulation: &Simulation) -> glam::DVec2 {
    let b = simulation.body(0);
    b.position - glam::DVec2::from_angle(b.angle.to_radians()) * 0.5
}

const TOML: &str = r#"
version = 1
[[body]]
name = "board"
shape = "box"
width = 2.0
height = 0.1
mass = 1.0
position = [0.0, 1.0]
[[body]]
name = "weight"
shape = "box"
width = 0.1
height = 0.1
mass = 0.5
position = [0.8, 0.7]
[[pin]]
name = "pivot"
body = "board"
at = [0.0, 1.0]
motor = { spin = 1.5, max_torque = 20.0 }
[[hinge]]
name = "hook"
a = "board"
b = "weight"
at = [0.8, 1.0]
"#;

/// A pin with a motor and a hinge read from a file, written back and read again, are
/// the same; the columns are the pin's angle and force, then the hinge's angle, after the
/// bodies'.
#[test]
fn joints_round_trip_and_give_their_columns() {
    let scene = Scene::from_toml(TOML).expect("valid");
    assert_eq!(scene.joints.len(), 2);
    assert_eq!(
        scene.joints[0].motor,
        Some(Motor::Spin {
            spin: 1.5,
            max_torque: 20.0
        })
    );
    assert_eq!(scene.joints[1].other(), Some("board"));
    let again = Scene::from_toml(&scene.to_toml()).expect("reads back");
    assert_eq!(again, scene);
    let json = Scene::from_json(&scene.to_json()).expect("reads back");
    assert_eq!(json, scene);
    let simulation = Simulation::new(&scene).expect("valid");
    let columns = simulation.csv_columns();
    let after = columns
        .iter()
        .position(|c| c == "weight.spin")
        .expect("the bodies' columns");
    assert_eq!(
        columns[after + 1..after + 5],
        [
            "pivot.angle",
            "pivot.force_x",
            "pivot.force_y",
            "hook.angle"
        ]
    );
}

/// Every joint that cannot be is refused with its place and a reason, never a panic.
#[test]
fn bad_joints_are_refused_in_words() {
    let particle = "\n[[particle]]\nname = \"ball\"\nmass = 1.0\n";
    for (change, words) in [
        ("body = \"board\"", "body = \"nothing\""),
        ("body = \"board\"", "body = \"ball\""),
        ("b = \"weight\"", "b = \"board\""),
        (
            "motor = { spin = 1.5, max_torque = 20.0 }",
            "motor = { spin = 1.5 }",
        ),
        (
            "motor = { spin = 1.5, max_torque = 20.0 }",
            "motor = { torque = inf }",
        ),
        (
            "motor = { spin = 1.5, max_torque = 20.0 }",
            "motor = { spin = 1.5, max_torque = -1.0 }",
        ),
        ("at = [0.0, 1.0]", "at = [0.0, 1.0]\nanchor = [0.5, 0.0]"),
        ("at = [0.8, 1.0]", "at = [0.8, 1.0]\ncolour = 3"),
    ] {
        let text = TOML.replacen(change, words, 1) + particle;
        let error = Scene::from_toml(&text).expect_err(words);
        let problem = &error.problems[0];
        assert!(problem.line.is_some(), "{words}: {problem}");
        assert!(
            problem.message.contains("pin 'pivot'") || problem.message.contains("hinge 'hook'"),
            "{words}: {problem}"
        );
    }
    let fixed = TOML.replacen("mass = 1.0\n", "mass = 1.0\nfixed = true\n", 1);
    let error = Scene::from_toml(&fixed).expect_err("a pin on a fixed board holds nothing");
    assert!(error.to_string().contains("pin 'pivot'"), "{error}");
    let hinged = fixed.replacen("motor = { spin = 1.5, max_torque = 20.0 }", "", 1);
    let hinged = hinged.replacen(
        "[[pin]]\nname = \"pivot\"\nbody = \"board\"\nat = [0.0, 1.0]\n",
        "",
        1,
    );
    assert!(
        Scene::from_toml(&hinged).is_ok(),
        "a weight hinged to a fixed board hangs from it, lawfully"
    );
    let both = TOML
        .replace("mass = 1.0\n", "mass = 1.0\nfixed = true\n")
        .replace("mass = 0.5\n", "mass = 0.5\nfixed = true\n");
    let error = Scene::from_toml(&both).expect_err("nothing moves");
    assert!(
        error.to_string().contains("nothing that can move"),
        "{error}"
    );
}

/// The nail's end of the ruler stays on the nail to 1e-12 m through ten seconds of a
/// 150° swing, under every method; the period under each is the elliptic integral's
/// within what its order allows at 1 ms (rk4, pefrl and dopri5 1e-8 s; verlet 1e-5 s).
/// The first-order methods gain energy at each pass through the bottom (semi-implicit
/// euler too: its symplectic property is lost to the joint's projection), so near 150°,
/// where the period grows fast with the amplitude, their period is far off at 1 ms; that
/// semi-implicit euler's error halves with the step is checked instead, and euler's pin
/// only.
#[test]
fn the_pin_holds_and_each_method_swings_at_its_order() {
    let amplitude = 150.0_f64;
    let inertia = 0.5 * (1.0 + 0.0004) / 12.0 + 0.5 * 0.25;
    let period =
        4.0 * (inertia / (0.5 * G * 0.5)).sqrt() * elliptic_k((amplitude.to_radians() / 2.0).sin());
    for (integrator, tolerance) in [
        (Integrator::Euler, f64::INFINITY),
        (Integrator::SemiImplicitEuler, f64::INFINITY),
        (Integrator::Verlet, 1e-5),
        (Integrator::Rk4, 1e-8),
        (Integrator::Pefrl, 1e-8),
        (Integrator::Dopri5, 1e-8),
    ] {
        let scene = ruler(amplitude, integrator);
        let event = physics::Event::parse("ruler.spin crosses 0 down").expect("parses");
        let mut simulation = Simulation::new(&scene).expect("valid");
        let mut watch = physics::Watch::new(&[event], &simulation).expect("watches");
        let turns = simulation.step_to_watching(10.0, &mut watch).expect("runs");
        if tolerance.is_finite() {
            let measured = turns[1].time() - turns[0].time();
            assert!(
                (measured - period).abs() < tolerance,
                "{integrator}: period {measured} against {period}"
            );
        }
        assert!(
            nail_end(&simulation).length() < 1e-12,
            "{integrator}: the nail's end is {} from the nail",
            nail_end(&simulation)
        );
    }
    let error = |h: f64| {
        let mut scene = ruler(amplitude, Integrator::SemiImplicitEuler);
        scene.simulation.time_step = h;
        let event = physics::Event::parse("ruler.spin crosses 0 down").expect("parses");
        let mut simulation = Simulation::new(&scene).expect("valid");
        let mut watch = physics::Watch::new(&[event], &simulation).expect("watches");
        let turns = simulation.step_to_watching(4.0, &mut watch).expect("runs");
        turns[0].time() - period
    };
    let ratio = error(2e-4) / error(1e-4);
    assert!(
        (1.7..2.3).contains(&ratio),
        "halving the step: ratio {ratio}"
    );
}

/// The joint's reaction on a hanging ruler swinging through its lowest point is its
/// weight plus the centripetal force m ω² d, ω from the energy it fell by (to 1e-9 of
/// it), and along the ruler.
#[test]
fn the_reaction_at_the_bottom_is_weight_plus_centripetal() {
    let scene = ruler(90.0, Integrator::Rk4);
    let event = physics::Event::parse("nail.angle crosses -90").expect("parses");
    let mut simulation = Simulation::new(&scene).expect("valid");
    let mut watch = physics::Watch::new(&[event], &simulation).expect("watches");
    let bottom = simulation.step_to_watching(1.0, &mut watch).expect("runs");
    let state = &bottom[0].at;
    let joint = state.joint(0);
    let inertia = 0.5 * (1.0 + 0.0004) / 12.0 + 0.5 * 0.25;
    let omega_squared = 2.0 * 0.5 * G * 0.5 / inertia;
    let expected = 0.5 * G + 0.5 * omega_squared * 0.5;
    assert!(
        (joint.force.y - expected).abs() < 1e-9 * expected,
        "{} against {expected}",
        joint.force.y
    );
    assert!(joint.force.x.abs() < 1e-9, "{}", joint.force.x);
}

/// A state saved mid-swing, while a motor spins up towards its target, and while a
/// seesaw tilts towards its limit (which it meets after the save), continues the
/// straight run bit for bit under every fixed-step method.
#[test]
fn joints_continue_from_a_saved_state_bit_for_bit() {
    for integrator in Integrator::ALL {
        if integrator == Integrator::Dopri5 {
            continue;
        }
        let mut scene = Scene::from_toml(TOML).expect("valid");
        scene.simulation.integrator = integrator;
        let mut seesaw = physics::example("seesaw")
            .expect("an example")
            .scene()
            .expect("valid");
        seesaw.simulation.integrator = integrator;
        for scene in [scene, ruler(120.0, integrator), seesaw] {
            let mut straight = Simulation::new(&scene).expect("valid");
            straight.step_to(0.37).expect("runs");
            let saved = Scene::from_toml(&straight.saved_state(&scene).to_toml()).expect("reads");
            let mut continued = Simulation::new(&saved).expect("valid");
            straight.step_to(2.0).expect("runs");
            continued.step_to(2.0).expect("runs");
            for i in 0..scene.bodies.len() {
                let (a, b) = (straight.body(i), continued.body(i));
                assert_eq!(a.position, b.position, "{integrator}");
                assert_eq!(a.velocity, b.velocity, "{integrator}");
                assert_eq!(a.angle.to_bits(), b.angle.to_bits(), "{integrator}");
            }
            let (a, b) = (straight.joint(0), continued.joint(0));
            assert_eq!(a.angle.to_bits(), b.angle.to_bits(), "{integrator}");
            assert_eq!(a.force, b.force, "{integrator}");
        }
    }
}

/// The motor of the file's seesaw drives it to its target spin, and a hinge's weight
/// hangs from its hook: the hook stays on the board to 1e-12 m.
#[test]
fn a_hinge_holds_while_a_motor_turns_its_board() {
    let scene = Scene::from_toml(TOML).expect("valid");
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(3.0).expect("runs");
    let board = simulation.body(0);
    let weight = simulation.body(1);
    let hook = simulation.joint(1).at;
    let on_board = board.position + glam::DVec2::from_angle(board.angle.to_radians()) * 0.8;
    assert!(
        (hook - on_board).length() < 1e-12,
        "{hook} against {on_board}"
    );
    assert!((weight.position - hook).length() - 0.3 < 1e-12);
    assert!((board.spin - 1.5).abs() < 1e-12, "held at {}", board.spin);
}

/// A limit stops a swing dead where the joint's angle reaches it, the stop located in the
/// step (the ruler from 90° onto a limit at the bottom arrives at a quarter of the
/// elliptic period), the ledger booking the kinetic energy it took (the energy fallen,
/// m g d, to rk4's error over the fall) with the books closing, and the ruler resting on it
/// after; limits that are no range, or that do not hold the start, are refused.
#[test]
fn a_limit_stops_the_joint_dead_and_books_the_energy() {
    for integrator in [Integrator::Rk4, Integrator::Verlet, Integrator::Dopri5] {
        let mut scene = ruler(90.0, integrator);
        scene.joints[0] = scene.joints[0].clone().limits(-90.0, 0.0);
        let text = scene.to_toml();
        assert!(text.contains("limits = [-90.0, 0.0]"), "{text}");
        assert_eq!(Scene::from_toml(&text).expect("reads back"), scene);
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.keep_ledger();
        let start = simulation.diagnostics().energy.total();
        simulation.step_to(2.0).expect("runs");
        let joint = simulation.joint(0);
        assert!(
            (joint.angle + 90.0).abs() < 1e-9,
            "{integrator}: {}",
            joint.angle
        );
        assert!(simulation.body(0).spin.abs() < 1e-12, "{integrator}");
        assert!((joint.force.y - 0.5 * G).abs() < 1e-9, "{integrator}");
        let ledger = simulation.ledger().expect("kept");
        let fallen = 0.5 * G * 0.5;
        // Verlet's energy error at 1 ms is of order (ω h)², some 3e-5.
        let tolerance = if integrator == Integrator::Verlet {
            1e-4
        } else {
            1e-9
        };
        assert!(
            (ledger.impacts - fallen).abs() < tolerance * fallen,
            "{integrator}: {} against {fallen}",
            ledger.impacts
        );
        let residual = simulation.diagnostics().energy.total() + ledger.total() - start;
        assert!(
            residual.abs() < tolerance * fallen,
            "{integrator}: residual {residual}"
        );
    }
    for (limits, words) in [
        ("limits = [10.0, -10.0]", "lower below the upper"),
        ("limits = [5.0, 10.0]", "outside its limits"),
        ("limits = [1.0]", "[lower, upper]"),
    ] {
        let text = TOML.replacen("at = [0.0, 1.0]", &format!("at = [0.0, 1.0]\n{limits}"), 1);
        let error = Scene::from_toml(&text).expect_err(limits);
        assert!(error.to_string().contains(words), "{limits}: {error}");
        assert!(error.problems[0].line.is_some(), "{limits}: {error}");
    }
}

/// The length of a string from `a` up over a wheel (`centre`, `radius`) and down to `b`,
/// written apart from the library: the two tangent runs and the arc between the points
/// where they leave the wheel, the arc over the top.
fn string_length(centre: glam::DVec2, radius: f64, a: glam::DVec2, b: glam::DVec2) -> f64 {
    let leave = |p: glam::DVec2, turn: f64| {
        let d = p - centre;
        let run = (d.length_squared() - radius * radius).sqrt();
        // The tangent point is the direction to p turned by the angle whose cosine is r/|d|.
        let angle = d.y.atan2(d.x) + turn * (radius / d.length()).acos();
        (angle, run)
    };
    let (angle_a, run_a) = leave(a, -1.0);
    let (angle_b, run_b) = leave(b, 1.0);
    let arc = (angle_a - angle_b).rem_euclid(std::f64::consts::TAU) * radius;
    run_a + run_b + arc
}

const ATWOOD: &str = r#"
version = 1
[simulation]
time_step = 0.001
[[body]]
name = "swinging"
shape = "box"
width = 0.2
height = 0.2
mass = 3.0
position = [-0.8, 0.5]
[[body]]
name = "hanging"
shape = "box"
width = 0.2
height = 0.2
mass = 2.0
position = [0.3, 0.0]
[[pulley]]
name = "wheel"
a = "swinging"
b = "hanging"
position = [0.0, 3.0]
radius = 0.3
mass = 1.5
"#;

/// A block swinging on one side of a heavy pulley (released at rest off the vertical
/// below where its string leaves the wheel) while the other rises and falls: the
/// string keeps its length (a closed form of its geometry, to 1e-12 m), the books close
/// with the wheel's kinetic energy in them (to 1e-9 J), the file reads back, and a saved
/// state (the wheel's spin and the string's length in it) continues bit for bit.
#[test]
fn a_pulley_holds_its_string_and_continues_bit_for_bit() {
    let scene = Scene::from_toml(ATWOOD).expect("valid");
    assert_eq!(Scene::from_toml(&scene.to_toml()).expect("reads"), scene);
    let start = |s: &Simulation| (s.body(0).position, s.body(1).position);
    let centre = glam::DVec2::new(0.0, 3.0);
    let mut simulation = Simulation::new(&scene).expect("valid");
    let (a, b) = start(&simulation);
    let length = string_length(centre, 0.3, a, b);
    simulation.keep_ledger();
    let energy = simulation.diagnostics().energy.total();
    simulation.step_to(1.2).expect("runs");
    let (a, b) = start(&simulation);
    let now = string_length(centre, 0.3, a, b);
    assert!((now - length).abs() < 1e-12, "{now} against {length}");
    let residual = simulation.diagnostics().energy.total()
        + simulation.ledger().expect("kept").total()
        - energy;
    assert!(residual.abs() < 1e-9, "residual {residual}");
    let columns = simulation.csv_columns();
    assert!(columns.ends_with(&[
        "wheel.tension_a".to_owned(),
        "wheel.tension_b".to_owned(),
        "kinetic_energy".to_owned(),
        "potential_energy".to_owned(),
        "total_energy".to_owned(),
        "momentum_x".to_owned(),
        "momentum_y".to_owned(),
        "angular_momentum".to_owned(),
    ]));
    for integrator in [Integrator::Rk4, Integrator::Verlet, Integrator::Pefrl] {
        let mut scene = scene.clone();
        scene.simulation.integrator = integrator;
        let mut straight = Simulation::new(&scene).expect("valid");
        straight.step_to(0.41).expect("runs");
        let saved = Scene::from_toml(&straight.saved_state(&scene).to_toml()).expect("reads");
        let mut continued = Simulation::new(&saved).expect("valid");
        straight.step_to(1.0).expect("runs");
        continued.step_to(1.0).expect("runs");
        for i in 0..2 {
            assert_eq!(
                straight.body(i).position,
                continued.body(i).position,
                "{integrator}"
            );
            assert_eq!(
                straight.body(i).velocity,
                continued.body(i).velocity,
                "{integrator}"
            );
        }
        assert_eq!(
            straight.joint(0).wheel_spin.to_bits(),
            continued.joint(0).wheel_spin.to_bits()
        );
    }
}

/// A pulley that cannot be is refused in words, as are quantities a pulley does not have
/// (and a pin's tension); a body pulled up to the wheel stops the run, naming both.
#[test]
fn bad_pulleys_are_refused_and_the_wheel_stops_a_run() {
    for (change, words, said) in [
        ("b = \"hanging\"", "b = \"swinging\"", "both 'swinging'"),
        ("radius = 0.3", "radius = 0.0", "radius"),
        ("b = \"hanging\"", "b = \"ball\"", "is a particle"),
        (
            "position = [0.3, 0.0]",
            "position = [0.3, 2.8]",
            "at the wheel",
        ),
    ] {
        let text = ATWOOD.replacen(change, words, 1)
            + "\n[[particle]]\nname = \"ball\"\nmass = 1.0\nposition = [5.0, 5.0]\n";
        let error = Scene::from_toml(&text).expect_err(words);
        assert!(error.to_string().contains(said), "{words}: {error}");
        assert!(error.problems[0].line.is_some(), "{words}: {error}");
    }
    for graph in ["wheel.angle", "wheel.tension"] {
        let text = format!("{ATWOOD}\n[[graph]]\nx = \"t\"\ny = [\"{graph}\"]\n");
        let error = Scene::from_toml(&text).expect_err(graph);
        assert!(error.to_string().contains("'wheel'"), "{graph}: {error}");
    }
    let simulation = Simulation::new(&Scene::from_toml(ATWOOD).expect("valid")).expect("valid");
    for bad in ["wheel.angle", "wheel.tension"] {
        let quantity = physics::Quantity::parse(bad).expect("parses");
        assert!(quantity.reading(&simulation).is_err(), "{bad}");
    }
    let pinned = Simulation::new(&ruler(30.0, Integrator::Rk4)).expect("valid");
    let tension = physics::Quantity::parse("nail.tension_a").expect("parses");
    assert!(tension.reading(&pinned).is_err());
    let mut simulation = simulation;
    let error = simulation
        .step_to(5.0)
        .expect_err("the light block reaches the wheel");
    assert!(
        error.to_string().contains("'hanging'") && error.to_string().contains("'wheel'"),
        "{error}"
    );
}

/// Two boxes of 1 and 2 kg hinged end to end, thrown in empty space with velocities that
/// move the hinge apart: the run starts from the nearest velocities the hinge allows (a
/// plastic impulse at the hinge, which keeps the momentum and the angular momentum and
/// takes kinetic energy, said by `joints_start_loss`), then keeps the momentum, the
/// angular momentum and the energy (to 1e-12) as the pair tumbles; a saved state is not
/// projected again.
#[test]
fn a_hinged_pair_thrown_keeps_its_momenta() {
    let mut world = World::gravity_only();
    world.gravity = [0.0, 0.0].into();
    let scene = Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(
            Body::rectangle("left", 0.4, 0.1, 1.0)
                .position([-0.2, 0.0])
                .moving([0.0, 1.0], 3.0),
        )
        .with_body(
            Body::rectangle("right", 0.4, 0.1, 2.0)
                .position([0.2, 0.0])
                .moving([1.0, 0.0], 0.0),
        )
        .with_joint(Joint::hinge("link", "left", "right", [0.0, 0.0]));
    // Before: p = (2, 1); L about the origin = Σ m x × v + I ω.
    let inertia = Body::rectangle("l", 0.4, 0.1, 1.0).inertia();
    let angular = -0.2 * 1.0 + inertia * 3.0;
    let mut simulation = Simulation::new(&scene).expect("valid");
    let lost = simulation
        .joints_start_loss()
        .expect("the hinge was pulled apart");
    let before = 0.5 * 1.0 + 0.5 * 2.0 + 0.5 * inertia * 9.0;
    let start = simulation.diagnostics();
    assert!((start.energy.kinetic - (before - lost)).abs() < 1e-12);
    assert!(lost > 0.1, "{lost}");
    for t in [0.0, 1.0, 3.0] {
        simulation.step_to(t).expect("runs");
        let d = simulation.diagnostics();
        assert!(
            (d.momentum - glam::DVec2::new(2.0, 1.0)).length() < 1e-12,
            "{t}: {}",
            d.momentum
        );
        assert!(
            (d.angular_momentum - angular).abs() < 1e-12,
            "{t}: {}",
            d.angular_momentum
        );
        assert!(
            (d.energy.kinetic - start.energy.kinetic).abs() < 1e-12,
            "{t}"
        );
    }
    let saved = Scene::from_toml(&simulation.saved_state(&scene).to_toml()).expect("reads");
    let again = Simulation::new(&saved).expect("valid");
    assert_eq!(
        again.joints_start_loss(),
        None,
        "a saved state is consistent already"
    );
}
