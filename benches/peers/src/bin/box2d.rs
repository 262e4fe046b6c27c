//! NewtonLab's ball pit beside the same pit in Box2D v3, on each number of threads asked
//! for, in one run.
//!
//! The scene is `physics::generated::ball_pit(n)` (what `newtonlab bench --scene pit`
//! measures): balls of radius 0.1 m and 1 kg dropped in a grid into a box, restitution
//! 0.5, no friction, g = 9.81 m/s², time step 1 ms. Box2D gets the same balls (rotation
//! locked), the walls as static boxes, four substeps a step and its defaults for the
//! rest (single precision, soft contacts, sleeping, a restitution threshold of 1 m/s);
//! its workers are its own scheduler's threads (`workerCount`), NewtonLab's its pool
//! (`set_threads`). Engines and thread counts alternate within each run, so the
//! machine's noise hits all alike; the figure is steps per second, the median of the
//! runs.
//!
//!     cd benches/peers && cargo run --release --bin box2d -- [--particles N] [--seconds S] [--runs R] [--threads 1,2]

use std::time::Instant;

use boxdd_sys::ffi;
use newtonlab_peers::{TIME_STEP, median, newtonlab};
use physics::{Bounds, Scene};

const SUBSTEPS: i32 = 4;

struct Options {
    particles: usize,
    seconds: f64,
    runs: usize,
    threads: Vec<usize>,
}

fn options() -> Result<Options, String> {
    let mut options = Options {
        particles: 10_000,
        seconds: 2.0,
        runs: 3,
        threads: vec![1, 2],
    };
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().ok_or(format!("{flag} needs a value"))?;
        let bad = |e: &dyn std::fmt::Display| format!("{flag} {value}: {e}");
        match flag.as_str() {
            "--particles" => options.particles = value.parse().map_err(|e| bad(&e))?,
            "--seconds" => options.seconds = value.parse().map_err(|e| bad(&e))?,
            "--runs" => options.runs = value.parse().map_err(|e| bad(&e))?,
            "--threads" => {
                options.threads = value
                    .split(',')
                    .map(|t| t.trim().parse().map_err(|e| bad(&e)))
                    .collect::<Result<_, _>>()?;
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(options)
}

fn vec2(x: f64, y: f64) -> ffi::b2Vec2 {
    ffi::b2Vec2 {
        x: x as f32,
        y: y as f32,
    }
}

/// The same pit as a Box2D world with `workers` workers.
fn box2d_world(scene: &Scene, workers: usize) -> ffi::b2WorldId {
    // SAFETY: Box2D's C API, called as its documentation says: definitions from its
    // defaults, pointers to locals that live through each call.
    unsafe {
        let mut def = ffi::b2DefaultWorldDef();
        def.gravity = vec2(0.0, -9.81);
        def.workerCount = workers as i32;
        let world = ffi::b2CreateWorld(&def);
        let restitution = scene.world.restitution;
        for particle in &scene.particles {
            let position = particle.position.to_dvec2();
            let velocity = particle.initial_velocity();
            let radius = particle.radius;
            let mut body = ffi::b2DefaultBodyDef();
            body.type_ = ffi::b2BodyType_b2_dynamicBody;
            body.position = vec2(position.x, position.y);
            body.linearVelocity = vec2(velocity.x, velocity.y);
            body.motionLocks.angularZ = true;
            let id = ffi::b2CreateBody(world, &body);
            let mut shape = ffi::b2DefaultShapeDef();
            shape.density = (particle.mass / (std::f64::consts::PI * radius * radius)) as f32;
            shape.material.friction = 0.0;
            shape.material.restitution = restitution as f32;
            let circle = ffi::b2Circle {
                center: vec2(0.0, 0.0),
                radius: radius as f32,
            };
            ffi::b2CreateCircleShape(id, &shape, &circle);
        }
        if let Some(Bounds { min, max, .. }) = scene.world.bounds {
            let (min, max) = (min.to_dvec2(), max.to_dvec2());
            let (centre, half) = ((min + max) / 2.0, (max - min) / 2.0);
            let thickness = 1.0;
            let ground = ffi::b2CreateBody(world, &ffi::b2DefaultBodyDef());
            let mut shape = ffi::b2DefaultShapeDef();
            shape.material.friction = 0.0;
            shape.material.restitution = restitution as f32;
            let walls = [
                (
                    (centre.x, min.y - thickness),
                    (half.x + 2.0 * thickness, thickness),
                ),
                (
                    (centre.x, max.y + thickness),
                    (half.x + 2.0 * thickness, thickness),
                ),
                (
                    (min.x - thickness, centre.y),
                    (thickness, half.y + 2.0 * thickness),
                ),
                (
                    (max.x + thickness, centre.y),
                    (thickness, half.y + 2.0 * thickness),
                ),
            ];
            for ((x, y), (hx, hy)) in walls {
                let rotation = ffi::b2Rot { c: 1.0, s: 0.0 };
                let wall = ffi::b2MakeOffsetBox(hx as f32, hy as f32, vec2(x, y), rotation);
                ffi::b2CreatePolygonShape(ground, &shape, &wall);
            }
        }
        world
    }
}

/// Steps per second of Box2D over `seconds` of simulated time.
fn box2d(scene: &Scene, seconds: f64, workers: usize) -> f64 {
    let world = box2d_world(scene, workers);
    let steps = (seconds / TIME_STEP).round() as u64;
    let start = Instant::now();
    for _ in 0..steps {
        // SAFETY: a world this function created and has not destroyed.
        unsafe { ffi::b2World_Step(world, TIME_STEP as f32, SUBSTEPS) };
    }
    let rate = steps as f64 / start.elapsed().as_secs_f64();
    // SAFETY: as above; not used again.
    unsafe { ffi::b2DestroyWorld(world) };
    rate
}

fn main() {
    let options = match options() {
        Ok(options) => options,
        Err(message) => {
            eprintln!(
                "error: {message}\nusage: box2d [--particles N] [--seconds S] [--runs R] [--threads 1,2]"
            );
            std::process::exit(2);
        }
    };
    let scene = physics::generated::ball_pit(options.particles);
    let counts = options.threads.len();
    let (mut ours, mut theirs) = (vec![Vec::new(); counts], vec![Vec::new(); counts]);
    for run in 1..=options.runs {
        for (k, &threads) in options.threads.iter().enumerate() {
            ours[k].push(newtonlab(&scene, options.seconds, threads));
            theirs[k].push(box2d(&scene, options.seconds, threads));
            println!(
                "run {run}, {threads} thread(s): NewtonLab {:.0} steps/s, Box2D {:.0} steps/s",
                ours[k][run - 1],
                theirs[k][run - 1]
            );
        }
    }
    println!(
        "{}-ball pit, 1 ms steps, 0 to {} s, median of {} runs (steps/s):",
        options.particles, options.seconds, options.runs
    );
    println!("  threads   NewtonLab   Box2D v3   ratio   NewtonLab's speed-up   Box2D's");
    for (k, &threads) in options.threads.iter().enumerate() {
        let (a, b) = (median(ours[k].clone()), median(theirs[k].clone()));
        let (a1, b1) = (median(ours[0].clone()), median(theirs[0].clone()));
        println!(
            "  {threads:>7}   {a:>9.0}   {b:>8.0}   {:>5.2}x   {:>20.2}x   {:>6.2}x",
            a / b,
            a / a1,
            b / b1
        );
    }
}
