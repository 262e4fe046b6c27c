//! What the app remembers from one session to the next: the text size, the high-contrast
//! theme and the language (so a user who needs them sets them once), and whether the
//! Getting started page was shown. On the desktop a small TOML file, `settings.toml` in the data directory
//! (`~/.local/share/newtonlab` on Linux; `NEWTONLAB_DATA_DIR` overrides it), written
//! atomically; in the browser, its local storage. An app made by `App::new` (the tests)
//! keeps none until it is given a file. A file that does not read (hand-edited,
//! from a newer version) gives the defaults for what it gets wrong, never an error.

use serde::{Deserialize, Serialize};

use crate::i18n::Language;

/// The text sizes offered, as a factor of the normal size.
pub const TEXT_SIZES: [f32; 5] = [1.0, 1.25, 1.5, 1.75, 2.0];

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Settings {
    /// Text and controls scaled by this factor (projector mode multiplies it by 1.6).
    pub text_size: f32,
    /// Black and white with strong outlines instead of the default theme.
    pub high_contrast: bool,
    /// The language chosen in the View menu (`en`, `de`, `es`); none: the system's.
    pub language: Option<String>,
    /// Whether the Getting started page was shown (on the first run, once).
    pub welcomed: bool,
    /// Where the class's browser build is served, for share links made on the desktop;
    /// none: `share::DEFAULT_ADDRESS`.
    pub web_address: Option<String>,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            text_size: 1.0,
            high_contrast: false,
            language: None,
            welcomed: false,
            web_address: None,
        }
    }
}

impl Settings {
    /// The settings in `text`, with the default for anything missing or unreadable.
    pub fn parse(text: &str) -> Self {
        let mut settings: Self = toml::from_str(text).unwrap_or_default();
        if !(settings.text_size.is_finite() && (0.5..=3.0).contains(&settings.text_size)) {
            settings.text_size = 1.0;
        }
        settings
    }

    pub fn to_text(&self) -> String {
        toml::to_string(self).unwrap_or_default()
    }

    /// The remembered language, if it is one the app has.
    pub fn language(&self) -> Option<Language> {
        self.language.as_deref().and_then(Language::from_locale)
    }
}

/// Where the desktop keeps the settings: `settings.toml` in `NEWTONLAB_DATA_DIR` or the
/// platform's data directory.
#[cfg(not(target_arch = "wasm32"))]
pub fn default_file() -> Option<std::path::PathBuf> {
    let dir = std::env::var_os("NEWTONLAB_DATA_DIR")
        .map(std::path::PathBuf::from)
        .or_else(crate::autosave::Autosave::default_dir)?;
    Some(dir.join("settings.toml"))
}

#[cfg(not(target_arch = "wasm32"))]
impl Settings {
    /// The settings in the file at `path`, or the defaults.
    pub fn load_from(path: &std::path::Path) -> Self {
        std::fs::read_to_string(path).map_or_else(|_| Self::default(), |text| Self::parse(&text))
    }

    /// Writes the settings to `path`, atomically.
    ///
    /// # Errors
    /// Why the folder or the file could not be written.
    pub fn save_to(&self, path: &std::path::Path) -> Result<(), String> {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        }
        crate::platform::write_atomically(path, self.to_text().as_bytes())
    }
}

/// The browser keeps the settings in its local storage.
#[cfg(target_arch = "wasm32")]
const KEY: &str = "newtonlab-settings";

#[cfg(target_arch = "wasm32")]
impl Settings {
    /// The settings of the last visit, or the defaults.
    pub fn load() -> Self {
        crate::platform::web::load(KEY).map_or_else(Self::default, |text| Self::parse(&text))
    }

    /// Keeps the settings in the browser (silently not, if its storage is off).
    pub fn save(&self) {
        crate::platform::web::store(KEY, &self.to_text());
    }
}

/// The high-contrast theme: black text on white, black outlines two points wide, the
/// selection in strong blue.
pub fn high_contrast_visuals() -> egui::Visuals {
    let mut visuals = egui::Visuals::light();
    let black = egui::Color32::BLACK;
    visuals.override_text_color = Some(black);
    visuals.panel_fill = egui::Color32::WHITE;
    visuals.window_fill = egui::Color32::WHITE;
    visuals.extreme_bg_color = egui::Color32::WHITE;
    visuals.window_stroke = egui::Stroke::new(2.0, black);
    for widget in [
        &mut visuals.widgets.noninteractive,
        &mut visuals.widgets.inactive,
        &mut visuals.widgets.hovered,
        &mut visuals.widgets.active,
        &mut visuals.widgets.open,
    ] {
        widget.bg_stroke = egui::Stroke::new(2.0, black);
        widget.fg_stroke = egui::Stroke::new(2.0, black);
    }
    visuals.widgets.inactive.weak_bg_fill = egui::Color32::WHITE;
    visuals.widgets.inactive.bg_fill = egui::Color32::WHITE;
    visuals.widgets.hovered.weak_bg_fill = egui::Color32::from_gray(220);
    visuals.selection.bg_fill = egui::Color32::from_rgb(0, 60, 200);
    visuals.selection.stroke = egui::Stroke::new(2.0, egui::Color32::WHITE);
    visuals
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_read_back_and_bad_values_give_defaults() {
        let settings = Settings {
            text_size: 1.5,
            high_contrast: true,
            language: Some("de".to_owned()),
            welcomed: true,
            web_address: Some("https://school.example/lab/".to_owned()),
        };
        assert_eq!(Settings::parse(&settings.to_text()), settings);
        assert_eq!(settings.language(), Some(Language::German));
        let refused = Settings::parse("text_size = 40.0").text_size;
        assert!((refused - 1.0).abs() < f32::EPSILON, "{refused}");
        assert_eq!(Settings::parse("not toml at all ["), Settings::default());
        assert_eq!(Settings::parse(""), Settings::default());
    }
}
