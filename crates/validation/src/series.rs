//! Experiment series against theory: `physics::series`, the code behind `newtonlab
//! sweep`, the app's series and Python's, measuring laws rather than single runs.

use physics::series::{Measure, Sweep, Vary};
use physics::{Particle, Scene, Tie, Vector, World};

use crate::Failure;
use crate::experiments::Outcome;
use crate::report::{Checks, Report};
use crate::theory;

const G: f64 = 9.81;

/// Each run of `sweep` on `scene`: the varied value and every measure, which must all
/// have a number.
fn measured(sweep: &Sweep, scene: &Scene) -> Result<Vec<(f64, Vec<f64>)>, Failure> {
    sweep.check(scene).map_err(Failure::Input)?;
    sweep
        .run(scene, 1, &|| {})
        .into_iter()
        .map(|row| {
            let values = row
                .measured
                .map_err(|why| Failure::Simulation(why.to_string()))?
                .into_iter()
                .collect::<Result<Vec<f64>, _>>()
                .map_err(|why| Failure::Simulation(why.to_string()))?;
            Ok((row.values[0], values))
        })
        .collect()
}

/// A number of values, as a check compares it.
#[expect(
    clippy::cast_precision_loss,
    reason = "a handful of runs, exact in f64"
)]
fn count<T>(values: &[T]) -> f64 {
    values.len() as f64
}

/// Checks that a series' runs start at FROM, end at TO and are `runs` in all: a count
/// off by one at either end would pass every law measured on the rest.
fn runs_reach_their_end(
    report: &mut Report,
    checks: &mut Checks,
    name: &str,
    rows: &[(f64, Vec<f64>)],
    (from, to, runs): (f64, f64, u32),
) {
    let first = rows.first().map_or(f64::NAN, |row| row.0);
    let last = rows.last().map_or(f64::NAN, |row| row.0);
    let scale = to.abs().max(1.0);
    checks.check(
        report,
        format!("{name} series: its first value, FROM"),
        (first, from, scale),
        1e-12,
    );
    checks.check(
        report,
        format!("{name} series: its last value, TO"),
        (last, to, scale),
        1e-12,
    );
    let runs = f64::from(runs);
    checks.check(
        report,
        format!("{name} series: its runs"),
        (count(rows), runs, runs),
        1e-12,
    );
}

fn sweep(scene: &Scene, vary: &str, until: f64, measures: &[&str]) -> Result<Sweep, Failure> {
    Ok(Sweep {
        varies: vec![Vary::parse(vary, scene).map_err(Failure::Input)?],
        until,
        measures: measures
            .iter()
            .map(|m| Measure::parse(m).map_err(Failure::Input))
            .collect::<Result<_, _>>()?,
        trace: false,
    })
}

/// Two laws measured as series, rk4 at 1 ms: a 1 m rod pendulum's period against its
/// amplitude, 10° to 170°, against 4 √(L/g) K(sin(θ₀/2)), to 1e-9 relative (half the
/// time from the rod's 1st to its 3rd counter-clockwise pass through the vertical, each
/// located, and `period Bob.x`, whose maxima are three a swing past 90°); and a
/// baseball's range against its
/// launch angle with quadratic drag (0.145 kg, c = 7.6e-4 kg/m, 40 m/s), against an
/// integration of the same equations written here (`theory::drag_landing`), to 1e-9
/// relative — the furthest angle falls below 45°.
pub(crate) fn series(report: &mut Report) -> Outcome {
    let mut checks = Checks::new("series");
    let pendulum = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("Bob", 1.0)
                .radius(0.05)
                .position(Vector::Polar {
                    magnitude: 1.0,
                    angle: -60.0,
                }),
        )
        .with_tie(Tie::rod("rod", [0.0, 0.0], "Bob", 1.0));
    // The rod passes the vertical counter-clockwise once a period; `period Bob.x` finds
    // the swing's cycle in x's maxima, three a swing past 90°.
    let passes = measured(
        &sweep(
            &pendulum,
            "Bob.position.angle=-80:80:20",
            16.0,
            &[
                "t at rod.angle crosses 0 up #1",
                "t at rod.angle crosses 0 up #3",
                "period Bob.x",
            ],
        )?,
        &pendulum,
    )?;
    runs_reach_their_end(report, &mut checks, "pendulum", &passes, (-80.0, 80.0, 9));
    for (angle, passes) in passes {
        let period = (passes[1] - passes[0]) / 2.0;
        let amplitude = angle + 90.0;
        let theory = theory::pendulum_period(1.0, G, amplitude.to_radians());
        checks.check(
            report,
            format!("pendulum at {amplitude}°: period (s)"),
            (period, theory, theory),
            1e-9,
        );
        checks.check(
            report,
            format!("pendulum at {amplitude}°: period of its x (s)"),
            (passes[2], theory, theory),
            1e-9,
        );
    }
    let (mass, c, speed) = (0.145, 7.6e-4, 40.0);
    let ball = Scene::new()
        .with_world(World::gravity_only())
        .with_particle(
            Particle::new("Ball", mass)
                .radius(0.0366)
                .velocity(Vector::Polar {
                    magnitude: speed,
                    angle: 45.0,
                })
                .drag(0.0, c),
        );
    let ranges = measured(
        &sweep(
            &ball,
            "Ball.velocity.angle=20:60:5",
            8.0,
            &["Ball.x at Ball.y crosses 0 down"],
        )?,
        &ball,
    )?;
    runs_reach_their_end(report, &mut checks, "baseball", &ranges, (20.0, 60.0, 9));
    // A range's values as `sweep` lists them, at both ends.
    let ones = physics::series::range_values(1.0, 3.0, 1.0).unwrap_or_default();
    checks.check(
        report,
        "range 1:3:1: its values' count, 1, 2, 3".to_owned(),
        (count(&ones), 3.0, 3.0),
        1e-12,
    );
    checks.check(
        report,
        "range 1:3:1: its values' sum".to_owned(),
        (ones.iter().sum(), 6.0, 6.0),
        1e-12,
    );
    let mut furthest = (0.0, 0.0);
    for (angle, range) in ranges {
        let range = range[0];
        let (theory, _) = theory::drag_landing(speed, angle, G, c / mass);
        checks.check(
            report,
            format!("baseball at {angle}°: range (m)"),
            (range, theory, theory),
            1e-9,
        );
        if range > furthest.1 {
            furthest = (angle, range);
        }
    }
    report.tables.push(checks.table(
        &format!(
            "Series: a pendulum's period against its amplitude; a baseball's range against its angle with drag (furthest at {}°)",
            furthest.0
        ),
        "period 4 √(L/g) K(sin(θ₀/2)); range by an integration of x'' = −k|v|vₓ, y'' = −g − k|v|vᵧ written apart (RK4, 10 µs), k = c/m",
    ));
    Ok(())
}
