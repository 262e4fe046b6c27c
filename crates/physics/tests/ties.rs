//! Rods and strings against theory: the large-amplitude pendulum's elliptic-integral
//! period, the double pendulum's energy, a string going slack at the instant its tension
//! vanishes and snapping taut where the projectile's path meets its length, Newton's
//! cradle on strings.
//!
//! Every run uses rk4 at the default 1 ms step unless it says otherwise.

mod common;

use common::{elliptic_k, run_to, simpson, simulation_at, start};
use physics::{DVec2, Integrator, Particle, Scene, SceneFormat, Simulation, Tie, TieKind, World};

const G: f64 = 9.81;

/// A bob of 1 kg on a rod of `length` from the origin, released at rest `angle` degrees
/// from the downward vertical.
fn pendulum(length: f64, angle: f64) -> Scene {
    pendulum_of(length, angle, 1.0, false)
}

/// The same with a bob of `mass` kilograms, the rod written from the bob to the pivot
/// when `reversed` (the constraint force then acts on the rod's `from` end).
fn pendulum_of(length: f64, angle: f64, mass: f64, reversed: bool) -> Scene {
    let (sin, cos) = angle.to_radians().sin_cos();
    let rod = if reversed {
        Tie::rod("rod", "bob", [0.0, 0.0], length)
    } else {
        Tie::rod("rod", [0.0, 0.0], "bob", length)
    };
    Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("bob", mass)
                .radius(0.1)
                .position([length * sin, -length * cos]),
        )
        .with_tie(rod)
}

/// 120° from the vertical, far from the small-angle law (which is off by 28 % there): the
/// period is 4 √(L/g) K(sin(θ₀/2)). After exactly one period the bob is back where it was
/// released, at rest; its speed there, divided by its tangential acceleration g sin θ₀,
/// is how far the simulated period is from the theory's. Tolerances: 1e-9 of the period
/// (rk4's error at 1 ms is about 1e-12 per step, the period is 4,400 steps) and 1e-8 m.
/// The rod keeps its length to 1e-12 at every sample. The same for a bob of 2.5 kg on a
/// rod written the other way round: the period does not depend on the mass, the tension
/// does.
#[test]
fn a_pendulum_at_120_degrees_keeps_the_elliptic_period() {
    for (mass, reversed) in [(1.0, false), (2.5, true)] {
        pendulum_keeps_the_elliptic_period(mass, reversed);
    }
}

fn pendulum_keeps_the_elliptic_period(mass: f64, reversed: bool) {
    let (length, angle) = (2.0, 120.0_f64);
    let scene = pendulum_of(length, angle, mass, reversed);
    let theta = angle.to_radians();
    let period = 4.0 * (length / G).sqrt() * elliptic_k((theta / 2.0).sin());
    let release = DVec2::new(length * theta.sin(), -length * theta.cos());
    let mut simulation = start(&scene);
    let mut t = 0.0;
    while t < period {
        t = (t + 0.01).min(period);
        run_to(&mut simulation, t);
        let stretch = simulation.positions()[0].length() / length - 1.0;
        assert!(
            stretch.abs() < 1e-12,
            "at t = {t} s the rod is off by {stretch:e}"
        );
    }
    let speed = simulation.velocities()[0].length();
    let period_error = speed / (G * theta.sin()) / period;
    assert!(
        period_error < 1e-9,
        "period off by {period_error:e} of {period} s"
    );
    let miss = simulation.positions()[0].distance(release);
    assert!(miss < 1e-8, "back {miss:e} m from the release point");
    // Half a period on, it is at the mirror image of the release point.
    let mut half = simulation_at(&scene, period / 2.0);
    let mirror = DVec2::new(-release.x, release.y);
    assert!(
        half.positions()[0].distance(mirror) < 1e-8,
        "{}",
        half.positions()[0]
    );
    // The tension at the release point, at rest: m g cos θ₀ (negative here: the rod
    // pushes, a string would go slack).
    half = start(&scene);
    let tension = half.tensions()[0];
    assert!(
        (tension - mass * G * theta.cos()).abs() < 1e-9,
        "tension {tension} N at release"
    );
}

/// A double pendulum of two 1 kg bobs on 1 m rods from the origin, the upper released
/// level with the pivot and the lower at `lower_y`, run for 20 s at `time_step`: the
/// largest energy error (J), with both rods checked at every sample to 1e-12.
fn double_pendulum_energy_error(lower_angle: f64, time_step: f64) -> f64 {
    let (sin, cos) = lower_angle.to_radians().sin_cos();
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("A", 1.0).radius(0.1).position([1.0, 0.0]))
        .with_particle(
            Particle::new("B", 1.0)
                .radius(0.1)
                .position([1.0 + sin, -cos]),
        )
        .with_tie(Tie::rod("upper", [0.0, 0.0], "A", 1.0))
        .with_tie(Tie::rod("lower", "A", "B", 1.0))
        .with_integrator(Integrator::Rk4, time_step);
    let mut simulation = start(&scene);
    let energy = |s: &Simulation| s.diagnostics().energy.total();
    let initial = energy(&simulation);
    let mut worst = 0.0_f64;
    for k in 1..=2000 {
        run_to(&mut simulation, f64::from(k) * 0.01);
        let x = simulation.positions();
        for (stretch, which) in [(x[0].length(), "upper"), (x[0].distance(x[1]), "lower")] {
            assert!(
                (stretch - 1.0).abs() < 1e-12,
                "{which} rod {stretch} m at t = {} s",
                simulation.time()
            );
        }
        let drift = (energy(&simulation) - initial).abs();
        assert!(
            drift.is_finite(),
            "energy {drift} at t = {}",
            simulation.time()
        );
        worst = worst.max(drift);
    }
    worst
}

/// The double pendulum is chaotic, its energy is not. Released with both rods level (the
/// lower bob whips round at up to 9 m/s), rk4 keeps the energy over 20 s to 1e-9 of the
/// pendulum's energy scale 3 m g L at half the default step, as the `double-pendulum`
/// example runs (measured 2.0e-9 J of 29 J), and to 1.5e-9 of it at the default step
/// (measured 3.0e-8 J). The error is rk4's own: it shrinks 16-fold when the step halves
/// (fourth order), which an error of the constraint handling (a projection adding
/// energy, a wrong multiplier) would not.
#[test]
fn a_double_pendulum_conserves_energy_to_the_integrators_order() {
    let scale = 3.0 * G;
    let (coarse, fine) = (
        double_pendulum_energy_error(90.0, 1e-3),
        double_pendulum_energy_error(90.0, 5e-4),
    );
    assert!(
        fine < 1e-9 * scale,
        "at 0.5 ms the energy drifted by {fine:e} J"
    );
    assert!(
        coarse < 1.5e-9 * scale,
        "at 1 ms the energy drifted by {coarse:e} J"
    );
    let order = (coarse / fine).log2();
    assert!(
        (3.5..4.5).contains(&order),
        "error order {order} ({coarse:e} J → {fine:e} J)"
    );
}

/// A ball on a string of length L, started at the bottom at √(3.5 g L): not fast enough to
/// go over the top (that takes √(5 g L)). The tension m v²/L + m g cos φ (φ from the
/// downward vertical) reaches zero where cos φ = (2 g L − v₀²)/(3 g L) = −½, at 120°,
/// with v² = g L / 2. From there the ball is a projectile until it is L from the pivot
/// again, where the string snaps taut (restitution 0: the radial speed is taken). At
/// 1 m and at 2 m (the `string-circle` example's length, where a slack instant found
/// only at the step's end shows most: the string would push for the rest of the step).
#[test]
fn a_string_goes_slack_where_its_tension_vanishes_and_snaps_taut_where_the_parabola_meets_it() {
    for length in [1.0, 2.0] {
        string_goes_slack_and_snaps_taut(length);
    }
}

fn string_goes_slack_and_snaps_taut(length: f64) {
    let v0 = (3.5 * G * length).sqrt();
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("ball", 1.0)
                .radius(0.05)
                .position([0.0, -length])
                .velocity([v0, 0.0]),
        )
        .with_tie(Tie::string("string", [0.0, 0.0], "ball", length));
    // Slack at cos φ = (2 g L − v0²)/(3 g L) = −½, 120°, then the parabola.
    let (t_slack, flight) = slack_flight(length, v0);
    // Where the parabola is L from the pivot again: bisection on the closed form.
    let (mut lo, mut hi) = (t_slack + 1e-3, t_slack + 2.0);
    assert!(
        flight(lo).length() < length && flight(hi).length() > length,
        "the bracket holds the taut instant"
    );
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if flight(mid).length() < length {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let t_taut = 0.5 * (lo + hi);
    // A microsecond before the slack instant the string still pulls; a microsecond after
    // it carries nothing and the ball falls freely: no tension at all, the acceleration g
    // to rounding (a string let go only at the step's end would still push here).
    let before = simulation_at(&scene, t_slack - 1e-6);
    assert!(
        before.tensions()[0] > 0.0,
        "L = {length}: still pulling before the slack instant: {} N",
        before.tensions()[0]
    );
    let after = simulation_at(&scene, t_slack + 1e-6);
    assert_eq!(
        after.tensions()[0].to_bits(),
        0.0_f64.to_bits(),
        "L = {length}: slack just after"
    );
    let fall = after.accelerations()[0] - DVec2::new(0.0, -G);
    assert!(
        fall.length() < 1e-12,
        "L = {length}: at t_slack + 1 µs the acceleration is off g by {fall}"
    );
    // In flight: on the parabola to 1e-9 m (rk4's error over the circular part is some
    // 1e-12 m; the slack instant is located to rounding), the string slack.
    for fraction in [0.1, 0.5, 0.9] {
        let t = t_slack + fraction * (t_taut - t_slack);
        let simulation = simulation_at(&scene, t);
        let miss = simulation.positions()[0].distance(flight(t));
        assert!(
            miss < 1e-9,
            "L = {length}: at t = {t} s, {miss:e} m off the parabola"
        );
        assert!(simulation.tensions()[0].abs() < 1e-12, "slack in flight");
    }
    // Taut at the instant the geometry says, to 1e-9 s: just before, the ball still
    // flies outward on the parabola; just after, the string has taken its radial speed.
    let radial = |s: &Simulation| s.velocities()[0].dot(s.positions()[0].normalize());
    let before = simulation_at(&scene, t_taut - 1e-9);
    assert!(
        radial(&before) > 1.0,
        "still flying outward: {} m/s",
        radial(&before)
    );
    let after = simulation_at(&scene, t_taut + 1e-9);
    assert!(
        radial(&after).abs() < 1e-6,
        "taut: radial speed {} m/s",
        radial(&after)
    );
    assert!(after.tensions()[0] > 0.0, "and pulling");
}

/// Newton's cradle hanging on strings: five touching equal balls on 4 m strings, the
/// first struck at 3 m/s at the bottom. The strings are vertical and taut, so the blow
/// passes along the row as on a table: the last ball leaves at 3 m/s and the others
/// stay still, to 1e-9 m/s. The last ball then swings up its string, its energy kept.
#[test]
fn newtons_cradle_on_strings_passes_the_blow_to_the_last_ball() {
    let scene = physics::example("newtons-cradle")
        .expect("the example exists")
        .scene()
        .expect("it loads");
    assert!(
        scene.springs.is_empty() && scene.ties.len() == 5,
        "hung on strings"
    );
    let simulation = simulation_at(&scene, 0.05);
    let v = simulation.velocities();
    for (i, v) in v.iter().enumerate().take(4) {
        assert!(v.length() < 1e-9, "ball {} moves at {v}", i + 1);
    }
    let (x, v) = (simulation.positions()[4], v[4]);
    let height = x.y + 4.0;
    let energy = 0.5 * v.length_squared() + G * height;
    assert!(
        (energy - 4.5).abs() < 1e-9 * 4.5,
        "the last ball has {energy} J/kg of 4.5"
    );
    assert!(v.x > 2.9, "and swings out: {v}");
}

/// Constraints do no work: a pendulum's ledger books nothing, and its energy closes to
/// rk4's error. A string snapping taut inelastically takes ½ m u² of the ball's radial
/// speed u, booked as an impact: a ball dropped from 0.6 m beside the pivot on a 1 m
/// string falls 0.8 m, so u = 0.8 √(2 g 0.8) (the radial direction is (0.6, −0.8)).
#[test]
fn rods_book_no_work_and_a_snapping_string_books_what_it_takes() {
    let mut simulation = start(&pendulum(2.0, 120.0));
    simulation.keep_ledger();
    let initial = simulation.diagnostics().energy.total();
    run_to(&mut simulation, 3.0);
    let ledger = simulation.ledger().expect("kept");
    assert_eq!(ledger.total().to_bits(), 0.0_f64.to_bits(), "{ledger:?}");
    let residual = simulation.diagnostics().energy.total() - initial;
    assert!(residual.abs() < 1e-9, "residual {residual:e} J");

    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("ball", 2.0).radius(0.05).position([0.6, 0.0]))
        .with_tie(Tie::string("string", [0.0, 0.0], "ball", 1.0));
    let mut simulation = start(&scene);
    simulation.keep_ledger();
    let initial = simulation.diagnostics().energy.total();
    run_to(&mut simulation, 1.0);
    let u = 0.8 * (2.0 * G * 0.8).sqrt();
    let taken = 0.5 * 2.0 * u * u;
    let ledger = simulation.ledger().expect("kept");
    assert!(
        (ledger.impacts - taken).abs() < 1e-9 * taken,
        "booked {} J of {taken} J",
        ledger.impacts
    );
    let residual = simulation.diagnostics().energy.total() + ledger.total() - initial;
    assert!(residual.abs() < 1e-8, "residual {residual:e} J");
}

/// A file's rods and strings: an unnamed one is named by its kind and number, a left-out
/// length is the distance at the start, a string snaps inelastically unless told; saving
/// and loading again gives the same scene.
#[test]
fn rods_and_strings_read_write_and_default_as_documented() {
    let text = r#"
version = 1
[[particle]]
name = "bob"
mass = 1.0
position = [3.0, -4.0]
[[particle]]
name = "B"
mass = 1.0
position = [3.0, -6.0]
[[rod]]
from = [0.0, 0.0]
to = "bob"
[[string]]
from = "bob"
to = "B"
length = 2.5
[[graph]]
y = ["rod1.tension", "string1.tension"]
"#;
    let scene = Scene::from_toml(text).expect("valid");
    assert_eq!(scene.ties.len(), 2);
    let (rod, string) = (&scene.ties[0], &scene.ties[1]);
    assert_eq!(
        (rod.name.as_str(), string.name.as_str()),
        ("rod1", "string1")
    );
    assert_eq!((rod.kind, string.kind), (TieKind::Rod, TieKind::String));
    assert!(
        (rod.length - 5.0).abs() < 1e-15,
        "the distance at the start: {}",
        rod.length
    );
    assert_eq!(string.restitution.to_bits(), 0.0_f64.to_bits());
    let again = Scene::from_toml(&scene.to_toml()).expect("its own output loads");
    assert_eq!(again, scene);
    let json = Scene::parse(&scene.to_json(), SceneFormat::Json).expect("JSON too");
    assert_eq!(json, scene);
}

/// Every way a rod or string can be wrong is refused with a message that names it.
#[test]
fn bad_rods_and_strings_are_refused_with_reasons() {
    let base = Scene::new()
        .with_particle(Particle::new("A", 1.0).position([0.0, -1.0]))
        .with_particle(Particle::new("P", 1.0).position([5.0, 0.0]).fixed());
    let cases: Vec<(Tie, &str)> = vec![
        (
            Tie::rod("r", [0.0, 0.0], "nobody", 1.0),
            "there is no particle named 'nobody'",
        ),
        (
            Tie::rod("r", "A", "A", 1.0),
            "both ends are the particle 'A'",
        ),
        (
            Tie::string("s", [0.0, 0.0], [1.0, 0.0], 1.0),
            "both ends are fixed points",
        ),
        (
            Tie::rod("r", "P", [0.0, 0.0], 5.0),
            "needs a moving particle",
        ),
        (
            Tie::rod("r", [0.0, 0.0], "A", -1.0),
            "length must be greater than 0",
        ),
        (
            Tie::string("s", [0.0, 0.0], "A", 1.0).restitution(2.0),
            "restitution must be between 0 and 1",
        ),
    ];
    for (tie, expected) in cases {
        let problems = base.clone().with_tie(tie.clone()).validate();
        assert!(
            problems.iter().any(|p| p.message.contains(expected)),
            "{tie:?}: {problems:?}"
        );
    }
    // Two 1 m rods from points 10 m apart cannot both hold one particle.
    let stretched = base
        .clone()
        .with_tie(Tie::rod("left", [0.0, 0.0], "A", 1.0))
        .with_tie(Tie::rod("right", [10.0, 0.0], "A", 1.0));
    let problems = stretched.validate();
    assert!(
        problems
            .iter()
            .any(|p| p.message.contains("cannot be kept")),
        "{problems:?}"
    );
    // Three rods pinning one particle are redundant, not contradictory: it is held.
    let pinned = base
        .with_tie(Tie::rod("a", [-1.0, -1.0], "A", 1.0))
        .with_tie(Tie::rod("b", [1.0, -1.0], "A", 1.0))
        .with_tie(Tie::rod("c", [0.0, 0.0], "A", 1.0));
    assert!(pinned.validate().is_empty(), "{:?}", pinned.validate());
    let mut simulation = start(&pinned.with_world(World::gravity_only()));
    run_to(&mut simulation, 1.0);
    assert!(
        simulation.positions()[0].distance(DVec2::new(0.0, -1.0)) < 1e-12,
        "held"
    );
}

/// The `double-pendulum` example: two copies started 1e-9 m apart. Each keeps its energy
/// (to 1e-9 of its scale 3 m g L, both started at E = 0), yet their lower bobs part:
/// within a micrometre of each other for the first 10 s (measured 4e-9 m), over half a
/// metre apart within 40 s (measured: 7 cm at 25 s, 1 m at 40 s).
#[test]
fn the_double_pendulum_example_is_chaotic_and_keeps_its_energy() {
    let scene = physics::example("double-pendulum")
        .expect("the example exists")
        .scene()
        .expect("it loads");
    let mut simulation = start(&scene);
    let copy_energy = |s: &Simulation, bobs: [usize; 2]| -> f64 {
        bobs.iter()
            .map(|&i| 0.5 * s.velocities()[i].length_squared() + G * s.positions()[i].y)
            .sum()
    };
    let mut apart: f64 = 0.0;
    for k in 1..=4000 {
        run_to(&mut simulation, f64::from(k) * 0.01);
        let (b1, b2) = (simulation.positions()[1], simulation.positions()[3]);
        let separation = (b1.y - b2.y).abs();
        if k <= 1000 {
            assert!(
                separation < 1e-6,
                "at t = {} s already {separation} m apart",
                simulation.time()
            );
        }
        apart = apart.max(separation);
        for bobs in [[0, 1], [2, 3]] {
            let energy = copy_energy(&simulation, bobs);
            assert!(
                energy.abs() < 1e-9 * 3.0 * G,
                "copy {bobs:?}: {energy:e} J at t = {} s",
                simulation.time()
            );
        }
    }
    assert!(
        apart > 0.5,
        "the copies stayed within {apart} m of each other"
    );
}

/// A pendulum on a rod (L = 1 m, released at 60°) bouncing elastically off a wall that
/// it meets at the bottom of its swing, where its velocity is along the wall's normal:
/// the bounce reverses the motion, so it is back at its release point, at rest, after
/// half a period, 2 √(L/g) K(sin 30°). The impact of a tied particle must end the step
/// and integrate the system again to its instant (the rod's force depends on the state);
/// treated as a free particle's, the rest of the step would miss that force.
#[test]
fn a_pendulum_bouncing_off_a_wall_at_the_bottom_swings_back_to_its_release() {
    use physics::Ramp;
    let (length, angle, radius) = (1.0, 60.0_f64, 0.05);
    let theta = angle.to_radians();
    let release = DVec2::new(length * theta.sin(), -length * theta.cos());
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("bob", 1.0).radius(radius).position(release))
        .with_tie(Tie::rod("rod", [0.0, 0.0], "bob", length))
        .with_ramp(Ramp::new("wall", [-radius, -1.5], [-radius, -0.5]).thickness(0.0));
    let half_period = 2.0 * (length / G).sqrt() * elliptic_k((theta / 2.0).sin());
    let simulation = simulation_at(&scene, half_period);
    let miss = simulation.positions()[0].distance(release);
    assert!(miss < 1e-8, "back {miss:e} m from the release point");
    let speed = simulation.velocities()[0].length();
    assert!(speed < 1e-7, "at rest: {speed} m/s");
}

/// A string with restitution ½: a ball dropped from 0.6 m beside the pivot of a 1 m
/// string falls 0.8 m freely, the string snaps taut where the ball is 1 m out (radial
/// unit (0.6, −0.8)) and sends it back inward at half its outward speed u, the
/// tangential speed kept: v' = v − (1 + e) u r̂. The string is then slack (its ends
/// approach), so 20 ms later the ball is on the parabola from there, to 1e-9 m.
#[test]
fn a_string_with_restitution_throws_the_ball_back_and_goes_slack() {
    let e = 0.5;
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("ball", 2.0).radius(0.05).position([0.6, 0.0]))
        .with_tie(Tie::string("string", [0.0, 0.0], "ball", 1.0).restitution(e));
    let t_snap = (2.0 * 0.8 / G).sqrt();
    let v = DVec2::new(0.0, -G * t_snap);
    let radial = DVec2::new(0.6, -0.8);
    let after = v - radial * ((1.0 + e) * v.dot(radial));
    let s = 0.02;
    let expected = DVec2::new(0.6, -0.8) + after * s + DVec2::new(0.0, -0.5 * G * s * s);
    let simulation = simulation_at(&scene, t_snap + s);
    let miss = simulation.positions()[0].distance(expected);
    assert!(miss < 1e-9, "{miss:e} m off the parabola after the bounce");
    assert!(
        simulation.tensions()[0].abs() < 1e-12,
        "slack after the bounce"
    );
}

/// A rod whose ends start at another distance than its length pulls them onto it before
/// the first step, along the rod (the smallest move): a bob placed 2.5 m out on a 2 m
/// rod starts 2 m out in the same direction, and a velocity along the rod is taken.
#[test]
fn a_rod_puts_its_ends_at_its_length_at_the_start() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("bob", 1.0)
                .radius(0.1)
                .position([1.5, -2.0])
                .velocity([3.0, -4.0]),
        )
        .with_tie(Tie::rod("rod", [0.0, 0.0], "bob", 2.0));
    let simulation = start(&scene);
    let x = simulation.positions()[0];
    assert!(x.distance(DVec2::new(1.2, -1.6)) < 1e-12, "{x}");
    let v = simulation.velocities()[0];
    assert!(
        v.length() < 1e-12,
        "the velocity was all along the rod: {v}"
    );
}

/// A triple pendulum (three 1 kg bobs on 1 m rods, released level): one island of three
/// links, so every row of the constraint solve is used. Over 10 s at 0.5 ms its energy
/// stays within 1e-9 of its scale 6 m g L (measured 4.6e-8 J of 59 J), and every rod
/// keeps its length to 1e-12. The bobs are 1 mm across so that they never strike each
/// other: an impact between tied bobs is resolved as between free ones and then put
/// back onto the rods, which takes energy (2.5 J in these 10 s with 0.1 m bobs; see
/// `docs/scene-format.md`).
#[test]
fn a_triple_pendulum_keeps_its_energy_and_its_lengths() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(Particle::new("A", 1.0).radius(0.001).position([1.0, 0.0]))
        .with_particle(Particle::new("B", 1.0).radius(0.001).position([2.0, 0.0]))
        .with_particle(Particle::new("C", 1.0).radius(0.001).position([3.0, 0.0]))
        .with_tie(Tie::rod("top", [0.0, 0.0], "A", 1.0))
        .with_tie(Tie::rod("middle", "A", "B", 1.0))
        .with_tie(Tie::rod("bottom", "B", "C", 1.0))
        .with_integrator(Integrator::Rk4, 5e-4);
    let mut simulation = start(&scene);
    let initial = simulation.diagnostics().energy.total();
    let mut worst = 0.0_f64;
    for k in 1..=1000 {
        run_to(&mut simulation, f64::from(k) * 0.01);
        let x = simulation.positions();
        for (length, which) in [
            (x[0].length(), "top"),
            (x[0].distance(x[1]), "middle"),
            (x[1].distance(x[2]), "bottom"),
        ] {
            assert!((length - 1.0).abs() < 1e-12, "{which} rod {length} m");
        }
        let drift = (simulation.diagnostics().energy.total() - initial).abs();
        assert!(
            drift.is_finite(),
            "energy {drift} at t = {}",
            simulation.time()
        );
        worst = worst.max(drift);
    }
    assert!(worst < 1e-9 * 6.0 * G, "energy drifted by {worst:e} J");
}

/// A string already at full length whose ball moves outward at the very start of the
/// run snaps taut then, before the first step: in no field, a ball 1 m below the pivot
/// moving at (1, −0.5) m/s. Inelastic (the default), its radial 0.5 m/s is taken and it
/// goes round at 1 m/s, at (sin t, −cos t) m; with restitution ½ the radial speed comes
/// back as 0.25 m/s inward and the ball flies straight, the string slack, at
/// (t, −1 + 0.25 t) m until it meets the string's length again at t = 0.5/1.0625 s.
/// To 1e-9 m (rk4 on a circle at 1 ms errs by about 1e-13 m in a second).
#[test]
fn a_string_at_full_length_snaps_taut_at_the_start_of_the_run() {
    let scene = |restitution: f64| {
        Scene::new()
            .with_world(World::no_forces())
            .with_particle(
                Particle::new("ball", 1.5)
                    .radius(0.05)
                    .position([0.0, -1.0])
                    .velocity([1.0, -0.5]),
            )
            .with_tie(Tie::string("string", [0.0, 0.0], "ball", 1.0).restitution(restitution))
    };
    let mut round = start(&scene(0.0));
    for t in [0.001, 0.5, 1.0, 2.0] {
        run_to(&mut round, t);
        let expected = DVec2::new(t.sin(), -t.cos());
        let at = round.positions()[0];
        assert!(
            at.distance(expected) < 1e-9,
            "t = {t}: at {at}, not {expected}"
        );
    }
    let mut thrown = start(&scene(0.5));
    for t in [0.001, 0.2, 0.45] {
        run_to(&mut thrown, t);
        let expected = DVec2::new(t, -1.0 + 0.25 * t);
        let at = thrown.positions()[0];
        assert!(
            at.distance(expected) < 1e-9,
            "t = {t}: at {at}, not {expected}"
        );
        let v = thrown.velocities()[0];
        assert!(
            v.distance(DVec2::new(1.0, 0.25)) < 1e-9,
            "t = {t}: moving at {v}"
        );
    }
}

/// Two free bodies of 1 kg and 3 kg on a 1 m rod, no forces. Started with the light end
/// moving along the rod at 1 m/s and the heavy one at rest, the rod takes the motion
/// along it out as an inelastic blow: both ends move on at the centre of mass's speed,
/// 1 × 1 / (1 + 3) = 0.25 m/s, the momentum 1 kg·m/s kept (weighting the two ends equally
/// would give 0.5 m/s each and double it). Then the centre of mass moves on uniformly.
/// Both ways round, so neither end's weight can hide the other's. To 1e-12.
#[test]
fn a_rod_between_unequal_masses_keeps_the_momentum_and_the_centre_of_mass() {
    for reversed in [false, true] {
        let (light, heavy) = (
            Particle::new("light", 1.0)
                .radius(0.05)
                .velocity([1.0, 0.0]),
            Particle::new("heavy", 3.0)
                .radius(0.05)
                .position([1.0, 0.0]),
        );
        let rod = if reversed {
            Tie::rod("rod", "heavy", "light", 1.0)
        } else {
            Tie::rod("rod", "light", "heavy", 1.0)
        };
        let scene = Scene::new()
            .with_world(World::no_forces())
            .with_particle(light)
            .with_particle(heavy)
            .with_tie(rod);
        let mut simulation = start(&scene);
        for (i, v) in simulation.velocities().iter().enumerate() {
            assert!(
                v.distance(DVec2::new(0.25, 0.0)) < 1e-12,
                "reversed {reversed}: end {i} starts at {v} m/s, not the centre of mass's 0.25"
            );
        }
        let centre = |s: &Simulation| (s.positions()[0] + s.positions()[1] * 3.0) / 4.0;
        run_to(&mut simulation, 10.0);
        let momentum = simulation.diagnostics().momentum;
        assert!(
            momentum.distance(DVec2::new(1.0, 0.0)) < 1e-12,
            "reversed {reversed}: momentum {momentum}"
        );
        let drift = centre(&simulation).distance(DVec2::new(0.75 + 2.5, 0.0));
        assert!(
            drift < 1e-12,
            "reversed {reversed}: the centre of mass is {drift:e} m off"
        );
    }
}

/// A dumbbell of 1 kg and 3 kg on a 1 m rod spinning at 2 rad/s about its centre of mass,
/// which sits still at the origin (the light end 0.75 m from it, the heavy 0.25 m). Over
/// 10 s (over three turns, 10,000 projections) the centre of mass stays put to 1e-12 m
/// and the momentum at 0 to 1e-12 kg·m/s; each end keeps its circle and its speed. A
/// projection weighted wrongly moves the centre a little at every step (by 2e-3 m).
#[test]
fn a_spinning_dumbbell_of_unequal_masses_keeps_its_centre_of_mass_still() {
    let omega = 2.0;
    let scene = Scene::new()
        .with_world(World::no_forces())
        .with_particle(
            Particle::new("light", 1.0)
                .radius(0.05)
                .position([-0.75, 0.0])
                .velocity([0.0, -0.75 * omega]),
        )
        .with_particle(
            Particle::new("heavy", 3.0)
                .radius(0.05)
                .position([0.25, 0.0])
                .velocity([0.0, 0.25 * omega]),
        )
        .with_tie(Tie::rod("rod", "light", "heavy", 1.0));
    let mut simulation = start(&scene);
    for k in 1..=100 {
        run_to(&mut simulation, 0.1 * f64::from(k));
        let x = simulation.positions();
        let centre = (x[0] + x[1] * 3.0) / 4.0;
        assert!(
            centre.length() < 1e-12,
            "t = {}: the centre of mass is at {centre}",
            simulation.time()
        );
        let momentum = simulation.diagnostics().momentum;
        assert!(momentum.length() < 1e-12, "momentum {momentum}");
        for (i, radius) in [(0, 0.75), (1, 0.25)] {
            assert!(
                (x[i].length() - radius).abs() < 1e-12,
                "end {i} off its circle"
            );
            let speed = simulation.velocities()[i].length();
            assert!(
                (speed - radius * omega).abs() < 1e-9,
                "end {i} at {speed} m/s"
            );
        }
    }
}

/// The circular motion's closed form for a ball on a string of `length` started at the
/// bottom at `v0` (too slow for the top): the slack angle φ, where m v²/L + m g cos φ =
/// 0, the instant the ball reaches it (∫ L dφ / v by Simpson's rule), and the flight
/// from there, as a function of time (the ball's position relative to its pivot).
fn slack_flight(length: f64, v0: f64) -> (f64, impl Fn(f64) -> DVec2) {
    let phi_slack = ((2.0 * G * length - v0 * v0) / (3.0 * G * length)).acos();
    let speed = move |phi: f64| (v0 * v0 - 2.0 * G * length * (1.0 - phi.cos())).sqrt();
    let t_slack = simpson(|phi| length / speed(phi), 0.0, phi_slack, 200_000);
    let (sin, cos) = phi_slack.sin_cos();
    let p_slack = DVec2::new(length * sin, -length * cos);
    let v_slack = DVec2::new(cos, sin) * speed(phi_slack);
    let flight = move |t: f64| {
        let s = t - t_slack;
        p_slack + v_slack * s + DVec2::new(0.0, -0.5 * G * s * s)
    };
    (t_slack, flight)
}

/// Two strings going slack inside the same step (about 1 ms): two balls on 0.25 m strings, 2 m
/// apart (nothing joins them), started at the bottom a little too slowly for the top, the
/// second faster so that its string goes slack a fraction of the step after the first's.
/// Each event is taken at its own instant, the earlier first: both balls then fly on
/// their own parabolas to 1e-9 m. Taking the later event first would leave the first
/// string pulling the wrong way for the rest of the step (a speed error of T′Δ²/2m, some
/// 1e-4 m/s), and its ball 1e-5 m off its parabola a tenth of a second later.
#[test]
fn two_strings_going_slack_in_one_step_each_go_at_their_instant() {
    let length = 0.25;
    let v_first = (3.5 * G * length).sqrt();
    let (t_first, first) = slack_flight(length, v_first);
    // A step of about 1 ms that puts the first slack instant a fifth into a step, and the
    // second's 0.6 of a step later, in the same step. From √(3.5 g L) up the slack instant
    // grows with the starting speed, so bisection finds the second ball's speed.
    let h = t_first / 240.2;
    let target = t_first + 0.6 * h;
    let (mut lo, mut hi) = (v_first, (4.9 * G * length).sqrt());
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if slack_flight(length, mid).0 < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let v_second = 0.5 * (lo + hi);
    let (t_second, second) = slack_flight(length, v_second);
    assert!(
        (t_second - target).abs() < 1e-9 && t_second < h * ((t_first / h).floor() + 1.0),
        "both in one step of {h} s: {t_first} s and {t_second} s"
    );
    let offset = DVec2::new(2.0, 0.0);
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(Integrator::Rk4, h)
        .with_particle(
            Particle::new("a", 1.0)
                .radius(0.02)
                .position([0.0, -length])
                .velocity([v_first, 0.0]),
        )
        .with_particle(
            Particle::new("b", 1.0)
                .radius(0.02)
                .position([offset.x, -length])
                .velocity([v_second, 0.0]),
        )
        // The later event's string first, so that keeping the first string found (or the
        // last) is not the same as keeping the earliest event.
        .with_tie(Tie::string("sb", [offset.x, 0.0], "b", length))
        .with_tie(Tie::string("sa", [0.0, 0.0], "a", length));
    let t = t_first.max(t_second) + 0.1;
    let simulation = simulation_at(&scene, t);
    for (i, expected) in [first(t), second(t) + offset].into_iter().enumerate() {
        let miss = simulation.positions()[i].distance(expected);
        assert!(
            miss < 1e-9,
            "ball {i}: {miss:e} m off its parabola at t = {t} s"
        );
    }
}

/// A string of 5 m from a 1 kg ball to a body of 1e12 kg flying away from it at (3, 1)
/// m/s under gravity, the ball on a 2 m rod to a free 1 kg pivot: the heavy body drags
/// the pair along. f64 ties masses a trillion apart: every sample keeps the string and
/// the rod at their lengths to a billionth (the run itself ends, in words, beyond that),
/// and the heavy body falls freely — the pair's pull changes its path by 1e-12 of the
/// ball's — along x = 3t, y = 5 + t − g t²/2 to 1e-9 m, or the Euler methods' own
/// closed forms, y = 5 + t − g t (t ∓ h)/2. Every integrator.
#[test]
fn masses_a_trillion_apart_hold_their_links_to_a_billionth() {
    for integrator in Integrator::ALL {
        let scene = Scene::new()
            .with_world(World::gravity_only())
            .with_integrator(integrator, 1e-3)
            .with_particle(Particle::new("light", 1.0).radius(0.1))
            .with_particle(
                Particle::new("heavy", 1e12)
                    .radius(0.1)
                    .position([0.0, 5.0])
                    .velocity([3.0, 1.0]),
            )
            .with_particle(Particle::new("pivot", 1.0).radius(0.1).position([2.0, 0.0]))
            .with_tie(Tie::rod("rod", "light", "pivot", 2.0))
            .with_tie(Tie::string("string", "light", "heavy", 5.0));
        let mut simulation = start(&scene);
        for k in 1..=20 {
            let t = 0.05 * f64::from(k);
            run_to(&mut simulation, t);
            let x = simulation.positions();
            let string = x[0].distance(x[1]) / 5.0 - 1.0;
            let rod = x[0].distance(x[2]) / 2.0 - 1.0;
            assert!(
                string.abs() < 1e-9 && rod.abs() < 1e-9,
                "{integrator:?} at {t} s: string off by {string:e}, rod by {rod:e}"
            );
            let lag = match integrator {
                Integrator::Euler => -1e-3,
                Integrator::SemiImplicitEuler => 1e-3,
                _ => 0.0,
            };
            let free = DVec2::new(3.0 * t, 5.0 + t - G * t * (t + lag) / 2.0);
            assert!(
                x[1].distance(free) < 1e-9,
                "{integrator:?} at {t} s: the heavy body is {} m off its fall",
                x[1].distance(free)
            );
        }
        assert!(
            simulation.positions()[0].length() > 1.0,
            "{integrator:?}: the ball was dragged along"
        );
    }
}

/// A rod too far from the origin for its length — a 1 m pendulum at (1e9, 1e9) m, where
/// positions are rounded to 1.2e-7 m — cannot be held to a billionth of its length, and
/// the run ends saying so rather than with a rod that is not its length.
#[test]
fn a_link_too_far_from_the_origin_for_its_length_is_named() {
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("bob", 1.0)
                .radius(0.1)
                .position([1e9, 1e9 - 1.0])
                .velocity([1.0, 0.0]),
        )
        .with_tie(Tie::rod("rod", [1e9, 1e9], "bob", 1.0));
    let mut simulation = start(&scene);
    let error = simulation.step_to(1.0).expect_err("the rod cannot be held");
    assert!(
        matches!(error, physics::SimulationError::TieTooFar { .. }),
        "{error}"
    );
    assert!(
        error.to_string().contains("too far from the origin"),
        "{error}"
    );
}
