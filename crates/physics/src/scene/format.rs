//! Scene files, version 1: TOML (and JSON with the same structure), loaded with
//! validation and saved in the same schema.
//!
//! Loading never stops at the first problem. The text is parsed into a small tree that
//! remembers where every key and value stands in the file; a reader walks it, noting
//! every unknown key, wrong type and missing field; the scene it builds is then checked by
//! [`Scene::validate`] (the same rules the app uses), and each problem gets the line and
//! column of the value it is about. JSON has no positions for values (`serde_json` keeps
//! none), so only its syntax errors carry a line and column.

use std::collections::{HashMap, HashSet};
use std::fmt::{self, Write as _};
use std::ops::Range;

use super::fields::{self, Field, Kind, Value as FieldValue};
use super::say;
use super::validate::{FieldRef, Section};
use super::{
    Bounds, Color, Endpoint, Follow, Graph, Particle, Ramp, Scene, Settings, Spring, Tie, TieKind,
    Vector, View, World,
};
use crate::Integrator;
use crate::scene::PairForces;

/// The scene-format version this library reads and writes.
pub const VERSION: i64 = 1;

/// The two encodings of a scene file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneFormat {
    /// TOML, the usual one.
    Toml,
    /// JSON with the same structure.
    Json,
}

impl SceneFormat {
    /// JSON for a `.json` file name, TOML for anything else.
    pub fn from_file_name(name: &str) -> Self {
        if name.to_ascii_lowercase().ends_with(".json") {
            Self::Json
        } else {
            Self::Toml
        }
    }
}

/// One thing wrong with a scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Problem {
    /// What is wrong, in words a student understands, starting with the object it is
    /// about: `particle 'B': mass must be greater than 0, got -2`.
    pub message: String,
    /// 1-based line in the file, where known.
    pub line: Option<usize>,
    /// 1-based column (in characters) in the file, where known.
    pub column: Option<usize>,
    /// The field the problem is about, where it is about one.
    pub field: Option<FieldRef>,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.column) {
            (Some(line), Some(column)) => {
                let (line, column) = (line.to_string(), column.to_string());
                let place = say(
                    "scene-at-line-column",
                    &[("line", &line), ("column", &column)],
                );
                write!(f, "{place}: {}", self.message)
            }
            (Some(line), None) => {
                let place = say("scene-at-line", &[("line", &line.to_string())]);
                write!(f, "{place}: {}", self.message)
            }
            _ => f.write_str(&self.message),
        }
    }
}

/// Why a scene could not be loaded: every problem found, in file order.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct LoadError {
    /// At least one.
    pub problems: Vec<Problem>,
}

impl LoadError {
    /// The problems as `newtonlab check` prints them for the file `source`: a count, then
    /// one line per problem, `source:line:column: message`.
    pub fn report(&self, source: &str) -> String {
        let count = self.problems.len();
        #[expect(clippy::cast_precision_loss, reason = "a count of problems")]
        let mut out = newtonlab_i18n::tr_with(
            "scene-problems-found",
            &[
                ("source", newtonlab_i18n::Arg::Text(source)),
                ("count", newtonlab_i18n::Arg::Number(count as f64)),
            ],
        );
        for problem in &self.problems {
            let place = match (problem.line, problem.column) {
                (Some(line), Some(column)) => format!("{source}:{line}:{column}"),
                (Some(line), None) => format!("{source}:{line}"),
                _ => source.to_owned(),
            };
            let _ = write!(out, "\n  {place}: {}", problem.message);
        }
        out
    }
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, problem) in self.problems.iter().enumerate() {
            if i > 0 {
                f.write_str("\n")?;
            }
            write!(f, "{problem}")?;
        }
        Ok(())
    }
}

impl Scene {
    /// Loads a scene from text in the given format.
    ///
    /// # Errors
    /// Every problem with the text or the scene it describes.
    pub fn parse(text: &str, format: SceneFormat) -> Result<Self, LoadError> {
        let root = match format {
            SceneFormat::Toml => parse_toml(text)?,
            SceneFormat::Json => parse_json(text)?,
        };
        let mut reader = Reader::new(text);
        let scene = reader.scene(&root);
        reader.finish(scene)
    }

    /// Loads a TOML scene.
    ///
    /// # Errors
    /// Every problem with the text or the scene it describes.
    pub fn from_toml(text: &str) -> Result<Self, LoadError> {
        Self::parse(text, SceneFormat::Toml)
    }

    /// Loads a JSON scene.
    ///
    /// # Errors
    /// Every problem with the text or the scene it describes.
    pub fn from_json(text: &str) -> Result<Self, LoadError> {
        Self::parse(text, SceneFormat::Json)
    }

    /// The scene as text in the given format.
    pub fn to_text(&self, format: SceneFormat) -> String {
        match format {
            SceneFormat::Toml => self.to_toml(),
            SceneFormat::Json => self.to_json(),
        }
    }

    /// The scene as a TOML scene file.
    pub fn to_toml(&self) -> String {
        let mut out = String::new();
        for section in self.document() {
            let _ = match section.header {
                Header::Root => Ok(()),
                Header::Table(name) => write!(out, "\n[{name}]\n"),
                Header::ArrayItem(name) => write!(out, "\n[[{name}]]\n"),
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
            .chain(
                self.ramps
                    .iter()
                    .map(|r| ("ramp", &r.name, out_fields(fields::RAMP, r))),
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
        sections
    }

    /// The app's part of the scene: `[[graph]]` and `[view]`.
    fn presentation(&self) -> Vec<OutSection> {
        let mut sections = Vec::new();
        for graph in &self.graphs {
            let mut entries = Vec::new();
            if let Some(title) = &graph.title {
                entries.push(("title", Out::Text(title.clone())));
            }
            entries.push(("x", Out::Text(graph.x.clone())));
            entries.push(("y", Out::TextList(graph.y.clone())));
            sections.push(OutSection {
                header: Header::ArrayItem("graph"),
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
/// Keys added to version 1 after files were first written: a writer leaves each out
/// while it holds its default, so a file saved without using it reads, and is written,
/// exactly as before the key existed.
const WRITTEN_WHEN_USED: &[&str] = &["softening", "collisions"];

fn out_fields<T>(fields: &[Field<T>], target: &T) -> Vec<(&'static str, Out)> {
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
            let unused = WRITTEN_WHEN_USED.contains(&f.key) && f.default == Some(&out.to_toml());
            (!unused).then_some((f.key, out))
        })
        .collect()
}

enum Header {
    Root,
    Table(&'static str),
    ArrayItem(&'static str),
}

struct OutSection {
    header: Header,
    entries: Vec<(&'static str, Out)>,
}

enum Out {
    Integer(i64),
    Number(f64),
    Bool(bool),
    Text(String),
    TextList(Vec<String>),
    Vector(Vector),
    Bounds(Bounds),
}

/// A TOML float that parses back to the same `f64`: Rust's `Debug` for `f64` is the
/// shortest round-tripping form and always has a `.` or an exponent, as TOML requires.
fn toml_float(x: f64) -> String {
    format!("{x:?}")
}

fn toml_vector(v: Vector) -> String {
    match v {
        Vector::Cartesian(v) => format!("[{}, {}]", toml_float(v.x), toml_float(v.y)),
        Vector::Polar { magnitude, angle } => format!(
            "{{ magnitude = {}, angle = {} }}",
            toml_float(magnitude),
            toml_float(angle)
        ),
    }
}

fn json_vector(v: Vector) -> serde_json::Value {
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
            Self::Bounds(b) => format!(
                "{{ min = {}, max = {} }}",
                toml_vector(b.min),
                toml_vector(b.max)
            ),
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
            Self::Bounds(b) => {
                serde_json::json!({ "min": json_vector(b.min), "max": json_vector(b.max) })
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// The parsed tree.

type Span = Option<Range<usize>>;

/// A parsed value with the byte range it came from (TOML only).
struct Node {
    value: Value,
    span: Span,
}

enum Value {
    Bool(bool),
    Number(f64),
    Text(String),
    Array(Vec<Node>),
    Table(Vec<Entry>),
    /// A TOML date or time: never valid in a scene.
    Datetime,
}

struct Entry {
    key: String,
    key_span: Span,
    node: Node,
}

impl Value {
    /// What the value is, as a message says it: "a number".
    fn kind(&self) -> String {
        say(
            match self {
                Self::Bool(_) => "scene-got-bool",
                Self::Number(_) => "scene-got-number",
                Self::Text(_) => "scene-got-text",
                Self::Array(_) => "scene-got-list",
                Self::Table(_) => "scene-got-table",
                Self::Datetime => "scene-got-date",
            },
            &[],
        )
    }
}

fn parse_toml(text: &str) -> Result<Node, LoadError> {
    let (table, errors) = toml::de::DeTable::parse_recoverable(text);
    if !errors.is_empty() {
        let problems = errors
            .iter()
            .map(|error| {
                let (line, column) = error.span().map_or((None, None), |span| {
                    let (line, column) = line_column(text, span.start);
                    (Some(line), Some(column))
                });
                Problem {
                    message: say("scene-bad-toml", &[("error", error.message().trim())]),
                    line,
                    column,
                    field: None,
                }
            })
            .collect();
        return Err(LoadError { problems });
    }
    let span = table.span();
    Ok(Node {
        value: toml_table(table.into_inner()),
        span: Some(span),
    })
}

fn toml_table(table: toml::de::DeTable<'_>) -> Value {
    Value::Table(
        table
            .into_iter()
            .map(|(key, value)| Entry {
                key_span: Some(key.span()),
                key: key.into_inner().into_owned(),
                node: toml_node(value),
            })
            .collect(),
    )
}

fn toml_node(node: toml::Spanned<toml::de::DeValue<'_>>) -> Node {
    use toml::de::DeValue;
    let span = Some(node.span());
    let value = match node.into_inner() {
        DeValue::String(s) => Value::Text(s.into_owned()),
        DeValue::Integer(i) => Value::Number(
            i64::from_str_radix(&i.as_str().replace('_', ""), i.radix())
                .map_or(f64::NAN, |i| i as f64),
        ),
        DeValue::Float(f) => Value::Number(parse_toml_float(f.as_str())),
        DeValue::Boolean(b) => Value::Bool(b),
        DeValue::Datetime(_) => Value::Datetime,
        DeValue::Array(items) => Value::Array(items.into_iter().map(toml_node).collect()),
        DeValue::Table(table) => toml_table(table),
    };
    Node { value, span }
}

fn parse_toml_float(raw: &str) -> f64 {
    let text = raw.replace('_', "");
    match text.trim_start_matches('+') {
        "inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        "nan" | "-nan" => f64::NAN,
        other => other.parse().unwrap_or(f64::NAN),
    }
}

fn parse_json(text: &str) -> Result<Node, LoadError> {
    match serde_json::from_str::<serde_json::Value>(text) {
        Ok(value) => Ok(json_node(value)),
        Err(error) => Err(LoadError {
            problems: vec![Problem {
                message: say("scene-bad-json", &[("error", &error.to_string())]),
                line: Some(error.line()),
                column: Some(error.column()),
                field: None,
            }],
        }),
    }
}

fn json_node(value: serde_json::Value) -> Node {
    use serde_json::Value as J;
    let value = match value {
        J::Null => Value::Datetime,
        J::Bool(b) => Value::Bool(b),
        J::Number(n) => Value::Number(n.as_f64().unwrap_or(f64::NAN)),
        J::String(s) => Value::Text(s),
        J::Array(items) => Value::Array(items.into_iter().map(json_node).collect()),
        J::Object(map) => Value::Table(
            map.into_iter()
                .map(|(key, value)| Entry {
                    key,
                    key_span: None,
                    node: json_node(value),
                })
                .collect(),
        ),
    };
    Node { value, span: None }
}

/// 1-based line and column (in characters) of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before[line_start..].chars().count() + 1;
    (line, column)
}

// ---------------------------------------------------------------------------------------
// The reader: tree → Scene, noting every structural problem.

struct Reader<'t> {
    text: &'t str,
    problems: Vec<(Span, Problem)>,
    /// Where each field's value stands, to place validation problems.
    spans: HashMap<FieldRef, Range<usize>>,
    /// Fields that already have a problem: validation would only repeat it.
    failed: HashSet<FieldRef>,
}

/// One table being read: which keys were used, for reporting unknown ones.
struct Table<'n> {
    entries: &'n [Entry],
    /// Where the table starts, for problems about keys it lacks.
    span: Span,
    used: Vec<bool>,
    section: Section,
    label: String,
}

impl<'n> Table<'n> {
    fn get(&mut self, key: &str) -> Option<&'n Node> {
        let index = self.entries.iter().position(|e| e.key == key)?;
        self.used[index] = true;
        Some(&self.entries[index].node)
    }
}

const ROOT_KEYS: &[&str] = &[
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
    "graph",
    "view",
];
const GRAPH_KEYS: &[&str] = &["title", "x", "y"];
const VIEW_KEYS: &[&str] = &["center", "width", "follow"];

impl<'t> Reader<'t> {
    fn new(text: &'t str) -> Self {
        Self {
            text,
            problems: Vec::new(),
            spans: HashMap::new(),
            failed: HashSet::new(),
        }
    }

    fn problem(&mut self, span: Span, field: Option<FieldRef>, message: String) {
        if let Some(field) = field {
            self.failed.insert(field);
        }
        let (line, column) = match &span {
            Some(span) => {
                let (line, column) = line_column(self.text, span.start);
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
    fn table<'n>(&mut self, node: &'n Node, section: Section, label: String) -> Option<Table<'n>> {
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
            None
        }
    }

    /// Reports the keys of `table` that were never read.
    fn close(&mut self, table: &Table<'_>, known: &[&str]) {
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
    fn field<T>(
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
        if let Some(span) = &node.span {
            self.spans.insert(field, span.clone());
        }
        match read(node) {
            Ok(value) => Some(value),
            Err(reason) => {
                let message = format!("{}: {key} {reason}", table.label);
                self.problem(node.span.clone(), Some(field), message);
                None
            }
        }
    }

    fn required<T>(
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

    fn scene(&mut self, root: &Node) -> Scene {
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
                let span = self.spans.get(&field).cloned();
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
        for (i, node) in self.items(&mut top, "particle").iter().enumerate() {
            let particle = self.particle(node, i);
            scene.particles.push(particle);
        }
        for (i, node) in self.items(&mut top, "spring").iter().enumerate() {
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
        for (i, node) in self.items(&mut top, "graph").iter().enumerate() {
            let graph = self.graph(node, i);
            scene.graphs.push(graph);
        }
        if let Some(node) = top.get("view") {
            scene.view = Some(self.view(node));
        }
        self.close(&top, ROOT_KEYS);
        scene
    }

    /// The entries of an array of tables such as `[[particle]]`.
    fn items<'n>(&mut self, top: &mut Table<'n>, key: &str) -> &'n [Node] {
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
    fn fields<T>(&mut self, t: &mut Table<'_>, fields: &[Field<T>], target: &mut T) {
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

    fn world(&mut self, node: &Node) -> World {
        let mut world = World::default();
        if let Some(mut t) = self.table(node, Section::World, "[world]".to_owned()) {
            self.fields(&mut t, fields::WORLD, &mut world);
            self.close(&t, &fields::keys(&[], fields::WORLD));
        }
        world
    }

    fn settings(&mut self, node: &Node) -> Settings {
        let mut settings = Settings::default();
        if let Some(mut t) = self.table(node, Section::Simulation, "[simulation]".to_owned()) {
            self.fields(&mut t, fields::SIMULATION, &mut settings);
            self.close(&t, &fields::keys(&[], fields::SIMULATION));
        }
        settings
    }

    /// Opens the table of an object and reads its name, which labels its messages.
    fn object<'n>(
        &mut self,
        node: &'n Node,
        kind: &str,
        section: Section,
        index: usize,
    ) -> Option<(Table<'n>, String)> {
        // Particles, springs and ramps are named by their initial (p1, s1, r1); rods and
        // strings in full (rod1, string1), which would clash with ramps and springs.
        let default_name = match kind {
            "rod" | "string" => format!("{kind}{}", index + 1),
            _ => format!("{}{}", &kind[..1], index + 1),
        };
        let mut t = self.table(node, section, super::validate::numbered(kind, index))?;
        let name = self
            .field(&mut t, "name", read_text)
            .unwrap_or(default_name);
        if !name.is_empty() {
            t.label = say("scene-named", &[("kind", kind), ("name", &name)]);
        }
        Some((t, name))
    }

    fn particle(&mut self, node: &Node, index: usize) -> Particle {
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

    fn spring(&mut self, node: &Node, index: usize) -> Spring {
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
    fn tie(&mut self, node: &Node, kind: TieKind, index: usize, scene: &Scene) -> Tie {
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

    fn ramp(&mut self, node: &Node, index: usize) -> Ramp {
        let mut ramp = Ramp::new(format!("r{}", index + 1), Vector::ZERO, Vector::ZERO);
        if let Some((mut t, name)) = self.object(node, "ramp", Section::Ramp(index), index) {
            ramp.name = name;
            self.fields(&mut t, fields::RAMP, &mut ramp);
            self.close(&t, &fields::keys(&["name"], fields::RAMP));
        }
        ramp
    }

    fn graph(&mut self, node: &Node, index: usize) -> Graph {
        let mut graph = Graph::against_time(Vec::<String>::new());
        let Some(mut t) = self.table(
            node,
            Section::Graph(index),
            super::validate::numbered("graph", index),
        ) else {
            return graph;
        };
        graph.title = self.field(&mut t, "title", read_text);
        if let Some(title) = &graph.title {
            t.label = say("scene-named", &[("kind", "graph"), ("name", title)]);
        }
        if let Some(x) = self.field(&mut t, "x", read_text) {
            graph.x = x;
        }
        graph.y = self.required(&mut t, "y", read_text_list, Vec::new());
        self.close(&t, GRAPH_KEYS);
        graph
    }

    fn view(&mut self, node: &Node) -> View {
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
        self.close(&t, VIEW_KEYS);
        view
    }

    /// Adds the validation problems (with positions) to the reading problems and returns
    /// the scene if there are none.
    fn finish(mut self, scene: Scene) -> Result<Scene, LoadError> {
        for mut problem in scene.validate() {
            let Some(field) = problem.field else { continue };
            if self.failed.contains(&field) {
                continue;
            }
            let span = self.spans.get(&field).cloned();
            if let Some(span) = &span {
                let (line, column) = line_column(self.text, span.start);
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

fn read_number(node: &Node) -> Result<f64, String> {
    match node.value {
        Value::Number(x) if x.is_finite() => Ok(x),
        Value::Number(x) => Err(say("scene-must-be-finite", &[("got", &x.to_string())])),
        ref other => Err(say("scene-must-be-number", &[("got", &other.kind())])),
    }
}

fn read_bool(node: &Node) -> Result<bool, String> {
    match node.value {
        Value::Bool(b) => Ok(b),
        ref other => Err(say("scene-must-be-bool", &[("got", &other.kind())])),
    }
}

fn read_text(node: &Node) -> Result<String, String> {
    match &node.value {
        Value::Text(text) => Ok(text.clone()),
        other => Err(say("scene-must-be-text", &[("got", &other.kind())])),
    }
}

/// Reads a value of `kind`.
fn read_value(kind: Kind, node: &Node) -> Result<FieldValue, String> {
    Ok(match kind {
        Kind::Number(_) => FieldValue::Number(read_number(node)?),
        Kind::Vector => FieldValue::Vector(read_vector(node)?),
        Kind::Bool => FieldValue::Bool(read_bool(node)?),
        Kind::Endpoint => FieldValue::Endpoint(read_endpoint(node)?),
        Kind::Integrator => FieldValue::Integrator(read_integrator(node)?),
        Kind::PairForces => FieldValue::PairForces(read_pair_forces(node)?),
        Kind::Color => FieldValue::Color(Some(read_color(node)?)),
        Kind::Bounds => FieldValue::Bounds(Some(read_bounds(node)?)),
    })
}

fn read_text_list(node: &Node) -> Result<Vec<String>, String> {
    let wrong = |got: String| say("scene-must-be-quantities", &[("got", &got)]);
    match &node.value {
        Value::Array(items) => items
            .iter()
            .map(|item| read_text(item).map_err(|_| wrong(item.value.kind())))
            .collect(),
        other => Err(wrong(other.kind())),
    }
}

/// The two ways to write a vector, as messages show them (the file's own syntax).
const VECTOR_FORMS: [(&str, &str); 2] = [
    ("cartesian", "[x, y]"),
    ("polar", "{ magnitude = m, angle = degrees }"),
];

fn read_vector(node: &Node) -> Result<Vector, String> {
    let wrong = |id, arg: (&str, &str)| say(id, &[VECTOR_FORMS[0], VECTOR_FORMS[1], arg]);
    match &node.value {
        Value::Array(items) => match items.as_slice() {
            [x, y] => Ok(Vector::cartesian(read_number(x)?, read_number(y)?)),
            _ => Err(wrong(
                "scene-vector-length",
                ("count", &items.len().to_string()),
            )),
        },
        Value::Table(entries) => {
            let get = |key: &str| entries.iter().find(|e| e.key == key).map(|e| &e.node);
            if let Some(extra) = entries
                .iter()
                .find(|e| e.key != "magnitude" && e.key != "angle")
            {
                return Err(wrong("scene-vector-extra", ("key", &extra.key)));
            }
            match (get("magnitude"), get("angle")) {
                (Some(m), Some(a)) => Ok(Vector::polar(
                    read_number(m).map_err(|e| format!("magnitude {e}"))?,
                    read_number(a).map_err(|e| format!("angle {e}"))?,
                )),
                _ => Err(wrong("scene-vector-polar", ("got", ""))),
            }
        }
        other => Err(wrong("scene-vector-got", ("got", &other.kind()))),
    }
}

fn read_bounds(node: &Node) -> Result<Bounds, String> {
    let wrong = |id, arg: (&str, &str)| say(id, &[("form", "{ min = [x, y], max = [x, y] }"), arg]);
    let Value::Table(entries) = &node.value else {
        return Err(wrong("scene-bounds-got", ("got", &node.value.kind())));
    };
    if let Some(extra) = entries.iter().find(|e| e.key != "min" && e.key != "max") {
        return Err(wrong("scene-bounds-extra", ("key", &extra.key)));
    }
    let get = |key: &str| entries.iter().find(|e| e.key == key).map(|e| &e.node);
    match (get("min"), get("max")) {
        (Some(min), Some(max)) => Ok(Bounds {
            min: read_vector(min).map_err(|e| format!("min {e}"))?,
            max: read_vector(max).map_err(|e| format!("max {e}"))?,
        }),
        _ => Err(wrong("scene-bounds-both", ("got", ""))),
    }
}

fn read_endpoint(node: &Node) -> Result<Endpoint, String> {
    match &node.value {
        Value::Text(name) => Ok(Endpoint::Particle(name.clone())),
        Value::Array(_) | Value::Table(_) => read_vector(node)
            .map(Endpoint::Point)
            .map_err(|e| say("scene-endpoint-point", &[("reason", &e)])),
        other => Err(say("scene-endpoint-got", &[("got", &other.kind())])),
    }
}

fn read_integrator(node: &Node) -> Result<Integrator, String> {
    let name = read_text(node)?;
    name.parse().map_err(|_| {
        let names: Vec<&str> = Integrator::ALL.iter().map(|i| i.as_str()).collect();
        say(
            "scene-not-integrator",
            &[("name", &name), ("names", &names.join(", "))],
        )
    })
}

fn read_pair_forces(node: &Node) -> Result<PairForces, String> {
    let name = read_text(node)?;
    PairForces::ALL
        .into_iter()
        .find(|mode| mode.as_str() == name)
        .ok_or_else(|| say("scene-not-pair-forces", &[("name", &name)]))
}

fn read_color(node: &Node) -> Result<Color, String> {
    let text = read_text(node)?;
    Color::parse_hex(&text).ok_or_else(|| say("scene-not-colour", &[("text", &text)]))
}

/// The known key closest to a misspelt one, if it is close enough to be a typo.
fn closest<'k>(key: &str, known: &[&'k str]) -> Option<&'k str> {
    known
        .iter()
        .map(|k| (edit_distance(key, k), *k))
        .filter(|(d, k)| *d <= 2.max(k.len() / 4))
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

/// Levenshtein distance, for "did you mean" hints.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut previous = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let substitution = previous + usize::from(ca != *cb);
            previous = row[j + 1];
            row[j + 1] = substitution.min(row[j] + 1).min(row[j + 1] + 1);
        }
    }
    row[b.len()]
}
