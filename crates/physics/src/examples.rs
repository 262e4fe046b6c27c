//! The built-in example scenes: one registry that the command line (`example:NAME`), the
//! tests, the validation report and the app's Examples menu all read. The files live in
//! `examples/scenes/` and are compiled in.

use crate::scene::Scene;
use crate::scene::format::LoadError;

/// A built-in scene.
#[derive(Clone, Copy, Debug)]
pub struct Example {
    /// What `example:NAME` names: the file's stem.
    pub name: &'static str,
    /// The scene file's text.
    pub source: &'static str,
}

impl Example {
    /// The scene.
    ///
    /// # Errors
    /// Never for the shipped files (a test loads every one); kept as a `Result` so a
    /// broken file is a message, not a crash.
    pub fn scene(&self) -> Result<Scene, LoadError> {
        Scene::from_toml(self.source)
    }
}

macro_rules! examples {
    ($($name:literal),* $(,)?) => {
        /// Every built-in scene, in menu order.
        pub static EXAMPLES: &[Example] = &[$(Example {
            name: $name,
            source: include_str!(concat!("../../../examples/scenes/", $name, ".toml")),
        }),*];
    };
}

examples!(
    "kinematics-cartesian",
    "kinematics-polar",
    "spring-undamped",
    "spring-damped-light",
    "spring-damped-heavy",
    "orbit",
    "charged-pair",
    "collision",
    "ramp-slides",
    "ramp-bounces",
    "paper-gravitation",
    "paper-coulomb",
    "newtons-cradle",
    "marble-run",
    "ball-pit",
);

/// The built-in scene with this name.
pub fn example(name: &str) -> Option<&'static Example> {
    EXAMPLES.iter().find(|e| e.name == name)
}
