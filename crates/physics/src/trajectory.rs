//! A run sampled as a table: the rows of `newtonlab run` and of Python's `newtonlab.run`,
//! one implementation for both, so the two give the same numbers bit for bit.
//!
//! A [`Plan`] says what is asked (until when, how often, which events, whether the energy
//! ledger and the impacts are kept); [`Trajectory::new`] checks it against the scene (an
//! end before the start, a grid whose instants run together, more rows or steps than a
//! run can take are refused, in words) and [`Trajectory::advance`] steps to each sample
//! instant in turn and hands over its rows: those of the events located on the way (each
//! at its own instant, inside its step), then the sample's. The samples are at k·DT
//! (each computed as k × DT, never accumulated: the grid of a run from 0), so a run from
//! a saved state samples the instants a run from 0 would.

use crate::Integrator;
use crate::events::Watch;
use crate::impact::{ImpactRecord, ImpactTarget};
use crate::quantity::{Event, Quantity, Reading};
use crate::scene::series::{MAX_STEPS, MAX_WORK, run_size};
use crate::scene::{Scene, Settings, say};
use crate::simulation::{Simulation, SimulationError};

/// The largest index k of a row's instant k·DT: 2⁵², below which consecutive products
/// are distinct f64s.
const MAX_GRID_INDEX: f64 = 4_503_599_627_370_496.0;
/// The most numbers one run's rows may hold without [`Plan::no_limit`]: 10⁸, some 2 GB of
/// CSV; beyond this a typo in the interval is likelier than intent.
pub const MAX_NUMBERS: f64 = 1e8;
/// The ledger's columns, in the order the rows give them. Drag's comes last, after the
/// residual: it was added after files were read by column position.
pub const LEDGER_COLUMNS: [&str; 5] = [
    "dissipated_damping",
    "dissipated_friction",
    "dissipated_impacts",
    "energy_residual",
    "dissipated_drag",
];

/// The ledger's last column where the scene has a motor: the work the motors did, J.
pub const MOTOR_WORK_COLUMN: &str = "work_motors";

/// The impact table's columns.
pub const IMPACT_COLUMNS: [&str; 7] = [
    "t",
    "particle",
    "other",
    "impulse",
    "normal_speed_before",
    "normal_speed_after",
    "kinetic_energy_lost",
];

/// What a run is asked for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Plan {
    /// Simulated time to run to, seconds.
    pub until: f64,
    /// The sampling interval, seconds; `None` for 0.01 s, or for no samples when there
    /// are events.
    pub every: Option<f64>,
    /// Events to locate, as typed (`Bob.vx crosses 0 down`).
    pub events: Vec<String>,
    /// Whether the rows end with the energy ledger ([`LEDGER_COLUMNS`]).
    pub ledger: bool,
    /// Quantities as typed (`rod.tension`, `Ball.kinetic_energy`), each a column of its
    /// own after the others: what the standard columns do not hold.
    pub columns: Vec<String>,
    /// Whether impacts are kept, for [`Trajectory::take_impacts`].
    pub impacts: bool,
    /// Whether to run beyond [`MAX_STEPS`], [`MAX_WORK`] and [`MAX_NUMBERS`] (`--no-limit`).
    pub no_limit: bool,
    /// Threads the step may use ([`Simulation::set_threads`]; 0 or 1: one). The rows are
    /// the same bits for any number.
    pub threads: usize,
}

/// An event as typed (trimmed) and as read.
type Named = (String, Event);

impl Plan {
    /// Whether the plan makes sense before any scene is read: an end that is a number, an
    /// interval that is a positive number, events that parse.
    ///
    /// # Errors
    /// The first of those that does not hold, in words.
    pub fn check(&self) -> Result<(), String> {
        self.read().map(|_| ())
    }

    /// The events, each as typed (trimmed) and as read, and the sampling interval.
    fn read(&self) -> Result<(Vec<Named>, Option<f64>), String> {
        for text in &self.columns {
            Quantity::parse(text.trim())
                .map_err(|reason| say("cli-column-invalid", &[("reason", &reason)]))?;
        }
        if !self.until.is_finite() {
            return Err(say(
                "cli-until-not-finite",
                &[("until", &self.until.to_string())],
            ));
        }
        let events = self
            .events
            .iter()
            .map(|text| Event::parse(text).map(|event| (text.trim().to_owned(), event)))
            .collect::<Result<Vec<_>, String>>()
            .map_err(|reason| say("cli-event-invalid", &[("reason", &reason)]))?;
        let every = match (self.every, events.is_empty()) {
            (Some(every), _) => Some(every),
            (None, true) => Some(0.01),
            (None, false) => None,
        };
        if let Some(every) = every
            && !(every.is_finite() && every > 0.0)
        {
            return Err(say("cli-every-invalid", &[("every", &every.to_string())]));
        }
        Ok((events, every))
    }
}

/// One row: its values in the order of [`Trajectory::columns`], and the event it is the
/// instant of (`None` for a sample).
#[derive(Clone, Copy, Debug)]
pub struct Row<'a> {
    /// The values.
    pub values: &'a [f64],
    /// The event's name as typed, for an event's row.
    pub event: Option<&'a str>,
}

/// A run in progress, sampled.
#[derive(Clone, Debug)]
pub struct Trajectory {
    simulation: Simulation,
    /// The sample instants (without samples: the start and the end, to step to).
    times: Vec<f64>,
    next: usize,
    /// Whether the instants of `times` are rows.
    regular: bool,
    /// The interval of the rows' grid, when there is one.
    every: Option<f64>,
    watch: Option<(Watch, Vec<String>)>,
    /// The energy at the start, when the ledger is kept.
    ledger_start: Option<f64>,
    note: Option<String>,
    /// The ramps' names, for the impacts' (the particles' are the simulation's).
    ramps: Vec<String>,
    /// The quantities asked as columns of their own, as typed and as found.
    extra: Vec<(String, Reading)>,
    values: Vec<f64>,
}

impl Trajectory {
    /// The run `plan` asks of `scene`, not yet started.
    ///
    /// # Errors
    /// In words: the scene's problems (each with its location where the file gave one),
    /// an end that is not finite or comes before the start, an interval that is not a
    /// positive number, too many rows or steps, an event that does not parse or names
    /// nothing in the scene.
    pub fn new(scene: &Scene, plan: &Plan) -> Result<Self, String> {
        let (events, every) = plan.read()?;
        check_extent(plan, every, scene)?;
        let mut simulation = Simulation::new(scene).map_err(|e| e.to_string())?;
        if plan.ledger {
            simulation.keep_ledger();
        }
        if plan.impacts {
            simulation.record_impacts();
        }
        simulation.set_threads(plan.threads);
        let watch = if events.is_empty() {
            None
        } else {
            let (names, list): (Vec<String>, Vec<Event>) = events.into_iter().unzip();
            let watch = Watch::new(&list, &simulation)
                .map_err(|reason| say("cli-event-invalid", &[("reason", &reason)]))?;
            Some((watch, names))
        };
        let start = scene.simulation.start_time;
        let times = every.map_or_else(
            || vec![start, plan.until],
            |every| sample_times(start, plan.until, every),
        );
        let ledger_start = plan.ledger.then(|| simulation.diagnostics().energy.total());
        let extra = plan
            .columns
            .iter()
            .map(|text| {
                let quantity = Quantity::parse(text.trim())?;
                Ok((text.trim().to_owned(), quantity.reading(&simulation)?))
            })
            .collect::<Result<Vec<_>, String>>()
            .map_err(|reason| say("cli-column-invalid", &[("reason", &reason)]))?;
        Ok(Self {
            simulation,
            times,
            next: 0,
            regular: every.is_some(),
            every,
            watch,
            ledger_start,
            note: every.and_then(|every| sampling_note(&scene.simulation, every)),
            ramps: scene.ramps.iter().map(|r| r.name.clone()).collect(),
            extra,
            values: Vec::new(),
        })
    }

    /// The columns' names, unquoted: the state's ([`Simulation::csv_columns`]), the
    /// ledger's when it is kept, then the quantities asked as columns ([`Plan::columns`]).
    /// The event of a row is not among them ([`Row::event`]).
    pub fn columns(&self) -> Vec<String> {
        column_names(&self.simulation, self.ledger_start, &self.extra)
    }

    /// Whether the rows hold the ledger's columns ([`LEDGER_COLUMNS`]).
    pub fn keeps_ledger(&self) -> bool {
        self.ledger_start.is_some()
    }

    /// Where the ledger's columns are among [`Self::columns`] (empty without a ledger):
    /// they are written in their shortest form (`0`, not `0.0`), as they always were.
    pub fn ledger_columns(&self) -> std::ops::Range<usize> {
        // The state's columns, then the ledger's (none without it), then the asked ones.
        self.simulation.csv_columns().len()..self.columns().len() - self.extra.len()
    }

    /// Whether a table needs a column saying which event a row is: the rows are of both
    /// kinds, samples and events, or of several events.
    pub fn mixes_rows(&self) -> bool {
        self.watch
            .as_ref()
            .is_some_and(|(_, names)| self.regular || names.len() > 1)
    }

    /// How many instants [`Self::advance`] steps to in all.
    pub fn instants(&self) -> usize {
        self.times.len()
    }

    /// When the interval is not a whole number of fixed steps: a note that some steps
    /// are shortened to land on the samples.
    pub fn note(&self) -> Option<&str> {
        self.note.as_deref()
    }

    /// The run as it stands.
    pub fn simulation(&self) -> &Simulation {
        &self.simulation
    }

    /// Steps on to the next instant, calling `each` with every row on the way (the
    /// events located inside the steps, in time order, then the sample). `None` once
    /// every instant is reached; `Some(Err)` when the simulation failed (its rows up to
    /// the failure were given; the run stops there).
    pub fn advance(
        &mut self,
        each: &mut (dyn FnMut(Row<'_>) + Send),
    ) -> Option<Result<(), SimulationError>> {
        let &t = self.times.get(self.next)?;
        self.next += 1;
        let stepped = match &mut self.watch {
            Some((watch, names)) => {
                // Each event's row goes out at the end of its step: a run of events alone
                // is one instant, and its rows stream rather than wait for the end.
                let (values, ledger_start, extra) =
                    (&mut self.values, self.ledger_start, &self.extra);
                self.simulation
                    .step_to_watching_each(t, watch, &mut |event| {
                        row_values(&event.at, ledger_start, extra, values);
                        finite_row(values, &event.at, ledger_start, extra)?;
                        each(Row {
                            values,
                            event: Some(&names[event.event]),
                        });
                        Ok(())
                    })
            }
            None => self.simulation.step_to(t),
        };
        let stepped = stepped.and_then(|()| {
            if !self.regular {
                return Ok(());
            }
            row_values(
                &self.simulation,
                self.ledger_start,
                &self.extra,
                &mut self.values,
            );
            finite_row(
                &self.values,
                &self.simulation,
                self.ledger_start,
                &self.extra,
            )?;
            // The row's instant as the grid names it (0.6, where the run stands at
            // 6 × 0.1 = 0.6000000000000001): what a reader of the table asked for.
            if let Some(t) = self.values.first_mut() {
                *t = instant_text(*t, self.every).parse().unwrap_or(*t);
            }
            each(Row {
                values: &self.values,
                event: None,
            });
            Ok(())
        });
        if stepped.is_err() {
            self.next = self.times.len();
        }
        Some(stepped)
    }

    /// The impacts since the last call, when the plan keeps them.
    pub fn take_impacts(&mut self) -> Vec<ImpactRecord> {
        self.simulation.take_impacts()
    }

    /// An impact's particle and what it hit, by name (`wall` for a wall).
    pub fn impact_names(&self, impact: &ImpactRecord) -> (&str, &str) {
        let other = match impact.other {
            ImpactTarget::Particle(j) => self.simulation.names()[j].as_str(),
            ImpactTarget::Ramp(k) => self.ramps[k].as_str(),
            ImpactTarget::Wall => "wall",
        };
        (self.simulation.names()[impact.particle].as_str(), other)
    }
}

/// `values`, a row of `simulation` (with the ledger's columns when `ledger_start` is
/// set), if every value in it is finite; otherwise the run has failed there, at the
/// first such column (an acceleration that overflowed between two bodies 1e-100 m apart
/// is infinite while their positions are not): a row is never written with a number
/// that is not one.
fn finite_row(
    values: &[f64],
    simulation: &Simulation,
    ledger_start: Option<f64>,
    extra: &[(String, Reading)],
) -> Result<(), SimulationError> {
    let Some(k) = values.iter().position(|v| !v.is_finite()) else {
        return Ok(());
    };
    let mut columns = column_names(simulation, ledger_start, extra);
    Err(SimulationError::ValueNotFinite {
        quantity: columns.swap_remove(k),
        value: values[k],
        time: values[0],
    })
}

/// The names of a row's columns: `simulation`'s state, the ledger's when `ledger_start`
/// is set, then the quantities of `extra`.
fn column_names(
    simulation: &Simulation,
    ledger_start: Option<f64>,
    extra: &[(String, Reading)],
) -> Vec<String> {
    let mut columns = simulation.csv_columns();
    if ledger_start.is_some() {
        columns.extend(LEDGER_COLUMNS.map(str::to_owned));
        if simulation.has_motors() {
            columns.push(MOTOR_WORK_COLUMN.to_owned());
        }
    }
    columns.extend(extra.iter().map(|(name, _)| name.clone()));
    columns
}

/// `simulation`'s row: its state, then the ledger when `ledger_start` is the energy it
/// started from, then the quantities of `extra`.
fn row_values(
    simulation: &Simulation,
    ledger_start: Option<f64>,
    extra: &[(String, Reading)],
    out: &mut Vec<f64>,
) {
    out.clear();
    simulation.csv_values(out);
    if let (Some(ledger), Some(start)) = (simulation.ledger(), ledger_start) {
        let residual = simulation.diagnostics().energy.total() + ledger.total() - start;
        out.extend([
            ledger.damping,
            ledger.friction,
            ledger.impacts,
            residual,
            ledger.drag,
        ]);
        if simulation.has_motors() {
            out.push(ledger.motors);
        }
    }
    out.extend(extra.iter().map(|&(_, reading)| simulation.read(reading)));
}

/// Whether the run `plan` asks of `scene`, sampled every `every`, stays within what it
/// can do: it ends after it starts and its rows' instants are distinct; and, unless the
/// plan says `no_limit`, its steps, its work and its rows are within reason.
fn check_extent(plan: &Plan, every: Option<f64>, scene: &Scene) -> Result<(), String> {
    let (until, settings) = (plan.until, &scene.simulation);
    let start = settings.start_time;
    if until < start {
        let id = if start == 0.0 {
            "cli-until-negative"
        } else {
            "cli-until-before-start"
        };
        return Err(say(
            id,
            &[("until", &until.to_string()), ("start", &start.to_string())],
        ));
    }
    let span = until - start;
    // Rows at k·DT: k must stay an integer an f64 counts exactly, or the grid's instants
    // run together (and the rows' search for them would not end).
    if let Some(every) = every
        && start.abs().max(until.abs()) / every > MAX_GRID_INDEX
    {
        return Err(say(
            "cli-every-too-fine",
            &[("every", &every.to_string()), ("until", &until.to_string())],
        ));
    }
    if plan.no_limit {
        return Ok(());
    }
    let columns =
        6 * scene.particles.len() + 6 + if plan.ledger { LEDGER_COLUMNS.len() } else { 0 };
    if let Some(every) = every
        && (span / every + 2.0) * columns as f64 > MAX_NUMBERS
    {
        return Err(say(
            "cli-too-many-rows",
            &[
                ("until", &until.to_string()),
                ("every", &every.to_string()),
                ("rows", &format!("{:.1e}", span / every)),
                ("columns", &columns.to_string()),
                ("most", &format!("{MAX_NUMBERS:e}")),
            ],
        ));
    }
    run_work(scene, until).map(|_| ())
}

/// The particle-steps a run of `scene` to `until` takes (moving particles × steps), or
/// why it is too long: more than [`MAX_STEPS`] steps or [`MAX_WORK`] particle-steps.
///
/// # Errors
/// The run's steps or work, over their bound, in words.
pub fn run_work(scene: &Scene, until: f64) -> Result<f64, String> {
    let settings = &scene.simulation;
    let (steps, work) = run_size(scene, until);
    if steps > MAX_STEPS {
        return Err(say(
            "cli-too-many-steps",
            &[
                ("until", &until.to_string()),
                ("step", &format!("{:e}", settings.time_step)),
                ("steps", &format!("{steps:.1e}")),
                ("most", &format!("{MAX_STEPS:e}")),
            ],
        ));
    }
    let particles = scene.particles.iter().filter(|p| !p.fixed).count().max(1);
    if work > MAX_WORK {
        return Err(say(
            "cli-too-much-work",
            &[
                ("until", &until.to_string()),
                ("steps", &format!("{steps:.1e}")),
                ("particles", &particles.to_string()),
                ("work", &format!("{work:.1e}")),
                ("most", &format!("{MAX_WORK:e}")),
            ],
        ));
    }
    Ok(work)
}

/// A fixed-step method lands exactly on every sample, so when the interval is not a
/// whole number of time steps some steps are shortened and the run integrates with a
/// smaller effective step than the scene says (more accurately, and differently from a
/// run sampled at a multiple). Says so, with the step and the interval.
fn sampling_note(settings: &Settings, every: f64) -> Option<String> {
    if settings.integrator == Integrator::Dopri5 {
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
        reason = "until / every and start / every are finite and bounded by check_extent"
    )]
    let index = |t: f64| (t / every).floor() as i64;
    let at = |k: i64| k as f64 * every;
    // An instant typed as the grid names it (0.7 for 7 × 0.1, which is 0.7000000000000001
    // in f64) stands for that grid instant: a run to it ends where a longer run's row
    // stands, so that its saved state continues that run, and a start on it is the
    // grid's row, not a second one an ulp later.
    let near = |t: f64| {
        let k = index(t + 0.5 * every);
        let exact = at(k).to_bits() == t.to_bits();
        (exact || (at(k) - t).abs() <= GRID_ROUNDING * t.abs()).then_some(k)
    };
    let until = near(until).map_or(until, |k| at(k).max(start));
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
    if let Some(k) = near(start)
        && k == first
        && at(k).to_bits() != start.to_bits()
    {
        first += 1;
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

/// How far, relative to it, an instant may lie from a grid instant k·DT and still be
/// that instant as typed: a few roundings of the product.
const GRID_ROUNDING: f64 = 4.0 * f64::EPSILON;

/// A row's instant as text: an instant of the grid k·`every` as the decimal the grid
/// names it (`0.7` for 7 × 0.1, which is 0.7000000000000001 in f64: a reader wants the
/// instant they asked for), any other as the shortest text that reads back to it.
fn instant_text(t: f64, every: Option<f64>) -> String {
    let exact = format!("{t:?}");
    match every.and_then(|every| grid_name(t, every)) {
        // Where the shortest text already names the grid's instant, it stays as it was.
        Some(name) if name.parse::<f64>().map(f64::to_bits) != Ok(t.to_bits()) => name,
        _ => exact,
    }
}

/// `t` as k × `every` in decimal, when `t` is that product to the bit.
fn grid_name(t: f64, every: f64) -> Option<String> {
    #[expect(
        clippy::cast_possible_truncation,
        reason = "checked against the product below; a far value gives no name"
    )]
    let k = (t / every).round() as i64;
    if (k as f64 * every).to_bits() != t.to_bits() || k.unsigned_abs() > 1 << 53 {
        return None;
    }
    // `every`'s shortest decimal, as digits and a count of decimals.
    let shown = format!("{every}");
    let (whole, decimals) = shown.split_once('.').unwrap_or((&shown, ""));
    let digits: u128 = format!("{whole}{decimals}").parse().ok()?;
    let product = digits.checked_mul(u128::from(k.unsigned_abs()))?;
    let scale = decimals.len();
    let mut text = format!("{product:0>width$}", width = scale + 1);
    if scale > 0 {
        text.insert(text.len() - scale, '.');
        let kept = text.trim_end_matches('0').trim_end_matches('.').len();
        text.truncate(kept);
    }
    if k < 0 && product != 0 {
        text.insert(0, '-');
    }
    Some(if text.contains('.') {
        text
    } else {
        format!("{text}.0")
    })
}

#[cfg(test)]
mod tests {
    use super::sample_times as from;
    use super::{Plan, Trajectory};
    use crate::{Particle, Scene};

    /// Each limit refuses the run, and `no_limit` lifts it (the run is only built, not
    /// taken).
    #[test]
    fn the_limits_refuse_and_no_limit_lifts_them() {
        let one = Scene::new().with_particle(Particle::new("a", 1.0));
        let mut many = Scene::new();
        for i in 0..20 {
            many = many
                .with_particle(Particle::new(format!("p{i}"), 1.0).position([f64::from(i), 0.0]));
        }
        for (scene, until, every, words) in [
            (&one, 1e6, Some(1.0), "steps"),
            (&many, 6e4, Some(1.0), "particle-steps"),
            (&one, 1.0, Some(1e-8), "numbers"),
        ] {
            let plan = Plan {
                until,
                every,
                ..Plan::default()
            };
            let Err(refused) = Trajectory::new(scene, &plan) else {
                panic!("{words}: not refused");
            };
            assert!(
                refused.contains(words) && refused.contains("--no-limit"),
                "{refused}"
            );
            let lifted = Plan {
                no_limit: true,
                ..plan
            };
            assert!(Trajectory::new(scene, &lifted).is_ok(), "{words}: lifted");
        }
    }

    fn sample_times(until: f64, every: f64) -> Vec<f64> {
        from(0.0, until, every)
    }

    #[test]
    fn samples_are_multiples_of_the_interval_and_end_at_until() {
        // 3 × 0.1 = 0.30000000000000004 is the grid's 0.3: the run ends on it, not an
        // ulp before it, where a longer run's row 3 stands.
        assert_eq!(
            sample_times(0.3, 0.1),
            vec![0.0, 0.1, 0.2, 3.0 * 0.1],
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

    /// An end or a start typed as the grid names an instant is that instant: a run to 0.7
    /// by 0.1 ends at 7 × 0.1 = 0.7000000000000001, where a longer run's row stands; from
    /// a start of 0.7 typed (or 7 × 0.1 saved) the next row is 0.8, never a second 0.7.
    #[test]
    fn an_instant_typed_as_the_grid_names_it_is_the_grid_instant() {
        let seven = 7.0_f64 * 0.1;
        assert_eq!(
            seven.to_bits(),
            0.700_000_000_000_000_1_f64.to_bits(),
            "f64"
        );
        let to = sample_times(0.7, 0.1);
        assert_eq!(to.len(), 8, "{to:?}");
        assert_eq!(to[7].to_bits(), seven.to_bits(), "ends on the grid: {to:?}");
        for start in [0.7, seven] {
            let on = from(start, 1.0, 0.1);
            assert_eq!(on.len(), 4, "{start}: {on:?}");
            assert_eq!(on[0].to_bits(), start.to_bits(), "the start first");
            assert_eq!(on[1].to_bits(), (8.0_f64 * 0.1).to_bits(), "then 0.8");
        }
        // Off the grid by more than rounding: a row of its own.
        assert_eq!(
            from(0.0, 0.75, 0.1).last(),
            Some(&0.75),
            "0.75 ends the rows"
        );
    }

    /// A grid instant is written as the grid names it, any other as its shortest text;
    /// where that already names it, nothing changes.
    #[test]
    fn a_grid_instant_is_written_as_the_grid_names_it() {
        use super::instant_text;
        let every = Some(0.1);
        assert_eq!(
            instant_text(6.0_f64 * 0.1, every),
            "0.6",
            "0.6000000000000001"
        );
        assert_eq!(instant_text(7.0_f64 * 0.1, every), "0.7");
        assert_eq!(instant_text(0.7, every), "0.7", "itself");
        assert_eq!(instant_text(0.0, every), "0.0");
        assert_eq!(instant_text(20.0, every), "20.0");
        assert_eq!(instant_text(-3.0_f64 * 0.1, every), "-0.3");
        assert_eq!(
            instant_text(3.0_f64 * 0.1, None),
            "0.30000000000000004",
            "no grid"
        );
        assert_eq!(instant_text(0.123, every), "0.123", "off the grid");
        assert_eq!(instant_text(1e-7, Some(1e-7)), "1e-7", "as it was written");
        assert_eq!(
            instant_text(13.0_f64 * 1e-7, Some(1e-7)),
            "0.0000013",
            "1.2999999999999998e-6"
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
