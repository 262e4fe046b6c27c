//! Scenes built in code: `Scene.add_particle(name=…, mass=…, position=…)` and its kin. An
//! object is made from keyword arguments by the scene format's field table, so every
//! keyword is a key of the file with the file's default, a missing required one or an
//! unknown one is a `TypeError` naming it, and the scene is checked by the file's rules
//! before it changes: a scene built in code is the scene its saved file reads back as,
//! bit for bit.

use numpy::{PyReadonlyArray1, PyReadonlyArray2};
use physics::fields::{self, Field};
use physics::{
    Body, Endpoint, Joint, Motor, ObjectKind, Particle, Ramp, Shape, Spring, Tie, TieKind, Vector,
};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::scene::{Scene, SceneObject, What, checked, from_python, number};
use crate::scene_error;

/// The `add_…` method that makes an object of `kind`: `add_` and the file's table name.
fn method(kind: ObjectKind) -> String {
    format!("add_{}", kind.as_str())
}

/// The name a file gives the `n`-th object of `kind` (from 1) that has none.
fn default_name(kind: ObjectKind, n: usize) -> String {
    match kind {
        ObjectKind::Particle => format!("p{n}"),
        ObjectKind::Spring => format!("s{n}"),
        ObjectKind::Ramp => format!("r{n}"),
        other => format!("{}{n}", other.as_str()),
    }
}

/// The keyword arguments as the file's keys: `from_` (`from` is Python's) is `from`.
fn given<'py>(kwargs: Option<&Bound<'py, PyDict>>) -> PyResult<Vec<(String, Bound<'py, PyAny>)>> {
    let Some(kwargs) = kwargs else {
        return Ok(Vec::new());
    };
    kwargs
        .iter()
        .map(|(key, value)| {
            let key: String = key.extract()?;
            let key = if key == "from_" {
                "from".to_owned()
            } else {
                key
            };
            Ok((key, value))
        })
        .collect()
}

/// Sets `target`'s fields from `given`, by the table `fields`; `extra` keys are the
/// caller's. A key that is none of them, or a required field not given, is a
/// `TypeError` naming it, as Python's own for a function's arguments.
fn fill<T>(
    method: &str,
    table: &[Field<T>],
    extra: &[&str],
    target: &mut T,
    given: &[(String, Bound<'_, PyAny>)],
) -> PyResult<()> {
    for (key, value) in given {
        if let Some(field) = table.iter().find(|f| f.key == key) {
            let value = from_python(field.kind, value, &format!("{method}(): {key}"))?;
            (field.set)(target, value);
        } else if !extra.contains(&key.as_str()) {
            let mut keys: Vec<&str> = table.iter().map(|f| f.key).collect();
            keys.extend(extra);
            let hint = physics::closest_key(key, &keys).map_or_else(
                || format!("its keywords are name, {}", keys.join(", ")),
                |k| format!("did you mean '{}'?", python_key(k)),
            );
            return Err(PyTypeError::new_err(format!(
                "{method}() got an unexpected keyword argument '{key}'; {hint}"
            )));
        }
    }
    let missing: Vec<String> = table
        .iter()
        .filter(|f| f.default.is_none() && !given.iter().any(|(k, _)| k == f.key))
        .map(|f| format!("'{}'", python_key(f.key)))
        .collect();
    if !missing.is_empty() {
        return Err(PyTypeError::new_err(format!(
            "{method}() missing required keyword argument{}: {}",
            if missing.len() == 1 { "" } else { "s" },
            missing.join(", ")
        )));
    }
    Ok(())
}

/// A file's key as a Python keyword: `from` is `from_`.
fn python_key(key: &str) -> &str {
    if key == "from" { "from_" } else { key }
}

/// A name no object of `scene` has: the one a file would give the next of its kind, or
/// the next number free.
fn free_name(scene: &physics::Scene, new: ObjectKind) -> String {
    let count = scene.objects_of(new).len();
    let names = all_names(scene).count();
    first_free(
        |n| default_name(new, n),
        count + 1,
        names,
        |name| taken(scene, name),
    )
    .1
}

/// The first of `prefix`1, `prefix`2, … from the `from`-th on that no object of `scene`
/// has: a joint's or a force's name, as a file would give it.
fn free_named(scene: &physics::Scene, prefix: &str, from: usize) -> String {
    let names = all_names(scene).count();
    first_free(
        |n| format!("{prefix}{n}"),
        from,
        names,
        |name| taken(scene, name),
    )
    .1
}

/// The first name `name(n)` from the `from`-th on that is not `taken`, with its
/// number: one of the next `names + 1` is free when `names` names are taken.
fn first_free(
    name: impl Fn(usize) -> String,
    from: usize,
    names: usize,
    taken: impl Fn(&str) -> bool,
) -> (usize, String) {
    (from..=from + names)
        .map(|n| (n, name(n)))
        .find(|(_, name)| !taken(name))
        .unwrap_or_else(|| (from, name(from)))
}

fn taken(scene: &physics::Scene, name: &str) -> bool {
    all_names(scene).any(|n| n == name)
}

/// Every object's name.
fn all_names(scene: &physics::Scene) -> impl Iterator<Item = String> + '_ {
    let particles = scene.particles.iter().map(|p| &p.name);
    let springs = scene.springs.iter().map(|s| &s.name);
    let ties = scene.ties.iter().map(|t| &t.name);
    let ramps = scene.ramps.iter().map(|r| &r.name);
    let bodies = scene.bodies.iter().map(|b| &b.name);
    let joints = scene.joints.iter().map(|j| &j.name);
    let forces = scene.forces.iter().map(|f| &f.name);
    particles
        .chain(springs)
        .chain(ties)
        .chain(ramps)
        .chain(bodies)
        .chain(joints)
        .chain(forces)
        .cloned()
}

/// Adds an object of kind `new` made from `kwargs` to `scene` and returns it.
pub(crate) fn add(
    scene: &Bound<'_, Scene>,
    new: ObjectKind,
    name: Option<String>,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<SceneObject> {
    let method_name = method(new);
    let method = method_name.as_str();
    let given = given(kwargs)?;
    let mut changed = scene.borrow().inner.clone();
    let name = name.unwrap_or_else(|| free_name(&changed, new));
    let origin = || Endpoint::Point(Vector::ZERO);
    let what = match new {
        ObjectKind::Particle => {
            let mut particle = Particle::new(name.clone(), 1.0);
            fill(method, fields::PARTICLE, &[], &mut particle, &given)?;
            changed.particles.push(particle);
            What::Object(new, name)
        }
        ObjectKind::Spring => {
            let mut spring = Spring::new(name.clone(), origin(), origin(), 0.0, 0.0);
            fill(method, fields::SPRING, &[], &mut spring, &given)?;
            changed.springs.push(spring);
            What::Object(new, name)
        }
        ObjectKind::Rod | ObjectKind::String => {
            let kind = if new == ObjectKind::Rod {
                TieKind::Rod
            } else {
                TieKind::String
            };
            let mut tie = Tie::rod(name.clone(), origin(), origin(), 1.0);
            tie.kind = kind;
            fill(method, fields::tie_fields(kind), &[], &mut tie, &given)?;
            // As a file: a length left out is the distance between the ends at the start.
            if !given.iter().any(|(k, _)| k == "length")
                && let Some(distance) = changed.distance(&tie.from, &tie.to)
            {
                tie.length = distance;
            }
            // The rods first, then the strings, as a file reads them back.
            let at = match kind {
                TieKind::Rod => changed
                    .ties
                    .iter()
                    .filter(|t| t.kind == TieKind::Rod)
                    .count(),
                TieKind::String => changed.ties.len(),
            };
            changed.ties.insert(at, tie);
            What::Object(new, name)
        }
        ObjectKind::Ramp => {
            let mut ramp = Ramp::new(name.clone(), Vector::ZERO, Vector::ZERO);
            fill(
                method,
                fields::RAMP,
                &["static_friction"],
                &mut ramp,
                &given,
            )?;
            if let Some((_, value)) = given.iter().find(|(k, _)| k == "static_friction") {
                ramp.static_friction =
                    Some(number(value, &format!("{method}(): static_friction"))?);
            }
            changed.ramps.push(ramp);
            What::Object(new, name)
        }
        ObjectKind::Body => {
            changed
                .bodies
                .push(body_from(method, name.clone(), &given)?);
            What::Object(new, name)
        }
        // Joints and forces name what they join or act on: their own methods make them.
        ObjectKind::Pin | ObjectKind::Hinge | ObjectKind::Pulley | ObjectKind::Force => {
            return Err(PyTypeError::new_err(format!(
                "{method}() takes the objects it joins or acts on; see its own signature"
            )));
        }
    };
    scene.borrow_mut().inner = checked(changed)?;
    SceneObject::of(scene.clone(), what)
}

/// A body from `add_body`'s keywords: the file's keys, its `shape` (`"box"`, or
/// `"polygon"`; left out, a polygon when `vertices` are given) and `vertices` as pairs.
fn body_from(method: &str, name: String, given: &[(String, Bound<'_, PyAny>)]) -> PyResult<Body> {
    let find = |key: &str| given.iter().find(|(k, _)| k == key).map(|(_, v)| v);
    let vertices = find("vertices")
        .map(|v| {
            v.extract::<Vec<[f64; 2]>>().map_err(|_| {
                PyTypeError::new_err(format!(
                    "{method}(): vertices must be a list of (x, y) pairs, or an (n, 2) array"
                ))
            })
        })
        .transpose()?;
    let shape = match find("shape") {
        Some(shape) => shape.extract::<String>().map_err(|_| {
            PyTypeError::new_err(format!("{method}(): shape must be \"box\" or \"polygon\""))
        })?,
        None if vertices.is_some() => "polygon".to_owned(),
        None => "box".to_owned(),
    };
    let mut body = Body::rectangle(name, 0.0, 0.0, 0.0);
    match shape.as_str() {
        "box" if vertices.is_some() => {
            return Err(crate::scene_error(format!(
                "{method}(): a box has width and height, not vertices (shape=\"polygon\")"
            )));
        }
        "box" => {}
        "polygon" => {
            let corners = vertices.ok_or_else(|| {
                PyTypeError::new_err(format!(
                    "{method}() missing required keyword argument: 'vertices'"
                ))
            })?;
            body.shape = Shape::Polygon(corners.into_iter().map(physics::DVec2::from).collect());
        }
        other => {
            return Err(crate::scene_error(format!(
                "{method}(): shape must be \"box\" or \"polygon\", got \"{other}\""
            )));
        }
    }
    if find("mass").is_some() && find("density").is_some() {
        return Err(crate::scene_error(format!(
            "{method}(): give a mass or a density, not both"
        )));
    }
    fill(
        method,
        fields::BODY,
        &["shape", "vertices", "static_friction"],
        &mut body,
        given,
    )?;
    if let Some(value) = find("static_friction") {
        body.static_friction = Some(number(value, &format!("{method}(): static_friction"))?);
    }
    Ok(body)
}

/// The joint's motor from `{"torque": τ}` or `{"spin": ω, "max_torque": τ}`.
fn motor(method: &str, value: &Bound<'_, PyAny>) -> PyResult<Motor> {
    let wrong = || {
        PyTypeError::new_err(format!(
            "{method}(): motor must be {{\"torque\": N·m}} or {{\"spin\": rad/s, \"max_torque\": N·m}}"
        ))
    };
    let table = value.cast::<PyDict>().map_err(|_| wrong())?;
    let get = |key: &str| -> PyResult<Option<f64>> {
        table
            .get_item(key)?
            .map(|v| number(&v, &format!("{method}(): motor's {key}")))
            .transpose()
    };
    match (
        get("torque")?,
        get("spin")?,
        get("max_torque")?,
        table.len(),
    ) {
        (Some(torque), None, None, 1) => Ok(Motor::Torque(torque)),
        (None, Some(spin), Some(max_torque), 2) => Ok(Motor::Spin { spin, max_torque }),
        _ => Err(wrong()),
    }
}

/// Adds a pin, a hinge or a pulley to `scene` (its place among the joints the one a file
/// reads it into: pins, then hinges, then pulleys); returns its name.
pub(crate) fn add_joint(
    scene: &Bound<'_, Scene>,
    method: &str,
    mut joint: Joint,
    (motor_value, limits): (Option<&Bound<'_, PyAny>>, Option<(f64, f64)>),
) -> PyResult<String> {
    let mut changed = scene.borrow().inner.clone();
    if joint.name.is_empty() {
        let kind = joint.kind_str();
        let from = changed
            .joints
            .iter()
            .filter(|j| j.kind_str() == kind)
            .count()
            + 1;
        joint.name = free_named(&changed, kind, from);
    }
    if let Some(value) = motor_value {
        joint.motor = Some(motor(method, value)?);
    }
    joint.limits = limits;
    let rank = |j: &Joint| match j.kind_str() {
        "pin" => 0,
        "hinge" => 1,
        _ => 2,
    };
    let at = changed.joints.partition_point(|j| rank(j) <= rank(&joint));
    let name = joint.name.clone();
    changed.joints.insert(at, joint);
    scene.borrow_mut().inner = checked(changed)?;
    Ok(name)
}

/// Adds a force of one's own to `scene`; returns its name (`force1`, … where free).
pub(crate) fn add_force(
    scene: &Bound<'_, Scene>,
    name: Option<String>,
    (fx, fy): (String, String),
    on: Option<&Bound<'_, PyAny>>,
    potential: Option<String>,
) -> PyResult<String> {
    let mut changed = scene.borrow().inner.clone();
    let name = name.unwrap_or_else(|| free_named(&changed, "force", changed.forces.len() + 1));
    let on = match on {
        None => Vec::new(),
        Some(one) if one.is_instance_of::<pyo3::types::PyString>() => vec![one.extract()?],
        Some(many) => many.extract::<Vec<String>>().map_err(|_| {
            PyTypeError::new_err("add_force(): on must be a particle's name or a list of names")
        })?,
    };
    let mut force = physics::Force::new(name.clone(), fx, fy).on(on);
    force.potential = potential;
    changed.forces.push(force);
    scene.borrow_mut().inner = checked(changed)?;
    Ok(name)
}

/// A column of `n` numbers: one number for all, or an array of `n`.
fn column(value: Option<&Bound<'_, PyAny>>, n: usize, what: &str) -> PyResult<Option<Vec<f64>>> {
    let Some(value) = value else {
        return Ok(None);
    };
    if let Ok(array) = value.extract::<PyReadonlyArray1<'_, f64>>() {
        let values = array
            .as_slice()
            .map_or_else(|_| array.as_array().to_vec(), <[f64]>::to_vec);
        if values.len() != n {
            return Err(scene_error(format!(
                "add_particles(): {what} has {} values for {n} positions",
                values.len()
            )));
        }
        return Ok(Some(values));
    }
    let one = number(value, &format!("add_particles(): {what}"))?;
    Ok(Some(vec![one; n]))
}

/// Pairs from an `(n, 2)` array.
fn pairs(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Vector>> {
    let array = value.extract::<PyReadonlyArray2<'_, f64>>().map_err(|_| {
        PyTypeError::new_err(format!(
            "add_particles(): {what} must be a numpy array of shape (n, 2) of floats"
        ))
    })?;
    let view = array.as_array();
    if view.ncols() != 2 {
        return Err(scene_error(format!(
            "add_particles(): {what} must have 2 columns (x, y), got {}",
            view.ncols()
        )));
    }
    Ok(view
        .rows()
        .into_iter()
        .map(|row| Vector::cartesian(row[0], row[1]))
        .collect())
}

/// Adds `n` particles at once from arrays; returns their names (`p1`, `p2`, … where
/// free).
pub(crate) fn add_particles(
    scene: &Bound<'_, Scene>,
    positions: &Bound<'_, PyAny>,
    velocities: Option<&Bound<'_, PyAny>>,
    masses: &Bound<'_, PyAny>,
    radii: Option<&Bound<'_, PyAny>>,
) -> PyResult<Vec<String>> {
    let positions = pairs(positions, "positions")?;
    let n = positions.len();
    let velocities = velocities.map(|v| pairs(v, "velocities")).transpose()?;
    if let Some(v) = &velocities
        && v.len() != n
    {
        return Err(scene_error(format!(
            "add_particles(): velocities has {} rows for {n} positions",
            v.len()
        )));
    }
    let masses = column(Some(masses), n, "masses")?.unwrap_or_default();
    let radii = column(radii, n, "radii")?;
    let mut changed = scene.borrow().inner.clone();
    let mut taken: std::collections::HashSet<String> = all_names(&changed).collect();
    let mut next = changed.particles.len() + 1;
    let mut names = Vec::with_capacity(n);
    for (i, position) in positions.into_iter().enumerate() {
        let (number, name) = first_free(
            |n| default_name(ObjectKind::Particle, n),
            next,
            taken.len(),
            |name| taken.contains(name),
        );
        next = number + 1;
        taken.insert(name.clone());
        let mut particle = Particle::new(name.clone(), masses[i]);
        particle.position = position;
        if let Some(v) = &velocities {
            particle.velocity = v[i];
        }
        if let Some(r) = &radii {
            particle.radius = r[i];
        }
        changed.particles.push(particle);
        names.push(name);
    }
    scene.borrow_mut().inner = checked(changed)?;
    Ok(names)
}
