//! The rules every scene obeys, checked on the plain data so that a scene built in code,
//! edited in the app or loaded from a file is judged the same way. The file loader adds
//! the problems only a file can have (syntax, unknown keys, wrong types) and the line
//! and column of each problem.

use std::collections::HashMap;

use super::error::{FieldRef, Problem, Section};
use super::fields::{self, Field, Kind, Value};
use super::{Color, Endpoint, Follow, Scene, Vector, say, say_numbers};
use crate::quantity::{LinkOf, Quantity};

mod bodies;
mod forces;
mod joints;

/// How far into a wall of the bounds a particle may start, as a fraction of its radius.
const WALL_OVERLAP: f64 = 0.1;

impl Scene {
    /// Every problem with this scene, in file order; empty when it is valid.
    pub fn validate(&self) -> Vec<Problem> {
        let mut check = Checker {
            scene: self,
            names: self.particle_indices(),
            problems: Vec::new(),
        };
        check.world();
        check.settings();
        check.names();
        check.particles();
        check.springs();
        check.ties();
        check.ramps();
        check.bodies();
        check.joints();
        check.forces();
        check.graphs();
        check.series();
        check.coincident();
        check.view();
        check.lesson();
        check.instruments();
        check.problems
    }

    /// How a problem in `section` is introduced in a message: `particle 'B'`.
    pub fn describe(&self, section: Section) -> String {
        fn named(kind: &str, name: Option<&str>, index: usize) -> String {
            match name {
                Some(name) if !name.is_empty() => {
                    say("scene-named", &[("kind", kind), ("name", name)])
                }
                _ => numbered(kind, index),
            }
        }
        match section {
            Section::Root => say("scene-the-scene", &[]),
            Section::World => "[world]".to_owned(),
            Section::Simulation => "[simulation]".to_owned(),
            Section::Particle(i) => named(
                "particle",
                self.particles.get(i).map(|p| p.name.as_str()),
                i,
            ),
            Section::Spring(i) => named("spring", self.springs.get(i).map(|s| s.name.as_str()), i),
            Section::Tie(i) => match self.ties.get(i) {
                Some(tie) => named(tie.kind.as_str(), Some(&tie.name), i),
                None => named("rod", None, i),
            },
            Section::Ramp(i) => named("ramp", self.ramps.get(i).map(|r| r.name.as_str()), i),
            Section::Body(i) => named("body", self.bodies.get(i).map(|b| b.name.as_str()), i),
            Section::Joint(i) => match self.joints.get(i) {
                Some(joint) => named(joint.kind_str(), Some(&joint.name), i),
                None => named("pin", None, i),
            },
            Section::Force(i) => named("force", self.forces.get(i).map(|f| f.name.as_str()), i),
            Section::Graph(i) => named(
                "graph",
                self.graphs.get(i).and_then(|g| g.title.as_deref()),
                i,
            ),
            Section::Series(i) => numbered("series", i),
            Section::View => "[view]".to_owned(),
            Section::Instruments => "[instruments]".to_owned(),
            Section::Stopwatch => "[instruments.stopwatch]".to_owned(),
            Section::Lesson => "[lesson]".to_owned(),
            Section::Slider(i) => numbered("slider", i),
            Section::Question(i) => named(
                "question",
                self.lesson
                    .as_ref()
                    .and_then(|l| l.questions.get(i))
                    .map(|q| q.id.as_str()),
                i,
            ),
        }
    }
}

/// What is wrong with a static coefficient of friction beside the kinetic `friction`:
/// negative, not finite, or below it.
pub(crate) fn static_problem(value: Option<f64>, friction: f64) -> Option<String> {
    let value = value?;
    if let Err(reason) = check_value(Rule::NonNegative, "static_friction", value) {
        return Some(reason);
    }
    (value < friction).then(|| {
        say(
            "scene-body-static-friction",
            &[
                ("static", &value.to_string()),
                ("kinetic", &friction.to_string()),
            ],
        )
    })
}

/// `kind #n` (1-based): an object without a name.
pub(crate) fn numbered(kind: &str, index: usize) -> String {
    say(
        "scene-numbered",
        &[("kind", kind), ("number", &(index + 1).to_string())],
    )
}

/// Checks a single typed value, as the app's inspector does before applying it.
///
/// # Errors
/// The reason, in the words of a full validation message without the object's name.
pub fn check_value(rule: Rule, field: &str, value: f64) -> Result<(), String> {
    let broken = |id| Err(say(id, &[("field", field), ("value", &value.to_string())]));
    if !value.is_finite() {
        return broken("scene-not-finite");
    }
    check_magnitude(field, value)?;
    match rule {
        Rule::Positive if value <= 0.0 => broken("scene-not-positive"),
        Rule::NonNegative if value < 0.0 => broken("scene-negative"),
        Rule::Fraction if !(0.0..=1.0).contains(&value) => broken("scene-not-fraction"),
        _ => Ok(()),
    }
}

/// The largest magnitude of any number in a scene. Forces multiply up to three inputs
/// (G m₁ m₂ / r², k q₁ q₂ / r²) and energies square speeds: with every input within
/// 10⁻¹⁰⁰ … 10¹⁰⁰ every such product stays inside the range of f64, so no force or
/// energy overflows to infinity or vanishes into zero.
pub const LARGEST_MAGNITUDE: f64 = 1e100;
/// The smallest non-zero magnitude of any number in a scene (a vector's components may be
/// smaller: positions and velocities multiply into no product); see
/// [`LARGEST_MAGNITUDE`].
pub const SMALLEST_MAGNITUDE: f64 = 1e-100;

/// A value (finite) is 0 or of a magnitude NewtonLab simulates reliably.
fn check_magnitude(field: &str, value: f64) -> Result<(), String> {
    let size = value.abs();
    if size == 0.0 || (SMALLEST_MAGNITUDE..=LARGEST_MAGNITUDE).contains(&size) {
        return Ok(());
    }
    let id = if size > LARGEST_MAGNITUDE {
        "scene-too-large"
    } else {
        "scene-too-small"
    };
    Err(say(
        id,
        &[("field", field), ("value", &format!("{value:e}"))],
    ))
}

/// What a number field must satisfy.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// Any finite number.
    Finite,
    /// Finite and > 0.
    Positive,
    /// Finite and >= 0.
    NonNegative,
    /// Finite and in 0..=1.
    Fraction,
}

struct Checker<'a> {
    scene: &'a Scene,
    /// The scene's particles by name ([`Scene::particle_indices`]): a scene with S
    /// springs and N particles would otherwise cost S × N comparisons to check.
    names: std::collections::HashMap<&'a str, usize>,
    problems: Vec<Problem>,
}

impl Checker<'_> {
    /// The index of the particle called `name`, as [`Scene::particle_index`] finds it.
    fn particle_index(&self, name: &str) -> Option<usize> {
        self.names.get(name).copied()
    }

    fn report(&mut self, section: Section, field: &'static str, reason: &str) {
        let message = format!("{}: {reason}", self.scene.describe(section));
        self.problems.push(Problem {
            message,
            line: None,
            column: None,
            field: Some(FieldRef { section, field }),
        });
    }

    fn number(&mut self, section: Section, field: &'static str, rule: Rule, value: f64) {
        if let Err(reason) = check_value(rule, field, value) {
            self.report(section, field, &reason);
        }
    }

    fn vector(&mut self, section: Section, field: &'static str, value: Vector) {
        if !value.is_finite() {
            self.report(
                section,
                field,
                &say("scene-vector-not-finite", &[("field", field)]),
            );
            return;
        }
        let sizes = match value {
            Vector::Cartesian(v) => [v.x, v.y],
            Vector::Polar { magnitude, .. } => [magnitude, 0.0],
        };
        // Only the upper bound: a tiny coordinate or velocity (a run's state near 0, a
        // component 1e-101 beside a large one) multiplies nothing into an overflow, and
        // how close two bodies come is not bounded by their coordinates' sizes anyway.
        if let Some(reason) = sizes
            .into_iter()
            .filter(|size| size.abs() > LARGEST_MAGNITUDE)
            .find_map(|size| check_magnitude(field, size).err())
        {
            self.report(section, field, &reason);
        }
    }

    /// The rules of the field table: every number obeys its rule, every vector (and
    /// fixed point) is finite.
    fn rules<T>(&mut self, section: Section, fields: &[Field<T>], target: &T) {
        for f in fields {
            match ((f.get)(target), f.kind) {
                (Value::Number(v), Kind::Number(rule)) => self.number(section, f.key, rule, v),
                (Value::Vector(v) | Value::Endpoint(Endpoint::Point(v)), _) => {
                    self.vector(section, f.key, v);
                }
                _ => {}
            }
        }
    }

    fn world(&mut self) {
        let world = &self.scene.world;
        let s = Section::World;
        self.rules(s, fields::WORLD, world);
        if let Some(bounds) = world.bounds {
            self.vector(s, "bounds", bounds.min);
            self.vector(s, "bounds", bounds.max);
            let (min, max) = (bounds.min.to_dvec2(), bounds.max.to_dvec2());
            if min.is_finite() && max.is_finite() && !(min.x < max.x && min.y < max.y) {
                self.report(
                    s,
                    "bounds",
                    &say_numbers("scene-bounds-order", &[min.x, min.y, max.x, max.y]),
                );
            }
            if let Err(reason) = check_value(Rule::NonNegative, "friction", bounds.friction) {
                self.report(s, "bounds", &format!("bounds {reason}"));
            }
            if let Some(reason) = static_problem(bounds.static_friction, bounds.friction) {
                self.report(s, "bounds", &format!("bounds {reason}"));
            }
        }
    }

    fn settings(&mut self) {
        let settings = &self.scene.simulation;
        self.rules(Section::Simulation, fields::SIMULATION, settings);
        // The clock must tell t from t + dt: far from 0 an f64 instant is coarse, and a
        // step below a trillionth of the time is rounded by more than 1e-4 of itself
        // (and at 1e16 s, t + dt == t: the run never advances).
        let (start, step) = (settings.start_time, settings.time_step);
        if start.is_finite() && step.is_finite() && step > 0.0 && step < 1e-12 * start.abs() {
            self.report(
                Section::Simulation,
                "start_time",
                &say(
                    "scene-clock-too-coarse",
                    &[("start", &start.to_string()), ("step", &step.to_string())],
                ),
            );
        }
    }

    /// Two particles that attract or repel each other may not start at one point
    /// without softening: the force between them is infinite there.
    fn coincident(&mut self) {
        let world = &self.scene.world;
        if world.softening != 0.0 {
            return;
        }
        let gravitation = world.gravitation && world.gravitational_constant != 0.0;
        let coulomb = world.electrostatics && world.coulomb_constant != 0.0;
        let mut first_at: HashMap<(u64, u64), usize> = HashMap::new();
        for (i, p) in self.scene.particles.iter().enumerate() {
            // Only particles that feel a pair force: all of them under gravitation,
            // the charged ones under Coulomb alone.
            if !(gravitation || (coulomb && p.charge != 0.0)) {
                continue;
            }
            let at = p.position.to_dvec2();
            if !at.is_finite() {
                continue;
            }
            // +0 and −0 are one point.
            let key = ((at.x + 0.0).to_bits(), (at.y + 0.0).to_bits());
            match first_at.get(&key) {
                Some(&j) => {
                    let other = &self.scene.particles[j].name;
                    self.report(
                        Section::Particle(i),
                        "position",
                        &say("scene-same-point", &[("other", other.as_str())]),
                    );
                }
                None => {
                    first_at.insert(key, i);
                }
            }
        }
    }

    fn names(&mut self) {
        let scene = self.scene;
        let sections = (0..scene.particles.len())
            .map(|i| (Section::Particle(i), scene.particles[i].name.as_str()))
            .chain(
                (0..scene.springs.len())
                    .map(|i| (Section::Spring(i), scene.springs[i].name.as_str())),
            )
            .chain((0..scene.ties.len()).map(|i| (Section::Tie(i), scene.ties[i].name.as_str())))
            .chain((0..scene.ramps.len()).map(|i| (Section::Ramp(i), scene.ramps[i].name.as_str())))
            .chain(
                (0..scene.bodies.len()).map(|i| (Section::Body(i), scene.bodies[i].name.as_str())),
            )
            .chain(
                (0..scene.joints.len()).map(|i| (Section::Joint(i), scene.joints[i].name.as_str())),
            )
            .chain(
                (0..scene.forces.len()).map(|i| (Section::Force(i), scene.forces[i].name.as_str())),
            );
        let mut first_use: HashMap<&str, Section> = HashMap::new();
        for (section, name) in sections {
            if name.trim().is_empty() {
                self.report(section, "name", &say("scene-name-empty", &[]));
            } else if let Some(&earlier) = first_use.get(name) {
                let earlier = match earlier {
                    Section::Particle(i) => numbered("particle", i),
                    Section::Spring(i) => numbered("spring", i),
                    Section::Ramp(i) => numbered("ramp", i),
                    Section::Body(i) => numbered("body", i),
                    Section::Tie(i) => say(
                        "scene-named",
                        &[("kind", scene.ties[i].kind.as_str()), ("name", name)],
                    ),
                    other => scene.describe(other),
                };
                self.report(
                    section,
                    "name",
                    &say("scene-name-taken", &[("name", name), ("earlier", &earlier)]),
                );
            } else {
                first_use.insert(name, section);
            }
        }
    }

    fn particles(&mut self) {
        let bounds = self
            .scene
            .world
            .bounds
            .map(|b| (b.min.to_dvec2(), b.max.to_dvec2()));
        for (i, particle) in self.scene.particles.iter().enumerate() {
            let s = Section::Particle(i);
            let position = particle.position.to_dvec2();
            // A ball resting against a wall presses into it a little (the resting solver
            // leaves about 1 % of the radius; the 1,000-ball pit's crash 1.1 %): a state
            // the simulation reached must open again, so only a reach further out is a
            // mistake.
            let reach = particle.radius * (1.0 - WALL_OVERLAP);
            if let Some((min, max)) = bounds
                && position.is_finite()
                && particle.radius > 0.0
                && !(position.x - reach >= min.x
                    && position.x + reach <= max.x
                    && position.y - reach >= min.y
                    && position.y + reach <= max.y)
            {
                self.report(
                    s,
                    "position",
                    &say_numbers(
                        "scene-outside-bounds",
                        &[position.x, position.y, particle.radius],
                    ),
                );
            }
            self.rules(s, fields::PARTICLE, particle);
            if particle.quadratic_drag > 0.0 && particle.drag_coefficient > 0.0 {
                let words = say(
                    "scene-drag-twice",
                    &[
                        ("a", &particle.quadratic_drag.to_string()),
                        ("b", &particle.drag_coefficient.to_string()),
                    ],
                );
                self.report(s, "drag_coefficient", &words);
            }
            // Linear drag decays the velocity at b/m whatever the speed: a fixed-step
            // method that cannot follow it would make energy from nothing from the start.
            let settings = &self.scene.simulation;
            let rate = particle.linear_drag / particle.mass;
            if settings.integrator != crate::Integrator::Dopri5
                && !particle.fixed
                && particle.mass > 0.0
                && rate * settings.time_step > crate::tuning::DRAG_STEP
            {
                let words = say(
                    "scene-drag-too-strong",
                    &[
                        ("a", &particle.linear_drag.to_string()),
                        ("b", &particle.mass.to_string()),
                        ("c", &format!("{:.3e}", 1.0 / rate)),
                        ("d", &settings.time_step.to_string()),
                    ],
                );
                self.report(s, "linear_drag", &words);
            }
        }
    }

    fn springs(&mut self) {
        for (i, spring) in self.scene.springs.iter().enumerate() {
            let s = Section::Spring(i);
            self.rules(s, fields::SPRING, spring);
            self.ends(s, "spring", &spring.from, &spring.to);
        }
    }

    /// Rods and strings: ends as for springs, a length the ends can have together.
    fn ties(&mut self) {
        for (i, tie) in self.scene.ties.iter().enumerate() {
            let s = Section::Tie(i);
            self.rules(s, fields::tie_fields(tie.kind), tie);
            self.ends(s, tie.kind.as_str(), &tie.from, &tie.to);
            let fixed = |end: &Endpoint| match end {
                Endpoint::Point(_) => true,
                Endpoint::Particle(name) => self
                    .particle_index(name)
                    .is_none_or(|p| self.scene.particles[p].fixed),
            };
            if fixed(&tie.from)
                && fixed(&tie.to)
                && !matches!(
                    (&tie.from, &tie.to),
                    (Endpoint::Point(_), Endpoint::Point(_))
                )
            {
                self.report(
                    s,
                    "to",
                    &say("scene-ends-fixed", &[("kind", tie.kind.as_str())]),
                );
            }
        }
        if self.problems.is_empty()
            && let Some((section, message)) = super::links::unsatisfiable(self.scene)
        {
            self.report(section, "length", &message);
        }
    }

    /// The ends of a spring, rod or string: particles that exist, not both fixed points,
    /// not one particle twice.
    fn ends(&mut self, s: Section, kind: &str, from: &Endpoint, to: &Endpoint) {
        for (field, end) in [("from", from), ("to", to)] {
            if let Endpoint::Particle(name) = end
                && self.particle_index(name).is_none()
            {
                self.report(
                    s,
                    field,
                    &say("scene-no-particle", &[("field", field), ("name", name)]),
                );
            }
        }
        match (from, to) {
            (Endpoint::Point(_), Endpoint::Point(_)) => {
                self.report(s, "to", &say("scene-ends-points", &[("kind", kind)]));
            }
            (Endpoint::Particle(a), Endpoint::Particle(b)) if a == b => self.report(
                s,
                "to",
                &say("scene-same-particle", &[("name", a), ("kind", kind)]),
            ),
            _ => {}
        }
    }

    fn ramps(&mut self) {
        for (i, ramp) in self.scene.ramps.iter().enumerate() {
            self.rules(Section::Ramp(i), fields::RAMP, ramp);
            if let Some(reason) = static_problem(ramp.static_friction, ramp.friction) {
                self.report(Section::Ramp(i), "static_friction", &reason);
            }
        }
        self.inside_ramps();
    }

    /// A moving particle must not start with its centre inside a ramp: pushed out to the
    /// nearest surface it could land anywhere (half a thickness of 1e100 m away), and a
    /// rod or string holding it could not follow.
    fn inside_ramps(&mut self) {
        for (i, p) in self.scene.particles.iter().enumerate() {
            if p.fixed {
                continue;
            }
            let at = p.position.to_dvec2();
            for ramp in &self.scene.ramps {
                let (a, b) = (ramp.from.to_dvec2(), ramp.to.to_dvec2());
                let along = b - a;
                let t = if along.length_squared() > 0.0 {
                    ((at - a).dot(along) / along.length_squared()).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let depth = 0.5 * ramp.thickness - at.distance(a + along * t);
                if depth > 0.0 && depth.is_finite() {
                    self.report(
                        Section::Particle(i),
                        "position",
                        &say("scene-inside-ramp", &[("ramp", ramp.name.as_str())]),
                    );
                    break;
                }
            }
        }
    }

    /// A graph's quantities must be quantities, of particles that exist.
    fn graphs(&mut self) {
        for (i, graph) in self.scene.graphs.iter().enumerate() {
            let s = Section::Graph(i);
            let axes = std::iter::once(("x", &graph.x)).chain(graph.y.iter().map(|y| ("y", y)));
            for (field, quantity) in axes {
                let text = &quantity.to_string();
                match quantity.clone() {
                    Quantity::Particle(name, _)
                        if self.particle_index(&name).is_none() && !self.is_body(&name) =>
                    {
                        self.report(
                            s,
                            field,
                            &say(
                                "scene-graph-no-particle",
                                &[("field", field), ("text", text), ("name", &name)],
                            ),
                        );
                    }
                    Quantity::Link(name, LinkOf::Tension)
                        if !self.scene.ties.iter().any(|t| t.name == name) =>
                    {
                        self.report(
                            s,
                            field,
                            &say(
                                "scene-graph-no-tie",
                                &[("field", field), ("text", text), ("name", &name)],
                            ),
                        );
                    }
                    Quantity::Link(name, of)
                        if !self.scene.ties.iter().any(|t| t.name == name)
                            && !self.scene.springs.iter().any(|t| t.name == name)
                            && !(of == LinkOf::Angle
                                && (self.is_body(&name)
                                    || self.is_joint(&name)
                                    || self.particle_index(&name).is_some())) =>
                    {
                        self.report(
                            s,
                            field,
                            &say(
                                "scene-graph-no-link",
                                &[("field", field), ("text", text), ("name", &name)],
                            ),
                        );
                    }
                    // A joint's quantities, and an angle named after a joint, are the
                    // quantities' own to judge (a pulley has tensions, no angle).
                    Quantity::Joint(..) => {
                        if let Err(reason) = quantity.check_in(self.scene) {
                            self.report(s, field, &format!("{field}: {reason}"));
                        }
                    }
                    Quantity::Link(ref name, LinkOf::Angle) if self.is_joint(name) => {
                        if let Err(reason) = quantity.check_in(self.scene) {
                            self.report(s, field, &format!("{field}: {reason}"));
                        }
                    }
                    Quantity::Time if field == "y" => {
                        self.report(s, field, &say("scene-graph-time-on-y", &[]));
                    }
                    _ => {}
                }
            }
        }
    }

    /// A series must name a number of the scene, a range with values, a run that ends
    /// after the start, measures that read and name objects that exist, a theory that
    /// reads.
    fn series(&mut self) {
        for (i, series) in self.scene.series.iter().enumerate() {
            for (field, why) in series.problems(self.scene) {
                self.report(Section::Series(i), field, &why);
            }
        }
    }

    /// A lesson's text holds no HTML, its sliders name numbers of the scene within their
    /// rules, its questions read and name what the scene has ([`super::Lesson::problems`]).
    fn lesson(&mut self) {
        let Some(lesson) = &self.scene.lesson else {
            return;
        };
        for (section, field, why) in lesson.problems(self.scene) {
            self.report(section, field, &why);
        }
    }

    /// The instruments' ends follow particles that exist; the stopwatch's triggers have
    /// what they need ([`super::Instruments::problems`]).
    fn instruments(&mut self) {
        let Some(instruments) = &self.scene.instruments else {
            return;
        };
        for (section, field, why) in instruments.problems(self.scene) {
            self.report(section, field, &why);
        }
    }

    fn view(&mut self) {
        let Some(view) = &self.scene.view else {
            return;
        };
        let s = Section::View;
        if let Some(center) = view.center
            && !center.is_finite()
        {
            self.report(
                s,
                "center",
                &say("scene-vector-not-finite", &[("field", "center")]),
            );
        }
        if let Some(width) = view.width {
            self.number(s, "width", Rule::Positive, width);
        }
        if let Some(Follow::Particle(name)) = &view.follow
            && self.particle_index(name).is_none()
        {
            self.report(s, "follow", &say("scene-follow-unknown", &[("name", name)]));
        }
    }
}

impl Color {
    /// A deterministic pleasant colour for the particle at `index`, for scenes that do
    /// not choose one.
    pub fn palette(index: usize) -> Self {
        const PALETTE: [[u8; 3]; 8] = [
            [0xd9, 0x4f, 0x4f],
            [0x3b, 0x7d, 0xd8],
            [0x4c, 0xa8, 0x5a],
            [0xe0, 0x9f, 0x3e],
            [0x8e, 0x5c, 0xc9],
            [0x2f, 0xa5, 0xa5],
            [0xc9, 0x5c, 0x9e],
            [0x7a, 0x7a, 0x7a],
        ];
        Self(PALETTE[index % PALETTE.len()])
    }
}

impl Quantity {
    /// Whether `scene` has the object the quantity names.
    ///
    /// # Errors
    /// The object it names is not there (with the names there are), or a tension is asked
    /// of a spring.
    pub fn check_in(&self, scene: &Scene) -> Result<(), String> {
        let names = |names: Vec<&String>| names.into_iter().cloned().collect::<Vec<String>>();
        let particles = names(scene.particles.iter().map(|p| &p.name).collect());
        let ties = names(scene.ties.iter().map(|t| &t.name).collect());
        let springs = names(scene.springs.iter().map(|s| &s.name).collect());
        let bodies = names(scene.bodies.iter().map(|b| &b.name).collect());
        let joints = names(scene.joints.iter().map(|j| &j.name).collect());
        let pulleys = names(
            scene
                .joints
                .iter()
                .filter(|j| j.is_pulley())
                .map(|j| &j.name)
                .collect(),
        );
        self.find(&crate::quantity::Names {
            particles: &particles,
            ties: &ties,
            springs: &springs,
            bodies: &bodies,
            joints: &joints,
            pulleys: &pulleys,
        })
        .map(|_| ())
    }
}
