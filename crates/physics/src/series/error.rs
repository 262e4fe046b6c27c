//! Why a measure has no number, or a run of a series none at all: typed, so that callers
//! can tell the cases apart, and said in the library's language only when shown.

use std::fmt;

use crate::scene::error::LoadError;
use crate::scene::say;
use crate::simulation::SimulationError;

/// Why a measure (or a whole run of measures) has no number.
#[derive(Clone, Debug, PartialEq)]
pub enum MeasureError {
    /// The scene does not make a simulation: its problems.
    Scene(LoadError),
    /// A measure that does not parse, or names what the scene does not have: the words
    /// of the measure's own parser.
    Measure(String),
    /// A value asked for at an instant outside the run.
    Instant {
        /// The instant asked for, seconds.
        instant: f64,
        /// The run's start, seconds.
        from: f64,
        /// The run's end, seconds.
        until: f64,
    },
    /// The run failed before its end.
    Run(SimulationError),
    /// A period of a quantity with fewer maxima than a cycle needs before `until`.
    NoPeriod {
        /// The maxima found.
        count: usize,
        /// The run's end, seconds.
        until: f64,
    },
    /// A period of a quantity whose maxima do not repeat ([`crate::cycle`]).
    IrregularPeriod {
        /// The maxima found.
        count: usize,
        /// The run's end, seconds.
        until: f64,
    },
    /// An event that did not happen the `nth` time before `until`.
    NoEvent {
        /// The event, as typed.
        event: String,
        /// How often it happened.
        count: usize,
        /// The occurrence asked for.
        nth: usize,
        /// The run's end, seconds.
        until: f64,
    },
    /// An extreme with no sample inside the run.
    Nothing {
        /// The run's end, seconds.
        until: f64,
    },
}

impl fmt::Display for MeasureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let words = match self {
            Self::Scene(load) => load.to_string(),
            Self::Run(failure) => failure.to_string(),
            Self::Measure(words) => words.clone(),
            Self::Instant {
                instant,
                from,
                until,
            } => say(
                "measure-instant",
                &[
                    ("instant", &instant.to_string()),
                    ("from", &from.to_string()),
                    ("until", &until.to_string()),
                ],
            ),
            Self::NoPeriod { count, until } => say(
                "measure-no-period",
                &[("count", &count.to_string()), ("until", &until.to_string())],
            ),
            Self::IrregularPeriod { count, until } => say(
                "measure-irregular-period",
                &[("count", &count.to_string()), ("until", &until.to_string())],
            ),
            Self::NoEvent {
                event,
                count,
                nth,
                until,
            } => say(
                "measure-no-event",
                &[
                    ("event", event),
                    ("count", &count.to_string()),
                    ("nth", &nth.to_string()),
                    ("until", &until.to_string()),
                ],
            ),
            Self::Nothing { until } => say("measure-none", &[("until", &until.to_string())]),
        };
        f.write_str(&words)
    }
}

impl std::error::Error for MeasureError {}

impl From<String> for MeasureError {
    fn from(words: String) -> Self {
        Self::Measure(words)
    }
}
