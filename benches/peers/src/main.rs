//! NewtonLab's ball pit beside the same pit in rapier2d-f64, in one run, on one thread.
//!
//! The scene is `physics::generated::ball_pit(n)` (what `newtonlab bench --scene pit`
//! measures): balls of radius 0.1 m and 1 kg dropped in a grid into a box, restitution
//! 0.5 everywhere, no friction, g = 9.81 m/s², time step 1 ms. Rapier gets the same
//! balls (rotation locked: NewtonLab's particles do not spin), the walls as fixed
//! cuboids, and its defaults for everything else (solver iterations, sleeping). Both are
//! timed over the same simulated interval, alternating engines so the machine's noise
//! hits both; the figure is steps per second and the ratio.
//!
//!     cd benches/peers && cargo run --release -- [--particles N] [--seconds S] [--runs R] [--threads T]
//!
//! This crate is a workspace of its own: CI and the main workspace never build rapier.

use std::time::Instant;

use newtonlab_peers::{TIME_STEP, median, newtonlab};
use physics::{Bounds, Scene};
use rapier2d_f64::prelude::*;


struct Options {
    particles: usize,
    seconds: f64,
    runs: usize,
    /// NewtonLab's threads for the contact search (rapier's build here has none).
    threads: usize,
}

fn options() -> Result<Options, String> {
    let mut options = Options {
        particles: 1000,
        seconds: 1.0,
        runs: 3,
        threads: 1,
    };
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().ok_or(format!("{flag} needs a value"))?;
        let bad = |e: &dyn std::fmt::Display| format!("{flag} {value}: {e}");
        match flag.as_str() {
            "--particles" => options.particles = value.parse().map_err(|e| bad(&e))?,
            "--seconds" => options.seconds = value.parse().map_err(|e| bad(&e))?,
            "--runs" => options.runs = value.parse().map_err(|e| bad(&e))?,
            "--threads" => options.threads = value.parse().map_err(|e| bad(&e))?,
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(options)
}

/// The same pit as a rapier world.
fn rapier_world(scene: &Scene) -> PhysicsWorld {
    let mut world = PhysicsWorld::new();
    world.gravity = Vector::new(0.0, -9.81);
    world.integration_parameters.dt = TIME_STEP;
    let restitution = scene.world.restitution;
    for particle in &scene.particles {
        let position = particle.position.to_dvec2();
        let velocity = particle.initial_velocity();
        let radius = particle.radius;
        let density = particle.mass / (std::f64::consts::PI * radius * radius);
        world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(position.x, position.y))
                .linvel(Vector::new(velocity.x, velocity.y))
                .lock_rotations(),
            ColliderBuilder::ball(radius)
                .density(density)
                .restitution(restitution)
                .friction(0.0),
        );
    }
    let Some(Bounds { min, max, .. }) = scene.world.bounds else {
        return world;
    };
    let (min, max) = (min.to_dvec2(), max.to_dvec2());
    let (centre, half) = ((min + max) / 2.0, (max - min) / 2.0);
    let thickness = 1.0;
    let walls = [
        (Vector::new(centre.x, min.y - thickness), Vector::new(half.x + 2.0 * thickness, thickness)),
        (Vector::new(centre.x, max.y + thickness), Vector::new(half.x + 2.0 * thickness, thickness)),
        (Vector::new(min.x - thickness, centre.y), Vector::new(thickness, half.y + 2.0 * thickness)),
        (Vector::new(max.x + thickness, centre.y), Vector::new(thickness, half.y + 2.0 * thickness)),
    ];
    for (centre, half) in walls {
        world.insert(
            RigidBodyBuilder::fixed().translation(centre),
            ColliderBuilder::cuboid(half.x, half.y)
                .restitution(restitution)
                .friction(0.0),
        );
    }
    world
}

/// Steps per second of rapier over `seconds` of simulated time.
fn rapier(scene: &Scene, seconds: f64) -> f64 {
    let mut world = rapier_world(scene);
    let steps = (seconds / TIME_STEP).round() as u64;
    let start = Instant::now();
    for _ in 0..steps {
        world.step();
    }
    steps as f64 / start.elapsed().as_secs_f64()
}

fn main() {
    let options = match options() {
        Ok(options) => options,
        Err(message) => {
            eprintln!("error: {message}\nusage: newtonlab_peers [--particles N] [--seconds S] [--runs R] [--threads T]");
            std::process::exit(2);
        }
    };
    let scene = physics::generated::ball_pit(options.particles);
    let (mut ours, mut theirs) = (Vec::new(), Vec::new());
    for run in 1..=options.runs {
        ours.push(newtonlab(&scene, options.seconds, options.threads));
        theirs.push(rapier(&scene, options.seconds));
        println!(
            "run {run}: NewtonLab {:.0} steps/s, rapier2d-f64 {:.0} steps/s",
            ours[run - 1],
            theirs[run - 1]
        );
    }
    let (ours, theirs) = (median(ours), median(theirs));
    println!(
        "{}-ball pit, 1 ms steps, 0 to {} s, NewtonLab on {} thread(s), rapier on one, median of {} runs:",
        options.particles, options.seconds, options.threads, options.runs
    );
    println!("  NewtonLab     {ours:>8.0} steps/s");
    println!("  rapier2d-f64  {theirs:>8.0} steps/s");
    println!("  ratio         {:>8.2}x", ours / theirs);
}
