//! Which object of a scene: one identity, [`ObjectId`] (its list and its index there),
//! and one name for each kind, [`ObjectKind`] (the scene file's table). The scene's
//! sections, its editing rules and Python's objects find and name objects through them,
//! so a new kind of object is one variant here and one arm in each function below.

use super::{Scene, Section, TieKind};
use crate::JointKind;

/// One object of a scene, by its list and its index in that list (file order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ObjectId {
    /// `[[particle]]`.
    Particle(usize),
    /// `[[spring]]`.
    Spring(usize),
    /// `[[rod]]` or `[[string]]`, in [`Scene::ties`].
    Tie(usize),
    /// `[[ramp]]`.
    Ramp(usize),
    /// `[[body]]`.
    Body(usize),
    /// `[[pin]]`, `[[hinge]]` or `[[pulley]]`, in [`Scene::joints`].
    Joint(usize),
    /// `[[force]]`.
    Force(usize),
}

/// What kind an object is, as the scene file names its table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ObjectKind {
    /// `[[particle]]`.
    Particle,
    /// `[[spring]]`.
    Spring,
    /// `[[rod]]`.
    Rod,
    /// `[[string]]`.
    String,
    /// `[[ramp]]`.
    Ramp,
    /// `[[body]]`.
    Body,
    /// `[[pin]]`.
    Pin,
    /// `[[hinge]]`.
    Hinge,
    /// `[[pulley]]`.
    Pulley,
    /// `[[force]]`.
    Force,
}

impl ObjectKind {
    /// Every kind, in the order a scene file writes them.
    pub const ALL: [Self; 10] = [
        Self::Particle,
        Self::Spring,
        Self::Rod,
        Self::String,
        Self::Ramp,
        Self::Body,
        Self::Pin,
        Self::Hinge,
        Self::Pulley,
        Self::Force,
    ];

    /// The scene file's table name: `particle`, `rod`, `pulley`, …
    pub const fn as_str(self) -> &'static str {
        match self {
            Self::Particle => "particle",
            Self::Spring => "spring",
            Self::Rod => TieKind::Rod.as_str(),
            Self::String => TieKind::String.as_str(),
            Self::Ramp => "ramp",
            Self::Body => "body",
            Self::Pin => "pin",
            Self::Hinge => "hinge",
            Self::Pulley => "pulley",
            Self::Force => "force",
        }
    }

    /// The object `i` of the list that holds this kind (a rod and a string share the
    /// ties, a pin, a hinge and a pulley the joints).
    pub const fn at(self, i: usize) -> ObjectId {
        match self {
            Self::Particle => ObjectId::Particle(i),
            Self::Spring => ObjectId::Spring(i),
            Self::Rod | Self::String => ObjectId::Tie(i),
            Self::Ramp => ObjectId::Ramp(i),
            Self::Body => ObjectId::Body(i),
            Self::Pin | Self::Hinge | Self::Pulley => ObjectId::Joint(i),
            Self::Force => ObjectId::Force(i),
        }
    }
}

impl ObjectId {
    /// The object a section of the file is, if it is one.
    pub const fn of(section: Section) -> Option<Self> {
        match section {
            Section::Particle(i) => Some(Self::Particle(i)),
            Section::Spring(i) => Some(Self::Spring(i)),
            Section::Tie(i) => Some(Self::Tie(i)),
            Section::Ramp(i) => Some(Self::Ramp(i)),
            Section::Body(i) => Some(Self::Body(i)),
            Section::Joint(i) => Some(Self::Joint(i)),
            Section::Force(i) => Some(Self::Force(i)),
            _ => None,
        }
    }

    /// The section of the file the object is.
    pub const fn section(self) -> Section {
        match self {
            Self::Particle(i) => Section::Particle(i),
            Self::Spring(i) => Section::Spring(i),
            Self::Tie(i) => Section::Tie(i),
            Self::Ramp(i) => Section::Ramp(i),
            Self::Body(i) => Section::Body(i),
            Self::Joint(i) => Section::Joint(i),
            Self::Force(i) => Section::Force(i),
        }
    }

    /// Its index in its list.
    pub const fn index(self) -> usize {
        match self {
            Self::Particle(i)
            | Self::Spring(i)
            | Self::Tie(i)
            | Self::Ramp(i)
            | Self::Body(i)
            | Self::Joint(i)
            | Self::Force(i) => i,
        }
    }

    /// The object at index `i` of the same list.
    #[must_use]
    pub const fn with_index(self, i: usize) -> Self {
        match self {
            Self::Particle(_) => Self::Particle(i),
            Self::Spring(_) => Self::Spring(i),
            Self::Tie(_) => Self::Tie(i),
            Self::Ramp(_) => Self::Ramp(i),
            Self::Body(_) => Self::Body(i),
            Self::Joint(_) => Self::Joint(i),
            Self::Force(_) => Self::Force(i),
        }
    }
}

/// What kind of section a field belongs to: an object's kind, or one of the scene's
/// own sections. It names the field's words in the app (`field-particle-mass`) and an
/// edit of a field in its history.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SectionKind {
    /// An object's table: `[[particle]]`, `[[rod]]`, …
    Object(ObjectKind),
    /// `[world]`.
    World,
    /// `[simulation]`.
    Simulation,
    /// A `[[graph]]`.
    Graph,
    /// A `[[series]]`.
    Series,
    /// The file's top level, its view and its instruments.
    Scene,
    /// The lesson, its sliders and its questions.
    Lesson,
}

impl SectionKind {
    /// The section's word in the scene file and in the app's messages.
    pub const fn as_str(self) -> &'static str {
        match self {
            Self::Object(kind) => kind.as_str(),
            Self::World => "world",
            Self::Simulation => "simulation",
            Self::Graph => "graph",
            Self::Series => "series",
            Self::Scene => "scene",
            Self::Lesson => "lesson",
        }
    }
}

impl Scene {
    /// What kind of section `section` is; an object missing from the scene is the kind
    /// its list first holds (a rod, a pin).
    pub fn section_kind(&self, section: Section) -> SectionKind {
        if let Some(id) = ObjectId::of(section) {
            let first_of_its_list = || {
                let list = id.with_index(0);
                ObjectKind::ALL.into_iter().find(|kind| kind.at(0) == list)
            };
            if let Some(kind) = self.kind_of(id).or_else(first_of_its_list) {
                return SectionKind::Object(kind);
            }
        }
        match section {
            Section::World => SectionKind::World,
            Section::Simulation => SectionKind::Simulation,
            Section::Graph(_) => SectionKind::Graph,
            Section::Series(_) => SectionKind::Series,
            Section::Lesson | Section::Slider(_) | Section::Question(_) => SectionKind::Lesson,
            _ => SectionKind::Scene,
        }
    }

    /// The name of object `id`; `None` when the scene has no such object.
    pub fn name_of_object(&self, id: ObjectId) -> Option<&str> {
        let i = id.index();
        match id {
            ObjectId::Particle(_) => self.particles.get(i).map(|p| p.name.as_str()),
            ObjectId::Spring(_) => self.springs.get(i).map(|s| s.name.as_str()),
            ObjectId::Tie(_) => self.ties.get(i).map(|t| t.name.as_str()),
            ObjectId::Ramp(_) => self.ramps.get(i).map(|r| r.name.as_str()),
            ObjectId::Body(_) => self.bodies.get(i).map(|b| b.name.as_str()),
            ObjectId::Joint(_) => self.joints.get(i).map(|j| j.name.as_str()),
            ObjectId::Force(_) => self.forces.get(i).map(|f| f.name.as_str()),
        }
    }

    /// What kind object `id` is; `None` when the scene has no such object.
    pub fn kind_of(&self, id: ObjectId) -> Option<ObjectKind> {
        let i = id.index();
        Some(match id {
            ObjectId::Particle(_) => self.particles.get(i).map(|_| ObjectKind::Particle)?,
            ObjectId::Spring(_) => self.springs.get(i).map(|_| ObjectKind::Spring)?,
            ObjectId::Tie(_) => match self.ties.get(i)?.kind {
                TieKind::Rod => ObjectKind::Rod,
                TieKind::String => ObjectKind::String,
            },
            ObjectId::Ramp(_) => self.ramps.get(i).map(|_| ObjectKind::Ramp)?,
            ObjectId::Body(_) => self.bodies.get(i).map(|_| ObjectKind::Body)?,
            ObjectId::Joint(_) => match self.joints.get(i)?.kind {
                JointKind::Pin => ObjectKind::Pin,
                JointKind::Hinge { .. } => ObjectKind::Hinge,
                JointKind::Pulley { .. } => ObjectKind::Pulley,
            },
            ObjectId::Force(_) => self.forces.get(i).map(|_| ObjectKind::Force)?,
        })
    }

    /// Every object of `kind`, in file order, with its name.
    pub fn objects_of(&self, kind: ObjectKind) -> Vec<(ObjectId, &str)> {
        (0..)
            .map(|i| kind.at(i))
            .map_while(|id| Some((id, self.name_of_object(id)?)))
            .filter(|&(id, _)| self.kind_of(id) == Some(kind))
            .collect()
    }

    /// The object of `kind` called `name`.
    pub fn find_object(&self, kind: ObjectKind, name: &str) -> Option<ObjectId> {
        self.objects_of(kind)
            .into_iter()
            .find(|&(_, n)| n == name)
            .map(|(id, _)| id)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Particle, Spring, Tie};

    fn scene() -> Scene {
        Scene::new()
            .with_particle(Particle::new("A", 1.0))
            .with_particle(Particle::new("B", 1.0).position([1.0, 0.0]))
            .with_spring(Spring::new("s", "A", "B", 10.0, 1.0))
            .with_tie(Tie::string("cord", "A", "B", 2.0))
            .with_tie(Tie::rod("bar", "A", "B", 1.0))
    }

    /// Every object's identity goes to its section and back, and names it; a rod and a
    /// string share the ties but are found by their own kind.
    #[test]
    fn an_object_is_found_by_kind_and_name_and_named_back() {
        let scene = scene();
        assert_eq!(
            scene.find_object(ObjectKind::Rod, "bar"),
            Some(ObjectId::Tie(1))
        );
        assert_eq!(scene.find_object(ObjectKind::String, "bar"), None);
        assert_eq!(
            scene.find_object(ObjectKind::String, "cord"),
            Some(ObjectId::Tie(0))
        );
        assert_eq!(scene.kind_of(ObjectId::Tie(0)), Some(ObjectKind::String));
        assert_eq!(scene.kind_of(ObjectId::Particle(2)), None);
        let particles: Vec<&str> = scene
            .objects_of(ObjectKind::Particle)
            .into_iter()
            .map(|(_, name)| name)
            .collect();
        assert_eq!(particles, ["A", "B"]);
        for kind in ObjectKind::ALL {
            for (id, name) in scene.objects_of(kind) {
                assert_eq!(ObjectId::of(id.section()), Some(id));
                assert_eq!(scene.name_of_object(id), Some(name));
                assert_eq!(id.with_index(id.index()), id);
            }
        }
        assert_eq!(ObjectId::of(Section::World), None);
    }
}
