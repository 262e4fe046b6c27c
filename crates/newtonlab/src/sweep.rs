//! `newtonlab sweep`: an experiment series on the command line. Vary a scene's values
//! over ranges, run the scene for each combination (in parallel), and write one CSV row
//! per run: the values, then each measure (`physics::series`).

use std::io::{self, BufWriter, Write};

use newtonlab_i18n::tr_text as say;
use physics::series::{Measure, Row, Sweep, Vary};

use crate::{Failure, scene_source};

#[derive(Debug, clap::Args)]
pub(crate) struct SweepArgs {
    /// A scene file (.toml or .json), or example:NAME for a built-in scene.
    scene: String,
    /// FIELD=FROM:TO:STEP: the scene value to vary (`Ball.velocity.angle`, `Bob.mass`,
    /// `world.gravity.y`, `simulation.time_step`) and its values FROM, FROM + STEP, … TO.
    /// Twice for a grid (the first outermost).
    #[arg(
        long,
        value_name = "FIELD=FROM:TO:STEP",
        required = true,
        allow_hyphen_values = true
    )]
    vary: Vec<String>,
    /// Simulated time each run lasts, seconds.
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    until: f64,
    /// What to read off each run: `QUANTITY at EVENT [#N]`, `t at EVENT`,
    /// `max QUANTITY`, `min QUANTITY`, `period QUANTITY` or `QUANTITY at T`. Repeatable;
    /// each is a column, named as typed.
    #[arg(long, value_name = "MEASURE", required = true)]
    measure: Vec<String>,
    /// Where to write the CSV; standard output when absent or `-`.
    #[arg(long, value_name = "FILE")]
    out: Option<String>,
    /// Threads to run on (each run on one); all of the machine's when absent.
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
}

pub(crate) fn sweep(args: &SweepArgs) -> Result<(), Failure> {
    if !args.until.is_finite() {
        return Err(Failure::Input(say(
            "cli-until-not-finite",
            &[("until", &args.until.to_string())],
        )));
    }
    let scene = scene_source::load(&args.scene)?;
    if args.until < scene.simulation.start_time {
        return Err(Failure::Input(say(
            "cli-until-before-start",
            &[
                ("until", &args.until.to_string()),
                ("start", &scene.simulation.start_time.to_string()),
            ],
        )));
    }
    let varies = args
        .vary
        .iter()
        .map(|text| Vary::parse(text, &scene))
        .collect::<Result<Vec<_>, _>>()
        .map_err(Failure::Input)?;
    let measures = args
        .measure
        .iter()
        .map(|text| Measure::parse(text))
        .collect::<Result<Vec<_>, _>>()
        .map_err(Failure::Input)?;
    let sweep = Sweep {
        varies,
        until: args.until,
        measures,
        trace: false,
    };
    sweep.check(&scene).map_err(Failure::Input)?;
    let threads = args.threads.unwrap_or_else(physics::every_core);
    let bar = crate::run::progress_bar(sweep.points().len() as u64, "runs");
    let rows = sweep.run(&scene, threads, &|| bar.inc(1));
    bar.finish_and_clear();
    report_problems(args, &rows);
    let written = write_csv(args, &rows);
    match written {
        Ok(()) => {}
        Err(error) if error.kind() == io::ErrorKind::BrokenPipe => {}
        Err(error) => {
            return Err(Failure::Input(say(
                "cli-cannot-write-csv",
                &[("error", &error.to_string())],
            )));
        }
    }
    if !rows.is_empty() && rows.iter().all(|row| row.measured.is_err()) {
        return Err(Failure::Simulation(say("sweep-every-run-failed", &[])));
    }
    Ok(())
}

/// Each `--vary`'s field, as typed.
fn varied_fields(args: &SweepArgs) -> Vec<&str> {
    args.vary
        .iter()
        .map(|v| {
            v.rsplit_once('=')
                .map_or(v.as_str(), |(field, _)| field)
                .trim()
        })
        .collect()
}

/// The header (the varied fields, then the measures, as typed) and a row per run; a
/// measure without a number is an empty field.
fn write_csv(args: &SweepArgs, rows: &[Row]) -> io::Result<()> {
    let sink: Box<dyn Write> = match args.out.as_deref() {
        None | Some("-") => Box::new(io::stdout().lock()),
        Some(path) => Box::new(std::fs::File::create(path)?),
    };
    let mut out = BufWriter::new(sink);
    let names: Vec<&str> = varied_fields(args)
        .into_iter()
        .chain(args.measure.iter().map(|m| m.trim()))
        .collect();
    out.write_all(physics::series::csv(&names, rows).as_bytes())?;
    out.flush()
}

/// On stderr, each run that failed and each measure that found nothing, and why.
fn report_problems(args: &SweepArgs, rows: &[Row]) {
    let fields = varied_fields(args);
    for row in rows {
        let run = row.label(&fields);
        match &row.measured {
            Err(why) => eprintln!(
                "{}",
                say(
                    "sweep-run-failed",
                    &[("run", &run), ("why", &why.to_string())]
                )
            ),
            Ok(measured) => {
                for (text, m) in args.measure.iter().zip(measured) {
                    if let Err(why) = m {
                        eprintln!(
                            "{}",
                            say(
                                "sweep-no-measure",
                                &[
                                    ("run", &run),
                                    ("measure", text.trim()),
                                    ("why", &why.to_string())
                                ]
                            )
                        );
                    }
                }
            }
        }
    }
}
