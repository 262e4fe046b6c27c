//! Scene files, version 1: TOML (and JSON with the same structure), loaded with
//! validation and saved in the same schema.
//!
//! Loading never stops at the first problem. The text is parsed into a small tree that
//! remembers where every key and value stands in the file (JSON's ranges too); a reader
//! walks it, noting every unknown key, wrong type and missing field; the scene it builds is
//! then checked by [`Scene::validate`] (the same rules the app uses), and each problem gets
//! the line and column of the value it is about, found in the tree.
//!
//! One job a file: `tree.rs` parses the text into that tree, `slices.rs` parses a long TOML
//! file a slice at a time (so that memory stays near the tree's own size), `read.rs` reads
//! the scene from the tree, `write.rs` writes a scene back, `lesson.rs` does both for a
//! lesson; what can be wrong is
//! `super::error`.

mod instruments;
mod lesson;
mod read;
mod slices;
mod tree;
mod values;
mod write;

use self::read::Reader;
use self::tree::{parse_json, parse_toml};
pub use self::values::closest;
use super::Scene;
use super::error::LoadError;

/// The scene-format version this library reads and writes.
pub const VERSION: i64 = 1;

/// The two encodings of a scene file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneFormat {
    /// TOML, the usual one.
    Toml,
    /// JSON with the same structure.
    Json,
}

impl SceneFormat {
    /// JSON for a `.json` file name, TOML for anything else.
    pub fn from_file_name(name: &str) -> Self {
        if name.to_ascii_lowercase().ends_with(".json") {
            Self::Json
        } else {
            Self::Toml
        }
    }
}

impl Scene {
    /// Loads a scene from text in the given format.
    ///
    /// # Errors
    /// Every problem with the text or the scene it describes.
    pub fn parse(text: &str, format: SceneFormat) -> Result<Self, LoadError> {
        let root = match format {
            SceneFormat::Toml => parse_toml(text)?,
            SceneFormat::Json => parse_json(text)?,
        };
        let mut reader = Reader::new(text);
        let scene = reader.scene(&root);
        reader.finish(scene, &root)
    }

    /// Loads a TOML scene.
    ///
    /// # Errors
    /// Every problem with the text or the scene it describes.
    pub fn from_toml(text: &str) -> Result<Self, LoadError> {
        Self::parse(text, SceneFormat::Toml)
    }

    /// Loads a JSON scene.
    ///
    /// # Errors
    /// Every problem with the text or the scene it describes.
    pub fn from_json(text: &str) -> Result<Self, LoadError> {
        Self::parse(text, SceneFormat::Json)
    }

    /// The scene as text in the given format.
    pub fn to_text(&self, format: SceneFormat) -> String {
        match format {
            SceneFormat::Toml => self.to_toml(),
            SceneFormat::Json => self.to_json(),
        }
    }
}
