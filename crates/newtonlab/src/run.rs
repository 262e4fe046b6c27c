//! `newtonlab run`: a scene's trajectory as CSV, sampled exactly at t = k·DT.

use std::io::{self, BufWriter, IsTerminal, Write};

use newtonlab_i18n::tr_text as say;
use std::fmt::Write as _;

use physics::{Plan, Simulation, Trajectory};

use crate::{Failure, scene_source};

#[derive(Debug, clap::Args)]
pub(crate) struct RunArgs {
    /// A scene file (.toml or .json), or example:NAME for a built-in scene.
    scene: String,
    /// Simulated time to run to, seconds.
    #[arg(long, value_name = "T", allow_hyphen_values = true)]
    until: f64,
    /// Sampling interval, seconds: rows at t = 0, DT, 2·DT, … and at T [default: 0.01,
    /// or none with --events].
    #[arg(long, value_name = "DT", allow_hyphen_values = true)]
    every: Option<f64>,
    /// A row at each instant EVENT happens, located inside its step to 1e-9 s or better:
    /// `QUANTITY crosses VALUE`, optionally `up` or `down` (`Bob.vx crosses 0 down`).
    /// May be given several times. Alone, the rows are the events'; with --every, both
    /// kinds in time order and a last column `event` naming the event (empty on the
    /// regular rows, which are those of a run without --events, bit for bit).
    #[arg(long = "events", value_name = "EVENT")]
    events: Vec<String>,
    /// A column of its own for QUANTITY, after the others (and before `event`): a rod's
    /// or string's `NAME.tension`, a particle's `NAME.speed` or `NAME.kinetic_energy`, a
    /// link's `NAME.angle` or `NAME.length`, a joint's `NAME.torque`, any quantity an
    /// event names. May be given several times; the column is named as typed.
    #[arg(long = "column", value_name = "QUANTITY")]
    columns: Vec<String>,
    /// Where to write the CSV; standard output when absent or `-`.
    #[arg(long, value_name = "FILE")]
    out: Option<String>,
    /// Also write every impact to FILE as CSV, one row each: t, particle, other (a
    /// particle's or a ramp's name, or wall), impulse (N·s), the normal speeds before
    /// and after (m/s), and the kinetic energy lost (J).
    #[arg(long, value_name = "FILE")]
    impacts: Option<String>,
    /// Also write the state at T to FILE as a scene whose start time is T, so a later
    /// run continues from there: JSON when FILE ends in .json, TOML otherwise.
    #[arg(long, value_name = "FILE")]
    save_state: Option<String>,
    /// Append the energy ledger to each row, joules: what spring damping, surface
    /// friction and impacts (with resting contact) took out of the motion since the
    /// start, the residual (kinetic + potential + all they took − the starting energy), and
    /// what air resistance took (last: it came later).
    #[arg(long)]
    ledger: bool,
    /// Run however long it takes: without it, a run of more than 10⁸ time steps, 10⁹
    /// particle-steps or 10⁸ numbers of rows is refused (a mistyped time step or
    /// interval is likelier than intent, and would look like a hang).
    #[arg(long)]
    no_limit: bool,
    /// Threads the step may use; every core when absent. The rows are the same bits for
    /// any number.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u16).range(1..=1024))]
    threads: Option<u16>,
}

pub(crate) fn run(args: &RunArgs) -> Result<(), Failure> {
    let plan = Plan {
        until: args.until,
        every: args.every,
        events: args.events.clone(),
        columns: args.columns.clone(),
        ledger: args.ledger,
        impacts: args.impacts.is_some(),
        no_limit: args.no_limit,
        threads: args.threads.map_or_else(physics::every_core, usize::from),
    };
    plan.check().map_err(Failure::Input)?;
    distinct_outputs(args)?;
    let scene = scene_source::load(&args.scene)?;
    let mut trajectory = Trajectory::new(&scene, &plan).map_err(Failure::Input)?;
    let mut impacts = match args.impacts.as_deref() {
        Some(path) => Some(ImpactLog::create(path)?),
        None => None,
    };
    if let Some(note) = trajectory.note() {
        eprintln!("{note}");
    }
    // Sendable: the rows of events are written from the step's thread as they are found.
    let sink: Box<dyn Write + Send> = match args.out.as_deref() {
        None | Some("-") => Box::new(io::stdout()),
        Some(path) => Box::new(std::fs::File::create(path).map_err(|error| {
            Failure::Input(say(
                "cli-cannot-create",
                &[("path", path), ("error", &error.to_string())],
            ))
        })?),
    };
    let mut out = BufWriter::new(sink);
    let written = write_csv(&mut trajectory, &mut out, impacts.as_mut())
        .and_then(|outcome| out.flush().map(|()| outcome));
    if let Some(log) = impacts {
        log.finish()?;
    }
    let outcome = match written {
        Ok(outcome) => outcome,
        // A reader that stops early (`| head`) is not an error of ours.
        Err(error) if error.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        Err(error) => Err(Failure::Input(say(
            "cli-cannot-write-csv",
            &[("error", &error.to_string())],
        ))),
    };
    if let (Ok(()), Some(path)) = (&outcome, args.save_state.as_deref()) {
        save_state(trajectory.simulation(), &scene, path)?;
    }
    outcome
}

/// The files the run writes are distinct: two outputs into one file would interleave
/// their rows.
fn distinct_outputs(args: &RunArgs) -> Result<(), Failure> {
    let outputs = [
        ("--out", args.out.as_deref().filter(|p| *p != "-")),
        ("--impacts", args.impacts.as_deref()),
        ("--save-state", args.save_state.as_deref()),
    ];
    for (k, (first, a)) in outputs.iter().enumerate() {
        for (second, b) in &outputs[k + 1..] {
            if let (Some(a), Some(b)) = (a, b)
                && std::path::Path::new(a) == std::path::Path::new(b)
            {
                return Err(Failure::Input(say(
                    "cli-same-output",
                    &[("first", first), ("second", second), ("path", a)],
                )));
            }
        }
    }
    Ok(())
}

/// `--save-state FILE`: the scene with the state reached, as a scene file.
fn save_state(simulation: &Simulation, scene: &physics::Scene, path: &str) -> Result<(), Failure> {
    let saved = simulation.saved_state(scene);
    // A state that would not reopen (a body flung beyond 1e100 m) is said, not written.
    if let Some(problem) = saved.validate().into_iter().next() {
        return Err(Failure::Simulation(say(
            "cli-state-not-saveable",
            &[
                ("time", &simulation.time().to_string()),
                ("problem", &problem.message),
            ],
        )));
    }
    let text = match physics::SceneFormat::from_file_name(path) {
        physics::SceneFormat::Json => saved.to_json(),
        physics::SceneFormat::Toml => saved.to_toml(),
    };
    std::fs::write(path, text).map_err(|error| {
        Failure::Input(say(
            "cli-cannot-save-state",
            &[("path", path), ("error", &error.to_string())],
        ))
    })
}

/// Writes the header and every row; a simulation failure ends the table after the last
/// good row and becomes the outcome. The numbers are the shortest text that parses back
/// to the same f64 (the ledger's in the shortest form, `0` rather than `0.0`, as it
/// always was).
fn write_csv(
    trajectory: &mut Trajectory,
    out: &mut (impl Write + Send),
    mut impacts: Option<&mut ImpactLog>,
) -> io::Result<Result<(), Failure>> {
    let columns = trajectory.columns();
    let ledger = trajectory.ledger_columns();
    // The `event` column only where both kinds of rows are: it tells them apart.
    let named = trajectory.mixes_rows();
    let mut header: Vec<String> = columns.iter().map(|c| physics::csv_field(c)).collect();
    if named {
        header.push("event".to_owned());
    }
    writeln!(out, "{}", header.join(","))?;
    let mut failed = None;
    let mut line = String::new();
    let progress = progress_bar(trajectory.instants() as u64, "rows");
    loop {
        let mut written = Ok(());
        let stepped = trajectory.advance(&mut |row| {
            if written.is_err() {
                return;
            }
            line.clear();
            for (k, value) in row.values.iter().enumerate() {
                let comma = if k == 0 { "" } else { "," };
                let _ = if ledger.contains(&k) {
                    write!(line, "{comma}{value}")
                } else {
                    write!(line, "{comma}{value:?}")
                };
            }
            if named {
                let _ = write!(
                    line,
                    ",{}",
                    row.event.map(physics::csv_field).unwrap_or_default()
                );
            }
            written = writeln!(out, "{line}");
        });
        written?;
        if let Some(log) = impacts.as_deref_mut() {
            let records = trajectory.take_impacts();
            log.write(trajectory, &records);
        }
        match stepped {
            None => break,
            Some(Ok(())) => progress.inc(1),
            Some(Err(error)) => {
                failed = Some(Failure::Simulation(error.to_string()));
                break;
            }
        }
    }
    progress.finish_and_clear();
    Ok(failed.map_or(Ok(()), Err))
}

/// `--impacts FILE`: one row per impact, with names rather than indices. A write error
/// is kept and reported when the run ends, so the trajectory is still written.
struct ImpactLog {
    path: String,
    out: BufWriter<std::fs::File>,
    error: Option<io::Error>,
}

impl ImpactLog {
    fn create(path: &str) -> Result<Self, Failure> {
        let file = std::fs::File::create(path).map_err(|error| {
            Failure::Input(say(
                "cli-cannot-create-log",
                &[("path", path), ("error", &error.to_string())],
            ))
        })?;
        let mut log = Self {
            path: path.to_owned(),
            out: BufWriter::new(file),
            error: None,
        };
        log.line(format_args!("{}", physics::IMPACT_COLUMNS.join(",")));
        Ok(log)
    }

    fn line(&mut self, text: std::fmt::Arguments<'_>) {
        if self.error.is_none() {
            self.error = writeln!(self.out, "{text}").err();
        }
    }

    fn write(&mut self, trajectory: &Trajectory, impacts: &[physics::ImpactRecord]) {
        for impact in impacts {
            let (particle, other) = trajectory.impact_names(impact);
            self.line(format_args!(
                "{},{},{},{},{},{},{}",
                impact.time,
                physics::csv_field(particle),
                physics::csv_field(other),
                impact.impulse,
                impact.normal_speed_before,
                impact.normal_speed_after,
                impact.kinetic_energy_lost
            ));
        }
    }

    fn finish(mut self) -> Result<(), Failure> {
        if self.error.is_none() {
            self.error = self.out.flush().err();
        }
        match self.error {
            None => Ok(()),
            Some(error) => Err(Failure::Input(format!(
                "cannot write the impact log '{}': {error}",
                self.path
            ))),
        }
    }
}

/// A progress bar of `len` `things` on stderr when it is a terminal (hidden otherwise).
pub(crate) fn progress_bar(len: u64, things: &str) -> indicatif::ProgressBar {
    if !io::stderr().is_terminal() {
        return indicatif::ProgressBar::hidden();
    }
    let bar = indicatif::ProgressBar::new(len);
    if let Ok(style) = indicatif::ProgressStyle::with_template(&format!(
        "{{bar:40}} {{pos}}/{{len}} {things}, {{eta}} left"
    )) {
        bar.set_style(style);
    }
    bar
}
