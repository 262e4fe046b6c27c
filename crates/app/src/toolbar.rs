//! The tool bar: editing tools, run controls (Play/Pause, Step, Reset, time scale,
//! integrator, time step) and what the canvas shows.

use egui::Ui;
use physics::{Integrator, Rule, check_value};

use crate::canvas::{Canvas, Tool};

/// What the user asked for in the tool bar this frame.
#[derive(Clone, Copy, Debug, Default)]
#[expect(
    clippy::struct_excessive_bools,
    reason = "independent buttons, each pressed or not"
)]
pub struct Requests {
    pub play_pause: bool,
    pub step: bool,
    pub reset: bool,
    pub fit: bool,
    pub integrator: Option<Integrator>,
    pub time_step: Option<f64>,
}

pub struct State<'a> {
    pub canvas: &'a mut Canvas,
    pub playing: bool,
    pub editable: bool,
    pub time_scale: &'a mut f64,
    pub integrator: Integrator,
    pub time_step: f64,
}

#[expect(
    clippy::too_many_lines,
    reason = "one row of controls, laid out in order"
)]
pub fn ui(ui: &mut Ui, state: &mut State<'_>) -> Requests {
    let mut requests = Requests::default();
    ui.horizontal_wrapped(|ui| {
        ui.add_enabled_ui(state.editable, |ui| {
            for tool in Tool::ALL {
                ui.selectable_value(&mut state.canvas.tool, tool, tool.label())
                    .on_hover_text(tool.hint());
            }
        });
        ui.separator();
        let play = if state.playing { "Pause" } else { "Play" };
        if ui
            .button(play)
            .on_hover_text("Run or pause the simulation (Space)")
            .clicked()
        {
            requests.play_pause = true;
        }
        if ui
            .button("Step")
            .on_hover_text("Advance by one time step (.)")
            .clicked()
        {
            requests.step = true;
        }
        if ui
            .button("Reset")
            .on_hover_text("Back to the scene as last edited (R)")
            .clicked()
        {
            requests.reset = true;
        }
        ui.add(
            egui::Slider::new(state.time_scale, 0.01..=100.0)
                .logarithmic(true)
                .text("× speed"),
        )
        .on_hover_text("Time scale: simulated seconds per real second (0.01× to 100×)");
        ui.separator();
        ui.add_enabled_ui(state.editable, |ui| {
            let label = ui.label("integrator");
            egui::ComboBox::from_id_salt("toolbar-integrator")
                .selected_text(state.integrator.as_str())
                .show_ui(ui, |ui| {
                    for method in Integrator::ALL {
                        if ui
                            .selectable_label(state.integrator == method, method.as_str())
                            .on_hover_text(method.describe())
                            .clicked()
                        {
                            requests.integrator = Some(method);
                        }
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text("How the motion is integrated in time");
            let id = egui::Id::unique("toolbar-time-step");
            let mut text: String = ui
                .data(|d| d.get_temp(id))
                .unwrap_or_else(|| state.time_step.to_string());
            let label = ui.label("dt");
            let response = ui
                .add(egui::TextEdit::singleline(&mut text).desired_width(70.0))
                .labelled_by(label.id)
                .on_hover_text("Time step, seconds (dopri5: the largest step)");
            ui.label("s");
            let parsed = text
                .trim()
                .parse::<f64>()
                .map_err(|_| "not a number".to_owned())
                .and_then(|v| check_value(Rule::Positive, "time step", v).map(|()| v));
            if response.has_focus() || parsed.is_err() {
                ui.data_mut(|d| d.insert_temp(id, text.clone()));
            } else {
                ui.data_mut(|d| d.remove::<String>(id));
            }
            match parsed {
                Ok(v) if response.lost_focus() && v.to_bits() != state.time_step.to_bits() => {
                    requests.time_step = Some(v);
                }
                Err(reason) => {
                    ui.colored_label(egui::Color32::from_rgb(200, 30, 30), reason.clone());
                }
                _ => {}
            }
        });
        ui.separator();
        let overlays = &mut state.canvas.overlays;
        ui.toggle_value(&mut overlays.velocity, "velocity")
            .on_hover_text("Velocity arrows (tip: where the particle will be in 0.5 s)");
        ui.toggle_value(&mut overlays.acceleration, "acceleration")
            .on_hover_text("Acceleration arrows");
        ui.toggle_value(&mut overlays.force, "force")
            .on_hover_text("Net force arrows (length grows with the logarithm of the force)");
        ui.toggle_value(&mut overlays.trails, "trails")
            .on_hover_text("Recent paths of the particles");
        ui.toggle_value(&mut overlays.names, "names")
            .on_hover_text("Object names");
        if ui
            .button("Fit")
            .on_hover_text("Fit the whole scene in view (F)")
            .clicked()
        {
            requests.fit = true;
        }
    });
    requests
}
