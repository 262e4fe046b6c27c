//! Every road an impact or a frictional contact can take through the contact code, each
//! against the impulse formulas, on *free* particles and on *coupled* ones.
//!
//! The contact code treats the two differently (see `contacts/mod.rs`): an impact of a
//! free particle is applied inside the step on its exact path, an impact of a coupled one
//! (a particle that feels a pairwise force or a spring) on the coupled particles' motion
//! through the step, which everything the struck one pulls then answers (with rk4; other
//! methods integrate the coupled particles again to that instant and on to the step's
//! end; in some cases the step ends there). Pairwise gravitation is on by default, so
//! most scenes a user builds take the coupled road — and once, a wrong restitution there
//! passed every test, because every test with e < 1 used free particles.
//!
//! How a particle is made coupled without spoiling the closed form: with gravitation on,
//! a *single* particle is coupled (it takes part in pairwise forces) but has no partner,
//! so its motion is exactly the uniform field's. For a pair, the mutual attraction of two
//! 1 kg balls a metre apart is G·m/r² ≈ 7e-11 m/s², which over the second these tests
//! run changes velocities by < 1e-10 m/s: the tolerances (1e-8 of the speeds involved)
//! leave room for that and fail any wrong factor in an impulse.

use physics::{Bounds, DVec2, Particle, Ramp, Scene, Simulation, World};

const G: f64 = 9.81;

/// No uniform field; pairwise gravitation on (coupled) or off (free); no electrostatics.
fn world(coupled: bool, restitution: f64) -> World {
    World {
        gravitation: coupled,
        electrostatics: false,
        restitution,
        ..World::weightless()
    }
}

fn label(coupled: bool) -> &'static str {
    if coupled { "coupled" } else { "free" }
}

/// An oblique impact of unequal masses in flight: the separation speed along the contact
/// normal is e times the approach speed, momentum is conserved, and the kinetic energy
/// lost is (1 − e²) × ½ μ vₙ² (μ the reduced mass). The contact instant solves
/// |Δx + Δv t| = rA + rB, a quadratic. Free particles to 1e-12 of the quantities
/// (rounding); coupled ones to 1e-8 (their mutual gravitation, see the module doc).
#[test]
fn an_impact_in_flight_has_the_worlds_restitution_free_or_coupled() {
    let (m1, m2, r1, r2) = (2.0, 5.0, 0.4, 0.6);
    let (x1, v1, x2, v2) = (
        DVec2::ZERO,
        DVec2::new(7.0, 1.0),
        DVec2::new(4.0, 0.7),
        DVec2::new(-1.0, 0.5),
    );
    let (dx, dv) = (x2 - x1, v2 - v1);
    let reach: f64 = r1 + r2;
    let (a, b, c) = (dv.dot(dv), 2.0 * dx.dot(dv), dx.dot(dx) - reach * reach);
    let contact_time = (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    let normal = (dx + dv * contact_time) / reach;
    let approach = -dv.dot(normal);
    let reduced_mass = m1 * m2 / (m1 + m2);
    for coupled in [false, true] {
        for restitution in [0.0, 0.3, 0.8, 1.0] {
            let scene = Scene::new()
                .with_world(world(coupled, restitution))
                .with_particle(Particle::new("A", m1).radius(r1).position(x1).velocity(v1))
                .with_particle(Particle::new("B", m2).radius(r2).position(x2).velocity(v2));
            let mut simulation = Simulation::new(&scene).unwrap();
            let before = simulation.diagnostics();
            simulation.step_to(1.0).unwrap();
            let after = simulation.diagnostics();
            let case = format!("{} e = {restitution}", label(coupled));
            let tolerance = if coupled { 1e-8 } else { 1e-12 };
            let separation = (simulation.velocities()[1] - simulation.velocities()[0]).dot(normal);
            assert!(
                (separation - restitution * approach).abs() < tolerance * approach,
                "{case}: separating at {separation}, theory {}",
                restitution * approach
            );
            let loss = before.energy.kinetic - after.energy.kinetic;
            let theory = (1.0 - restitution * restitution) * 0.5 * reduced_mass * approach.powi(2);
            assert!(
                (loss - theory).abs() < tolerance * before.energy.kinetic,
                "{case}: lost {loss} J, theory {theory} J"
            );
            assert!(
                (after.momentum - before.momentum).length() < tolerance * 40.0,
                "{case}: momentum moved by {}",
                after.momentum - before.momentum
            );
        }
    }
}

/// Two equal touching balls, the first moving into the second at v: the impact happens at
/// the start of the first step (the touching road, not the search inside a step). Momentum
/// and the restitution law give v₁' = (1 − e)/2 · v and v₂' = (1 + e)/2 · v.
#[test]
fn an_impact_between_touching_balls_has_the_worlds_restitution_free_or_coupled() {
    let v = 3.0;
    for coupled in [false, true] {
        for restitution in [0.0, 0.5, 1.0] {
            let scene = Scene::new()
                .with_world(world(coupled, restitution))
                .with_particle(Particle::new("A", 1.0).radius(0.5).velocity([v, 0.0]))
                .with_particle(Particle::new("B", 1.0).radius(0.5).position([1.0, 0.0]));
            let mut simulation = Simulation::new(&scene).unwrap();
            simulation.step_to(0.1).unwrap();
            let (a, b) = (simulation.velocities()[0], simulation.velocities()[1]);
            let case = format!("{} e = {restitution}", label(coupled));
            let (theory_a, theory_b) =
                (0.5 * (1.0 - restitution) * v, 0.5 * (1.0 + restitution) * v);
            assert!(
                a.distance(DVec2::new(theory_a, 0.0)) < 1e-8 * v,
                "{case}: A leaves at {a}, theory {theory_a}"
            );
            assert!(
                b.distance(DVec2::new(theory_b, 0.0)) < 1e-8 * v,
                "{case}: B leaves at {b}, theory {theory_b}"
            );
        }
    }
}

/// A ball dropped from h = 2 m onto a level ramp of restitution e meets it at
/// t₁ = √(2h/g) at speed v = √(2gh), leaves at e·v and tops out e²·h above the contact
/// height at t₁ + e·v/g (with e = 0 it stays at rest on the surface). Free and coupled;
/// ramps and the world's walls.
#[test]
fn a_bounce_off_a_surface_has_its_restitution_free_or_coupled() {
    let (h, radius) = (2.0, 0.25);
    let impact_speed = (2.0 * G * h).sqrt();
    for coupled in [false, true] {
        for restitution in [0.0, 0.4, 0.9] {
            for on_wall in [false, true] {
                let mut world = World {
                    gravity: physics::Vector::cartesian(0.0, -G),
                    ..world(coupled, restitution)
                };
                let mut scene = Scene::new();
                if on_wall {
                    world.bounds = Some(Bounds {
                        min: [-5.0, 0.0].into(),
                        max: [5.0, 10.0].into(),
                        friction: 0.0,
                        static_friction: None,
                    });
                } else {
                    scene = scene.with_ramp(
                        Ramp::new("floor", [-5.0, -0.05], [5.0, -0.05])
                            .thickness(0.1)
                            .restitution(restitution),
                    );
                }
                let scene = scene.with_world(world).with_particle(
                    Particle::new("ball", 1.0)
                        .radius(radius)
                        .position([0.0, radius + h]),
                );
                let mut simulation = Simulation::new(&scene).unwrap();
                let t1 = (2.0 * h / G).sqrt();
                // With e = 0 there is no apex: look a little later, at the ball at rest.
                let apex = t1 + (restitution * impact_speed / G).max(0.1);
                simulation.step_to(apex).unwrap();
                let height = simulation.positions()[0].y - radius;
                let theory = restitution * restitution * h;
                let case = format!(
                    "{} {} e = {restitution}",
                    label(coupled),
                    if on_wall { "wall" } else { "ramp" }
                );
                assert!(
                    (height - theory).abs() < 1e-8,
                    "{case}: at the apex {height} m up, theory {theory} m"
                );
                assert!(
                    simulation.velocities()[0].length() < 1e-8 * impact_speed,
                    "{case}: at the apex moving at {}",
                    simulation.velocities()[0]
                );
            }
        }
    }
}

/// Two balls with different accelerations (A carries its own applied acceleration on top
/// of the field) meet in flight: their relative motion is a parabola, so the instant and
/// the normal of contact depend on where each is inside the step, not only at its ends.
/// The contact instant is the first root of |Δx₀ + Δv t + ½ Δa t²| = rA + rB, found here
/// by bisection; the impulse of the paper's 8–10 with e = 0.6 at that instant, and free
/// flight before and after, give both balls' velocities at t = 1 s. To 1e-9 of the
/// speeds: the impact is located to 1e-9 s or better.
#[test]
fn an_impact_between_unequally_accelerated_balls_is_exact_free_or_coupled() {
    let (m1, m2, r1, r2, restitution) = (1.5, 2.5, 0.3, 0.2, 0.6);
    let field = DVec2::new(0.0, -G);
    let own = DVec2::new(6.0, 9.0); // A's applied acceleration, m/s²
    let (x1, v1, x2, v2) = (
        DVec2::ZERO,
        DVec2::new(2.0, 0.5),
        DVec2::new(1.6, 0.45),
        DVec2::new(-1.0, 0.0),
    );
    let (a1, a2) = (field + own, field);
    let gap = |t: f64| {
        let dx = (x2 - x1) + (v2 - v1) * t + (a2 - a1) * (0.5 * t * t);
        dx.length() - (r1 + r2)
    };
    // The first sign change on a fine grid, then bisection to rounding.
    let mut hi = 0.0;
    while gap(hi) > 0.0 {
        hi += 1e-3;
        assert!(hi < 1.0, "the set-up collides within a second");
    }
    let mut lo = hi - 1e-3;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if gap(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    let tc = hi;
    let normal = ((x2 - x1) + (v2 - v1) * tc + (a2 - a1) * (0.5 * tc * tc)) / (r1 + r2);
    let (u1, u2) = (v1 + a1 * tc, v2 + a2 * tc);
    let approach = (u1 - u2).dot(normal);
    assert!(approach > 0.0, "closing at contact");
    let impulse = (1.0 + restitution) * approach / (1.0 / m1 + 1.0 / m2);
    let t = 1.0;
    let theory_a = u1 - normal * (impulse / m1) + a1 * (t - tc);
    let theory_b = u2 + normal * (impulse / m2) + a2 * (t - tc);
    for coupled in [false, true] {
        let scene = Scene::new()
            .with_world(World {
                gravity: physics::Vector::cartesian(0.0, -G),
                ..world(coupled, restitution)
            })
            .with_particle(
                Particle::new("A", m1)
                    .radius(r1)
                    .position(x1)
                    .velocity(v1)
                    .acceleration(own),
            )
            .with_particle(Particle::new("B", m2).radius(r2).position(x2).velocity(v2));
        let mut simulation = Simulation::new(&scene).unwrap();
        simulation.step_to(t).unwrap();
        let (a, b) = (simulation.velocities()[0], simulation.velocities()[1]);
        assert!(
            a.distance(theory_a) < 1e-9 * 10.0,
            "{}: A at {a}, theory {theory_a}",
            label(coupled)
        );
        assert!(
            b.distance(theory_b) < 1e-9 * 10.0,
            "{}: B at {b}, theory {theory_b}",
            label(coupled)
        );
    }
}

/// A ball pulled onto a wall by a spring (k = 100 N/m, m = 1 kg: ω = 10 /s; released
/// 1.1 m from the spring's equilibrium, which lies 0.1 m behind the wall's contact
/// position c) bounces with e = ½ and comes to rest against the wall.
/// Its motion between bounces is simple harmonic about the equilibrium, so each return
/// to the wall is at the speed it left: the approach speeds are v₁ eᵏ with
/// v₁ = ω √(A² − c²) — to 1e-9 relative (impacts located to 1e-9 s) while they are
/// well above a resting contact's. Left alone those bounces would go on for ever in a
/// finite time (the arcs shrink with the speed); the contact code ends them where the
/// approach is no faster than a resting contact's, of order 2 a h (a = k c / m, the
/// spring's pull at the wall): the first impact clearly slower than that is inelastic and
/// the last (a resting speed scaled wrongly, near zero, gave two more bounces), no impact
/// slower than a tenth of it is logged, and the ball then rests on the wall.
#[test]
fn a_ball_pulled_onto_a_wall_by_a_spring_bounces_then_rests() {
    let (k, m, radius, e, h) = (100.0, 1.0, 0.1, 0.5, 1e-3);
    let world = World {
        bounds: Some(Bounds {
            min: [0.0, -5.0].into(),
            max: [10.0, 5.0].into(),
            friction: 0.0,
            static_friction: None,
        }),
        ..world(false, e)
    };
    let scene = ball_on_a_spring(world, (k, m, radius));
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.record_impacts();
    simulation.step_to(3.0).unwrap();
    let impacts = simulation.take_impacts();
    // About the equilibrium (the ball's centre at x = 0): amplitude 1.1, wall at 0.1.
    let (amplitude, contact) = (1.1_f64, radius);
    let first = (k / m).sqrt() * (amplitude * amplitude - contact * contact).sqrt();
    let resting_speed = 2.0 * (k * contact / m) * h;
    let bounces = (0..64)
        .take_while(|&n| first * e.powi(n) > 2.0 * resting_speed)
        .count();
    assert!(bounces >= 8 && impacts.len() > bounces, "{impacts:?}");
    for (n, impact) in impacts.iter().enumerate().take(bounces) {
        let expected = first * e.powi(i32::try_from(n).unwrap());
        let error = (impact.normal_speed_before - expected).abs() / expected;
        assert!(
            error < 1e-9,
            "bounce {n}: {} m/s against {expected} ({error:e})",
            impact.normal_speed_before
        );
        let separation = e * impact.normal_speed_before;
        assert!((impact.normal_speed_after - separation).abs() < 1e-12 * expected);
    }
    let slowest = impacts
        .iter()
        .map(|i| i.normal_speed_before)
        .fold(f64::INFINITY, f64::min);
    assert!(
        slowest > 0.1 * resting_speed,
        "an impact at {slowest} m/s: slower ones are resting contact"
    );
    // An approach clearly faster than a resting contact's (by 20 %: the code's scale is
    // the largest change of velocity in the step, about the spring's pull) bounces with
    // e; one clearly slower is the last impact, and inelastic.
    for (n, impact) in impacts.iter().enumerate() {
        let (u, after) = (impact.normal_speed_before, impact.normal_speed_after);
        if u > 1.2 * resting_speed {
            assert!(
                (after - e * u).abs() < 1e-12 * first,
                "impact {n}: {impact:?}"
            );
        } else if u < 0.8 * resting_speed {
            assert!(
                after == 0.0 && n + 1 == impacts.len(),
                "impact {n} at {u} m/s, slower than a resting contact's, must end the bouncing: {impact:?}"
            );
        }
    }
    let (x, v) = (
        simulation.positions()[1].x,
        simulation.velocities()[1].length(),
    );
    assert!(
        (x - contact).abs() < 1e-2 * radius && v < 1e-6,
        "at rest against the wall: at {x} m, moving at {v} m/s"
    );
}

/// The impact log names what each particle struck: one ball dropped onto the second of
/// two ramps, one onto the floor of the world's box, one onto another ball resting on
/// the floor. Each meets its target at the free-fall time √(2 h / g) (h the drop to
/// contact), to 1e-9 s.
#[test]
fn the_impact_log_names_the_ramp_the_wall_or_the_particle_struck() {
    use physics::ImpactTarget;
    let world = World {
        gravity: physics::Vector::cartesian(0.0, -G),
        bounds: Some(Bounds {
            min: [-10.0, 0.0].into(),
            max: [10.0, 10.0].into(),
            friction: 0.0,
            static_friction: None,
        }),
        ..world(false, 0.5)
    };
    let (radius, h) = (0.1, 1.5);
    let scene = Scene::new()
        .with_world(world)
        .with_ramp(Ramp::new("left", [-8.0, 1.0], [-6.0, 1.0]).thickness(0.1))
        .with_ramp(Ramp::new("right", [6.0, 1.0], [8.0, 1.0]).thickness(0.1))
        .with_particle(
            Particle::new("onto ramp", 1.0)
                .radius(radius)
                .position([7.0, 1.0 + 0.05 + radius + h]),
        )
        .with_particle(
            Particle::new("onto floor", 1.0)
                .radius(radius)
                .position([0.0, radius + h]),
        )
        .with_particle(
            Particle::new("resting", 1.0)
                .radius(radius)
                .position([3.0, radius]),
        )
        .with_particle(
            Particle::new("onto ball", 1.0)
                .radius(radius)
                .position([3.0, 3.0 * radius + h]),
        );
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.record_impacts();
    simulation.step_to(0.6).unwrap();
    let impacts = simulation.take_impacts();
    let first = |p: usize| {
        impacts
            .iter()
            .find(|i| i.particle == p || i.other == ImpactTarget::Particle(p))
            .unwrap_or_else(|| panic!("no impact of particle {p}: {impacts:?}"))
    };
    let fall = (2.0 * h / G).sqrt();
    for (p, expected) in [
        (0, ImpactTarget::Ramp(1)),
        (1, ImpactTarget::Wall),
        (3, ImpactTarget::Particle(2)),
    ] {
        let impact = first(p);
        let struck = if impact.particle == p {
            impact.other
        } else {
            ImpactTarget::Particle(impact.particle)
        };
        assert_eq!(struck, expected, "particle {p}: {impact:?}");
        assert!(
            (impact.time - fall).abs() < 1e-9,
            "particle {p}: {impact:?}, theory {fall} s"
        );
    }
}

/// A coupled impact is located where the bodies touch on the motion, not where the
/// step's interpolating path says they do: a ball on a stiff spring (ω = 100 /s, so a
/// 1 ms step is a tenth of a radian and the cubic through the step's ends misses the
/// motion by some 1e-7 m) strikes a fixed ball. Closed form: from rest at A = 1.1 m the
/// ball's centre is at A cos ωt and touches at x = 0.1 m, at t = acos(1/11)/ω with
/// speed ω √(A² − 0.1²). The instant agrees to 2e-8 s and the speed to 1.5e-7 of
/// itself: rk4's own error after the 15 steps before it, whose phase lags (ωh)⁵/120 a
/// step (1.2e-8 s in all; measured 1.15e-8 s and 9.7e-8; integrating the coupled system
/// to the instant instead, as each impact once did, 1.18e-8 s and 1.0e-7). Measured on
/// the cubic through the step's ends (as the impact search's paths are) instead of the
/// motion's own curve (`simulation/coupled/response.rs`), the speed is off by 1.8e-6 of
/// itself; on the quintic through their positions, velocities and accelerations, 2.2e-7.
#[test]
fn a_coupled_impact_is_located_where_the_balls_touch() {
    let (radius, omega, amplitude) = (0.1, 100.0_f64, 1.1_f64);
    let scene = ball_on_a_spring(world(false, 1.0), (omega * omega, 1.0, radius)).with_particle(
        Particle::new("target", 1.0)
            .radius(radius)
            .position([-0.1, 0.0])
            .fixed(),
    );
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.record_impacts();
    simulation.step_to(0.05).unwrap();
    let first = *simulation.take_impacts().first().expect("an impact");
    let touch = 0.1;
    let time = (touch / amplitude).acos() / omega;
    let speed = omega * (amplitude * amplitude - touch * touch).sqrt();
    assert!(
        (first.time - time).abs() < 2e-8,
        "at {} s against {time} s",
        first.time
    );
    let error = (first.normal_speed_before - speed).abs() / speed;
    assert!(
        error < 1.5e-7,
        "at {} m/s against {speed} ({error:e})",
        first.normal_speed_before
    );
}

/// A ball (index 1) of `mass` and `radius` 1.1 m right of the origin, on a spring of
/// `stiffness` and natural length 3 m from a fixed anchor (index 0) at x = 3 m: the
/// spring's equilibrium puts the ball's centre at the origin.
fn ball_on_a_spring(world: World, (stiffness, mass, radius): (f64, f64, f64)) -> Scene {
    Scene::new()
        .with_world(world)
        .with_particle(
            Particle::new("anchor", 1.0)
                .radius(radius)
                .position([3.0, 0.0])
                .fixed(),
        )
        .with_particle(
            Particle::new("ball", mass)
                .radius(radius)
                .position([1.1, 0.0]),
        )
        .with_spring(physics::Spring::new(
            "spring", "anchor", "ball", stiffness, 3.0,
        ))
}

/// A ball on a spring rattles between two walls 4 mm apart, up to four times a step:
/// each impact of a coupled particle is applied inside the step, on the step's motion,
/// and the ball departs from it by the spring's answer (`simulation/coupled/response.rs`;
/// no impact ends its step). Closed form: the spring
/// (ω = 1 rad/s, equilibrium at the box's centre) gives simple harmonic motion between
/// the walls, where the centre reaches ±d. Starting at the centre at v₀, the ball first
/// strikes at asin(d/C)/ω, C = v₀/ω, at u₁ = √(v₀² − ω²d²); leaving a wall at w it
/// meets the other after 2·asin(d/C')/ω, C' = √(d² + w²/ω²), at w again, and leaves at
/// e·w. Every instant to 1e-9 s and every speed to 1e-9 of itself over the first 20
/// impacts: the motion is rk4's, off by about (ωh)⁵/120 of itself, 3e-11 on a whole
/// 0.02 s step (measured: speeds to 3e-13, instants to 4e-11 s). Leaving out the
/// answer's fifth-order term (the velocity's ω⁴ Δv s⁴/24) puts the speeds 2e-9 off;
/// measuring on the cubic through the step's ends, 1.1e-9. (With 0.1 s steps and 1 cm between the
/// walls the seventh impact is 1.3e-9 s late, rk4's error, as it was when each coupled
/// impact ended the step.)
#[test]
fn a_coupled_ball_rattling_between_walls_strikes_at_its_closed_form_instants() {
    let (v0, d, radius, e, h) = (1.0_f64, 0.002_f64, 0.1, 0.9, 0.02);
    let half = d + radius;
    let scene = Scene::new()
        .with_world(World {
            bounds: Some(Bounds {
                min: [-half, -1.0].into(),
                max: [half, 1.0].into(),
                friction: 0.0,
                static_friction: None,
            }),
            ..world(false, e)
        })
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(radius)
                .velocity([v0, 0.0]),
        )
        .with_spring(physics::Spring::new("spring", [3.0, 0.0], "ball", 1.0, 3.0))
        .with_integrator(physics::Integrator::Rk4, h);
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.record_impacts();
    simulation.step_to(1.0).unwrap();
    let impacts = simulation.take_impacts();
    assert!(impacts.len() >= 20, "{} impacts", impacts.len());
    let most_in_a_step = (0..50)
        .map(|k| {
            let step = f64::from(k) * h..f64::from(k + 1) * h;
            impacts.iter().filter(|i| step.contains(&i.time)).count()
        })
        .max();
    assert!(
        most_in_a_step >= Some(4),
        "{most_in_a_step:?} impacts in a step"
    );
    // None of them ended its step: 50 passes through the pipeline for 50 steps (ending
    // the step at each would give one pass per impact more).
    assert_eq!(simulation.steps_taken(), 50);
    let mut time = (d / v0).asin();
    let mut speed = (v0 * v0 - d * d).sqrt();
    for (n, impact) in impacts.iter().take(20).enumerate() {
        assert!(
            (impact.time - time).abs() < 1e-9,
            "impact {n} at {} s against {time} s",
            impact.time
        );
        let error = (impact.normal_speed_before - speed).abs() / speed;
        assert!(
            error < 1e-9,
            "impact {n} at {} m/s against {speed} ({error:e})",
            impact.normal_speed_before
        );
        assert!((impact.normal_speed_after - e * impact.normal_speed_before).abs() < 1e-12);
        speed *= e;
        time += 2.0 * (d / (d * d + speed * speed).sqrt()).asin();
    }
}

/// A coupled ball strikes a free one, which crosses to a wall, bounces and comes back,
/// all inside one half-second step: the free ball's path after the coupled impact is
/// searched again (the wall's impact, and the return, would be missed otherwise). The
/// striker is the only charged ball (coupled, with no partner to pull it); elastic
/// impacts of equal masses swap velocities: the striker at 1 m/s meets the ball 0.1 m
/// away at 0.1 s, that ball's centre reaches the wall 0.1 m on at 0.2 s, and it meets
/// the striker, now at rest, on its way back at 0.3 s. Each instant to 1e-12 s (straight
/// lines, no field: rounding).
#[test]
fn a_free_ball_struck_by_a_coupled_one_is_followed_through_the_step() {
    let radius = 0.1;
    let scene = Scene::new()
        .with_world(World {
            electrostatics: true,
            bounds: Some(Bounds {
                min: [-1.0, -1.0].into(),
                max: [0.5, 1.0].into(),
                friction: 0.0,
                static_friction: None,
            }),
            ..world(false, 1.0)
        })
        .with_particle(
            Particle::new("striker", 1.0)
                .radius(radius)
                .charge(1e-6)
                .velocity([1.0, 0.0]),
        )
        .with_particle(
            Particle::new("struck", 1.0)
                .radius(radius)
                .position([0.3, 0.0]),
        )
        .with_integrator(physics::Integrator::Rk4, 0.5);
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.record_impacts();
    simulation.step().unwrap();
    let times: Vec<f64> = simulation.take_impacts().iter().map(|i| i.time).collect();
    assert_eq!(times.len(), 3, "{times:?}");
    for (time, expected) in times.iter().zip([0.1, 0.2, 0.3]) {
        assert!((time - expected).abs() < 1e-12, "{times:?}");
    }
}

/// A world with gravity and an elastic floor along y = 0 (a ramp of no thickness from
/// x = −5 m to 5 m), whose balls strike each other with `restitution`.
fn on_an_elastic_floor(restitution: f64) -> Scene {
    Scene::new()
        .with_world(World {
            restitution,
            ..World::gravity_only()
        })
        .with_ramp(
            Ramp::new("floor", [-5.0, 0.0], [5.0, 0.0])
                .thickness(0.0)
                .restitution(1.0),
        )
}

/// `scene` with ball B (mass `masses.0`) resting on the floor at the origin, held by a
/// spring of `stiffness` from 3 m beside it at its natural length (so coupled, and pulled
/// by nothing while it rests), and ball A (`masses.1`) `d` above it, both of `radius`;
/// particles 1 and 2, after a ball C resting on the floor 3 m to the left (so that
/// neither is the first particle nor has the first contact in the lists).
fn dropped_on_a_sprung_ball(
    scene: Scene,
    (mass_b, mass_a): (f64, f64),
    stiffness: f64,
    (radius, d): (f64, f64),
) -> Scene {
    scene
        .with_particle(
            Particle::new("C", 1.0)
                .radius(radius)
                .position([-3.0, radius]),
        )
        .with_particle(
            Particle::new("B", mass_b)
                .radius(radius)
                .position([0.0, radius]),
        )
        .with_particle(
            Particle::new("A", mass_a)
                .radius(radius)
                .position([0.0, 3.0 * radius + d]),
        )
        .with_spring(physics::Spring::new(
            "spring",
            [3.0, radius],
            "B",
            stiffness,
            3.0,
        ))
}

/// A coupled ball struck into the floor it rests on bounces off it: ball B rests on the
/// floor, held by a spring at its natural length (so coupled, and pulled by nothing),
/// and an equal ball A dropped from 0.2 m above it lands on it at u = √(2 g d), all
/// impacts elastic. A stops, B goes down at u, the floor sends it up at u and it gives
/// that to A: A rises at u and is back at its release height, at rest, after twice its
/// fall, t = 2 √(2d/g), with B still on the floor. To 1e-9 m and 1e-9 m/s (the instants
/// are located to 1e-12 s; rk4 is exact for the fall). Catching B on the floor as if the
/// blow were slow (the in-step catch of `simulation/coupled.rs`, for blows slower than a
/// resting contact's speed) would leave A resting on B, 0.2 m low.
#[test]
fn a_coupled_ball_struck_hard_into_its_floor_bounces_off_it() {
    let (radius, d, g) = (0.1, 0.2, 9.81);
    let scene = Scene::new().with_world(World {
        restitution: 1.0,
        bounds: Some(Bounds {
            min: [-5.0, 0.0].into(),
            max: [5.0, 10.0].into(),
            friction: 0.0,
            static_friction: None,
        }),
        ..World::gravity_only()
    });
    let scene = dropped_on_a_sprung_ball(scene, (1.0, 1.0), 1.0, (radius, d));
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.step_to(2.0 * (2.0 * d / g).sqrt()).unwrap();
    let (x, v) = (simulation.positions(), simulation.velocities());
    for (name, k, height) in [("A", 2, 3.0 * radius + d), ("B", 1, radius)] {
        assert!(
            x[k].distance(DVec2::new(0.0, height)) < 1e-9 && v[k].length() < 1e-9,
            "{name} at {} moving at {}, theory (0, {height}) at rest",
            x[k],
            v[k]
        );
    }
}

/// A coupled ball struck into the floor it rests on and sent off it flies as a ball
/// thrown up: B (3 kg) rests on an elastic floor, held by a spring at its natural length
/// (so coupled; 1e-9 N/m, which pulls it by less than 1e-15 m over the run), and A
/// (1 kg), dropped from 0.2 m above it, lands on it at u = √(2 g d). Impacts between the
/// balls are inelastic: A and B go down together at u/4, the floor sends B up at u/4,
/// and B and A then move up together at w = (3 − 1)/4 · u/4 = u/8, B off the floor. From
/// the impact on, both fly as thrown up at w: y = y₀ + w s − g s²/2, s the time since
/// the impact at t₁ = √(2d/g), until they land after 2w/g. Held to 1e-9 m at a quarter,
/// a half and three quarters of the flight (the instants are located to 1e-12 s). The
/// floor's support of B must stop at the bounce, inside the step: left on for the rest
/// of that step (B "floats" without its weight), B is some 1e-6 m high.
#[test]
fn a_coupled_ball_sent_off_its_floor_by_a_blow_flies_as_thrown_up() {
    let (radius, d, g) = (0.1, 0.2, 9.81);
    let scene = on_an_elastic_floor(0.0);
    let scene = dropped_on_a_sprung_ball(scene, (3.0, 1.0), 1e-9, (radius, d));
    let mut simulation = Simulation::new(&scene).unwrap();
    let (t1, u) = ((2.0 * d / g).sqrt(), (2.0 * g * d).sqrt());
    fly_up_together(&mut simulation, t1, u / 8.0, radius);
}

/// Balls B (particle 1, on the floor) and A (particle 2, on B), both of `radius`, go up
/// together at `up` from the floor at `from` seconds, as thrown: y = y₀ + w s − g s²/2.
/// Held to 1e-9 m at a quarter, a half and three quarters of the flight.
fn fly_up_together(simulation: &mut Simulation, from: f64, up: f64, radius: f64) {
    let g = 9.81;
    let flight = 2.0 * up / g;
    for fraction in [0.25, 0.5, 0.75] {
        let s = fraction * flight;
        simulation.step_to(from + s).expect("steps");
        let rise = up * s - 0.5 * g * s * s;
        let x = simulation.positions();
        for (name, k, start) in [("B", 1, radius), ("A", 2, 3.0 * radius)] {
            let expected = DVec2::new(0.0, start + rise);
            assert!(
                x[k].distance(expected) < 1e-9,
                "{name} at {s} s after going up: {}, theory {expected} ({:e} m off)",
                x[k],
                x[k].distance(expected)
            );
        }
    }
}

/// A coupled ball struck back into a floor it was leaving bounces where it meets the
/// floor: B (3 kg, on the spring of `dropped_on_a_sprung_ball`) starts on an elastic
/// floor rising at v₀, and A (1 kg) above it, falling at u = 1 m/s, strikes it τ = 0.5 ms
/// later, inside the first step, when B is some µm up, tens of times the touching
/// tolerance. The impact search leaves that floor to the resting contacts (B touched it at
/// the step's start). Twice: v₀ = 0.03 m/s, faster than a resting contact leaves (2 g h,
/// 0.02 m/s in the 1 ms step), so the floor lets B go and it flies freely (A's gap is
/// (u + v₀) τ: gravity does not change it); and v₀ = 0.01 m/s, slower, so the floor holds
/// B, which rises at v₀ without falling back until the blow (the gap is
/// (u + v₀) τ + g τ²/2) and then loses the floor's support. All impacts are elastic: A
/// goes up, and B down at V (the impulse formulas) until it meets the floor δ later (its
/// height + V δ − g δ²/2 = 0), which sends it up at W = −(V − g δ); from there both fly
/// freely, A ahead of B. Held to 1e-9 m at a
/// quarter, a half and three quarters of B's flight (measured: 4e-16 m). Without the
/// impact with the floor B had touched (`Contacts::closing_on_rests` finding nothing), B
/// sinks into the floor until the step's end and the next step's start bounces it:
/// 1.0e-4 m off; the held ball kept under the floor's support after the blow (not
/// released, `Motion::release`), it meets the floor later and slower: 2.5e-6 m off; the
/// support's loss added instead of taken away: 2.4e-4 m.
#[test]
fn a_coupled_ball_rising_off_its_floor_struck_back_bounces_where_it_meets_it() {
    let (radius, g, u, tb) = (0.1, 9.81, 1.0, 5e-4);
    let (mass_b, mass_a) = (3.0, 1.0);
    for (v0, held) in [(0.03, false), (0.01, true)] {
        let scene = on_an_elastic_floor(1.0);
        // Until the blow, B rises at v₀ (held) or flies (free); A falls freely.
        let fall = 0.5 * g * tb * tb;
        let (gap, height_b, v_b) = if held {
            ((u + v0) * tb + fall, v0 * tb, v0)
        } else {
            ((u + v0) * tb, v0 * tb - fall, v0 - g * tb)
        };
        let mut scene = dropped_on_a_sprung_ball(scene, (mass_b, mass_a), 1e-9, (radius, gap));
        scene.particles[1] = scene.particles[1].clone().velocity([0.0, v0]);
        scene.particles[2] = scene.particles[2].clone().velocity([0.0, -u]);
        let mut simulation = Simulation::new(&scene).unwrap();
        let v_a = -u - g * tb;
        let total = mass_a + mass_b;
        let after_b = v_b + 2.0 * mass_a / total * (v_a - v_b);
        let after_a = v_a + 2.0 * mass_b / total * (v_b - v_a);
        let height_a = 2.0 * radius + height_b;
        // B meets the floor δ later and bounces up at W.
        let delta = (after_b + (after_b * after_b + 2.0 * g * height_b).sqrt()) / g;
        let bounce = tb + delta;
        let up = -(after_b - g * delta);
        let flight = 2.0 * up / g;
        for fraction in [0.25, 0.5, 0.75] {
            let s = fraction * flight;
            simulation.step_to(bounce + s).unwrap();
            let since_blow = s + delta;
            let expected = [
                ("B", 1, radius + up * s - 0.5 * g * s * s),
                (
                    "A",
                    2,
                    radius + height_a + after_a * since_blow - 0.5 * g * since_blow * since_blow,
                ),
            ];
            let x = simulation.positions();
            for (name, k, height) in expected {
                let expected = DVec2::new(0.0, height);
                assert!(
                    x[k].distance(expected) < 1e-9,
                    "{} B: {name} at {s} s after the bounce: {}, theory {expected} ({:e} m off)",
                    if held { "held" } else { "free" },
                    x[k],
                    x[k].distance(expected)
                );
            }
        }
    }
}

/// A coupled ball struck back into a floor it was leaving passes its bounce there on to
/// the ball on it at once: as in the test above, B (3 kg, coupled) rises at v₀ = 0.01 m/s
/// off an elastic floor that holds it, and A (1 kg, falling at u = 1 m/s) strikes it
/// τ = 0.5 ms into the first step, when B is v₀ τ = 5 µm up; but the balls' impacts are
/// inelastic, so they go down together at V = (v + 3 v₀)/4 (v A's speed then), B meets
/// the floor δ later (v₀ τ + V δ − g δ²/2 = 0), which sends it up at W = −(V − g δ) into
/// A, still touching it and coming down at W: both go up together at (3 − 1)/4 · W = W/2,
/// as thrown from the floor. Held to 1e-9 m at a quarter, a half and three quarters of
/// that flight (measured: 4e-16 m). With the bounce off a surface the ball had drifted off
/// not passed on at its instant (`off_a_rest` in `simulation/coupled/response.rs`), A
/// sinks into B until the step's end, whose resting solver leaves the blow to the next
/// step's start: 2.5e-5 m off a quarter into the flight.
#[test]
fn a_coupled_ball_struck_back_into_its_floor_passes_the_bounce_on_to_the_ball_on_it() {
    let (radius, g, u, v0, tb) = (0.1, 9.81, 1.0, 0.01, 5e-4);
    let (mass_b, mass_a) = (3.0, 1.0);
    let gap = (u + v0) * tb + 0.5 * g * tb * tb;
    let scene = on_an_elastic_floor(0.0);
    let mut scene = dropped_on_a_sprung_ball(scene, (mass_b, mass_a), 1e-9, (radius, gap));
    scene.particles[1] = scene.particles[1].clone().velocity([0.0, v0]);
    scene.particles[2] = scene.particles[2].clone().velocity([0.0, -u]);
    let mut simulation = Simulation::new(&scene).unwrap();
    let v_a = -u - g * tb;
    let v = (mass_a * v_a + mass_b * v0) / (mass_a + mass_b);
    let delta = (v + (v * v + 2.0 * g * v0 * tb).sqrt()) / g;
    let w = -(v - g * delta);
    let up = w * (mass_b - mass_a) / (mass_a + mass_b);
    fly_up_together(&mut simulation, tb + delta, up, radius);
}

/// A coupled ball the floor holds stays on the floor through impacts inside the step:
/// a ball on a frictionless floor, on a spring from a point above it (natural length
/// 0.5 m, stretched to 1 m: it pulls up with 2.5 N, less than the ball's weight), slides
/// to and fro and strikes the walls 0.4 m apart elastically, several times a second. The
/// floor holds it (closed form: its centre's height is its radius at every instant). The
/// spring's answer to each blow pulls partly upwards (its axis is tilted); the floor's
/// support takes that part away, as it takes the spring's whole upward pull. Held to
/// 1e-12 of the radius at every millisecond for 5 s (the support cancels the vertical
/// acceleration exactly: measured 0). Leaving the answer's vertical part in moves the
/// ball off the floor by 2.6e-10 m (`simulation/coupled/response.rs`, `Motion::hold`);
/// leaving it in the rates of acceleration the impacts are measured on, by 1.6e-9 m.
#[test]
fn a_sprung_ball_on_the_floor_stays_on_it_through_its_impacts() {
    let radius = 0.1;
    let scene = Scene::new()
        .with_world(World {
            restitution: 1.0,
            bounds: Some(Bounds {
                min: [-0.2 - radius, 0.0].into(),
                max: [0.2 + radius, 10.0].into(),
                friction: 0.0,
                static_friction: None,
            }),
            ..World::gravity_only()
        })
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(radius)
                .position([0.0, radius])
                .velocity([2.0, 0.0]),
        )
        .with_spring(physics::Spring::new(
            "spring",
            [0.0, radius + 1.0],
            "ball",
            5.0,
            0.5,
        ));
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.record_impacts();
    let mut worst: f64 = 0.0;
    for k in 1..=5000 {
        simulation.step_to(f64::from(k) * 1e-3).unwrap();
        worst = worst.max((simulation.positions()[0].y - radius).abs());
    }
    let walls = simulation
        .take_impacts()
        .iter()
        .filter(|impact| impact.normal_speed_before > 0.5)
        .count();
    assert!(walls >= 20, "{walls} impacts with the walls");
    assert!(worst <= 1e-12 * radius, "off the floor by {worst:e} m");
}

/// The clock and the motion agree while coupled impacts end steps early: in the paper's
/// 4.1 mixture (150 balls, the charged and sprung ones coupled) with its springs damped,
/// every impact of a coupled ball ends the step (the energy ledger books a damper's power
/// over a whole step), and the next starts there. A free ball added along the top of the
/// box, its weight cancelled by an applied acceleration of (0, g), glides at (0.1, 0)
/// m/s: at every millisecond for 2 s it is at x₀ + 0.1 t, to 1e-9 m (rk4 is exact for it
/// up to rounding, 1e-12 m over the run; a clock off the motion by a piece of a step
/// would put it 1e-4 m off per millisecond). (Undamped, no step of this scene ends
/// early since blows into the floor are passed on inside the step.)
#[test]
fn a_glider_keeps_time_with_the_clock_while_coupled_impacts_end_steps_early() {
    let mut scene = physics::generated::mixed(150);
    for spring in &mut scene.springs {
        spring.damping = 0.01;
    }
    let (x0, y0) = (-1.5, 5.3);
    scene.particles.push(
        Particle::new("glider", 1.0)
            .radius(0.1)
            .position([x0, y0])
            .velocity([0.1, 0.0])
            .acceleration([0.0, 9.81]),
    );
    let glider = scene.particles.len() - 1;
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    for k in 1..=2000 {
        simulation.step().expect("the pile stays finite");
        let t = simulation.time();
        assert!(
            (t - f64::from(k) * 1e-3).abs() < 1e-12,
            "after {k} steps the clock says {t} s"
        );
        let at = simulation.positions()[glider];
        assert!(
            at.distance(DVec2::new(x0 + 0.1 * t, y0)) < 1e-9,
            "at {t} s the glider is at {at}"
        );
    }
    assert!(
        simulation.steps_taken() > 2000,
        "no step ended early: the test misses its road"
    );
}

/// A blow passed on at a step's start reaches a ball on a *damped* spring under Verlet,
/// which carries each step's end acceleration into the next: that acceleration holds the
/// damping of the velocity before the blow, and must be dropped. A free ball A (1 m/s)
/// strikes a free ball B inside a step; B touches C, and its blow reaches C at the next
/// step's start (the touching road). Equal masses, e = 1: C leaves at B's speed from
/// where the step left it, and then moves as the damped oscillator (k = 4π² N/m,
/// c = 2 N·s/m, 1 kg): x(t) = e^(−γt)(x₀ cos ωt + (v₀ + γx₀)/ω sin ωt),
/// γ = c/2m, ω² = k/m − γ². Held to 2e-6 m over 0.3 s: Verlet's own error at
/// h = 1 ms, measured 3.6e-7 m.
///
/// Three things drop the carried acceleration here, each enough alone: the impact
/// inside the step before (its paths changed), the resting solver's correction of B's
/// overlap with C, and the start's impacts. With all three dropped by hand, C is
/// 1.3e-4 m off (the acceleration kept the damping of C at rest, c·v·h/2m = 1e-3 m/s
/// slow). So a blow at a step's start always follows an impact that already dropped it,
/// and the start's own report (mutants of `impacts_now`'s return value) cannot matter.
#[test]
fn a_blow_passed_on_at_a_steps_start_drops_the_carried_acceleration() {
    let (k, c, radius) = (4.0 * std::f64::consts::PI.powi(2), 2.0, 0.1);
    let equilibrium = 2.0 * radius;
    let scene = Scene::new()
        .with_world(world(false, 1.0))
        // Meets B at 0.7996 s, inside a step: B is struck inside it and passes the blow on
        // to C at the next step's start.
        .with_particle(
            Particle::new("A", 1.0)
                .radius(radius)
                .position([-1.0 + 4e-4, 0.0])
                .velocity([1.0, 0.0]),
        )
        .with_particle(Particle::new("B", 1.0).radius(radius))
        .with_particle(
            Particle::new("C", 1.0)
                .radius(radius)
                .position([equilibrium, 0.0]),
        )
        .with_spring(
            physics::Spring::new("spring", [equilibrium + 3.0, 0.0], "C", k, 3.0).damping(c),
        )
        .with_integrator(physics::Integrator::Verlet, 1e-3);
    let mut simulation = Simulation::new(&scene).expect("a valid scene");
    simulation.record_impacts();
    while simulation.take_impacts().is_empty() {
        simulation.step().expect("a step");
        assert!(simulation.time() < 1.0, "A never struck B");
    }
    let start = simulation.time();
    let (x0, v0) = (
        simulation.positions()[2].x - equilibrium,
        simulation.velocities()[1].x,
    );
    assert_eq!(
        simulation.velocities()[2],
        DVec2::ZERO,
        "C moved before the blow"
    );
    assert!((v0 - 1.0).abs() < 1e-12, "B leaves A at {v0} m/s");
    let gamma = c / 2.0;
    let omega = (k - gamma * gamma).sqrt();
    let mut worst: f64 = 0.0;
    while simulation.time() < start + 0.3 {
        simulation.step().expect("a step");
        let t = simulation.time() - start;
        let theory = equilibrium
            + (-gamma * t).exp()
                * (x0 * (omega * t).cos() + (v0 + gamma * x0) / omega * (omega * t).sin());
        worst = worst.max((simulation.positions()[2].x - theory).abs());
    }
    let blows = simulation.take_impacts();
    assert!(
        blows
            .iter()
            .any(|i| i.time.to_bits() == start.to_bits() && i.particle == 1),
        "B's blow on C is not at the step's start: {blows:?}"
    );
    eprintln!("C is within {worst:e} m of the damped oscillator");
    assert!(worst < 2e-6, "C is {worst} m off the damped oscillator");
}
