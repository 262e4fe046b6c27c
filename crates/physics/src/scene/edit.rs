//! Edits that are rules of the scene rather than of any one screen: a renamed particle's
//! springs, rods, strings, graphs and camera follow it; a deleted particle takes its
//! springs, rods, strings and graph series with it. The app's inspector, canvas and keyboard all edit through these.

use super::{Endpoint, Scene, Section};

impl Scene {
    /// The name of the object of `section`, if there is one.
    pub fn name_of(&self, section: Section) -> Option<&str> {
        match section {
            Section::Particle(i) => self.particles.get(i).map(|p| p.name.as_str()),
            Section::Spring(i) => self.springs.get(i).map(|s| s.name.as_str()),
            Section::Tie(i) => self.ties.get(i).map(|t| t.name.as_str()),
            Section::Ramp(i) => self.ramps.get(i).map(|r| r.name.as_str()),
            _ => None,
        }
    }

    /// Renames the object of `section`; everything that names a renamed particle (spring
    /// ends, graph series, the camera) follows it. Nothing happens for a section that is
    /// not an object.
    pub fn rename(&mut self, section: Section, new: &str) {
        let Some(old) = self.name_of(section).map(str::to_owned) else {
            return;
        };
        match section {
            Section::Particle(i) => {
                new.clone_into(&mut self.particles[i].name);
                let ends = self.springs.iter_mut().map(|s| [&mut s.from, &mut s.to]);
                let tie_ends = self.ties.iter_mut().map(|t| [&mut t.from, &mut t.to]);
                for end in ends.chain(tie_ends).flatten() {
                    if matches!(end, Endpoint::Particle(name) if *name == old) {
                        *end = Endpoint::Particle(new.to_owned());
                    }
                }
                self.rename_in_presentation(&old, new);
            }
            Section::Spring(i) => new.clone_into(&mut self.springs[i].name),
            Section::Tie(i) => {
                new.clone_into(&mut self.ties[i].name);
                self.rename_in_presentation(&old, new);
            }
            Section::Ramp(i) => new.clone_into(&mut self.ramps[i].name),
            _ => {}
        }
    }

    /// Removes the object of `section`. A particle takes with it the springs attached to
    /// it and the graph series that plot it (a phase plot against it goes back to time).
    pub fn remove(&mut self, section: Section) {
        match section {
            Section::Particle(i) if i < self.particles.len() => {
                let name = self.particles.remove(i).name;
                let attached = |end: &Endpoint| matches!(end, Endpoint::Particle(n) if *n == name);
                self.springs
                    .retain(|s| !attached(&s.from) && !attached(&s.to));
                self.ties.retain(|t| !attached(&t.from) && !attached(&t.to));
                self.forget_in_presentation(&name);
            }
            Section::Spring(i) if i < self.springs.len() => {
                self.springs.remove(i);
            }
            Section::Tie(i) if i < self.ties.len() => {
                let name = self.ties.remove(i).name;
                self.forget_in_presentation(&name);
            }
            Section::Ramp(i) if i < self.ramps.len() => {
                self.ramps.remove(i);
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::{Follow, Graph, Particle, Quantity, Scene, Section, Spring, View};

    fn two_balls() -> Scene {
        let mut scene = Scene::new()
            .with_particle(Particle::new("A", 1.0))
            .with_particle(Particle::new("B", 1.0).position([1.0, 0.0]))
            .with_spring(Spring::new("s1", "A", "B", 1.0, 1.0));
        let mut graph = Graph::of(["A.vx", "B.y"]).expect("quantities");
        graph.x = Quantity::parse("A.x").expect("a quantity");
        scene.graphs.push(graph);
        scene.view = Some(View {
            follow: Some(Follow::Particle("A".to_owned())),
            ..View::default()
        });
        scene
    }

    #[test]
    fn a_renamed_particle_is_followed_by_its_springs_graphs_and_camera() {
        let mut scene = two_balls();
        scene.rename(Section::Particle(0), "C");
        assert_eq!(scene.springs[0].from, "C".into());
        let names = |graph: &Graph| {
            (
                graph.x.to_string(),
                graph.y.iter().map(ToString::to_string).collect::<Vec<_>>(),
            )
        };
        assert_eq!(
            names(&scene.graphs[0]),
            ("C.x".to_owned(), vec!["C.vx".to_owned(), "B.y".to_owned()])
        );
        assert_eq!(
            scene.view.unwrap().follow,
            Some(Follow::Particle("C".to_owned()))
        );
    }

    #[test]
    fn a_deleted_particle_takes_its_springs_and_series() {
        let mut scene = two_balls();
        scene.remove(Section::Particle(0));
        assert!(scene.springs.is_empty());
        assert_eq!(scene.graphs[0].x, Quantity::Time);
        assert_eq!(
            scene.graphs[0].y,
            [Quantity::parse("B.y").expect("a quantity")]
        );
        assert_eq!(scene.view.as_ref().unwrap().follow, None);
        assert!(scene.validate().is_empty());
    }
}
