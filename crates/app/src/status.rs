//! The status line: what the app says to the user, the run's speed and time, and the
//! live region a screen reader hears.

use crate::App;
use crate::action::Action;
use crate::i18n;
use crate::i18n::{Arg, tr, tr_with};
use egui::Ui;

/// How long the status line keeps a notice, seconds.
const NOTICE_SECONDS: f64 = 10.0;

impl App {
    /// Stamps a new notice with the time it is first shown; forgets it once it is old.
    pub(crate) fn age_notice(&mut self, ui: &Ui) {
        let now = ui.input(|i| i.time);
        if let Some((_, since)) = &mut self.notice {
            let shown = *since.get_or_insert(now);
            if now - shown > NOTICE_SECONDS {
                self.notice = None;
            } else {
                ui.ctx()
                    .request_repaint_after(std::time::Duration::from_secs_f64(
                        NOTICE_SECONDS - (now - shown) + 0.1,
                    ));
            }
        }
    }

    pub(crate) fn status(&self, ui: &mut Ui) -> Option<Action> {
        let mut action = None;
        ui.horizontal(|ui| {
            ui.monospace(format!("t = {:.4} s", self.time()));
            ui.separator();
            if let Some((notice, _)) = &self.notice {
                let said = ui.label(egui::RichText::new(notice).strong());
                ui.ctx().accesskit_node_builder(said.id, |node| {
                    node.set_live(egui::accesskit::Live::Polite);
                });
                ui.separator();
            }
            if let Some(failure) = &self.runner.failure {
                if ui
                    .button(tr("failure-reset"))
                    .on_hover_text(tr("toolbar-reset-hint"))
                    .clicked()
                {
                    action = Some(Action::Reset);
                }
                ui.colored_label(
                    egui::Color32::from_rgb(200, 30, 30),
                    tr_with("status-stopped", &[("failure", Arg::Text(failure))]),
                );
                return;
            }
            let time_scale = self.document.scene().simulation.time_scale;
            match (self.runner.playing, self.runner.shortfall(time_scale)) {
                (true, Some(fraction)) => {
                    let (ratio, real) = (
                        i18n::decimal(fraction, 2),
                        i18n::decimal(fraction * time_scale, 2),
                    );
                    ui.colored_label(
                        egui::Color32::from_rgb(190, 110, 0),
                        tr_with(
                            "status-behind",
                            &[("ratio", Arg::Text(&ratio)), ("real", Arg::Text(&real))],
                        ),
                    );
                }
                (true, None) => {
                    // Before the first measurement, the speed asked for.
                    let real = i18n::decimal(self.runner.achieved.unwrap_or(time_scale), 2);
                    ui.label(tr_with("status-real-time", &[("real", Arg::Text(&real))]));
                }
                (false, _) if !self.runner.is_editing() => {
                    ui.label(tr("status-paused"));
                }
                (false, _) => {
                    ui.label(tr("status-editing"));
                }
            }
            ui.separator();
            ui.label(tr_with(
                "status-physics-time",
                &[(
                    "ms",
                    Arg::Text(
                        &self
                            .runner
                            .physics_per_frame
                            .map_or_else(|| "–".to_owned(), |t| i18n::decimal(t * 1000.0, 1)),
                    ),
                )],
            ))
            .on_hover_text(tr("status-physics-time-hint"));
            ui.separator();
            let frame = ui.input(|i| i.stable_dt);
            ui.label(tr_with(
                "status-frame-time",
                &[(
                    "ms",
                    Arg::Text(&i18n::decimal(f64::from(frame) * 1000.0, 1)),
                )],
            ));
            ui.separator();
            objects(ui, self.document.scene());
            if !self.announcer.text.is_empty() {
                ui.separator();
                let said = ui.label(&self.announcer.text);
                // A polite live region: read when it changes, the focus left where it is.
                ui.ctx().accesskit_node_builder(said.id, |node| {
                    node.set_live(egui::accesskit::Live::Polite);
                });
            }
        });
        action
    }
}

/// What the scene holds, counted by kind.
fn objects(ui: &mut Ui, scene: &physics::Scene) {
    #[expect(clippy::cast_precision_loss, reason = "counts of objects")]
    let count = |n: usize| Arg::Number(n as f64);
    ui.label(tr_with(
        "status-objects",
        &[
            ("particles", count(scene.particles.len())),
            ("springs", count(scene.springs.len())),
            ("ties", count(scene.ties.len())),
            ("ramps", count(scene.ramps.len())),
        ],
    ));
    if !scene.bodies.is_empty() {
        ui.label(tr_with(
            "status-bodies",
            &[("bodies", count(scene.bodies.len()))],
        ));
    }
}
