//! Same scene, same bits: for any number of threads, and run after run (Box2D's and
//! Rapier's determinism tests do the same across worker counts).

mod common;

use common::example_scene;
use physics::{DVec2, Simulation, generated};

/// Every coordinate of every position and velocity, as bits.
fn fingerprint(simulation: &Simulation) -> Vec<u64> {
    let bits = |v: &DVec2| [v.x.to_bits(), v.y.to_bits()];
    simulation
        .positions()
        .iter()
        .chain(simulation.velocities())
        .flat_map(bits)
        .collect()
}

/// `scene` after 20 steps on `threads` threads.
fn twenty_steps(scene: &physics::Scene, threads: usize) -> Simulation {
    let mut simulation = Simulation::new(scene).expect("a valid scene");
    simulation.set_threads(threads);
    for _ in 0..20 {
        simulation.step().expect("it steps");
    }
    simulation
}

/// A 5,000-ball pit run into its pile: its step runs on a thread of the pool, the
/// contact searches are split across threads and the impacts at each step's start are
/// swept strip by strip (`contacts/strips.rs`, from 4,096 particles). The state after
/// 0.9 s, with hundreds of balls touching, is bit-identical on 1, 2, 3, 7 and 16 threads,
/// with the same impacts; and the same whether or not the impacts are logged (the
/// strips keep those at a step's start only for a log).
#[test]
fn the_pit_gives_the_same_bits_on_any_number_of_threads() {
    let scene = generated::ball_pit(5_000);
    let run = |threads: usize, log: bool| {
        let mut simulation = Simulation::new(&scene).unwrap();
        simulation.set_threads(threads);
        if log {
            simulation.record_impacts();
        }
        simulation.step_to(0.9).unwrap();
        let impacts = simulation.take_impacts().len();
        (fingerprint(&simulation), impacts, simulation.threads())
    };
    let (one, impacts, _) = run(1, true);
    assert!(impacts > 10_000, "the run has impacts to order: {impacts}");
    let radius = scene.particles[0].radius;
    let positions = Simulation::new(&scene).map(|mut s| {
        s.step_to(0.9).unwrap();
        s.positions().to_vec()
    });
    let positions = positions.unwrap();
    let touching = (0..positions.len())
        .flat_map(|i| (i + 1..positions.len()).map(move |j| (i, j)))
        .filter(|&(i, j)| positions[i].distance(positions[j]) <= 2.0 * radius * (1.0 + 1e-6))
        .count();
    assert!(touching > 500, "the pile has touching balls: {touching}");
    let (unlogged, ..) = run(1, false);
    assert!(unlogged == one, "the same bits without a log of impacts");
    for threads in [2, 3, 7, 16] {
        let (bits, count, used) = run(threads, true);
        assert_eq!(used, threads, "the pool has {threads} threads");
        assert_eq!(count, impacts, "{threads} threads: the same impacts");
        assert!(bits == one, "{threads} threads: the same bits as one");
    }
}

/// The mixed scene of 5,000 balls (500 charged: the coupled group's Coulomb sum is split
/// into blocks of rows across threads, each step runs on a thread of the pool, and the
/// impacts at a step's start are swept in strips) run through its first impacts of
/// charged and sprung balls, which are integrated inside the step: bit-identical on 1,
/// 2, 3, 7 and 16 threads. The charges are ten times the 4.1 scene's,
/// so that the Coulomb forces are not far below the weights: a force's rounding then
/// shows in the acceleration's bits (summing the blocks in another order on two threads
/// fails this test; with the scene's own charges it did not).
#[test]
fn coupled_impacts_give_the_same_bits_on_any_number_of_threads() {
    let mut scene = generated::mixed(5000);
    for ball in &mut scene.particles {
        ball.charge *= 10.0;
    }
    let run = |threads: usize| {
        let mut simulation = Simulation::new(&scene).unwrap();
        simulation.set_threads(threads);
        simulation.record_impacts();
        simulation.step_to(0.45).unwrap();
        let impacts = simulation.take_impacts();
        // Every tenth ball is charged and its neighbour sprung to it.
        let coupled = impacts.iter().filter(|i| i.particle % 10 < 2).count();
        (fingerprint(&simulation), impacts.len(), coupled)
    };
    let (one, impacts, coupled) = run(1);
    assert!(
        coupled > 20,
        "the run has coupled impacts: {coupled} of {impacts}"
    );
    for threads in [2, 3, 7, 16] {
        let (bits, count, _) = run(threads);
        assert_eq!(count, impacts, "{threads} threads: the same impacts");
        assert!(bits == one, "{threads} threads: the same bits as one");
    }
}

/// A charged, gravitating cloud of 1,500 bodies (enough that the direct pair sum is
/// split into blocks of rows across threads) run for 20 steps: bit-identical on 1, 2, 3,
/// 7 and 16 threads.
#[test]
fn the_pair_sum_gives_the_same_bits_on_any_number_of_threads() {
    let scene = generated::charged_cloud(1500).with_integrator(physics::Integrator::Rk4, 1e-4);
    let run = |threads: usize| fingerprint(&twenty_steps(&scene, threads));
    let one = run(1);
    for threads in [2, 3, 7, 16] {
        assert!(
            run(threads) == one,
            "{threads} threads: the same bits as one"
        );
    }
}

/// The Barnes–Hut tree's forces and potential energy, each body's sum on whichever thread
/// takes it: a 5,000-body cluster (enough to be split) stepped 20 times gives the same
/// bits, and the same potential energy, on 1, 2, 3, 7 and 16 threads.
#[test]
fn the_tree_gives_the_same_bits_on_any_number_of_threads() {
    let scene = generated::cluster(5000);
    let run = |threads: usize| {
        let simulation = twenty_steps(&scene, threads);
        let energy = simulation.diagnostics().energy.gravitation.to_bits();
        (fingerprint(&simulation), energy)
    };
    let one = run(1);
    for threads in [2, 3, 7, 16] {
        assert!(
            run(threads) == one,
            "{threads} threads: the same bits as one"
        );
    }
}

/// A keyframe (a copy without the scratch buffers each step fills again) stepped on gives
/// the bits the simulation it was taken from gives: for the 1,000-ball pit in its crash
/// (resting contacts, impacts, the carried broad phase), a ball swung on a string
/// (a string's modes), the orbit under dopri5 (its step-size memory) and Newton's
/// cradle on strings.
#[test]
fn a_keyframe_steps_on_as_the_run_does() {
    let examples = [
        ("ball-pit", 1.2),
        ("string-circle", 1.0),
        ("orbit", 3.0),
        ("newtons-cradle", 0.5),
    ];
    for (name, until) in examples {
        let scene = example_scene(name);
        let mut run = Simulation::new(&scene).unwrap();
        run.step_to(until).unwrap();
        let mut keyframe = run.keyframe();
        for _ in 0..200 {
            run.step().unwrap();
            keyframe.step().unwrap();
        }
        assert!(
            fingerprint(&keyframe) == fingerprint(&run),
            "{name}: the keyframe went its own way"
        );
    }
}
