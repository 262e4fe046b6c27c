//! Reading a scene from the parse tree: every unknown key, wrong type and missing field
//! noted with its place, then the scene's own checks, and "did you mean" for a misspelt key.

use std::collections::HashSet;

use super::VERSION;
use super::tree::{Entry, Lines, Node, Span, Value};
use super::values::{
    closest, read_bool, read_limits, read_motor, read_number, read_point, read_points, read_text,
    read_text_list, read_value, read_vector,
};
use crate::Quantity;
use crate::scene::error::{FieldRef, LoadError, Problem, Section};
use crate::scene::fields::{self, Field};
use crate::scene::validate;
use crate::scene::{
    Body, Endpoint, Follow, Force, Graph, Joint, JointKind, Particle, Ramp, Scene, Series,
    Settings, Shape, Spring, Tie, TieKind, Vector, View, World, say,
};

pub(super) struct Reader<'t> {
    pub(super) text: &'t str,
    pub(super) problems: Vec<(Span, Problem)>,
    /// Fields that already have a problem: validation would only repeat it.
    pub(super) failed: HashSet<FieldRef>,
    /// Where the text's lines start, found at the first problem (a file with 20,000
    /// problems would otherwise be scanned from its start for each).
    lines: Option<Lines>,
    /// Sections that are not tables: their checker's problems would only be about
    /// defaults.
    failed_sections: HashSet<Section>,
}

/// One table being read: which keys were used, for reporting unknown ones.
pub(super) struct Table<'n> {
    pub(super) entries: &'n [Entry<'n>],
    /// Where the table starts, for problems about keys it lacks.
    pub(super) span: Span,
    pub(super) used: Vec<bool>,
    pub(super) section: Section,
    pub(super) label: String,
}

impl<'n> Table<'n> {
    pub(super) fn get(&mut self, key: &str) -> Option<&'n Node<'n>> {
        let index = self.entries.iter().position(|e| e.key == key)?;
        self.used[index] = true;
        Some(&self.entries[index].node)
    }
}

pub(super) const ROOT_KEYS: &[&str] = &[
    "version",
    "name",
    "description",
    "world",
    "simulation",
    "particle",
    "spring",
    "rod",
    "string",
    "ramp",
    "body",
    "pin",
    "hinge",
    "pulley",
    "graph",
    "series",
    "view",
    "lesson",
    "instruments",
];
pub(super) const GRAPH_KEYS: &[&str] = &["title", "x", "y"];
pub(super) const SERIES_KEYS: &[&str] =
    &["vary", "from", "to", "step", "until", "measure", "theory"];
pub(super) const VIEW_KEYS: &[&str] = &[
    "center",
    "width",
    "follow",
    "trails",
    "velocity",
    "acceleration",
    "force",
    "names",
];

impl<'t> Reader<'t> {
    /// 1-based line and column (in characters) of byte `offset` of the text.
    fn line_column(&mut self, offset: usize) -> (usize, usize) {
        let text = self.text;
        self.lines
            .get_or_insert_with(|| Lines::new(text))
            .at(text, offset)
    }

    pub(super) fn new(text: &'t str) -> Self {
        Self {
            text,
            problems: Vec::new(),
            failed: HashSet::new(),
            lines: None,
            failed_sections: HashSet::new(),
        }
    }

    pub(super) fn problem(&mut self, span: Span, field: Option<FieldRef>, message: String) {
        if let Some(field) = field {
            self.failed.insert(field);
        }
        let (line, column) = match &span {
            Some(span) => {
                let (line, column) = self.line_column(span.start);
                (Some(line), Some(column))
            }
            None => (None, None),
        };
        self.problems.push((
            span,
            Problem {
                message,
                line,
                column,
                field,
            },
        ));
    }

    /// Opens `node` as a table, or reports that it is not one.
    pub(super) fn table<'n>(
        &mut self,
        node: &'n Node,
        section: Section,
        label: String,
    ) -> Option<Table<'n>> {
        if let Value::Table(entries) = &node.value {
            Some(Table {
                entries,
                span: node.span.clone(),
                used: vec![false; entries.len()],
                section,
                label,
            })
        } else {
            let kind = node.value.kind();
            self.problem(
                node.span.clone(),
                None,
                say("scene-not-a-table", &[("label", &label), ("got", &kind)]),
            );
            // The object read in its place has only defaults: what the checker would say
            // of them (an empty name, both ends fixed) is not the user's problem.
            self.failed_sections.insert(section);
            None
        }
    }

    /// Reports the keys of `table` that were never read.
    pub(super) fn close(&mut self, table: &Table<'_>, known: &[&str]) {
        for (entry, used) in table.entries.iter().zip(&table.used) {
            if !used {
                let hint = closest(&entry.key, known).map_or_else(
                    || say("scene-keys-here", &[("keys", &known.join(", "))]),
                    |k| say("scene-did-you-mean", &[("key", k)]),
                );
                let message = say(
                    "scene-unknown-key",
                    &[
                        ("label", &table.label),
                        ("key", &entry.key),
                        ("hint", &hint),
                    ],
                );
                self.problem(entry.key_span.clone(), None, message);
            }
        }
    }

    /// Reads `key` with `read`, remembering its span; `None` when absent or invalid.
    pub(super) fn field<T>(
        &mut self,
        table: &mut Table<'_>,
        key: &'static str,
        read: impl FnOnce(&Node) -> Result<T, String>,
    ) -> Option<T> {
        let node = table.get(key)?;
        let field = FieldRef {
            section: table.section,
            field: key,
        };
        match read(node) {
            Ok(value) => Some(value),
            Err(reason) => {
                let message = format!("{}: {key} {reason}", table.label);
                self.problem(node.span.clone(), Some(field), message);
                None
            }
        }
    }

    pub(super) fn required<T>(
        &mut self,
        table: &mut Table<'_>,
        key: &'static str,
        read: impl FnOnce(&Node) -> Result<T, String>,
        placeholder: T,
    ) -> T {
        if table.entries.iter().any(|e| e.key == key) {
            return self.field(table, key, read).unwrap_or(placeholder);
        }
        let field = FieldRef {
            section: table.section,
            field: key,
        };
        let message = say("scene-required", &[("label", &table.label), ("key", key)]);
        self.problem(table.span.clone(), Some(field), message);
        placeholder
    }

    pub(super) fn scene(&mut self, root: &Node) -> Scene {
        let mut scene = Scene::default();
        let Some(mut top) = self.table(root, Section::Root, say("scene-the-whole", &[])) else {
            return scene;
        };
        top.label = say("scene-the-scene", &[]);
        if top.entries.iter().any(|e| e.key == "version") {
            let version = self.field(&mut top, "version", read_number);
            #[expect(
                clippy::float_cmp,
                reason = "version numbers are small integers, exact in f64"
            )]
            let supported = version.is_none_or(|v| v == VERSION as f64);
            if let Some(version) = version.filter(|_| !supported) {
                let field = FieldRef {
                    section: Section::Root,
                    field: "version",
                };
                let span = value_span(top.entries, field.field);
                self.problem(
                    span,
                    None,
                    say(
                        "scene-version-unsupported",
                        &[
                            ("version", &version.to_string()),
                            ("supported", &VERSION.to_string()),
                        ],
                    ),
                );
            }
        } else {
            self.problem(None, None, say("scene-version-required", &[]));
        }
        scene.name = self.field(&mut top, "name", read_text);
        scene.description = self.field(&mut top, "description", read_text);
        if let Some(node) = top.get("world") {
            scene.world = self.world(node);
        }
        if let Some(node) = top.get("simulation") {
            scene.simulation = self.settings(node);
        }
        let particles = self.items(&mut top, "particle");
        scene.particles.reserve_exact(particles.len());
        for (i, node) in particles.iter().enumerate() {
            let particle = self.particle(node, i);
            scene.particles.push(particle);
        }
        let springs = self.items(&mut top, "spring");
        scene.springs.reserve_exact(springs.len());
        for (i, node) in springs.iter().enumerate() {
            let spring = self.spring(node, i);
            scene.springs.push(spring);
        }
        for kind in [TieKind::Rod, TieKind::String] {
            for (i, node) in self.items(&mut top, kind.as_str()).iter().enumerate() {
                let tie = self.tie(node, kind, i, &scene);
                scene.ties.push(tie);
            }
        }
        for (i, node) in self.items(&mut top, "ramp").iter().enumerate() {
            let ramp = self.ramp(node, i);
            scene.ramps.push(ramp);
        }
        for (i, node) in self.items(&mut top, "body").iter().enumerate() {
            let body = self.body(node, i);
            scene.bodies.push(body);
        }
        for kind in ["pin", "hinge", "pulley"] {
            for (i, node) in self.items(&mut top, kind).iter().enumerate() {
                let joint = self.joint(node, kind, i, scene.joints.len());
                scene.joints.push(joint);
            }
        }
        for (i, node) in self.items(&mut top, "force").iter().enumerate() {
            let force = self.force(node, i);
            scene.forces.push(force);
        }
        for (i, node) in self.items(&mut top, "graph").iter().enumerate() {
            let graph = self.graph(node, i);
            scene.graphs.push(graph);
        }
        for (i, node) in self.items(&mut top, "series").iter().enumerate() {
            let series = self.series(node, i);
            scene.series.push(series);
        }
        if let Some(node) = top.get("view") {
            scene.view = Some(self.view(node));
        }
        if let Some(node) = top.get("lesson") {
            scene.lesson = Some(self.lesson(node));
        }
        if let Some(node) = top.get("instruments") {
            scene.instruments = Some(self.instruments(node));
        }
        self.close(&top, ROOT_KEYS);
        scene
    }

    /// The entries of an array of tables such as `[[particle]]`.
    pub(super) fn items<'n>(&mut self, top: &mut Table<'n>, key: &str) -> &'n [Node<'n>] {
        match top.get(key) {
            None => &[],
            Some(Node {
                value: Value::Array(items),
                ..
            }) => items,
            Some(node) => {
                self.problem(
                    node.span.clone(),
                    None,
                    say(
                        "scene-not-a-list",
                        &[("key", key), ("got", &node.value.kind())],
                    ),
                );
                &[]
            }
        }
    }

    /// Reads every field of `fields` present in `t` into `target`; a required one that
    /// is missing is a problem (and `target` keeps its placeholder).
    pub(super) fn fields<T>(&mut self, t: &mut Table<'_>, fields: &[Field<T>], target: &mut T) {
        for f in fields {
            let read = |node: &Node| read_value(f.kind, node);
            let value = if f.default.is_none() {
                self.required(t, f.key, |node| read(node).map(Some), None)
            } else {
                self.field(t, f.key, read)
            };
            if let Some(value) = value {
                (f.set)(target, value);
            }
        }
    }

    pub(super) fn world(&mut self, node: &Node) -> World {
        let mut world = World::default();
        if let Some(mut t) = self.table(node, Section::World, "[world]".to_owned()) {
            self.fields(&mut t, fields::WORLD, &mut world);
            self.close(&t, &fields::keys(&[], fields::WORLD));
        }
        world
    }

    pub(super) fn settings(&mut self, node: &Node) -> Settings {
        let mut settings = Settings::default();
        if let Some(mut t) = self.table(node, Section::Simulation, "[simulation]".to_owned()) {
            self.fields(&mut t, fields::SIMULATION, &mut settings);
            self.close(&t, &fields::keys(&[], fields::SIMULATION));
        }
        settings
    }

    /// Opens the table of an object and reads its name, which labels its messages.
    pub(super) fn object<'n>(
        &mut self,
        node: &'n Node,
        kind: &str,
        section: Section,
        index: usize,
    ) -> Option<(Table<'n>, String)> {
        // Particles, springs and ramps are named by their initial (p1, s1, r1); rods and
        // strings in full (rod1, string1), which would clash with ramps and springs.
        let default_name = match kind {
            "rod" | "string" | "body" | "pin" | "hinge" | "pulley" | "force" => {
                format!("{kind}{}", index + 1)
            }
            _ => format!("{}{}", &kind[..1], index + 1),
        };
        let mut t = self.table(node, section, validate::numbered(kind, index))?;
        let name = self
            .field(&mut t, "name", read_text)
            .unwrap_or(default_name);
        if !name.is_empty() {
            t.label = say("scene-named", &[("kind", kind), ("name", &name)]);
        }
        Some((t, name))
    }

    pub(super) fn particle(&mut self, node: &Node, index: usize) -> Particle {
        // Placeholders for required fields: a missing one is reported, never used.
        let mut particle = Particle::new(format!("p{}", index + 1), 1.0);
        if let Some((mut t, name)) = self.object(node, "particle", Section::Particle(index), index)
        {
            particle.name = name;
            self.fields(&mut t, fields::PARTICLE, &mut particle);
            self.close(&t, &fields::keys(&["name"], fields::PARTICLE));
        }
        particle
    }

    pub(super) fn spring(&mut self, node: &Node, index: usize) -> Spring {
        let placeholder = || Endpoint::Point(Vector::ZERO);
        let mut spring = Spring::new(
            format!("s{}", index + 1),
            placeholder(),
            placeholder(),
            0.0,
            0.0,
        );
        if let Some((mut t, name)) = self.object(node, "spring", Section::Spring(index), index) {
            spring.name = name;
            self.fields(&mut t, fields::SPRING, &mut spring);
            self.close(&t, &fields::keys(&["name"], fields::SPRING));
        }
        spring
    }

    /// A rod or a string, the `index`-th of its kind; `scene` holds the particles read so
    /// far, which give a length left out of the file.
    pub(super) fn tie(&mut self, node: &Node, kind: TieKind, index: usize, scene: &Scene) -> Tie {
        let placeholder = || Endpoint::Point(Vector::ZERO);
        let mut tie = Tie::rod(String::new(), placeholder(), placeholder(), 1.0);
        tie.kind = kind;
        let section = Section::Tie(scene.ties.len());
        if let Some((mut t, name)) = self.object(node, kind.as_str(), section, index) {
            let fields = fields::tie_fields(kind);
            let has_length = t.entries.iter().any(|e| e.key == "length");
            tie.name = name;
            self.fields(&mut t, fields, &mut tie);
            self.close(&t, &fields::keys(&["name"], fields));
            if !has_length && let Some(distance) = scene.distance(&tie.from, &tie.to) {
                tie.length = distance;
            }
        }
        tie
    }

    pub(super) fn ramp(&mut self, node: &Node, index: usize) -> Ramp {
        let mut ramp = Ramp::new(format!("r{}", index + 1), Vector::ZERO, Vector::ZERO);
        if let Some((mut t, name)) = self.object(node, "ramp", Section::Ramp(index), index) {
            ramp.name = name;
            self.fields(&mut t, fields::RAMP, &mut ramp);
            ramp.static_friction = self.field(&mut t, "static_friction", read_number);
            let mut known = fields::keys(&["name"], fields::RAMP);
            known.push("static_friction");
            self.close(&t, &known);
        }
        ramp
    }

    pub(super) fn body(&mut self, node: &Node, index: usize) -> Body {
        let mut body = Body::rectangle(String::new(), 0.0, 0.0, 0.0);
        let Some((mut t, name)) = self.object(node, "body", Section::Body(index), index) else {
            return body;
        };
        body.name = name;
        let shape = self.required(&mut t, "shape", read_text, String::new());
        match shape.as_str() {
            "box" => {}
            "polygon" => body.shape = Shape::Polygon(Vec::new()),
            _ => {
                // Without a shape its size cannot be judged: nothing said of it.
                for key in ["width", "height", "vertices"] {
                    self.failed.insert(FieldRef {
                        section: t.section,
                        field: key,
                    });
                }
                let field = FieldRef {
                    section: t.section,
                    field: "shape",
                };
                // A missing shape is said already; a wrong one is said here.
                if !self.failed.contains(&field) {
                    let message = say("scene-body-shape", &[("got", &shape)]);
                    let message = format!("{}: {message}", t.label);
                    self.problem(value_span(t.entries, "shape"), Some(field), message);
                }
            }
        }
        if let Shape::Polygon(vertices) = &mut body.shape {
            *vertices = self.required(&mut t, "vertices", read_points, Vec::new());
        }
        body.static_friction = self.field(&mut t, "static_friction", read_number);
        let has = |key: &str| t.entries.iter().any(|e| e.key == key);
        let both = has("mass") && has("density");
        self.fields(&mut t, fields::BODY, &mut body);
        if both {
            let field = FieldRef {
                section: t.section,
                field: "density",
            };
            let message = format!("{}: {}", t.label, say("scene-body-mass-and-density", &[]));
            self.problem(value_span(t.entries, "density"), Some(field), message);
        }
        let mut known = fields::keys(&["name"], fields::BODY);
        known.extend(fields::BODY_SHAPE_KEYS.map(|(key, ..)| key));
        self.close(&t, &known);
        body
    }

    /// A force of one's own, the `index`-th.
    pub(super) fn force(&mut self, node: &Node, index: usize) -> Force {
        let mut force = Force::new(String::new(), "0", "0");
        let Some((mut t, name)) = self.object(node, "force", Section::Force(index), index) else {
            return force;
        };
        force.name = name;
        force.on = self.field(&mut t, "on", read_text_list).unwrap_or_default();
        force.fx = self
            .field(&mut t, "fx", read_text)
            .unwrap_or_else(|| "0".to_owned());
        force.fy = self
            .field(&mut t, "fy", read_text)
            .unwrap_or_else(|| "0".to_owned());
        force.potential = self.field(&mut t, "potential", read_text);
        self.close(&t, &["name", "on", "fx", "fy", "potential"]);
        force
    }

    /// A pin or a hinge, the `index`-th of its kind and the `section`-th joint.
    pub(super) fn joint(&mut self, node: &Node, kind: &str, index: usize, section: usize) -> Joint {
        let mut joint = Joint::pin(String::new(), String::new(), Vector::ZERO);
        let Some((mut t, name)) = self.object(node, kind, Section::Joint(section), index) else {
            return joint;
        };
        joint.name = name;
        if kind == "pulley" {
            let a = self.required(&mut t, "a", read_text, String::new());
            joint.body = self.required(&mut t, "b", read_text, String::new());
            joint.at = self.required(&mut t, "position", read_vector, Vector::ZERO);
            let radius = self.required(&mut t, "radius", read_number, 0.0);
            let mass = self.field(&mut t, "mass", read_number).unwrap_or(0.0);
            let inertia = self.field(&mut t, "inertia", read_number).unwrap_or(0.5);
            let spin = self.field(&mut t, "spin", read_number).unwrap_or(0.0);
            let length = self.field(&mut t, "length", read_number);
            joint.kind = JointKind::Pulley {
                a,
                radius,
                mass,
                inertia,
                spin,
                length,
            };
            let known = [
                "name", "a", "b", "position", "radius", "mass", "inertia", "spin", "length",
            ];
            self.close(&t, &known);
            return joint;
        }
        let mut known = vec!["name", "at", "motor", "anchor", "reference_angle", "limits"];
        if kind == "pin" {
            joint.body = self.required(&mut t, "body", read_text, String::new());
            known.push("body");
        } else {
            let a = self.required(&mut t, "a", read_text, String::new());
            joint.body = self.required(&mut t, "b", read_text, String::new());
            let anchor_a = self.field(&mut t, "anchor_a", read_point);
            joint.kind = JointKind::Hinge { a, anchor_a };
            known.extend(["a", "b", "anchor_a"]);
        }
        joint.at = self.required(&mut t, "at", read_vector, Vector::ZERO);
        joint.anchor = self.field(&mut t, "anchor", read_point);
        joint.reference_angle = self.field(&mut t, "reference_angle", read_number);
        joint.motor = self.field(&mut t, "motor", read_motor);
        joint.limits = self.field(&mut t, "limits", read_limits);
        self.close(&t, &known);
        joint
    }

    pub(super) fn graph(&mut self, node: &Node, index: usize) -> Graph {
        let mut graph = Graph::against_time([]);
        let Some(mut t) = self.table(
            node,
            Section::Graph(index),
            validate::numbered("graph", index),
        ) else {
            return graph;
        };
        graph.title = self.field(&mut t, "title", read_text);
        if let Some(title) = &graph.title {
            t.label = say("scene-named", &[("kind", "graph"), ("name", title)]);
        }
        // Each name is read as a quantity here, each one that is not said at its field.
        if let Some(x) = self.field(&mut t, "x", read_text) {
            match Quantity::parse(&x) {
                Ok(x) => graph.x = x,
                Err(reason) => self.quantity_problem(&t, "x", &reason),
            }
        }
        for y in self.required(&mut t, "y", read_text_list, Vec::new()) {
            match Quantity::parse(&y) {
                Ok(y) => graph.y.push(y),
                Err(reason) => self.quantity_problem(&t, "y", &reason),
            }
        }
        self.close(&t, GRAPH_KEYS);
        graph
    }

    pub(super) fn series(&mut self, node: &Node, index: usize) -> Series {
        let mut series = Series {
            vary: String::new(),
            from: 0.0,
            to: 0.0,
            step: 1.0,
            until: 1.0,
            measure: Vec::new(),
            theory: None,
        };
        let Some(mut t) = self.table(
            node,
            Section::Series(index),
            validate::numbered("series", index),
        ) else {
            return series;
        };
        series.vary = self.required(&mut t, "vary", read_text, String::new());
        series.from = self.required(&mut t, "from", read_number, 0.0);
        series.to = self.required(&mut t, "to", read_number, 0.0);
        series.step = self.required(&mut t, "step", read_number, 1.0);
        series.until = self.required(&mut t, "until", read_number, 1.0);
        series.measure = self.required(&mut t, "measure", read_text_list, Vec::new());
        series.theory = self.field(&mut t, "theory", read_text);
        self.close(&t, SERIES_KEYS);
        series
    }

    /// A name in a graph's `key` that is no quantity: `reason`, at the field.
    fn quantity_problem(&mut self, table: &Table<'_>, key: &'static str, reason: &str) {
        let field = FieldRef {
            section: table.section,
            field: key,
        };
        let span = value_span(table.entries, key);
        let message = format!("{}: {key}: {reason}", table.label);
        self.problem(span, Some(field), message);
        // The field's other names are still checked: every problem is listed at once.
        self.failed.remove(&field);
    }

    pub(super) fn view(&mut self, node: &Node) -> View {
        let mut view = View::default();
        let Some(mut t) = self.table(node, Section::View, "[view]".to_owned()) else {
            return view;
        };
        view.center = self
            .field(&mut t, "center", read_vector)
            .map(Vector::to_dvec2);
        view.width = self.field(&mut t, "width", read_number);
        view.follow = self
            .field(&mut t, "follow", read_text)
            .map(|text| Follow::parse(&text));
        view.trails = self.field(&mut t, "trails", read_bool);
        view.velocity = self.field(&mut t, "velocity", read_bool);
        view.acceleration = self.field(&mut t, "acceleration", read_bool);
        view.force = self.field(&mut t, "force", read_bool);
        view.names = self.field(&mut t, "names", read_bool);
        self.close(&t, VIEW_KEYS);
        view
    }

    /// Adds the validation problems (with positions) to the reading problems and returns
    /// the scene if there are none.
    pub(super) fn finish(mut self, scene: Scene, root: &Node) -> Result<Scene, LoadError> {
        for mut problem in scene.validate() {
            let Some(field) = problem.field else { continue };
            if self.failed.contains(&field) || self.failed_sections.contains(&field.section) {
                continue;
            }
            let span = place(root, field);
            if let Some(span) = &span {
                let (line, column) = self.line_column(span.start);
                problem.line = Some(line);
                problem.column = Some(column);
            }
            self.problems.push((span, problem));
        }
        if self.problems.is_empty() {
            return Ok(scene);
        }
        // File order; problems without a position (missing keys) last, in reading order.
        self.problems
            .sort_by_key(|(span, _)| span.as_ref().map_or(usize::MAX, |s| s.start));
        Err(LoadError {
            problems: self.problems.into_iter().map(|(_, p)| p).collect(),
        })
    }
}

/// Where a field's value stands in the file, or its section where the file leaves the field
/// out (a rod's length taken from the distance): found in the tree when a check of the
/// scene has a problem, rather than noted for every field read.
fn place(root: &Node, field: FieldRef) -> Span {
    let section = section_node(root, field.section)?;
    let Value::Table(entries) = &section.value else {
        return None;
    };
    value_span(entries, field.field).or_else(|| section.span.clone())
}

/// The value of `key` among a table's entries.
fn value_span(entries: &[Entry], key: &str) -> Span {
    let entry = entries.iter().find(|e| e.key == key)?;
    entry.node.span.clone()
}

/// The items of the array of tables `key` among a table's entries; none where the key is
/// missing or no array (the reader reads none there either).
pub(super) fn array_items<'n>(entries: &'n [Entry<'n>], key: &str) -> &'n [Node<'n>] {
    match entries.iter().find(|e| e.key == key).map(|e| &e.node) {
        Some(Node {
            value: Value::Array(items),
            ..
        }) => items,
        _ => &[],
    }
}

/// A section's table in the tree, counted as the reader counts them.
fn section_node<'n>(root: &'n Node<'n>, section: Section) -> Option<&'n Node<'n>> {
    let Value::Table(top) = &root.value else {
        return None;
    };
    let get = |key: &str| top.iter().find(|e| e.key == key).map(|e| &e.node);
    let items = |key: &str| array_items(top, key);
    match section {
        Section::Root => Some(root),
        Section::World => get("world"),
        Section::Simulation => get("simulation"),
        Section::View => get("view"),
        Section::Instruments | Section::Stopwatch => {
            super::instruments::instruments_node(get("instruments")?, section)
        }
        Section::Lesson | Section::Slider(_) | Section::Question(_) => {
            super::lesson::lesson_node(get("lesson")?, section)
        }
        Section::Particle(i) => items("particle").get(i),
        Section::Spring(i) => items("spring").get(i),
        Section::Ramp(i) => items("ramp").get(i),
        Section::Body(i) => items("body").get(i),
        // Pins first, then hinges, then pulleys, as the reader reads them into
        // `Scene::joints`.
        Section::Joint(i) => {
            let (pins, hinges) = (items("pin"), items("hinge"));
            match (
                i.checked_sub(pins.len()),
                i.checked_sub(pins.len() + hinges.len()),
            ) {
                (None, _) => pins.get(i),
                (Some(i), None) => hinges.get(i),
                (_, Some(i)) => items("pulley").get(i),
            }
        }
        Section::Force(i) => items("force").get(i),
        Section::Graph(i) => items("graph").get(i),
        Section::Series(i) => items("series").get(i),
        // Rods first, then strings, as the reader reads them into `Scene::ties`.
        Section::Tie(i) => {
            let rods = items(TieKind::Rod.as_str());
            match i.checked_sub(rods.len()) {
                None => rods.get(i),
                Some(i) => items(TieKind::String.as_str()).get(i),
            }
        }
    }
}
