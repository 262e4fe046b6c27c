//! [`Setting`]: one number of a scene by name, read and written through the scene's
//! field table so that it obeys the file's rules; and the constants a theory may name.

use std::fmt;

use crate::scene::fields::{self, Field, Kind, Value};
use crate::scene::{ObjectKind, Scene, Section, Vector, say};

/// The part of a vector a [`Setting`] writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Part {
    X,
    Y,
    Magnitude,
    /// Degrees, counter-clockwise from +x, as the file's polar form.
    Angle,
}

impl Part {
    /// This part of `vector`.
    fn get(self, vector: Vector) -> f64 {
        let v = vector.to_dvec2();
        let (magnitude, angle) = polar(vector);
        match self {
            Self::X => v.x,
            Self::Y => v.y,
            Self::Magnitude => magnitude,
            Self::Angle => angle,
        }
    }

    fn parse(text: &str) -> Option<Self> {
        Some(match text {
            "x" => Self::X,
            "y" => Self::Y,
            "magnitude" => Self::Magnitude,
            "angle" => Self::Angle,
            _ => return None,
        })
    }

    /// `vector` with this part set to `value` (a magnitude or an angle keeps the other
    /// of the polar pair; x or y the other component).
    fn set(self, vector: Vector, value: f64) -> Vector {
        let v = vector.to_dvec2();
        let (magnitude, angle) = polar(vector);
        match self {
            Self::X => Vector::Cartesian(glam::DVec2::new(value, v.y)),
            Self::Y => Vector::Cartesian(glam::DVec2::new(v.x, value)),
            Self::Magnitude => Vector::Polar {
                magnitude: value,
                angle,
            },
            Self::Angle => Vector::Polar {
                magnitude,
                angle: value,
            },
        }
    }
}

/// `vector`'s magnitude and angle (degrees), as written where it is polar.
fn polar(vector: Vector) -> (f64, f64) {
    match vector {
        Vector::Polar { magnitude, angle } => (magnitude, angle),
        Vector::Cartesian(c) => (c.length(), c.y.atan2(c.x).to_degrees()),
    }
}

/// One number of a scene, by name: `OBJECT.key`, a vector's `OBJECT.key.x|.y|.magnitude|.angle`,
/// `world.key[.x|.y|…]`, `simulation.key`.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    text: String,
    /// The section it writes to: an object with a field table (a particle, a spring, a
    /// rod or a string, a ramp, a body), `[world]` or `[simulation]`.
    target: Section,
    key: &'static str,
    part: Option<Part>,
    /// The SI unit of the number written.
    unit: &'static str,
}

impl fmt::Display for Setting {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// The field of `fields` called `key` that holds a number (or a vector, with a part):
/// its key, whether it is a vector, and its unit.
fn numeric<T>(
    fields: &'static [Field<T>],
    key: &str,
) -> Option<(&'static str, bool, &'static str)> {
    let field = fields.iter().find(|f| f.key == key)?;
    match field.kind {
        Kind::Number(_) => Some((field.key, false, field.unit)),
        Kind::Vector => Some((field.key, true, field.unit)),
        _ => None,
    }
}

/// The number in `object`'s field `key` (its `part`, for a vector).
fn read<T>(fields: &[Field<T>], object: &T, key: &str, part: Option<Part>) -> Option<f64> {
    let field = fields.iter().find(|f| f.key == key)?;
    match ((field.get)(object), part) {
        (Value::Number(n), None) => Some(n),
        (Value::Vector(v), Some(part)) => Some(part.get(v)),
        _ => None,
    }
}

/// Writes `value` into `object`'s field `key` (its `part`, for a vector).
fn write<T>(fields: &[Field<T>], object: &mut T, key: &str, part: Option<Part>, value: f64) {
    let Some(field) = fields.iter().find(|f| f.key == key) else {
        return;
    };
    let new = match ((field.get)(object), part) {
        (Value::Number(_), None) => Value::Number(value),
        (Value::Vector(v), Some(part)) => Value::Vector(part.set(v, value)),
        _ => return,
    };
    (field.set)(object, new);
}

impl Setting {
    /// Reads `text` as a number of `scene`.
    ///
    /// # Errors
    /// No such object, key or part, or a key that holds no number (in words).
    pub fn parse(text: &str, scene: &Scene) -> Result<Self, String> {
        let text = text.trim();
        let unknown = |what: &str| say(what, &[("text", text)]);
        // The object: `world`, `simulation`, or the longest object name before a dot
        // (names may hold dots and spaces).
        let objects = ObjectKind::ALL
            .into_iter()
            .flat_map(|kind| scene.objects_of(kind))
            .map(|(id, name)| (name, id.section()))
            .chain([
                ("world", Section::World),
                ("simulation", Section::Simulation),
            ]);
        let (target, rest) = objects
            .filter_map(|(name, target)| {
                let rest = text.strip_prefix(name)?.strip_prefix('.')?;
                Some((name.len(), target, rest))
            })
            .max_by_key(|&(length, _, _)| length)
            .map(|(_, target, rest)| (target, rest))
            .ok_or_else(|| unknown("setting-object"))?;
        let (key, part) = match rest.split_once('.') {
            Some((key, part)) => (key, Some(part)),
            None => (rest, None),
        };
        let found = match target {
            Section::Particle(_) => numeric(fields::PARTICLE, key),
            Section::Spring(_) => numeric(fields::SPRING, key),
            Section::Tie(i) => numeric(fields::tie_fields(scene.ties[i].kind), key),
            Section::Ramp(_) => numeric(fields::RAMP, key),
            Section::Body(_) => numeric(fields::BODY, key),
            Section::World => numeric(fields::WORLD, key),
            Section::Simulation => numeric(fields::SIMULATION, key),
            // Joints and forces have no numbers to vary.
            _ => None,
        };
        let (key, vector, unit) = found.ok_or_else(|| unknown("setting-key"))?;
        let part = match (vector, part) {
            (false, None) => None,
            (true, Some(part)) => Some(Part::parse(part).ok_or_else(|| unknown("setting-part"))?),
            (true, None) | (false, Some(_)) => return Err(unknown("setting-part")),
        };
        let unit = if part == Some(Part::Angle) {
            "°"
        } else {
            unit
        };
        Ok(Self {
            text: text.to_owned(),
            target,
            key,
            part,
            unit,
        })
    }

    /// The field it writes, as a problem with the scene names it.
    pub fn field(&self) -> crate::scene::FieldRef {
        crate::scene::FieldRef {
            section: self.target,
            field: self.key,
        }
    }

    /// The unit of the number written: the field's, degrees for a vector's angle.
    pub fn unit(&self) -> &'static str {
        self.unit
    }

    /// The number in `scene` (0 where the scene no longer has the object).
    pub fn value(&self, scene: &Scene) -> f64 {
        let (key, part) = (self.key, self.part);
        match self.target {
            Section::Particle(i) => scene
                .particles
                .get(i)
                .and_then(|p| read(fields::PARTICLE, p, key, part)),
            Section::Spring(i) => scene
                .springs
                .get(i)
                .and_then(|s| read(fields::SPRING, s, key, part)),
            Section::Tie(i) => scene
                .ties
                .get(i)
                .and_then(|t| read(fields::tie_fields(t.kind), t, key, part)),
            Section::Ramp(i) => scene
                .ramps
                .get(i)
                .and_then(|r| read(fields::RAMP, r, key, part)),
            Section::Body(i) => scene
                .bodies
                .get(i)
                .and_then(|b| read(fields::BODY, b, key, part)),
            Section::World => read(fields::WORLD, &scene.world, key, part),
            Section::Simulation => read(fields::SIMULATION, &scene.simulation, key, part),
            _ => None,
        }
        .unwrap_or(0.0)
    }

    /// Writes `value` into `scene`.
    pub fn set(&self, scene: &mut Scene, value: f64) {
        let (key, part) = (self.key, self.part);
        match self.target {
            Section::Particle(i) => {
                write(fields::PARTICLE, &mut scene.particles[i], key, part, value);
            }
            Section::Spring(i) => write(fields::SPRING, &mut scene.springs[i], key, part, value),
            Section::Tie(i) => {
                let fields = fields::tie_fields(scene.ties[i].kind);
                write(fields, &mut scene.ties[i], key, part, value);
            }
            Section::Ramp(i) => write(fields::RAMP, &mut scene.ramps[i], key, part, value),
            Section::Body(i) => write(fields::BODY, &mut scene.bodies[i], key, part, value),
            Section::World => write(fields::WORLD, &mut scene.world, key, part, value),
            Section::Simulation => {
                write(fields::SIMULATION, &mut scene.simulation, key, part, value);
            }
            _ => {}
        }
    }
}

impl Setting {
    /// Whether it is a number of `[simulation]` (the time step, the start), which changes
    /// how long each run takes.
    pub(super) fn is_simulation(&self) -> bool {
        self.target == Section::Simulation
    }

    /// Whether it is a vector's angle (degrees in the file, radians in a theory).
    pub(super) fn is_angle(&self) -> bool {
        self.part == Some(Part::Angle)
    }
}

impl Setting {
    /// The scene's constants a theory may name, for this setting's object.
    pub(super) fn constants(&self, scene: &Scene) -> Vec<(&'static str, f64)> {
        // `pi` as the app's fields read it (exmex's own is `PI`).
        let mut named = vec![
            ("g", scene.world.gravity.to_dvec2().length()),
            ("pi", std::f64::consts::PI),
        ];
        match self.target {
            Section::Particle(i) => {
                let p = &scene.particles[i];
                named.extend([
                    ("m", p.mass),
                    ("r", p.radius),
                    ("v0", p.velocity.to_dvec2().length()),
                    ("h", p.position.to_dvec2().y),
                    ("b", p.linear_drag),
                    ("c", p.quadratic_drag_in(scene.world.air_density)),
                ]);
                // The length of the first rod or string that holds it.
                let holds = |end: &crate::scene::Endpoint| matches!(end, crate::scene::Endpoint::Particle(n) if *n == p.name);
                if let Some(tie) = scene.ties.iter().find(|t| holds(&t.from) || holds(&t.to)) {
                    named.push(("L", tie.length));
                }
            }
            Section::Tie(i) => named.push(("L", scene.ties[i].length)),
            Section::Spring(i) => {
                let s = &scene.springs[i];
                named.extend([("k", s.stiffness), ("L", s.natural_length)]);
            }
            Section::Body(i) => {
                let b = &scene.bodies[i];
                named.extend([
                    ("m", b.total_mass()),
                    ("I", b.inertia()),
                    ("v0", b.velocity.to_dvec2().length()),
                    ("h", b.position.to_dvec2().y),
                    ("w", b.width),
                ]);
            }
            _ => {}
        }
        named
    }
}
