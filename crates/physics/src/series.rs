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

use std::fmt;

use crate::cycle::NoCycle;
use crate::events::{Event, Located, Turn, Watch};
use crate::quantity::{Quantity, Reading};
use crate::scene::fields::{self, Field, Kind, Value};
use crate::scene::{Scene, Section, Vector, say};
use crate::simulation::{Simulation, SimulationError};

/// Which object a [`Setting`] writes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Target {
    Particle(usize),
    Spring(usize),
    Tie(usize),
    Ramp(usize),
    Body(usize),
    World,
    Simulation,
}

/// The part of a vector a [`Setting`] writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Part {
    X,
    Y,
    Magnitude,
    /// Degrees, counter-clockwise from +x, as the file's polar form.
    Angle,
}

impl Part {
    /// This part of `vector`.
    fn get(self, vector: Vector) -> f64 {
        let v = vector.to_dvec2();
        let (magnitude, angle) = polar(vector);
        match self {
            Self::X => v.x,
            Self::Y => v.y,
            Self::Magnitude => magnitude,
            Self::Angle => angle,
        }
    }

    fn parse(text: &str) -> Option<Self> {
        Some(match text {
            "x" => Self::X,
            "y" => Self::Y,
            "magnitude" => Self::Magnitude,
            "angle" => Self::Angle,
            _ => return None,
        })
    }

    /// `vector` with this part set to `value` (a magnitude or an angle keeps the other
    /// of the polar pair; x or y the other component).
    fn set(self, vector: Vector, value: f64) -> Vector {
        let v = vector.to_dvec2();
        let (magnitude, angle) = polar(vector);
        match self {
            Self::X => Vector::Cartesian(glam::DVec2::new(value, v.y)),
            Self::Y => Vector::Cartesian(glam::DVec2::new(v.x, value)),
            Self::Magnitude => Vector::Polar {
                magnitude: value,
                angle,
            },
            Self::Angle => Vector::Polar {
                magnitude,
                angle: value,
            },
        }
    }
}

/// `vector`'s magnitude and angle (degrees), as written where it is polar.
fn polar(vector: Vector) -> (f64, f64) {
    match vector {
        Vector::Polar { magnitude, angle } => (magnitude, angle),
        Vector::Cartesian(c) => (c.length(), c.y.atan2(c.x).to_degrees()),
    }
}

/// One number of a scene, by name: `OBJECT.key`, a vector's `OBJECT.key.x|.y|.magnitude|.angle`,
/// `world.key[.x|.y|…]`, `simulation.key`.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    text: String,
    target: Target,
    key: &'static str,
    part: Option<Part>,
    /// The SI unit of the number written.
    unit: &'static str,
}

impl fmt::Display for Setting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// The field of `fields` called `key` that holds a number (or a vector, with a part):
/// its key, whether it is a vector, and its unit.
fn numeric<T>(
    fields: &'static [Field<T>],
    key: &str,
) -> Option<(&'static str, bool, &'static str)> {
    let field = fields.iter().find(|f| f.key == key)?;
    match field.kind {
        Kind::Number(_) => Some((field.key, false, field.unit)),
        Kind::Vector => Some((field.key, true, field.unit)),
        _ => None,
    }
}

/// The number in `object`'s field `key` (its `part`, for a vector).
fn read<T>(fields: &[Field<T>], object: &T, key: &str, part: Option<Part>) -> Option<f64> {
    let field = fields.iter().find(|f| f.key == key)?;
    match ((field.get)(object), part) {
        (Value::Number(n), None) => Some(n),
        (Value::Vector(v), Some(part)) => Some(part.get(v)),
        _ => None,
    }
}

/// Writes `value` into `object`'s field `key` (its `part`, for a vector).
fn write<T>(fields: &[Field<T>], object: &mut T, key: &str, part: Option<Part>, value: f64) {
    let Some(field) = fields.iter().find(|f| f.key == key) else {
        return;
    };
    let new = match ((field.get)(object), part) {
        (Value::Number(_), None) => Value::Number(value),
        (Value::Vector(v), Some(part)) => Value::Vector(part.set(v, value)),
        _ => return,
    };
    (field.set)(object, new);
}

impl Setting {
    /// Reads `text` as a number of `scene`.
    ///
    /// # Errors
    /// No such object, key or part, or a key that holds no number (in words).
    pub fn parse(text: &str, scene: &Scene) -> Result<Self, String> {
        let text = text.trim();
        let unknown = |what: &str| say(what, &[("text", text)]);
        // The object: `world`, `simulation`, or the longest object name before a dot
        // (names may hold dots and spaces).
        let objects = scene
            .particles
            .iter()
            .enumerate()
            .map(|(i, p)| (p.name.as_str(), Target::Particle(i)))
            .chain(
                scene
                    .springs
                    .iter()
                    .enumerate()
                    .map(|(i, s)| (s.name.as_str(), Target::Spring(i))),
            )
            .chain(
                scene
                    .ties
                    .iter()
                    .enumerate()
                    .map(|(i, t)| (t.name.as_str(), Target::Tie(i))),
            )
            .chain(
                scene
                    .ramps
                    .iter()
                    .enumerate()
                    .map(|(i, r)| (r.name.as_str(), Target::Ramp(i))),
            )
            .chain(
                scene
                    .bodies
                    .iter()
                    .enumerate()
                    .map(|(i, b)| (b.name.as_str(), Target::Body(i))),
            )
            .chain([("world", Target::World), ("simulation", Target::Simulation)]);
        let (target, rest) = objects
            .filter_map(|(name, target)| {
                let rest = text.strip_prefix(name)?.strip_prefix('.')?;
                Some((name.len(), target, rest))
            })
            .max_by_key(|&(length, _, _)| length)
            .map(|(_, target, rest)| (target, rest))
            .ok_or_else(|| unknown("setting-object"))?;
        let (key, part) = match rest.split_once('.') {
            Some((key, part)) => (key, Some(part)),
            None => (rest, None),
        };
        let found = match target {
            Target::Particle(_) => numeric(fields::PARTICLE, key),
            Target::Spring(_) => numeric(fields::SPRING, key),
            Target::Tie(i) => numeric(fields::tie_fields(scene.ties[i].kind), key),
            Target::Ramp(_) => numeric(fields::RAMP, key),
            Target::Body(_) => numeric(fields::BODY, key),
            Target::World => numeric(fields::WORLD, key),
            Target::Simulation => numeric(fields::SIMULATION, key),
        };
        let (key, vector, unit) = found.ok_or_else(|| unknown("setting-key"))?;
        let part = match (vector, part) {
            (false, None) => None,
            (true, Some(part)) => Some(Part::parse(part).ok_or_else(|| unknown("setting-part"))?),
            (true, None) | (false, Some(_)) => return Err(unknown("setting-part")),
        };
        let unit = if part == Some(Part::Angle) {
            "°"
        } else {
            unit
        };
        Ok(Self {
            text: text.to_owned(),
            target,
            key,
            part,
            unit,
        })
    }

    /// The field it writes, as a problem with the scene names it.
    pub fn field(&self) -> crate::scene::FieldRef {
        let section = match self.target {
            Target::Particle(i) => Section::Particle(i),
            Target::Spring(i) => Section::Spring(i),
            Target::Tie(i) => Section::Tie(i),
            Target::Ramp(i) => Section::Ramp(i),
            Target::Body(i) => Section::Body(i),
            Target::World => Section::World,
            Target::Simulation => Section::Simulation,
        };
        crate::scene::FieldRef {
            section,
            field: self.key,
        }
    }

    /// The unit of the number written: the field's, degrees for a vector's angle.
    pub fn unit(&self) -> &'static str {
        self.unit
    }

    /// The number in `scene` (0 where the scene no longer has the object).
    pub fn value(&self, scene: &Scene) -> f64 {
        let (key, part) = (self.key, self.part);
        match self.target {
            Target::Particle(i) => scene
                .particles
                .get(i)
                .and_then(|p| read(fields::PARTICLE, p, key, part)),
            Target::Spring(i) => scene
                .springs
                .get(i)
                .and_then(|s| read(fields::SPRING, s, key, part)),
            Target::Tie(i) => scene
                .ties
                .get(i)
                .and_then(|t| read(fields::tie_fields(t.kind), t, key, part)),
            Target::Ramp(i) => scene
                .ramps
                .get(i)
                .and_then(|r| read(fields::RAMP, r, key, part)),
            Target::Body(i) => scene
                .bodies
                .get(i)
                .and_then(|b| read(fields::BODY, b, key, part)),
            Target::World => read(fields::WORLD, &scene.world, key, part),
            Target::Simulation => read(fields::SIMULATION, &scene.simulation, key, part),
        }
        .unwrap_or(0.0)
    }

    /// Writes `value` into `scene`.
    pub fn set(&self, scene: &mut Scene, value: f64) {
        let (key, part) = (self.key, self.part);
        match self.target {
            Target::Particle(i) => {
                write(fields::PARTICLE, &mut scene.particles[i], key, part, value);
            }
            Target::Spring(i) => write(fields::SPRING, &mut scene.springs[i], key, part, value),
            Target::Tie(i) => {
                let fields = fields::tie_fields(scene.ties[i].kind);
                write(fields, &mut scene.ties[i], key, part, value);
            }
            Target::Ramp(i) => write(fields::RAMP, &mut scene.ramps[i], key, part, value),
            Target::Body(i) => write(fields::BODY, &mut scene.bodies[i], key, part, value),
            Target::World => write(fields::WORLD, &mut scene.world, key, part, value),
            Target::Simulation => {
                write(fields::SIMULATION, &mut scene.simulation, key, part, value);
            }
        }
    }
}

/// A setting and the values it takes.
#[derive(Clone, Debug, PartialEq)]
pub struct Vary {
    /// What is varied.
    pub setting: Setting,
    /// Its values, in order.
    pub values: Vec<f64>,
}

impl Vary {
    /// Reads `FIELD=FROM:TO:STEP` against `scene`: FROM, FROM + STEP, … up to TO (TO
    /// itself when the steps reach it, to a billionth of a step).
    ///
    /// # Errors
    /// A malformed text, an unknown field, a step of 0 or one that leads away from TO.
    pub fn parse(text: &str, scene: &Scene) -> Result<Self, String> {
        let malformed = || say("vary-malformed", &[("text", text.trim())]);
        let (field, range) = text.rsplit_once('=').ok_or_else(malformed)?;
        let numbers: Vec<f64> = range
            .split(':')
            .map(|n| n.trim().parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect::<Option<_>>()
            .ok_or_else(malformed)?;
        let [from, to, step] = numbers[..] else {
            return Err(malformed());
        };
        let values = range_values(from, to, step)
            .ok_or_else(|| range_problem(text.trim(), from, to, step))?;
        Ok(Self {
            setting: Setting::parse(field, scene)?,
            values,
        })
    }
}

/// Why FROM:TO:STEP (written `text`) gives no values: more than a million, or none.
pub fn range_problem(text: &str, from: f64, to: f64, step: f64) -> String {
    let count = (to - from) / step;
    if count.is_finite() && count > 1e6 {
        say(
            "vary-too-many",
            &[("text", text), ("count", &format!("{count:.1e}"))],
        )
    } else {
        say("vary-empty", &[("text", text)])
    }
}

/// Whether runs to `until` of `steps` steps at most, `work` particle-steps in all, are
/// within a series' bounds.
///
/// # Errors
/// The bound exceeded, in words.
fn sweep_extent(until: f64, runs: f64, steps: f64, work: f64) -> Result<(), String> {
    if steps > crate::MAX_STEPS {
        return Err(say(
            "series-too-many-steps",
            &[
                ("until", &until.to_string()),
                ("steps", &format!("{steps:.1e}")),
                ("most", &format!("{:e}", crate::MAX_STEPS)),
            ],
        ));
    }
    if work > MAX_SWEEP_WORK {
        return Err(say(
            "series-too-much-work",
            &[
                ("runs", &runs.to_string()),
                ("work", &format!("{work:.1e}")),
                ("most", &format!("{MAX_SWEEP_WORK:e}")),
            ],
        ));
    }
    Ok(())
}

/// The most runs a series takes.
pub const MAX_RUNS: usize = 1_000_000;

/// The most particle-steps a series takes in all, its runs together: ten of `run`'s
/// largest ([`crate::MAX_WORK`]), minutes on every core.
pub const MAX_SWEEP_WORK: f64 = 1e10;

/// FROM, FROM + STEP, … up to TO; `None` for a step of 0, one leading away from TO, or
/// more than a million values.
pub fn range_values(from: f64, to: f64, step: f64) -> Option<Vec<f64>> {
    let steps = (to - from) / step;
    if step == 0.0 || !steps.is_finite() || !(-1e-9..=1e6).contains(&steps) {
        return None;
    }
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "checked to be in 0..=1e6"
    )]
    let count = (steps + 1e-9).floor().max(0.0) as u32;
    Some((0..=count).map(|k| from + f64::from(k) * step).collect())
}

/// One number read off a run.
#[derive(Clone, Debug, PartialEq)]
pub enum Measure {
    /// A quantity (`t` for the instant) at the `nth` occurrence (from 1) of an event.
    At {
        /// What is read.
        quantity: Quantity,
        /// When.
        event: Event,
        /// Which occurrence, from 1.
        nth: usize,
    },
    /// A quantity's largest value over the run.
    Max(Quantity),
    /// A quantity's smallest value over the run.
    Min(Quantity),
    /// The duration of a quantity's cycle: the mean span over the smallest number of
    /// successive maxima that repeats ([`crate::cycle`]).
    Period(Quantity),
    /// A quantity at an instant.
    AtTime(Quantity, f64),
}

impl Measure {
    /// Reads `QUANTITY at EVENT [#N]`, `t at EVENT`, `max QUANTITY`, `min QUANTITY`,
    /// `period QUANTITY` or `QUANTITY at T`.
    ///
    /// # Errors
    /// What the text should have been.
    pub fn parse(text: &str) -> Result<Self, String> {
        let text = text.trim();
        let malformed = || say("measure-malformed", &[("text", text)]);
        for (word, make) in [
            ("max ", Self::Max as fn(Quantity) -> Self),
            ("min ", Self::Min),
            ("period ", Self::Period),
        ] {
            if let Some(rest) = text.strip_prefix(word) {
                return Ok(make(Quantity::parse(rest.trim())?));
            }
        }
        let (quantity, when) = text.split_once(" at ").ok_or_else(malformed)?;
        let quantity = Quantity::parse(quantity.trim())?;
        let when = when.trim();
        if let Ok(t) = when.parse::<f64>() {
            if !t.is_finite() {
                return Err(malformed());
            }
            return Ok(Self::AtTime(quantity, t));
        }
        let (event, nth) = match when.rsplit_once('#') {
            Some((event, n)) => (
                event,
                n.trim()
                    .parse::<usize>()
                    .ok()
                    .filter(|&n| n > 0)
                    .ok_or_else(malformed)?,
            ),
            None => (when, 1),
        };
        Ok(Self::At {
            quantity,
            event: Event::parse(event)?,
            nth,
        })
    }

    /// The unit of its number: seconds for a period, else its quantity's.
    pub fn unit(&self) -> &'static str {
        match self {
            Self::Period(_) => "s",
            _ => self.quantity().unit(),
        }
    }

    /// The quantity it reads.
    fn quantity(&self) -> &Quantity {
        match self {
            Self::At { quantity, .. }
            | Self::Max(quantity)
            | Self::Min(quantity)
            | Self::Period(quantity)
            | Self::AtTime(quantity, _) => quantity,
        }
    }
}

/// Reads `measures` off a run of `scene` to `until`: each a number, or why there is none
/// (an event that did not happen often enough, a period of fewer than three maxima or of maxima
/// that do not repeat).
///
/// # Errors
/// The scene does not load, a measure names an object it does not have, an instant
/// outside the run, or the run failed (in words).
pub fn measure(
    scene: &Scene,
    until: f64,
    measures: &[Measure],
) -> Result<Vec<Result<f64, String>>, String> {
    measure_tracing(scene, until, measures, None).map(|(measured, _)| measured)
}

/// Each measure's number, or why there is none.
pub type Measured = Vec<Result<f64, String>>;

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
) -> Result<(Measured, Vec<Vec<glam::DVec2>>), String> {
    let mut simulation = Simulation::new(scene).map_err(|e| e.to_string())?;
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
        .map_err(|e| e.to_string())?;
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
    fn new(measures: &'a [Measure], simulation: &Simulation, until: f64) -> Result<Self, String> {
        let readings = measures
            .iter()
            .map(|m| m.quantity().reading(simulation))
            .collect::<Result<Vec<_>, _>>()?;
        for m in measures {
            if let Measure::AtTime(_, t) = m
                && !(simulation.time()..=until).contains(t)
            {
                return Err(say(
                    "measure-instant",
                    &[
                        ("instant", &t.to_string()),
                        ("from", &simulation.time().to_string()),
                        ("until", &until.to_string()),
                    ],
                ));
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

    fn finish(self, end: &Simulation) -> Vec<Result<f64, String>> {
        let until = end.time().to_string();
        self.measures
            .iter()
            .enumerate()
            .map(|(k, m)| match m {
                Measure::Period(_) => match crate::cycle(&self.maxima[k]) {
                    Ok(cycle) => Ok(cycle.period),
                    Err(NoCycle::TooFew(count)) => Err(say(
                        "measure-no-period",
                        &[("count", &count.to_string()), ("until", &until)],
                    )),
                    Err(NoCycle::Irregular(count)) => Err(say(
                        "measure-irregular-period",
                        &[("count", &count.to_string()), ("until", &until)],
                    )),
                },
                Measure::At { event, nth, .. } => {
                    let w = self.watched.iter().position(|&w| w == k).unwrap_or(0);
                    self.found[k].ok_or_else(|| {
                        say(
                            "measure-no-event",
                            &[
                                ("event", &event.to_string()),
                                ("count", &self.counts[w].to_string()),
                                ("nth", &nth.to_string()),
                                ("until", &until),
                            ],
                        )
                    })
                }
                _ => self.found[k].ok_or_else(|| say("measure-none", &[("until", &until)])),
            })
            .collect()
    }
}

/// A series: every combination of the settings' values (the first setting's outermost),
/// each run to `until` and measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    /// The settings varied, the first outermost.
    pub varies: Vec<Vary>,
    /// How long each run lasts, seconds (the instant it ends).
    pub until: f64,
    /// What each run is measured for.
    pub measures: Vec<Measure>,
    /// Whether each run keeps its particles' paths (the app draws them overlaid).
    pub trace: bool,
}

/// One run of a series: the settings' values, and what was measured (or why the run
/// failed).
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Each setting's value in this run.
    pub values: Vec<f64>,
    /// Each measure's number or why there is none; or why the run failed.
    pub measured: Result<Vec<Result<f64, String>>, String>,
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
        Measuring::new(&self.measures, &simulation, self.until)?;
        self.extent(scene)
    }

    /// Whether the series' work is within its bounds ([`Self::check`]), without loading
    /// the scene: what a scene file's `[[series]]` is checked for.
    ///
    /// # Errors
    /// The bound exceeded, in words.
    pub fn extent(&self, scene: &Scene) -> Result<(), String> {
        let runs: f64 = self.varies.iter().map(|v| v.values.len() as f64).product();
        if runs > MAX_RUNS as f64 {
            return Err(say(
                "series-too-many-runs",
                &[
                    ("runs", &format!("{runs:.1e}")),
                    ("most", &MAX_RUNS.to_string()),
                ],
            ));
        }
        // A run's work depends on the values only through the simulation's settings
        // (its time step, its start).
        let timed = self
            .varies
            .iter()
            .any(|v| v.setting.target == Target::Simulation);
        let sizes: Vec<(f64, f64)> = if timed {
            self.points()
                .iter()
                .map(|point| {
                    let mut varied = scene.clone();
                    for (vary, &value) in self.varies.iter().zip(point) {
                        vary.setting.set(&mut varied, value);
                    }
                    crate::trajectory::run_size(&varied, self.until)
                })
                .collect()
        } else {
            let (steps, work) = crate::trajectory::run_size(scene, self.until);
            vec![(steps, work * runs)]
        };
        let steps = sizes.iter().map(|s| s.0).fold(0.0, f64::max);
        let total: f64 = sizes.iter().map(|s| s.1).sum();
        sweep_extent(self.until, runs, steps, total)
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

    /// Every combination of the settings' values, in the series' order.
    pub fn points(&self) -> Vec<Vec<f64>> {
        self.varies.iter().fold(vec![Vec::new()], |points, vary| {
            points
                .iter()
                .flat_map(|point| {
                    vary.values.iter().map(move |&value| {
                        let mut next = point.clone();
                        next.push(value);
                        next
                    })
                })
                .collect()
        })
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

impl fmt::Display for Measure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::At {
                quantity,
                event,
                nth,
            } => {
                write!(f, "{quantity} at {event}")?;
                if *nth == 1 {
                    Ok(())
                } else {
                    write!(f, " #{nth}")
                }
            }
            Self::Max(q) => write!(f, "max {q}"),
            Self::Min(q) => write!(f, "min {q}"),
            Self::Period(q) => write!(f, "period {q}"),
            Self::AtTime(q, t) => write!(f, "{q} at {t:?}"),
        }
    }
}

impl Measure {
    /// Each quantity it names, mutably (its own, and its event's).
    pub fn quantities_mut(&mut self) -> Vec<&mut Quantity> {
        match self {
            Self::At {
                quantity, event, ..
            } => vec![quantity, &mut event.quantity],
            Self::Max(q) | Self::Min(q) | Self::Period(q) | Self::AtTime(q, _) => vec![q],
        }
    }

    /// Whether `scene` has every object the measure names (its quantity's, its event's).
    ///
    /// # Errors
    /// The first missing object, with the names there are.
    pub fn check_in(&self, scene: &Scene) -> Result<(), String> {
        self.quantity().check_in(scene)?;
        match self {
            Self::At { event, .. } => event.quantity.check_in(scene),
            _ => Ok(()),
        }
    }
}

/// The law a series is expected to follow: an expression of the varied value (`x`, also
/// `a`; an angle in radians, the file's degrees converted) and of the scene's constants:
/// `g`, the field's strength (m/s²); of the varied particle, `m` (kg), `r` (m), `v0`
/// (its speed at the start, m/s), `h` (its height at the start, m), `b` and `c` (its
/// air resistance) and `L` (the length of the first rod or string holding it); of a
/// varied rod or string `L` (m), of a varied spring `k` (N/m) and `L` (its natural
/// length). `v0^2*sin(2*a)/g` is the range of a projectile launched
/// from the ground at the angle varied. Arithmetic as the app's fields: + − × ÷ ^, sqrt,
/// sin, cos, tan, asin, acos, atan, exp, ln, log10, abs, `pi` (or `PI`), and `K`, the complete
/// elliptic integral of the first kind K(k) (a pendulum's period is
/// `4*sqrt(L/g)*K(sin(θ₀/2))`).
#[derive(Clone, Debug)]
pub struct Theory {
    expression: exmex::FlatEx<f64, TheoryOps>,
    /// The values of the expression's variables but the varied one, in its order; the
    /// varied one's place.
    constants: Vec<f64>,
    varied: Vec<usize>,
    /// Whether the varied value is an angle (degrees, turned into radians).
    angle: bool,
}

impl Theory {
    /// Reads `text` for the series varying `vary` on `scene`.
    ///
    /// # Errors
    /// The text is no expression, or names something that is not one of the variables
    /// above (in words, with the names there are).
    pub fn parse(text: &str, scene: &Scene, vary: &str) -> Result<Self, String> {
        use exmex::Express as _;
        let setting = Setting::parse(vary, scene)?;
        let expression = exmex::FlatEx::<f64, TheoryOps>::parse(text.trim())
            .map_err(|_| say("theory-unreadable", &[("text", text.trim())]))?;
        let named = setting.constants(scene);
        let mut constants = Vec::new();
        let mut varied = Vec::new();
        for (k, name) in expression.var_names().iter().enumerate() {
            if name == "x" || name == "a" {
                varied.push(k);
                constants.push(0.0);
                continue;
            }
            let value = named
                .iter()
                .find(|(n, _)| n == name)
                .map(|&(_, v)| v)
                .ok_or_else(|| {
                    let names: Vec<&str> = ["x", "a"]
                        .into_iter()
                        .chain(named.iter().map(|(n, _)| *n))
                        .collect();
                    say(
                        "theory-unknown-name",
                        &[("name", name), ("names", &names.join(", "))],
                    )
                })?;
            constants.push(value);
        }
        Ok(Self {
            expression,
            constants,
            varied,
            angle: setting.part == Some(Part::Angle),
        })
    }

    /// The law's value at the varied value `x` (in the file's unit).
    pub fn at(&self, x: f64) -> f64 {
        use exmex::Express as _;
        let x = if self.angle { x.to_radians() } else { x };
        let mut values = self.constants.clone();
        for &k in &self.varied {
            values[k] = x;
        }
        self.expression.eval(&values).unwrap_or(f64::NAN)
    }
}

/// exmex's operators on floats, and `K`.
#[derive(Clone, Debug)]
struct TheoryOps;

impl exmex::MakeOperators<f64> for TheoryOps {
    fn make<'a>() -> Vec<exmex::Operator<'a, f64>> {
        let mut operators = exmex::FloatOpsFactory::<f64>::make();
        operators.push(exmex::Operator::make_unary("K", elliptic_k));
        operators
    }
}

/// The complete elliptic integral of the first kind K(k), |k| < 1, by the
/// arithmetic–geometric mean (quadratic convergence: 30 rounds are past f64's digits).
pub fn elliptic_k(k: f64) -> f64 {
    if k.abs() >= 1.0 || k.is_nan() {
        return f64::NAN;
    }
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..30 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

impl Setting {
    /// The scene's constants a theory may name, for this setting's object.
    fn constants(&self, scene: &Scene) -> Vec<(&'static str, f64)> {
        // `pi` as the app's fields read it (exmex's own is `PI`).
        let mut named = vec![
            ("g", scene.world.gravity.to_dvec2().length()),
            ("pi", std::f64::consts::PI),
        ];
        match self.target {
            Target::Particle(i) => {
                let p = &scene.particles[i];
                named.extend([
                    ("m", p.mass),
                    ("r", p.radius),
                    ("v0", p.velocity.to_dvec2().length()),
                    ("h", p.position.to_dvec2().y),
                    ("b", p.linear_drag),
                    ("c", p.quadratic_drag),
                ]);
                // The length of the first rod or string that holds it.
                let holds = |end: &crate::scene::Endpoint| matches!(end, crate::scene::Endpoint::Particle(n) if *n == p.name);
                if let Some(tie) = scene.ties.iter().find(|t| holds(&t.from) || holds(&t.to)) {
                    named.push(("L", tie.length));
                }
            }
            Target::Tie(i) => named.push(("L", scene.ties[i].length)),
            Target::Spring(i) => {
                let s = &scene.springs[i];
                named.extend([("k", s.stiffness), ("L", s.natural_length)]);
            }
            Target::Body(i) => {
                let b = &scene.bodies[i];
                named.extend([
                    ("m", b.total_mass()),
                    ("I", b.inertia()),
                    ("v0", b.velocity.to_dvec2().length()),
                    ("h", b.position.to_dvec2().y),
                    ("w", b.width),
                ]);
            }
            Target::Ramp(_) | Target::World | Target::Simulation => {}
        }
        named
    }
}
