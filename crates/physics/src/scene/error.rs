//! What is wrong with a scene, and where: the problems every reader and check reports,
//! each with its line and column in the file where known and the field it is about.

use std::fmt::{self, Write as _};

use super::say;

/// A part of the scene that a problem belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Section {
    /// The top level of the file (`version`, `name`, `description`).
    Root,
    /// `[world]`.
    World,
    /// `[simulation]`.
    Simulation,
    /// The particle at this index, in file order.
    Particle(usize),
    /// The spring at this index.
    Spring(usize),
    /// The rod or string at this index of [`Scene::ties`](super::Scene::ties).
    Tie(usize),
    /// The ramp at this index.
    Ramp(usize),
    /// The rigid body at this index (`[[body]]`).
    Body(usize),
    /// The pin or hinge at this index of [`Scene::joints`](super::Scene::joints).
    Joint(usize),
    /// The force of one's own at this index (`[[force]]`).
    Force(usize),
    /// The graph at this index (`[[graph]]`).
    Graph(usize),
    /// The series at this index (`[[series]]`).
    Series(usize),
    /// `[view]`.
    View,
    /// `[lesson]`.
    Lesson,
    /// The lesson's slider at this index (`[[lesson.slider]]`).
    Slider(usize),
    /// The lesson's question at this index (`[[lesson.question]]`).
    Question(usize),
    /// `[instruments]`.
    Instruments,
    /// `[instruments.stopwatch]`.
    Stopwatch,
}

/// A field of a section: where a problem is, for the app's inspector and for locating
/// the problem in a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FieldRef {
    /// The section.
    pub section: Section,
    /// The key, as written in the scene format (`"mass"`, `"natural_length"`); empty for
    /// the section as a whole.
    pub field: &'static str,
}

/// One thing wrong with a scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// What is wrong, in words a student understands, starting with the object it is
    /// about: `particle 'B': mass must be greater than 0, got -2`.
    pub message: String,
    /// 1-based line in the file, where known.
    pub line: Option<usize>,
    /// 1-based column (in characters) in the file, where known.
    pub column: Option<usize>,
    /// The field the problem is about, where it is about one.
    pub field: Option<FieldRef>,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.column) {
            (Some(line), Some(column)) => {
                let (line, column) = (line.to_string(), column.to_string());
                let place = say(
                    "scene-at-line-column",
                    &[("line", &line), ("column", &column)],
                );
                write!(f, "{place}: {}", self.message)
            }
            (Some(line), None) => {
                let place = say("scene-at-line", &[("line", &line.to_string())]);
                write!(f, "{place}: {}", self.message)
            }
            _ => f.write_str(&self.message),
        }
    }
}

/// Why a scene could not be loaded: every problem found, in file order.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct LoadError {
    /// At least one.
    pub problems: Vec<Problem>,
}

impl LoadError {
    /// The problems as `newtonlab check` prints them for the file `source`: a count, then
    /// one line per problem, `source:line:column: message`.
    pub fn report(&self, source: &str) -> String {
        let count = self.problems.len();
        #[expect(clippy::cast_precision_loss, reason = "a count of problems")]
        let mut out = newtonlab_i18n::tr_with(
            "scene-problems-found",
            &[
                ("source", newtonlab_i18n::Arg::Text(source)),
                ("count", newtonlab_i18n::Arg::Number(count as f64)),
            ],
        );
        for problem in &self.problems {
            let place = match (problem.line, problem.column) {
                (Some(line), Some(column)) => format!("{source}:{line}:{column}"),
                (Some(line), None) => format!("{source}:{line}"),
                _ => source.to_owned(),
            };
            let _ = write!(out, "\n  {place}: {}", problem.message);
        }
        out
    }
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, problem) in self.problems.iter().enumerate() {
            if i > 0 {
                f.write_str("\n")?;
            }
            write!(f, "{problem}")?;
        }
        Ok(())
    }
}
