//! Forces of one's own (`[[force]]`), the magnetic field and drag from a coefficient: the
//! format, the checks' words, the edits that follow names, and the physics that the
//! `forces` group of `validate` does not already hold to closed forms.

use physics::{Force, Integrator, Particle, Scene, Section, Simulation, World};

const SCENE: &str = r#"version = 1

[world]
gravity = [0.0, 0.0]
gravitation = false
electrostatics = false
air_density = 1.0
magnetic_field = 0.25

[[particle]]
name = "ball"
mass = 2.0
radius = 0.2
charge = 0.5
position = [1.0, 0.0]
velocity = [0.0, 1.0]
drag_coefficient = 0.4

[[particle]]
name = "other"
mass = 1.0
position = [5.0, 5.0]

[[force]]
name = "wind"
on = ["ball"]
fx = "0.3*sin(2*t) - x"
fy = "-0.1*vy"
"#;

fn problems(text: &str) -> Vec<String> {
    match Scene::from_toml(text) {
        Ok(scene) => scene.validate().iter().map(ToString::to_string).collect(),
        Err(e) => e.problems.iter().map(ToString::to_string).collect(),
    }
}

/// What a file says is read, written and read again to the same scene.
#[test]
fn forces_and_the_new_keys_read_and_write_back() {
    let scene = Scene::from_toml(SCENE).expect("reads");
    assert_eq!(
        (
            scene.world.magnetic_field.to_bits(),
            scene.world.air_density.to_bits(),
            scene.particles[0].drag_coefficient.to_bits()
        ),
        (0.25f64.to_bits(), 1.0f64.to_bits(), 0.4f64.to_bits())
    );
    assert_eq!(
        scene.forces,
        [Force::new("wind", "0.3*sin(2*t) - x", "-0.1*vy").on(["ball"])]
    );
    let written = scene.to_toml();
    assert_eq!(Scene::from_toml(&written).expect("reads back"), scene);
    // Unused, the new keys are not written: an old file saves as it did.
    let plain = Scene::new().with_particle(Particle::new("p", 1.0));
    let text = plain.to_toml();
    for key in [
        "air_density",
        "magnetic_field",
        "drag_coefficient",
        "[[force]]",
    ] {
        assert!(!text.contains(key), "{key} in\n{text}");
    }
}

/// Bad forces are refused at their place, in words that say what is allowed.
#[test]
fn bad_forces_are_refused_in_words() {
    let base = "version = 1\n[[particle]]\nname = \"b\"\nposition = [1.0, 0.0]\n";
    let cases = [
        ("fx = \"2*\"", "is no expression"),
        (
            "fx = \"-k*x\"",
            "names 'k': a force may name x, y, vx, vy, t, m, q, pi",
        ),
        ("on = [\"nobody\"]", "there is no particle 'nobody'"),
        ("fx = \"1/(x-1)\"", "not a finite force"),
        (
            "fx = \"-vx\"\npotential = \"0\"",
            "names the velocity or the time",
        ),
        (
            "fx = \"-x\"\npotential = \"x^2\"",
            "−∇U is (-2.000000, 0.000000) N but the force is (-1.000000, 0.000000) N",
        ),
        (
            "fx = \"-x\"\npotential = \"vx\"",
            "a potential energy is of the position alone",
        ),
        ("fz = \"1\"", "fz"),
    ];
    for (lines, expected) in cases {
        let text = format!("{base}[[force]]\nname = \"f\"\n{lines}\n");
        let found = problems(&text);
        assert!(
            found
                .iter()
                .any(|p| p.contains(expected) && p.contains("force 'f'")),
            "{lines}: {found:?}"
        );
    }
    let on_body = "version = 1\n[[body]]\nname = \"box\"\nshape = \"box\"\nwidth = 1.0\nheight = 1.0\nmass = 1.0\nposition = [0.0, 0.0]\n[[force]]\non = [\"box\"]\nfx = \"1\"\n";
    assert!(
        problems(on_body)
            .iter()
            .any(|p| p.contains("'box' is a body: forces of one's own act on particles")),
        "{:?}",
        problems(on_body)
    );
    let both = "version = 1\n[[particle]]\nposition = [0.0, 0.0]\nquadratic_drag = 0.1\ndrag_coefficient = 0.5\n";
    assert!(
        problems(both)
            .iter()
            .any(|p| p.contains("drag_coefficient") || p.contains("drag coefficient")),
        "{:?}",
        problems(both)
    );
}

/// A particle renamed takes its forces along; removed, the forces on it alone go with it
/// (an empty list would mean every particle) and the others lose its name.
#[test]
fn a_force_follows_its_particles_name() {
    let mut scene = Scene::from_toml(SCENE).expect("reads");
    scene
        .forces
        .push(Force::new("both", "1", "0").on(["ball", "other"]));
    scene.rename(Section::Particle(0), "Bowl");
    assert_eq!(scene.forces[0].on, ["Bowl"]);
    assert_eq!(scene.forces[1].on, ["Bowl", "other"]);
    scene.remove(Section::Particle(0));
    assert_eq!(scene.forces.len(), 1);
    assert_eq!(scene.forces[0].on, ["other"]);
    assert!(scene.validate().is_empty(), "{:?}", scene.validate());
}

/// The drag coefficient is c = ½ ρ `C_d` π r², the same bits as that c typed.
#[test]
fn a_drag_coefficient_is_its_quadratic_drag() {
    let ball = |c: f64, cd: f64| {
        let mut p = Particle::new("b", 0.5).radius(0.12).velocity([10.0, 20.0]);
        p.quadratic_drag = c;
        p.drag_coefficient = cd;
        Scene::new()
            .with_world(World {
                air_density: 1.3,
                ..World::gravity_only()
            })
            .with_particle(p)
    };
    let c = 0.5 * 1.3 * 0.47 * std::f64::consts::PI * 0.12 * 0.12;
    let mut a = Simulation::new(&ball(c, 0.0)).expect("valid");
    let mut b = Simulation::new(&ball(0.0, 0.47)).expect("valid");
    a.step_to(2.0).expect("runs");
    b.step_to(2.0).expect("runs");
    assert_eq!(a.positions(), b.positions());
    assert!(
        a.positions()[0].y < 20.0 * 2.0 - 0.5 * 9.81 * 4.0 - 0.1,
        "drag acts"
    );
}

/// The magnetic field never works: a charge in it keeps its speed (rk4's error only,
/// 1e-12 over 20 turns) while a charge of the other sign turns the other way.
#[test]
fn the_magnetic_field_turns_without_working() {
    let charged = |q: f64| {
        Scene::new()
            .with_world(World {
                magnetic_field: 2.0,
                ..World::no_forces()
            })
            .with_particle(
                Particle::new("i", 1.0)
                    .radius(0.1)
                    .charge(q)
                    .velocity([1.0, 0.0]),
            )
    };
    let mut plus = Simulation::new(&charged(1.0)).expect("valid");
    let mut minus = Simulation::new(&charged(-1.0)).expect("valid");
    plus.step_to(0.5).expect("runs");
    minus.step_to(0.5).expect("runs");
    assert!(plus.positions()[0].y < 0.0 && minus.positions()[0].y > 0.0);
    plus.step_to(20.0 * std::f64::consts::PI).expect("runs");
    let speed = plus.velocities()[0].length();
    assert!((speed - 1.0).abs() < 1e-12, "{speed}");
}

/// A force that varies in time continues from a saved state bit for bit, under every
/// fixed-step method: the saved instant is the force's clock.
#[test]
fn a_force_in_time_continues_from_a_saved_state_bit_for_bit() {
    for method in [
        Integrator::Euler,
        Integrator::SemiImplicitEuler,
        Integrator::Verlet,
        Integrator::Rk4,
        Integrator::Pefrl,
    ] {
        let scene = Scene::from_toml(SCENE)
            .expect("reads")
            .with_integrator(method, 5e-4);
        let mut straight = Simulation::new(&scene).expect("valid");
        straight.step_to(0.7).expect("runs");
        let saved = Scene::from_toml(&straight.saved_state(&scene).to_toml()).expect("reads");
        let mut continued = Simulation::new(&saved).expect("valid");
        straight.step_to(1.3).expect("runs");
        continued.step_to(1.3).expect("runs");
        assert_eq!(straight.positions(), continued.positions(), "{method}");
        assert_eq!(straight.velocities(), continued.velocities(), "{method}");
    }
}
