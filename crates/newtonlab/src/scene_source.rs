//! Where a scene comes from: a file path, `example:NAME` for a built-in scene, or a
//! share link (`https://…/#scene=…`, as File → Share link makes them).

use physics::{LoadError, Scene, SceneFormat};

use crate::Failure;
use newtonlab_i18n::tr_text as say;

/// Loads and validates the scene `source` names; every problem goes into the message.
/// The largest scene file read: 100 MB (a million particles take some 150 MB as TOML;
/// far beyond the app's and the CLI's reach anyway).
const MAX_SCENE_BYTES: u64 = 100_000_000;

/// Whether `source` is a share link rather than a file's name: it carries a scene or an
/// example in its fragment, and no file has that name.
pub(crate) fn is_link(source: &str) -> bool {
    (source.contains("#scene=") || source.contains("#example="))
        && !std::path::Path::new(source).exists()
}

pub(crate) fn load(source: &str) -> Result<Scene, Failure> {
    if is_link(source) {
        return newtonlab_app::share::open(source).map_err(Failure::Input);
    }
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
    let cannot = |error: &dyn std::fmt::Display| {
        Failure::Input(say(
            "cli-cannot-read",
            &[("source", source), ("error", &error.to_string())],
        ))
    };
    // A file, and of a size a scene can have: a device, a FIFO or /dev/zero would be
    // read until memory runs out.
    let metadata = std::fs::metadata(source).map_err(|e| cannot(&e))?;
    if !metadata.is_file() {
        return Err(Failure::Input(say("cli-not-a-file", &[("source", source)])));
    }
    if metadata.len() > MAX_SCENE_BYTES {
        return Err(Failure::Input(say(
            "cli-file-too-large",
            &[
                ("source", source),
                ("megabytes", &(metadata.len() / 1_000_000).to_string()),
                ("most", &(MAX_SCENE_BYTES / 1_000_000).to_string()),
            ],
        )));
    }
    let text = std::fs::read_to_string(source).map_err(|e| cannot(&e))?;
    Scene::parse(&text, SceneFormat::from_file_name(source))
        .map_err(|error| describe(source, &error))
}

fn describe(source: &str, error: &LoadError) -> Failure {
    Failure::Input(error.report(source))
}
