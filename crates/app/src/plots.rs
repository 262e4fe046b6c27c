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

use egui::Ui;
use physics::{Graph, Quantity, Total, csv_field};

use crate::action::Action;
use crate::analysis;
use crate::document::Document;
use crate::edit::Edit;
use crate::format;
use crate::i18n::{Arg, tr, tr_with};
use crate::recording::Recording;
use crate::run_loop::Runner;

mod panel;
mod read;

use panel::{Asking, GraphPanel, Runs};

/// Points drawn per series at most; the CSV export has every sample.
const MAX_POINTS: usize = 4_000;

/// The graph panel's own state: each graph's, and the teacher's asking.
#[derive(Default)]
pub struct Graphs {
    /// Each graph's state, by its index in the scene.
    panels: Vec<GraphPanel>,
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

/// What an untitled graph shows, as a figure's title says it: "bob.x against t",
/// "A.y, B.y against t".
pub fn describe(graph: &Graph) -> String {
    let y: Vec<String> = graph.y.iter().map(ToString::to_string).collect();
    tr_with(
        "graph-figure-title",
        &[
            ("y", Arg::Text(&y.join(", "))),
            ("x", Arg::Text(&graph.x.to_string())),
        ],
    )
}

/// The colour of each of a graph's series, on screen and in its figure: the colour its
/// particle or body has on the canvas, where every series belongs to a different one
/// (two balls' heights, each in its ball's colour). `None` where two series share an
/// object or one is a system's quantity: the palette then tells them apart, which one
/// object's colour could not.
pub fn object_colours(scene: &physics::Scene, series: &[Quantity]) -> Option<Vec<[u8; 3]>> {
    let mut names: Vec<&str> = Vec::with_capacity(series.len());
    for q in series {
        let Quantity::Particle(name, _) = q else {
            return None;
        };
        if names.contains(&name.as_str()) {
            return None;
        }
        names.push(name);
    }
    names
        .into_iter()
        .map(|name| crate::canvas::object_rgb(scene, name))
        .collect()
}

/// The recorded samples of `graph` as CSV: t first, then the x axis if it is not t,
/// then each series; one row per sample, at the simulation's instants.
pub fn to_csv(recording: &Recording, graph: &Graph) -> String {
    let mut columns = vec![Quantity::Time];
    if graph.x != Quantity::Time {
        columns.push(graph.x.clone());
    }
    columns.extend(graph.y.iter().cloned());
    let header: Vec<String> = columns.iter().map(|q| csv_field(&label(q))).collect();
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
        crate::readouts::ui(ui, runner, document.scene());
        let mut action = impact_list(ui, runner, document.scene());
        ui.separator();
        let count = document.scene().graphs.len();
        self.panels.resize_with(count, GraphPanel::default);
        for (g, panel) in self.panels.iter_mut().enumerate() {
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
                let asking = Asking {
                    can_ask: self.can_ask,
                    asked: &mut self.asked,
                };
                if let Some(a) = panel.ui(ui, document, runs, g, asking) {
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
        self.panels
            .get(g)
            .and_then(|panel| panel.read.as_ref())
            .map(|read| {
                read.analyses
                    .iter()
                    .flat_map(|a| a.extremes.iter().map(|e| (e.x, e.value, e.maximum)))
                    .collect()
            })
            .unwrap_or_default()
    }

    /// What graph `g` read off its series last frame (its periods and fits), as shown.
    pub fn readings(&self, g: usize) -> &[String] {
        self.panels.get(g).map_or(&[], |panel| &panel.readings)
    }

    /// Fits graph `g`'s series with `model` from the next frame on (`None`: no fit).
    pub fn set_fit(&mut self, g: usize, model: Option<analysis::Model>) {
        if self.panels.len() <= g {
            self.panels.resize_with(g + 1, GraphPanel::default);
        }
        self.panels[g].fit = model;
    }

    /// Where graph `g`'s plot was drawn last frame, for its picture.
    pub fn rect(&self, g: usize) -> egui::Rect {
        self.panels
            .get(g)
            .map_or(egui::Rect::NOTHING, |panel| panel.rect)
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
    // Before Play too, so that the panel below does not move when Play starts.
    let impacts = runner
        .recording
        .as_ref()
        .map_or(&[][..], |recording| recording.impacts());
    // With the run's keyframes, a click on an impact's time shows the run at its
    // located instant.
    let can_go = runner.timeline.is_some();
    let mut action = None;
    egui::CollapsingHeader::new(tr_with(
        "impacts-title",
        &[("count", Arg::Number(impacts.len() as f64))],
    ))
    .id_salt("impacts")
    .show(ui, |ui| {
        let Some(recording) = runner.recording.as_ref().filter(|_| !impacts.is_empty()) else {
            ui.label(tr("impacts-none"));
            return;
        };
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

#[cfg(test)]
mod tests {
    use physics::{Color, Particle, Quantity, Scene};

    use super::object_colours;

    /// Two balls' heights are drawn in the balls' own colours (a chosen one, and the
    /// palette's for the second ball, as the canvas draws it); two quantities of one ball,
    /// or one of the system, leave the graph's palette to tell them apart.
    #[test]
    fn each_series_takes_its_own_objects_colour() {
        let mut a = Particle::new("a", 1.0);
        a.color = Some(Color([10, 20, 30]));
        let scene = Scene::new()
            .with_particle(a)
            .with_particle(Particle::new("b", 1.0).position([1.0, 0.0]));
        let q = |text: &str| Quantity::parse(text).expect("a quantity");
        assert_eq!(
            object_colours(&scene, &[q("b.y"), q("a.y")]),
            Some(vec![Color::palette(1).0, [10, 20, 30]])
        );
        assert_eq!(object_colours(&scene, &[q("a.x"), q("a.y")]), None);
        assert_eq!(
            object_colours(&scene, &[q("a.y"), q("kinetic_energy")]),
            None
        );
    }

    /// An untitled graph's figure is titled by what it plots: "Graph 1" says nothing.
    #[test]
    fn an_untitled_graph_is_described_by_its_quantities() {
        let q = |text: &str| Quantity::parse(text).expect("a quantity");
        let graph = physics::Graph::against_time([q("a.y"), q("b.y")]);
        assert_eq!(super::describe(&graph), "a.y, b.y against t");
    }
}
