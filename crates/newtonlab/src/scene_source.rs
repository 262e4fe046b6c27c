//! Where a scene comes from: a file path, or `example:NAME` for a built-in scene.

use physics::{LoadError, Scene, SceneFormat};

use crate::Failure;
use newtonlab_i18n::tr_text as say;

/// Loads and validates the scene `source` names; every problem goes into the message.
pub(crate) fn load(source: &str) -> Result<Scene, Failure> {
    if let Some(name) = source.strip_prefix("example:") {
        let example = physics::example(name).ok_or_else(|| {
            let names: Vec<&str> = physics::EXAMPLES.iter().map(|e| e.name).collect();
            Failure::Input(say(
                "cli-no-example",
                &[("name", name), ("names", &names.join(", "))],
            ))
        })?;
        return example.scene().map_err(|error| describe(source, &error));
    }
    let text = std::fs::read_to_string(source).map_err(|error| {
        Failure::Input(say(
            "cli-cannot-read",
            &[("source", source), ("error", &error.to_string())],
        ))
    })?;
    Scene::parse(&text, SceneFormat::from_file_name(source))
        .map_err(|error| describe(source, &error))
}

fn describe(source: &str, error: &LoadError) -> Failure {
    Failure::Input(error.report(source))
}
