//! The parse tree: TOML or JSON as nodes that remember where each key and value stands
//! in the file (JSON's read by `jsonc-parser` in strict mode, for its ranges), so that
//! every problem of either format is told with its line and column.

use std::borrow::Cow;
use std::ops::Range;

use crate::scene::error::{LoadError, Problem};
use crate::scene::say;

pub(super) type Span = Option<Range<usize>>;

/// A parsed value with the byte range it came from.
pub(super) struct Node<'t> {
    pub(super) value: Value<'t>,
    pub(super) span: Span,
}

pub(super) enum Value<'t> {
    Bool(bool),
    Number(f64),
    /// Text borrowed from the file where it is written plainly (a name, most keys): a
    /// million particles then cost no million small strings.
    Text(Cow<'t, str>),
    Array(Vec<Node<'t>>),
    Table(Vec<Entry<'t>>),
    /// A TOML date or time: never valid in a scene.
    Datetime,
    /// JSON's `null`: never valid in a scene.
    Null,
    /// A number as written that no f64 holds (1e-400, 1e400): kept as text, so that the
    /// message says what was written rather than 0 or infinity.
    Beyond(String),
}

pub(super) struct Entry<'t> {
    pub(super) key: Cow<'t, str>,
    pub(super) key_span: Span,
    pub(super) node: Node<'t>,
}

impl Value<'_> {
    /// What the value is, as a message says it: "a number".
    pub(super) fn kind(&self) -> String {
        say(
            match self {
                Self::Bool(_) => "scene-got-bool",
                Self::Number(_) | Self::Beyond(_) => "scene-got-number",
                Self::Text(_) => "scene-got-text",
                Self::Array(_) => "scene-got-list",
                Self::Table(_) => "scene-got-table",
                Self::Datetime => "scene-got-date",
                Self::Null => "scene-got-null",
            },
            &[],
        )
    }
}

/// A TOML text's tree: slice by slice where that means the same (a long scene), else whole.
pub(super) fn parse_toml(text: &str) -> Result<Node<'_>, LoadError> {
    match super::slices::parse_in_slices(text) {
        Some(root) => Ok(root),
        None => parse_toml_whole(text),
    }
}

/// A TOML text's tree, parsed at once.
pub(super) fn parse_toml_whole(text: &str) -> Result<Node<'_>, LoadError> {
    let (table, errors) = toml::de::DeTable::parse_recoverable(text);
    if !errors.is_empty() {
        // One scan for the line starts: a file can hold thousands of syntax errors.
        let lines = Lines::new(text);
        let problems = errors
            .iter()
            .map(|error| {
                let (line, column) = error.span().map_or((None, None), |span| {
                    let (line, column) = lines.at(text, span.start);
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
        value: Value::Table(toml_entries(table.into_inner(), 0)),
        span: Some(span),
    })
}

/// A TOML table's entries, every range moved by `offset` (where the parsed text starts in
/// the file).
pub(super) fn toml_entries(table: toml::de::DeTable<'_>, offset: usize) -> Vec<Entry<'_>> {
    table
        .into_iter()
        .map(|(key, value)| Entry {
            key_span: Some(moved(key.span(), offset)),
            key: key.into_inner(),
            node: toml_node(value, offset),
        })
        .collect()
}

fn moved(span: Range<usize>, offset: usize) -> Range<usize> {
    span.start + offset..span.end + offset
}

fn toml_node(node: toml::Spanned<toml::de::DeValue<'_>>, offset: usize) -> Node<'_> {
    use toml::de::DeValue;
    let span = Some(moved(node.span(), offset));
    let value = match node.into_inner() {
        DeValue::String(s) => Value::Text(s),
        DeValue::Integer(i) => {
            let digits = i.as_str().replace('_', "");
            // Beyond i64 (99999999999999999999) a decimal integer is still a number.
            match i64::from_str_radix(&digits, i.radix()) {
                Ok(i) => Value::Number(i as f64),
                Err(_) if i.radix() == 10 => number(&digits),
                Err(_) => Value::Beyond(digits),
            }
        }
        DeValue::Float(f) => match parse_toml_float(f.as_str()) {
            x if x.is_nan() && !f.as_str().contains("nan") => Value::Beyond(f.as_str().to_owned()),
            x => number_as_written(f.as_str(), x),
        },
        DeValue::Boolean(b) => Value::Bool(b),
        DeValue::Datetime(_) => Value::Datetime,
        DeValue::Array(items) => {
            // A fresh vector of its own length: collected in place, the tree would keep
            // toml's larger items' room (a million positions held twice their size).
            let mut nodes = Vec::with_capacity(items.len());
            nodes.extend(items.into_iter().map(|item| toml_node(item, offset)));
            Value::Array(nodes)
        }
        DeValue::Table(table) => Value::Table(toml_entries(table, offset)),
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

/// `text` as a number: what it parses to, or [`Value::Beyond`] when that is 0 or infinite
/// though the digits say otherwise.
fn number(text: &str) -> Value<'static> {
    number_as_written(text, text.parse().unwrap_or(f64::NAN))
}

/// `x`, read from `text`, or [`Value::Beyond`] when it rounded to 0 or to infinity from a
/// number that is neither (1e-400, 1e400).
fn number_as_written(text: &str, x: f64) -> Value<'static> {
    let mantissa = text.split(['e', 'E']).next().unwrap_or(text);
    let nonzero = mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b));
    let infinite_as_written = text.contains("inf");
    if (x == 0.0 && nonzero) || (x.is_infinite() && !infinite_as_written) {
        Value::Beyond(text.to_owned())
    } else {
        Value::Number(x)
    }
}

/// A problem of the JSON text at byte `at`.
fn json_problem(text: &str, at: usize, message: String) -> LoadError {
    let (line, column) = line_column(text, at);
    LoadError {
        problems: vec![Problem {
            message,
            line: Some(line),
            column: Some(column),
            field: None,
        }],
    }
}

pub(super) fn parse_json(text: &str) -> Result<Node<'_>, LoadError> {
    // A byte-order mark is no part of the JSON (TOML's reader passes over it too); the
    // ranges stay those of the whole text.
    let start = if text.starts_with('\u{feff}') {
        '\u{feff}'.len_utf8()
    } else {
        0
    };
    let strict = jsonc_parser::ParseOptions {
        allow_comments: false,
        allow_loose_object_property_names: false,
        allow_trailing_commas: false,
        allow_missing_commas: false,
        allow_single_quoted_strings: false,
        allow_hexadecimal_numbers: false,
        allow_unary_plus_numbers: false,
    };
    let parsed = jsonc_parser::parse_to_ast(
        &text[start..],
        &jsonc_parser::CollectOptions::default(),
        &strict,
    )
    .map_err(|error| {
        json_problem(
            text,
            start + error.range().start,
            say("scene-bad-json", &[("error", &error.kind().to_string())]),
        )
    })?;
    let value = parsed.value.ok_or_else(|| {
        json_problem(
            text,
            text.len(),
            say("scene-bad-json", &[("error", "the file holds no value")]),
        )
    })?;
    json_node(value, start, text)
}

/// A JSON value as a node; its ranges moved by `start` (the byte-order mark) into `text`.
fn json_node<'t>(
    value: jsonc_parser::ast::Value<'t>,
    start: usize,
    text: &str,
) -> Result<Node<'t>, LoadError> {
    use jsonc_parser::ast::Value as J;
    let span = |range: jsonc_parser::common::Range| Some(start + range.start..start + range.end);
    Ok(match value {
        J::NullKeyword(null) => Node {
            value: Value::Null,
            span: span(null.range),
        },
        J::BooleanLit(b) => Node {
            value: Value::Bool(b.value),
            span: span(b.range),
        },
        J::NumberLit(n) => Node {
            value: number(n.value),
            span: span(n.range),
        },
        J::StringLit(s) => Node {
            value: Value::Text(s.value),
            span: span(s.range),
        },
        J::Array(array) => Node {
            span: span(array.range),
            value: Value::Array(
                array
                    .elements
                    .into_iter()
                    .map(|item| json_node(item, start, text))
                    .collect::<Result<_, _>>()?,
            ),
        },
        J::Object(object) => {
            let mut entries: Vec<Entry> = Vec::with_capacity(object.properties.len());
            for property in object.properties {
                let (key, key_range) = match property.name {
                    jsonc_parser::ast::ObjectPropName::String(s) => (s.value, s.range),
                    jsonc_parser::ast::ObjectPropName::Word(w) => (Cow::Borrowed(w.value), w.range),
                };
                // TOML refuses a key given twice; so does JSON here, rather than keep the
                // last in silence.
                if entries.iter().any(|e| e.key == key) {
                    return Err(json_problem(
                        text,
                        start + key_range.start,
                        say("scene-json-duplicate-key", &[("key", &key)]),
                    ));
                }
                entries.push(Entry {
                    key,
                    key_span: span(key_range),
                    node: json_node(property.value, start, text)?,
                });
            }
            Node {
                value: Value::Table(entries),
                span: span(object.range),
            }
        }
    })
}

/// Where each line of a text starts: a problem's line by binary search, so that many
/// problems cost no more than one scan of the text.
pub(super) struct Lines {
    starts: Vec<usize>,
}

impl Lines {
    pub(super) fn new(text: &str) -> Self {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Self { starts }
    }

    /// 1-based line and column (in characters) of byte `offset` of `text`, the text the
    /// lines were found in.
    pub(super) fn at(&self, text: &str, offset: usize) -> (usize, usize) {
        let offset = offset.min(text.len());
        let line = self.starts.partition_point(|&start| start <= offset);
        let start = self.starts[line - 1];
        let column = text.get(start..offset).map_or(1, |s| s.chars().count() + 1);
        (line, column)
    }
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

#[cfg(test)]
mod tests {
    use super::{Lines, line_column};

    /// The table of line starts places every byte as the scan from the start does, on
    /// lines of several lengths, with characters of several widths.
    #[test]
    fn lines_place_every_offset_as_a_scan_does() {
        let text = "version = 1\n\n[[particle]]\nname = \"Bébé ünd 🐢\"\nmass = -1\n\r\nlast";
        let lines = Lines::new(text);
        for offset in (0..=text.len()).filter(|&i| text.is_char_boundary(i)) {
            assert_eq!(
                lines.at(text, offset),
                line_column(text, offset),
                "at {offset}"
            );
        }
    }
}
