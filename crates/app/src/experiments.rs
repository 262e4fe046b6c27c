//! The experiment series panel: the scene's `[[series]]`, each edited in place (the
//! setting varied, its range, how long each run lasts, the measures, the law expected),
//! run with a click — on the desktop on every core, in the browser one run a frame — and
//! plotted: each measure against the varied value, the law as a curve, and the
//! residuals. The runs are `physics::series`'s, the same as `newtonlab sweep`'s.

use std::sync::Arc;
#[cfg(not(target_arch = "wasm32"))]
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use egui::Ui;
use egui_plot::{Legend, Line, Plot, PlotPoints, Points};
use physics::series::{Row, Theory};
use physics::{Scene, Series};
use web_time::Instant;

use crate::action::Action;
use crate::document::Document;
use crate::edit::Edit;
use crate::format;
use crate::i18n::{Arg, tr, tr_with};
use crate::picture::Format;

/// What the panel keeps of each series: its last results and the run in progress.
#[derive(Default)]
pub struct Experiments {
    /// Each scene series' results, by index.
    pub results: Vec<Option<Results>>,
    /// The run in progress, if any.
    running: Option<Running>,
    /// Each series' fields as being typed: (series index, key) → text.
    drafts: std::collections::HashMap<(usize, &'static str), String>,
    /// The series whose results came last: the canvas draws its runs' paths.
    last: Option<usize>,
}

/// A series' last results.
#[derive(Clone, Debug)]
pub struct Results {
    /// What was run.
    pub series: Series,
    /// One row per run, in order.
    pub rows: Vec<Row>,
    /// Wall-clock seconds the series took.
    pub seconds: f64,
}

/// A series being run.
struct Running {
    index: usize,
    series: Series,
    total: usize,
    done: Arc<AtomicUsize>,
    started: Instant,
    #[cfg(not(target_arch = "wasm32"))]
    finished: Arc<Mutex<Option<Vec<Row>>>>,
    /// In the browser: the sweep, the scene and the rows so far, one run a frame.
    #[cfg(target_arch = "wasm32")]
    work: (physics::series::Sweep, Scene, Vec<Vec<f64>>, Vec<Row>),
}

impl Experiments {
    /// The panel: each series, and a button to add one.
    pub fn ui(
        &mut self,
        ui: &mut Ui,
        document: &mut Document,
        selected: Option<&str>,
    ) -> Option<Action> {
        self.poll(ui.ctx());
        ui.heading(tr("experiments-heading"))
            .on_hover_text(tr("experiments-heading-hint"));
        let count = document.scene().series.len();
        self.results.resize(count, None);
        let mut action = None;
        for i in 0..count {
            if i >= document.scene().series.len() {
                break; // one was removed this frame
            }
            ui.push_id(("experiment", i), |ui| {
                if let Some(a) = self.one(ui, document, i, selected) {
                    action = Some(a);
                }
            });
            ui.separator();
        }
        let particle = selected
            .map(str::to_owned)
            .or_else(|| document.scene().particles.first().map(|p| p.name.clone()));
        if ui
            .add_enabled(particle.is_some(), egui::Button::new(tr("experiment-add")))
            .on_hover_text(tr("experiment-add-hint"))
            .clicked()
            && let Some(name) = particle
        {
            document.apply(Edit::AddExperiment, |scene| {
                scene.series.push(Series {
                    vary: format!("{name}.velocity.angle"),
                    from: 15.0,
                    to: 75.0,
                    step: 5.0,
                    until: 5.0,
                    measure: vec![format!("max {name}.y")],
                    theory: None,
                });
            });
        }
        action
    }

    /// The paths of every run of the series that finished last, each particle's a
    /// polyline, for the canvas to draw faintly over the scene.
    pub fn paths(&self) -> Vec<&[physics::DVec2]> {
        self.last
            .and_then(|i| self.results.get(i)?.as_ref())
            .map(|results| {
                results
                    .rows
                    .iter()
                    .flat_map(|row| row.paths.iter().map(Vec::as_slice))
                    .collect()
            })
            .unwrap_or_default()
    }

    /// Whether a series is being run.
    pub fn is_running(&self) -> bool {
        self.running.is_some()
    }

    /// Forgets every result (a new scene).
    pub fn clear(&mut self) {
        *self = Self::default();
    }

    /// Runs series `index` of `scene`: on the desktop on a thread of its own, over every
    /// core; in the browser a few runs a frame.
    ///
    /// # Errors
    /// Why it cannot run: no such series, or one that does not read on the scene.
    pub fn start(&mut self, scene: &Scene, index: usize) -> Result<(), String> {
        if self.running.is_some() {
            return Ok(());
        }
        let series = scene
            .series
            .get(index)
            .cloned()
            .ok_or_else(|| tr("experiment-none"))?;
        let mut sweep = series.sweep(scene)?;
        sweep.check(scene)?;
        sweep.trace = true;
        let points = sweep.points();
        let done = Arc::new(AtomicUsize::new(0));
        // On the desktop, a thread of its own runs the series over every core.
        #[cfg(not(target_arch = "wasm32"))]
        let finished = {
            let finished = Arc::new(Mutex::new(None));
            let (scene, counter, slot) = (scene.clone(), Arc::clone(&done), Arc::clone(&finished));
            let threads = physics::every_core();
            std::thread::spawn(move || {
                let rows = sweep.run(&scene, threads, &|| {
                    counter.fetch_add(1, Ordering::Relaxed);
                });
                if let Ok(mut place) = slot.lock() {
                    *place = Some(rows);
                }
            });
            finished
        };
        self.running = Some(Running {
            index,
            series,
            total: points.len(),
            done,
            started: Instant::now(),
            #[cfg(not(target_arch = "wasm32"))]
            finished,
            #[cfg(target_arch = "wasm32")]
            work: (sweep, scene.clone(), points, Vec::new()),
        });
        Ok(())
    }

    /// Takes the results of a finished run; in the browser, does the next runs first.
    fn poll(&mut self, ctx: &egui::Context) {
        let Some(running) = &mut self.running else {
            return;
        };
        ctx.request_repaint();
        #[cfg(target_arch = "wasm32")]
        let rows = {
            let (sweep, scene, points, rows) = &mut running.work;
            // A few runs a frame, within about 30 ms, so that the page stays alive.
            let frame = Instant::now();
            while rows.len() < points.len() && frame.elapsed().as_secs_f64() < 0.03 {
                let row = sweep.run_one(scene, &points[rows.len()]);
                rows.push(row);
            }
            running.done.store(rows.len(), Ordering::Relaxed);
            (rows.len() == points.len()).then(|| std::mem::take(rows))
        };
        #[cfg(not(target_arch = "wasm32"))]
        let rows = running
            .finished
            .lock()
            .ok()
            .and_then(|mut place| place.take());
        let Some(rows) = rows else {
            return;
        };
        let seconds = running.started.elapsed().as_secs_f64();
        let index = running.index;
        let series = running.series.clone();
        self.running = None;
        if let Some(slot) = self.results.get_mut(index) {
            *slot = Some(Results {
                series,
                rows,
                seconds,
            });
            self.last = Some(index);
        }
    }

    /// Waits until the run in progress is done (for tests and the command line).
    pub fn finish(&mut self, ctx: &egui::Context) {
        while self.running.is_some() {
            self.poll(ctx);
            std::thread::sleep(std::time::Duration::from_millis(2));
        }
    }

    #[expect(
        clippy::too_many_lines,
        reason = "one series' fields, run and plots, in order"
    )]
    fn one(
        &mut self,
        ui: &mut Ui,
        document: &mut Document,
        i: usize,
        selected: Option<&str>,
    ) -> Option<Action> {
        let scene = document.scene();
        let series = scene.series[i].clone();
        let mut action = None;
        let mut removed = false;
        ui.horizontal(|ui| {
            ui.heading(tr_with(
                "experiment-title",
                &[("number", Arg::Text(&(i + 1).to_string()))],
            ));
            removed = ui
                .small_button(tr("experiment-remove"))
                .on_hover_text(tr("experiment-remove-hint"))
                .clicked();
        });
        if removed {
            document.apply(Edit::RemoveExperiment, |scene| {
                scene.series.remove(i);
            });
            self.results.remove(i);
            self.drafts.clear();
            self.last = None;
            return None;
        }
        // This series' problems alone: the whole scene is not checked every frame.
        let problems: Vec<String> = series
            .problems(scene)
            .into_iter()
            .map(|(_, why)| why)
            .collect();
        let mut edited: Option<Series> = None;
        egui::Grid::new("experiment fields")
            .num_columns(2)
            .show(ui, |ui| {
                let mut text = |ui: &mut Ui, key: &'static str, now: String, hint: &str| {
                    let label = ui.label(tr(&format!("experiment-{key}")));
                    let draft = self.drafts.entry((i, key)).or_insert_with(|| now.clone());
                    let response = ui
                        .add(egui::TextEdit::singleline(draft).desired_width(200.0))
                        .labelled_by(label.id)
                        .on_hover_text(tr(hint));
                    ui.end_row();
                    let committed = response.lost_focus();
                    if !response.has_focus() && !committed && *draft != now {
                        // Changed elsewhere (undo, another field): show the scene's value.
                        draft.clone_from(&now);
                    }
                    committed.then(|| draft.trim().to_owned())
                };
                let mut next = series.clone();
                let mut changed = false;
                if let Some(v) = text(ui, "vary", series.vary.clone(), "experiment-vary-hint")
                    && v != series.vary
                {
                    next.vary = v;
                    changed = true;
                }
                for (key, value) in [
                    ("from", series.from),
                    ("to", series.to),
                    ("step", series.step),
                    ("until", series.until),
                ] {
                    let hint = format!("experiment-{key}-hint");
                    if let Some(v) = text(ui, key, format::field(value), &hint)
                        && let Ok(number) = format::typed(&v).trim().parse::<f64>()
                        && number.to_bits() != value.to_bits()
                    {
                        match key {
                            "from" => next.from = number,
                            "to" => next.to = number,
                            "step" => next.step = number,
                            _ => next.until = number,
                        }
                        changed = true;
                    }
                }
                let measures = series.measure.join("; ");
                if let Some(v) = text(ui, "measure", measures.clone(), "experiment-measure-hint")
                    && v != measures
                {
                    next.measure = v
                        .split(';')
                        .map(str::trim)
                        .filter(|m| !m.is_empty())
                        .map(str::to_owned)
                        .collect();
                    changed = true;
                }
                let theory = series.theory.clone().unwrap_or_default();
                if let Some(v) = text(ui, "theory", theory.clone(), "experiment-theory-hint")
                    && v != theory
                {
                    next.theory = (!v.is_empty()).then_some(v);
                    changed = true;
                }
                if changed {
                    edited = Some(next);
                }
            });
        ui.horizontal(|ui| {
            // Measures to add, for the selection (or the first particle).
            ui.menu_button(tr("experiment-add-measure"), |ui| {
                for choice in measures(document.scene(), selected, series.until) {
                    if ui.button(&choice).clicked() {
                        let mut next = edited.take().unwrap_or_else(|| series.clone());
                        self.drafts.remove(&(i, "measure"));
                        next.measure.push(choice);
                        edited = Some(next);
                        ui.close();
                    }
                }
            })
            .response
            .on_hover_text(tr("experiment-add-measure-hint"));
            // The values a series can vary, from the selection (or the first particle).
            ui.menu_button(tr("experiment-choose"), |ui| {
                for choice in choices(document.scene(), selected) {
                    if ui.button(&choice).clicked() {
                        let mut next = edited.take().unwrap_or_else(|| series.clone());
                        self.drafts.remove(&(i, "vary"));
                        next.vary = choice;
                        edited = Some(next);
                        ui.close();
                    }
                }
            })
            .response
            .on_hover_text(tr("experiment-choose-hint"));
        });
        if let Some(next) = edited {
            document.apply(Edit::ChangeExperiment, |scene| scene.series[i] = next);
        }
        for problem in &problems {
            ui.colored_label(egui::Color32::from_rgb(200, 30, 30), problem);
        }
        let running_here = self.running.as_ref().filter(|r| r.index == i);
        ui.horizontal(|ui| {
            let can_run = problems.is_empty() && self.running.is_none();
            if ui
                .add_enabled(can_run, egui::Button::new(tr("experiment-run")))
                .on_hover_text(tr("experiment-run-hint"))
                .clicked()
            {
                action = Some(Action::RunExperiment(i));
            }
            if let Some(running) = running_here {
                ui.label(tr_with(
                    "experiment-progress",
                    &[
                        (
                            "done",
                            Arg::Number(running.done.load(Ordering::Relaxed) as f64),
                        ),
                        ("total", Arg::Number(running.total as f64)),
                    ],
                ));
            } else if let Some(Some(results)) = self.results.get(i) {
                ui.label(tr_with(
                    "experiment-took",
                    &[
                        ("runs", Arg::Number(results.rows.len() as f64)),
                        ("seconds", Arg::Text(&format::fixed(results.seconds, 2))),
                    ],
                ));
            }
        });
        let Some(Some(results)) = self.results.get(i) else {
            // Before a run, the law alone, so that an example opens with its curve.
            if series.theory.is_some() {
                let empty = Results {
                    series,
                    rows: Vec::new(),
                    seconds: 0.0,
                };
                plot(ui, document.scene(), &empty);
            }
            return action;
        };
        plot(ui, document.scene(), results);
        ui.horizontal(|ui| {
            if ui
                .button(tr("graph-export-csv"))
                .on_hover_text(tr("experiment-export-csv-hint"))
                .clicked()
            {
                action = Some(Action::ExportExperiment(i, None));
            }
            let shown = if cfg!(target_arch = "wasm32") { 0 } else { 2 };
            for (format, text) in [
                (Format::Png, "graph-save-png"),
                (Format::Svg, "graph-save-svg"),
            ]
            .into_iter()
            .take(shown)
            {
                if ui.button(tr(text)).clicked() {
                    action = Some(Action::ExportExperiment(i, Some(format)));
                }
            }
        });
        action
    }
}

/// Every number of the selected particle (the first, if none is selected) a series can
/// vary, as `vary` names it, and the world's: its mass, radius, charge, drag, and each
/// part of its position and velocity; the field's x and y and the restitution.
fn choices(scene: &Scene, selected: Option<&str>) -> Vec<String> {
    use physics::fields::{Kind, PARTICLE};
    let name = selected.or_else(|| scene.particles.first().map(|p| p.name.as_str()));
    let mut out = Vec::new();
    if let Some(name) = name {
        for field in PARTICLE {
            match field.kind {
                Kind::Number(_) => out.push(format!("{name}.{}", field.key)),
                Kind::Vector => out.extend(
                    ["x", "y", "magnitude", "angle"]
                        .map(|part| format!("{name}.{}.{part}", field.key)),
                ),
                _ => {}
            }
        }
    }
    out.extend(["world.gravity.y", "world.restitution"].map(str::to_owned));
    out
}

/// Measures a series often wants, for the selected particle (the first, if none is
/// selected) and each rod or string: where and when it comes down, its extremes, its
/// period, its speed at the end, a swing's period from the rod's passes.
fn measures(scene: &Scene, selected: Option<&str>, until: f64) -> Vec<String> {
    let name = selected.or_else(|| scene.particles.first().map(|p| p.name.as_str()));
    let mut out = Vec::new();
    if let Some(n) = name {
        out.extend([
            format!("{n}.x at {n}.y crosses 0 down"),
            format!("t at {n}.y crosses 0 down"),
            format!("max {n}.y"),
            format!("min {n}.y"),
            format!("max {n}.speed"),
            format!("period {n}.x"),
            format!("{n}.speed at {until}"),
            format!("t at {n}.vx crosses 0 #2"),
        ]);
    }
    for tie in &scene.ties {
        out.push(format!(
            "t at {} crosses 0 up #2",
            physics::Quantity::Link(tie.name.clone(), physics::LinkOf::Angle)
        ));
    }
    out
}

/// The measures against the varied value (dots), the law (a line over the range) and the
/// residuals of the first measure from it.
fn plot(ui: &mut Ui, scene: &Scene, results: &Results) {
    let columns = columns(results);
    let theory = law(scene, &results.series);
    // Room above the points for the legend, which egui_plot draws inside the plot.
    let (low, high) = columns
        .iter()
        .flat_map(|(_, points)| points.iter().map(|p| p[1]))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
            (a.min(y), b.max(y))
        });
    let shown = Plot::new("experiment")
        .legend(Legend::default())
        .include_y(if high > low {
            high + 0.3 * (high - low)
        } else {
            high
        })
        .allow_scroll(false)
        .x_axis_label(results.series.vary.clone())
        .x_axis_formatter(format::plot_tick)
        .y_axis_formatter(format::plot_tick)
        .height(200.0);
    shown.show(ui, |plot| {
        for (name, points) in &columns {
            plot.points(
                Points::new(name.clone(), PlotPoints::from(points.clone()))
                    .radius(4.0)
                    .shape(egui_plot::MarkerShape::Circle),
            );
        }
        if let Some(law) = &theory {
            plot.line(Line::new(
                law.name.clone(),
                PlotPoints::from(law.curve.clone()),
            ));
        }
    });
    if let (Some(law), Some((name, points))) = (&theory, columns.first())
        && !points.is_empty()
    {
        let residuals: Vec<[f64; 2]> = points
            .iter()
            .map(|p| [p[0], p[1] - law.theory.at(p[0])])
            .collect();
        let worst = residuals.iter().map(|r| r[1].abs()).fold(0.0, f64::max);
        ui.label(
            egui::RichText::new(tr_with(
                "experiment-residuals",
                &[
                    ("measure", Arg::Text(name)),
                    ("worst", Arg::Text(&format::number(worst))),
                ],
            ))
            .small()
            .family(egui::FontFamily::Monospace),
        );
        Plot::new("experiment residuals")
            .allow_scroll(false)
            .x_axis_formatter(format::plot_tick)
            .y_axis_formatter(format::plot_tick)
            .height(90.0)
            .show(ui, |plot| {
                plot.points(
                    Points::new(tr("experiment-residual"), PlotPoints::from(residuals)).radius(3.0),
                );
            });
    }
}

/// Each measure's points (varied value, measured), named as typed; runs without a number
/// left out.
pub fn columns(results: &Results) -> Vec<(String, Vec<[f64; 2]>)> {
    results
        .series
        .measure
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let points = results
                .rows
                .iter()
                .filter_map(|row| {
                    let value = row.measured.as_ref().ok()?.get(k)?.as_ref().ok()?;
                    Some([row.values[0], *value])
                })
                .collect();
            (name.clone(), points)
        })
        .collect()
}

/// A series' law, read once: its name, the law itself, and its curve over the series'
/// range (400 points).
pub struct Law {
    pub name: String,
    pub theory: Theory,
    pub curve: Vec<[f64; 2]>,
}

/// The series' law, if it has one that reads.
pub fn law(scene: &Scene, series: &Series) -> Option<Law> {
    let text = series.theory.as_deref()?;
    let theory = Theory::parse(text, scene, &series.vary).ok()?;
    let curve = (0..=400)
        .map(|k| {
            let x = series.from + (series.to - series.from) * f64::from(k) / 400.0;
            [x, theory.at(x)]
        })
        .filter(|p| p[1].is_finite())
        .collect();
    Some(Law {
        name: tr_with("experiment-theory-curve", &[("law", Arg::Text(text))]),
        theory,
        curve,
    })
}

/// The results as `newtonlab sweep` writes them: the varied value, then each measure.
pub fn to_csv(results: &Results) -> String {
    let names: Vec<&str> = std::iter::once(results.series.vary.as_str())
        .chain(results.series.measure.iter().map(String::as_str))
        .collect();
    physics::series::csv(&names, &results.rows)
}
