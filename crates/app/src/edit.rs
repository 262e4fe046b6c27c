//! The undoable edits: what each change of the scene was, for the undo history and the
//! words Edit → Undo and Redo show. A type, not a string, so that every edit has its
//! words in every language (a test asks each language for each kind).

use physics::ObjectKind;

use crate::i18n::{Arg, tr, tr_with};

/// One undoable change of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edit {
    /// A field typed in the inspector or the settings: the section's kind (`particle`,
    /// `world`, …) and the scene file's key.
    Set {
        kind: &'static str,
        key: &'static str,
    },
    Add(ObjectKind),
    Delete(ObjectKind),
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
    const ALL: [Self; 43] = [
        Self::Add(ObjectKind::Particle),
        Self::Add(ObjectKind::Spring),
        Self::Add(ObjectKind::Rod),
        Self::Add(ObjectKind::String),
        Self::Add(ObjectKind::Ramp),
        Self::Add(ObjectKind::Body),
        Self::Add(ObjectKind::Pin),
        Self::Add(ObjectKind::Hinge),
        Self::Add(ObjectKind::Pulley),
        Self::Add(ObjectKind::Force),
        Self::Delete(ObjectKind::Particle),
        Self::Delete(ObjectKind::Spring),
        Self::Delete(ObjectKind::Rod),
        Self::Delete(ObjectKind::String),
        Self::Delete(ObjectKind::Ramp),
        Self::Delete(ObjectKind::Body),
        Self::Delete(ObjectKind::Pin),
        Self::Delete(ObjectKind::Hinge),
        Self::Delete(ObjectKind::Pulley),
        Self::Delete(ObjectKind::Force),
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
            Self::Add(ObjectKind::Particle) => "edit-add-particle",
            Self::Add(ObjectKind::Spring) => "edit-add-spring",
            Self::Add(ObjectKind::Rod) => "edit-add-rod",
            Self::Add(ObjectKind::String) => "edit-add-string",
            Self::Add(ObjectKind::Ramp) => "edit-add-ramp",
            Self::Add(ObjectKind::Body) => "edit-add-body",
            Self::Add(ObjectKind::Pin) => "edit-add-pin",
            Self::Add(ObjectKind::Hinge) => "edit-add-hinge",
            Self::Add(ObjectKind::Pulley) => "edit-add-pulley",
            Self::Add(ObjectKind::Force) => "edit-add-force",
            Self::Delete(ObjectKind::Particle) => "edit-delete-particle",
            Self::Delete(ObjectKind::Spring) => "edit-delete-spring",
            Self::Delete(ObjectKind::Rod) => "edit-delete-rod",
            Self::Delete(ObjectKind::String) => "edit-delete-string",
            Self::Delete(ObjectKind::Ramp) => "edit-delete-ramp",
            Self::Delete(ObjectKind::Body) => "edit-delete-body",
            Self::Delete(ObjectKind::Pin) => "edit-delete-pin",
            Self::Delete(ObjectKind::Hinge) => "edit-delete-hinge",
            Self::Delete(ObjectKind::Pulley) => "edit-delete-pulley",
            Self::Delete(ObjectKind::Force) => "edit-delete-force",
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
