//! Particles that turn, against the closed forms of rigid discs and rings: rolling down
//! an incline at g sin θ/(1 + k), slipping beyond the grip, a bowled ball that starts
//! to roll at a located instant, spin traded for speed at an impact, angular momentum
//! kept where no outside torque acts, and the ledger's books closing. k = I/(m r²).

use physics::{Bounds, Integrator, Particle, Ramp, Scene, Simulation, Vector, World, example};

const G: f64 = 9.81;

fn world() -> World {
    World {
        gravity: Vector::cartesian(0.0, -G),
        ..World::gravity_only()
    }
}

/// A particle of radius `r` resting on a thin ramp through the origin that falls at
/// `theta` degrees to the right, `friction` μ, released at rest.
fn on_incline(theta: f64, friction: f64, inertia: f64, method: Integrator) -> (Scene, f64) {
    let r = 0.1;
    let down = theta.to_radians();
    let normal = (down.sin(), down.cos());
    let scene = Scene::new()
        .with_world(world())
        .with_ramp(
            Ramp::new("slope", [0.0, 0.0], Vector::polar(40.0, -theta))
                .thickness(0.0)
                .friction(friction),
        )
        .with_particle(
            Particle::new("disc", 1.5)
                .radius(r)
                .position([r * normal.0 + 0.05, r * normal.1 - 0.05 * down.tan()])
                .turning(inertia, 0.0),
        )
        .with_integrator(method, 1e-3);
    (scene, r)
}

/// Distance along the incline from the start, and the speed, of particle 0.
fn along(simulation: &Simulation, start: physics::DVec2, theta: f64) -> (f64, f64) {
    let direction = physics::DVec2::new(theta.to_radians().cos(), -theta.to_radians().sin());
    (
        (simulation.positions()[0] - start).dot(direction),
        simulation.velocities()[0].dot(direction),
    )
}

/// A solid disc (k = ½) and a thin ring (k = 1) on a 20° incline with μ = 0.5 (at
/// least tan θ·k/(1 + k) = 0.18 for the ring): they roll, at a = g sin θ/(1 + k), so
/// after 1 s they have gone ½ a and move at a, turning clockwise at ω = −v/r. Constant
/// forces are integrated exactly by Verlet, RK4, PEFRL and Dopri5 (their error terms
/// hold the third derivative of position): 1e-9 m is rounding over 1,000 steps. Euler's
/// position is off by O(h), but its velocity (a sum of constant accelerations) is exact
/// for every method. A weighting bug (a = g sin θ/(1 + 2k), or ω = v/r) fails by
/// metres.
#[test]
fn a_disc_and_a_ring_roll_down_the_incline_at_g_sin_theta_over_one_plus_k() {
    let theta = 20.0_f64;
    for k in [0.5, 1.0] {
        for method in Integrator::ALL {
            let (scene, r) = on_incline(theta, 0.5, k, method);
            let mut simulation = Simulation::new(&scene).unwrap();
            let start = simulation.positions()[0];
            simulation.step_to(1.0).unwrap();
            let a = G * theta.to_radians().sin() / (1.0 + k);
            let (distance, speed) = along(&simulation, start, theta);
            assert!(
                (speed - a).abs() < 1e-9,
                "k = {k}, {method:?}: {speed} m/s, theory {a}"
            );
            let spin = simulation.spins()[0];
            assert!(
                (spin + speed / r).abs() < 1e-9 * speed / r,
                "rolls: ω = {spin}, −v/r = {}",
                -speed / r
            );
            if !matches!(method, Integrator::Euler | Integrator::SemiImplicitEuler) {
                assert!(
                    (distance - 0.5 * a).abs() < 1e-9,
                    "k = {k}, {method:?}: {distance} m, theory {}",
                    0.5 * a
                );
                let turned = simulation.angles()[0].to_radians();
                assert!(
                    (turned + distance / r).abs() < 1e-9 * distance / r,
                    "turned {turned} rad for {distance} m"
                );
            }
        }
    }
}

/// Galileo's race: released together on one incline, a frictionless point slides at
/// g sin θ and wins, the disc (k = ½) is second and the ring (k = 1) last.
#[test]
fn the_slider_wins_the_disc_is_second_and_the_ring_last() {
    let scene = example("galileo-incline").unwrap().scene().unwrap();
    let mut simulation = Simulation::new(&scene).unwrap();
    let start = simulation.positions().to_vec();
    simulation.step_to(1.0).unwrap();
    let gone: Vec<f64> = (0..3)
        .map(|i| simulation.positions()[i].distance(start[i]))
        .collect();
    let theta = 20.0_f64.to_radians();
    for (i, k) in [0.0, 0.5, 1.0].into_iter().enumerate() {
        let theory = 0.5 * G * theta.sin() / (1.0 + k);
        assert!(
            (gone[i] - theory).abs() < 1e-9,
            "{}: {} m, theory {theory}",
            scene.particles[i].name,
            gone[i]
        );
    }
}

/// A ring (k = 1) on a 20° incline with μ = 0.1 < tan θ/2: it cannot roll, and slips
/// with a = g (sin θ − μ cos θ) while friction spins it up at μ g cos θ/(k r). A sign
/// error in the friction's torque spins it the wrong way; one that lets it roll moves
/// it at g sin θ/2 instead.
#[test]
fn below_the_grip_it_slips_and_friction_spins_it_up() {
    let theta = 20.0_f64;
    let (mu, k) = (0.1, 1.0);
    let (scene, r) = on_incline(theta, mu, k, Integrator::Rk4);
    let mut simulation = Simulation::new(&scene).unwrap();
    let start = simulation.positions()[0];
    simulation.step_to(1.0).unwrap();
    let (s, c) = (theta.to_radians().sin(), theta.to_radians().cos());
    let a = G * (s - mu * c);
    let (distance, speed) = along(&simulation, start, theta);
    assert!((speed - a).abs() < 1e-9, "{speed} m/s, theory {a}");
    assert!((distance - 0.5 * a).abs() < 1e-9, "{distance} m");
    let spin = simulation.spins()[0];
    let theory = -mu * G * c / (k * r);
    assert!((spin - theory).abs() < 1e-9, "ω = {spin}, theory {theory}");
}

/// A disc bowled along a level lane at v₀ without spin slips, slowing at μg while
/// friction spins it up, until its contact point stops slipping at t* = v₀ k/((1 + k) μ g)
/// with v = v₀/(1 + k) (2 v₀/3 for a disc); it then rolls on at that speed. The instant
/// is located inside its step: found only at the next step's start, the ball would slip
/// up to a step longer and leave slower by up to μ g h (2e-2 m/s here), where the test
/// allows 1e-12. Friction took ½ m v₀² − ½ m (1 + k) v², and angular momentum about a
/// point of the lane, which friction's line passes through, is kept: L = I ω − m r v.
#[test]
fn a_bowled_ball_starts_to_roll_at_the_instant_theory_gives() {
    let (m, r, v0, mu) = (2.0, 0.11, 6.0, 0.2);
    for k in [0.5, 0.4] {
        for method in [Integrator::Rk4, Integrator::Verlet, Integrator::Dopri5] {
            let scene = Scene::new()
                .with_world(world())
                .with_ramp(
                    Ramp::new("lane", [-1.0, 0.0], [100.0, 0.0])
                        .thickness(0.0)
                        .friction(mu),
                )
                .with_particle(
                    Particle::new("ball", m)
                        .radius(r)
                        .position([0.0, r])
                        .velocity([v0, 0.0])
                        .turning(k, 0.0),
                )
                .with_integrator(method, 1e-2);
            let mut simulation = Simulation::new(&scene).unwrap();
            simulation.keep_ledger();
            let momentum =
                |s: &Simulation| k * m * r * r * s.spins()[0] - m * r * s.velocities()[0].x;
            let before = momentum(&simulation);
            let t_star = v0 * k / ((1.0 + k) * mu * G);
            let v = v0 / (1.0 + k);
            simulation.step_to(2.0).unwrap();
            let speed = simulation.velocities()[0].x;
            assert!(
                (speed - v).abs() < 1e-12 * v0,
                "k = {k}, {method:?}: {speed} m/s after, theory {v}"
            );
            let x = v0 * t_star - 0.5 * mu * G * t_star * t_star + v * (2.0 - t_star);
            let at = simulation.positions()[0].x;
            assert!((at - x).abs() < 1e-9, "x = {at}, theory {x}");
            assert!((simulation.spins()[0] + v / r).abs() < 1e-9, "rolls");
            let kept = momentum(&simulation);
            assert!(
                (kept - before).abs() < 1e-12 * before.abs(),
                "L about the lane {kept}, at the start {before}"
            );
            let ledger = simulation.ledger().unwrap();
            let lost = 0.5 * m * v0 * v0 - 0.5 * m * (1.0 + k) * v * v;
            assert!(
                (ledger.friction - lost).abs() < 1e-9,
                "friction took {} J, theory {lost}",
                ledger.friction
            );
            let energy = simulation.diagnostics().energy.total() + ledger.total();
            let start = 0.5 * m * v0 * v0 + m * G * r;
            assert!(
                (energy - start).abs() < 1e-9 * start,
                "the books close: {energy} J, {start} at the start"
            );
        }
    }
}

/// The impact of a disc (k = ½) falling at u onto a floor of restitution e, spinning at
/// ω₀ counter-clockwise. With enough grip the contact point is brought to rest: it
/// leaves at −ω₀ r/3 with ω₀/3, and friction took m r² ω₀²/6. With little grip it
/// slides: the tangential impulse is μ (1 + e) m u, the spin loses that times r/I.
/// Either way it leaves upwards at e u.
#[test]
fn a_spinning_disc_bounces_off_a_gripping_floor_as_theory_says() {
    let (m, r, omega, e, drop) = (2.0, 0.25, 12.0, 0.8, 1.0);
    for friction in [5.0, 0.05] {
        let mut world = world();
        world.restitution = e;
        world.bounds = Some(Bounds {
            min: Vector::cartesian(-10.0, 0.0),
            max: Vector::cartesian(10.0, 10.0),
            friction,
            static_friction: None,
        });
        let scene = Scene::new()
            .with_world(world)
            .with_particle(
                Particle::new("ball", m)
                    .radius(r)
                    .position([0.0, r + drop])
                    .turning(0.5, omega),
            )
            .with_integrator(Integrator::Rk4, 1e-2);
        let mut simulation = Simulation::new(&scene).unwrap();
        simulation.keep_ledger();
        simulation.record_impacts();
        let fall = (2.0 * drop / G).sqrt();
        simulation.step_to(fall + 0.01).unwrap();
        let impacts = simulation.take_impacts();
        assert_eq!(impacts.len(), 1);
        assert!(
            (impacts[0].time - fall).abs() < 1e-12,
            "{}",
            impacts[0].time
        );
        let u = G * fall;
        let v = simulation.velocities()[0];
        let spin = simulation.spins()[0];
        let (vx, after) = if friction > 1.0 {
            (-omega * r / 3.0, omega / 3.0)
        } else {
            let impulse = friction * (1.0 + e) * m * u;
            (-impulse / m, omega - impulse * r / (0.5 * m * r * r))
        };
        assert!(
            (v.x - vx).abs() < 1e-12,
            "μ = {friction}: vx = {}, theory {vx}",
            v.x
        );
        assert!(
            (spin - after).abs() < 1e-12 * omega,
            "ω = {spin}, theory {after}"
        );
        // It turned at ω₀ until the impact, inside a step, and at the new spin after.
        let turned = simulation.angles()[0].to_radians();
        let theory = omega * fall + after * 0.01;
        assert!(
            (turned - theory).abs() < 1e-9,
            "turned {turned} rad, theory {theory}"
        );
        let up = e * u - G * 0.01;
        assert!((v.y - up).abs() < 1e-9, "vy = {}, theory {up}", v.y);
        if friction > 1.0 {
            let lost = m * r * r * omega * omega / 6.0;
            let friction_took = simulation.ledger().unwrap().friction;
            assert!(
                (friction_took - lost).abs() < 1e-12,
                "{friction_took} J, theory {lost}"
            );
        }
    }
}

/// A ring (k = 1, 1 kg) rolled ahead of a disc (k = ½, 3 kg) that touches it, on a
/// gripping floor (μ = 1), by a sideways pull of gravity gₓ = 2 m/s²: alone the disc
/// would roll at gₓ/(1 + ½), faster than the ring's gₓ/2, so it pushes the ring and
/// they roll together as one rigid roller, at a = (m₁ + m₂) gₓ / (m₁(1 + k₁) +
/// m₂(1 + k₂)) = 8/6.5 m/s² — each push the resting solver gives met by the floor's
/// friction, which shares it between speed and spin. Taken as a push on a point (the
/// resting solver's impulses passing the floor's friction by, the spin then made to
/// follow), they moved at the mass-weighted mean of the two alone, 1.25 m/s after 1 s
/// against 1.2308, and the spins' energy came from nowhere (0.08 J in the books' residual
/// after 1 s). Under every method: both at a t to 1e-5 m/s (the resting solver leaves an
/// approach below 1e-4 of a resting contact's 2 g h, 2e-6 m/s a step, measured 6e-7),
/// and rolling (ω r = −v to 1e-9 m/s). The books close to 1e-9 J under the methods that
/// integrate a constant force exactly; the two Euler methods' residual is their own
/// error (5 mJ at 1 ms), which halves with the step.
#[test]
fn a_disc_pushing_a_ring_along_a_gripping_floor_rolls_with_it_as_one_roller() {
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
            Particle::new("ring", m[0])
                .radius(r)
                .position([r, r])
                .turning(k[0], 0.0),
        )
        .with_particle(
            Particle::new("disc", m[1])
                .radius(r)
                .position([-r, r])
                .turning(k[1], 0.0),
        );
    // The residual of the books after 1 s with `method` at `h`, once the motion is
    // checked.
    let residual = |method: Integrator, h: f64| {
        let mut simulation = Simulation::new(&scene.clone().with_integrator(method, h)).unwrap();
        simulation.keep_ledger();
        let start = simulation.diagnostics().energy.total();
        simulation.step_to(1.0).unwrap();
        let (v, spins) = (simulation.velocities(), simulation.spins());
        for (name, (v, spin)) in ["ring", "disc"].iter().zip(v.iter().zip(&spins)) {
            assert!(
                (v.x - a).abs() < 1e-5,
                "{method:?}: the {name} moves at {}, theory {a}",
                v.x
            );
            assert!(
                (spin * r + v.x).abs() < 1e-9,
                "{method:?}: the {name} slips: ω r = {}, v = {}",
                spin * r,
                v.x
            );
        }
        let ledger = simulation.ledger().unwrap();
        simulation.diagnostics().energy.total() + ledger.total() - start
    };
    for method in [
        Integrator::Verlet,
        Integrator::Rk4,
        Integrator::Pefrl,
        Integrator::Dopri5,
    ] {
        let residual = residual(method, 1e-3);
        assert!(residual.abs() < 1e-9, "{method:?}: residual {residual} J");
    }
    for method in [Integrator::Euler, Integrator::SemiImplicitEuler] {
        let ratio = residual(method, 1e-3) / residual(method, 5e-4);
        assert!(
            (ratio - 2.0).abs() < 0.01,
            "{method:?}: the residual shrinks {ratio}× as the step halves"
        );
    }
}

/// A ball thrown forward at v with backspin ω (counter-clockwise for a ball moving
/// right) onto a gripping floor leaves at (v − k ω r)/(1 + k): strong backspin sends it
/// back the way it came.
#[test]
fn backspin_bounces_a_ball_back() {
    let (r, k, v, omega) = (0.2, 0.4, 2.0, 40.0);
    let mut world = world();
    world.bounds = Some(Bounds {
        min: Vector::cartesian(-20.0, 0.0),
        max: Vector::cartesian(20.0, 20.0),
        friction: 10.0,
        static_friction: None,
    });
    let scene = Scene::new()
        .with_world(world)
        .with_particle(
            Particle::new("ball", 0.5)
                .radius(r)
                .position([0.0, r + 0.5])
                .velocity([v, 0.0])
                .turning(k, omega),
        )
        .with_integrator(Integrator::Rk4, 1e-2);
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.step_to(0.4).unwrap();
    let back = (v - k * omega * r) / (1.0 + k);
    let vx = simulation.velocities()[0].x;
    assert!(back < 0.0);
    assert!((vx - back).abs() < 1e-12, "vx = {vx}, theory {back}");
    assert!(
        (simulation.spins()[0] + back / r).abs() < 1e-12,
        "leaves rolling"
    );
}

/// Two turning discs of unequal mass, radius and inertia collide off-centre with
/// friction between them: the impulses are equal and opposite at one point, so momentum
/// and angular momentum about any point are kept (1e-12 of the scale), and the contact
/// points leave without slipping when the grip suffices. A wrong weighting of the
/// rotational inverse mass (r/I for r²/I) breaks the angular momentum.
#[test]
fn colliding_spinning_discs_keep_angular_momentum() {
    let mut world = World::no_forces();
    world.friction = 0.8;
    world.restitution = 0.6;
    let scene = Scene::new()
        .with_world(world)
        .with_particle(
            Particle::new("a", 1.0)
                .radius(0.3)
                .position([-1.0, 0.1])
                .velocity([3.0, 0.5])
                .turning(0.5, 7.0),
        )
        .with_particle(
            Particle::new("b", 3.5)
                .radius(0.5)
                .position([1.0, -0.2])
                .velocity([-1.0, 0.0])
                .turning(1.0, -2.0),
        )
        .with_integrator(Integrator::Rk4, 1e-3);
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.record_impacts();
    let before = simulation.diagnostics();
    simulation.step_to(1.0).unwrap();
    let impacts = simulation.take_impacts();
    assert_eq!(impacts.len(), 1, "they meet once");
    let after = simulation.diagnostics();
    assert!((after.momentum - before.momentum).length() < 1e-12 * 7.0);
    assert!(
        (after.angular_momentum - before.angular_momentum).abs() < 1e-12 * 10.0,
        "L {} then {}",
        before.angular_momentum,
        after.angular_momentum
    );
    assert!(after.energy.kinetic < before.energy.kinetic);
    // Where they were at the impact: nothing acts on them, so they moved straight.
    let (x, v, w) = (
        simulation.positions(),
        simulation.velocities(),
        simulation.spins(),
    );
    let back = 1.0 - impacts[0].time;
    let n = ((x[1] - v[1] * back) - (x[0] - v[0] * back)).normalize();
    let slip = (v[0] - v[1]).dot(n.perp()) + w[0] * 0.3 + w[1] * 0.5;
    assert!(
        slip.abs() < 1e-12,
        "the contact points left together: {slip}"
    );
}

/// Points (inertia 0) feel no friction at impacts: world friction changes nothing about
/// a thousand balls crashing into a pile, to the bit, and their runs gain no columns.
#[test]
fn points_are_untouched_by_friction_at_impacts() {
    let scene = example("ball-pit").unwrap().scene().unwrap();
    let mut gripping = scene.clone();
    gripping.world.friction = 0.9;
    let mut plain = Simulation::new(&scene).unwrap();
    let mut rough = Simulation::new(&gripping).unwrap();
    assert_eq!(rough.csv_columns(), plain.csv_columns());
    for t in [0.25, 0.5] {
        plain.step_to(t).unwrap();
        rough.step_to(t).unwrap();
        assert_eq!(plain.csv_row(), rough.csv_row(), "t = {t}");
    }
}

/// The scene file's new keys: negative inertia or friction and a non-finite spin are
/// refused with the field named; a saved state keeps spin and angle, and a run from it
/// goes on as the first would have.
#[test]
fn the_keys_are_checked_and_a_saved_state_keeps_the_turning() {
    for (text, field) in [
        ("inertia = -0.5", "inertia"),
        ("spin = nan", "spin"),
        ("angle = inf", "angle"),
    ] {
        let file = format!(
            "version = 1\n[[particle]]\nname = \"a\"\nmass = 1.0\nposition = [0.0, 0.0]\n{text}\n"
        );
        let problems = Scene::from_toml(&file).unwrap_err().problems;
        assert!(
            problems.iter().any(|p| p.message.contains(field)),
            "{text}: {problems:?}"
        );
    }
    for world in [
        "[world]\nfriction = -1.0",
        "[world]\nbounds = { min = [0.0, 0.0], max = [1.0, 1.0], friction = -2.0 }",
    ] {
        let file = format!("version = 1\n{world}\n");
        let problems = Scene::from_toml(&file).unwrap_err().problems;
        assert!(
            problems.iter().any(|p| p.message.contains("friction")),
            "{world}: {problems:?}"
        );
    }
    let scene = example("bowling").unwrap().scene().unwrap();
    let mut straight = Simulation::new(&scene).unwrap();
    straight.step_to(0.3).unwrap();
    let saved = straight.saved_state(&scene);
    let reread = Scene::from_toml(&saved.to_toml()).unwrap();
    assert_eq!(
        reread.particles[0].spin.to_bits(),
        straight.spins()[0].to_bits()
    );
    assert_eq!(
        reread.particles[0].angle.to_bits(),
        straight.angles()[0].to_bits()
    );
    let mut continued = Simulation::new(&reread).unwrap();
    straight.step_to(2.0).unwrap();
    continued.step_to(2.0).unwrap();
    let (a, b) = (straight.velocities()[0], continued.velocities()[0]);
    assert!((a - b).length() < 1e-12, "{a} straight, {b} continued");
}

/// A turning particle's angle is saved to the bit: at each of 40 instants of the bowling
/// ball's slide and roll, the saved state, written as a scene file and read again, starts
/// with the very angle the run had (radians written as degrees came back an ulp off for
/// some 13 % of values: −445.18820681664283° read back as −445.1882068166428).
#[test]
fn a_saved_angle_reads_back_to_the_bit() {
    let scene = example("bowling").unwrap().scene().unwrap();
    let mut run = Simulation::new(&scene).unwrap();
    for k in 1..=40 {
        run.step_to(f64::from(k) * 0.05).unwrap();
        let text = run.saved_state(&scene).to_toml();
        let again = Simulation::new(&Scene::from_toml(&text).unwrap()).unwrap();
        assert_eq!(
            again.angles()[0].to_bits(),
            run.angles()[0].to_bits(),
            "at {} s: {} saved, {} read back",
            run.time(),
            run.angles()[0],
            again.angles()[0]
        );
    }
}
