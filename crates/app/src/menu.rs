//! The menu bar and the keyboard shortcuts: every command a menu item or a key gives,
//! as an [`Action`].

use crate::App;
use crate::action::Action;
use crate::canvas::{FieldKind, Instrument};
use crate::i18n;
use crate::i18n::{Arg, tr, tr_with};
#[cfg(target_arch = "wasm32")]
use crate::web;
use crate::{action, picture, settings, toolbar};
use egui::Ui;

impl App {
    #[expect(clippy::too_many_lines, reason = "the four menus, item by item")]
    pub(crate) fn menu(&mut self, ui: &mut Ui) -> Option<Action> {
        let mut action = None;
        let ctx = ui.ctx().clone();
        let mut item = |ui: &mut Ui, label: &str, hint: &str, does: Action, enabled: bool| {
            let shortcut = does.shortcut_text(&ctx);
            let mut button = egui::Button::new(label);
            if !shortcut.is_empty() {
                button = button.shortcut_text(shortcut);
            }
            if ui
                .add_enabled(enabled, button)
                .on_hover_text(hint)
                .clicked()
            {
                action = Some(does);
            }
        };
        egui::MenuBar::new().ui(ui, |ui| {
            let file = ui
                .menu_button(tr("menu-file"), |ui| {
                    item(ui, &tr("menu-new"), &tr("menu-new-hint"), Action::New, true);
                    item(
                        ui,
                        &tr("menu-open"),
                        &tr("menu-open-hint"),
                        Action::Open,
                        true,
                    );
                    item(
                        ui,
                        &tr("menu-save"),
                        &tr("menu-save-hint"),
                        Action::Save,
                        true,
                    );
                    item(
                        ui,
                        &tr("menu-save-canvas"),
                        &tr("menu-save-canvas-hint"),
                        Action::ExportPicture(picture::Subject::Canvas),
                        true,
                    );
                    item(
                        ui,
                        &tr("menu-save-as"),
                        &tr("menu-save-as-hint"),
                        Action::SaveAs,
                        true,
                    );
                    #[cfg(not(target_arch = "wasm32"))]
                    {
                        let lesson = self.document.scene().lesson.is_some();
                        for (key, label, hint) in [
                            (false, "menu-worksheet", "menu-worksheet-hint"),
                            (true, "menu-answer-key", "menu-answer-key-hint"),
                        ] {
                            item(
                                ui,
                                &tr(label),
                                &tr(hint),
                                Action::ExportWorksheet(key),
                                lesson,
                            );
                        }
                    }
                    #[cfg(not(target_arch = "wasm32"))]
                    item(
                        ui,
                        &tr("menu-share-link"),
                        &tr("menu-share-link-hint"),
                        Action::ShareLink,
                        true,
                    );
                    item(
                        ui,
                        &tr("menu-open-link"),
                        &tr("menu-open-link-hint"),
                        Action::OpenLink,
                        true,
                    );
                    #[cfg(target_arch = "wasm32")]
                    if ui
                        .button(tr("menu-copy-link"))
                        .on_hover_text(tr("menu-copy-link-hint"))
                        .clicked()
                    {
                        self.files.message = Some(match web::copy_link(self.document.scene()) {
                            Ok(_) => tr("menu-link-copied"),
                            Err(reason) => reason,
                        });
                    }
                })
                .response
                .on_hover_text(tr("menu-file-hint"));
            crate::landmarks::mark(ui, crate::landmarks::Region::Menu, file.id);
            ui.menu_button(tr("menu-edit"), |ui| {
                let editable = self.runner.is_editing();
                let undo = self.document.undo_edit().map_or(tr("menu-undo"), |edit| {
                    tr_with("menu-undo-what", &[("what", Arg::Text(&edit.words()))])
                });
                let can_undo = editable && self.document.undo_edit().is_some();
                item(ui, &undo, &tr("menu-undo-hint"), Action::Undo, can_undo);
                let redo = self.document.redo_edit().map_or(tr("menu-redo"), |edit| {
                    tr_with("menu-redo-what", &[("what", Arg::Text(&edit.words()))])
                });
                let can_redo = editable && self.document.redo_edit().is_some();
                item(ui, &redo, &tr("menu-redo-hint"), Action::Redo, can_redo);
                let can_delete = editable && self.selection.is_some();
                for (label, hint, action, enabled) in [
                    ("menu-cut", "menu-cut-hint", Action::Cut, can_delete),
                    (
                        "menu-copy",
                        "menu-copy-hint",
                        Action::Copy,
                        self.selection.is_some(),
                    ),
                    (
                        "menu-paste",
                        "menu-paste-hint",
                        Action::Paste,
                        editable && self.clipboard.is_some(),
                    ),
                    (
                        "menu-duplicate",
                        "menu-duplicate-hint",
                        Action::Duplicate,
                        can_delete,
                    ),
                ] {
                    item(ui, &tr(label), &tr(hint), action, enabled);
                }
                item(
                    ui,
                    &tr("menu-delete"),
                    &tr("menu-delete-hint"),
                    Action::Delete,
                    can_delete,
                );
            })
            .response
            .on_hover_text(tr("menu-edit-hint"));
            ui.menu_button(tr("menu-examples"), |ui| {
                // Fields and forces, the rigid bodies and the lessons in menus of their own: one list of
                // every scene would run past a laptop's screen.
                let mut list = |ui: &mut Ui, kind: Kind| {
                    for (name, title, _) in example_titles().iter().filter(|e| e.2 == kind) {
                        let hint = format!("example:{name}");
                        item(ui, title, &hint, Action::Example(name), true);
                    }
                };
                list(ui, Kind::Particles);
                ui.menu_button(tr("menu-fields"), |ui| list(ui, Kind::Fields));
                ui.menu_button(tr("menu-bodies"), |ui| list(ui, Kind::Bodies));
                ui.menu_button(tr("menu-lessons"), |ui| list(ui, Kind::Lesson));
            })
            .response
            .on_hover_text(tr("menu-examples-hint"));
            ui.menu_button(tr("menu-view"), |ui| {
                item(ui, &tr("menu-fit"), &tr("menu-fit-hint"), Action::Fit, true);
                let tick = |on: bool| if on { "• " } else { "" };
                item(
                    ui,
                    &format!("{}{}", tick(self.panels.inspector), tr("menu-inspector")),
                    &tr("menu-inspector-hint"),
                    Action::ToggleInspector,
                    true,
                );
                item(
                    ui,
                    &format!("{}{}", tick(self.panels.graphs), tr("menu-graphs")),
                    &tr("menu-graphs-hint"),
                    Action::ToggleGraphs,
                    true,
                );
                if self.document.scene().lesson.is_some() {
                    item(
                        ui,
                        &format!("{}{}", tick(self.panels.lesson), tr("menu-lesson")),
                        &tr("menu-lesson-hint"),
                        Action::ToggleLesson,
                        true,
                    );
                }
                item(
                    ui,
                    &format!("{}{}", tick(self.panels.projector), tr("menu-projector")),
                    &tr("menu-projector-hint"),
                    Action::ToggleProjector,
                    true,
                );
                ui.menu_button(tr("menu-follow"), |ui| {
                    toolbar::follow_menu(ui, &mut self.canvas, &self.document);
                })
                .response
                .on_hover_text(tr("menu-follow-hint"));
                ui.menu_button(tr("menu-language"), |ui| {
                    for language in i18n::Language::ALL {
                        let chosen = i18n::language() == language;
                        if ui.selectable_label(chosen, language.name()).clicked() {
                            i18n::set_language(language);
                            // The last sentence said was in the old language.
                            self.announcer.text.clear();
                            self.settings.language = Some(language.code().to_owned());
                            self.keep_settings();
                        }
                    }
                })
                .response
                .on_hover_text(tr("menu-language-hint"));
                ui.menu_button(tr("menu-text-size"), |ui| {
                    for size in settings::TEXT_SIZES {
                        let chosen = (self.settings.text_size - size).abs() < 1e-3;
                        let label = format!("{:.0} %", size * 100.0);
                        if ui.selectable_label(chosen, label).clicked() {
                            self.settings.text_size = size;
                            self.keep_settings();
                        }
                    }
                })
                .response
                .on_hover_text(tr("menu-text-size-hint"));
                if ui
                    .checkbox(&mut self.settings.high_contrast, tr("menu-high-contrast"))
                    .on_hover_text(tr("menu-high-contrast-hint"))
                    .changed()
                {
                    self.keep_settings();
                }
            })
            .response
            .on_hover_text(tr("menu-view-hint"));
            ui.menu_button(tr("menu-measure"), |ui| {
                let instruments = &self.canvas.instruments;
                let tick = |on: bool| if on { "• " } else { "" };
                for instrument in [Instrument::Tape, Instrument::Probe, Instrument::Protractor] {
                    item(
                        ui,
                        &format!(
                            "{}{}",
                            tick(instruments.active == Some(instrument)),
                            instrument.label()
                        ),
                        &instrument.hint(),
                        Action::Instrument(instrument),
                        true,
                    );
                }
                for (kind, name) in [
                    (None, tr("menu-no-field")),
                    (Some(FieldKind::Electric), tr("menu-electric-field")),
                    (
                        Some(FieldKind::Gravitational),
                        tr("menu-gravitational-field"),
                    ),
                ] {
                    item(
                        ui,
                        &format!("{}{name}", tick(instruments.field_view == kind)),
                        &tr("menu-field-hint"),
                        Action::FieldView(kind),
                        true,
                    );
                }
                item(
                    ui,
                    &format!("{}{}", tick(self.stopwatch.shown), tr("menu-stopwatch")),
                    &tr("menu-stopwatch-hint"),
                    Action::ToggleStopwatch,
                    true,
                );
                item(
                    ui,
                    &tr("menu-clear-measurements"),
                    &tr("menu-clear-measurements-hint"),
                    Action::ClearMeasurements,
                    instruments.tape.is_some()
                        || instruments.probe.is_some()
                        || instruments.protractor.is_some(),
                );
            })
            .response
            .on_hover_text(tr("menu-measure-hint"));
            ui.menu_button(tr("menu-help"), |ui| {
                item(
                    ui,
                    &tr("menu-getting-started"),
                    &tr("menu-getting-started-hint"),
                    Action::ToggleGettingStarted,
                    true,
                );
                item(
                    ui,
                    &tr("menu-keys"),
                    &tr("menu-keys-hint"),
                    Action::ToggleHelp,
                    true,
                );
            });
        });
        action
    }

    /// The actions whose shortcuts were pressed this frame. Bare keys are left to a
    /// focused control (a text field types them, a button takes Space and Enter), except
    /// on the canvas, whose own keys are others (`canvas/keyboard.rs`).
    pub(crate) fn shortcuts(ui: &Ui, canvas: Option<egui::Id>) -> Vec<Action> {
        // A pass egui discards (to lay out again) sees the same keys once more: Space
        // would play and pause at once. Shortcuts act in the first pass only.
        if ui.ctx().current_pass_index() > 0 {
            return Vec::new();
        }
        let focused = ui.ctx().memory(egui::Memory::focused);
        let typing = focused.is_some() && focused != canvas;
        ui.input_mut(|i| {
            let mut actions: Vec<Action> = action::SHORTCUTS
                .iter()
                .filter(|(shortcut, _)| !(typing && Action::is_plain(shortcut)))
                .filter(|(shortcut, _)| i.consume_shortcut(shortcut))
                .map(|(_, action)| *action)
                .collect();
            // The system's copy and cut (Ctrl+C, Ctrl+X) copy objects unless a field
            // has the focus, which copies its text.
            if !typing {
                actions.extend(i.events.iter().filter_map(|event| match event {
                    egui::Event::Copy => Some(Action::Copy),
                    egui::Event::Cut => Some(Action::Cut),
                    _ => None,
                }));
            }
            actions
        })
    }

    /// The text the system pasted (Ctrl+V) this frame, unless a field has the focus,
    /// which takes it.
    pub(crate) fn pasted_text(ui: &Ui, canvas: Option<egui::Id>) -> Option<String> {
        if ui.ctx().current_pass_index() > 0 {
            return None;
        }
        let focused = ui.ctx().memory(egui::Memory::focused);
        if focused.is_some() && focused != canvas {
            return None;
        }
        ui.input(|i| {
            i.events.iter().find_map(|event| match event {
                egui::Event::Paste(text) => Some(text.clone()),
                _ => None,
            })
        })
    }
}

/// A built-in scene as the menu lists it: its name, its title, and whether it is a lesson.
type Listed = (&'static str, String, Kind);

/// Where an example is listed: the Examples menu itself, its rigid bodies' menu, or its
/// lessons' menu (a lesson with bodies is a lesson).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Particles,
    Fields,
    Bodies,
    Lesson,
}

/// Every built-in scene's name and title, read once: the menu is drawn every frame it is
/// open, and parsing a thousand-ball scene each time would make it stutter.
fn example_titles() -> &'static [Listed] {
    static TITLES: std::sync::OnceLock<Vec<Listed>> = std::sync::OnceLock::new();
    TITLES.get_or_init(|| {
        physics::EXAMPLES
            .iter()
            .map(|e| {
                let scene = e.scene().ok();
                let kind = match &scene {
                    Some(s) if s.lesson.is_some() => Kind::Lesson,
                    Some(s) if !s.bodies.is_empty() => Kind::Bodies,
                    Some(s) if s.world.magnetic_field != 0.0 || !s.forces.is_empty() => {
                        Kind::Fields
                    }
                    _ => Kind::Particles,
                };
                let title = scene.and_then(|s| s.name);
                (e.name, title.unwrap_or_else(|| e.name.to_owned()), kind)
            })
            .collect()
    })
}
