//! No lost work on the desktop: while the scene has unsaved changes it is written every
//! few seconds to the platform's data directory (`directories`: on Linux
//! `~/.local/share/newtonlab`), with the file it belongs to. Saving the scene, or
//! leaving with nothing unsaved, removes the copy; after a crash or a kill the next start
//! finds it and offers to recover it. (The browser keeps the edited scene in its local
//! storage instead: `web.rs`.)
//!
//! Every write is atomic (`platform::write_atomically`): a kill mid-write leaves the last
//! complete copy, never half a file.

use std::path::{Path, PathBuf};

use physics::{Scene, SceneFormat};
use web_time::Instant;

use crate::document::Document;
use crate::platform;

/// Seconds between autosaves while there are unsaved changes.
pub const INTERVAL: f64 = 5.0;

const SCENE_FILE: &str = "autosave.toml";
const PATH_FILE: &str = "autosave.path";

/// Work found after a crash.
#[derive(Clone, Debug, PartialEq)]
pub struct Recovered {
    pub scene: Scene,
    /// The file the scene belonged to, if it had one.
    pub path: Option<String>,
}

#[derive(Clone, Debug)]
pub struct Autosave {
    dir: PathBuf,
    interval: f64,
    last: Option<Instant>,
    /// The scene as last written, so an unchanged scene is not written again.
    written: Option<Scene>,
}

impl Autosave {
    /// Autosaving into `dir` every `interval` seconds.
    pub fn in_dir(dir: impl Into<PathBuf>, interval: f64) -> Self {
        Self {
            dir: dir.into(),
            interval,
            last: None,
            written: None,
        }
    }

    /// The platform's data directory for NewtonLab, if it has one.
    pub fn default_dir() -> Option<PathBuf> {
        directories::ProjectDirs::from("org", "NewtonLab", "newtonlab")
            .map(|dirs| dirs.data_dir().to_path_buf())
    }

    fn file(&self, name: &str) -> PathBuf {
        self.dir.join(name)
    }

    /// Work left by a session that ended without saving it. A copy that no longer loads
    /// (written by a newer NewtonLab, say) is left where it is and not offered.
    pub fn find(&self) -> Option<Recovered> {
        let text = std::fs::read_to_string(self.file(SCENE_FILE)).ok()?;
        let scene = Scene::parse(&text, SceneFormat::Toml).ok()?;
        let path = std::fs::read_to_string(self.file(PATH_FILE))
            .ok()
            .filter(|p| !p.is_empty());
        Some(Recovered { scene, path })
    }

    /// Called every frame: writes the scene when it has unsaved changes that are not
    /// written yet and the interval has passed; removes the copy when nothing is unsaved.
    /// Returns a message when writing failed.
    pub fn tick(&mut self, document: &Document) -> Option<String> {
        if !document.is_dirty() {
            if self.written.is_some() {
                self.clear();
            }
            return None;
        }
        let due = self
            .last
            .is_none_or(|last| last.elapsed().as_secs_f64() >= self.interval);
        if !due || self.written.as_ref() == Some(document.scene()) {
            return None;
        }
        self.last = Some(Instant::now());
        self.write(document).err()
    }

    /// Writes the scene now (on exit, or when due).
    ///
    /// # Errors
    /// Why the copy could not be written.
    pub fn write(&mut self, document: &Document) -> Result<(), String> {
        std::fs::create_dir_all(&self.dir).map_err(|e| {
            crate::i18n::tr_text(
                "file-cannot-autosave",
                &[
                    ("path", &self.dir.display().to_string()),
                    ("error", &e.to_string()),
                ],
            )
        })?;
        let path = document.path.clone().unwrap_or_default();
        platform::write_atomically(&self.file(PATH_FILE), path.as_bytes())?;
        platform::write_atomically(
            &self.file(SCENE_FILE),
            document.scene().to_toml().as_bytes(),
        )?;
        self.written = Some(document.scene().clone());
        Ok(())
    }

    /// Removes the copy: the work is saved, or was discarded on purpose.
    pub fn clear(&mut self) {
        for name in [SCENE_FILE, PATH_FILE] {
            let _ = std::fs::remove_file(self.file(name));
        }
        self.written = None;
    }

    /// Where the copies go.
    pub fn dir(&self) -> &Path {
        &self.dir
    }
}
