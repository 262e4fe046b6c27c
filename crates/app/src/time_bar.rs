//! The time machine's bar under the canvas, and the stopwatch's window.

use crate::App;
use crate::action::Action;
use crate::edit::Edit;
use crate::i18n::{Arg, tr, tr_with};
use crate::recording::Recording;
use crate::{canvas, format, stopwatch};
use egui::Ui;

impl App {
    /// The time machine's bar while a run exists: a slider over every step of the run,
    /// Step back, and, at a moment gone back to, the way back to the end and Edit from
    /// here.
    pub(crate) fn timeline_bar(&mut self, ui: &mut Ui) -> Option<Action> {
        let mut action = None;
        let Some(timeline) = &self.runner.timeline else {
            return None;
        };
        let (end, shown) = (timeline.end, timeline.shown);
        let step = self
            .runner
            .simulation()
            .map_or(0.0, physics::Simulation::time_step);
        ui.horizontal(|ui| {
            let back = ui
                .add_enabled(
                    shown.unwrap_or(end) > 0,
                    egui::Button::new(tr("timeline-step-back")),
                )
                .on_hover_text(tr("timeline-step-back-hint"));
            if back.clicked() {
                action = Some(Action::StepBack);
            }
            let mut at = shown.unwrap_or(end);
            ui.spacing_mut().slider_width = (ui.available_width() - 420.0).max(120.0);
            let slider = ui
                .add(egui::Slider::new(&mut at, 0..=end.max(1)).show_value(false))
                .on_hover_text(tr("timeline-slider-hint"));
            if slider.changed() {
                action = Some(Action::GoTo(at));
            }
            let start = self.document.scene().simulation.start_time;
            #[expect(clippy::cast_precision_loss, reason = "a count of steps")]
            let (now, last) = (start + at as f64 * step, start + end as f64 * step);
            ui.label(tr_with(
                "timeline-time",
                &[
                    ("now", Arg::Text(&format::number(now))),
                    ("last", Arg::Text(&format::number(last))),
                ],
            ));
            if shown.is_some() {
                if ui
                    .button(tr("timeline-to-end"))
                    .on_hover_text(tr("timeline-to-end-hint"))
                    .clicked()
                {
                    action = Some(Action::GoTo(end));
                }
                if ui
                    .button(tr("timeline-edit-from-here"))
                    .on_hover_text(tr("timeline-edit-from-here-hint"))
                    .clicked()
                {
                    action = Some(Action::EditFromHere);
                }
            }
        });
        action
    }

    /// Turns the moment shown into the scene's initial conditions (undoable).
    pub(crate) fn edit_from_here(&mut self) {
        let Some(simulation) = self.runner.simulation() else {
            return;
        };
        let saved = simulation.saved_state(self.document.scene());
        self.runner.reset();
        self.document
            .apply(Edit::EditFromHere, |scene| *scene = saved);
        self.selection = None;
    }

    /// Lets the stopwatch see the run's events since the last frame.
    pub(crate) fn time_stopwatch(&mut self) {
        let Some(simulation) = self.runner.simulation() else {
            self.stopwatch.forget_run();
            return;
        };
        let positions = simulation.positions();
        let gate = self
            .canvas
            .instruments
            .tape
            .and_then(|tape| canvas::tape_ends(tape, positions));
        let impacts = self
            .runner
            .recording
            .as_ref()
            .map_or(&[][..], Recording::impacts);
        self.stopwatch
            .update(simulation.time(), positions, impacts, gate);
    }

    /// The stopwatch's window, when shown: the reading, Start/Stop and Reset, and what
    /// starts and stops it.
    pub(crate) fn stopwatch_window(&mut self, ui: &Ui) {
        use stopwatch::{State, Trigger};
        let mut shown = self.stopwatch.shown;
        let now = self.time();
        egui::Window::new(tr("stopwatch-title"))
            .open(&mut shown)
            .resizable(false)
            .default_pos(self.canvas.rect.right_top() + egui::vec2(-240.0, 12.0))
            .show(ui.ctx(), |ui| {
                let watch = &mut self.stopwatch;
                ui.label(
                    egui::RichText::new(format!("{:.4} s", watch.reading))
                        .monospace()
                        .size(22.0),
                );
                ui.label(tr(match watch.state {
                    State::Stopped => "stopwatch-stopped",
                    State::Armed => "stopwatch-armed",
                    State::Running(_) => "stopwatch-running",
                }));
                ui.horizontal(|ui| {
                    let running = matches!(watch.state, State::Running(_) | State::Armed);
                    let label = tr(if running {
                        "stopwatch-stop"
                    } else {
                        "stopwatch-start"
                    });
                    if ui.button(label).clicked() {
                        if running {
                            watch.stop(now);
                        } else {
                            watch.start(now);
                        }
                    }
                    if ui.button(tr("stopwatch-reset")).clicked() {
                        watch.reset();
                    }
                });
                for (salt, trigger) in [
                    ("stopwatch-start-on", &mut watch.start_on),
                    ("stopwatch-stop-on", &mut watch.stop_on),
                ] {
                    ui.horizontal(|ui| {
                        let text = ui.label(tr(salt));
                        egui::ComboBox::from_id_salt(salt)
                            .selected_text(trigger.label())
                            .show_ui(ui, |ui| {
                                for choice in Trigger::ALL {
                                    ui.selectable_value(trigger, choice, choice.label());
                                }
                            })
                            .response
                            .labelled_by(text.id);
                    });
                }
                ui.label(egui::RichText::new(tr("stopwatch-note")).small());
            });
        self.stopwatch.shown = shown;
    }
}
