//! `newtonlab run`: a scene's trajectory as CSV, sampled exactly at t = k·DT.

use std::io::{self, BufWriter, IsTerminal, Write};

use newtonlab_i18n::tr_text as say;
use physics::Simulation;

use crate::{Failure, scene_source};

/// The largest index k of a row's instant k·DT: 2⁵², below which consecutive products
/// are distinct f64s.
const MAX_GRID_INDEX: f64 = 4_503_599_627_370_496.0;
/// The most rows one run may write: beyond this a typo in --every is likelier than intent.
const MAX_ROWS: f64 = 1e8;
/// The most time steps one run may take: 10⁹ steps of even the lightest scene take about
/// a quarter of an hour here; more is a time step or a --until mistyped, and would look
/// like a hang.
const MAX_STEPS: f64 = 1e9;

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
}

pub(crate) fn run(args: &RunArgs) -> Result<(), Failure> {
    if !args.until.is_finite() {
        return Err(Failure::Input(say(
            "cli-until-not-finite",
            &[("until", &args.until.to_string())],
        )));
    }
    let events = events(args)?;
    let every = every(args, &events)?;
    distinct_outputs(args)?;
    let scene = scene_source::load(&args.scene)?;
    check_extent(args, every, &scene)?;
    let start = scene.simulation.start_time;
    let mut simulation = Simulation::new(&scene).map_err(|e| Failure::Input(e.to_string()))?;
    if args.ledger {
        simulation.keep_ledger();
    }
    let mut impacts = match args.impacts.as_deref() {
        Some(path) => {
            simulation.record_impacts();
            Some(ImpactLog::create(path, &scene)?)
        }
        None => None,
    };
    if let Some(note) = every.and_then(|every| sampling_note(&scene.simulation, every)) {
        eprintln!("{note}");
    }
    let watch = watch(events, &simulation)?;
    let times = every.map_or_else(
        || vec![start, args.until],
        |every| sample_times(start, args.until, every),
    );
    let rows = Rows {
        regular: every.is_some(),
        watch,
    };
    let sink: Box<dyn Write> = match args.out.as_deref() {
        None | Some("-") => Box::new(io::stdout().lock()),
        Some(path) => Box::new(std::fs::File::create(path).map_err(|error| {
            Failure::Input(say(
                "cli-cannot-create",
                &[("path", path), ("error", &error.to_string())],
            ))
        })?),
    };
    let mut out = BufWriter::new(sink);
    let written = write_csv(&mut simulation, &times, rows, &mut out, impacts.as_mut())
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
        save_state(&simulation, &scene, path)?;
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

/// Whether the run asked for stays within what it can do: it ends after it starts, its
/// rows' instants are distinct, and neither its rows nor its steps are beyond reason.
fn check_extent(args: &RunArgs, every: Option<f64>, scene: &physics::Scene) -> Result<(), Failure> {
    let start = scene.simulation.start_time;
    if args.until < start {
        let (until, start) = (args.until.to_string(), start.to_string());
        let id = if scene.simulation.start_time == 0.0 {
            "cli-until-negative"
        } else {
            "cli-until-before-start"
        };
        return Err(Failure::Input(say(
            id,
            &[("until", &until), ("start", &start)],
        )));
    }
    let span = args.until - start;
    // Rows at k·DT: k must stay an integer an f64 counts exactly, or the grid's instants
    // run together (and the rows' search for them would not end).
    if let Some(every) = every
        && start.abs().max(args.until.abs()) / every > MAX_GRID_INDEX
    {
        return Err(Failure::Input(say(
            "cli-every-too-fine",
            &[
                ("every", &every.to_string()),
                ("until", &args.until.to_string()),
            ],
        )));
    }
    if let Some(every) = every
        && span / every > MAX_ROWS
    {
        return Err(Failure::Input(say(
            "cli-too-many-rows",
            &[
                ("until", &args.until.to_string()),
                ("every", &every.to_string()),
                ("rows", &MAX_ROWS.to_string()),
            ],
        )));
    }
    let steps = span / scene.simulation.time_step;
    if steps > MAX_STEPS {
        return Err(Failure::Input(say(
            "cli-too-many-steps",
            &[
                ("until", &args.until.to_string()),
                ("step", &format!("{:e}", scene.simulation.time_step)),
                ("steps", &format!("{steps:.1e}")),
                ("most", &format!("{MAX_STEPS:e}")),
            ],
        )));
    }
    Ok(())
}

/// `--events`: each event as typed (trimmed) and as read.
fn events(args: &RunArgs) -> Result<Vec<(String, physics::Event)>, Failure> {
    args.events
        .iter()
        .map(|text| physics::Event::parse(text).map(|event| (text.trim().to_owned(), event)))
        .collect::<Result<Vec<_>, String>>()
        .map_err(|reason| Failure::Input(say("cli-event-invalid", &[("reason", &reason)])))
}

/// The sampling interval: `--every`, or 0.01 s unless there are events (then none).
fn every(args: &RunArgs, events: &[(String, physics::Event)]) -> Result<Option<f64>, Failure> {
    let every = match (args.every, events.is_empty()) {
        (Some(every), _) => Some(every),
        (None, true) => Some(0.01),
        (None, false) => None,
    };
    match every {
        Some(every) if !(every.is_finite() && every > 0.0) => Err(Failure::Input(say(
            "cli-every-invalid",
            &[("every", &every.to_string())],
        ))),
        _ => Ok(every),
    }
}

/// The watch of `events` in `simulation`, with their names, if there are any.
fn watch(
    events: Vec<(String, physics::Event)>,
    simulation: &Simulation,
) -> Result<Option<(physics::Watch, Vec<String>)>, Failure> {
    if events.is_empty() {
        return Ok(None);
    }
    let (names, list): (Vec<String>, Vec<physics::Event>) = events.into_iter().unzip();
    let watch = physics::Watch::new(&list, simulation)
        .map_err(|reason| Failure::Input(say("cli-event-invalid", &[("reason", &reason)])))?;
    Ok(Some((watch, names)))
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

/// A fixed-step method lands exactly on every sample, so when --every is not a whole
/// number of time steps some steps are shortened and the run integrates with a smaller
/// effective step than the scene says (more accurately, and differently from a run
/// sampled at a multiple). Says so, with the step and the interval.
fn sampling_note(settings: &physics::Settings, every: f64) -> Option<String> {
    if settings.integrator == physics::Integrator::Dopri5 {
        return None; // adaptive: its steps follow the error, not the time step
    }
    let steps = every / settings.time_step;
    if (steps - steps.round()).abs() <= 1e-9 * steps.max(1.0) {
        return None;
    }
    Some(say(
        "cli-sampling-note",
        &[
            ("every", &every.to_string()),
            ("step", &settings.time_step.to_string()),
        ],
    ))
}

/// t = k·DT for every k with start ≤ k·DT ≤ T (each computed as k × DT, never
/// accumulated: the grid of a run from 0), with `start` first and T last when they are
/// not among them.
fn sample_times(start: f64, until: f64, every: f64) -> Vec<f64> {
    #[expect(
        clippy::cast_possible_truncation,
        reason = "until / every and start / every are finite and bounded by the caller's checks"
    )]
    let index = |t: f64| (t / every).floor() as i64;
    let at = |k: i64| k as f64 * every;
    let (mut first, mut last) = (index(start), index(until));
    // The division may round either way: settle each end on the exact products.
    while at(first) < start {
        first += 1;
    }
    while at(first - 1) >= start {
        first -= 1;
    }
    while at(last + 1) <= until {
        last += 1;
    }
    while at(last) > until {
        last -= 1;
    }
    let mut times = Vec::new();
    // Exact: the start is a row of its own unless it is a grid instant to the bit.
    if first > last || at(first).to_bits() != start.to_bits() {
        times.push(start);
    }
    times.extend((first..=last).map(at));
    if times.last() != Some(&until) {
        times.push(until);
    }
    times
}

/// What `run` writes rows of: the samples (`regular`), and the events of a watch with
/// the names they were given.
struct Rows {
    regular: bool,
    watch: Option<(physics::Watch, Vec<String>)>,
}

/// Writes the header and a row per sample and per event; a simulation failure ends the
/// table after the last good row and becomes the outcome. Without regular rows `times`
/// is only the start and the end.
fn write_csv(
    simulation: &mut Simulation,
    times: &[f64],
    mut rows: Rows,
    out: &mut impl Write,
    mut impacts: Option<&mut ImpactLog>,
) -> io::Result<Result<(), Failure>> {
    let ledger_start = simulation
        .ledger()
        .map(|_| simulation.diagnostics().energy.total());
    // The `event` column only where both kinds of rows are: it tells them apart.
    let named = rows.regular && rows.watch.is_some();
    let mut header = simulation.csv_header();
    if ledger_start.is_some() {
        // Drag's column comes last, after the residual: it was added after files were
        // read by column position.
        header.push_str(
            ",dissipated_damping,dissipated_friction,dissipated_impacts,energy_residual,dissipated_drag",
        );
    }
    if named {
        header.push_str(",event");
    }
    writeln!(out, "{header}")?;
    let row = |out: &mut dyn Write, simulation: &Simulation, event: Option<&str>| {
        write!(out, "{}", simulation.csv_row())?;
        if let (Some(ledger), Some(start)) = (simulation.ledger(), ledger_start) {
            let residual = simulation.diagnostics().energy.total() + ledger.total() - start;
            write!(
                out,
                ",{},{},{},{residual},{}",
                ledger.damping, ledger.friction, ledger.impacts, ledger.drag
            )?;
        }
        if named {
            write!(
                out,
                ",{}",
                event.map(physics::csv_field).unwrap_or_default()
            )?;
        }
        writeln!(out)
    };
    let progress = progress_bar(times.len() as u64, "rows");
    for &t in times {
        let stepped = match &mut rows.watch {
            Some((watch, names)) => match simulation.step_to_watching(t, watch) {
                Ok(found) => {
                    for event in &found {
                        row(out, &event.at, Some(&names[event.event]))?;
                    }
                    Ok(())
                }
                Err(error) => Err(error),
            },
            None => simulation.step_to(t),
        };
        if let Some(log) = impacts.as_deref_mut() {
            log.write(&simulation.take_impacts());
        }
        if let Err(error) = stepped {
            progress.finish_and_clear();
            return Ok(Err(Failure::Simulation(error.to_string())));
        }
        if rows.regular {
            row(out, simulation, None)?;
        }
        progress.inc(1);
    }
    progress.finish_and_clear();
    Ok(Ok(()))
}

/// `--impacts FILE`: one row per impact, with names rather than indices. A write error
/// is kept and reported when the run ends, so the trajectory is still written.
struct ImpactLog {
    path: String,
    out: BufWriter<std::fs::File>,
    particles: Vec<String>,
    ramps: Vec<String>,
    error: Option<io::Error>,
}

impl ImpactLog {
    fn create(path: &str, scene: &physics::Scene) -> Result<Self, Failure> {
        let file = std::fs::File::create(path).map_err(|error| {
            Failure::Input(say(
                "cli-cannot-create-log",
                &[("path", path), ("error", &error.to_string())],
            ))
        })?;
        let mut log = Self {
            path: path.to_owned(),
            out: BufWriter::new(file),
            particles: scene.particle_names(),
            ramps: scene.ramps.iter().map(|r| r.name.clone()).collect(),
            error: None,
        };
        log.line(format_args!(
            "t,particle,other,impulse,normal_speed_before,normal_speed_after,kinetic_energy_lost"
        ));
        Ok(log)
    }

    fn line(&mut self, text: std::fmt::Arguments<'_>) {
        if self.error.is_none() {
            self.error = writeln!(self.out, "{text}").err();
        }
    }

    fn write(&mut self, impacts: &[physics::ImpactRecord]) {
        for impact in impacts {
            let other = match impact.other {
                physics::ImpactTarget::Particle(j) => self.particles[j].clone(),
                physics::ImpactTarget::Ramp(k) => self.ramps[k].clone(),
                physics::ImpactTarget::Wall => "wall".to_owned(),
            };
            let particle = self.particles[impact.particle].clone();
            self.line(format_args!(
                "{},{},{},{},{},{},{}",
                impact.time,
                physics::csv_field(&particle),
                physics::csv_field(&other),
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

/// A progress bar on stderr when it is a terminal; hidden otherwise.
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

#[cfg(test)]
mod tests {
    use super::sample_times as from;

    fn sample_times(until: f64, every: f64) -> Vec<f64> {
        from(0.0, until, every)
    }

    #[test]
    fn samples_are_multiples_of_the_interval_and_end_at_until() {
        // 3 × 0.1 = 0.30000000000000004 > 0.3, so the last multiple is 0.2 and 0.3 is added.
        assert_eq!(
            sample_times(0.3, 0.1),
            vec![0.0, 0.1, 0.2, 0.3],
            "0.3 by 0.1"
        );
        assert_eq!(
            sample_times(1.0, 0.25),
            vec![0.0, 0.25, 0.5, 0.75, 1.0],
            "no duplicate end"
        );
        assert_eq!(
            sample_times(1.05, 0.5),
            vec![0.0, 0.5, 1.0, 1.05],
            "end off the grid"
        );
        assert_eq!(sample_times(0.0, 0.1), vec![0.0], "zero duration");
        let times = sample_times(20.0, 0.1);
        assert_eq!(times.len(), 201, "20 s by 0.1 s");
        assert_eq!(
            times[7].to_bits(),
            (7.0_f64 * 0.1).to_bits(),
            "k·DT, not accumulated"
        );
    }

    /// From a start time the rows are those of the grid of a run from 0 that fall in
    /// [start, T], with the start first and T last when they are not on it.
    #[test]
    fn from_a_start_time_the_rows_keep_the_grid_of_a_run_from_zero() {
        assert_eq!(
            from(0.25, 1.0, 0.5),
            vec![0.25, 0.5, 1.0],
            "start off the grid"
        );
        assert_eq!(from(0.5, 1.0, 0.5), vec![0.5, 1.0], "start on the grid");
        assert_eq!(from(0.3, 0.4, 0.5), vec![0.3, 0.4], "no grid point between");
        assert_eq!(from(1.0, 1.0, 0.5), vec![1.0], "zero duration");
        assert_eq!(
            from(-1.2, 0.3, 0.5),
            vec![-1.2, -1.0, -0.5, 0.0, 0.3],
            "negative start"
        );
        let times = from(1.0, 2.0, 0.1);
        // 10 × 0.1 = 1 exactly; 11 × 0.1 = 1.1000000000000001 is the grid's, not 1 + 0.1.
        assert_eq!(times.len(), 11, "{times:?}");
        assert_eq!(
            times[1].to_bits(),
            (11.0_f64 * 0.1).to_bits(),
            "the grid of a run from 0"
        );
    }
}
