//! `newtonlab.Scene` and its objects. A scene is read and written through the scene
//! format's field table (`physics::fields`), so every attribute is a key of the file, and
//! a value is checked by the file's own rules: the change is made on a copy, the copy is
//! validated as a loaded file would be, and only a valid copy replaces the scene.

use std::path::PathBuf;

use physics::fields::{self, Field, Kind, Value};
use physics::{
    Bounds, Color, Endpoint, Integrator, ObjectId, ObjectKind, PairForces, Section, Vector,
};
use pyo3::exceptions::{
    PyAttributeError, PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyPermissionError,
    PyTypeError,
};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

use crate::scene_error;

/// The largest scene file read: 100 MB, as the command line's (a million particles take
/// some 150 MB as TOML; far beyond what a notebook would run).
const MAX_SCENE_BYTES: u64 = 100_000_000;

/// A scene: particles, springs, rods, strings and ramps in a world, with the settings
/// of its simulation. Made with `newtonlab.load`, `Scene.from_toml` or `Scene.from_json`.
#[pyclass(module = "newtonlab")]
#[derive(Clone)]
pub struct Scene {
    pub(crate) inner: physics::Scene,
}

/// Which object of a scene a [`SceneObject`] is: an object by its kind and name, or a
/// section that is always there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum What {
    Object(ObjectKind, String),
    World,
    Simulation,
}

impl What {
    fn kind(&self) -> &'static str {
        match self {
            Self::Object(kind, _) => kind.as_str(),
            Self::World => "world",
            Self::Simulation => "simulation",
        }
    }

    fn name(&self) -> Option<&str> {
        match self {
            Self::Object(_, name) => Some(name),
            Self::World | Self::Simulation => None,
        }
    }

    /// Where the object is in `scene`, or why it is not there.
    fn section(&self, scene: &physics::Scene) -> PyResult<Section> {
        let (kind, name) = match self {
            Self::Object(kind, name) => (*kind, name),
            Self::World => return Ok(Section::World),
            Self::Simulation => return Ok(Section::Simulation),
        };
        scene
            .find_object(kind, name)
            .map(ObjectId::section)
            .ok_or_else(|| {
                let names: Vec<&str> = scene.objects_of(kind).into_iter().map(|(_, n)| n).collect();
                scene_error(format!(
                    "the scene has no {} named '{name}'; its {}s are: {}",
                    self.kind(),
                    self.kind(),
                    if names.is_empty() {
                        "none".to_owned()
                    } else {
                        names.join(", ")
                    }
                ))
            })
    }
}

/// The keys of `section`'s fields.
fn keys(scene: &physics::Scene, section: Section) -> Vec<&'static str> {
    fn of<T>(fields: &[Field<T>]) -> Vec<&'static str> {
        fields.iter().map(|f| f.key).collect()
    }
    match section {
        Section::Particle(_) => of(fields::PARTICLE),
        Section::Spring(_) => of(fields::SPRING),
        Section::Tie(i) => of(fields::tie_fields(scene.ties[i].kind)),
        Section::Ramp(_) => of(fields::RAMP),
        Section::Body(_) => of(fields::BODY),
        Section::World => of(fields::WORLD),
        Section::Simulation => of(fields::SIMULATION),
        _ => Vec::new(),
    }
}

/// `section`'s field `key`: its kind and value.
fn get(scene: &physics::Scene, section: Section, key: &str) -> Option<(Kind, Value)> {
    fn of<T>(fields: &[Field<T>], object: &T, key: &str) -> Option<(Kind, Value)> {
        let field = fields.iter().find(|f| f.key == key)?;
        Some((field.kind, (field.get)(object)))
    }
    match section {
        Section::Particle(i) => of(fields::PARTICLE, &scene.particles[i], key),
        Section::Spring(i) => of(fields::SPRING, &scene.springs[i], key),
        Section::Tie(i) => of(fields::tie_fields(scene.ties[i].kind), &scene.ties[i], key),
        Section::Ramp(i) => of(fields::RAMP, &scene.ramps[i], key),
        Section::Body(i) => of(fields::BODY, &scene.bodies[i], key),
        Section::World => of(fields::WORLD, &scene.world, key),
        Section::Simulation => of(fields::SIMULATION, &scene.simulation, key),
        _ => None,
    }
}

/// Writes `value` into `section`'s field `key`.
fn set(scene: &mut physics::Scene, section: Section, key: &str, value: Value) {
    fn of<T>(fields: &[Field<T>], object: &mut T, key: &str, value: Value) {
        if let Some(field) = fields.iter().find(|f| f.key == key) {
            (field.set)(object, value);
        }
    }
    match section {
        Section::Particle(i) => of(fields::PARTICLE, &mut scene.particles[i], key, value),
        Section::Spring(i) => of(fields::SPRING, &mut scene.springs[i], key, value),
        Section::Tie(i) => {
            let fields = fields::tie_fields(scene.ties[i].kind);
            of(fields, &mut scene.ties[i], key, value);
        }
        Section::Ramp(i) => of(fields::RAMP, &mut scene.ramps[i], key, value),
        Section::Body(i) => of(fields::BODY, &mut scene.bodies[i], key, value),
        Section::World => of(fields::WORLD, &mut scene.world, key, value),
        Section::Simulation => of(fields::SIMULATION, &mut scene.simulation, key, value),
        _ => {}
    }
}

/// A value as Python sees it: a float, an `(x, y)` tuple, a bool, a name, a colour's
/// `"#rrggbb"`, bounds as `((xmin, ymin), (xmax, ymax))`, or `None`.
fn to_python(py: Python<'_>, value: Value) -> PyResult<Py<PyAny>> {
    let pair = |v: Vector| {
        let v = v.to_dvec2();
        (v.x, v.y)
    };
    Ok(match value {
        Value::Number(x) => x.into_pyobject(py)?.into_any().unbind(),
        Value::Vector(v) | Value::Endpoint(Endpoint::Point(v)) => {
            pair(v).into_pyobject(py)?.into_any().unbind()
        }
        Value::Bool(b) => PyBool::new(py, b).to_owned().into_any().unbind(),
        Value::Endpoint(Endpoint::Particle(name)) => name.into_pyobject(py)?.into_any().unbind(),
        Value::Integrator(integrator) => integrator
            .to_string()
            .into_pyobject(py)?
            .into_any()
            .unbind(),
        Value::PairForces(mode) => mode.as_str().into_pyobject(py)?.into_any().unbind(),
        Value::Color(color) => color
            .map(Color::to_hex)
            .into_pyobject(py)?
            .into_any()
            .unbind(),
        // The walls' friction, when they have any, as a third item.
        Value::Bounds(Some(b)) if b.friction != 0.0 => (pair(b.min), pair(b.max), b.friction)
            .into_pyobject(py)?
            .into_any()
            .unbind(),
        Value::Bounds(bounds) => bounds
            .map(|b| (pair(b.min), pair(b.max)))
            .into_pyobject(py)?
            .into_any()
            .unbind(),
    })
}

/// A number from Python: a float or an int, not a bool (which Python counts as an int).
pub(crate) fn number(value: &Bound<'_, PyAny>, what: &str) -> PyResult<f64> {
    if value.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{what} must be a number, got a bool"
        )));
    }
    value.extract::<f64>().map_err(|_| {
        PyTypeError::new_err(format!("{what} must be a number, got {}", type_name(value)))
    })
}

/// A value's type as a message says it: "a str", "an int".
fn type_name(value: &Bound<'_, PyAny>) -> String {
    value.get_type().name().map_or_else(
        |_| "something else".to_owned(),
        |n| {
            let n = n.to_string();
            let article = if n.starts_with(['a', 'e', 'i', 'o', 'u']) {
                "an"
            } else {
                "a"
            };
            format!("{article} {n}")
        },
    )
}

/// A vector from Python: `(x, y)` (any sequence of two numbers, a numpy array too), or a
/// dict `{"magnitude": m, "angle": degrees}`.
fn vector(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vector> {
    if let Ok(dict) = value.cast::<PyDict>() {
        let part = |key: &str| -> PyResult<f64> {
            let item = dict.get_item(key)?.ok_or_else(|| {
                scene_error(format!(
                    "{what} as a dict needs 'magnitude' and 'angle' (degrees)"
                ))
            })?;
            number(&item, &format!("{what}'s {key}"))
        };
        return Ok(Vector::polar(part("magnitude")?, part("angle")?));
    }
    let message = || {
        format!(
            "{what} must be (x, y) or {{\"magnitude\": m, \"angle\": degrees}}, got {}",
            type_name(value)
        )
    };
    // Not a pair at all is a TypeError; a sequence of another length, a SceneError.
    let wrong = || scene_error(message());
    if value.is_instance_of::<PyString>() {
        return Err(PyTypeError::new_err(message()));
    }
    let items: Vec<Bound<'_, PyAny>> = value
        .try_iter()
        .map_err(|_| PyTypeError::new_err(message()))?
        .collect::<PyResult<_>>()?;
    let [x, y] = &items[..] else {
        return Err(wrong());
    };
    Ok(Vector::cartesian(
        number(x, &format!("{what}'s x"))?,
        number(y, &format!("{what}'s y"))?,
    ))
}

/// The value of kind `kind` that `value` stands for, or why it cannot.
pub(crate) fn from_python(kind: Kind, value: &Bound<'_, PyAny>, what: &str) -> PyResult<Value> {
    let text = || -> PyResult<String> {
        value.extract::<String>().map_err(|_| {
            PyTypeError::new_err(format!("{what} must be a string, got {}", type_name(value)))
        })
    };
    Ok(match kind {
        Kind::Number(_) => Value::Number(number(value, what)?),
        Kind::Vector => Value::Vector(vector(value, what)?),
        Kind::Bool => Value::Bool(
            value
                .cast::<PyBool>()
                .map_err(|_| {
                    PyTypeError::new_err(format!(
                        "{what} must be True or False, got {}",
                        type_name(value)
                    ))
                })?
                .is_true(),
        ),
        Kind::Endpoint => {
            if value.is_instance_of::<PyString>() {
                Value::Endpoint(Endpoint::Particle(text()?))
            } else {
                Value::Endpoint(Endpoint::Point(vector(value, what)?))
            }
        }
        Kind::Integrator => Value::Integrator(
            text()?
                .parse::<Integrator>()
                .map_err(|e| scene_error(format!("{what}: {e}")))?,
        ),
        Kind::PairForces => {
            let name = text()?;
            Value::PairForces(
                PairForces::ALL
                    .into_iter()
                    .find(|m| m.as_str() == name)
                    .ok_or_else(|| {
                        scene_error(format!("{what} must be 'direct' or 'tree', got '{name}'"))
                    })?,
            )
        }
        Kind::Color => {
            if value.is_none() {
                Value::Color(None)
            } else {
                let hex = text()?;
                Value::Color(Some(Color::parse_hex(&hex).ok_or_else(|| {
                    scene_error(format!("{what} must be \"#rrggbb\" or None, got '{hex}'"))
                })?))
            }
        }
        Kind::Bounds => {
            if value.is_none() {
                Value::Bounds(None)
            } else {
                let wrong = || {
                    scene_error(format!(
                        "{what} must be ((xmin, ymin), (xmax, ymax)), with the walls' friction as a third item if they have any, or None"
                    ))
                };
                let items: Vec<Bound<'_, PyAny>> = value
                    .try_iter()
                    .map_err(|_| wrong())?
                    .collect::<PyResult<_>>()?;
                let (min, max, friction) = match &items[..] {
                    [min, max] => (min, max, 0.0),
                    [min, max, friction] => {
                        (min, max, number(friction, &format!("{what}'s friction"))?)
                    }
                    _ => return Err(wrong()),
                };
                Value::Bounds(Some(Bounds {
                    min: vector(min, &format!("{what}'s lower-left corner"))?,
                    max: vector(max, &format!("{what}'s upper-right corner"))?,
                    friction,
                    static_friction: None,
                }))
            }
        }
    })
}

/// `scene` if it is valid, or a `SceneError` with every problem.
pub(crate) fn checked(scene: physics::Scene) -> PyResult<physics::Scene> {
    let problems = scene.validate();
    if problems.is_empty() {
        return Ok(scene);
    }
    let messages: Vec<String> = problems.into_iter().map(|p| p.message).collect();
    Err(scene_error(messages.join("\n")))
}

/// A scene from a file's text, or a `SceneError` with every problem, each at its line and
/// column in `source`.
fn parse(text: &str, format: physics::SceneFormat, source: &str) -> PyResult<physics::Scene> {
    physics::Scene::parse(text, format).map_err(|e| scene_error(e.report(source)))
}

/// Reads a scene: a file (`.toml` or `.json`), or `"example:NAME"` for a built-in one
/// (`newtonlab.examples()` lists them).
///
/// Raises `SceneError` with every problem of the file, each with its line and column;
/// `FileNotFoundError`, `IsADirectoryError` or `PermissionError` for a file that cannot
/// be read.
#[pyfunction]
pub fn load(source: PathBuf) -> PyResult<Scene> {
    let text = source.to_string_lossy().into_owned();
    if let Some(name) = text.strip_prefix("example:") {
        let example = physics::example(name).ok_or_else(|| {
            let names: Vec<&str> = physics::EXAMPLES.iter().map(|e| e.name).collect();
            scene_error(format!(
                "there is no example '{name}'; the examples are: {}",
                names.join(", ")
            ))
        })?;
        let inner = example.scene().map_err(|e| scene_error(e.report(&text)))?;
        return Ok(Scene { inner });
    }
    // Python's own errors for files: a missing one is a FileNotFoundError, a folder an
    // IsADirectoryError, one not to be read a PermissionError.
    let cannot = |e: &std::io::Error| {
        let message = format!("cannot read '{text}': {e}");
        match e.kind() {
            std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
            std::io::ErrorKind::PermissionDenied => PyPermissionError::new_err(message),
            std::io::ErrorKind::IsADirectory => PyIsADirectoryError::new_err(message),
            _ => PyOSError::new_err(message),
        }
    };
    // A file, and of a size a scene can have: a device or a FIFO would be read until
    // memory runs out.
    let metadata = std::fs::metadata(&source).map_err(|e| cannot(&e))?;
    if metadata.is_dir() {
        return Err(PyIsADirectoryError::new_err(format!(
            "'{text}' is a folder, not a scene file"
        )));
    }
    if !metadata.is_file() {
        return Err(scene_error(format!("'{text}' is not a file")));
    }
    if metadata.len() > MAX_SCENE_BYTES {
        return Err(scene_error(format!(
            "'{text}' is {} MB; a scene file may have at most {} MB",
            metadata.len() / 1_000_000,
            MAX_SCENE_BYTES / 1_000_000
        )));
    }
    let contents = std::fs::read_to_string(&source).map_err(|e| cannot(&e))?;
    let inner = parse(
        &contents,
        physics::SceneFormat::from_file_name(&text),
        &text,
    )?;
    Ok(Scene { inner })
}

/// The built-in scenes: `{name: title}`, each loadable as `load("example:NAME")`.
#[pyfunction]
pub fn examples() -> Vec<(String, String)> {
    physics::EXAMPLES
        .iter()
        .map(|example| {
            let title = example
                .scene()
                .ok()
                .and_then(|scene| scene.name)
                .unwrap_or_default();
            (example.name.to_owned(), title)
        })
        .collect()
}

/// A scene given as a `Scene` or as what `load` takes.
pub(crate) fn scene_of(value: &Bound<'_, PyAny>) -> PyResult<physics::Scene> {
    if let Ok(scene) = value.cast::<Scene>() {
        return Ok(scene.borrow().inner.clone());
    }
    let source: PathBuf = value.extract().map_err(|_| {
        scene_error(format!(
            "a scene must be a newtonlab.Scene, a file's path or \"example:NAME\", got {}",
            type_name(value)
        ))
    })?;
    Ok(load(source)?.inner)
}

#[pymethods]
impl Scene {
    /// An empty scene: the default world (g = 9.81 m/s² downwards) and settings.
    #[new]
    fn new() -> Self {
        Self {
            inner: physics::Scene::new(),
        }
    }

    /// A scene from the text of a TOML scene file.
    #[staticmethod]
    fn from_toml(text: &str) -> PyResult<Self> {
        Ok(Self {
            inner: parse(text, physics::SceneFormat::Toml, "<toml>")?,
        })
    }

    /// A scene from the text of a JSON scene file.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        Ok(Self {
            inner: parse(text, physics::SceneFormat::Json, "<json>")?,
        })
    }

    /// The scene as a TOML scene file's text.
    fn to_toml(&self) -> String {
        self.inner.to_toml()
    }

    /// The scene as a JSON scene file's text.
    fn to_json(&self) -> String {
        self.inner.to_json()
    }

    /// An independent copy.
    fn copy(&self) -> Self {
        self.clone()
    }

    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.clone()
    }

    /// The particle called `name`, its fields as attributes.
    fn particle(slf: Bound<'_, Self>, name: &str) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::Object(ObjectKind::Particle, name.to_owned()))
    }

    /// The spring called `name`.
    fn spring(slf: Bound<'_, Self>, name: &str) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::Object(ObjectKind::Spring, name.to_owned()))
    }

    /// The rod called `name`.
    fn rod(slf: Bound<'_, Self>, name: &str) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::Object(ObjectKind::Rod, name.to_owned()))
    }

    /// The string called `name`.
    fn string(slf: Bound<'_, Self>, name: &str) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::Object(ObjectKind::String, name.to_owned()))
    }

    /// The ramp called `name`.
    fn ramp(slf: Bound<'_, Self>, name: &str) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::Object(ObjectKind::Ramp, name.to_owned()))
    }

    /// The rigid body called `name`: its table's fields as attributes (`block.angle`,
    /// `block.mass`); its shape stays as the file gives it.
    fn body(slf: Bound<'_, Self>, name: &str) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::Object(ObjectKind::Body, name.to_owned()))
    }

    /// Adds a particle and returns it: the scene file's keys as keywords (`mass` and
    /// `position` required), checked by the file's rules.
    #[pyo3(signature = (name=None, **fields))]
    fn add_particle(
        slf: Bound<'_, Self>,
        name: Option<String>,
        fields: Option<Bound<'_, PyDict>>,
    ) -> PyResult<SceneObject> {
        crate::build::add(&slf, ObjectKind::Particle, name, fields.as_ref())
    }

    /// Adds a spring (`from_`, `to`, `stiffness`, `natural_length`, …) and returns it.
    #[pyo3(signature = (name=None, **fields))]
    fn add_spring(
        slf: Bound<'_, Self>,
        name: Option<String>,
        fields: Option<Bound<'_, PyDict>>,
    ) -> PyResult<SceneObject> {
        crate::build::add(&slf, ObjectKind::Spring, name, fields.as_ref())
    }

    /// Adds a rod (`from_`, `to`; `length` defaults to their distance) and returns it.
    #[pyo3(signature = (name=None, **fields))]
    fn add_rod(
        slf: Bound<'_, Self>,
        name: Option<String>,
        fields: Option<Bound<'_, PyDict>>,
    ) -> PyResult<SceneObject> {
        crate::build::add(&slf, ObjectKind::Rod, name, fields.as_ref())
    }

    /// Adds a string (`from_`, `to`; `length` defaults to their distance) and returns it.
    #[pyo3(signature = (name=None, **fields))]
    fn add_string(
        slf: Bound<'_, Self>,
        name: Option<String>,
        fields: Option<Bound<'_, PyDict>>,
    ) -> PyResult<SceneObject> {
        crate::build::add(&slf, ObjectKind::String, name, fields.as_ref())
    }

    /// Adds a ramp (`from_`, `to`, `friction`, `static_friction`, …) and returns it.
    #[pyo3(signature = (name=None, **fields))]
    fn add_ramp(
        slf: Bound<'_, Self>,
        name: Option<String>,
        fields: Option<Bound<'_, PyDict>>,
    ) -> PyResult<SceneObject> {
        crate::build::add(&slf, ObjectKind::Ramp, name, fields.as_ref())
    }

    /// Adds a rigid body and returns it: `shape="box"` with `width` and `height`, or a
    /// polygon's `vertices` (counter-clockwise pairs, in its own frame), `mass` or
    /// `density`, `position` of the centroid, and the file's other keys (`angle`,
    /// `velocity`, `spin`, `restitution`, `friction`, `static_friction`, `fixed`).
    #[pyo3(signature = (name=None, **fields))]
    fn add_body(
        slf: Bound<'_, Self>,
        name: Option<String>,
        fields: Option<Bound<'_, PyDict>>,
    ) -> PyResult<SceneObject> {
        crate::build::add(&slf, ObjectKind::Body, name, fields.as_ref())
    }

    /// Adds a pin holding `body` to the world at the point `at` (on or off the body);
    /// `motor` `{"torque": N·m}` or `{"spin": rad/s, "max_torque": N·m}`, `limits`
    /// (lower, upper) in degrees. Returns its name.
    #[pyo3(signature = (name=None, *, body, at, motor=None, limits=None))]
    fn add_pin(
        slf: Bound<'_, Self>,
        name: Option<String>,
        body: String,
        at: (f64, f64),
        motor: Option<Bound<'_, PyAny>>,
        limits: Option<(f64, f64)>,
    ) -> PyResult<String> {
        let joint = physics::Joint::pin(name.unwrap_or_default(), body, [at.0, at.1]);
        crate::build::add_joint(&slf, "add_pin", joint, (motor.as_ref(), limits))
    }

    /// Adds a hinge: bodies `a` and `b` share the point `at`; `motor` drives b against a,
    /// `limits` bound b's turn against a's (degrees). Returns its name.
    #[pyo3(signature = (name=None, *, a, b, at, motor=None, limits=None))]
    fn add_hinge(
        slf: Bound<'_, Self>,
        name: Option<String>,
        a: String,
        b: String,
        at: (f64, f64),
        motor: Option<Bound<'_, PyAny>>,
        limits: Option<(f64, f64)>,
    ) -> PyResult<String> {
        let joint = physics::Joint::hinge(name.unwrap_or_default(), a, b, [at.0, at.1]);
        crate::build::add_joint(&slf, "add_hinge", joint, (motor.as_ref(), limits))
    }

    /// Adds a pulley: an ideal string from body `a` over a wheel of `radius` m at
    /// `position` to body `b`; the wheel's `mass` (kg, 0: massless) and `inertia`
    /// (I/(m r²), 0.5 a disc). Returns its name.
    #[pyo3(signature = (name=None, *, a, b, position, radius, mass=0.0, inertia=0.5))]
    #[expect(
        clippy::too_many_arguments,
        reason = "the scene file's keys, as keywords"
    )]
    fn add_pulley(
        slf: Bound<'_, Self>,
        name: Option<String>,
        a: String,
        b: String,
        position: (f64, f64),
        radius: f64,
        mass: f64,
        inertia: f64,
    ) -> PyResult<String> {
        let mut joint = physics::Joint::pulley(
            name.unwrap_or_default(),
            (a, b),
            [position.0, position.1],
            radius,
            mass,
        );
        if let physics::JointKind::Pulley { inertia: i, .. } = &mut joint.kind {
            *i = inertia;
        }
        crate::build::add_joint(&slf, "add_pulley", joint, (None, None))
    }

    /// The pins', hinges' and pulleys' names, in the order a file reads them.
    #[getter]
    fn joints(&self) -> Vec<String> {
        self.inner.joints.iter().map(|j| j.name.clone()).collect()
    }

    /// Adds a force of one's own (`[[force]]`) and returns its name: `fx` and `fy`
    /// expressions (N) of x, y, vx, vy, t, m, q; `on` a particle's name or a list of
    /// them (every particle when left out); `potential` (J, of x, y, m, q), booked as
    /// potential energy. Checked as a file's: a `SceneError` says what is wrong.
    #[pyo3(signature = (name=None, *, fx="0".to_owned(), fy="0".to_owned(), on=None, potential=None))]
    fn add_force(
        slf: Bound<'_, Self>,
        name: Option<String>,
        fx: String,
        fy: String,
        on: Option<Bound<'_, PyAny>>,
        potential: Option<String>,
    ) -> PyResult<String> {
        crate::build::add_force(&slf, name, (fx, fy), on.as_ref(), potential)
    }

    /// The forces of its own' names (`[[force]]`).
    #[getter]
    fn forces(&self) -> Vec<String> {
        self.inner.forces.iter().map(|f| f.name.clone()).collect()
    }

    /// Adds `n` particles from arrays (positions and velocities of shape (n, 2), masses
    /// and radii of n or one number for all); returns their names.
    #[pyo3(signature = (positions, masses, velocities=None, radii=None))]
    fn add_particles(
        slf: Bound<'_, Self>,
        positions: Bound<'_, PyAny>,
        masses: Bound<'_, PyAny>,
        velocities: Option<Bound<'_, PyAny>>,
        radii: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Vec<String>> {
        crate::build::add_particles(
            &slf,
            &positions,
            velocities.as_ref(),
            &masses,
            radii.as_ref(),
        )
    }

    /// The world: gravity, the pair forces' constants, the bounds.
    #[getter]
    fn world(slf: Bound<'_, Self>) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::World)
    }

    /// The simulation's settings: integrator, time step, start time.
    #[getter]
    fn simulation(slf: Bound<'_, Self>) -> PyResult<SceneObject> {
        SceneObject::of(slf, What::Simulation)
    }

    /// The particles' names, in scene order.
    #[getter]
    fn particles(&self) -> Vec<String> {
        self.inner.particle_names()
    }

    /// The springs' names.
    #[getter]
    fn springs(&self) -> Vec<String> {
        self.inner.springs.iter().map(|s| s.name.clone()).collect()
    }

    /// The rods' names.
    #[getter]
    fn rods(&self) -> Vec<String> {
        self.ties(physics::TieKind::Rod)
    }

    /// The strings' names.
    #[getter]
    fn strings(&self) -> Vec<String> {
        self.ties(physics::TieKind::String)
    }

    /// The ramps' names.
    #[getter]
    fn ramps(&self) -> Vec<String> {
        self.inner.ramps.iter().map(|r| r.name.clone()).collect()
    }

    /// The rigid bodies' names.
    #[getter]
    fn bodies(&self) -> Vec<String> {
        self.inner.bodies.iter().map(|b| b.name.clone()).collect()
    }

    fn __repr__(&self) -> String {
        format!(
            "<newtonlab.Scene {}: {} particles, {} springs, {} rods and strings, {} ramps, {} bodies>",
            self.inner
                .name
                .as_deref()
                .map_or_else(|| "(untitled)".to_owned(), |n| format!("'{n}'")),
            self.inner.particles.len(),
            self.inner.springs.len(),
            self.inner.ties.len(),
            self.inner.ramps.len(),
            self.inner.bodies.len()
        )
    }
}

impl Scene {
    fn ties(&self, kind: physics::TieKind) -> Vec<String> {
        self.inner
            .ties
            .iter()
            .filter(|t| t.kind == kind)
            .map(|t| t.name.clone())
            .collect()
    }
}

/// One object of a scene — a particle, spring, rod, string, ramp or body, the world or
/// the settings — with the scene file's keys as attributes (`ball.mass`, `ball.velocity`).
/// Writing one checks the value by the file's rules; a bad value raises `SceneError` and
/// leaves the scene as it was.
#[pyclass(module = "newtonlab")]
pub struct SceneObject {
    scene: Py<Scene>,
    what: What,
}

impl SceneObject {
    pub(crate) fn of(scene: Bound<'_, Scene>, what: What) -> PyResult<Self> {
        what.section(&scene.borrow().inner)?;
        Ok(Self {
            scene: scene.unbind(),
            what,
        })
    }

    /// The `AttributeError` of a key the object does not have, reading or writing it:
    /// the key it most likely meant, or every key it has.
    fn no_field(&self, scene: &physics::Scene, section: Section, key: &str) -> PyErr {
        let keys = keys(scene, section);
        let hint = physics::closest_key(key, &keys).map_or_else(
            || format!("its fields are: {}", keys.join(", ")),
            |k| format!("did you mean '{k}'?"),
        );
        PyAttributeError::new_err(format!("{} has no field '{key}'; {hint}", self.label()))
    }

    /// How the object's messages name it: `particle 'Ball'`, `world`.
    fn label(&self) -> String {
        match self.what.name() {
            Some(name) => format!("{} '{name}'", self.what.kind()),
            None => self.what.kind().to_owned(),
        }
    }
}

#[pymethods]
impl SceneObject {
    fn __getattr__(&self, py: Python<'_>, key: &str) -> PyResult<Py<PyAny>> {
        let scene = self.scene.borrow(py);
        let section = self.what.section(&scene.inner)?;
        if key == "name" && self.what.name().is_some() {
            return Ok(scene
                .inner
                .name_of(section)
                .unwrap_or_default()
                .into_pyobject(py)?
                .into_any()
                .unbind());
        }
        match get(&scene.inner, section, key) {
            Some((_, value)) => to_python(py, value),
            None => Err(self.no_field(&scene.inner, section, key)),
        }
    }

    fn __setattr__(&mut self, py: Python<'_>, key: &str, value: Bound<'_, PyAny>) -> PyResult<()> {
        let mut scene = self.scene.borrow_mut(py);
        let section = self.what.section(&scene.inner)?;
        let mut changed = scene.inner.clone();
        let what = format!("{}: {key}", self.label());
        if key == "name" && self.what.name().is_some() {
            let new: String = value.extract().map_err(|_| {
                PyTypeError::new_err(format!(
                    "{what} must be a string, got {}",
                    type_name(&value)
                ))
            })?;
            changed.rename(section, &new);
            scene.inner = checked(changed)?;
            self.what = match &self.what {
                What::Object(kind, _) => What::Object(*kind, new),
                other => other.clone(),
            };
            return Ok(());
        }
        let Some((kind, _)) = get(&scene.inner, section, key) else {
            return Err(self.no_field(&scene.inner, section, key));
        };
        let value = from_python(kind, &value, &what)?;
        set(&mut changed, section, key, value);
        scene.inner = checked(changed)?;
        Ok(())
    }

    fn __dir__(&self, py: Python<'_>) -> PyResult<Vec<&'static str>> {
        let scene = self.scene.borrow(py);
        let section = self.what.section(&scene.inner)?;
        let mut keys = keys(&scene.inner, section);
        if self.what.name().is_some() {
            keys.insert(0, "name");
        }
        Ok(keys)
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let scene = self.scene.borrow(py);
        let section = self.what.section(&scene.inner)?;
        let mut parts = Vec::new();
        for key in keys(&scene.inner, section) {
            if let Some((_, value)) = get(&scene.inner, section, key) {
                let shown = to_python(py, value)?.bind(py).repr()?.to_string();
                parts.push(format!("{key}={shown}"));
            }
        }
        Ok(format!("<{}: {}>", self.label(), parts.join(", ")))
    }
}
