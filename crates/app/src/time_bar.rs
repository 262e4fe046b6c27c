//! The time machine's bar under the canvas, and the stopwatch's window.

use crate::App;
use crate::action::Action;
use crate::edit::Edit;
use crate::i18n::{Arg, tr, tr_with};
use crate::recording::Recording;
use crate::watching::Watching;
use crate::{canvas, format, stopwatch};
use egui::Ui;

impl App {
    /// The time machine's bar: a slider over every step of the run, Step back, and, at a
    /// moment gone back to, the way back to the end and Edit from here. Before a run it
    /// is there, greyed out, so that Play does not shrink the canvas (which would rescale
    /// the view to keep all it showed).
    pub(crate) fn timeline_bar(&mut self, ui: &mut Ui) -> Option<Action> {
        let Some(timeline) = &self.runner.timeline else {
            ui.add_enabled_ui(false, |ui| self.bar(ui, 0, None))
                .response
                .on_disabled_hover_text(tr("timeline-before-play"));
            return None;
        };
        let (end, shown) = (timeline.end, timeline.shown);
        self.bar(ui, end, shown)
    }

    /// [`Self::timeline_bar`] over a run of `end` steps, showing step `shown` (`None`:
    /// the end).
    fn bar(&mut self, ui: &mut Ui, end: u64, shown: Option<u64>) -> Option<Action> {
        let mut action = None;
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
            if ui.is_enabled() {
                crate::landmarks::mark(ui, crate::landmarks::Region::TimeBar, back.id);
            }
            let mut at = shown.unwrap_or(end);
            ui.spacing_mut().slider_width = (ui.available_width() - 300.0).max(120.0);
            let slider = ui
                .add(egui::Slider::new(&mut at, 0..=end.max(1)).show_value(false))
                .on_hover_text(tr("timeline-slider-hint"));
            if slider.changed() {
                action = Some(Action::GoTo(at));
            }
            let start = self.document.scene().simulation.start_time;
            #[expect(clippy::cast_precision_loss, reason = "a count of steps")]
            let (now, last) = (start + at as f64 * step, start + end as f64 * step);
            // The instant shown exactly (an event's, between steps), else the step's.
            let now = self
                .runner
                .simulation()
                .map_or(now, physics::Simulation::time);
            ui.label(tr_with(
                "timeline-time",
                &[
                    ("now", Arg::Text(&format::number(now))),
                    ("last", Arg::Text(&format::number(last))),
                ],
            ));
        });
        action.or_else(|| self.jumps_row(ui, shown.map(|_| end)))
    }

    /// The jumps to turning points and impacts, a typed instant, and at a moment gone
    /// back to (`gone_back`: the run's end) the way back to the end and Edit from here: the
    /// time bar's second row.
    fn jumps_row(&mut self, ui: &mut Ui, gone_back: Option<u64>) -> Option<Action> {
        let mut action = None;
        ui.horizontal(|ui| {
            for (label, hint, jump) in [
                (
                    "timeline-previous-turn",
                    "timeline-turn-hint",
                    Action::TurningPoint(false),
                ),
                (
                    "timeline-next-turn",
                    "timeline-turn-hint",
                    Action::TurningPoint(true),
                ),
                (
                    "timeline-previous-impact",
                    "timeline-impact-hint",
                    Action::Impact(false),
                ),
                (
                    "timeline-next-impact",
                    "timeline-impact-hint",
                    Action::Impact(true),
                ),
            ] {
                if ui.small_button(tr(label)).on_hover_text(tr(hint)).clicked() {
                    action = Some(jump);
                }
            }
            self.time_field(ui);
            if let Some(end) = gone_back {
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

    /// A field to type an instant of the run into (`1.5`, `1500 ms`); Enter goes there.
    fn time_field(&mut self, ui: &mut Ui) {
        let id = egui::Id::unique("timeline go to");
        let mut text: String = ui.data(|d| d.get_temp(id)).unwrap_or_default();
        let label = ui.label(tr("timeline-go-to"));
        let response = ui
            .add(egui::TextEdit::singleline(&mut text).desired_width(64.0))
            .labelled_by(label.id)
            .on_hover_text(tr("timeline-go-to-hint"));
        ui.data_mut(|d| d.insert_temp(id, text.clone()));
        if response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
            match crate::units::parse(&crate::format::typed(&text), "s") {
                Ok(time) => {
                    self.runner.go_to_time(time);
                    ui.data_mut(|d| d.remove::<String>(id));
                }
                Err(reason) => self.notify(reason),
            }
        }
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

    /// Gives the run what the stopwatch waits for, before the frame's physics: the typed
    /// event and the light gate (the tape's segment where it is now), watched inside
    /// every step from here on.
    pub(crate) fn watch_for_stopwatch(&mut self) {
        let Some(simulation) = self.runner.simulation() else {
            return;
        };
        let gate = self
            .canvas
            .instruments
            .tape
            .and_then(|tape| canvas::tape_ends(tape, simulation.positions()));
        let wanted = self.stopwatch.wanted(gate);
        if wanted.is_empty() {
            self.runner.watching = None;
            self.stopwatch.problem = None;
            return;
        }
        if self.runner.watching.as_ref().map(|w| &w.wanted) == Some(&wanted) {
            return;
        }
        match Watching::new(wanted, simulation) {
            Ok(watching) => {
                self.runner.watching = Some(watching);
                self.stopwatch.problem = None;
            }
            Err(problem) => {
                self.runner.watching = None;
                self.stopwatch.problem = Some(problem);
            }
        }
    }

    /// Lets the stopwatch see the run's events since the last frame.
    pub(crate) fn time_stopwatch(&mut self) {
        let Some(simulation) = self.runner.simulation() else {
            self.stopwatch.forget_run();
            return;
        };
        let now = simulation.time();
        let cues = self
            .runner
            .watching
            .as_mut()
            .map(Watching::take)
            .unwrap_or_default();
        let impacts = self
            .runner
            .recording
            .as_ref()
            .map_or(&[][..], Recording::impacts);
        self.stopwatch.update(now, impacts, &cues);
    }

    /// The stopwatch's window, when shown: the reading (and the laps), Start/Stop and
    /// Reset, what starts and stops it and which occurrence, the event it waits for, and
    /// lap mode. At the canvas's lower left, clear of the readouts.
    pub(crate) fn stopwatch_window(&mut self, ui: &Ui) {
        use stopwatch::State;
        let mut shown = self.stopwatch.shown;
        let now = self.time();
        let mut asked = None;
        egui::Window::new(tr("stopwatch-title"))
            .open(&mut shown)
            .resizable(false)
            .default_pos(self.canvas.rect.left_bottom() + egui::vec2(12.0, -260.0))
            .show(ui.ctx(), |ui| {
                let watch = &mut self.stopwatch;
                // Shown to the microsecond a located event means; the full value is a
                // hover or a click (to the clipboard) away.
                let full = format!("{} s", watch.reading);
                let reading = ui
                    .add(
                        egui::Label::new(
                            egui::RichText::new(format!("{} s", format::fixed(watch.reading, 6)))
                                .monospace()
                                .size(22.0),
                        )
                        .sense(egui::Sense::click()),
                    )
                    .on_hover_text(tr_with("reading-full", &[("value", Arg::Text(&full))]));
                if reading.clicked() {
                    ui.ctx().copy_text(full.clone());
                    self.announcer.text = tr_with("reading-copied", &[("value", Arg::Text(&full))]);
                }
                ui.label(tr(match watch.state {
                    State::Stopped => "stopwatch-stopped",
                    State::Armed => "stopwatch-armed",
                    State::Running(_) => "stopwatch-running",
                }));
                // A typed event that cannot be watched is said at once, and the watch
                // does not start on it (it would run on past the event it never sees).
                let problem = watch.event_problem(self.document.scene());
                ui.horizontal(|ui| {
                    let running = matches!(watch.state, State::Running(_) | State::Armed);
                    let label = tr(if running {
                        "stopwatch-stop"
                    } else {
                        "stopwatch-start"
                    });
                    let can = running || problem.is_none();
                    if ui.add_enabled(can, egui::Button::new(label)).clicked() {
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
                triggers(ui, watch, problem.as_deref());
                laps(ui, watch);
                // The teacher's view only: the inspector is out.
                if let Some(measure) = self
                    .stopwatch
                    .question(self.document.scene())
                    .filter(|_| self.panels.inspector)
                    && ui
                        .button(tr("stopwatch-ask"))
                        .on_hover_text(tr("stopwatch-ask-hint"))
                        .clicked()
                {
                    asked = Some(measure);
                }
                ui.label(egui::RichText::new(tr("stopwatch-note")).small());
            });
        self.stopwatch.shown = shown;
        if let Some(measure) = asked {
            let event = self.stopwatch.event.trim().to_owned();
            let prompt = tr_with("stopwatch-ask-prompt", &[("event", Arg::Text(&event))]);
            self.ask(prompt, measure, "s", 0.01);
        }
    }

    /// Adds a question to the scene's lesson (a lesson titled as the scene when it has
    /// none), one undoable edit, and shows the lesson: the teacher's "ask about this".
    /// Its answer key is the measure, as every question's is.
    pub(crate) fn ask(&mut self, prompt: String, measure: String, unit: &str, tolerance: f64) {
        let scene = self.document.scene();
        let lesson = scene.lesson.clone().unwrap_or_else(|| physics::Lesson {
            title: scene.name.clone().unwrap_or_else(|| tr("lesson-untitled")),
            ..physics::Lesson::default()
        });
        let id = (1..=lesson.questions.len() + 1)
            .map(|n| format!("q{n}"))
            .find(|id| lesson.question(id).is_none())
            .unwrap_or_default();
        let question = physics::Question {
            id: id.clone(),
            prompt,
            measure,
            unit: unit.to_owned(),
            tolerance,
            reveal: false,
        };
        self.document.apply(crate::edit::Edit::Ask, |scene| {
            let mut lesson = lesson;
            lesson.questions.push(question);
            scene.lesson = Some(lesson);
        });
        self.panels.lesson = true;
        self.tell(tr_with("stopwatch-asked", &[("id", Arg::Text(&id))]));
    }
}

/// The stopwatch's choices: what starts and stops it, which occurrence, and the event;
/// first, the two settings a lesson most often wants, in one click.
fn triggers(ui: &mut Ui, watch: &mut stopwatch::Stopwatch, problem: Option<&str>) {
    use stopwatch::Trigger;
    ui.horizontal(|ui| {
        if ui
            .small_button(tr("stopwatch-period-at-gate"))
            .on_hover_text(tr("stopwatch-period-at-gate-hint"))
            .clicked()
        {
            watch.period_at_the_gate();
        }
        if ui
            .small_button(tr("stopwatch-between-impacts"))
            .on_hover_text(tr("stopwatch-between-impacts-hint"))
            .clicked()
        {
            watch.between_impacts();
        }
    });
    let rows = [
        (
            "stopwatch-start-on",
            &Trigger::STARTS[..],
            &mut watch.start_on,
            &mut watch.start_nth,
        ),
        (
            "stopwatch-stop-on",
            &Trigger::STOPS[..],
            &mut watch.stop_on,
            &mut watch.stop_nth,
        ),
    ];
    for (salt, choices, trigger, nth) in rows {
        ui.horizontal(|ui| {
            let text = ui.label(tr(salt));
            egui::ComboBox::from_id_salt(salt)
                .selected_text(stopwatch::label(*trigger))
                .show_ui(ui, |ui| {
                    for &choice in choices {
                        ui.selectable_value(trigger, choice, stopwatch::label(choice));
                    }
                })
                .response
                .labelled_by(text.id);
            if trigger.counts() {
                let label = ui.label(tr("stopwatch-nth"));
                ui.add(egui::DragValue::new(nth).range(1..=999).speed(0.1))
                    .labelled_by(label.id)
                    .on_hover_text(tr("stopwatch-nth-hint"));
            }
        });
    }
    if watch.start_on == Trigger::Event || watch.stop_on == Trigger::Event {
        ui.horizontal(|ui| {
            let label = ui.label(tr("stopwatch-event-label"));
            let typed = ui
                .add(
                    egui::TextEdit::singleline(&mut watch.event)
                        .hint_text("rod.angle crosses 0 down")
                        .desired_width(190.0),
                )
                .labelled_by(label.id)
                .on_hover_text(tr("stopwatch-event-hint"));
            if typed.changed() {
                // What the run found wrong was of the text before.
                watch.problem = None;
            }
        });
    }
    if let Some(problem) = problem.or(watch.problem.as_deref()) {
        ui.colored_label(egui::Color32::from_rgb(200, 30, 30), problem);
    }
}

/// Lap mode, and the laps with their mean.
fn laps(ui: &mut Ui, watch: &mut stopwatch::Stopwatch) {
    ui.checkbox(&mut watch.lap_mode, tr("stopwatch-lap-mode"))
        .on_hover_text(tr("stopwatch-lap-mode-hint"));
    if !watch.laps.is_empty() {
        egui::ScrollArea::vertical()
            .max_height(90.0)
            .show(ui, |ui| {
                for (k, lap) in watch.laps.iter().enumerate() {
                    ui.monospace(format!("{:>3}  {} s", k + 1, format::fixed(*lap, 6)));
                }
            });
        if let Some(mean) = watch.mean_lap() {
            ui.monospace(tr_with(
                "stopwatch-mean",
                &[
                    ("mean", Arg::Text(&format::fixed(mean, 6))),
                    ("laps", Arg::Text(&watch.laps.len().to_string())),
                ],
            ));
        }
    }
}
