//! The profile's account of the work that may be split across threads: inside the step,
//! zero where nothing is split, and Amdahl's bound from it between 1 and the threads.

use std::sync::OnceLock;
use std::time::Instant;

use physics::{Particle, Scene, Simulation, generated};

fn clock() -> f64 {
    static EPOCH: OnceLock<Instant> = OnceLock::new();
    EPOCH.get_or_init(Instant::now).elapsed().as_secs_f64()
}

fn profiled(scene: &Scene, threads: usize, steps: usize) -> physics::Profile {
    let mut simulation = Simulation::new(scene).expect("valid");
    simulation.set_clock(Some(clock));
    simulation.set_threads(threads);
    for _ in 0..steps {
        simulation.step().expect("steps");
    }
    simulation.profile()
}

#[test]
fn the_split_work_is_inside_the_step_and_bounds_the_speed_up() {
    // 3,000 charged particles: the direct pair sum is split in pieces (over 4.5 million
    // pairs a force evaluation), on one thread as on two.
    let cloud = generated::charged_cloud(3_000);
    for threads in [1, 2] {
        let profile = profiled(&cloud, threads, 3);
        let (split, total) = (profile.parallel_seconds(), profile.total());
        assert!(
            split > 0.5 * total,
            "{threads} threads: {split} of {total} s split"
        );
        assert!(split <= total, "{threads} threads: inside the step");
    }
    let profile = profiled(&cloud, 1, 3);
    assert!(
        (profile.amdahl(1) - 1.0).abs() < 1e-12,
        "one thread: no speed-up"
    );
    let mut last = 1.0;
    for n in [2, 4, 8, 16] {
        let bound = profile.amdahl(n);
        assert!(bound > last && bound <= n as f64, "{n}: {bound}");
        last = bound;
    }
    // One particle: nothing to split.
    let one = Scene::new().with_particle(Particle::new("a", 1.0));
    let profile = profiled(&one, 1, 100);
    assert!(profile.parallel_seconds() == 0.0, "nothing split");
    assert!((profile.amdahl(16) - 1.0).abs() < 1e-12, "no speed-up");
}
