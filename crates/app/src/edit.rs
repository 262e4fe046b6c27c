//! The undoable edits: what each change of the scene was, for the undo history and the
//! words Edit → Undo and Redo show. A type, not a string, so that every edit has its
//! words in every language (a test asks each language for each kind).

use std::borrow::Cow;

use physics::{ObjectKind, SectionKind};

use crate::i18n::{Arg, tr, tr_with};

/// One undoable change of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edit {
    /// A field typed in the inspector or the settings: the kind of its section and the
    /// scene file's key.
    Set {
        section: SectionKind,
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
    /// Every edit but [`Edit::Set`]'s fields and those of each kind of object
    /// ([`Edit::Add`], [`Edit::Delete`]), for the tests.
    #[cfg(test)]
    const OTHERS: [Self; 23] = [
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

    /// The message of its words, but for [`Edit::Set`] (whose words name the field):
    /// an object added or deleted is `edit-add-KIND`, `edit-delete-KIND` by the file's
    /// table name.
    fn message(self) -> Cow<'static, str> {
        Cow::Borrowed(match self {
            Self::Set { .. } => "edit-set",
            Self::Add(kind) => return Cow::Owned(format!("edit-add-{}", kind.as_str())),
            Self::Delete(kind) => return Cow::Owned(format!("edit-delete-{}", kind.as_str())),
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
        })
    }

    /// What the edit did, in the language of the app ("set mass", "Masse setzen").
    pub fn words(self) -> String {
        match self {
            Self::Set { section, key } => {
                let field = tr(&field_message(section, key));
                tr_with("edit-set", &[("what", Arg::Text(&field))])
            }
            other => tr(&other.message()),
        }
    }
}

/// The message of a field's label in the inspector (`field-particle-mass`); its help is
/// the same with `-help`. English says what the field table says (a test holds them
/// equal), German and Spanish translate it; the scene file's key stays the same.
pub fn field_message(section: SectionKind, key: &str) -> String {
    format!("field-{}-{}", section.as_str(), key.replace('_', "-"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n;

    /// Every edit has its own words (every language has every message: `i18n`'s tests),
    /// and a field's edit names the field as the inspector does.
    #[test]
    fn every_edit_has_its_words() {
        let objects = ObjectKind::ALL
            .into_iter()
            .flat_map(|kind| [Edit::Add(kind), Edit::Delete(kind)]);
        for edit in objects.chain(Edit::OTHERS) {
            assert!(i18n::has(&edit.message()), "{edit:?} has no message");
        }
        let section = SectionKind::Object(ObjectKind::Particle);
        let set = Edit::Set {
            section,
            key: "mass",
        };
        assert!(i18n::has(&field_message(section, "mass")), "{set:?}");
    }
}
