//! `newtonlab bench`: simulation speed, measured on this machine.
//!
//! The scene is [`physics::generated::charged_cloud`]: `n` particles that all attract by
//! gravitation and attract or repel by Coulomb's law, so every step evaluates all
//! n(n−1)/2 pairs once per force evaluation. The wall clock is read here, in the binary:
//! the library never reads clocks.

use std::time::{Duration, Instant};

use physics::{Integrator, Simulation};

use crate::Failure;

#[derive(Debug, clap::Args)]
pub(crate) struct BenchArgs {
    /// Number of mutually gravitating, charged particles.
    #[arg(long, default_value_t = 1000)]
    particles: usize,
    /// Integrator to measure.
    #[arg(long, default_value = "rk4", value_parser = parse_integrator)]
    integrator: Integrator,
    /// Seconds of measurement (after one warm-up step).
    #[arg(long, default_value_t = 3.0)]
    seconds: f64,
}

fn parse_integrator(name: &str) -> Result<Integrator, String> {
    name.parse()
        .map_err(|e: physics::UnknownIntegrator| e.to_string())
}

/// Force evaluations per step of each fixed-step method.
fn evaluations_per_step(integrator: Integrator) -> u64 {
    match integrator {
        Integrator::Euler | Integrator::SemiImplicitEuler | Integrator::Verlet => 1,
        Integrator::Rk4 => 4,
        Integrator::Dopri5 => 6,
    }
}

pub(crate) fn bench(args: &BenchArgs) -> Result<(), Failure> {
    if !(args.seconds.is_finite() && args.seconds > 0.0) {
        return Err(Failure::Input(format!(
            "--seconds must be greater than 0; got {}",
            args.seconds
        )));
    }
    let scene =
        physics::generated::charged_cloud(args.particles).with_integrator(args.integrator, 1e-4);
    let mut simulation = Simulation::new(&scene).map_err(|e| Failure::Input(e.to_string()))?;
    let fail = |e: physics::SimulationError| Failure::Simulation(e.to_string());
    simulation.step().map_err(fail)?;
    let budget = Duration::from_secs_f64(args.seconds);
    let start = Instant::now();
    let mut steps: u64 = 0;
    while start.elapsed() < budget {
        simulation.step().map_err(fail)?;
        steps += 1;
    }
    let elapsed = start.elapsed().as_secs_f64();
    let n = args.particles as u64;
    let pairs = n * n.saturating_sub(1) / 2;
    let steps_per_second = steps as f64 / elapsed;
    let pair_rate = steps_per_second * (pairs * evaluations_per_step(args.integrator)) as f64;
    #[expect(clippy::print_stdout, reason = "the command's report")]
    {
        println!(
            "{n} gravitating, charged particles, {}: {steps} steps in {elapsed:.2} s",
            args.integrator
        );
        println!("  {steps_per_second:.1} steps per second");
        println!(
            "  {:.3e} pair interactions per second ({pairs} pairs, {} force evaluations per step)",
            pair_rate,
            evaluations_per_step(args.integrator)
        );
    }
    Ok(())
}
