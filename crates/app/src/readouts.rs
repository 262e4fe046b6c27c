//! The energy readouts above the graphs: energies by kind, what damping, friction,
//! drag and impacts took since Play (rods and strings take nothing: a constraint does no
//! work), the numerical error (what the books leave unaccounted) and the total momentum,
//! as a table and as bars.

use egui::Ui;
use physics::{Scene, Total};

use crate::format;
use crate::i18n::{Arg, tr, tr_with};
use crate::run_loop::Runner;

/// Which rows the readouts have for a scene: decided by the scene, not by the values, so
/// that the rows before Play (their values a dash) are those while it runs and the
/// panel below them does not move when Play fills them in.
#[derive(Clone, Copy)]
#[expect(
    clippy::struct_excessive_bools,
    reason = "four independent rows, each there or not"
)]
struct Rows {
    /// A force of one's own with a potential.
    own_potential: bool,
    /// Air resistance on some particle.
    drag: bool,
    /// A motor on some joint.
    motors: bool,
    /// Rods or strings (listed at 0: constraints do no work).
    ties: bool,
    /// Which potentials have a bar, in the table's order: height, springs, gravitation,
    /// electrostatics (the table lists all four).
    potentials: [bool; 4],
}

impl Rows {
    fn of(scene: &Scene) -> Self {
        let air = scene.world.air_density;
        Self {
            own_potential: scene.forces.iter().any(|f| f.potential.is_some()),
            drag: scene
                .particles
                .iter()
                .any(|p| p.linear_drag > 0.0 || p.quadratic_drag_in(air) > 0.0),
            motors: scene.joints.iter().any(|j| j.motor.is_some()),
            ties: !scene.ties.is_empty(),
            potentials: [
                scene.world.gravity.to_dvec2() != physics::DVec2::ZERO,
                !scene.springs.is_empty(),
                scene.world.gravitation && scene.particles.len() > 1,
                scene.world.electrostatics && scene.particles.iter().any(|p| p.charge != 0.0),
            ],
        }
    }
}

/// Energies by kind, the energy ledger, momentum: live while running, the last recorded
/// values after a failure, a dash for each before Play.
pub(crate) fn ui(ui: &mut Ui, runner: &Runner, scene: &Scene) {
    let shown = Rows::of(scene);
    // The books: what damping, friction and impacts took since Play, and what is left
    // unaccounted, the numerical error (the integrator's, and the position correction
    // of piles), as a share of the energy at Play (in joules when that was 0).
    let ledger = || {
        runner
            .simulation()
            .and_then(physics::Simulation::ledger)
            .unwrap_or_default()
    };
    let (status, energy, ledger, start) =
        match (runner.simulation(), &runner.failure, &runner.recording) {
            (Some(_), Some(_), Some(recording)) => {
                let get = |t| recording.last_total(t).unwrap_or(f64::NAN);
                let energy = Energies {
                    kinetic: get(Total::KineticEnergy),
                    potential: vec![(tr("readout-potential"), get(Total::PotentialEnergy))],
                    total: get(Total::TotalEnergy),
                    momentum: [get(Total::MomentumX), get(Total::MomentumY)],
                };
                (tr("readout-failed"), energy, ledger(), runner.start_energy)
            }
            (Some(simulation), _, _) => {
                let d = runner.diagnostics().unwrap_or_default();
                let e = d.energy;
                let energy = Energies {
                    kinetic: e.kinetic,
                    potential: potentials(
                        [e.uniform, e.spring, e.gravitation, e.electrostatic],
                        shown.own_potential.then_some(e.own),
                    ),
                    total: e.total(),
                    momentum: [d.momentum.x, d.momentum.y],
                };
                let at = format::with_unit(simulation.time(), "s");
                let status = tr_with("readout-at", &[("time", Arg::Text(&at))]);
                (status, energy, ledger(), runner.start_energy)
            }
            (None, _, _) => {
                let energy = Energies {
                    kinetic: f64::NAN,
                    potential: potentials([f64::NAN; 4], shown.own_potential.then_some(f64::NAN)),
                    total: f64::NAN,
                    momentum: [f64::NAN; 2],
                };
                let nothing = physics::Ledger {
                    damping: f64::NAN,
                    friction: f64::NAN,
                    impacts: f64::NAN,
                    drag: f64::NAN,
                    motors: f64::NAN,
                };
                (tr("readout-press-play"), energy, nothing, f64::NAN)
            }
        };
    // The heading and, beside it on its line, what the values are of (before Play, at
    // an instant, after a failure): a line of the same height in every state.
    ui.horizontal(|ui| {
        let heading = ui.add(
            egui::Label::new(egui::RichText::new(tr("readout-heading")).heading())
                .sense(egui::Sense::focusable_noninteractive()),
        );
        crate::landmarks::mark(ui, crate::landmarks::Region::Graphs, heading.id);
        ui.add(egui::Label::new(egui::RichText::new(status).weak()).truncate());
    });
    let residual_joules = energy.total + ledger.total() - start;
    table(ui, &energy, ledger, (start, residual_joules), shown);
    energy_bars(ui, &books(&energy, ledger, residual_joules, start, shown));
}

/// The potentials' rows, in the table's order (height, springs, gravitation,
/// electrostatics, and the forces of one's own where the scene has one with a
/// potential), each with its name in the app's language.
fn potentials(values: [f64; 4], own: Option<f64>) -> Vec<(String, f64)> {
    [
        "readout-potential-field",
        "readout-potential-springs",
        "readout-potential-gravitation",
        "readout-potential-electrostatic",
    ]
    .into_iter()
    .zip(values)
    .map(|(id, value)| (tr(id), value))
    .chain(own.map(|value| (tr("readout-potential-own"), value)))
    .collect()
}

/// The readouts' table: a dash for a value not known yet (before Play).
fn table(
    ui: &mut Ui,
    energy: &Energies,
    ledger: physics::Ledger,
    (start, residual_joules): (f64, f64),
    shown: Rows,
) {
    let number = |value: f64| {
        if value.is_nan() {
            "—".to_owned()
        } else {
            format::number(value)
        }
    };
    let residual = if residual_joules.is_nan() {
        "—".to_owned()
    } else if start == 0.0 {
        format::with_unit(residual_joules, "J")
    } else {
        format!(
            "{} %",
            format::number(100.0 * residual_joules / start.abs())
        )
    };
    egui::Grid::new("readouts")
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            let mut rows = vec![(tr("readout-kinetic"), number(energy.kinetic))];
            rows.extend(
                energy
                    .potential
                    .iter()
                    .map(|(name, value)| (name.clone(), number(*value))),
            );
            rows.push((tr("readout-total"), number(energy.total)));
            rows.push((tr("readout-total-at-play"), number(start)));
            rows.push((tr("readout-damping"), number(ledger.damping)));
            rows.push((tr("readout-friction"), number(ledger.friction)));
            rows.push((tr("readout-impacts"), number(ledger.impacts)));
            if shown.drag {
                rows.push((tr("readout-drag"), number(ledger.drag)));
            }
            if shown.motors {
                rows.push((tr("readout-motors"), number(ledger.motors)));
            }
            if shown.ties {
                // Listed so that nobody looks for them: constraints do no work.
                rows.push((tr("readout-ties"), "0".to_owned()));
            }
            rows.push((tr("readout-error"), residual));
            let momentum = if energy.momentum[0].is_nan() {
                "—".to_owned()
            } else {
                format::pair(energy.momentum[0], energy.momentum[1])
            };
            rows.push((tr("readout-momentum"), momentum));
            for (name, value) in rows {
                ui.label(name);
                ui.monospace(value);
                ui.end_row();
            }
        });
}

/// The bars of the energy books: kinetic, each potential of the table, what dissipation
/// took, the numerical error and the energy at Play, joules; the same bars before Play
/// and through the run (a value not known yet, or 0, has no bar but its name).
fn books(
    energy: &Energies,
    ledger: physics::Ledger,
    residual: f64,
    start: f64,
    shown: Rows,
) -> Vec<(String, f64, egui::Color32)> {
    let mut bars = vec![(tr("bar-kinetic"), energy.kinetic, KINETIC)];
    bars.extend(
        energy
            .potential
            .iter()
            .enumerate()
            // After a failure the recording has the potentials' sum alone: its bar stays.
            .filter(|&(k, _)| {
                energy.potential.len() == 1 || shown.potentials.get(k).copied().unwrap_or(true)
            })
            .map(|(_, (name, value))| {
                let name = name.trim_end_matches(" (J)");
                let name = name.split_once(": ").map_or(name, |(_, kind)| kind);
                (name.to_owned(), *value, POTENTIAL)
            }),
    );
    bars.extend([
        (tr("bar-damping"), ledger.damping, DISSIPATED),
        (tr("bar-friction"), ledger.friction, DISSIPATED),
        (tr("bar-impacts"), ledger.impacts, DISSIPATED),
    ]);
    if shown.drag {
        bars.push((tr("bar-drag"), ledger.drag, DISSIPATED));
    }
    if shown.motors {
        bars.push((tr("bar-motors"), ledger.motors, GIVEN));
    }
    bars.extend([
        (tr("readout-error"), residual, ERROR_BAR),
        (tr("bar-total-at-play"), start, TOTAL),
    ]);
    bars
}

const KINETIC: egui::Color32 = egui::Color32::from_rgb(60, 140, 70);
const POTENTIAL: egui::Color32 = egui::Color32::from_rgb(60, 100, 190);
const DISSIPATED: egui::Color32 = egui::Color32::from_rgb(200, 110, 40);
/// What motors gave: energy coming in, beside the energy at Play.
const GIVEN: egui::Color32 = egui::Color32::from_rgb(130, 80, 170);
const ERROR_BAR: egui::Color32 = egui::Color32::from_rgb(190, 50, 50);
const TOTAL: egui::Color32 = egui::Color32::from_rgb(90, 90, 90);

/// The energy books as bars, like `PhET`'s energy charts: each kind's joules to one scale
/// (the largest of them), from a zero line in the middle, so a negative potential
/// extends left; kinetic green, potential blue, what dissipation took orange, the
/// numerical error red, the energy at Play grey. The numbers are in the table above.
fn energy_bars(ui: &mut Ui, bars: &[(String, f64, egui::Color32)]) {
    let scale = bars
        .iter()
        .map(|(_, value, _)| value.abs())
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    ui.label(egui::RichText::new(tr("bars-title")).strong())
        .on_hover_text(tr("bars-hint"));
    let width = ui.available_width().min(320.0);
    for (name, value, colour) in bars {
        let (name, value, colour) = (name.as_str(), *value, *colour);
        let (rect, response) =
            ui.allocate_exact_size(egui::vec2(width, 14.0), egui::Sense::hover());
        let painter = ui.painter_at(rect);
        let label_width = 110.0;
        painter.text(
            rect.left_center(),
            egui::Align2::LEFT_CENTER,
            name,
            egui::FontId::proportional(11.0),
            ui.visuals().text_color(),
        );
        let track = egui::Rect::from_min_max(
            egui::pos2(rect.left() + label_width, rect.top() + 2.0),
            egui::pos2(rect.right(), rect.bottom() - 2.0),
        );
        let zero = track.center().x;
        painter.line_segment(
            [
                egui::pos2(zero, track.top()),
                egui::pos2(zero, track.bottom()),
            ],
            egui::Stroke::new(1.0, egui::Color32::from_gray(150)),
        );
        if scale > 0.0 && value.is_finite() {
            #[expect(clippy::cast_possible_truncation, reason = "a length on screen")]
            let length = (value / scale) as f32 * track.width() / 2.0;
            let bar = egui::Rect::from_x_y_ranges(
                zero.min(zero + length)..=zero.max(zero + length),
                track.y_range(),
            );
            painter.rect_filled(bar, 1.0, colour);
        }
        if value.is_nan() {
            response.on_hover_text(format!("{name}: —"));
        } else {
            response.on_hover_text(format!("{name}: {} J", format::number(value)));
        }
    }
}

struct Energies {
    kinetic: f64,
    /// Each kind's name (in the app's language, with its unit) and joules.
    potential: Vec<(String, f64)>,
    total: f64,
    momentum: [f64; 2],
}
