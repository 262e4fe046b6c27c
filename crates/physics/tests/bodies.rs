//! Rigid bodies (`[[body]]`): the scene file's keys read and written back, the rules a
//! body obeys, and free flight against its closed forms under each method.

#![expect(
    clippy::float_cmp,
    reason = "typed values, and values no arithmetic touched, are compared exactly"
)]

use physics::{
    Body, Bounds, DVec2, Event, Integrator, Ramp, Scene, SceneFormat, Shape, Simulation, Vector,
    Watch, World,
};

const G: f64 = 9.81;

fn thrown(integrator: Integrator, h: f64) -> Scene {
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(integrator, h)
        .with_body(
            Body::rectangle("board", 0.6, 0.1, 1.5)
                .position([0.0, 1.0])
                .angle(10.0)
                .moving([3.0, 4.0], 6.0),
        )
}

const FILE: &str = r##"version = 1

[[body]]
name = "block"
shape = "box"
width = 0.4
height = 0.2
mass = 2.0
position = [0.0, 1.0]
angle = 20.0
friction = 0.3
static_friction = 0.5

[[body]]
shape = "polygon"
vertices = [[0.0, 0.0], [0.4, 0.0], [0.2, 0.3]]
density = 25.0
position = [2.0, 0.0]
fixed = true
color = "#4f7fd9"
"##;

#[test]
fn a_scene_file_reads_and_writes_its_bodies_back() {
    let scene = Scene::from_toml(FILE).expect("reads");
    assert_eq!(scene.bodies.len(), 2);
    let (block, wedge) = (&scene.bodies[0], &scene.bodies[1]);
    assert_eq!(block.shape, Shape::Box);
    assert_eq!((block.width, block.height, block.mass), (0.4, 0.2, 2.0));
    assert_eq!(block.static_friction, Some(0.5));
    assert_eq!(wedge.name, "body2", "named by kind and number");
    assert!(matches!(&wedge.shape, Shape::Polygon(v) if v.len() == 3));
    assert!((wedge.total_mass() - 25.0 * 0.06).abs() < 1e-15);
    assert!(wedge.fixed);
    for format in [SceneFormat::Toml, SceneFormat::Json] {
        let text = match format {
            SceneFormat::Toml => scene.to_toml(),
            SceneFormat::Json => scene.to_json(),
        };
        let again = Scene::parse(&text, format).expect("reads back");
        assert_eq!(again, scene, "{text}");
    }
    let written = scene.to_toml();
    assert!(!written.contains("density = 0.0") && !written.contains("width = 0.0"));
}

/// Each wrong body is refused with its line and column and words that say what to do.
#[test]
fn wrong_bodies_are_refused_where_they_are_wrong() {
    let body = |lines: &str| format!("version = 1\n\n[[body]]\nname = \"b\"\n{lines}\n");
    for (text, line, says) in [
        (
            body("shape = \"circle\"\nmass = 1.0\nposition = [0.0, 0.0]"),
            5,
            "\"box\" or \"polygon\"",
        ),
        (
            body("shape = \"box\"\nwidth = 0.0\nheight = 1.0\nmass = 1.0\nposition = [0.0, 0.0]"),
            6,
            "width greater than 0",
        ),
        (
            body(
                "shape = \"polygon\"\nvertices = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [2.0, 2.0], [0.0, 2.0]]\nmass = 1.0\nposition = [0.0, 0.0]",
            ),
            6,
            "not convex at vertex 3",
        ),
        (
            body(
                "shape = \"polygon\"\nvertices = [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]]\nmass = 1.0\nposition = [0.0, 0.0]",
            ),
            6,
            "clockwise",
        ),
        (
            body(
                "shape = \"box\"\nwidth = 1.0\nheight = 1.0\nmass = 1.0\ndensity = 2.0\nposition = [0.0, 0.0]",
            ),
            9,
            "not both",
        ),
        (
            body(
                "shape = \"box\"\nwidth = 1.0\nheight = 1.0\nmass = 1.0\nfriction = 0.5\nstatic_friction = 0.2\nposition = [0.0, 0.0]",
            ),
            10,
            "at least the kinetic friction 0.5",
        ),
        (
            body("shape = \"polygon\"\nvertices = [1.0, 2.0]\nmass = 1.0\nposition = [0.0, 0.0]"),
            6,
            "list of points",
        ),
    ] {
        let problems = Scene::from_toml(&text).expect_err("refused").problems;
        let problem = &problems[0];
        assert!(problem.message.contains(says), "{problem}");
        assert_eq!(problem.line, Some(line), "{problem}");
    }
    let no_mass = body("shape = \"box\"\nwidth = 1.0\nheight = 1.0\nposition = [0.0, 0.0]");
    let problems = Scene::from_toml(&no_mass).expect_err("refused").problems;
    assert!(problems[0].message.contains("mass (kg) or a density"));
}

#[test]
fn bodies_inside_each_other_at_the_start_are_refused_naming_both() {
    let text = "version = 1\n\n[[body]]\nname = \"a\"\nshape = \"box\"\nwidth = 1.0\nheight = 1.0\nmass = 1.0\nposition = [0.0, 0.0]\n\n[[body]]\nname = \"b\"\nshape = \"box\"\nwidth = 1.0\nheight = 1.0\nmass = 1.0\nposition = [0.5, 0.5]\nangle = 30.0\n";
    let problems = Scene::from_toml(text).expect_err("refused").problems;
    assert_eq!(problems.len(), 1);
    let message = &problems[0].message;
    assert!(
        message.contains("body 'b'") && message.contains("'a'"),
        "{message}"
    );
    assert_eq!(problems[0].line, Some(17));
}

/// The centroid on x₀ + v₀ t + g t²/2 and the angle θ₀ + ω t under the methods exact
/// for a constant acceleration; euler and semi-implicit euler on their own sums,
/// x₀ + n h v₀ + g h² n(n ∓ 1)/2, as a particle beside the body would be.
#[test]
fn a_thrown_board_flies_on_each_method_s_closed_form() {
    let (t, h): (f64, f64) = (0.8, 1e-3);
    let n = (t / h).round();
    let (x0, v0, g) = (
        DVec2::new(0.0, 1.0),
        DVec2::new(3.0, 4.0),
        DVec2::new(0.0, -G),
    );
    for integrator in Integrator::ALL {
        let mut simulation = Simulation::new(&thrown(integrator, h)).expect("valid");
        simulation.step_to(t).expect("runs");
        let board = simulation.body(0);
        let expected = match integrator {
            Integrator::Euler => x0 + v0 * (n * h) + g * (h * h * n * (n - 1.0) / 2.0),
            Integrator::SemiImplicitEuler => x0 + v0 * (n * h) + g * (h * h * n * (n + 1.0) / 2.0),
            _ => x0 + v0 * t + 0.5 * g * t * t,
        };
        assert!(
            (board.position - expected).length() < 1e-12,
            "{integrator}: {} against {expected}",
            board.position
        );
        let angle = 10.0 + (6.0 * t).to_degrees();
        assert!((board.angle - angle).abs() < 1e-11, "{integrator}");
        assert_eq!(board.acceleration, g);
        let rotational = 0.5 * (1.5 * (0.36 + 0.01) / 12.0) * 36.0;
        assert!((board.rotational_energy - rotational).abs() < 1e-14);
    }
}

#[test]
fn a_board_s_energy_and_columns() {
    let mut simulation = Simulation::new(&thrown(Integrator::Rk4, 1e-3)).expect("valid");
    let energy = simulation.diagnostics().energy.total();
    let expected = 0.5 * 1.5 * 25.0 + 0.5 * (1.5 * 0.37 / 12.0) * 36.0 + 1.5 * G * 1.0;
    assert!((energy - expected).abs() < 1e-12 * expected, "{energy}");
    simulation.step_to(1.0).expect("runs");
    let after = simulation.diagnostics().energy.total();
    assert!(
        (after - energy).abs() < 1e-12 * energy,
        "{after} against {energy}"
    );
    let columns = simulation.csv_columns();
    let board: Vec<&str> = columns[1..9].iter().map(String::as_str).collect();
    assert_eq!(
        board,
        [
            "board.x",
            "board.y",
            "board.vx",
            "board.vy",
            "board.ax",
            "board.ay",
            "board.angle",
            "board.spin"
        ]
    );
    assert_eq!(columns.last().map(String::as_str), Some("angular_momentum"));
    let mut values = Vec::new();
    simulation.csv_values(&mut values);
    assert_eq!(values.len(), columns.len());
    assert_eq!(values[8], 6.0, "the spin");
}

/// `board.angle crosses 45` at (45° − 10°)/ω.
#[test]
fn an_event_on_a_body_s_angle_is_located_in_the_step() {
    let mut simulation = Simulation::new(&thrown(Integrator::Rk4, 1e-2)).expect("valid");
    let event = Event::parse("board.angle crosses 45").expect("reads");
    let mut watch = Watch::new(&[event], &simulation).expect("watches");
    let found = simulation.step_to_watching(1.0, &mut watch).expect("runs");
    let expected = 35f64.to_radians() / 6.0;
    assert_eq!(found.len(), 1);
    assert!(
        (found[0].time() - expected).abs() < 1e-12,
        "{}",
        found[0].time()
    );
}

/// A state saved at any instant continues bit for bit: the angle kept in the unit the
/// file writes.
#[test]
fn a_saved_body_continues_bit_for_bit() {
    let scene = thrown(Integrator::Verlet, 5e-4);
    let mut straight = Simulation::new(&scene).expect("valid");
    straight.step_to(0.7).expect("runs");
    let saved = Scene::from_toml(&straight.saved_state(&scene).to_toml()).expect("reads");
    let mut continued = Simulation::new(&saved).expect("valid");
    straight.step_to(1.0).expect("runs");
    continued.step_to(1.0).expect("runs");
    let (a, b) = (straight.body(0), continued.body(0));
    assert_eq!(a.position, b.position);
    assert_eq!(a.velocity, b.velocity);
    assert_eq!(a.angle.to_bits(), b.angle.to_bits());
}

/// A fixed body stays where it is, whatever velocity was typed, and counts no energy.
#[test]
fn a_fixed_body_stays() {
    let mut body = Body::rectangle("wall", 0.2, 2.0, 5.0).position([3.0, 1.0]);
    body = body.moving([1.0, 0.0], 2.0);
    body.fixed = true;
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_body(body);
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(1.0).expect("runs");
    let wall = simulation.body(0);
    assert_eq!(wall.position, DVec2::new(3.0, 1.0));
    assert_eq!((wall.spin, wall.angle), (0.0, 0.0));
    assert_eq!(simulation.diagnostics().energy.total(), 0.0);
}

#[test]
fn a_series_varies_a_body_s_start_angle() {
    let mut scene = thrown(Integrator::Rk4, 1e-3);
    let setting = physics::series::Setting::parse("board.angle", &scene).expect("a setting");
    setting.set(&mut scene, 30.0);
    assert_eq!(scene.bodies[0].angle, 30.0);
    let setting = physics::series::Setting::parse("board.velocity.x", &scene).expect("vector");
    setting.set(&mut scene, -1.0);
    assert_eq!(scene.bodies[0].velocity.to_dvec2().x, -1.0);
}

/// A box of 2 kg resting on a ramp at `slope` degrees of friction `mu`, turned to it.
fn on_incline(slope: f64, mu: f64, method: Integrator) -> Scene {
    let ramp = Ramp::new("incline", [0.0, 0.0], [0.0, 0.0]).friction(mu);
    let ramp = Ramp {
        to: ramp.end_for(slope, 6.0),
        ..ramp
    };
    let at = ramp.touching(2.0, 0.1);
    Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(method, 1e-3)
        .with_ramp(ramp)
        .with_body(
            Body::rectangle("block", 0.4, 0.2, 2.0)
                .position([at.x, at.y])
                .angle(slope),
        )
}

/// tan 20° < 0.5: the block holds, moved by rounding alone; tan 30° > 0.2: it slides
/// g (sin θ − μ cos θ) t²/2, its acceleration read as that, under each method exact for a
/// constant acceleration.
#[test]
fn a_block_holds_on_an_incline_or_slides_down_it() {
    let scene = on_incline(20.0, 0.5, Integrator::Rk4);
    let start = scene.bodies[0].position.to_dvec2();
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(5.0).expect("runs");
    let block = simulation.body(0);
    assert!(block.position.distance(start) < 1e-10, "{}", block.position);
    assert!(block.acceleration.length() < 1e-12);
    assert!((block.angle - 20.0).abs() < 1e-12);
    for method in [Integrator::Rk4, Integrator::Verlet, Integrator::Dopri5] {
        let scene = on_incline(30.0, 0.2, method);
        let start = scene.bodies[0].position.to_dvec2();
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.step_to(1.0).expect("runs");
        let theta = 30_f64.to_radians();
        let a = G * (theta.sin() - 0.2 * theta.cos());
        let block = simulation.body(0);
        let slid = block.position.distance(start);
        assert!((slid - a / 2.0).abs() < 1e-9 * a, "{method}: {slid}");
        assert!((block.acceleration.length() - a).abs() < 1e-9 * a);
        assert!(block.spin.abs() < 1e-12, "it slides without turning");
    }
    // Half a degree either side of arctan μ.
    let threshold = 0.5_f64.atan().to_degrees();
    for (slope, holds) in [(threshold - 0.5, true), (threshold + 0.5, false)] {
        let scene = on_incline(slope, 0.5, Integrator::Rk4);
        let start = scene.bodies[0].position.to_dvec2();
        let mut simulation = Simulation::new(&scene).expect("valid");
        simulation.step_to(0.5).expect("runs");
        let moved = simulation.body(0).position.distance(start);
        assert_eq!(moved < 1e-10, holds, "at {slope}°: moved {moved} m");
    }
}

/// A block sent up an incline slows, stops where v₀²/(2 g (sin θ + μ cos θ)) says (the
/// instant located in its step), and holds there since tan θ < μ.
#[test]
fn a_block_sent_up_an_incline_stops_and_holds() {
    let mut scene = on_incline(15.0, 0.5, Integrator::Rk4);
    let v0 = 2.0;
    let up = DVec2::from_angle(15_f64.to_radians()) * v0;
    scene.bodies[0].velocity = up.into();
    let start = scene.bodies[0].position.to_dvec2();
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(2.0).expect("runs");
    let theta = 15_f64.to_radians();
    let reach = v0 * v0 / (2.0 * G * (theta.sin() + 0.5 * theta.cos()));
    let block = simulation.body(0);
    assert!(
        (block.position.distance(start) - reach).abs() < 1e-9,
        "{} against {reach}",
        block.position.distance(start)
    );
    assert!(block.velocity.length() < 1e-12);
}

fn in_a_box(gravity: [f64; 2], restitution: f64, body: Body) -> Scene {
    let mut world = World::gravity_only();
    world.gravity = gravity.into();
    world.restitution = restitution;
    world.bounds = Some(Bounds {
        min: Vector::cartesian(-2.0, 0.0),
        max: Vector::cartesian(2.0, 3.0),
        friction: 0.0,
        static_friction: None,
    });
    Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_body(body)
}

/// Dropped flat with e = 0, a box lands on both corners at once, the impulses solved
/// together: it rests at its half height without turning.
#[test]
fn a_box_dropped_flat_lands_without_turning() {
    let body = Body::rectangle("box", 0.4, 0.2, 1.0).position([0.3, 1.0]);
    let mut simulation = Simulation::new(&in_a_box([0.0, -9.81], 0.0, body)).expect("valid");
    simulation.step_to(1.0).expect("runs");
    let b = simulation.body(0);
    assert!(
        b.spin.abs() < 1e-12 && (b.position.y - 0.1).abs() < 1e-12,
        "{b:?}"
    );
    assert!(b.velocity.length() < 1e-12);
}

/// Off an elastic frictionless wall with no field: the kinetic energy, translational and
/// rotational, is kept and the velocity along the wall untouched; without spin the
/// instant it strikes is (x₀ − w/2 − wall)/v, located inside its step.
#[test]
fn a_box_strikes_a_wall_elastically_at_its_instant() {
    let thrown = |spin: f64| {
        let body = Body::rectangle("box", 0.4, 0.2, 1.0)
            .position([0.0, 1.5])
            .moving([-2.0, 0.5], spin);
        in_a_box([0.0, 0.0], 1.0, body)
    };
    let mut simulation = Simulation::new(&thrown(3.0)).expect("valid");
    let before = simulation.body(0);
    simulation.step_to(1.5).expect("runs");
    let after = simulation.body(0);
    assert!(after.velocity.x > 0.0, "it came back: {after:?}");
    let energy = before.kinetic_energy;
    assert!((after.kinetic_energy - energy).abs() < 1e-12 * energy);
    assert_eq!(after.velocity.y, before.velocity.y);
    let mut simulation = Simulation::new(&thrown(0.0)).expect("valid");
    let event = Event::parse("box.vx crosses 0 up").expect("reads");
    let mut watch = Watch::new(&[event], &simulation).expect("watches");
    let found = simulation.step_to_watching(1.5, &mut watch).expect("runs");
    assert!((found[0].time() - 0.9).abs() < 1e-9, "{}", found[0].time());
}

/// The books close with bodies: a sliding block's friction takes μ m g cos θ d, a box
/// dropped flat onto an inelastic floor gives its impact the kinetic energy it landed
/// with, m g Δh; the residual stays at rounding.
#[test]
fn the_ledger_books_what_the_surfaces_take_from_bodies() {
    let scene = on_incline(30.0, 0.2, Integrator::Rk4);
    let start = scene.bodies[0].position.to_dvec2();
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.keep_ledger();
    let energy = simulation.diagnostics().energy.total();
    simulation.step_to(1.0).expect("runs");
    let d = simulation.body(0).position.distance(start);
    let friction = 0.2 * 2.0 * G * 30_f64.to_radians().cos() * d;
    let ledger = simulation.ledger().expect("kept");
    assert!(
        (ledger.friction - friction).abs() < 1e-9 * friction,
        "{ledger:?}"
    );
    let residual = simulation.diagnostics().energy.total() + ledger.total() - energy;
    assert!(residual.abs() < 1e-9 * energy.abs().max(1.0), "{residual}");
    let body = Body::rectangle("box", 0.4, 0.2, 1.0).position([0.3, 1.0]);
    let mut simulation = Simulation::new(&in_a_box([0.0, -9.81], 0.0, body)).expect("valid");
    simulation.keep_ledger();
    simulation.step_to(1.0).expect("runs");
    let ledger = simulation.ledger().expect("kept");
    let landed = 1.0 * G * 0.9;
    assert!(
        (ledger.impacts - landed).abs() < 1e-9 * landed,
        "{ledger:?}"
    );
    assert!(ledger.friction.abs() < 1e-9, "{ledger:?}");
}

/// The free-body diagram of a block held on a 20° incline: its weight m g at the
/// centroid, normal forces summing to m g cos θ along the face's normal, friction
/// m g sin θ up the slope, and together nothing: it stays.
#[test]
fn a_held_block_s_forces_are_its_free_body_diagram() {
    let simulation = Simulation::new(&on_incline(20.0, 0.5, Integrator::Rk4)).expect("valid");
    let forces = simulation.body_forces(0);
    let theta = 20_f64.to_radians();
    let (m, g) = (2.0, G);
    assert_eq!(forces[0].arm, DVec2::ZERO);
    assert!((forces[0].force - DVec2::new(0.0, -m * g)).length() < 1e-12);
    let normal: DVec2 = forces[1..]
        .iter()
        .filter(|f| !f.friction)
        .map(|f| f.force)
        .sum();
    let friction: DVec2 = forces.iter().filter(|f| f.friction).map(|f| f.force).sum();
    assert!(
        (normal.length() - m * g * theta.cos()).abs() < 1e-9,
        "{normal}"
    );
    assert!(
        (friction.length() - m * g * theta.sin()).abs() < 1e-9,
        "{friction}"
    );
    let up = DVec2::from_angle(theta);
    assert!(friction.dot(up) > 0.0, "friction holds it up the slope");
    let total: DVec2 = forces.iter().map(|f| f.force).sum();
    assert!(total.length() < 1e-9, "{total}");
}

/// A ramp's own static friction: μs = 0.5 holds a block on 25° (tan 25° = 0.47), where
/// its kinetic μk = 0.3 alone would not; a block sent down it slides with
/// g (sin θ − μk cos θ), faster than it would under μs; a static coefficient below the
/// kinetic one is refused, and the key reads and writes back on ramps and walls.
#[test]
fn static_friction_holds_and_kinetic_friction_slides() {
    let held = |v0: f64| {
        let mut scene = on_incline(25.0, 0.3, Integrator::Rk4);
        scene.ramps[0].static_friction = Some(0.5);
        let down = -DVec2::from_angle(25_f64.to_radians()) * v0;
        scene.bodies[0].velocity = down.into();
        scene
    };
    let scene = held(0.0);
    let start = scene.bodies[0].position.to_dvec2();
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(2.0).expect("runs");
    assert!(simulation.body(0).position.distance(start) < 1e-10);
    let scene = held(0.5);
    let mut simulation = Simulation::new(&scene).expect("valid");
    simulation.step_to(0.5).expect("runs");
    let theta = 25_f64.to_radians();
    let a = G * (theta.sin() - 0.3 * theta.cos());
    let v = simulation.body(0).velocity.length();
    assert!((v - (0.5 + a * 0.5)).abs() < 1e-9, "{v}");
    let mut wrong = held(0.0);
    wrong.ramps[0].static_friction = Some(0.1);
    assert!(
        wrong.validate()[0]
            .message
            .contains("at least the kinetic friction 0.3")
    );
    let mut both = held(0.0);
    both.world.bounds = Some(Bounds {
        min: Vector::cartesian(-5.0, -1.0),
        max: Vector::cartesian(10.0, 10.0),
        friction: 0.2,
        static_friction: Some(0.6),
    });
    let text = both.to_toml();
    assert!(text.contains("static_friction = 0.5") && text.contains("static_friction = 0.6"));
    assert_eq!(Scene::from_toml(&text).expect("reads"), both);
    assert_eq!(Scene::from_json(&both.to_json()).expect("reads"), both);
}

/// The app asks for a body's forces while its scene is being edited, valid or not: a body
/// of no mass or no area gives finite forces or none, never a panic.
#[test]
fn forces_of_a_body_being_edited_are_finite_or_none() {
    let mut scene = on_incline(20.0, 0.5, Integrator::Rk4);
    scene.bodies[0].mass = 0.0;
    assert!(!scene.validate().is_empty());
    assert!(scene.body_forces(0).iter().all(|f| f.force.is_finite()));
    scene.bodies[0] = Body::polygon("flat", vec![DVec2::ZERO, DVec2::X], 1.0);
    assert!(scene.body_forces(0).iter().all(|f| f.force.is_finite()));
    assert!(scene.body_forces(5).is_empty());
}

/// A tall box (0.2 × 1 m, 3 kg) tipping over the lower corner of a 13° incline that
/// grips it (μ = 1): at every reading its centroid's acceleration is that of a body
/// turning about a fixed corner, α ẑ × r − ω² r with α = −m g rₓ / I and
/// I = m (w² + h²)/3 about the corner, worked out from the reading's own angle and spin; and its
/// free-body diagram has the corner's push, the weight and the corner's forces summing to
/// m a. Each reading, not only the first, which is where a free fall (0, −g) was read
/// between steps. The limit, 2e-3 of |a|, is what the spin's own lag behind an ideal
/// pivot (some 0.1 % by 0.6 s: the corner is held by an impact every other step) leaves.
#[test]
fn a_tipping_box_reads_the_acceleration_of_a_pivot_at_every_reading() {
    let (m, w, h) = (3.0, 0.2, 1.0);
    let slope = 13.0;
    let ramp = Ramp::new("incline", [0.0, 0.0], [0.0, 0.0]).friction(1.0);
    let ramp = Ramp {
        to: ramp.end_for(slope, 6.0),
        ..ramp
    };
    let at = ramp.touching(3.0, h / 2.0);
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, 1e-3)
        .with_ramp(ramp)
        .with_body(
            Body::rectangle("box", w, h, m)
                .position([at.x, at.y])
                .angle(slope),
        );
    let mut simulation = Simulation::new(&scene).expect("valid");
    let inertia = m * (w * w + h * h) / 3.0;
    for reading in 0..=12 {
        simulation
            .step_to(0.05 * f64::from(reading))
            .expect("steps");
        let body = simulation.body(0);
        let turned = DVec2::from_angle(body.angle.to_radians());
        // From the corner it turns about (downhill, below) to the centroid.
        let r = turned.rotate(DVec2::new(w / 2.0, h / 2.0));
        let alpha = -m * G * r.x / inertia;
        let theory = alpha * r.perp() - body.spin * body.spin * r;
        let error = (body.acceleration - theory).length() / theory.length();
        assert!(
            error < 2e-3,
            "t {}: {} against {theory} ({error:.1e})",
            simulation.time(),
            body.acceleration
        );
        let forces = simulation.body_forces(0);
        assert!(
            forces.len() > 1,
            "t {}: the corner pushes",
            simulation.time()
        );
        let total: DVec2 = forces.iter().map(|f| f.force).sum();
        assert!(
            (total - m * body.acceleration).length() < 1e-9 * m * G,
            "t {}: {total}",
            simulation.time()
        );
    }
}
