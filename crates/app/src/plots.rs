//! Readouts and graphs. Energies by kind, what damping, friction and impacts took since
//! Play (rods and strings take nothing: a constraint does no work), the numerical error
//! (what the books leave unaccounted) as a percentage and the total momentum; then the
//! scene's graphs (`[[graph]]`): any quantities against time or against one another (a
//! phase plot such as x against vx), several series each.
//!
//! A graph is only a choice of quantities: the values come from the run's
//! [`Recording`], which holds every quantity of every particle from Play on. So switching
//! the x axis, adding a series late or exporting never loses data, and Reset keeps the
//! last run's graphs until the next Play. The graphs are part of the scene: editing them
//! is an undoable change, saved with the file.

use std::fmt::Write as _;

use egui::Ui;
use egui_plot::{AxisHints, Legend, Line, LineStyle, Plot, PlotPoints, VLine};
use physics::{Graph, LinkOf, Of, Particle, Quantity, Total};

use crate::action::Action;
use crate::analysis;
use crate::document::Document;
use crate::edit::Edit;
use crate::format;
use crate::i18n::{Arg, tr, tr_with};
use crate::picture::Format;
use crate::recording::Recording;
use crate::run_loop::Runner;
use crate::timeline::Timeline;

/// Points drawn per series at most; the CSV export has every sample.
const MAX_POINTS: usize = 4_000;

/// An edit of one graph: what it is, for undo, and what it does.
type GraphEdit = (Edit, Box<dyn FnOnce(&mut Graph)>);

/// The graph panel's own state: the choice being made in each "add" row.
#[derive(Default)]
pub struct Graphs {
    choice: Vec<(usize, Of)>,
    /// Whether each graph marks its series' maxima, minima and zero crossings.
    pub marks: Vec<bool>,
    /// Whether each graph's view is to be reset at the next frame.
    reset: Vec<bool>,
    /// What each graph read off its series last frame (the periods, the fits), as shown.
    pub readings: Vec<Vec<String>>,
    /// The model each graph fits its series with, if any.
    pub fits: Vec<Option<analysis::Model>>,
    /// What each graph last read off its series, and of which samples.
    read: Vec<Option<Read>>,
    /// Where each graph's plot was drawn last frame, for its picture.
    pub rects: Vec<egui::Rect>,
    /// Whether a period read may become a lesson's question (the teacher's view).
    pub can_ask: bool,
    /// The quantity whose period the teacher asked about this frame.
    pub asked: Option<String>,
}

/// `A.vx (m/s)`, `total_energy (J)`, `t (s)`.
pub fn label(quantity: &Quantity) -> String {
    format!("{quantity} ({})", quantity.unit())
}

/// A system quantity in words of the app's language, with its unit ("kinetic energy
/// (J)"), as the graphs show it (its buttons, legend and axis; the CSV keeps [`label`]);
/// other quantities as [`label`] (their names are the scene's).
pub fn words(quantity: &Quantity) -> String {
    let Quantity::Total(total) = quantity else {
        return label(quantity);
    };
    let key = match total {
        Total::KineticEnergy => "total-kinetic-energy",
        Total::PotentialEnergy => "total-potential-energy",
        Total::TotalEnergy => "total-total-energy",
        Total::MomentumX => "total-momentum-x",
        Total::MomentumY => "total-momentum-y",
        Total::AngularMomentum => "total-angular-momentum",
    };
    format!("{} ({})", tr(key), quantity.unit())
}

/// The recorded samples of `graph` as CSV: t first, then the x axis if it is not t,
/// then each series; one row per sample, at the simulation's instants.
pub fn to_csv(recording: &Recording, graph: &Graph) -> String {
    let mut columns = vec![Quantity::Time];
    if graph.x != Quantity::Time {
        columns.push(graph.x.clone());
    }
    columns.extend(graph.y.iter().cloned());
    let quote = |s: String| {
        if s.contains([',', '"']) {
            format!("\"{}\"", s.replace('"', "\"\""))
        } else {
            s
        }
    };
    let header: Vec<String> = columns.iter().map(|q| quote(label(q))).collect();
    let mut out = header.join(",");
    out.push('\n');
    let found: Vec<_> = columns.iter().map(|q| recording.column(q)).collect();
    for k in 0..recording.len() {
        let fields: Vec<String> = found
            .iter()
            .map(|c| c.map_or_else(String::new, |c| format!("{:?}", recording.at(k, c))))
            .collect();
        out.push_str(&fields.join(","));
        out.push('\n');
    }
    out
}

impl Graphs {
    /// The readouts and the graphs. Returns an action the user asked for (export).
    pub fn ui(&mut self, ui: &mut Ui, document: &mut Document, runner: &Runner) -> Option<Action> {
        crate::readouts::ui(ui, runner);
        let mut action = impact_list(ui, runner, document.scene());
        ui.separator();
        let count = document.scene().graphs.len();
        self.choice.resize(count, (0, Of::Y));
        self.marks.resize(count, false);
        self.reset.resize(count, false);
        self.readings.resize(count, Vec::new());
        self.fits.resize(count, None);
        self.read.resize_with(count, || None);
        self.rects.resize(count, egui::Rect::NOTHING);
        for g in 0..count {
            ui.push_id(("graph", g), |ui| {
                // Gone back in time: a cursor on the graphs at the moment shown.
                let cursor = runner
                    .timeline
                    .as_ref()
                    .and_then(|t| t.shown)
                    .and(runner.simulation())
                    .map(physics::Simulation::time);
                let runs = Runs {
                    recording: runner.recording.as_ref(),
                    earlier: &runner.earlier[..],
                    cursor,
                    playing: runner.playing,
                    timeline: runner.timeline.as_ref(),
                };
                if let Some(a) = self.graph(ui, document, runs, g) {
                    action = Some(a);
                }
            });
            ui.separator();
        }
        if ui
            .button(tr("graph-add"))
            .on_hover_text(tr("graph-add-hint"))
            .clicked()
        {
            document.apply(Edit::AddGraph, |scene| {
                scene.graphs.push(Graph::against_time([]));
            });
        }
        action
    }

    /// The maxima and minima graph `g` marks (its series' in order), as last read: a
    /// time, a value and whether each is a maximum.
    pub fn extremes(&self, g: usize) -> Vec<(f64, f64, bool)> {
        self.read
            .get(g)
            .and_then(Option::as_ref)
            .map(|read| {
                read.analyses
                    .iter()
                    .flat_map(|a| a.extremes.iter().map(|e| (e.x, e.value, e.maximum)))
                    .collect()
            })
            .unwrap_or_default()
    }

    #[expect(
        clippy::too_many_lines,
        reason = "one graph's controls, laid out in order"
    )]
    fn graph(
        &mut self,
        ui: &mut Ui,
        document: &mut Document,
        runs: Runs<'_>,
        g: usize,
    ) -> Option<Action> {
        let Runs {
            recording,
            earlier,
            cursor,
            playing,
            timeline,
        } = runs;
        // Only what the panel reads, not the whole scene, every frame.
        let graph = &document.scene().graphs[g].clone();
        let names = document.scene().particle_names();
        // A turning particle's quantities are offered only where one turns.
        let turning = document.scene().particles.iter().any(Particle::turns);
        let (x, series) = (graph.x.clone(), graph.y.clone());
        let mut action = None;
        let mut change: Option<GraphEdit> = None;
        ui.horizontal(|ui| {
            ui.heading(graph.title.clone().unwrap_or_else(|| {
                tr_with(
                    "graph-untitled",
                    &[("number", Arg::Text(&(g + 1).to_string()))],
                )
            }));
            if ui
                .small_button(tr("graph-remove"))
                .on_hover_text(tr("graph-remove-hint"))
                .clicked()
            {
                change = Some((Edit::RemoveGraph, Box::new(|_| {})));
            }
        });
        ui.horizontal_wrapped(|ui| {
            let (mut particle, mut of) = self.choice[g];
            particle = particle.min(names.len().saturating_sub(1));
            let label = ui.label(tr("graph-particle"));
            egui::ComboBox::from_id_salt("graph particle")
                .selected_text(names.get(particle).map_or("—", String::as_str))
                .show_ui(ui, |ui| {
                    for (i, name) in names.iter().enumerate() {
                        ui.selectable_value(&mut particle, i, name.as_str());
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(tr("graph-particle-hint"));
            let label = ui.label(tr("graph-quantity"));
            egui::ComboBox::from_id_salt("graph quantity")
                .selected_text(of.key())
                .show_ui(ui, |ui| {
                    for q in Of::ALL.into_iter().filter(|&q| turning || !q.turns()) {
                        ui.selectable_value(&mut of, q, q.key());
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(tr("graph-quantity-hint"));
            self.choice[g] = (particle, of);
            let chosen = names
                .get(particle)
                .map(|name| Quantity::Particle(name.clone(), of));
            if ui
                .add_enabled(chosen.is_some(), egui::Button::new(tr("graph-add-series")))
                .on_hover_text(tr("graph-add-series-hint"))
                .clicked()
                && let Some(text) = chosen.clone()
            {
                change = Some((Edit::AddSeries, Box::new(move |graph| graph.y.push(text))));
            }
            if ui
                .add_enabled(chosen.is_some(), egui::Button::new(tr("graph-x-axis")))
                .on_hover_text(tr("graph-x-axis-hint"))
                .clicked()
                && let Some(text) = chosen
            {
                change = Some((Edit::SetXAxis, Box::new(move |graph| graph.x = text)));
            }
        });
        // Each rod's and string's angle, length and tension; each spring's angle and length.
        let scene = document.scene();
        let ties = scene
            .ties
            .iter()
            .flat_map(|t| LinkOf::ALL.map(|of| Quantity::Link(t.name.clone(), of)));
        let springs = scene.springs.iter().flat_map(|s| {
            [LinkOf::Angle, LinkOf::Length].map(|of| Quantity::Link(s.name.clone(), of))
        });
        let links: Vec<Quantity> = ties.chain(springs).collect();
        ui.horizontal_wrapped(|ui| {
            let totals = Total::ALL
                .into_iter()
                .filter(|&t| turning || t != Total::AngularMomentum)
                .map(Quantity::Total);
            for quantity in totals.chain(links) {
                let hint = tr(match quantity {
                    Quantity::Link(_, LinkOf::Tension) => "graph-tension-hint",
                    Quantity::Link(_, LinkOf::Angle) => "graph-angle-hint",
                    Quantity::Link(_, LinkOf::Length) => "graph-length-hint",
                    _ => "graph-total-hint",
                });
                if ui
                    .small_button(words(&quantity))
                    .on_hover_text(hint)
                    .clicked()
                {
                    change = Some((
                        Edit::AddSeries,
                        Box::new(move |graph| graph.y.push(quantity)),
                    ));
                }
            }
        });
        ui.horizontal_wrapped(|ui| {
            if x != Quantity::Time {
                ui.label(tr_with(
                    "graph-x-axis-now",
                    &[("quantity", Arg::Text(&words(&x)))],
                ));
                if ui
                    .small_button(tr("graph-use-time"))
                    .on_hover_text(tr("graph-use-time-hint"))
                    .clicked()
                {
                    change = Some((Edit::SetXAxis, Box::new(|graph| graph.x = Quantity::Time)));
                }
            }
            for (k, q) in series.iter().enumerate() {
                if ui
                    .small_button(format!("× {}", words(q)))
                    .on_hover_text(tr("graph-remove-series-hint"))
                    .clicked()
                {
                    change = Some((
                        Edit::RemoveSeries,
                        Box::new(move |graph| {
                            graph.y.remove(k);
                        }),
                    ));
                }
            }
        });
        if let Some((what, edit)) = change {
            document.apply(what, |scene| {
                if what == Edit::RemoveGraph {
                    scene.graphs.remove(g);
                } else {
                    edit(&mut scene.graphs[g]);
                }
            });
        }
        let samples = recording.map_or(0, Recording::len);
        ui.horizontal(|ui| {
            if ui
                .add_enabled(samples > 0, egui::Button::new(tr("graph-export-csv")))
                .on_hover_text(tr("graph-export-csv-hint"))
                .clicked()
            {
                action = Some(Action::ExportGraph(g));
            }
            // In the browser a graph saves as the picture on screen (`figure.rs`).
            let formats = [
                (Format::Png, "graph-save-png", "graph-save-png-hint"),
                (Format::Svg, "graph-save-svg", "graph-save-svg-hint"),
            ];
            let shown = if cfg!(target_arch = "wasm32") { 1 } else { 2 };
            for (format, text, hint) in formats.into_iter().take(shown) {
                if ui
                    .add_enabled(samples > 0, egui::Button::new(tr(text)))
                    .on_hover_text(tr(hint))
                    .clicked()
                {
                    action = Some(Action::ExportFigure(g, format));
                }
            }
        });
        let Some(recording) = recording else {
            ui.label(tr("graph-press-play"));
            return action;
        };
        ui.horizontal(|ui| {
            ui.checkbox(&mut self.marks[g], tr("graph-marks"))
                .on_hover_text(tr("graph-marks-hint"));
            let fit = &mut self.fits[g];
            let label = ui.label(tr("graph-fit"));
            egui::ComboBox::from_id_salt(("graph fit", g))
                .selected_text(fit.map_or_else(|| tr("graph-fit-none"), model_name))
                .show_ui(ui, |ui| {
                    ui.selectable_value(fit, None, tr("graph-fit-none"));
                    for model in analysis::Model::ALL {
                        ui.selectable_value(fit, Some(model), model_name(model));
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(tr("graph-fit-hint"));
            if !earlier.is_empty()
                && ui
                    .small_button(tr("graph-forget-earlier"))
                    .on_hover_text(tr("graph-forget-earlier-hint"))
                    .clicked()
            {
                action = Some(Action::ForgetEarlierRuns);
            }
            if ui
                .small_button(tr("graph-reset-view"))
                .on_hover_text(tr("graph-reset-view-hint"))
                .clicked()
            {
                self.reset[g] = true;
            }
        });
        // What is drawn: at most MAX_POINTS a series. What the graph reads off its
        // series (extremes, fits) is of every sample, and kept until the run changes.
        let every = samples.div_ceil(MAX_POINTS).max(1);
        let columns = series_points(recording, &x, &series, every);
        let marks = self.marks[g] && x == Quantity::Time;
        let key = ReadKey {
            samples,
            x: x.clone(),
            series: series.clone(),
            marks,
            fit: self.fits[g],
            // Located in the run once it stops: while it plays, each frame would wait.
            located: marks && !playing && timeline.is_some(),
        };
        if (marks || key.fit.is_some())
            && self.read[g]
                .as_ref()
                .is_none_or(|r| r.is_stale(&key, playing))
        {
            self.read[g] = Some(Read::of(recording, key, timeline));
        }
        let empty = Read::default();
        let read = self.read[g]
            .as_ref()
            .filter(|_| marks || self.fits[g].is_some())
            .unwrap_or(&empty);
        let (analyses, fits) = (&read.analyses, &read.fits);
        let mut plot = Plot::new("graph")
            .legend(Legend::default())
            // The wheel scrolls the panel, not the plot (Ctrl and the wheel zoom it).
            .allow_scroll(false)
            // egui_plot's default hides x labels closer than 60 points, which on a panel
            // this narrow leaves only "0"; a label that does not fit is still skipped.
            .custom_x_axes(vec![
                AxisHints::new_x()
                    .label(words(&x))
                    .label_spacing(24.0..=40.0),
            ])
            .height(220.0);
        if std::mem::take(&mut self.reset[g]) {
            plot = plot.reset();
        }
        // The earlier runs' series first, greyed, so the last run's are drawn over them.
        let earlier_lines: Vec<Vec<[f64; 2]>> = earlier
            .iter()
            .flat_map(|run| {
                series.iter().filter_map(|q| {
                    let (across, up) = (run.column(&x)?, run.column(q)?);
                    let every = run.len().div_ceil(MAX_POINTS).max(1);
                    Some(
                        (0..run.len())
                            .step_by(every)
                            .map(|k| [run.at(k, across), run.at(k, up)])
                            .collect(),
                    )
                })
            })
            .collect();
        let shown = plot.show(ui, |plot| {
            for points in &earlier_lines {
                plot.line(
                    Line::new(tr("graph-earlier-runs"), PlotPoints::from(points.clone()))
                        .color(egui::Color32::from_gray(150))
                        .width(1.0),
                );
            }
            for (q, points) in &columns {
                plot.line(Line::new(words(q), PlotPoints::from(points.clone())));
            }
            for analysis in analyses {
                analysis.draw(plot);
            }
            for (name, fit, (from, to)) in fits {
                let curve: PlotPoints = (0..=400)
                    .map(|k| {
                        let x = from + (to - from) * f64::from(k) / 400.0;
                        [x, fit.model.value(&fit.parameters, x)]
                    })
                    .collect();
                plot.line(
                    Line::new(format!("{name} fit"), curve)
                        .style(LineStyle::dashed_loose())
                        .color(egui::Color32::from_rgb(60, 60, 60)),
                );
            }
            if let (Quantity::Time, Some(t)) = (&x, cursor) {
                plot.vline(
                    VLine::new("shown", t)
                        .color(egui::Color32::from_rgb(200, 60, 60))
                        .width(1.5),
                );
            }
            if x == Quantity::Time {
                for t in impact_marks(recording, &series) {
                    plot.vline(
                        VLine::new("impacts", t)
                            .color(egui::Color32::from_gray(140))
                            .style(LineStyle::dashed_dense()),
                    );
                }
            }
        });
        // The values under the pointer: where it is across, and each series there.
        if let Some(pointer) = shown.response.hover_pos() {
            let at = shown.transform.value_from_position(pointer).x;
            let mut line = format!("{x} = {}", format::with_unit(at, x.unit()));
            for (q, points) in &columns {
                let (across, up): (Vec<f64>, Vec<f64>) =
                    points.iter().map(|p| (p[0], p[1])).unzip();
                let sorted = across.windows(2).all(|w| w[0] <= w[1]);
                if let Some(value) = sorted
                    .then(|| analysis::value_at(&across, &up, at))
                    .flatten()
                {
                    let _ = write!(line, ";  {q} = {}", format::with_unit(value, q.unit()));
                }
            }
            ui.label(
                egui::RichText::new(line)
                    .small()
                    .family(egui::FontFamily::Monospace),
            );
        }
        self.readings[g] = analyses
            .iter()
            .filter_map(Analysis::period_words)
            .chain(fits.iter().map(|(name, fit, _)| fit_words(name, fit)))
            .collect();
        // Monospace: its font has the superscripts of a power of ten (1.2 × 10⁻¹³).
        let periods = analyses.iter().filter(|a| a.period_words().is_some());
        let askable = periods.map(|a| a.has_period().then(|| a.name.clone()));
        let askable: Vec<Option<String>> = askable.chain(fits.iter().map(|_| None)).collect();
        for (words, ask) in self.readings[g].iter().zip(askable) {
            ui.horizontal_wrapped(|ui| {
                ui.label(
                    egui::RichText::new(words)
                        .small()
                        .family(egui::FontFamily::Monospace),
                );
                if let Some(name) = ask.filter(|_| self.can_ask)
                    && ui
                        .small_button(tr("stopwatch-ask"))
                        .on_hover_text(tr("graph-ask-hint"))
                        .clicked()
                {
                    self.asked = Some(name);
                }
            });
        }
        self.rects[g] = shown.response.rect;
        action
    }
}

/// Each series of `series` against `x`, every `every`th sample and the last.
fn series_points(
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

/// What a graph draws from: the last run, the runs before it, the moment shown when gone
/// back in time, whether it plays, and its keyframes (to locate extremes in).
#[derive(Clone, Copy)]
struct Runs<'a> {
    recording: Option<&'a Recording>,
    earlier: &'a [Recording],
    cursor: Option<f64>,
    playing: bool,
    timeline: Option<&'a Timeline>,
}

/// What a graph's reading was made of: the run's samples so far and the graph's choices.
#[derive(Clone, Debug, PartialEq)]
struct ReadKey {
    samples: usize,
    x: Quantity,
    series: Vec<Quantity>,
    marks: bool,
    fit: Option<analysis::Model>,
    /// Whether the marks are to be located in the run, not read off the samples.
    located: bool,
}

/// What a graph read off every sample of its series: extremes and zeros, and fits.
#[derive(Default)]
struct Read {
    key: Option<ReadKey>,
    analyses: Vec<Analysis>,
    fits: Vec<(String, analysis::Fit, (f64, f64))>,
}

impl Read {
    /// Reads `recording` as `key` asks, locating the marks in `timeline` if it says so.
    fn of(recording: &Recording, key: ReadKey, timeline: Option<&Timeline>) -> Self {
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
    fn is_stale(&self, key: &ReadKey, playing: bool) -> bool {
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
struct Analysis {
    name: String,
    extremes: Vec<analysis::Extreme>,
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
    fn draw(&self, plot: &mut egui_plot::PlotUi<'_>) {
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
    fn has_period(&self) -> bool {
        matches!(analysis::period(&self.extremes), Some(Ok(_)))
    }

    /// "period of bob.x: 3.0446 s (mean of 2 cycles, located in the run)", or why the
    /// maxima give none.
    fn period_words(&self) -> Option<String> {
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

/// A model's name in the app's language.
fn model_name(model: analysis::Model) -> String {
    tr(match model {
        analysis::Model::Line => "graph-fit-line",
        analysis::Model::Parabola => "graph-fit-parabola",
        analysis::Model::Sine => "graph-fit-sine",
        analysis::Model::Decay => "graph-fit-decay",
    })
}

/// "fit of bob.x: y = A sin(ω t + φ) + c; A = 1.7320 ± 0.0001, …; rms 3e-5".
fn fit_words(name: &str, fit: &analysis::Fit) -> String {
    let parameters: Vec<String> = fit
        .model
        .names()
        .iter()
        .zip(fit.parameters.iter().zip(&fit.uncertainties))
        .map(|(n, (value, sigma))| {
            format!(
                "{n} = {} ± {}",
                format::number(*value),
                format::number(*sigma)
            )
        })
        .collect();
    tr_with(
        "graph-fit-result",
        &[
            ("quantity", Arg::Text(name)),
            ("model", Arg::Text(&model_name(fit.model))),
            ("parameters", Arg::Text(&parameters.join(", "))),
            ("rms", Arg::Text(&format::number(fit.rms))),
        ],
    )
}

/// Marks shown on a graph at most: more would be a grey smear.
const MARKS: usize = 60;

/// The instants of the impacts that involve the graph's particles (every impact, for a
/// graph of system quantities), when there are few enough to mark legibly.
pub fn impact_marks(recording: &Recording, series: &[Quantity]) -> Vec<f64> {
    let particles: Vec<usize> = series
        .iter()
        .filter_map(|q| match q {
            Quantity::Particle(name, _) => recording.index_of(name),
            _ => None,
        })
        .collect();
    let system = series.iter().any(|q| matches!(q, Quantity::Total(_)));
    let involved = |impact: &physics::ImpactRecord| {
        system
            || particles.contains(&impact.particle)
            || matches!(impact.other, physics::ImpactTarget::Particle(j) if particles.contains(&j))
    };
    let times: Vec<f64> = recording
        .impacts()
        .iter()
        .filter(|i| involved(i))
        .map(|i| i.time)
        .take(MARKS + 1)
        .collect();
    if times.len() > MARKS {
        Vec::new()
    } else {
        times
    }
}

/// The impacts of the run, in time order (as many as the recording keeps): when, what
/// hit what, the impulse and the kinetic energy each took. Only the rows in view are
/// laid out, so a run of a hundred thousand impacts costs what twenty do.
fn impact_list(ui: &mut Ui, runner: &Runner, scene: &physics::Scene) -> Option<Action> {
    let Some(recording) = &runner.recording else {
        return None;
    };
    // With the run's keyframes, a click on an impact's time shows the run at its
    // located instant.
    let can_go = runner.timeline.is_some();
    let mut action = None;
    let impacts = recording.impacts();
    egui::CollapsingHeader::new(tr_with(
        "impacts-title",
        &[("count", Arg::Number(impacts.len() as f64))],
    ))
    .id_salt("impacts")
    .show(ui, |ui| {
        if impacts.is_empty() {
            ui.label(tr("impacts-none"));
            return;
        }
        let names = recording.names();
        let name = |i: usize| names.get(i).map_or("?", String::as_str);
        let row_height = ui.text_style_height(&egui::TextStyle::Body) + 4.0;
        egui::ScrollArea::vertical()
            .max_height(180.0)
            .auto_shrink([false, true])
            .show_rows(ui, row_height, impacts.len(), |ui, rows| {
                egui::Grid::new("impact rows")
                    .num_columns(5)
                    .striped(true)
                    .show(ui, |ui| {
                        for label in [
                            "impacts-time",
                            "impacts-particle",
                            "impacts-hit",
                            "impacts-impulse",
                            "impacts-lost",
                        ] {
                            ui.strong(tr(label));
                        }
                        ui.end_row();
                        let first = rows.start;
                        for (k, impact) in impacts[rows].iter().enumerate() {
                            let other = match impact.other {
                                physics::ImpactTarget::Particle(j) => name(j).to_owned(),
                                physics::ImpactTarget::Ramp(k) => scene
                                    .ramps
                                    .get(k)
                                    .map_or_else(|| tr("impacts-a-ramp"), |r| r.name.clone()),
                                physics::ImpactTarget::Wall => tr("impacts-wall"),
                            };
                            let time = ui
                                .add_enabled(
                                    can_go,
                                    egui::Button::new(
                                        egui::RichText::new(format::number(impact.time))
                                            .monospace(),
                                    )
                                    .small(),
                                )
                                .on_hover_text(tr("impacts-go-to-hint"));
                            if time.clicked() {
                                action = Some(Action::GoToImpact(first + k));
                            }
                            ui.label(name(impact.particle));
                            ui.label(other);
                            ui.monospace(format::number(impact.impulse));
                            ui.monospace(format::number(impact.kinetic_energy_lost));
                            ui.end_row();
                        }
                    });
            });
    });
    action
}
