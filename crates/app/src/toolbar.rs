//! The tool bar: editing tools, run controls (Play/Pause, Step, Reset, time scale,
//! integrator, time step) and what the canvas shows.

use egui::Ui;
use physics::{Follow, Integrator, Rule, check_value};

use crate::action::Action;
use crate::canvas::{Canvas, Instrument, Tool};
use crate::document::Document;
use crate::edit::Edit;
use crate::i18n::tr;
use crate::run_loop::Runner;

/// The tool bar, one frame. The integrator, the time step and the time scale are the
/// scene's and change as undoable edits; everything else is an [`Action`].
#[expect(
    clippy::too_many_lines,
    reason = "one row of controls, laid out in order"
)]
pub fn ui(
    ui: &mut Ui,
    canvas: &mut Canvas,
    document: &mut Document,
    runner: &Runner,
    compact: bool,
) -> Option<Action> {
    let mut action = None;
    let editable = runner.is_editing();
    let settings = document.scene().simulation.clone();
    ui.horizontal_wrapped(|ui| {
        // Projector mode keeps the run controls only: the tools, the method and the
        // overlays are for preparing a lesson, not for showing it.
        let measuring = canvas.instruments.active;
        // In projector mode no empty group or separator is left behind: each drew a
        // stray mark beside Play and set Fit below the row.
        if !compact {
            ui.add_enabled_ui(editable, |ui| {
                for tool in Tool::ALL {
                    if ui
                        .selectable_label(canvas.tool == tool && measuring.is_none(), tool.label())
                        .on_hover_text(tool.hint())
                        .clicked()
                    {
                        action = Some(Action::Tool(tool));
                    }
                }
            });
            ui.separator();
        }
        // One width for the three, the widest label's in this language: the row does not
        // re-wrap when Play becomes Pause.
        let labels = [
            "toolbar-play",
            "toolbar-pause",
            "toolbar-step",
            "toolbar-reset",
        ]
        .map(tr);
        let width = labels
            .iter()
            .map(|label| {
                egui::WidgetText::from(label.as_str())
                    .into_galley(ui, None, f32::INFINITY, egui::TextStyle::Button)
                    .size()
                    .x
            })
            .fold(40.0, f32::max)
            + 12.0;
        let [play, pause, step, reset] = labels;
        let play = if runner.playing { pause } else { play };
        for (label, hint, pressed) in [
            (play, tr("toolbar-play-hint"), Action::PlayPause),
            (step, tr("toolbar-step-hint"), Action::Step),
            (reset, tr("toolbar-reset-hint"), Action::Reset),
        ] {
            let button = ui
                .add_sized([width, 20.0], egui::Button::new(label))
                .on_hover_text(hint);
            if pressed == Action::PlayPause {
                crate::landmarks::mark(ui, crate::landmarks::Region::Toolbar, button.id);
            }
            if button.clicked() {
                action = Some(pressed);
            }
        }
        let mut time_scale = settings.time_scale;
        ui.spacing_mut().slider_width = 70.0;
        let slider = ui
            .add(
                egui::Slider::new(&mut time_scale, 0.01..=100.0)
                    .logarithmic(true)
                    .custom_formatter(|v, _| crate::format::number(v))
                    .custom_parser(|s| crate::format::typed(s).trim().parse().ok())
                    .text("×"),
            )
            .on_hover_text(tr("toolbar-time-scale-hint"));
        if slider.drag_started() {
            document.begin_gesture(Edit::SetTimeScale);
        }
        if slider.changed() && time_scale.to_bits() != settings.time_scale.to_bits() {
            document.apply(Edit::SetTimeScale, |scene| {
                scene.simulation.time_scale = time_scale;
            });
        }
        if slider.drag_stopped() {
            document.end_gesture();
        }
        ui.separator();
        if !compact {
            ui.add_enabled_ui(editable, |ui| {
                let label = ui.label(tr("field-simulation-integrator"));
                egui::ComboBox::from_id_salt("toolbar integrator")
                    .selected_text(settings.integrator.as_str())
                    .show_ui(ui, |ui| {
                        for method in Integrator::ALL {
                            if ui
                                .selectable_label(settings.integrator == method, method.as_str())
                                .on_hover_text(method.describe())
                                .clicked()
                            {
                                document.apply(Edit::SetIntegrator, |scene| {
                                    scene.simulation.integrator = method;
                                });
                            }
                        }
                    })
                    .response
                    .labelled_by(label.id)
                    .on_hover_text(tr("toolbar-integrator-hint"));
                // The step, its field and its unit wrap as one.
                ui.horizontal(|ui| {
                    let id = egui::Id::unique("toolbar time step");
                    let mut text: String = ui
                        .data(|d| d.get_temp(id))
                        .unwrap_or_else(|| crate::format::field(settings.time_step));
                    let label = ui.label("dt");
                    let response = ui
                        .add(egui::TextEdit::singleline(&mut text).desired_width(70.0))
                        .labelled_by(label.id)
                        .on_hover_text(tr("toolbar-time-step-hint"));
                    ui.label("s");
                    let parsed =
                        crate::units::parse(&crate::format::typed(&text), "s").and_then(|v| {
                            check_value(Rule::Positive, &tr("field-simulation-time-step"), v)
                                .map(|()| v)
                        });
                    if response.has_focus() || parsed.is_err() {
                        ui.data_mut(|d| d.insert_temp(id, text.clone()));
                    } else {
                        ui.data_mut(|d| d.remove::<String>(id));
                    }
                    match parsed {
                        Ok(v)
                            if response.lost_focus()
                                && v.to_bits() != settings.time_step.to_bits() =>
                        {
                            document
                                .apply(Edit::SetTimeStep, |scene| scene.simulation.time_step = v);
                        }
                        Err(reason) => {
                            ui.colored_label(egui::Color32::from_rgb(200, 30, 30), reason.clone());
                        }
                        _ => {}
                    }
                });
            });
            ui.separator();
        }
        let overlays = &mut canvas.overlays;
        if !compact {
            overlays_ui(ui, overlays);
            // The instruments are tools too (usable while a run plays): one of them or
            // one editing tool is chosen, and the bar shows which.
            ui.separator();
            for instrument in [Instrument::Tape, Instrument::Protractor, Instrument::Probe] {
                if ui
                    .selectable_label(measuring == Some(instrument), instrument.label())
                    .on_hover_text(instrument.hint())
                    .clicked()
                {
                    action = Some(Action::Instrument(instrument));
                }
            }
            ui.separator();
        }
        if ui
            .button(tr("menu-fit"))
            .on_hover_text(tr("toolbar-fit-hint"))
            .clicked()
        {
            action = Some(Action::Fit);
        }
    });
    action
}

/// The toggles for what the canvas draws.
fn overlays_ui(ui: &mut Ui, overlays: &mut crate::canvas::Overlays) {
    for (on, id) in [
        (&mut overlays.velocity, "toolbar-velocity"),
        (&mut overlays.acceleration, "toolbar-acceleration"),
        (&mut overlays.force, "toolbar-force"),
        (&mut overlays.trails, "toolbar-trails"),
        (&mut overlays.names, "toolbar-names"),
    ] {
        ui.toggle_value(on, tr(id))
            .on_hover_text(tr(&format!("{id}-hint")));
    }
}

/// What the camera follows while playing (View → Follow): nothing, every particle, or
/// one particle.
pub fn follow_menu(ui: &mut Ui, canvas: &mut Canvas, document: &Document) {
    ui.selectable_value(&mut canvas.follow, None, tr("follow-nothing"))
        .on_hover_text(tr("follow-nothing-hint"));
    ui.selectable_value(&mut canvas.follow, Some(Follow::All), tr("follow-all"))
        .on_hover_text(tr("follow-all-hint"));
    egui::ScrollArea::vertical()
        .max_height(300.0)
        .show(ui, |ui| {
            for particle in &document.scene().particles {
                let target = Some(Follow::Particle(particle.name.clone()));
                ui.selectable_value(&mut canvas.follow, target, &particle.name)
                    .on_hover_text(tr("follow-particle-hint"));
            }
        });
}
