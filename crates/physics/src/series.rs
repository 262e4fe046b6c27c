//! Experiment series: vary a scene's value over a range, run the scene for each value,
//! and measure each run (`newtonlab sweep`, the app's series panel, Python's `sweep`).
//!
//! A [`Setting`] names one number of the scene (`Ball.velocity.angle`, `Bob.mass`,
//! `world.gravity.y`, `simulation.time_step`) and writes it through the scene's field
//! table, so it obeys the same rules as the file. A [`Measure`] reads one number off a
//! run, located as exactly as events are: a quantity at the Nth occurrence of an event,
//! its maximum or minimum (between the steps around the largest sample, as
//! [`Simulation::extreme_until`] finds it), its period (its true cycle from its
//! located maxima, [`crate::cycle`], or why it has none), or its value at an instant. A run is never changed by
//! being measured: it takes the steps it takes without measures, bit for bit, and an
//! instant between two steps is read off a copy stepped on to it.
//!
//! The runs of a series are independent: they run on every core (native builds), each on
//! one thread, and come back in the series' order, so the results are the same bits for
//! any number of threads.

mod error;

pub use error::MeasureError;

use crate::cycle::NoCycle;
use crate::events::{Located, Watch};
use crate::quantity::{Event, Reading, Turn};
use crate::scene::{Lesson, Question, Scene};
use crate::simulation::{Simulation, SimulationError};

pub use crate::scene::series::{
    MAX_RUNS, MAX_SWEEP_WORK, Measure, Setting, Sweep, Theory, Vary, elliptic_k, range_problem,
    range_values,
};

/// Reads `measures` off a run of `scene` to `until`: each a number, or why there is none
/// (an event that did not happen often enough, a period of fewer than three maxima or of maxima
/// that do not repeat).
///
/// # Errors
/// The scene does not load, a measure names an object it does not have, an instant
/// outside the run, or the run failed (in words).
pub fn measure(scene: &Scene, until: f64, measures: &[Measure]) -> Result<Measured, MeasureError> {
    measure_tracing(scene, until, measures, None).map(|(measured, _)| measured)
}

/// Each measure's number, or why there is none.
pub type Measured = Vec<Result<f64, MeasureError>>;

/// Samples of a path a traced run keeps at most.
const MOST_PATH_SAMPLES: usize = 1000;

/// [`measure`], and with `trace` also each particle's path: its positions at the start
/// and after each step at least `until / 1000` s after the last kept (at most a thousand
/// a particle), as polylines in the scene's order of particles.
///
/// # Errors
/// As [`measure`].
pub fn measure_tracing(
    scene: &Scene,
    until: f64,
    measures: &[Measure],
    trace: Option<()>,
) -> Result<(Measured, Vec<Vec<glam::DVec2>>), MeasureError> {
    let mut simulation = Simulation::new(scene).map_err(MeasureError::Scene)?;
    let mut runs = Measuring::new(measures, &simulation, until)?;
    let start = simulation.keyframe();
    runs.begin(&start);
    let spacing = (until - start.time()) / MOST_PATH_SAMPLES as f64;
    let mut paths: Vec<Vec<glam::DVec2>> = trace
        .map(|()| start.positions().iter().map(|&p| vec![p]).collect())
        .unwrap_or_default();
    let mut kept = start.time();
    simulation
        .step_to_observed(
            until,
            Some(&mut |before: &Simulation, after: &Simulation| {
                if trace.is_some() && after.time() - kept >= spacing {
                    kept = after.time();
                    for (path, &p) in paths.iter_mut().zip(after.positions()) {
                        path.push(p);
                    }
                }
                runs.after_step(before, after)
            }),
        )
        .map_err(MeasureError::Run)?;
    Ok((runs.finish(&simulation), paths))
}

/// The state of each measure through a run.
struct Measuring<'a> {
    measures: &'a [Measure],
    /// Each measure's quantity found in the simulation.
    readings: Vec<Reading>,
    /// The events of the `At` measures, with the measure each serves.
    watch: Watch,
    watched: Vec<usize>,
    /// How often each watched event has happened.
    counts: Vec<usize>,
    /// What each measure has found so far.
    found: Vec<Option<f64>>,
    /// For the extremes and periods: the value at the last two step ends (NaN for the
    /// other measures, which need none).
    history: Vec<[f64; 2]>,
    /// The state at the start of the previous step (an extreme's bracket starts there).
    previous: Option<Simulation>,
    /// The located maxima, instant and value, for the periods.
    maxima: Vec<Vec<(f64, f64)>>,
    /// Whether an extreme or a period is measured (only then is `previous` kept).
    keeps_previous: bool,
}

impl<'a> Measuring<'a> {
    fn new(
        measures: &'a [Measure],
        simulation: &Simulation,
        until: f64,
    ) -> Result<Self, MeasureError> {
        let readings = measures
            .iter()
            .map(|m| m.quantity().reading(simulation))
            .collect::<Result<Vec<_>, _>>()?;
        for m in measures {
            if let Measure::AtTime(_, t) = m
                && !(simulation.time()..=until).contains(t)
            {
                return Err(MeasureError::Instant {
                    instant: *t,
                    from: simulation.time(),
                    until,
                });
            }
        }
        let (events, watched): (Vec<Event>, Vec<usize>) = measures
            .iter()
            .enumerate()
            .filter_map(|(k, m)| match m {
                Measure::At { event, .. } => Some((event.clone(), k)),
                _ => None,
            })
            .unzip();
        let watch = Watch::new(&events, simulation)?;
        Ok(Self {
            measures,
            readings,
            counts: vec![0; watched.len()],
            watch,
            watched,
            found: vec![None; measures.len()],
            history: vec![[f64::NAN; 2]; measures.len()],
            previous: None,
            maxima: vec![Vec::new(); measures.len()],
            keeps_previous: measures
                .iter()
                .any(|m| matches!(m, Measure::Max(_) | Measure::Min(_) | Measure::Period(_))),
        })
    }

    /// Reads what the start state gives: an instant at the start, the first sample of
    /// the extremes.
    fn begin(&mut self, start: &Simulation) {
        for (k, m) in self.measures.iter().enumerate() {
            let value = start.read(self.readings[k]);
            match m {
                Measure::AtTime(_, t) if *t <= start.time() => self.found[k] = Some(value),
                Measure::Max(_) | Measure::Min(_) => self.found[k] = Some(value),
                _ => {}
            }
            self.history[k] = [f64::NAN, value];
        }
    }

    fn after_step(
        &mut self,
        before: &Simulation,
        after: &Simulation,
    ) -> Result<(), SimulationError> {
        let mut events: Vec<Located> = Vec::new();
        self.watch.after_step(before, after, &mut events)?;
        for event in events {
            let k = self.watched[event.event];
            self.counts[event.event] += 1;
            if let Measure::At { nth, .. } = self.measures[k]
                && self.counts[event.event] == nth
            {
                self.found[k] = Some(event.at.read(self.readings[k]));
            }
        }
        for (k, m) in self.measures.iter().enumerate() {
            let reading = self.readings[k];
            match m {
                Measure::AtTime(_, t) if before.time() < *t && *t <= after.time() => {
                    let mut copy = before.keyframe();
                    copy.step_to(*t)?;
                    self.found[k] = Some(copy.read(reading));
                }
                Measure::Max(_) | Measure::Min(_) | Measure::Period(_) => {
                    // Only these read their quantity at every step's end.
                    let now = after.read(reading);
                    let [earlier, last] = self.history[k];
                    self.history[k] = [last, now];
                    let (turn, sign) = if matches!(m, Measure::Min(_)) {
                        (Turn::Minimum, -1.0)
                    } else {
                        (Turn::Maximum, 1.0)
                    };
                    let beats = |value: f64, best: Option<f64>| {
                        best.is_none_or(|best| sign * value > sign * best)
                    };
                    // The sample at `before` is a turning point: the extreme lies between
                    // the step ends around it, where it is located.
                    let turning = sign * last > sign * earlier && sign * last >= sign * now;
                    let period = matches!(m, Measure::Period(_));
                    // (The sample itself is the best so far: it was the step's end.)
                    let best = self.found[k].is_none_or(|best| sign * last >= sign * best);
                    if turning
                        && (period || best)
                        && let Some(previous) = &self.previous
                    {
                        let at = previous.extreme_until(reading, after.time(), turn)?;
                        let value = at.read(reading);
                        if period {
                            self.maxima[k].push((at.time(), value));
                        } else if beats(value, self.found[k]) {
                            self.found[k] = Some(value);
                        }
                    }
                    // A run that ends still rising has its extreme at its end.
                    if !period && beats(now, self.found[k]) {
                        self.found[k] = Some(now);
                    }
                }
                _ => {}
            }
        }
        if self.keeps_previous {
            self.previous = Some(before.keyframe());
        }
        Ok(())
    }

    fn finish(self, end: &Simulation) -> Measured {
        let until = end.time();
        self.measures
            .iter()
            .enumerate()
            .map(|(k, m)| match m {
                Measure::Period(_) => match crate::cycle(&self.maxima[k]) {
                    Ok(cycle) => Ok(cycle.period),
                    Err(NoCycle::TooFew(count)) => Err(MeasureError::NoPeriod { count, until }),
                    Err(NoCycle::Irregular(count)) => {
                        Err(MeasureError::IrregularPeriod { count, until })
                    }
                },
                Measure::At { event, nth, .. } => {
                    let w = self.watched.iter().position(|&w| w == k).unwrap_or(0);
                    self.found[k].ok_or_else(|| MeasureError::NoEvent {
                        event: event.to_string(),
                        count: self.counts[w],
                        nth: *nth,
                        until,
                    })
                }
                _ => self.found[k].ok_or(MeasureError::Nothing { until }),
            })
            .collect()
    }
}

/// One run of a series: the settings' values, and what was measured (or why the run
/// failed).
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Each setting's value in this run.
    pub values: Vec<f64>,
    /// Each measure's number or why there is none; or why the run failed.
    pub measured: Result<Measured, MeasureError>,
    /// Each particle's path, when the series traces them ([`Sweep::trace`]; else empty).
    pub paths: Vec<Vec<glam::DVec2>>,
}

impl Row {
    /// Which run this is, in words: `Ball.mass = 2, Ball.velocity.angle = 30`, each of
    /// `fields` (the settings as typed) with its value.
    pub fn label(&self, fields: &[impl AsRef<str>]) -> String {
        let parts: Vec<String> = fields
            .iter()
            .zip(&self.values)
            .map(|(field, value)| format!("{} = {value}", field.as_ref()))
            .collect();
        parts.join(", ")
    }
}

impl Sweep {
    /// Whether the series can run on `scene`: the scene loads, every measure's objects
    /// are in it, every instant is within the run, and the work is bounded as `run`'s
    /// is: at most [`MAX_RUNS`] runs, each within `run`'s steps and particle-steps
    /// ([`crate::MAX_STEPS`], [`crate::MAX_WORK`]), and [`MAX_SWEEP_WORK`] particle-steps in all —
    /// a mistyped range or time step is likelier than intent, and would look like a hang.
    ///
    /// # Errors
    /// The first problem, in words.
    pub fn check(&self, scene: &Scene) -> Result<(), String> {
        let simulation = Simulation::new(scene).map_err(|e| e.to_string())?;
        Measuring::new(&self.measures, &simulation, self.until).map_err(|e| e.to_string())?;
        self.extent(scene)
    }

    /// One run: `scene` with the settings at `values` (one per setting), measured.
    pub fn run_one(&self, scene: &Scene, values: &[f64]) -> Row {
        let mut varied = scene.clone();
        for (vary, &value) in self.varies.iter().zip(values) {
            vary.setting.set(&mut varied, value);
        }
        let trace = self.trace.then_some(());
        let (measured, paths) = match measure_tracing(&varied, self.until, &self.measures, trace) {
            Ok((measured, paths)) => (Ok(measured), paths),
            Err(why) => (Err(why), Vec::new()),
        };
        Row {
            values: values.to_vec(),
            measured,
            paths,
        }
    }

    /// Runs and measures every combination on `scene`, on up to `threads` threads (where
    /// there are threads), calling `progress` after each run. The rows come back in the
    /// series' order, the same bits for any number of threads.
    pub fn run(&self, scene: &Scene, threads: usize, progress: &(dyn Fn() + Sync)) -> Vec<Row> {
        let one = |values: &Vec<f64>| {
            let row = self.run_one(scene, values);
            progress();
            row
        };
        let points = self.points();
        #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
        if threads > 1
            && let Ok(pool) = rayon::ThreadPoolBuilder::new().num_threads(threads).build()
        {
            use rayon::prelude::*;
            return pool.install(|| points.par_iter().map(one).collect());
        }
        let _ = threads;
        points.iter().map(one).collect()
    }
}

/// The rows as CSV, as `newtonlab sweep` writes them: a header of `names` (the varied
/// settings, then the measures, as typed), then a row per run: its values, then each
/// measure's number, empty where there is none.
pub fn csv(names: &[&str], rows: &[Row]) -> String {
    let header: Vec<String> = names.iter().map(|n| crate::csv_field(n)).collect();
    let mut out = header.join(",");
    out.push('\n');
    for row in rows {
        let mut fields: Vec<String> = row.values.iter().map(f64::to_string).collect();
        let measures = names.len().saturating_sub(row.values.len());
        match &row.measured {
            Ok(measured) => fields.extend(
                measured
                    .iter()
                    .map(|m| m.as_ref().map(f64::to_string).unwrap_or_default()),
            ),
            Err(_) => fields.extend(std::iter::repeat_n(String::new(), measures)),
        }
        out.push_str(&fields.join(","));
        out.push('\n');
    }
    out
}

impl Lesson {
    /// What `scene` (as the student set it up) measures for each question, in the
    /// question's unit: one run to [`Self::until`], every measure read off it.
    ///
    /// # Errors
    /// A measure that does not read, or a scene that does not run (in words); a measure
    /// the run does not reach (an event that never happens) is that question's error.
    pub fn answers(&self, scene: &Scene) -> Result<Measured, MeasureError> {
        let measures = self
            .questions
            .iter()
            .map(Question::parsed)
            .collect::<Result<Vec<_>, _>>()?;
        let until = self.until(scene);
        let measured = measure(scene, until, &measures)?;
        Ok(measured
            .into_iter()
            .zip(&self.questions)
            .map(|(value, question)| value.map(|si| question.in_unit(si)))
            .collect())
    }
}
