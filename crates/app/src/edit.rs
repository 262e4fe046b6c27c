//! The undoable edits: what each change of the scene was, for the undo history and the
//! words Edit → Undo and Redo show. A type, not a string, so that every edit has its
//! words in every language (a test asks each language for each kind).

use crate::i18n::{Arg, tr, tr_with};

/// A kind of object the tools add and Delete removes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Object {
    Particle,
    Spring,
    Rod,
    String,
    Ramp,
    Body,
}

/// One undoable change of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edit {
    /// A field typed in the inspector or the settings: the section's kind (`particle`,
    /// `world`, …) and the scene file's key.
    Set {
        kind: &'static str,
        key: &'static str,
    },
    Add(Object),
    Delete(Object),
    /// A new name typed in the inspector.
    Rename,
    MoveParticle,
    MoveRamp,
    MoveRampEnd,
    MoveBody,
    /// A velocity drawn on the canvas.
    SetVelocity,
    SetTimeScale,
    SetIntegrator,
    SetTimeStep,
    /// A moment of the run made the scene's start.
    EditFromHere,
    AddGraph,
    RemoveGraph,
    AddSeries,
    RemoveSeries,
    SetXAxis,
    /// An experiment series added, changed or removed.
    AddExperiment,
    ChangeExperiment,
    RemoveExperiment,
    /// Objects pasted or duplicated.
    Paste,
    /// Objects selected together, moved or deleted.
    MoveGroup,
    DeleteGroup,
    /// A lesson's slider moved.
    Slide,
    /// A question added to the lesson from what is measured on the screen.
    Ask,
}

impl Edit {
    /// Every edit but [`Edit::Set`]'s fields, for the tests.
    #[cfg(test)]
    const ALL: [Self; 35] = [
        Self::Add(Object::Particle),
        Self::Add(Object::Spring),
        Self::Add(Object::Rod),
        Self::Add(Object::String),
        Self::Add(Object::Ramp),
        Self::Add(Object::Body),
        Self::Delete(Object::Particle),
        Self::Delete(Object::Spring),
        Self::Delete(Object::Rod),
        Self::Delete(Object::String),
        Self::Delete(Object::Ramp),
        Self::Delete(Object::Body),
        Self::Rename,
        Self::MoveParticle,
        Self::MoveRamp,
        Self::MoveRampEnd,
        Self::MoveBody,
        Self::SetVelocity,
        Self::SetTimeScale,
        Self::SetIntegrator,
        Self::SetTimeStep,
        Self::EditFromHere,
        Self::AddGraph,
        Self::RemoveGraph,
        Self::AddSeries,
        Self::RemoveSeries,
        Self::SetXAxis,
        Self::AddExperiment,
        Self::ChangeExperiment,
        Self::RemoveExperiment,
        Self::Paste,
        Self::MoveGroup,
        Self::DeleteGroup,
        Self::Slide,
        Self::Ask,
    ];

    /// The message of its words, but for [`Edit::Set`] (whose words name the field).
    fn message(self) -> &'static str {
        match self {
            Self::Set { .. } => "edit-set",
            Self::Add(Object::Particle) => "edit-add-particle",
            Self::Add(Object::Spring) => "edit-add-spring",
            Self::Add(Object::Rod) => "edit-add-rod",
            Self::Add(Object::String) => "edit-add-string",
            Self::Add(Object::Ramp) => "edit-add-ramp",
            Self::Add(Object::Body) => "edit-add-body",
            Self::Delete(Object::Particle) => "edit-delete-particle",
            Self::Delete(Object::Spring) => "edit-delete-spring",
            Self::Delete(Object::Rod) => "edit-delete-rod",
            Self::Delete(Object::String) => "edit-delete-string",
            Self::Delete(Object::Ramp) => "edit-delete-ramp",
            Self::Delete(Object::Body) => "edit-delete-body",
            Self::Rename => "edit-rename",
            Self::MoveParticle => "edit-move-particle",
            Self::MoveRamp => "edit-move-ramp",
            Self::MoveRampEnd => "edit-move-ramp-end",
            Self::MoveBody => "edit-move-body",
            Self::SetVelocity => "edit-set-velocity",
            Self::SetTimeScale => "edit-set-time-scale",
            Self::SetIntegrator => "edit-set-integrator",
            Self::SetTimeStep => "edit-set-time-step",
            Self::EditFromHere => "edit-edit-from-here",
            Self::AddGraph => "edit-add-graph",
            Self::RemoveGraph => "edit-remove-graph",
            Self::AddSeries => "edit-add-series",
            Self::RemoveSeries => "edit-remove-series",
            Self::SetXAxis => "edit-set-x-axis",
            Self::AddExperiment => "edit-add-experiment",
            Self::ChangeExperiment => "edit-change-experiment",
            Self::RemoveExperiment => "edit-remove-experiment",
            Self::Paste => "edit-paste",
            Self::MoveGroup => "edit-move-group",
            Self::DeleteGroup => "edit-delete-group",
            Self::Slide => "edit-slide",
            Self::Ask => "edit-ask",
        }
    }

    /// What the edit did, in the language of the app ("set mass", "Masse setzen").
    pub fn words(self) -> String {
        match self {
            Self::Set { kind, key } => {
                let field = tr(&field_message(kind, key));
                tr_with("edit-set", &[("what", Arg::Text(&field))])
            }
            other => tr(other.message()),
        }
    }
}

/// The message of a field's label in the inspector (`field-particle-mass`); its help is
/// the same with `-help`. English says what the field table says (a test holds them
/// equal), German and Spanish translate it; the scene file's key stays the same.
pub fn field_message(section: &str, key: &str) -> String {
    format!("field-{section}-{}", key.replace('_', "-"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n;

    /// Every edit has its own words (every language has every message: `i18n`'s tests),
    /// and a field's edit names the field as the inspector does.
    #[test]
    fn every_edit_has_its_words() {
        for edit in Edit::ALL {
            assert!(i18n::has(edit.message()), "{edit:?} has no message");
        }
        let set = Edit::Set {
            kind: "particle",
            key: "mass",
        };
        assert!(i18n::has(&field_message("particle", "mass")), "{set:?}");
    }
}
