//! The scene being edited, with unlimited undo and redo, the file it belongs to, and
//! whether it has changed since it was saved.
//!
//! Every change goes through [`Document::apply`], which keeps the scene as it was before:
//! undo is a stack of whole scenes. A scene is small (a thousand particles are ~100 kB),
//! so snapshots cost little and can never get out of step with the change they undo,
//! as inverse commands can. A drag is one gesture: one undo step however many frames
//! it moves things.

use physics::Scene;

use crate::edit::Edit;

#[derive(Clone, Debug)]
pub struct Document {
    scene: Scene,
    /// (what the change was, the scene before it)
    undo: Vec<(Edit, Scene)>,
    redo: Vec<(Edit, Scene)>,
    /// The file name (a path on the desktop, a name on the web), if saved or opened.
    pub path: Option<String>,
    /// What to call a scene that has no file (an example's title).
    pub label: Option<String>,
    /// The file's modification time and length when last opened or saved here.
    pub disk: Option<(std::time::SystemTime, u64)>,
    /// The scene as last saved or opened, to tell whether there are unsaved changes.
    saved: Scene,
    /// A gesture (a drag) in progress: its first change made the undo step.
    gesture: bool,
}

impl Document {
    /// A document for `scene`, unchanged and without a file.
    pub fn new(scene: Scene) -> Self {
        Self {
            saved: scene.clone(),
            scene,
            undo: Vec::new(),
            redo: Vec::new(),
            path: None,
            label: None,
            disk: None,
            gesture: false,
        }
    }

    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Changes the scene as one undoable step, `edit`.
    pub fn apply(&mut self, edit: Edit, change: impl FnOnce(&mut Scene)) {
        if !self.gesture {
            self.undo.push((edit, self.scene.clone()));
        }
        change(&mut self.scene);
        self.redo.clear();
    }

    /// Starts a gesture: the changes until [`Self::end_gesture`] undo as one step.
    pub fn begin_gesture(&mut self, edit: Edit) {
        if !self.gesture {
            self.undo.push((edit, self.scene.clone()));
            self.redo.clear();
            self.gesture = true;
        }
    }

    /// Ends a gesture; one that changed nothing leaves no undo step.
    pub fn end_gesture(&mut self) {
        if self.gesture {
            self.gesture = false;
            if self
                .undo
                .last()
                .is_some_and(|(_, before)| *before == self.scene)
            {
                self.undo.pop();
            }
        }
    }

    pub fn in_gesture(&self) -> bool {
        self.gesture
    }

    /// What Undo would undo.
    pub fn undo_edit(&self) -> Option<Edit> {
        self.undo.last().map(|&(edit, _)| edit)
    }

    /// What Redo would redo.
    pub fn redo_edit(&self) -> Option<Edit> {
        self.redo.last().map(|&(edit, _)| edit)
    }

    pub fn undo(&mut self) -> bool {
        self.end_gesture();
        let Some((label, before)) = self.undo.pop() else {
            return false;
        };
        let now = std::mem::replace(&mut self.scene, before);
        self.redo.push((label, now));
        true
    }

    pub fn redo(&mut self) -> bool {
        let Some((label, after)) = self.redo.pop() else {
            return false;
        };
        let now = std::mem::replace(&mut self.scene, after);
        self.undo.push((label, now));
        true
    }

    /// Whether the scene differs from the one last saved or opened.
    pub fn is_dirty(&self) -> bool {
        self.scene != self.saved
    }

    /// Marks the whole scene as unsaved work belonging to `path` (recovered after a
    /// crash): saving is needed to keep it.
    pub fn mark_unsaved(&mut self, path: Option<String>) {
        self.saved = Scene::new();
        if self.saved == self.scene {
            self.saved.name = Some(String::new());
        }
        self.path = path;
    }

    /// Records that the scene was saved to `path`.
    pub fn mark_saved(&mut self, path: String) {
        self.saved = self.scene.clone();
        self.path = Some(path);
    }

    /// The file's name without its folders, or the label, or "untitled".
    pub fn title(&self) -> String {
        match (&self.path, &self.label) {
            (Some(p), _) => p.rsplit(['/', '\\']).next().unwrap_or(p).to_owned(),
            (None, Some(label)) => label.clone(),
            (None, None) => "untitled".to_owned(),
        }
    }

    /// Sets the scene's `[view]` (the camera, when saving) without an undo step: moving
    /// the camera is not an edit.
    pub fn set_view(&mut self, view: physics::View) {
        self.scene.view = Some(view);
    }

    /// Sets the scene's `[instruments]` (when saving or sharing) without an undo step:
    /// laying a tape is a measurement, not an edit.
    pub fn set_instruments(&mut self, instruments: Option<physics::Instruments>) {
        self.scene.instruments = instruments;
    }

    /// A name not used by any object, `prefix` followed by the smallest free number.
    pub fn unused_name(&self, prefix: &str) -> String {
        let scene = &self.scene;
        let taken = |name: &str| {
            scene.particles.iter().any(|p| p.name == name)
                || scene.springs.iter().any(|s| s.name == name)
                || scene.ties.iter().any(|t| t.name == name)
                || scene.ramps.iter().any(|r| r.name == name)
                || scene.bodies.iter().any(|b| b.name == name)
        };
        // Some number up to one past the count of objects is always free.
        let count = scene.particles.len()
            + scene.springs.len()
            + scene.ties.len()
            + scene.ramps.len()
            + scene.bodies.len();
        (1..=count + 1)
            .map(|n| format!("{prefix}{n}"))
            .find(|name| !taken(name))
            .unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use physics::ObjectKind;
    use physics::Particle;

    /// Names are unique among all objects, bodies too: a particle placed beside a body
    /// called `p1` is not called `p1`.
    #[test]
    fn a_new_name_is_free_among_bodies_too() {
        let mut scene = Scene::new();
        scene
            .bodies
            .push(physics::Body::rectangle("p1", 0.4, 0.2, 1.0));
        let document = Document::new(scene);
        assert_eq!(document.unused_name("p"), "p2");
    }

    #[test]
    fn undo_and_redo_without_limit() {
        let mut document = Document::new(Scene::new());
        for i in 0..500 {
            document.apply(Edit::Add(ObjectKind::Particle), |scene| {
                scene.particles.push(Particle::new(format!("p{i}"), 1.0));
            });
        }
        assert!(document.is_dirty(), "changed");
        while document.undo() {}
        assert_eq!(document.scene().particles.len(), 0, "all undone");
        assert!(!document.is_dirty(), "back to the saved scene");
        while document.redo() {}
        assert_eq!(document.scene().particles.len(), 500, "all redone");
    }

    #[test]
    fn a_gesture_is_one_step_and_a_new_change_clears_redo() {
        let mut document = Document::new(Scene::new().with_particle(Particle::new("a", 1.0)));
        document.begin_gesture(Edit::MoveParticle);
        for x in 0..10 {
            document.apply(Edit::MoveParticle, |scene| {
                scene.particles[0].position = [f64::from(x), 0.0].into();
            });
        }
        document.end_gesture();
        document.undo();
        assert_eq!(
            document.scene().particles[0].position,
            [0.0, 0.0].into(),
            "one step"
        );
        document.apply(Edit::Rename, |scene| scene.particles[0].name = "b".into());
        assert!(!document.redo(), "redo cleared by a new change");
        document.begin_gesture(Edit::MoveRamp);
        document.end_gesture();
        assert_eq!(
            document.undo_edit(),
            Some(Edit::Rename),
            "an empty gesture leaves no step"
        );
    }
}
