//! The built-in example scenes: one registry that the command line (`example:NAME`), the
//! tests, the validation report and the app's Examples menu all read. The files live in
//! `examples/scenes/` and are compiled in; the largest scenes are made by code instead
//! ([`crate::generated`]), since ten thousand particles in a file would only weigh down
//! the program (and the web page) that carries it.

use crate::scene::Scene;
use crate::scene::error::LoadError;

/// A built-in scene.
#[derive(Clone, Copy, Debug)]
pub struct Example {
    /// What `example:NAME` names: the file's stem.
    pub name: &'static str,
    source: Source,
}

/// Where an example comes from.
#[derive(Clone, Copy, Debug)]
enum Source {
    /// A scene file's text.
    File(&'static str),
    /// A scene made by code.
    Generated(fn() -> Scene),
}

impl Example {
    /// The scene.
    ///
    /// # Errors
    /// Never for the shipped files (a test loads every one); kept as a `Result` so a
    /// broken file is a message, not a crash.
    pub fn scene(&self) -> Result<Scene, LoadError> {
        match self.source {
            Source::File(text) => Scene::from_toml(text),
            Source::Generated(make) => Ok(make()),
        }
    }

    /// The scene file's text, for an example shipped as a file.
    pub fn file_text(&self) -> Option<&'static str> {
        match self.source {
            Source::File(text) => Some(text),
            Source::Generated(_) => None,
        }
    }
}

/// The 10,000-ball pit: the generated layout of the `ball-pit` example, ten times larger.
fn ball_pit_10000() -> Scene {
    let mut scene = crate::generated::ball_pit(10_000);
    scene.name = Some("Ball pit of 10,000".to_owned());
    scene
}

macro_rules! examples {
    ($($name:literal),* $(,)?) => {
        /// Every built-in scene, in menu order.
        pub static EXAMPLES: &[Example] = &[$(Example {
            name: $name,
            source: Source::File(include_str!(concat!("../../../examples/scenes/", $name, ".toml"))),
        }),*, Example {
            name: "ball-pit-10000",
            source: Source::Generated(ball_pit_10000),
        }, Example {
            name: "star-cluster",
            source: Source::Generated(crate::generated::star_cluster),
        }, Example {
            name: "colliding-discs",
            source: Source::Generated(crate::generated::colliding_discs),
        }];
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
    "projectile",
    "projectile-range",
    "ramp-slides",
    "ramp-bounces",
    "paper-gravitation",
    "paper-coulomb",
    "newtons-cradle",
    "marble-run",
    "ball-pit",
    "pendulum",
    "pendulum-amplitude",
    "double-pendulum",
    "string-circle",
    "terminal-speed",
    "cyclotron",
    "anharmonic-oscillator",
    "galileo-incline",
    "bowling",
    "spin-bounce",
    "thrown-board",
    "block-on-incline",
    "tipping-box",
    "colliding-blocks",
    "stacked-boxes",
    "physical-pendulum",
    "seesaw",
    "motor-wheel",
    "atwood",
    "lesson-galileo-incline",
    "lesson-projectile-range",
    "lesson-spring-period",
    "lesson-collisions",
    "lesson-block-slide",
);

/// The built-in scene with this name.
pub fn example(name: &str) -> Option<&'static Example> {
    EXAMPLES.iter().find(|e| e.name == name)
}
