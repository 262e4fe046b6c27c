//! Kepler orbits around a fixed sun with G·M = 1 (G set to 1, M = 1 kg): the closed-form
//! circular orbit has radius 1, speed 1 and period 2π; an ellipse conserves the energy
//! v²/2 − 1/r exactly.

use std::f64::consts::PI;

use physics::{DVec2, Integrator, Particle, Scene, Simulation, World};

fn kepler(integrator: Integrator, time_step: f64, speed: f64) -> Scene {
    let mut world = World::weightless();
    world.gravitational_constant = 1.0;
    let mut scene = Scene::new()
        .with_world(world)
        .with_integrator(integrator, time_step)
        .with_particle(Particle::new("Sun", 1.0).fixed())
        .with_particle(
            Particle::new("Planet", 1e-9)
                .radius(0.01)
                .position([1.0, 0.0])
                .velocity([0.0, speed]),
        );
    scene.simulation.tolerance = 1e-12;
    scene
}

/// After exactly one period the planet is back at its start: dopri5 at tolerance 1e-12
/// keeps the accumulated error of ~10³ steps near 1e-10, well within 1e-8 of the radius.
#[test]
fn circular_orbit_returns_to_its_start_after_one_period_with_dopri5() {
    let mut simulation = Simulation::new(&kepler(Integrator::Dopri5, 0.05, 1.0)).unwrap();
    simulation.step_to(2.0 * PI).unwrap();
    let miss = simulation.positions()[1].distance(DVec2::new(1.0, 0.0));
    assert!(miss < 1e-8, "missed the start by {miss} m on a 1 m orbit");
    // Half way round it is at the opposite point, at the same radius.
    let mut simulation = Simulation::new(&kepler(Integrator::Dopri5, 0.05, 1.0)).unwrap();
    simulation.step_to(PI).unwrap();
    let miss = simulation.positions()[1].distance(DVec2::new(-1.0, 0.0));
    assert!(miss < 1e-8, "half-period position off by {miss} m");
}

/// Energy per unit mass of the planet, v²/2 − GM/r.
fn specific_energy(simulation: &Simulation) -> f64 {
    let (x, v) = (simulation.positions()[1], simulation.velocities()[1]);
    0.5 * v.length_squared() - 1.0 / x.length()
}

/// The largest |ΔE| and the mean ΔE over orbits `first..last` (period `period`).
fn energy_error(
    simulation: &mut Simulation,
    start: f64,
    period: f64,
    orbits: std::ops::Range<u32>,
) -> (f64, f64) {
    let samples_per_orbit = 200;
    let (mut worst, mut sum, mut count) = (0.0_f64, 0.0, 0.0);
    for k in orbits.start * samples_per_orbit..orbits.end * samples_per_orbit {
        simulation
            .step_to(f64::from(k) * period / f64::from(samples_per_orbit))
            .expect("the orbit integrates");
        let error = specific_energy(simulation) - start;
        // Not `f64::max`, which passes a NaN by.
        assert!(
            error.is_finite(),
            "energy error {error} at t = {}",
            simulation.time()
        );
        worst = worst.max(error.abs());
        sum += error;
        count += 1.0;
    }
    (worst, sum / count)
}

/// Velocity Verlet is symplectic: on an eccentric orbit (e ≈ 0.44) its energy error
/// oscillates within each orbit but does not grow. Over orbits 90–100 it must be no larger
/// than over orbits 0–10 (20 % allowance for sampling different phases), and its mean
/// must not have moved by more than a tenth of that amplitude — a secular drift of
/// even 1 % of the amplitude per orbit would break both.
#[test]
fn verlet_energy_error_on_an_eccentric_orbit_stays_bounded_over_100_orbits() {
    assert_energy_error_bounded(Integrator::Verlet, 2e-3, 1.2, 90, 1e-4);
}

/// On the eccentric orbit started at `speed`, at `time_step`: the energy error over
/// orbits 0–10 is positive and under `limit` J/kg; over the ten orbits from `late` it
/// is no larger (20 % allowance for sampling different phases), and its mean has not
/// moved by more than a tenth of the early amplitude.
fn assert_energy_error_bounded(
    integrator: Integrator,
    time_step: f64,
    speed: f64,
    late: u32,
    limit: f64,
) {
    let semi_major_axis = 1.0 / (2.0 - speed * speed);
    let period = 2.0 * PI * semi_major_axis.powf(1.5);
    let mut simulation =
        Simulation::new(&kepler(integrator, time_step, speed)).expect("a valid scene");
    let start = specific_energy(&simulation);
    let (early_worst, early_mean) = energy_error(&mut simulation, start, period, 0..10);
    simulation
        .step_to(f64::from(late) * period)
        .expect("the orbit integrates");
    let (late_worst, late_mean) = energy_error(&mut simulation, start, period, late..late + 10);
    assert!(
        early_worst > 0.0 && early_worst < limit,
        "{integrator}: early amplitude {early_worst}"
    );
    assert!(
        late_worst <= 1.2 * early_worst,
        "{integrator}: grew from {early_worst} to {late_worst}"
    );
    assert!(
        (late_mean - early_mean).abs() < 0.1 * early_worst,
        "{integrator}: mean drifted from {early_mean} to {late_mean} (amplitude {early_worst})"
    );
}

/// An eccentric orbit of eccentricity 0.5 about a fixed centre of attraction strength
/// `mu` (m³/s² per unit of the planet's mass), starting at periapsis rₚ = 1 m on +x:
/// vₚ = √(μ (1 + e)/rₚ), semi-major axis a = rₚ/(1 − e) = 2 m, apoapsis 3 m, period
/// T = 2π √(a³/μ). Only an inverse-square law closes the orbit at T with the apoapsis at
/// 3 m; only the right constant gives that T.
fn assert_kepler_ellipse(scene: &Scene, mu: f64, what: &str) {
    let period = 2.0 * PI * (8.0 / mu).sqrt();
    let mut simulation = Simulation::new(scene).expect("a valid scene");
    simulation
        .step_to(period / 2.0)
        .expect("the orbit integrates");
    let apoapsis = simulation.positions()[1];
    assert!(
        apoapsis.distance(DVec2::new(-3.0, 0.0)) < 1e-8,
        "{what}: at T/2 at {apoapsis}, theory (−3, 0)"
    );
    simulation.step_to(period).expect("the orbit integrates");
    let back = simulation.positions()[1];
    assert!(
        back.distance(DVec2::new(1.0, 0.0)) < 1e-8,
        "{what}: after one period at {back}, theory (1, 0)"
    );
}

fn periapsis_speed(mu: f64) -> f64 {
    (mu * 1.5).sqrt()
}

/// Gravitation with a non-default G: G = 0.5, M = 3 kg, so μ = G M = 1.5 m³/s². dopri5
/// at 1e-12 keeps the apsides within 1e-8 m over the orbit.
#[test]
fn an_eccentric_gravitational_orbit_has_keplers_period_and_apsides_for_any_g() {
    let mu = 1.5;
    let mut world = World::weightless();
    world.gravitational_constant = 0.5;
    world.electrostatics = false;
    let mut scene = Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Dopri5, 0.05)
        .with_particle(Particle::new("Sun", 3.0).fixed())
        .with_particle(
            Particle::new("Planet", 1e-9)
                .radius(0.01)
                .position([1.0, 0.0])
                .velocity([0.0, periapsis_speed(mu)]),
        );
    scene.simulation.tolerance = 1e-12;
    assert_kepler_ellipse(&scene, mu, "gravitation, G = 0.5");
}

/// Coulomb attraction with a non-default k: k = 2, q = +1.5 C fixed and −0.25 C on a
/// 0.5 kg body, so μ = k |q₁ q₂| / m = 1.5 m³/s². Gravitation off.
#[test]
fn an_eccentric_coulomb_orbit_has_keplers_period_and_apsides_for_any_k() {
    let mu = 1.5;
    let mut world = World::weightless();
    world.gravitation = false;
    world.coulomb_constant = 2.0;
    let mut scene = Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Dopri5, 0.05)
        .with_particle(Particle::new("Nucleus", 1.0).charge(1.5).fixed())
        .with_particle(
            Particle::new("Electron", 0.5)
                .radius(0.01)
                .charge(-0.25)
                .position([1.0, 0.0])
                .velocity([0.0, periapsis_speed(mu)]),
        );
    scene.simulation.tolerance = 1e-12;
    assert_kepler_ellipse(&scene, mu, "Coulomb, k = 2");
}

/// dopri5's step control at work: an orbit of eccentricity 0.9 (GM = 1, periapsis 0.1 m,
/// so a = 1 m and T = 2π s) with a largest step of a whole second. A fixed step that large
/// would fling the planet off at periapsis, where it moves at √19 m/s; the controller must
/// shrink the step there (rejecting the first tries) and let it grow on the slow side. At
/// tolerance 1e-10 the planet is at apoapsis (−1.9, 0) at T/2 and back at periapsis at T
/// within 1e-6 m.
#[test]
fn dopri5_controls_its_step_through_a_close_periapsis() {
    let mu: f64 = 1.0;
    let periapsis = 0.1;
    let speed = (mu * 1.9 / periapsis).sqrt();
    let mut world = World::weightless();
    world.gravitational_constant = 1.0;
    world.electrostatics = false;
    let mut scene = Scene::new()
        .with_world(world)
        .with_integrator(Integrator::Dopri5, 1.0)
        .with_particle(Particle::new("Sun", 1.0).radius(0.01).fixed())
        .with_particle(
            Particle::new("Planet", 1e-9)
                .radius(0.001)
                .position([periapsis, 0.0])
                .velocity([0.0, speed]),
        );
    scene.simulation.tolerance = 1e-10;
    let mut simulation = Simulation::new(&scene).unwrap();
    simulation.step_to(PI).unwrap();
    let apoapsis = simulation.positions()[1];
    assert!(
        apoapsis.distance(DVec2::new(-1.9, 0.0)) < 1e-6,
        "at T/2 at {apoapsis}, theory (−1.9, 0)"
    );
    simulation.step_to(2.0 * PI).unwrap();
    let back = simulation.positions()[1];
    assert!(
        back.distance(DVec2::new(periapsis, 0.0)) < 1e-6,
        "after one period at {back}, theory (0.1, 0)"
    );
    assert!(
        simulation.steps_taken() > 20,
        "the step shrank near periapsis: {} steps",
        simulation.steps_taken()
    );
}

/// PEFRL is fourth order and symplectic. On the same eccentric orbit (e ≈ 0.44) at a step
/// of 0.01 s, five times Verlet's above: after exactly ten periods the planet is back at
/// its start within 1e-6 m (measured 2.7e-8 m; Verlet at this step misses by 7.9e-3 m),
/// the energy error over orbits 0–10 is under 1e-9 of the 0.28 J/kg binding energy
/// (measured 2.6e-11 J/kg), and over orbits 40–50 it has neither grown (20 % allowance
/// for sampling) nor drifted.
#[test]
fn pefrl_closes_an_eccentric_orbit_and_keeps_its_energy_error_bounded() {
    let speed: f64 = 1.2;
    let semi_major_axis = 1.0 / (2.0 - speed * speed);
    let period = 2.0 * PI * semi_major_axis.powf(1.5);
    for (integrator, closes) in [(Integrator::Pefrl, true), (Integrator::Verlet, false)] {
        let mut simulation = Simulation::new(&kepler(integrator, 1e-2, speed)).unwrap();
        simulation.step_to(10.0 * period).unwrap();
        let miss = simulation.positions()[1].distance(DVec2::new(1.0, 0.0));
        assert_eq!(
            miss < 1e-6,
            closes,
            "{integrator}: missed the start by {miss} m after ten orbits"
        );
    }
    // The binding energy is 0.28 J/kg.
    assert_energy_error_bounded(Integrator::Pefrl, 1e-2, speed, 40, 1e-9 * 0.28);
}
