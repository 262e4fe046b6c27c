//! What the app keeps between sessions: the settings, and copies of unsaved work.

use crate::App;
#[cfg(not(target_arch = "wasm32"))]
use crate::autosave;
use crate::i18n;
#[cfg(not(target_arch = "wasm32"))]
use crate::i18n::{Arg, tr_with};
use crate::settings;
use egui::Ui;

impl App {
    /// The text size (times projector mode's 1.6) and the theme, as the settings say.
    pub(crate) fn apply_settings(&self, ui: &Ui) {
        let projector = if self.panels.projector { 1.6 } else { 1.0 };
        let zoom = projector * self.settings.text_size;
        if (ui.ctx().zoom_factor() - zoom).abs() > 1e-3 {
            ui.ctx().set_zoom_factor(zoom);
        }
        let high_contrast = ui.style().visuals.override_text_color.is_some();
        if high_contrast != self.settings.high_contrast {
            ui.ctx().set_visuals(if self.settings.high_contrast {
                settings::high_contrast_visuals()
            } else {
                ui.ctx().theme().default_visuals()
            });
        }
    }

    /// Keeps the settings for the next session; says so if they cannot be kept.
    pub(crate) fn keep_settings(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(path) = &self.settings_file
            && let Err(reason) = self.settings.save_to(path)
        {
            self.notify(tr_with(
                "notice-settings-not-kept",
                &[("reason", Arg::Text(&reason))],
            ));
        }
        #[cfg(target_arch = "wasm32")]
        self.settings.save();
    }

    /// Starts with the settings kept in `path` and keeps later changes there.
    #[cfg(not(target_arch = "wasm32"))]
    #[must_use]
    pub fn with_settings_file(mut self, path: std::path::PathBuf) -> Self {
        let settings = settings::Settings::load_from(&path);
        self.settings_file = Some(path);
        self.with_settings(settings)
    }

    /// Opens the Getting started page if these settings never showed it, and remembers
    /// that it was (the first run of the desktop app, the first visit of the page).
    #[must_use]
    pub fn welcome_first_run(mut self) -> Self {
        if !self.settings.welcomed {
            self.settings.welcomed = true;
            self.panels.getting_started = true;
            self.keep_settings();
        }
        self
    }

    /// Starts with the settings of the last session: its text size, theme and language
    /// (or the system's language, if none was chosen).
    #[must_use]
    pub fn with_settings(mut self, settings: settings::Settings) -> Self {
        i18n::set_language(
            settings
                .language()
                .unwrap_or_else(i18n::Language::of_system),
        );
        self.settings = settings;
        self
    }

    /// Autosaves unsaved work when due (desktop; the browser keeps its copy in `web.rs`).
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn keep_copy(&mut self) {
        if self.files.recover.is_none()
            && let Some(autosave) = &mut self.autosave
        {
            match autosave.tick(&self.document) {
                Some(message) if !self.autosave_failed => {
                    self.autosave_failed = true;
                    self.notify(format!(
                        "{message}\nUnsaved work is not being kept: save it."
                    ));
                }
                Some(_) => {}
                None => self.autosave_failed = false,
            }
        }
    }

    /// Brings back work an earlier session left unsaved: unsaved again, with its file.
    #[cfg(not(target_arch = "wasm32"))]
    pub(crate) fn recover(&mut self, recovered: Box<autosave::Recovered>) {
        let recovered = *recovered;
        let label = recovered.scene.name.clone();
        self.replace(recovered.scene, None, label);
        self.document.mark_unsaved(recovered.path);
    }
}
