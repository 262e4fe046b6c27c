//! The same bits on one thread and on many: the work a step shares out (the pair sum in
//! blocks of rows, the contacts in strips) gives every number of a run exactly as one
//! thread does. The tests hold this too; `validate` guards it on the machine it runs on.

use physics::{Scene, Simulation, generated};

use crate::Failure;
use crate::experiments::Outcome;
use crate::report::{Checks, Report};

/// Threads for the shared run: every core, and at least four, so that the work is split
/// even on a small machine.
fn many() -> usize {
    physics::every_core().max(4)
}

/// `scene` stepped `steps` times on `threads` threads: every position and velocity, and
/// the impacts on the way.
fn run(scene: &Scene, threads: usize, steps: usize) -> Result<(Vec<f64>, usize), Failure> {
    let mut simulation = Simulation::new(scene).map_err(|e| Failure::Input(e.to_string()))?;
    simulation.set_threads(threads);
    simulation.record_impacts();
    let mut impacts = 0;
    for _ in 0..steps {
        simulation
            .step()
            .map_err(|e| Failure::Simulation(e.to_string()))?;
        impacts += simulation.take_impacts().len();
    }
    let numbers = simulation.positions().iter().chain(simulation.velocities());
    Ok((numbers.flat_map(|v| [v.x, v.y]).collect(), impacts))
}

/// A cloud of 300 charges (the direct pair sum, in blocks of rows past 256 bodies) and a
/// pit of 5,000 balls (impacts and resting contacts found in strips past 4,096), each
/// run on one thread and on [`many`]: not one bit differs.
pub(crate) fn threads(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("threads");
    let many = many();
    let runs = [
        (
            "300 charges, the pair sum in blocks",
            generated::charged_cloud(300),
            200,
        ),
        (
            "a pit of 5,000 balls, contacts in strips",
            generated::ball_pit(5000),
            600,
        ),
    ];
    for (name, scene, steps) in runs {
        let (one, impacts) = run(&scene, 1, steps)?;
        let (shared, _) = run(&scene, many, steps)?;
        let differing = one
            .iter()
            .zip(&shared)
            .filter(|(a, b)| a.to_bits() != b.to_bits())
            .count()
            + one.len().abs_diff(shared.len());
        #[expect(clippy::cast_precision_loss, reason = "a count, exact in f64")]
        let differing = differing as f64;
        checks.check(
            report,
            format!(
                "{name}: numbers that differ after {steps} steps ({impacts} impacts) on 1 and {many} threads"
            ),
            (differing, 0.0, 1.0),
            0.0,
        );
    }
    report.tables.push(checks.table(
        "Threads: one thread against many, bit for bit",
        "every position and velocity identical, to the bit",
    ));
    Ok(())
}
