//! `newtonlab bench`: simulation speed, measured on this machine.
//!
//! Three scenes, all generated so that any size can be measured:
//! - `cloud` ([`physics::generated::charged_cloud`]): `n` particles that all attract by
//!   gravitation and attract or repel by Coulomb's law, so every step evaluates all
//!   n(n−1)/2 pairs once per force evaluation; reports pair interactions per second;
//! - `pit` ([`physics::generated::ball_pit`]): `n` balls dropped into a box at the app's
//!   time step (1 ms), measured from the drop, through the crash, to rest: contacts;
//! - `mixed` ([`physics::generated::mixed`]): the pit with charges and springs, the scene
//!   of `validate`'s processing-time table (the paper's 4.1), measured like the pit;
//! - `scrub`: the ball pit recorded by the app's time machine
//!   ([`newtonlab_app::timeline`]) for a simulated interval, then gone back to 20 moments
//!   spread over it: the keyframes' count, interval and memory, and the time to show a
//!   moment again;
//! - `cluster` ([`physics::generated::cluster`]): `n` bodies in orbit in a disc, their
//!   gravitation summed with the Barnes–Hut tree; reports whole force evaluations per
//!   second.
//!
//! The wall clock is read here, in the binary: the library never reads clocks.

use std::sync::OnceLock;
use std::time::{Duration, Instant};

use physics::{Integrator, Profile, Simulation, Stage};

use crate::Failure;

/// Which scene to measure.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
enum BenchScene {
    /// Mutually gravitating, charged particles: pairwise forces.
    Cloud,
    /// Balls dropped into a box: impacts and resting contact.
    Pit,
    /// The pit with every tenth ball charged and every tenth pair joined by a spring:
    /// the scene of `validate`'s processing-time table (the paper's 4.1).
    Mixed,
    /// A star cluster summed with the Barnes–Hut tree: gravitation at scale.
    Cluster,
    /// The app's time machine: the pit recorded for `--seconds` simulated seconds as the
    /// app records a run, then gone back to moments spread over it.
    Scrub,
    /// An experiment series: a 20 × 20 grid (launch angle × quadratic drag) of a thrown
    /// ball, each run measured for its range, on one thread and on `--threads`.
    Sweep,
}

#[derive(Debug, clap::Args)]
pub(crate) struct BenchArgs {
    /// The scene.
    #[arg(long, value_enum, default_value = "cloud")]
    scene: BenchScene,
    /// Number of particles.
    #[arg(long, default_value_t = 1000)]
    particles: usize,
    /// Integrator to measure.
    #[arg(long, default_value = "rk4", value_parser = parse_integrator)]
    integrator: Integrator,
    /// Cloud: seconds of measurement (after one warm-up step). Pit: simulated seconds
    /// from the drop (the whole fall, crash and settling).
    #[arg(long, default_value_t = 3.0)]
    seconds: f64,
    /// Threads for the contact search and the direct pair sum (default: every core; 1
    /// for the single-thread figure). Results are bit-identical for any number.
    #[arg(long)]
    threads: Option<usize>,
}

/// The most bodies `bench` builds.
const MOST_PARTICLES: usize = 10_000_000;
/// The longest `--seconds`: an hour.
const MOST_SECONDS: f64 = 3600.0;
/// The most `--threads`: far more than any machine's cores.
const MOST_THREADS: usize = 1024;

fn parse_integrator(name: &str) -> Result<Integrator, String> {
    name.parse()
        .map_err(|e: physics::UnknownIntegrator| e.to_string())
}

/// Force evaluations per step of each fixed-step method.
fn evaluations_per_step(integrator: Integrator) -> u64 {
    match integrator {
        Integrator::Euler | Integrator::SemiImplicitEuler | Integrator::Verlet => 1,
        Integrator::Rk4 | Integrator::Pefrl => 4,
        Integrator::Dopri5 => 6,
    }
}

/// `--seconds` and `--particles` within what a benchmark can do.
fn check_args(args: &BenchArgs) -> Result<(), Failure> {
    // An hour at most: simulated seconds of the pit, or seconds of measurement.
    if !(args.seconds.is_finite() && args.seconds > 0.0 && args.seconds <= MOST_SECONDS) {
        return Err(Failure::Input(format!(
            "--seconds must be greater than 0 and at most {MOST_SECONDS}; got {}",
            args.seconds
        )));
    }
    // Threads beyond a few per core only cost their start, seconds for thousands.
    if let Some(threads) = args.threads
        && !(1..=MOST_THREADS).contains(&threads)
    {
        return Err(Failure::Input(format!(
            "--threads must be between 1 and {MOST_THREADS}; got {threads}"
        )));
    }
    // At least one body (none divides by zero in the figures); a bound on the count,
    // since an allocation that fails aborts the process (a billion did).
    if !(1..=MOST_PARTICLES).contains(&args.particles) {
        return Err(Failure::Input(format!(
            "--particles must be between 1 and {MOST_PARTICLES}; got {}",
            args.particles
        )));
    }
    Ok(())
}

pub(crate) fn bench(args: &BenchArgs) -> Result<(), Failure> {
    check_args(args)?;
    if matches!(args.scene, BenchScene::Scrub) {
        return scrub(args);
    }
    if matches!(args.scene, BenchScene::Sweep) {
        return sweep(args);
    }
    let scene = match args.scene {
        BenchScene::Cloud => {
            physics::generated::charged_cloud(args.particles).with_integrator(args.integrator, 1e-4)
        }
        BenchScene::Pit | BenchScene::Scrub | BenchScene::Sweep => {
            physics::generated::ball_pit(args.particles).with_integrator(args.integrator, 1e-3)
        }
        BenchScene::Mixed => {
            physics::generated::mixed(args.particles).with_integrator(args.integrator, 1e-3)
        }
        BenchScene::Cluster => {
            physics::generated::cluster(args.particles).with_integrator(args.integrator, 1e-3)
        }
    };
    let mut simulation = Simulation::new(&scene).map_err(|e| Failure::Input(e.to_string()))?;
    let tree_error = matches!(args.scene, BenchScene::Cluster)
        .then(|| tree_error(&scene, &simulation))
        .flatten();
    simulation.set_threads(args.threads.unwrap_or_else(physics::every_core));
    let fail = |e: physics::SimulationError| Failure::Simulation(e.to_string());
    simulation.step().map_err(fail)?;
    simulation.set_clock(Some(clock));
    let advances_before = simulation.steps_taken();
    let budget = Duration::from_secs_f64(args.seconds);
    let start = Instant::now();
    let mut steps: u64 = 0;
    // The cloud's cost per step is the same throughout; the pit's changes as it falls,
    // crashes and settles, so it is measured over a fixed simulated interval.
    let running = |simulation: &Simulation| match args.scene {
        BenchScene::Cloud | BenchScene::Cluster => start.elapsed() < budget,
        BenchScene::Pit | BenchScene::Mixed | BenchScene::Scrub | BenchScene::Sweep => {
            simulation.time() < args.seconds
        }
    };
    while running(&simulation) {
        simulation.step().map_err(fail)?;
        steps += 1;
    }
    let elapsed = start.elapsed().as_secs_f64();
    let n = args.particles as u64;
    let steps_per_second = steps as f64 / elapsed;
    let integrator = args.integrator;
    match args.scene {
        BenchScene::Cloud => {
            let pairs = n * n.saturating_sub(1) / 2;
            let evaluations = evaluations_per_step(integrator);
            let pair_rate = steps_per_second * (pairs * evaluations) as f64;
            out!(
                "{n} gravitating, charged particles, {integrator}: {steps} steps in {elapsed:.2} s"
            );
            out!("  {steps_per_second:.1} steps per second");
            out!(
                "  {pair_rate:.3e} pair interactions per second ({pairs} pairs, {evaluations} force evaluations per step)"
            );
        }
        BenchScene::Cluster => report_cluster(
            &simulation,
            (steps, elapsed),
            advances_before,
            integrator,
            tree_error,
        ),
        BenchScene::Pit | BenchScene::Mixed | BenchScene::Scrub | BenchScene::Sweep => {
            let simulated = simulation.time();
            let threads = simulation.threads();
            let what = if matches!(args.scene, BenchScene::Mixed) {
                "mixed pit (charges, springs)"
            } else {
                "pit"
            };
            out!(
                "{n}-ball {what}, {integrator}, time step 1 ms, {threads} thread(s): {steps} steps in {elapsed:.2} s (simulated 0 to {simulated:.2} s)"
            );
            // One figure a line, "<number> <unit>", for scripts (docs/cli.md).
            out!("  {steps_per_second:.1} steps per second");
            out!("  {:.2}x real time", simulated / elapsed);
            let passes = simulation.steps_taken() - advances_before;
            out!(
                "  {passes} passes through the step's pipeline (a step ends early at an impact of a particle under pairwise forces or springs)"
            );
        }
    }
    print_profile(&simulation.profile(), steps, simulation.threads());
    Ok(())
}

/// `bench --scene scrub`: the pit recorded as the app records a run, then shown again
/// at 20 moments spread over it (each the step just before a keyframe, the farthest
/// from the keyframe before it: the worst case), timed.
fn scrub(args: &BenchArgs) -> Result<(), Failure> {
    use newtonlab_app::timeline::Timeline;
    let scene = physics::generated::ball_pit(args.particles).with_integrator(args.integrator, 1e-3);
    let mut simulation = Simulation::new(&scene).map_err(|e| Failure::Input(e.to_string()))?;
    let fail = |e: physics::SimulationError| Failure::Simulation(e.to_string());
    let mut timeline = Timeline::start(&simulation);
    let start = Instant::now();
    while simulation.time() < args.seconds {
        simulation.step().map_err(fail)?;
        timeline.after_step(&simulation);
    }
    let recording = start.elapsed().as_secs_f64();
    let interval = timeline.interval();
    let mut latencies: Vec<f64> = (1..=20)
        .map(|k| {
            let step = (timeline.end * k / 20).saturating_sub(1);
            // The last step of an interval is the farthest from its keyframe.
            let step = step - step % interval + interval - 1;
            let clock = Instant::now();
            let shown = timeline.state_at(step.min(timeline.end));
            let seconds = clock.elapsed().as_secs_f64();
            shown.map(|_| seconds)
        })
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| Failure::Simulation("a step could not be shown again".to_owned()))?;
    latencies.sort_by(f64::total_cmp);
    let n = args.particles;
    {
        out!(
            "{n}-ball pit recorded for {:.0} s ({} steps) in {recording:.1} s",
            simulation.time(),
            timeline.end
        );
        out!(
            "  {} keyframes every {interval} steps, {:.1} MiB",
            timeline.len(),
            timeline.bytes() as f64 / f64::from(1 << 20)
        );
        out!(
            "  going back to a moment: {:.1} ms median, {:.1} ms worst (20 moments, each {} steps past its keyframe)",
            latencies[latencies.len() / 2] * 1e3,
            latencies[latencies.len() - 1] * 1e3,
            interval - 1
        );
    }
    Ok(())
}

/// A 20 × 20 series of a thrown ball (launch angle 10°–86°, quadratic drag 0–0.0019 kg/m,
/// each run to its landing) on one thread, then on `--threads` (every core by default):
/// the wall time of each, their ratio, and whether both gave the same bits.
fn sweep(args: &BenchArgs) -> Result<(), Failure> {
    use physics::series::{Measure, Sweep, Vary};
    use physics::{Particle, Scene, Vector, World};
    let scene = Scene::new()
        .with_world(World::gravity_only())
        .with_integrator(args.integrator, 1e-3)
        .with_particle(
            Particle::new("Ball", 0.145)
                .radius(0.0366)
                .velocity(Vector::Polar {
                    magnitude: 30.0,
                    angle: 45.0,
                }),
        );
    let input = |e: String| Failure::Input(e);
    let sweep = Sweep {
        varies: vec![
            Vary::parse("Ball.velocity.angle=10:86:4", &scene).map_err(input)?,
            Vary::parse("Ball.quadratic_drag=0:0.0019:0.0001", &scene).map_err(input)?,
        ],
        until: 6.5,
        measures: vec![Measure::parse("Ball.x at Ball.y crosses 0 down").map_err(input)?],
        trace: false,
    };
    let threads = args.threads.unwrap_or_else(physics::every_core);
    let timed = |threads: usize| {
        let clock = Instant::now();
        let rows = sweep.run(&scene, threads, &|| {});
        (clock.elapsed().as_secs_f64(), rows)
    };
    let (one, rows_one) = timed(1);
    let (many, rows_many) = timed(threads);
    {
        out!("sweep of {} runs (20 angles × 20 drags)", rows_one.len());
        out!("  {one:.3} s on 1 thread");
        out!("  {many:.3} s on {threads} threads");
        out!("  {:.2}x faster on {threads} threads", one / many);
        out!(
            "  the same results on both: {}",
            if rows_one == rows_many { "yes" } else { "NO" }
        );
    }
    if rows_one == rows_many {
        Ok(())
    } else {
        Err(Failure::Simulation(
            "the series gave different results on different thread counts".to_owned(),
        ))
    }
}

/// The most bodies whose tree forces `bench` checks against the direct sum.
const TREE_ERROR_BODIES: usize = 20_000;

/// √(Σ|tree − direct|² / Σ|direct|²) of the accelerations over every body at the start of `scene`, whose
/// `simulation` sums with the tree; `None` above [`TREE_ERROR_BODIES`].
fn tree_error(scene: &physics::Scene, simulation: &Simulation) -> Option<f64> {
    if scene.particles.len() > TREE_ERROR_BODIES {
        return None;
    }
    let mut direct = scene.clone();
    direct.simulation.pair_forces = physics::PairForces::Direct;
    let exact = Simulation::new(&direct).ok()?.accelerations();
    let tree = simulation.accelerations();
    let error: f64 = tree
        .iter()
        .zip(&exact)
        .map(|(t, d)| t.distance_squared(*d))
        .sum();
    let size: f64 = exact.iter().map(|d| d.length_squared()).sum();
    Some((error / size).sqrt())
}

/// Seconds since the first call: the clock lent to the simulation's profiler.
fn clock() -> f64 {
    static EPOCH: OnceLock<Instant> = OnceLock::new();
    EPOCH.get_or_init(Instant::now).elapsed().as_secs_f64()
}

/// The time per stage, as Box2D's profile shows it: microseconds per step and share;
/// the share of work that may be split across threads, and on one thread the speed-up
/// Amdahl's law allows on 2, 4, 8 and 16.
fn print_profile(profile: &Profile, steps: u64, threads: usize) {
    let total = profile.total();
    if steps == 0 || total <= 0.0 {
        return;
    }
    out!("  time per step by stage:");
    for stage in Stage::ALL {
        let seconds = profile.seconds(stage);
        out!(
            "    {:<18} {:>9.1} µs  {:>5.1} %",
            stage.name(),
            seconds / steps as f64 * 1e6,
            seconds / total * 100.0
        );
    }
    let share = profile.parallel_seconds() / total;
    out!(
        "  work that may be split across threads: {:.1} % of the step, serial: {:.1} %",
        share * 100.0,
        (1.0 - share) * 100.0
    );
    if threads == 1 {
        let predicted: Vec<String> = [2, 4, 8, 16]
            .iter()
            .map(|&n| format!("{n}: {:.2}x", profile.amdahl(n)))
            .collect();
        out!(
            "  Amdahl's bound from this profile, speed-up on N threads: {}",
            predicted.join(", ")
        );
    }
}

/// `bench --scene cluster`'s report: force evaluations per second over the whole run and
/// over the integrator's time alone, and the tree's error against the direct sum.
fn report_cluster(
    simulation: &Simulation,
    (steps, elapsed): (u64, f64),
    advances_before: u64,
    integrator: Integrator,
    tree_error: Option<f64>,
) {
    let n = simulation.len();
    let steps_per_second = steps as f64 / elapsed;
    let evaluations = evaluations_per_step(integrator);
    let rate = steps_per_second * evaluations as f64;
    out!(
        "{n}-body cluster, Barnes–Hut tree (opening angle 0.5), {integrator}: {steps} steps in {elapsed:.2} s"
    );
    out!("  {steps_per_second:.1} steps per second");
    out!(
        "  {rate:.1} force evaluations per second (all {n} bodies each; {evaluations} per step, more when an impact integrates again)"
    );
    // The forces alone: the integrator's trial steps, timed by the profile
    // (the broad phase and impacts of n moving bodies are the rest).
    let integrating = simulation.profile().seconds(Stage::Integration);
    let trials = simulation.steps_taken() - advances_before;
    if integrating > 0.0 {
        let forces_rate = (trials * evaluations) as f64 / integrating;
        out!(
            "  {forces_rate:.1} force evaluations per second while integrating ({trials} trial steps in {integrating:.2} s)"
        );
    }
    match tree_error {
        Some(error) => {
            out!("  {error:.2e} normalised RMS force error against the direct sum, at the start");
        }
        None => out!(
            "  (the force error is measured up to {TREE_ERROR_BODIES} bodies: the direct sum is O(n²))"
        ),
    }
}
