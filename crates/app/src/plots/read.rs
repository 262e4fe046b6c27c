//! What a graph reads off every sample of its series, kept until the run or the graph's
//! choices change: maxima, minima and zero crossings (located in the run where the budget
//! allows), periods, and fits.

use physics::Quantity;

use super::MARKS;
use crate::analysis;
use crate::format;
use crate::i18n::{Arg, tr_with};
use crate::recording::Recording;
use crate::timeline::Timeline;

/// Each series of `series` against `x`, every `every`th sample and the last.
pub(super) fn series_points(
    recording: &Recording,
    x: &Quantity,
    series: &[Quantity],
    every: usize,
) -> Vec<(Quantity, Vec<[f64; 2]>)> {
    let samples = recording.len();
    series
        .iter()
        .filter_map(|q| {
            let (across, up) = (recording.column(x)?, recording.column(q)?);
            let last = (samples > 0 && !(samples - 1).is_multiple_of(every)).then(|| samples - 1);
            let points = (0..samples)
                .step_by(every)
                .chain(last)
                .map(|k| [recording.at(k, across), recording.at(k, up)])
                .collect();
            Some((q.clone(), points))
        })
        .collect()
}

/// What a graph's reading was made of: the run's samples so far and the graph's choices.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ReadKey {
    pub samples: usize,
    pub x: Quantity,
    pub series: Vec<Quantity>,
    pub marks: bool,
    pub fit: Option<analysis::Model>,
    /// Whether the marks are to be located in the run, not read off the samples.
    pub located: bool,
}

/// What a graph read off every sample of its series: extremes and zeros, and fits.
#[derive(Default)]
pub(super) struct Read {
    key: Option<ReadKey>,
    pub analyses: Vec<Analysis>,
    /// Each series' fit: its name, the fit, and the span of x it was fitted over.
    pub fits: Vec<(String, analysis::Fit, (f64, f64))>,
}

impl Read {
    /// Reads `recording` as `key` asks, locating the marks in `timeline` if it says so.
    pub fn of(recording: &Recording, key: ReadKey, timeline: Option<&Timeline>) -> Self {
        let columns = series_points(recording, &key.x, &key.series, 1);
        let mut budget = LOCATING_BUDGET;
        let analyses = columns
            .iter()
            .filter(|_| key.marks)
            .map(|(q, points)| {
                let mut analysis = Analysis::of(q, points);
                if let Some(timeline) = timeline.filter(|_| key.located) {
                    analysis.locate(q, points, timeline, &mut budget);
                }
                analysis
            })
            .collect();
        let fits = key
            .fit
            .map(|model| {
                columns
                    .iter()
                    .filter_map(|(q, points)| {
                        let (x, y): (Vec<f64>, Vec<f64>) =
                            points.iter().map(|p| (p[0], p[1])).unzip();
                        let span = x
                            .iter()
                            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                                (a.min(v), b.max(v))
                            });
                        analysis::fit(model, &x, &y).map(|fit| (q.to_string(), fit, span))
                    })
                    .collect()
            })
            .unwrap_or_default();
        Self {
            key: Some(key),
            analyses,
            fits,
        }
    }

    /// Whether it must be read again for `key`: the graph's choices changed, or the run
    /// grew — while it plays, only once it has grown by a twentieth, so that a fit over
    /// a long run is not made again at every frame.
    pub fn is_stale(&self, key: &ReadKey, playing: bool) -> bool {
        let Some(old) = &self.key else {
            return true;
        };
        let same_choices = ReadKey {
            samples: key.samples,
            ..old.clone()
        } == *key;
        if !same_choices {
            return true;
        }
        if playing {
            key.samples * 20 >= old.samples * 21
        } else {
            key.samples != old.samples
        }
    }
}

/// The particle-steps a graph may spend locating its marks in the run, at most (a
/// fraction of a second once a run stops): a
/// pendulum's marks are all located, a large scene's are read off the samples past it.
const LOCATING_BUDGET: f64 = 2e6;

/// A series' maxima, minima and zero crossings against time: read off its samples
/// ([`analysis`]), then located in the run where the budget allows ([`Self::locate`]).
pub(super) struct Analysis {
    pub name: String,
    pub extremes: Vec<analysis::Extreme>,
    zeros: Vec<f64>,
    /// Whether every mark was located in the run (else some are read off the samples).
    located: bool,
}

impl Analysis {
    fn of(quantity: &Quantity, points: &[[f64; 2]]) -> Self {
        let (x, y): (Vec<f64>, Vec<f64>) = points.iter().map(|p| (p[0], p[1])).unzip();
        Self {
            name: quantity.to_string(),
            extremes: analysis::extrema(&x, &y),
            zeros: analysis::zeros(&x, &y),
            located: false,
        }
    }

    /// Locates each mark in the run, as the stopwatch's events are
    /// ([`Timeline::extreme_between`], [`Timeline::crossing_between`]): between the
    /// samples around the sampled estimate, by stepping to the instant. Marks past what
    /// `budget` (particle-steps) pays for keep their sampled estimate.
    fn locate(
        &mut self,
        quantity: &Quantity,
        points: &[[f64; 2]],
        timeline: &Timeline,
        budget: &mut f64,
    ) {
        let Some(reading) = timeline.reading(quantity) else {
            return;
        };
        let times: Vec<f64> = points.iter().map(|p| p[0]).collect();
        if times.is_empty() {
            return;
        }
        // The samples on either side of an estimate (the nearest one's neighbours).
        let around = |t: f64| {
            let k = times.partition_point(|&s| s < t).min(times.len() - 1);
            let nearest = if k > 0 && t - times[k - 1] < times[k] - t {
                k - 1
            } else {
                k
            };
            (
                times[nearest.saturating_sub(1)],
                times[(nearest + 1).min(times.len() - 1)],
            )
        };
        let mut all = true;
        for extreme in self.extremes.iter_mut().take(MARKS) {
            let span = around(extreme.x);
            if !timeline.pay_for(span, budget) {
                all = false;
                break;
            }
            let turn = if extreme.maximum {
                physics::Turn::Maximum
            } else {
                physics::Turn::Minimum
            };
            match timeline.extreme_between(reading, span, turn) {
                Some(at) => {
                    extreme.x = at.time();
                    extreme.value = at.read(reading);
                }
                None => all = false,
            }
        }
        for zero in self.zeros.iter_mut().take(MARKS) {
            // Between the sample before the estimate and the one after the next.
            let k = times.partition_point(|&s| s < *zero);
            if k == 0 {
                continue; // on the first sample, exactly
            }
            let span = (times[k - 1], times[(k + 1).min(times.len() - 1)]);
            if !timeline.pay_for(span, budget) {
                all = false;
                break;
            }
            match timeline.crossing_between(reading, 0.0, span) {
                Some(t) => *zero = t,
                None => all = false,
            }
        }
        self.located = all && self.extremes.len() <= MARKS && self.zeros.len() <= MARKS;
    }

    /// The marks: up triangles at maxima, down at minima, rings at zero crossings.
    pub fn draw(&self, plot: &mut egui_plot::PlotUi<'_>) {
        let at = |maximum: bool| -> Vec<[f64; 2]> {
            self.extremes
                .iter()
                .filter(|e| e.maximum == maximum)
                .take(MARKS)
                .map(|e| [e.x, e.value])
                .collect()
        };
        for (points, shape) in [
            (at(true), egui_plot::MarkerShape::Up),
            (at(false), egui_plot::MarkerShape::Down),
            (
                self.zeros.iter().take(MARKS).map(|&t| [t, 0.0]).collect(),
                egui_plot::MarkerShape::Circle,
            ),
        ] {
            plot.points(
                egui_plot::Points::new(format!("{} marks", self.name), points)
                    .shape(shape)
                    .radius(4.0)
                    .color(egui::Color32::from_rgb(200, 120, 20)),
            );
        }
    }

    /// Whether its maxima give a period (a lesson may ask for it: `period NAME`).
    pub fn has_period(&self) -> bool {
        matches!(analysis::period(&self.extremes), Some(Ok(_)))
    }

    /// "period of bob.x: 3.0446 s (mean of 2 cycles, located in the run)", or why the
    /// maxima give none.
    pub fn period_words(&self) -> Option<String> {
        let quantity = ("quantity", Arg::Text(&self.name));
        let cycle = match analysis::period(&self.extremes)? {
            Ok(cycle) => cycle,
            Err(physics::NoCycle::TooFew(count)) => {
                return Some(tr_with(
                    "graph-period-too-few",
                    &[quantity, ("count", Arg::Number(count as f64))],
                ));
            }
            Err(physics::NoCycle::Irregular(count)) => {
                return Some(tr_with(
                    "graph-period-irregular",
                    &[quantity, ("count", Arg::Number(count as f64))],
                ));
            }
        };
        Some(tr_with(
            "graph-period",
            &[
                quantity,
                ("period", Arg::Text(&format::fixed(cycle.period, 6))),
                ("cycles", Arg::Number(cycle.cycles as f64)),
                ("maxima", Arg::Number(cycle.maxima_per_cycle as f64)),
                (
                    "how",
                    Arg::Text(if self.located { "located" } else { "sampled" }),
                ),
            ],
        ))
    }
}
