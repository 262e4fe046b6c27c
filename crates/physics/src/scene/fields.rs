//! One table of the scene's fields. Each field of `[world]`, `[simulation]`,
//! `[[particle]]`, `[[spring]]`, `[[rod]]`, `[[string]]` and `[[ramp]]` is defined once here — its key, what a
//! person calls it, its kind and rule, unit, default and one line of help — and that
//! definition drives the TOML/JSON reader and writer, [`Scene::validate`]'s rules for
//! numbers and vectors, the app's inspector (label, unit, tooltip, checking) and the
//! reference table in `docs/scene-format.md` (a test keeps that table equal to
//! [`reference()`]).
//!
//! Names are the one field outside the table: every object has one, it labels every
//! message about the object, and renaming carries references along (`edit.rs`).
//! `[[graph]]` and `[view]` are the app's and have their own reader (`presentation.rs`).
//!
//! [`Scene::validate`]: super::Scene::validate

use std::fmt::Write as _;

use super::{
    Body, Bounds, Color, Endpoint, PairForces, Particle, Ramp, Settings, Spring, Tie, Vector, World,
};
use crate::Integrator;
use crate::scene::Rule;

/// What kind of value a field holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A number, with its rule.
    Number(Rule),
    /// `[x, y]` or `{ magnitude, angle }`.
    Vector,
    /// `true` or `false`.
    Bool,
    /// A particle's name, or a fixed point.
    Endpoint,
    /// An integration method's name.
    Integrator,
    /// How pairwise forces are summed: `direct` or `tree`.
    PairForces,
    /// `"#rrggbb"`, optional.
    Color,
    /// `{ min = [x, y], max = [x, y] }`, optional.
    Bounds,
}

/// A field's value, whatever its kind.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// [`Kind::Number`].
    Number(f64),
    /// [`Kind::Vector`].
    Vector(Vector),
    /// [`Kind::Bool`].
    Bool(bool),
    /// [`Kind::Endpoint`].
    Endpoint(Endpoint),
    /// [`Kind::Integrator`].
    Integrator(Integrator),
    /// [`Kind::PairForces`].
    PairForces(PairForces),
    /// [`Kind::Color`]; `None` when not chosen.
    Color(Option<Color>),
    /// [`Kind::Bounds`]; `None` when there are none.
    Bounds(Option<Bounds>),
}

/// Where the app edits a field.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// In the inspector.
    Inspector,
    /// In the tool bar (the integrator and the time step).
    Toolbar,
}

/// One field of a section whose values are of type `T`.
pub struct Field<T: 'static> {
    /// The key in a scene file.
    pub key: &'static str,
    /// What a person calls it (the inspector's label).
    pub label: &'static str,
    /// Its kind, with the rule a number obeys.
    pub kind: Kind,
    /// The SI unit, or "" for a pure number.
    pub unit: &'static str,
    /// The default as a file would write it; `None` when the field is required.
    pub default: Option<&'static str>,
    /// One line of help (the inspector's tooltip, the docs' description).
    pub help: &'static str,
    /// Where the app edits it.
    pub place: Place,
    /// Reads the value.
    pub get: fn(&T) -> Value,
    /// Writes the value; a value of another kind is ignored.
    pub set: fn(&mut T, Value),
}

/// A field read and written as it is stored: a number, a vector or a flag.
macro_rules! plain {
    ($variant:ident, $kind:expr, $key:literal, $label:literal, $field:ident, $unit:literal, $default:expr, $help:literal) => {
        Field {
            key: $key,
            label: $label,
            kind: $kind,
            unit: $unit,
            default: $default,
            help: $help,
            place: Place::Inspector,
            get: |t| Value::$variant(t.$field),
            set: |t, v| {
                if let Value::$variant(v) = v {
                    t.$field = v;
                }
            },
        }
    };
}

macro_rules! number {
    ($key:literal, $label:literal, $field:ident, $rule:expr, $unit:literal, $default:expr, $help:literal) => {
        plain!(
            Number,
            Kind::Number($rule),
            $key,
            $label,
            $field,
            $unit,
            $default,
            $help
        )
    };
}

macro_rules! vector {
    ($key:literal, $label:literal, $field:ident, $unit:literal, $default:expr, $help:literal) => {
        plain!(
            Vector,
            Kind::Vector,
            $key,
            $label,
            $field,
            $unit,
            $default,
            $help
        )
    };
}

macro_rules! boolean {
    ($key:literal, $label:literal, $field:ident, $default:literal, $help:literal) => {
        plain!(
            Bool,
            Kind::Bool,
            $key,
            $label,
            $field,
            "",
            Some($default),
            $help
        )
    };
}

macro_rules! endpoint {
    ($key:literal, $field:ident, $help:literal) => {
        Field {
            key: $key,
            label: $key,
            kind: Kind::Endpoint,
            unit: "",
            default: None,
            help: $help,
            place: Place::Inspector,
            get: |t| Value::Endpoint(t.$field.clone()),
            set: |t, v| {
                if let Value::Endpoint(v) = v {
                    t.$field = v;
                }
            },
        }
    };
}

/// `[world]`.
pub const WORLD: &[Field<World>] = &[
    vector!(
        "gravity",
        "gravity",
        gravity,
        "m/s²",
        Some("[0.0, -9.81]"),
        "The uniform field"
    ),
    boolean!(
        "gravitation",
        "gravitation between particles",
        gravitation,
        "true",
        "Newton's inverse-square attraction between every pair"
    ),
    number!(
        "gravitational_constant",
        "G",
        gravitational_constant,
        Rule::Finite,
        "N·m²/kg²",
        Some("6.6742e-11"),
        "The gravitational constant (the paper's value)"
    ),
    boolean!(
        "electrostatics",
        "electrostatics",
        electrostatics,
        "true",
        "Coulomb's law between charged particles"
    ),
    number!(
        "coulomb_constant",
        "k",
        coulomb_constant,
        Rule::Finite,
        "N·m²/C²",
        Some("8.988e9"),
        "The Coulomb constant"
    ),
    number!(
        "softening",
        "softening",
        softening,
        Rule::NonNegative,
        "m",
        Some("0.0"),
        "Plummer softening ε of gravitation and Coulomb: force ∝ r/(r² + ε²)^(3/2), finite in close passes"
    ),
    number!(
        "air_density",
        "air density",
        air_density,
        Rule::NonNegative,
        "kg/m³",
        Some("1.2"),
        "ρ, what a particle's drag coefficient pushes against: ½ ρ C_d π r² v² (air at 20 °C: 1.2)"
    ),
    number!(
        "magnetic_field",
        "magnetic field",
        magnetic_field,
        Rule::Finite,
        "T",
        Some("0.0"),
        "B_z, out of the screen positive: a force q v × B on every moving charged particle"
    ),
    boolean!(
        "collisions",
        "collisions between particles",
        collisions,
        "true",
        "Particles strike and rest on each other; false: they pass through each other (ramps and bounds still stop them)"
    ),
    number!(
        "restitution",
        "restitution",
        restitution,
        Rule::Fraction,
        "",
        Some("1.0"),
        "Particle–particle impacts: 0 (sticky) to 1 (elastic)"
    ),
    number!(
        "friction",
        "friction between particles",
        friction,
        Rule::NonNegative,
        "",
        Some("0.0"),
        "μ between turning particles at impacts: their contact points grip within μ times the normal impulse"
    ),
    Field {
        key: "bounds",
        label: "bounds",
        kind: Kind::Bounds,
        unit: "m",
        default: Some("none"),
        help: "A reflecting box around the world",
        place: Place::Inspector,
        get: |w| Value::Bounds(w.bounds),
        set: |w, v| {
            if let Value::Bounds(v) = v {
                w.bounds = v;
            }
        },
    },
];

/// `[simulation]`.
pub const SIMULATION: &[Field<Settings>] = &[
    Field {
        key: "integrator",
        label: "integrator",
        kind: Kind::Integrator,
        unit: "",
        default: Some("\"rk4\""),
        help: "How the motion is integrated in time: euler, semi-implicit-euler, verlet, rk4, pefrl, dopri5",
        place: Place::Toolbar,
        get: |s| Value::Integrator(s.integrator),
        set: |s, v| {
            if let Value::Integrator(v) = v {
                s.integrator = v;
            }
        },
    },
    Field {
        place: Place::Toolbar,
        ..number!(
            "time_step",
            "time step",
            time_step,
            Rule::Positive,
            "s",
            Some("0.001"),
            "The step (dopri5: the largest step)"
        )
    },
    number!(
        "tolerance",
        "tolerance",
        tolerance,
        Rule::Positive,
        "",
        Some("1e-9"),
        "dopri5 only: error allowed per step, relative and absolute"
    ),
    number!(
        "time_scale",
        "time scale",
        time_scale,
        Rule::Positive,
        "×",
        Some("1.0"),
        "Simulated seconds per real second when playing in the app"
    ),
    Field {
        key: "pair_forces",
        label: "pair forces",
        kind: Kind::PairForces,
        unit: "",
        default: Some("\"direct\""),
        help: "How gravitation is summed: direct (every pair, exact) or tree (Barnes–Hut, for thousands of bodies)",
        place: Place::Inspector,
        get: |s| Value::PairForces(s.pair_forces),
        set: |s, v| {
            if let Value::PairForces(v) = v {
                s.pair_forces = v;
            }
        },
    },
    number!(
        "opening_angle",
        "opening angle",
        opening_angle,
        Rule::Positive,
        "",
        Some("0.5"),
        "Tree only: a group of size s at distance d acts as one body when s/d is below this"
    ),
    number!(
        "start_time",
        "start time",
        start_time,
        Rule::Finite,
        "s",
        Some("0.0"),
        "The instant the scene's state describes (a saved state keeps its time)"
    ),
];

/// `[[particle]]`, after its name.
pub const PARTICLE: &[Field<Particle>] = &[
    number!(
        "mass",
        "mass",
        mass,
        Rule::Positive,
        "kg",
        None,
        "Mass, greater than 0"
    ),
    number!(
        "radius",
        "radius",
        radius,
        Rule::Positive,
        "m",
        Some("0.5"),
        "Radius, greater than 0"
    ),
    number!(
        "charge",
        "charge",
        charge,
        Rule::Finite,
        "C",
        Some("0.0"),
        "Electric charge"
    ),
    vector!("position", "position", position, "m", None, "Position"),
    vector!(
        "velocity",
        "velocity",
        velocity,
        "m/s",
        Some("[0.0, 0.0]"),
        "Velocity"
    ),
    vector!(
        "acceleration",
        "acceleration",
        acceleration,
        "m/s²",
        Some("[0.0, 0.0]"),
        "A constant applied acceleration on top of all forces"
    ),
    boolean!(
        "fixed",
        "fixed",
        fixed,
        "false",
        "A fixed particle never moves; it still attracts, repels and is hit"
    ),
    number!(
        "linear_drag",
        "air resistance, linear",
        linear_drag,
        Rule::NonNegative,
        "kg/s",
        Some("0.0"),
        "Air resistance b: a force of b v against the motion (slow motion in a thick fluid)"
    ),
    number!(
        "quadratic_drag",
        "air resistance, quadratic",
        quadratic_drag,
        Rule::NonNegative,
        "kg/m",
        Some("0.0"),
        "Air resistance c: a force of c v² against the motion (a ball through air: c = ½ ρ C_d A)"
    ),
    number!(
        "drag_coefficient",
        "drag coefficient",
        drag_coefficient,
        Rule::NonNegative,
        "",
        Some("0.0"),
        "C_d: air resistance ½ ρ C_d π r² v² from the world's air density and the radius (a ball: 0.47); instead of the quadratic c"
    ),
    number!(
        "inertia",
        "moment of inertia",
        inertia,
        Rule::NonNegative,
        "m r²",
        Some("0.0"),
        "I/(m r²): 0 a point that never turns, 0.5 a solid disc, 1 a thin ring"
    ),
    number!(
        "spin",
        "spin",
        spin,
        Rule::Finite,
        "rad/s",
        Some("0.0"),
        "Angular velocity ω, counter-clockwise positive (a turning particle's)"
    ),
    number!(
        "angle",
        "angle",
        angle,
        Rule::Finite,
        "°",
        Some("0.0"),
        "Orientation, counter-clockwise: where the turning particle's marked radius points"
    ),
    Field {
        key: "color",
        label: "colour",
        kind: Kind::Color,
        unit: "",
        default: Some("a palette colour"),
        help: "Display colour, \"#rrggbb\"",
        place: Place::Inspector,
        get: |p| Value::Color(p.color),
        set: |p, v| {
            if let Value::Color(v) = v {
                p.color = v;
            }
        },
    },
];

/// `[[spring]]`, after its name.
pub const SPRING: &[Field<Spring>] = &[
    endpoint!("from", from, "A particle's name, or a fixed point [x, y]"),
    endpoint!("to", to, "A particle's name, or a fixed point [x, y]"),
    number!(
        "stiffness",
        "stiffness",
        stiffness,
        Rule::NonNegative,
        "N/m",
        None,
        "k, 0 or more"
    ),
    number!(
        "natural_length",
        "natural length",
        natural_length,
        Rule::NonNegative,
        "m",
        None,
        "The length at which the spring exerts no force"
    ),
    number!(
        "damping",
        "damping",
        damping,
        Rule::NonNegative,
        "N·s/m",
        Some("0.0"),
        "b: force −b·(relative velocity along the spring)"
    ),
];

/// `[[rod]]`, after its name.
pub const ROD: &[Field<Tie>] = &[
    endpoint!("from", from, "A particle's name, or a fixed point [x, y]"),
    endpoint!("to", to, "A particle's name, or a fixed point [x, y]"),
    number!(
        "length",
        "length",
        length,
        Rule::Positive,
        "m",
        Some("the distance at the start"),
        "The distance the rod keeps between its ends"
    ),
];

/// `[[string]]`, after its name: a rod's fields and the restitution of snapping taut.
pub const STRING: &[Field<Tie>] = &[
    endpoint!("from", from, "A particle's name, or a fixed point [x, y]"),
    endpoint!("to", to, "A particle's name, or a fixed point [x, y]"),
    number!(
        "length",
        "length",
        length,
        Rule::Positive,
        "m",
        Some("the distance at the start"),
        "The farthest apart the string lets its ends go"
    ),
    number!(
        "restitution",
        "restitution",
        restitution,
        Rule::Fraction,
        "",
        Some("0.0"),
        "When it snaps taut: 0 (the ends stop separating) to 1 (they bounce back)"
    ),
];

/// The fields of a rod or a string.
pub fn tie_fields(kind: super::TieKind) -> &'static [Field<Tie>] {
    match kind {
        super::TieKind::Rod => ROD,
        super::TieKind::String => STRING,
    }
}

/// `[[ramp]]`, after its name.
pub const RAMP: &[Field<Ramp>] = &[
    vector!("from", "from", from, "m", None, "One end of the ramp"),
    vector!("to", "to", to, "m", None, "The other end"),
    number!(
        "thickness",
        "thickness",
        thickness,
        Rule::NonNegative,
        "m",
        Some("0.1"),
        "The ramp is every point within half this of its segment"
    ),
    number!(
        "restitution",
        "restitution",
        restitution,
        Rule::Fraction,
        "",
        Some("1.0"),
        "0 (no bounce) to 1 (perfectly elastic)"
    ),
    number!(
        "friction",
        "friction",
        friction,
        Rule::NonNegative,
        "",
        Some("0.0"),
        "Coefficient of static and kinetic friction"
    ),
];

/// `[[body]]`, after its name and besides its shape (`shape`, `vertices`) and
/// `static_friction`, which the reader and writer take apart ([`BODY_SHAPE_KEYS`]).
/// A box's `width` and `height` and the `mass` or `density` not given hold 0 and are not
/// written.
pub const BODY: &[Field<Body>] = &[
    number!(
        "width",
        "width",
        width,
        Rule::NonNegative,
        "m",
        Some("box: required"),
        "A box's extent along its own x"
    ),
    number!(
        "height",
        "height",
        height,
        Rule::NonNegative,
        "m",
        Some("box: required"),
        "A box's extent along its own y"
    ),
    // Setting one of mass and density puts the other out of use (0), so that typing a
    // mass in the inspector replaces a density; the reader refuses a file giving both.
    Field {
        key: "mass",
        label: "mass",
        kind: Kind::Number(Rule::NonNegative),
        unit: "kg",
        default: Some("or density"),
        help: "Mass, greater than 0 (or give the density instead)",
        place: Place::Inspector,
        get: |b| Value::Number(b.mass),
        set: |b, v| {
            if let Value::Number(v) = v {
                b.mass = v;
                if v != 0.0 {
                    b.density = 0.0;
                }
            }
        },
    },
    Field {
        key: "density",
        label: "density",
        kind: Kind::Number(Rule::NonNegative),
        unit: "kg/m²",
        default: Some("or mass"),
        help: "Mass per area: the shape's area gives the mass",
        place: Place::Inspector,
        get: |b| Value::Number(b.density),
        set: |b, v| {
            if let Value::Number(v) = v {
                b.density = v;
                if v != 0.0 {
                    b.mass = 0.0;
                }
            }
        },
    },
    vector!("position", "position", position, "m", None, "The centroid"),
    number!(
        "angle",
        "angle",
        angle,
        Rule::Finite,
        "°",
        Some("0.0"),
        "Orientation, counter-clockwise"
    ),
    vector!(
        "velocity",
        "velocity",
        velocity,
        "m/s",
        Some("[0.0, 0.0]"),
        "The centroid's velocity"
    ),
    number!(
        "spin",
        "spin",
        spin,
        Rule::Finite,
        "rad/s",
        Some("0.0"),
        "Angular velocity ω, counter-clockwise positive"
    ),
    number!(
        "restitution",
        "restitution",
        restitution,
        Rule::Fraction,
        "",
        Some("1.0"),
        "0 (no bounce) to 1 (perfectly elastic)"
    ),
    number!(
        "friction",
        "friction",
        friction,
        Rule::NonNegative,
        "",
        Some("0.0"),
        "Kinetic coefficient of friction"
    ),
    boolean!("fixed", "fixed", fixed, "false", "A fixed body never moves"),
    Field {
        key: "color",
        label: "colour",
        kind: Kind::Color,
        unit: "",
        default: Some("a palette colour"),
        help: "Display colour, \"#rrggbb\"",
        place: Place::Inspector,
        get: |b| Value::Color(b.color),
        set: |b, v| {
            if let Value::Color(v) = v {
                b.color = v;
            }
        },
    },
];

/// A ramp's key outside [`RAMP`], with the reference's line: the static friction, whose
/// default is another field.
pub const RAMP_STATIC_FRICTION: (&str, &str, &str, &str, &str) = (
    "static_friction",
    "number ≥ friction",
    "",
    "friction",
    "Static coefficient of friction for rigid bodies resting on it (particles hold and slide with `friction`)",
);

/// The keys of `[[body]]` outside [`BODY`], with the reference's line for each: the
/// shape, its vertices, and the static friction (whose default is another field).
pub const BODY_SHAPE_KEYS: [(&str, &str, &str, &str, &str); 3] = [
    (
        "shape",
        "box or polygon",
        "",
        "**required**",
        "A box (`width`, `height`) or a convex polygon (`vertices`)",
    ),
    (
        "vertices",
        "list of [x, y]",
        "m",
        "polygon: required",
        "3 to 64 corners, counter-clockwise, convex, in the body's frame (moved so that the centroid is the origin)",
    ),
    (
        "static_friction",
        "number ≥ friction",
        "",
        "friction",
        "Static coefficient of friction",
    ),
];

/// The keys of a section's fields, after `first` (such as `name`).
pub fn keys<T>(first: &[&'static str], fields: &[Field<T>]) -> Vec<&'static str> {
    first
        .iter()
        .copied()
        .chain(fields.iter().map(|f| f.key))
        .collect()
}

/// The reference of every field as a Markdown table per section: what
/// `docs/scene-format.md` shows.
pub fn reference() -> String {
    fn section<T>(out: &mut String, title: &str, fields: &[Field<T>]) {
        let _ = writeln!(out, "`{title}`\n");
        out.push_str("| key | kind | unit | default | |\n|---|---|---|---|---|\n");
        for f in fields {
            let kind = match f.kind {
                Kind::Number(Rule::Finite) => "number",
                Kind::Number(Rule::Positive) => "number > 0",
                Kind::Number(Rule::NonNegative) => "number ≥ 0",
                Kind::Number(Rule::Fraction) => "number in 0..1",
                Kind::Vector => "vector",
                Kind::Bool => "true or false",
                Kind::Endpoint => "name or point",
                Kind::Integrator => "method",
                Kind::PairForces => "direct or tree",
                Kind::Color => "colour",
                Kind::Bounds => "box",
            };
            let _ = writeln!(
                out,
                "| `{}` | {kind} | {} | {} | {} |",
                f.key,
                f.unit,
                f.default.unwrap_or("**required**"),
                f.help
            );
        }
        out.push('\n');
    }
    let mut out = String::new();
    section(&mut out, "[world]", WORLD);
    section(&mut out, "[simulation]", SIMULATION);
    section(&mut out, "[[particle]]", PARTICLE);
    section(&mut out, "[[spring]]", SPRING);
    section(&mut out, "[[rod]]", ROD);
    section(&mut out, "[[string]]", STRING);
    section(&mut out, "[[ramp]]", RAMP);
    out.pop();
    let (key, kind, unit, default, help) = RAMP_STATIC_FRICTION;
    let _ = writeln!(out, "| `{key}` | {kind} | {unit} | {default} | {help} |");
    out.push('\n');
    section(&mut out, "[[body]]", BODY);
    // The body's keys outside the table, in the table just written.
    out.pop();
    for (key, kind, unit, default, help) in BODY_SHAPE_KEYS {
        let _ = writeln!(out, "| `{key}` | {kind} | {unit} | {default} | {help} |");
    }
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every field's getter and setter agree: set what was got, on another object, and
    /// get it back.
    #[test]
    fn setters_write_what_getters_read() {
        fn check<T>(fields: &[Field<T>], from: &T, to: &mut T) {
            for f in fields {
                let value = (f.get)(from);
                (f.set)(to, value.clone());
                assert_eq!((f.get)(to), value, "{}", f.key);
            }
        }
        let mut a = Particle::new("a", 2.0)
            .position([1.0, 2.0])
            .velocity([3.0, 4.0])
            .acceleration([5.0, 6.0])
            .radius(0.7)
            .charge(-1.0)
            .fixed();
        a.color = Some(Color([1, 2, 3]));
        check(PARTICLE, &a, &mut Particle::new("b", 1.0));
        let spring = Spring::new("s", "a", [1.0, 1.0], 3.0, 4.0).damping(0.5);
        check(SPRING, &spring, &mut Spring::new("t", "x", "y", 1.0, 1.0));
        let string = Tie::string("s", "a", [1.0, 1.0], 3.0).restitution(0.5);
        check(STRING, &string, &mut Tie::rod("t", "x", "y", 1.0));
        let ramp = Ramp::new("r", [0.0, 1.0], [2.0, 3.0])
            .thickness(0.3)
            .restitution(0.4)
            .friction(0.6);
        check(RAMP, &ramp, &mut Ramp::new("q", [0.0, 0.0], [1.0, 0.0]));
        let mut body = Body::rectangle("b", 0.4, 0.2, 2.0)
            .position([1.0, 2.0])
            .angle(20.0)
            .moving([1.0, -1.0], 3.0);
        (body.restitution, body.friction, body.fixed) = (0.2, 0.3, true);
        body.color = Some(Color([1, 2, 3]));
        check(BODY, &body, &mut Body::rectangle("c", 1.0, 1.0, 1.0));
        let mut world = World::weightless();
        world.bounds = Some(Bounds {
            min: Vector::cartesian(-1.0, -1.0),
            max: Vector::cartesian(1.0, 1.0),
            friction: 0.0,
            static_friction: None,
        });
        world.restitution = 0.3;
        check(WORLD, &world, &mut World::default());
        let settings = Settings {
            integrator: Integrator::Dopri5,
            time_step: 0.1,
            tolerance: 1e-6,
            time_scale: 3.0,
            start_time: 2.5,
            pair_forces: PairForces::Tree,
            opening_angle: 0.3,
        };
        check(SIMULATION, &settings, &mut Settings::default());
    }
}
