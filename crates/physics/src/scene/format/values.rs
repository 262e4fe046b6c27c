//! Reading one value of a scene file: a number, a vector in either form, a point list,
//! bounds, an endpoint, an integrator, a motor, a colour; and "did you mean" for a
//! misspelt key.

use super::tree::{Node, Value};
use crate::Integrator;
use crate::scene::fields::{Kind, Value as FieldValue};
use crate::scene::{Bounds, Color, Endpoint, Motor, PairForces, Vector, say};

pub(super) fn read_number(node: &Node) -> Result<f64, String> {
    match node.value {
        Value::Number(x) if x.is_finite() => Ok(x),
        Value::Number(x) => Err(say("scene-must-be-finite", &[("got", &x.to_string())])),
        Value::Beyond(ref text) => Err(say("scene-number-beyond-f64", &[("text", text)])),
        ref other => Err(say("scene-must-be-number", &[("got", &other.kind())])),
    }
}

/// `[x, y]` in metres: a point in a body's frame.
pub(super) fn read_point(node: &Node) -> Result<glam::DVec2, String> {
    read_vector(node).map(Vector::to_dvec2)
}

/// `[lower, upper]` in degrees.
pub(super) fn read_limits(node: &Node) -> Result<(f64, f64), String> {
    match &node.value {
        Value::Array(items) if items.len() == 2 => {
            Ok((read_number(&items[0])?, read_number(&items[1])?))
        }
        _ => Err(say("scene-limits", &[])),
    }
}

/// `{ torque = T }` or `{ spin = W, max_torque = T }`.
pub(super) fn read_motor(node: &Node) -> Result<Motor, String> {
    let Value::Table(entries) = &node.value else {
        return Err(say("scene-motor", &[]));
    };
    let number = |key: &str| match entries.iter().find(|e| e.key == key) {
        None => Ok(None),
        Some(entry) => read_number(&entry.node).map(Some),
    };
    let torque = number("torque")?;
    let spin = number("spin")?;
    let max_torque = number("max_torque")?;
    let known = entries
        .iter()
        .all(|e| ["torque", "spin", "max_torque"].contains(&e.key.as_ref()));
    match (torque, spin, max_torque) {
        (Some(torque), None, None) if known => Ok(Motor::Torque(torque)),
        (None, Some(spin), Some(max_torque)) if known => Ok(Motor::Spin { spin, max_torque }),
        _ => Err(say("scene-motor", &[])),
    }
}

pub(super) fn read_bool(node: &Node) -> Result<bool, String> {
    match node.value {
        Value::Bool(b) => Ok(b),
        ref other => Err(say("scene-must-be-bool", &[("got", &other.kind())])),
    }
}

pub(super) fn read_text(node: &Node) -> Result<String, String> {
    match &node.value {
        Value::Text(text) => Ok(text.to_string()),
        other => Err(say("scene-must-be-text", &[("got", &other.kind())])),
    }
}

/// Reads a value of `kind`.
pub(super) fn read_value(kind: Kind, node: &Node) -> Result<FieldValue, String> {
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

pub(super) fn read_text_list(node: &Node) -> Result<Vec<String>, String> {
    let wrong = |got: String| say("scene-must-be-quantities", &[("got", &got)]);
    match &node.value {
        Value::Array(items) => items
            .iter()
            .map(|item| read_text(item).map_err(|_| wrong(item.value.kind())))
            .collect(),
        other => Err(wrong(other.kind())),
    }
}

/// A polygon's vertices: a list of `[x, y]`.
pub(super) fn read_points(node: &Node) -> Result<Vec<glam::DVec2>, String> {
    let wrong = |got: String| say("scene-must-be-points", &[("got", &got)]);
    let Value::Array(items) = &node.value else {
        return Err(wrong(node.value.kind()));
    };
    items
        .iter()
        .map(|item| match &item.value {
            Value::Array(pair) if pair.len() == 2 => Ok(glam::DVec2::new(
                read_number(&pair[0])?,
                read_number(&pair[1])?,
            )),
            other => Err(wrong(other.kind())),
        })
        .collect()
}

/// The two ways to write a vector, as messages show them (the file's own syntax).
pub(super) const VECTOR_FORMS: [(&str, &str); 2] = [
    ("cartesian", "[x, y]"),
    ("polar", "{ magnitude = m, angle = degrees }"),
];

pub(super) fn read_vector(node: &Node) -> Result<Vector, String> {
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

pub(super) fn read_bounds(node: &Node) -> Result<Bounds, String> {
    let wrong = |id, arg: (&str, &str)| {
        say(
            id,
            &[
                (
                    "form",
                    "{ min = [x, y], max = [x, y], friction = μ, static_friction = μs }",
                ),
                arg,
            ],
        )
    };
    let Value::Table(entries) = &node.value else {
        return Err(wrong("scene-bounds-got", ("got", &node.value.kind())));
    };
    if let Some(extra) = entries
        .iter()
        .find(|e| !["min", "max", "friction", "static_friction"].contains(&&*e.key))
    {
        return Err(wrong("scene-bounds-extra", ("key", &extra.key)));
    }
    let get = |key: &str| entries.iter().find(|e| e.key == key).map(|e| &e.node);
    let friction = match get("friction") {
        Some(node) => read_number(node).map_err(|e| format!("friction {e}"))?,
        None => 0.0,
    };
    let static_friction = match get("static_friction") {
        Some(node) => Some(read_number(node).map_err(|e| format!("static_friction {e}"))?),
        None => None,
    };
    match (get("min"), get("max")) {
        (Some(min), Some(max)) => Ok(Bounds {
            min: read_vector(min).map_err(|e| format!("min {e}"))?,
            max: read_vector(max).map_err(|e| format!("max {e}"))?,
            friction,
            static_friction,
        }),
        _ => Err(wrong("scene-bounds-both", ("got", ""))),
    }
}

pub(super) fn read_endpoint(node: &Node) -> Result<Endpoint, String> {
    match &node.value {
        Value::Text(name) => Ok(Endpoint::Particle(name.to_string())),
        Value::Array(_) | Value::Table(_) => read_vector(node)
            .map(Endpoint::Point)
            .map_err(|e| say("scene-endpoint-point", &[("reason", &e)])),
        other => Err(say("scene-endpoint-got", &[("got", &other.kind())])),
    }
}

pub(super) fn read_integrator(node: &Node) -> Result<Integrator, String> {
    let name = read_text(node)?;
    name.parse().map_err(|_| {
        let names: Vec<&str> = Integrator::ALL.iter().map(|i| i.as_str()).collect();
        say(
            "scene-not-integrator",
            &[("name", &name), ("names", &names.join(", "))],
        )
    })
}

pub(super) fn read_pair_forces(node: &Node) -> Result<PairForces, String> {
    let name = read_text(node)?;
    PairForces::ALL
        .into_iter()
        .find(|mode| mode.as_str() == name)
        .ok_or_else(|| say("scene-not-pair-forces", &[("name", &name)]))
}

pub(super) fn read_color(node: &Node) -> Result<Color, String> {
    let text = read_text(node)?;
    Color::parse_hex(&text).ok_or_else(|| say("scene-not-colour", &[("text", &text)]))
}

/// The known key closest to a misspelt one, if it is close enough to be a typo: the
/// scene file's "did you mean", and any front end's (Python's keywords).
pub fn closest<'k>(key: &str, known: &[&'k str]) -> Option<&'k str> {
    known
        .iter()
        .map(|k| (edit_distance(key, k), *k))
        .filter(|(d, k)| *d <= 2.max(k.len() / 4))
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

/// Levenshtein distance, for "did you mean" hints.
pub(super) fn edit_distance(a: &str, b: &str) -> usize {
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
