//! A series as a scene file, a command line or Python writes it: what is varied over
//! which values ([`Vary`], [`Setting`]), what each run is measured for ([`Measure`]), the
//! law expected ([`Theory`]) and how large its runs may be. Running one is
//! [`crate::series`]' work; a scene checks its own series and lesson questions with this
//! vocabulary.

use std::fmt;

use super::{Scene, say};
use crate::quantity::{Event, Quantity};

mod setting;
mod theory;

pub use setting::Setting;
pub use theory::{Theory, elliptic_k};

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

/// The most time steps one run may take without [`crate::Plan::no_limit`]: 10⁸ steps of the
/// lightest scene take a minute or two here; more is a time step or an end mistyped, and
/// would look like a hang.
pub const MAX_STEPS: f64 = 1e8;
/// The most particle-steps (particles × steps) one run may take without
/// [`crate::Plan::no_limit`]: 10⁹, a few minutes of the 1,000-ball pit (99 charged particles at
/// a time step of 1e-9 s for half a second would be 5·10¹⁰, hours).
pub const MAX_WORK: f64 = 1e9;

/// A run of `scene` to `until`: its steps, and its particle-steps (the steps times the
/// moving particles, at least one).
pub fn run_size(scene: &Scene, until: f64) -> (f64, f64) {
    let settings = &scene.simulation;
    let steps = (until - settings.start_time) / settings.time_step;
    let particles = scene.particles.iter().filter(|p| !p.fixed).count().max(1);
    (steps, steps * particles as f64)
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
    pub(crate) fn quantity(&self) -> &Quantity {
        match self {
            Self::At { quantity, .. }
            | Self::Max(quantity)
            | Self::Min(quantity)
            | Self::Period(quantity)
            | Self::AtTime(quantity, _) => quantity,
        }
    }
}

/// Whether runs to `until` of `steps` steps at most, `work` particle-steps in all, are
/// within a series' bounds.
///
/// # Errors
/// The bound exceeded, in words.
fn sweep_extent(until: f64, runs: f64, steps: f64, work: f64) -> Result<(), String> {
    if steps > MAX_STEPS {
        return Err(say(
            "series-too-many-steps",
            &[
                ("until", &until.to_string()),
                ("steps", &format!("{steps:.1e}")),
                ("most", &format!("{MAX_STEPS:e}")),
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

impl Sweep {
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
        let timed = self.varies.iter().any(|v| v.setting.is_simulation());
        let sizes: Vec<(f64, f64)> = if timed {
            self.points()
                .iter()
                .map(|point| {
                    let mut varied = scene.clone();
                    for (vary, &value) in self.varies.iter().zip(point) {
                        vary.setting.set(&mut varied, value);
                    }
                    run_size(&varied, self.until)
                })
                .collect()
        } else {
            let (steps, work) = run_size(scene, self.until);
            vec![(steps, work * runs)]
        };
        let steps = sizes.iter().map(|s| s.0).fold(0.0, f64::max);
        let total: f64 = sizes.iter().map(|s| s.1).sum();
        sweep_extent(self.until, runs, steps, total)
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
