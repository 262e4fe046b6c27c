//! Edits that are rules of the scene rather than of any one screen: a renamed particle's
//! springs, rods, strings, forces, graphs and camera follow it; a deleted particle takes its
//! springs, rods, strings, the forces on it alone and graph series with it; a deleted body
//! takes the pins, hinges and pulleys that hold it. The app's inspector, canvas and keyboard all edit through these.

use super::{Endpoint, ObjectId, Scene, Section};

impl Scene {
    /// The name of the object of `section`, if there is one.
    pub fn name_of(&self, section: Section) -> Option<&str> {
        self.name_of_object(ObjectId::of(section)?)
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
                for on in self.forces.iter_mut().flat_map(|f| f.on.iter_mut()) {
                    if *on == old {
                        new.clone_into(on);
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
            Section::Body(i) => {
                new.clone_into(&mut self.bodies[i].name);
                self.rename_in_presentation(&old, new);
            }
            _ => {}
        }
    }

    /// Removes the objects of `sections` ([`Self::remove`] of each, found by name as the
    /// lists close up; a link a removed particle took with it is gone already).
    pub fn remove_all(&mut self, sections: &[Section]) {
        let named: Vec<(ObjectId, String)> = sections
            .iter()
            .filter_map(|&section| {
                Some((ObjectId::of(section)?, self.name_of(section)?.to_owned()))
            })
            .collect();
        for (id, name) in named {
            // The object of the same list with that name, while the list has one.
            let now = (0..)
                .map(|i| id.with_index(i))
                .map_while(|at| Some((at, self.name_of(at.section())?)))
                .find(|&(_, now)| now == name)
                .map(|(at, _)| at);
            if let Some(at) = now {
                self.remove(at.section());
            }
        }
    }

    /// Removes the object of `section`. A particle takes with it the springs attached to
    /// it and the graph series that plot it (a phase plot against it goes back to time).
    pub fn remove(&mut self, section: Section) {
        match section {
            Section::Particle(i) if i < self.particles.len() => {
                let particle = self.particles.remove(i);
                let name = particle.name;
                if let Some(instruments) = &mut self.instruments {
                    instruments.unpin(&name, particle.position);
                }
                let attached = |end: &Endpoint| matches!(end, Endpoint::Particle(n) if *n == name);
                self.springs
                    .retain(|s| !attached(&s.from) && !attached(&s.to));
                self.ties.retain(|t| !attached(&t.from) && !attached(&t.to));
                // A force on it alone goes with it (an empty list would mean every
                // particle).
                self.forces.retain_mut(|f| {
                    let named = !f.on.is_empty();
                    f.on.retain(|n| *n != name);
                    !named || !f.on.is_empty()
                });
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
            Section::Body(i) if i < self.bodies.len() => {
                let name = self.bodies.remove(i).name;
                // A joint is nothing without a body it holds: it goes with it, as a
                // spring with its particle, and so do the graphs of it.
                let holds = |joint: &super::Joint| {
                    joint.body == name || joint.other() == Some(name.as_str())
                };
                let joints: Vec<String> = self
                    .joints
                    .iter()
                    .filter(|j| holds(j))
                    .map(|j| j.name.clone())
                    .collect();
                self.joints.retain(|j| !holds(j));
                self.forget_in_presentation(&name);
                for joint in joints {
                    self.forget_in_presentation(&joint);
                }
            }
            _ => {}
        }
    }
}

impl Scene {
    /// The object of `section` alone, as a scene of its own: what Copy puts on the
    /// clipboard as scene-file text. A spring, rod or string brings the particles it ties
    /// (a rod copied from a pendulum is a pendulum), so the scene stands by itself.
    pub fn extract(&self, section: Section) -> Option<Scene> {
        let mut part = Scene {
            world: self.world.clone(),
            simulation: self.simulation.clone(),
            ..Scene::new()
        };
        let ends = |from: &Endpoint, to: &Endpoint| {
            [from, to]
                .into_iter()
                .filter_map(|end| match end {
                    Endpoint::Particle(name) => self.particles.iter().find(|p| p.name == *name),
                    Endpoint::Point(_) => None,
                })
                .cloned()
                .collect::<Vec<_>>()
        };
        match section {
            Section::Particle(i) => part.particles.push(self.particles.get(i)?.clone()),
            Section::Spring(i) => {
                let spring = self.springs.get(i)?;
                part.particles = ends(&spring.from, &spring.to);
                part.springs.push(spring.clone());
            }
            Section::Tie(i) => {
                let tie = self.ties.get(i)?;
                part.particles = ends(&tie.from, &tie.to);
                part.ties.push(tie.clone());
            }
            Section::Ramp(i) => part.ramps.push(self.ramps.get(i)?.clone()),
            Section::Body(i) => part.bodies.push(self.bodies.get(i)?.clone()),
            _ => return None,
        }
        part.particles.dedup_by(|a, b| a.name == b.name);
        Some(part)
    }

    /// The objects of `sections` together, as one scene of their own ([`Self::extract`]
    /// of each, a particle brought by several links taken once); `None` when none of them
    /// is an object of this scene.
    pub fn extract_all(&self, sections: &[Section]) -> Option<Scene> {
        let mut parts = sections.iter().filter_map(|&section| self.extract(section));
        let mut whole = parts.next()?;
        for part in parts {
            for particle in part.particles {
                if !whole.particles.iter().any(|p| p.name == particle.name) {
                    whole.particles.push(particle);
                }
            }
            whole.springs.extend(part.springs);
            whole.ties.extend(part.ties);
            whole.ramps.extend(part.ramps);
            whole.bodies.extend(part.bodies);
        }
        Some(whole)
    }

    /// Adds `other`'s particles, springs, rods, strings, ramps and bodies to this scene (not its
    /// world, settings, graphs or view), each moved by `offset` metres and renamed where
    /// its name is taken here (`ball` → `ball 2`), what ties a renamed particle following
    /// it. Returns the sections of the objects added, in this scene.
    pub fn paste(&mut self, other: &Scene, offset: glam::DVec2) -> Vec<Section> {
        let mut taken: std::collections::HashSet<String> =
            self.object_names().into_iter().map(str::to_owned).collect();
        let mut fresh = |name: &str| {
            let mut candidate = name.to_owned();
            let mut k = 2;
            while taken.contains(&candidate) {
                candidate = format!("{name} {k}");
                k += 1;
            }
            taken.insert(candidate.clone());
            candidate
        };
        let moved = |v: super::Vector| super::Vector::from(v.to_dvec2() + offset);
        let mut renamed = std::collections::HashMap::new();
        let mut added = Vec::new();
        for particle in &other.particles {
            let mut particle = particle.clone();
            let name = fresh(&particle.name);
            renamed.insert(particle.name.clone(), name.clone());
            particle.name = name;
            particle.position = moved(particle.position);
            added.push(Section::Particle(self.particles.len()));
            self.particles.push(particle);
        }
        let end = |end: &Endpoint| match end {
            Endpoint::Particle(name) => {
                Endpoint::Particle(renamed.get(name).cloned().unwrap_or_else(|| name.clone()))
            }
            Endpoint::Point(point) => Endpoint::Point(moved(*point)),
        };
        for spring in &other.springs {
            let mut spring = spring.clone();
            spring.name = fresh(&spring.name);
            (spring.from, spring.to) = (end(&spring.from), end(&spring.to));
            added.push(Section::Spring(self.springs.len()));
            self.springs.push(spring);
        }
        for tie in &other.ties {
            let mut tie = tie.clone();
            tie.name = fresh(&tie.name);
            (tie.from, tie.to) = (end(&tie.from), end(&tie.to));
            added.push(Section::Tie(self.ties.len()));
            self.ties.push(tie);
        }
        for ramp in &other.ramps {
            let mut ramp = ramp.clone();
            ramp.name = fresh(&ramp.name);
            (ramp.from, ramp.to) = (moved(ramp.from), moved(ramp.to));
            added.push(Section::Ramp(self.ramps.len()));
            self.ramps.push(ramp);
        }
        for body in &other.bodies {
            let mut body = body.clone();
            body.name = fresh(&body.name);
            body.position = moved(body.position);
            added.push(Section::Body(self.bodies.len()));
            self.bodies.push(body);
        }
        added
    }

    /// Every object's name: particles, springs, rods, strings, ramps and bodies.
    fn object_names(&self) -> Vec<&str> {
        let particles = self.particles.iter().map(|p| p.name.as_str());
        let springs = self.springs.iter().map(|s| s.name.as_str());
        let ties = self.ties.iter().map(|t| t.name.as_str());
        let ramps = self.ramps.iter().map(|r| r.name.as_str());
        let bodies = self.bodies.iter().map(|b| b.name.as_str());
        particles
            .chain(springs)
            .chain(ties)
            .chain(ramps)
            .chain(bodies)
            .collect()
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

    /// A deleted board takes the pin that held it and the hinge that hung a block from
    /// it, and the graph of the pin's angle; the block stays, and the scene is valid.
    #[test]
    fn a_deleted_body_takes_its_joints_and_their_graphs() {
        use crate::{Body, Joint};
        let mut scene = Scene::new()
            .with_body(Body::rectangle("board", 2.0, 0.1, 1.0).position([0.0, 1.0]))
            .with_body(Body::rectangle("block", 0.2, 0.2, 1.0).position([0.8, 0.7]))
            .with_body(Body::rectangle("other", 0.2, 0.2, 1.0).position([3.0, 0.7]));
        scene.joints.push(Joint::pin("nail", "board", [0.0, 1.0]));
        scene
            .joints
            .push(Joint::hinge("hook", "board", "block", [0.8, 0.95]));
        scene.joints.push(Joint::pin("peg", "other", [3.0, 0.9]));
        scene
            .graphs
            .push(Graph::of(["nail.angle", "nail.torque", "peg.angle"]).expect("quantities"));
        assert!(scene.validate().is_empty(), "{:?}", scene.validate());
        scene.remove(Section::Body(0));
        let names: Vec<&str> = scene.joints.iter().map(|j| j.name.as_str()).collect();
        assert_eq!(names, ["peg"]);
        let plotted: Vec<String> = scene.graphs[0].y.iter().map(ToString::to_string).collect();
        assert_eq!(plotted, ["peg.angle"]);
        assert!(scene.validate().is_empty(), "{:?}", scene.validate());
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

    /// Objects removed together are found by name as the lists close up: A (which takes
    /// its spring), the spring again (gone already) and C, whatever the order asked.
    #[test]
    fn objects_removed_together_are_each_the_one_asked_for() {
        let mut scene = two_balls().with_particle(Particle::new("C", 1.0).position([2.0, 0.0]));
        scene.remove_all(&[
            Section::Particle(0),
            Section::Spring(0),
            Section::Particle(2),
        ]);
        let names: Vec<&str> = scene.particles.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["B"]);
        assert!(scene.springs.is_empty());
    }

    /// Objects copied together make one scene, a particle two links tie taken once.
    #[test]
    fn objects_copied_together_make_one_scene() {
        let scene = two_balls().with_spring(Spring::new("s2", "B", "A", 2.0, 1.0));
        let part = scene
            .extract_all(&[Section::Spring(0), Section::Spring(1)])
            .expect("objects");
        let names: Vec<&str> = part.particles.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["A", "B"]);
        assert_eq!(part.springs.len(), 2);
        assert!(scene.extract_all(&[]).is_none());
    }

    /// A rod copied from a pendulum is a pendulum: pasted into the same scene, its bob
    /// comes along renamed, the rod ties the new bob, and both are moved by the offset;
    /// the scene is valid.
    #[test]
    fn a_copied_rod_pastes_as_a_new_pendulum() {
        let scene = Scene::new()
            .with_particle(Particle::new("bob", 1.0).position([0.0, -2.0]))
            .with_tie(crate::Tie::rod("rod", [0.0, 0.0], "bob", 2.0));
        let part = scene.extract(Section::Tie(0)).expect("an object");
        let text = part.to_toml();
        let mut pasted = scene.clone();
        let added = pasted.paste(
            &Scene::from_toml(&text).expect("scene-file text"),
            glam::DVec2::new(1.0, 0.0),
        );
        assert_eq!(added, [Section::Particle(1), Section::Tie(1)]);
        assert_eq!(pasted.particles[1].name, "bob 2");
        assert_eq!(
            pasted.particles[1].position.to_dvec2(),
            glam::DVec2::new(1.0, -2.0)
        );
        assert_eq!(pasted.ties[1].name, "rod 2");
        assert_eq!(pasted.ties[1].to, "bob 2".into());
        assert_eq!(
            pasted.ties[1].from,
            crate::Endpoint::Point([1.0, 0.0].into())
        );
        assert!(pasted.validate().is_empty(), "{:?}", pasted.validate());
    }
}
