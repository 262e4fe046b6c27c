//! One graph on the panel, drawn in rows: its title, the series to add (a particle's
//! quantity, a system total, a link's), the axis and the series it has, export, marks
//! and fits, the plot, the values under the pointer, and what it read off its series.

use std::fmt::Write as _;

use egui::Ui;
use egui_plot::{AxisHints, Legend, Line, LineStyle, Plot, PlotPoints, VLine};
use physics::{Graph, LinkOf, Of, Particle, Quantity, Scene, Total};

use super::read::{Analysis, Read, ReadKey, series_points};
use super::{MAX_POINTS, fit_words, impact_marks, model_name, words};
use crate::action::Action;
use crate::analysis;
use crate::document::Document;
use crate::edit::Edit;
use crate::format;
use crate::i18n::{Arg, tr, tr_with};
use crate::picture::Format;
use crate::recording::Recording;
use crate::timeline::Timeline;

/// A graph's plot, points (before Play as through the run).
const PLOT_HEIGHT: f32 = 220.0;

/// An edit of one graph: what it is, for undo, and what it does.
type GraphEdit = (Edit, Box<dyn FnOnce(&mut Graph)>);

/// What a graph draws from: the last run, the runs before it, the moment shown when gone
/// back in time, whether it plays, and its keyframes (to locate extremes in).
#[derive(Clone, Copy)]
pub(super) struct Runs<'a> {
    pub recording: Option<&'a Recording>,
    pub earlier: &'a [Recording],
    pub cursor: Option<f64>,
    pub playing: bool,
    pub timeline: Option<&'a Timeline>,
}

/// Whether the graphs may turn a period into a lesson's question, and the one asked.
pub(super) struct Asking<'a> {
    pub can_ask: bool,
    pub asked: &'a mut Option<String>,
}

/// One graph's own state on the panel.
pub(super) struct GraphPanel {
    /// The choice being made in the "add" row: a particle's index and its quantity.
    choice: (usize, Of),
    /// Whether it marks its series' maxima, minima and zero crossings.
    pub marks: bool,
    /// Whether its view is to be reset at the next frame.
    reset: bool,
    /// What it read off its series last frame (the periods, the fits), as shown.
    pub readings: Vec<String>,
    /// The model it fits its series with, if any.
    pub fit: Option<analysis::Model>,
    /// What it last read off its series, and of which samples.
    pub read: Option<Read>,
    /// Where its plot was drawn last frame, for its picture.
    pub rect: egui::Rect,
}

impl Default for GraphPanel {
    fn default() -> Self {
        Self {
            choice: (0, Of::Y),
            marks: false,
            reset: false,
            readings: Vec::new(),
            fit: None,
            read: None,
            rect: egui::Rect::NOTHING,
        }
    }
}

impl GraphPanel {
    /// Graph `g` of the scene, row by row. Returns an action the user asked for.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        document: &mut Document,
        runs: Runs<'_>,
        g: usize,
        mut asking: Asking<'_>,
    ) -> Option<Action> {
        // Only what the panel reads, not the whole scene, every frame.
        let graph = document.scene().graphs[g].clone();
        let change = [
            title_row(ui, &graph, g),
            self.particle_row(ui, document.scene()),
            system_row(ui, document.scene()),
            axis_row(ui, &graph),
        ]
        .into_iter()
        .flatten()
        .last();
        if let Some((what, edit)) = change {
            document.apply(what, |scene| {
                if what == Edit::RemoveGraph {
                    scene.graphs.remove(g);
                } else {
                    edit(&mut scene.graphs[g]);
                }
            });
        }
        let samples = runs.recording.map_or(0, Recording::len);
        let mut action = export_row(ui, samples, g);
        let Some(recording) = runs.recording else {
            // The rows and the plot a run fills, there and empty: nothing below them
            // moves when Play starts.
            ui.add_enabled_ui(false, |ui| self.analysis_row(ui, false, g));
            empty_plot(ui, &graph.x);
            return action;
        };
        action = self
            .analysis_row(ui, !runs.earlier.is_empty(), g)
            .or(action);
        let (x, series) = (&graph.x, &graph.y);
        // What is drawn: at most MAX_POINTS a series. What the graph reads off its
        // series (extremes, fits) is of every sample, and kept until the run changes.
        let every = samples.div_ceil(MAX_POINTS).max(1);
        let columns = series_points(recording, x, series, every);
        self.read_series(recording, &graph, runs);
        // Taken out while the rows below borrow the panel, and put back as it was.
        let read = self.read.take();
        let empty = Read::default();
        let shown = read
            .as_ref()
            .filter(|_| self.marks && *x == Quantity::Time || self.fit.is_some())
            .unwrap_or(&empty);
        let colours = super::object_colours(document.scene(), series);
        let plot = self.plot(
            ui,
            (&graph, colours.as_deref()),
            runs,
            recording,
            &columns,
            shown,
        );
        pointer_readout(ui, &plot, x, &columns);
        self.readings_rows(ui, shown, &mut asking);
        self.rect = plot.response.rect;
        self.read = read;
        action
    }

    /// The particle and its quantity to add as a series or as the x axis.
    fn particle_row(&mut self, ui: &mut Ui, scene: &Scene) -> Option<GraphEdit> {
        let names = scene.particle_names();
        // A turning particle's quantities are offered only where one turns.
        let turning = scene.particles.iter().any(Particle::turns);
        let mut change: Option<GraphEdit> = None;
        ui.horizontal_wrapped(|ui| {
            let (mut particle, mut of) = self.choice;
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
            self.choice = (particle, of);
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
        change
    }

    /// Marks, the fit, forgetting earlier runs and resetting the view.
    fn analysis_row(&mut self, ui: &mut Ui, earlier: bool, g: usize) -> Option<Action> {
        let mut action = None;
        // Wrapped: one row wider than the panel would widen it, and the canvas beside it
        // would narrow the moment a run starts.
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut self.marks, tr("graph-marks"))
                .on_hover_text(tr("graph-marks-hint"));
            let fit = &mut self.fit;
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
            if earlier
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
                self.reset = true;
            }
        });
        action
    }

    /// Reads the marks and fits off every sample again when the run or the choices
    /// changed since the last reading.
    fn read_series(&mut self, recording: &Recording, graph: &Graph, runs: Runs<'_>) {
        let marks = self.marks && graph.x == Quantity::Time;
        let key = ReadKey {
            samples: recording.len(),
            x: graph.x.clone(),
            series: graph.y.clone(),
            marks,
            fit: self.fit,
            // Located in the run once it stops: while it plays, each frame would wait.
            located: marks && !runs.playing && runs.timeline.is_some(),
        };
        if (marks || key.fit.is_some())
            && self
                .read
                .as_ref()
                .is_none_or(|r| r.is_stale(&key, runs.playing))
        {
            self.read = Some(Read::of(recording, key, runs.timeline));
        }
    }

    /// The plot: earlier runs greyed, the last run's series, marks, fits, the moment
    /// shown and the impacts.
    fn plot(
        &mut self,
        ui: &mut Ui,
        (graph, colours): (&Graph, Option<&[[u8; 3]]>),
        runs: Runs<'_>,
        recording: &Recording,
        columns: &[(Quantity, Vec<[f64; 2]>)],
        read: &Read,
    ) -> egui_plot::PlotResponse<()> {
        let (x, series) = (&graph.x, &graph.y);
        let mut plot = Plot::new("graph")
            .legend(Legend::default())
            // The wheel scrolls the panel, not the plot (Ctrl and the wheel zoom it).
            .allow_scroll(false)
            // egui_plot's default hides x labels closer than 60 points, which on a panel
            // this narrow leaves only "0"; a label that does not fit is still skipped.
            .custom_x_axes(vec![
                AxisHints::new_x()
                    .label(words(x))
                    .label_spacing(24.0..=40.0)
                    .formatter(format::plot_tick),
            ])
            .y_axis_formatter(format::plot_tick)
            .height(PLOT_HEIGHT);
        if std::mem::take(&mut self.reset) {
            plot = plot.reset();
        }
        let earlier_lines = earlier_lines(runs.earlier, x, series);
        // The fitted curve in the theme's strongest text colour: seen on dark and light.
        let fit_colour = ui.visuals().strong_text_color();
        plot.show(ui, |plot| {
            for points in &earlier_lines {
                plot.line(
                    Line::new(tr("graph-earlier-runs"), PlotPoints::from(points.clone()))
                        .color(egui::Color32::from_gray(150))
                        .width(1.0),
                );
            }
            for (q, points) in columns {
                let mut line = Line::new(words(q), PlotPoints::from(points.clone()));
                if let Some([r, g, b]) = colours
                    .zip(series.iter().position(|y| y == q))
                    .map(|(colours, k)| colours[k])
                {
                    line = line.color(egui::Color32::from_rgb(r, g, b));
                }
                plot.line(line);
            }
            for analysis in &read.analyses {
                analysis.draw(plot);
            }
            for (name, fit, (from, to)) in &read.fits {
                let curve: PlotPoints = (0..=400)
                    .map(|k| {
                        let x = from + (to - from) * f64::from(k) / 400.0;
                        [x, fit.model.value(&fit.parameters, x)]
                    })
                    .collect();
                plot.line(
                    Line::new(format!("{name} fit"), curve)
                        .style(LineStyle::dashed_loose())
                        .color(fit_colour),
                );
            }
            if let (Quantity::Time, Some(t)) = (x, runs.cursor) {
                plot.vline(
                    VLine::new("shown", t)
                        .color(egui::Color32::from_rgb(200, 60, 60))
                        .width(1.5),
                );
            }
            if *x == Quantity::Time {
                for t in impact_marks(recording, series) {
                    plot.vline(
                        VLine::new("impacts", t)
                            .color(egui::Color32::from_gray(140))
                            .style(LineStyle::dashed_dense()),
                    );
                }
            }
        })
    }

    /// The periods and fits read, each period with a button that makes it a lesson's
    /// question where the teacher may ask.
    fn readings_rows(&mut self, ui: &mut Ui, read: &Read, asking: &mut Asking<'_>) {
        let (analyses, fits) = (&read.analyses, &read.fits);
        self.readings = analyses
            .iter()
            .filter_map(Analysis::period_words)
            .chain(fits.iter().map(|(name, fit, _)| fit_words(name, fit)))
            .collect();
        let periods = analyses.iter().filter(|a| a.period_words().is_some());
        let askable = periods.map(|a| a.has_period().then(|| a.name.clone()));
        let askable: Vec<Option<String>> = askable.chain(fits.iter().map(|_| None)).collect();
        for (words, ask) in self.readings.iter().zip(askable) {
            ui.horizontal_wrapped(|ui| {
                // Monospace: its font has the superscripts of a power of ten (1.2 × 10⁻¹³).
                ui.label(
                    egui::RichText::new(words)
                        .small()
                        .family(egui::FontFamily::Monospace),
                );
                if let Some(name) = ask.filter(|_| asking.can_ask)
                    && ui
                        .small_button(tr("stopwatch-ask"))
                        .on_hover_text(tr("graph-ask-hint"))
                        .clicked()
                {
                    *asking.asked = Some(name);
                }
            });
        }
    }
}

/// The graph's title and its remove button.
fn title_row(ui: &mut Ui, graph: &Graph, g: usize) -> Option<GraphEdit> {
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
    change
}

/// A button for each system total and each rod's and string's angle, length and
/// tension, each spring's angle and length.
fn system_row(ui: &mut Ui, scene: &Scene) -> Option<GraphEdit> {
    let turning = scene.particles.iter().any(Particle::turns);
    let ties = scene
        .ties
        .iter()
        .flat_map(|t| LinkOf::ALL.map(|of| Quantity::Link(t.name.clone(), of)));
    let springs = scene
        .springs
        .iter()
        .flat_map(|s| [LinkOf::Angle, LinkOf::Length].map(|of| Quantity::Link(s.name.clone(), of)));
    let links: Vec<Quantity> = ties.chain(springs).collect();
    let mut change: Option<GraphEdit> = None;
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
    change
}

/// The x axis when it is not time (with a button back to time), and a remove button for
/// each series.
fn axis_row(ui: &mut Ui, graph: &Graph) -> Option<GraphEdit> {
    let mut change: Option<GraphEdit> = None;
    ui.horizontal_wrapped(|ui| {
        if graph.x != Quantity::Time {
            ui.label(tr_with(
                "graph-x-axis-now",
                &[("quantity", Arg::Text(&words(&graph.x)))],
            ));
            if ui
                .small_button(tr("graph-use-time"))
                .on_hover_text(tr("graph-use-time-hint"))
                .clicked()
            {
                change = Some((Edit::SetXAxis, Box::new(|graph| graph.x = Quantity::Time)));
            }
        }
        for (k, q) in graph.y.iter().enumerate() {
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
    change
}

/// Export as CSV and as a picture, once there are samples.
fn export_row(ui: &mut Ui, samples: usize, g: usize) -> Option<Action> {
    let mut action = None;
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
    action
}

/// The earlier runs' series, each at most [`MAX_POINTS`] points.
fn earlier_lines(earlier: &[Recording], x: &Quantity, series: &[Quantity]) -> Vec<Vec<[f64; 2]>> {
    earlier
        .iter()
        .flat_map(|run| {
            series.iter().filter_map(|q| {
                let (across, up) = (run.column(x)?, run.column(q)?);
                let every = run.len().div_ceil(MAX_POINTS).max(1);
                Some(
                    (0..run.len())
                        .step_by(every)
                        .map(|k| [run.at(k, across), run.at(k, up)])
                        .collect(),
                )
            })
        })
        .collect()
}

/// The plot before Play: its axes as the run will have them, the same height, and what
/// fills it written in its middle.
fn empty_plot(ui: &mut Ui, x: &Quantity) {
    Plot::new("graph")
        .allow_scroll(false)
        .allow_drag(false)
        .allow_zoom(false)
        .custom_x_axes(vec![
            AxisHints::new_x()
                .label(words(x))
                .formatter(format::plot_tick),
        ])
        .y_axis_formatter(format::plot_tick)
        .height(PLOT_HEIGHT)
        .show(ui, |plot| {
            plot.text(egui_plot::Text::new(
                "press play",
                egui_plot::PlotPoint::new(0.5, 0.5),
                tr("graph-press-play"),
            ));
        });
}

/// The values under the pointer: where it is across, and each series there.
fn pointer_readout(
    ui: &mut Ui,
    plot: &egui_plot::PlotResponse<()>,
    x: &Quantity,
    columns: &[(Quantity, Vec<[f64; 2]>)],
) {
    let Some(pointer) = plot.response.hover_pos() else {
        return;
    };
    let at = plot.transform.value_from_position(pointer).x;
    let mut line = format!("{x} = {}", format::with_unit(at, x.unit()));
    for (q, points) in columns {
        let (across, up): (Vec<f64>, Vec<f64>) = points.iter().map(|p| (p[0], p[1])).unzip();
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
