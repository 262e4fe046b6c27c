//! The energy readouts above the graphs: energies by kind, what damping, friction,
//! drag and impacts took since Play (rods and strings take nothing: a constraint does no
//! work), the numerical error (what the books leave unaccounted) and the total momentum,
//! as a table and as bars.

use egui::Ui;
use physics::Total;

use crate::format;
use crate::i18n::tr;
use crate::run_loop::Runner;

/// Energies by kind, the energy ledger, momentum: live while running, the last recorded
/// values after a failure.
pub(crate) fn ui(ui: &mut Ui, runner: &Runner) {
    let heading = ui.add(
        egui::Label::new(egui::RichText::new(tr("readout-heading")).heading())
            .sense(egui::Sense::focusable_noninteractive()),
    );
    crate::landmarks::mark(ui, crate::landmarks::Region::Graphs, heading.id);
    let energy = match (runner.simulation(), &runner.failure, &runner.recording) {
        (Some(_), Some(_), Some(recording)) => {
            ui.label(tr("readout-failed"));
            let get = |t| recording.last_total(t).unwrap_or(f64::NAN);
            Energies {
                kinetic: get(Total::KineticEnergy),
                potential: vec![(tr("readout-potential"), get(Total::PotentialEnergy))],
                total: get(Total::TotalEnergy),
                momentum: [get(Total::MomentumX), get(Total::MomentumY)],
            }
        }
        (Some(_), _, _) => {
            let d = runner.diagnostics().unwrap_or_default();
            let mut potential = vec![
                (tr("readout-potential-field"), d.energy.uniform),
                (tr("readout-potential-springs"), d.energy.spring),
                (tr("readout-potential-gravitation"), d.energy.gravitation),
                (
                    tr("readout-potential-electrostatic"),
                    d.energy.electrostatic,
                ),
            ];
            if runner
                .simulation()
                .is_some_and(physics::Simulation::has_own_potential)
            {
                potential.push((tr("readout-potential-own"), d.energy.own));
            }
            Energies {
                kinetic: d.energy.kinetic,
                potential,
                total: d.energy.total(),
                momentum: [d.momentum.x, d.momentum.y],
            }
        }
        (None, _, _) => {
            ui.label(tr("readout-press-play"));
            return;
        }
    };
    let start = runner.start_energy;
    // The books: what damping, friction and impacts took since Play, and what is left
    // unaccounted, the numerical error (the integrator's, and the position correction
    // of piles), as a share of the energy at Play (in joules when that was 0).
    let ledger = runner
        .simulation()
        .and_then(physics::Simulation::ledger)
        .unwrap_or_default();
    let residual_joules = energy.total + ledger.total() - start;
    let residual = if start == 0.0 {
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
            let mut rows = vec![(tr("readout-kinetic"), format::number(energy.kinetic))];
            rows.extend(
                energy
                    .potential
                    .iter()
                    .map(|(name, value)| (name.clone(), format::number(*value))),
            );
            rows.push((tr("readout-total"), format::number(energy.total)));
            rows.push((tr("readout-total-at-play"), format::number(start)));
            rows.push((tr("readout-damping"), format::number(ledger.damping)));
            rows.push((tr("readout-friction"), format::number(ledger.friction)));
            rows.push((tr("readout-impacts"), format::number(ledger.impacts)));
            if ledger.drag != 0.0 {
                rows.push((tr("readout-drag"), format::number(ledger.drag)));
            }
            if ledger.motors != 0.0 {
                rows.push((tr("readout-motors"), format::number(ledger.motors)));
            }
            if runner
                .simulation()
                .is_some_and(|s| !s.tie_names().is_empty())
            {
                // Listed so that nobody looks for them: constraints do no work.
                rows.push((tr("readout-ties"), "0".to_owned()));
            }
            rows.push((tr("readout-error"), residual));
            rows.push((
                tr("readout-momentum"),
                format::pair(energy.momentum[0], energy.momentum[1]),
            ));
            for (name, value) in rows {
                ui.label(name);
                ui.monospace(value);
                ui.end_row();
            }
        });
    energy_bars(ui, &books(&energy, ledger, residual_joules, start));
}

/// The bars of the energy books: kinetic, each potential there is, what dissipation
/// took, the numerical error and the energy at Play, joules.
fn books(
    energy: &Energies,
    ledger: physics::Ledger,
    residual: f64,
    start: f64,
) -> Vec<(String, f64, egui::Color32)> {
    let mut bars = vec![(tr("bar-kinetic"), energy.kinetic, KINETIC)];
    bars.extend(
        energy
            .potential
            .iter()
            .filter(|(_, value)| *value != 0.0)
            .map(|(name, value)| {
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
    if ledger.drag != 0.0 {
        bars.push((tr("bar-drag"), ledger.drag, DISSIPATED));
    }
    if ledger.motors != 0.0 {
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
        response.on_hover_text(format!("{name}: {} J", format::number(value)));
    }
}

struct Energies {
    kinetic: f64,
    /// Each kind's name (in the app's language, with its unit) and joules.
    potential: Vec<(String, f64)>,
    total: f64,
    momentum: [f64; 2],
}
