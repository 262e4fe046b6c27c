//! The parse tree: TOML or JSON as nodes that remember where each key and value stands
//! in the file.

use std::ops::Range;

use crate::scene::error::{LoadError, Problem};
use crate::scene::say;

pub(super) type Span = Option<Range<usize>>;

/// A parsed value with the byte range it came from (TOML only).
pub(super) struct Node {
    pub(super) value: Value,
    pub(super) span: Span,
}

pub(super) enum Value {
    Bool(bool),
    Number(f64),
    Text(String),
    Array(Vec<Node>),
    Table(Vec<Entry>),
    /// A TOML date or time: never valid in a scene.
    Datetime,
}

pub(super) struct Entry {
    pub(super) key: String,
    pub(super) key_span: Span,
    pub(super) node: Node,
}

impl Value {
    /// What the value is, as a message says it: "a number".
    pub(super) fn kind(&self) -> String {
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

pub(super) fn parse_toml(text: &str) -> Result<Node, LoadError> {
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

pub(super) fn toml_table(table: toml::de::DeTable<'_>) -> Value {
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

pub(super) fn toml_node(node: toml::Spanned<toml::de::DeValue<'_>>) -> Node {
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

pub(super) fn parse_toml_float(raw: &str) -> f64 {
    let text = raw.replace('_', "");
    match text.trim_start_matches('+') {
        "inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        "nan" | "-nan" => f64::NAN,
        other => other.parse().unwrap_or(f64::NAN),
    }
}

pub(super) fn parse_json(text: &str) -> Result<Node, LoadError> {
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

pub(super) fn json_node(value: serde_json::Value) -> Node {
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
pub(super) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before[line_start..].chars().count() + 1;
    (line, column)
}

// ---------------------------------------------------------------------------------------
// The reader: tree → Scene, noting every structural problem.
