//! Writing a scene: TOML and JSON in the same schema, each field in table order.

use std::fmt::Write as _;

use super::VERSION;
use crate::scene::fields::{self, Field, Value as FieldValue};
use glam::DVec2;

use crate::scene::{Body, Bounds, Endpoint, Force, Joint, JointKind, Motor, Scene, Shape, Vector};

impl Scene {
    /// The scene as a TOML scene file.
    pub fn to_toml(&self) -> String {
        let mut out = String::new();
        for section in self.document() {
            let _ = match section.header {
                Header::Root => Ok(()),
                Header::Table(name) => write!(out, "\n[{name}]\n"),
                Header::ArrayItem(name) => write!(out, "\n[[{name}]]\n"),
                Header::Nested(table, name) => write!(out, "\n[[{table}.{name}]]\n"),
                Header::Sub(table, name) => write!(out, "\n[{table}.{name}]\n"),
            };
            for (key, value) in &section.entries {
                let _ = writeln!(out, "{key} = {}", value.to_toml());
            }
        }
        out
    }

    /// The scene as a JSON scene file.
    pub fn to_json(&self) -> String {
        use serde_json::{Map, Value};
        let mut root = Map::new();
        for section in self.document() {
            let entries: Map<String, Value> = section
                .entries
                .iter()
                .map(|(key, value)| ((*key).to_owned(), value.to_json()))
                .collect();
            match section.header {
                Header::Root => root.extend(entries),
                Header::Table(name) => {
                    root.insert(name.to_owned(), Value::Object(entries));
                }
                Header::Nested(table, name) => {
                    let parent = root
                        .entry(table.to_owned())
                        .or_insert_with(|| Value::Object(Map::new()));
                    if let Value::Object(parent) = parent {
                        let list = parent
                            .entry(name.to_owned())
                            .or_insert_with(|| Value::Array(Vec::new()));
                        if let Value::Array(list) = list {
                            list.push(Value::Object(entries));
                        }
                    }
                }
                Header::Sub(table, name) => {
                    let parent = root
                        .entry(table.to_owned())
                        .or_insert_with(|| Value::Object(Map::new()));
                    if let Value::Object(parent) = parent {
                        parent.insert(name.to_owned(), Value::Object(entries));
                    }
                }
                Header::ArrayItem(name) => {
                    let list = root
                        .entry(name.to_owned())
                        .or_insert_with(|| Value::Array(Vec::new()));
                    if let Value::Array(list) = list {
                        list.push(Value::Object(entries));
                    }
                }
            }
        }
        let mut text = serde_json::to_string_pretty(&Value::Object(root)).unwrap_or_default();
        text.push('\n');
        text
    }

    /// The scene as sections of key–value pairs: one description that both writers
    /// render, so TOML and JSON can never disagree on the schema.
    fn document(&self) -> Vec<OutSection> {
        let mut root = vec![("version", Out::Integer(VERSION))];
        if let Some(name) = &self.name {
            root.push(("name", Out::Text(name.clone())));
        }
        if let Some(description) = &self.description {
            root.push(("description", Out::Text(description.clone())));
        }
        let world = out_fields(fields::WORLD, &self.world);
        let simulation = out_fields(fields::SIMULATION, &self.simulation);
        let mut sections = vec![
            OutSection {
                header: Header::Root,
                entries: root,
            },
            OutSection {
                header: Header::Table("world"),
                entries: world,
            },
            OutSection {
                header: Header::Table("simulation"),
                entries: simulation,
            },
        ];
        let objects = self
            .particles
            .iter()
            .map(|p| ("particle", &p.name, out_fields(fields::PARTICLE, p)))
            .chain(
                self.springs
                    .iter()
                    .map(|s| ("spring", &s.name, out_fields(fields::SPRING, s))),
            )
            .chain(self.ties.iter().map(|t| {
                (
                    t.kind.as_str(),
                    &t.name,
                    out_fields(fields::tie_fields(t.kind), t),
                )
            }))
            .chain(self.ramps.iter().map(|r| {
                let mut entries = out_fields(fields::RAMP, r);
                if let Some(s) = r.static_friction {
                    entries.push(("static_friction", Out::Number(s)));
                }
                ("ramp", &r.name, entries)
            }))
            .chain(
                self.bodies
                    .iter()
                    .map(|b| ("body", &b.name, body_fields(b))),
            )
            .chain(
                self.joints
                    .iter()
                    .map(|j| (j.kind_str(), &j.name, joint_fields(j))),
            )
            .chain(
                self.forces
                    .iter()
                    .map(|f| ("force", &f.name, force_fields(f))),
            );
        for (kind, name, entries) in objects {
            let mut named = vec![("name", Out::Text(name.clone()))];
            named.extend(entries);
            sections.push(OutSection {
                header: Header::ArrayItem(kind),
                entries: named,
            });
        }
        sections.extend(self.presentation());
        if let Some(instruments) = self.instruments.as_ref().filter(|i| !i.is_empty()) {
            sections.extend(super::instruments::instruments_sections(instruments));
        }
        if let Some(lesson) = &self.lesson {
            sections.extend(super::lesson::lesson_sections(lesson));
        }
        sections
    }

    /// The app's part of the scene: `[[graph]]`, `[[series]]` and `[view]`.
    fn presentation(&self) -> Vec<OutSection> {
        let mut sections = Vec::new();
        for graph in &self.graphs {
            let mut entries = Vec::new();
            if let Some(title) = &graph.title {
                entries.push(("title", Out::Text(title.clone())));
            }
            entries.push(("x", Out::Text(graph.x.to_string())));
            entries.push((
                "y",
                Out::TextList(graph.y.iter().map(ToString::to_string).collect()),
            ));
            sections.push(OutSection {
                header: Header::ArrayItem("graph"),
                entries,
            });
        }
        for series in &self.series {
            let mut entries = vec![
                ("vary", Out::Text(series.vary.clone())),
                ("from", Out::Number(series.from)),
                ("to", Out::Number(series.to)),
                ("step", Out::Number(series.step)),
                ("until", Out::Number(series.until)),
                ("measure", Out::TextList(series.measure.clone())),
            ];
            if let Some(theory) = &series.theory {
                entries.push(("theory", Out::Text(theory.clone())));
            }
            sections.push(OutSection {
                header: Header::ArrayItem("series"),
                entries,
            });
        }
        if let Some(view) = &self.view {
            let mut entries = Vec::new();
            if let Some(center) = view.center {
                entries.push(("center", Out::Vector(Vector::Cartesian(center))));
            }
            if let Some(width) = view.width {
                entries.push(("width", Out::Number(width)));
            }
            if let Some(follow) = &view.follow {
                entries.push(("follow", Out::Text(follow.as_str().to_owned())));
            }
            for (key, toggle) in [
                ("trails", view.trails),
                ("velocity", view.velocity),
                ("acceleration", view.acceleration),
                ("force", view.force),
                ("names", view.names),
            ] {
                if let Some(on) = toggle {
                    entries.push((key, Out::Bool(on)));
                }
            }
            sections.push(OutSection {
                header: Header::Table("view"),
                entries,
            });
        }
        sections
    }
}

/// A section's fields as written: every field in table order, optional ones only when
/// set.
/// Fields added to version 1 after files were first written, by label (a key alone can
/// be older in another section: a ramp's `friction`): a writer leaves each out while it
/// holds its default, so a file saved without using it reads, and is written, exactly
/// as before the field existed.
pub(super) const WRITTEN_WHEN_USED: &[&str] = &[
    "softening",
    "collisions between particles",
    "air resistance, linear",
    "air resistance, quadratic",
    "air density",
    "magnetic field",
    "drag coefficient",
    "friction between particles",
    "moment of inertia",
    "spin",
    "angle",
];

pub(super) fn out_fields<T>(fields: &[Field<T>], target: &T) -> Vec<(&'static str, Out)> {
    fields
        .iter()
        .filter_map(|f| {
            let out = match (f.get)(target) {
                FieldValue::Number(x) => Out::Number(x),
                FieldValue::Vector(v) => Out::Vector(v),
                FieldValue::Bool(b) => Out::Bool(b),
                FieldValue::Endpoint(Endpoint::Particle(name)) => Out::Text(name),
                FieldValue::Endpoint(Endpoint::Point(point)) => Out::Vector(point),
                FieldValue::Integrator(method) => Out::Text(method.as_str().to_owned()),
                FieldValue::PairForces(mode) => Out::Text(mode.as_str().to_owned()),
                FieldValue::Color(color) => Out::Text(color?.to_hex()),
                FieldValue::Bounds(bounds) => Out::Bounds(bounds?),
            };
            let unused = WRITTEN_WHEN_USED.contains(&f.label) && f.default == Some(&out.to_toml());
            (!unused).then_some((f.key, out))
        })
        .collect()
}

/// A body's entries: its shape first, then its table's fields without the zeros that
/// stand for "not given" (a polygon's width and height, the one of mass and density left
/// out), the static friction after the kinetic one when given.
fn body_fields(body: &Body) -> Vec<(&'static str, Out)> {
    let mut entries = vec![("shape", Out::Text(body.shape.as_str().to_owned()))];
    if let Shape::Polygon(vertices) = &body.shape {
        entries.push(("vertices", Out::Points(vertices.clone())));
    }
    for (key, out) in out_fields(fields::BODY, body) {
        let unset = matches!(out, Out::Number(x) if x == 0.0)
            && ["width", "height", "mass", "density"].contains(&key);
        if !unset {
            entries.push((key, out));
        }
        if key == "friction"
            && let Some(s) = body.static_friction
        {
            entries.push(("static_friction", Out::Number(s)));
        }
    }
    entries
}

fn force_fields(force: &Force) -> Vec<(&'static str, Out)> {
    let mut entries = Vec::new();
    if !force.on.is_empty() {
        entries.push(("on", Out::TextList(force.on.clone())));
    }
    entries.push(("fx", Out::Text(force.fx.clone())));
    entries.push(("fy", Out::Text(force.fy.clone())));
    if let Some(potential) = &force.potential {
        entries.push(("potential", Out::Text(potential.clone())));
    }
    entries
}

fn joint_fields(joint: &Joint) -> Vec<(&'static str, Out)> {
    let point = |p: DVec2| Out::Vector(Vector::Cartesian(p));
    let mut entries = Vec::new();
    if let JointKind::Pulley {
        a,
        radius,
        mass,
        inertia,
        spin,
        length,
    } = &joint.kind
    {
        entries.push(("a", Out::Text(a.clone())));
        entries.push(("b", Out::Text(joint.body.clone())));
        entries.push(("position", Out::Vector(joint.at)));
        entries.push(("radius", Out::Number(*radius)));
        entries.push(("mass", Out::Number(*mass)));
        entries.push(("inertia", Out::Number(*inertia)));
        if *spin != 0.0 {
            entries.push(("spin", Out::Number(*spin)));
        }
        if let Some(length) = length {
            entries.push(("length", Out::Number(*length)));
        }
        return entries;
    }
    match &joint.kind {
        JointKind::Pin => entries.push(("body", Out::Text(joint.body.clone()))),
        JointKind::Pulley { .. } => {}
        JointKind::Hinge { a, anchor_a } => {
            entries.push(("a", Out::Text(a.clone())));
            entries.push(("b", Out::Text(joint.body.clone())));
            if let Some(anchor) = anchor_a {
                entries.push(("anchor_a", point(*anchor)));
            }
        }
    }
    entries.push(("at", Out::Vector(joint.at)));
    if let Some(anchor) = joint.anchor {
        entries.push(("anchor", point(anchor)));
    }
    if let Some(reference) = joint.reference_angle {
        entries.push(("reference_angle", Out::Number(reference)));
    }
    if let Some((lower, upper)) = joint.limits {
        entries.push((
            "limits",
            Out::List(vec![Out::Number(lower), Out::Number(upper)]),
        ));
    }
    match joint.motor {
        None => {}
        Some(Motor::Torque(torque)) => {
            entries.push(("motor", Out::Numbers(vec![("torque", torque)])));
        }
        Some(Motor::Spin { spin, max_torque }) => entries.push((
            "motor",
            Out::Numbers(vec![("spin", spin), ("max_torque", max_torque)]),
        )),
    }
    entries
}

pub(super) enum Header {
    Root,
    Table(&'static str),
    ArrayItem(&'static str),
    /// An item of an array of tables inside a table: `[[lesson.question]]`.
    Nested(&'static str, &'static str),
    /// A table inside a table: `[instruments.stopwatch]`.
    Sub(&'static str, &'static str),
}

pub(super) struct OutSection {
    pub(super) header: Header,
    pub(super) entries: Vec<(&'static str, Out)>,
}

pub(super) enum Out {
    Integer(i64),
    Number(f64),
    Bool(bool),
    Text(String),
    TextList(Vec<String>),
    Vector(Vector),
    Bounds(Bounds),
    Points(Vec<glam::DVec2>),
    /// A list of mixed values: an instrument's ends, each a name or a point.
    List(Vec<Out>),
    /// An inline table of numbers: a motor, `{ spin = 2.0, max_torque = 5.0 }`.
    Numbers(Vec<(&'static str, f64)>),
}

/// A TOML float that parses back to the same `f64`: Rust's `Debug` for `f64` is the
/// shortest round-tripping form and always has a `.` or an exponent, as TOML requires.
pub(super) fn toml_float(x: f64) -> String {
    format!("{x:?}")
}

pub(super) fn toml_vector(v: Vector) -> String {
    match v {
        Vector::Cartesian(v) => format!("[{}, {}]", toml_float(v.x), toml_float(v.y)),
        Vector::Polar { magnitude, angle } => format!(
            "{{ magnitude = {}, angle = {} }}",
            toml_float(magnitude),
            toml_float(angle)
        ),
    }
}

pub(super) fn json_vector(v: Vector) -> serde_json::Value {
    match v {
        Vector::Cartesian(v) => serde_json::json!([v.x, v.y]),
        Vector::Polar { magnitude, angle } => {
            serde_json::json!({ "magnitude": magnitude, "angle": angle })
        }
    }
}

impl Out {
    fn to_toml(&self) -> String {
        match self {
            Self::Integer(i) => i.to_string(),
            Self::Number(x) => toml_float(*x),
            Self::Bool(b) => b.to_string(),
            Self::Text(text) => toml::Value::String(text.clone()).to_string(),
            Self::TextList(list) => {
                let items: Vec<String> = list
                    .iter()
                    .map(|t| toml::Value::String(t.clone()).to_string())
                    .collect();
                format!("[{}]", items.join(", "))
            }
            Self::Vector(v) => toml_vector(*v),
            Self::List(items) => {
                let items: Vec<String> = items.iter().map(Out::to_toml).collect();
                format!("[{}]", items.join(", "))
            }
            Self::Points(points) => {
                let items: Vec<String> = points
                    .iter()
                    .map(|&p| toml_vector(Vector::Cartesian(p)))
                    .collect();
                format!("[{}]", items.join(", "))
            }
            Self::Numbers(entries) => {
                let items: Vec<String> = entries
                    .iter()
                    .map(|(key, x)| format!("{key} = {}", toml_float(*x)))
                    .collect();
                format!("{{ {} }}", items.join(", "))
            }
            Self::Bounds(b) => {
                let mut text = format!(
                    "{{ min = {}, max = {}",
                    toml_vector(b.min),
                    toml_vector(b.max)
                );
                if b.friction != 0.0 {
                    let _ = write!(text, ", friction = {}", toml_float(b.friction));
                }
                if let Some(s) = b.static_friction {
                    let _ = write!(text, ", static_friction = {}", toml_float(s));
                }
                text.push_str(" }");
                text
            }
        }
    }

    fn to_json(&self) -> serde_json::Value {
        match self {
            Self::Integer(i) => (*i).into(),
            Self::Number(x) => (*x).into(),
            Self::Bool(b) => (*b).into(),
            Self::Text(text) => text.clone().into(),
            Self::TextList(list) => list.clone().into(),
            Self::Vector(v) => json_vector(*v),
            Self::List(items) => items.iter().map(Out::to_json).collect(),
            Self::Points(points) => points
                .iter()
                .map(|&p| json_vector(Vector::Cartesian(p)))
                .collect(),
            Self::Numbers(entries) => entries
                .iter()
                .map(|(key, x)| ((*key).to_owned(), serde_json::Value::from(*x)))
                .collect::<serde_json::Map<_, _>>()
                .into(),
            Self::Bounds(b) => {
                let mut bounds =
                    serde_json::json!({ "min": json_vector(b.min), "max": json_vector(b.max) });
                if b.friction != 0.0 {
                    bounds["friction"] = b.friction.into();
                }
                if let Some(s) = b.static_friction {
                    bounds["static_friction"] = s.into();
                }
                bounds
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// The parsed tree.
