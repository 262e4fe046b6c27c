//! The editable description of a scene: plain data, exactly the fields of the scene
//! format (`docs/scene-format.md`, version 1), in the form the user typed them.
//!
//! Nothing here is derived or cached: a vector stays polar if it was typed polar, a
//! colour stays the colour that was chosen. [`crate::Simulation::new`] converts a scene
//! into runtime state; [`Scene::validate`] lists everything wrong with one.

mod body;
mod edit;
pub mod error;
pub mod fields;
pub(crate) mod force;
pub mod format;
pub mod instruments;
mod joint;
pub mod lesson;
mod links;
mod object;
mod presentation;
pub mod series;
mod validate;

use glam::DVec2;
/// The checker's message `id` in the thread's language, its arguments given as text:
/// numbers are written by the caller as files write them.
pub(crate) use newtonlab_i18n::tr_text as say;

pub use crate::constraints::TieKind;
pub use body::{Body, Moments, Shape, moments};
pub use error::{FieldRef, Section};
pub use force::Force;
pub use instruments::{Instruments, Protractor, Stopwatch, Trigger};
pub(crate) use joint::in_frame;
pub use joint::{Joint, JointKind, Motor};
pub use lesson::{Lesson, Question, Slider, Verdict};
pub use object::{ObjectId, ObjectKind, SectionKind};
pub use presentation::{Follow, Graph, Series, View};
pub use validate::{Rule, check_value};

/// A 2D vector as the user typed it: Cartesian `[x, y]` or polar
/// `{ magnitude, angle }` with the angle in degrees counter-clockwise from +x.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Vector {
    /// Components along x and y.
    Cartesian(DVec2),
    /// A length and a direction.
    Polar {
        /// The length, in the vector's unit.
        magnitude: f64,
        /// Degrees, counter-clockwise from +x.
        angle: f64,
    },
}

impl Vector {
    /// The zero vector, Cartesian.
    pub const ZERO: Self = Self::Cartesian(DVec2::ZERO);

    /// A Cartesian vector.
    pub const fn cartesian(x: f64, y: f64) -> Self {
        Self::Cartesian(DVec2::new(x, y))
    }

    /// A polar vector: `magnitude` at `angle` degrees counter-clockwise from +x.
    pub const fn polar(magnitude: f64, angle: f64) -> Self {
        Self::Polar { magnitude, angle }
    }

    /// The Cartesian components, whatever the form.
    pub fn to_dvec2(self) -> DVec2 {
        match self {
            Self::Cartesian(v) => v,
            Self::Polar { magnitude, angle } => {
                let (sin, cos) = angle.to_radians().sin_cos();
                DVec2::new(magnitude * cos, magnitude * sin)
            }
        }
    }

    /// The same vector in polar form, with the angle in (-180, 180].
    #[must_use]
    pub fn to_polar(self) -> Self {
        match self {
            Self::Polar { .. } => self,
            Self::Cartesian(v) => Self::Polar {
                magnitude: v.length(),
                angle: v.y.atan2(v.x).to_degrees(),
            },
        }
    }

    /// The same vector in Cartesian form.
    #[must_use]
    pub fn to_cartesian(self) -> Self {
        Self::Cartesian(self.to_dvec2())
    }

    /// Whether both numbers are finite.
    pub fn is_finite(self) -> bool {
        match self {
            Self::Cartesian(v) => v.is_finite(),
            Self::Polar { magnitude, angle } => magnitude.is_finite() && angle.is_finite(),
        }
    }
}

impl From<DVec2> for Vector {
    fn from(v: DVec2) -> Self {
        Self::Cartesian(v)
    }
}

impl From<[f64; 2]> for Vector {
    fn from([x, y]: [f64; 2]) -> Self {
        Self::cartesian(x, y)
    }
}

/// An sRGB colour, written `"#rrggbb"` in scene files.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Color(pub [u8; 3]);

impl Color {
    /// Parses `#rrggbb` (case-insensitive).
    pub fn parse_hex(text: &str) -> Option<Self> {
        let hex = text.strip_prefix('#')?;
        if hex.len() != 6 || !hex.is_ascii() {
            return None;
        }
        let channel = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).ok();
        Some(Self([channel(0)?, channel(2)?, channel(4)?]))
    }

    /// `#rrggbb`, lower case.
    pub fn to_hex(self) -> String {
        let [r, g, b] = self.0;
        format!("#{r:02x}{g:02x}{b:02x}")
    }
}

/// A point mass with a radius: the paper's projectile.
#[derive(Clone, Debug, PartialEq)]
pub struct Particle {
    /// Unique among all objects of the scene.
    pub name: String,
    /// Kilograms, > 0.
    pub mass: f64,
    /// Metres, > 0. Default 0.5.
    pub radius: f64,
    /// Coulombs. Default 0.
    pub charge: f64,
    /// Metres.
    pub position: Vector,
    /// Metres per second. Default zero.
    pub velocity: Vector,
    /// A constant applied acceleration on top of all forces, metres per second squared.
    /// Default zero.
    pub acceleration: Vector,
    /// A fixed particle never moves; it still attracts, repels and is hit, with infinite
    /// inertia. Default false.
    pub fixed: bool,
    /// Display colour; `None` lets the app choose.
    pub color: Option<Color>,
    /// Linear air resistance b, kg/s: a force −b v. Default 0.
    pub linear_drag: f64,
    /// Quadratic air resistance c, kg/m: a force −c |v| v. Default 0.
    pub quadratic_drag: f64,
    /// The drag coefficient `C_d`, ≥ 0: quadratic air resistance ½ ρ `C_d` π r² |v| v from
    /// the world's air density and the particle's cross-section (instead of
    /// `quadratic_drag`, not both). Default 0.
    pub drag_coefficient: f64,
    /// The moment of inertia as a multiple of m r², ≥ 0: 0 (the default) is the paper's
    /// point particle, which never turns and feels no friction at impacts; 0.5 a solid
    /// disc, 1 a thin ring.
    pub inertia: f64,
    /// Angular velocity, radians per second, counter-clockwise positive. Default 0.
    pub spin: f64,
    /// Orientation, degrees counter-clockwise: only where its marked radius is drawn.
    /// Default 0.
    pub angle: f64,
}

impl Particle {
    /// A particle of `mass` kilograms at the origin, at rest, with the default radius.
    #[must_use]
    pub fn new(name: impl Into<String>, mass: f64) -> Self {
        Self {
            name: name.into(),
            mass,
            radius: 0.5,
            charge: 0.0,
            position: Vector::ZERO,
            velocity: Vector::ZERO,
            acceleration: Vector::ZERO,
            fixed: false,
            color: None,
            linear_drag: 0.0,
            quadratic_drag: 0.0,
            drag_coefficient: 0.0,
            inertia: 0.0,
            spin: 0.0,
            angle: 0.0,
        }
    }

    /// The quadratic air resistance c it feels, kg/m, in air of density `air_density`
    /// (kg/m³): its own c, or ½ ρ `C_d` π r² from its drag coefficient.
    pub fn quadratic_drag_in(&self, air_density: f64) -> f64 {
        if self.drag_coefficient > 0.0 {
            0.5 * air_density
                * self.drag_coefficient
                * std::f64::consts::PI
                * self.radius
                * self.radius
        } else {
            self.quadratic_drag
        }
    }

    /// Whether it turns: a moment of inertia above zero.
    pub fn turns(&self) -> bool {
        self.inertia > 0.0
    }

    /// The velocity it starts with, m/s: zero for a fixed particle, whatever was typed.
    pub fn initial_velocity(&self) -> DVec2 {
        if self.fixed {
            DVec2::ZERO
        } else {
            self.velocity.to_dvec2()
        }
    }

    /// Sets the position, metres.
    #[must_use]
    pub fn position(mut self, position: impl Into<Vector>) -> Self {
        self.position = position.into();
        self
    }

    /// Sets the velocity, metres per second.
    #[must_use]
    pub fn velocity(mut self, velocity: impl Into<Vector>) -> Self {
        self.velocity = velocity.into();
        self
    }

    /// Sets the constant applied acceleration, metres per second squared.
    #[must_use]
    pub fn acceleration(mut self, acceleration: impl Into<Vector>) -> Self {
        self.acceleration = acceleration.into();
        self
    }

    /// Sets the radius, metres.
    #[must_use]
    pub fn radius(mut self, radius: f64) -> Self {
        self.radius = radius;
        self
    }

    /// Sets the charge, coulombs.
    #[must_use]
    pub fn charge(mut self, charge: f64) -> Self {
        self.charge = charge;
        self
    }

    /// Sets the air resistance: linear `b` (kg/s, F = −b v) and quadratic `c` (kg/m,
    /// F = −c |v| v).
    #[must_use]
    pub fn drag(mut self, b: f64, c: f64) -> Self {
        self.linear_drag = b;
        self.quadratic_drag = c;
        self
    }

    /// Makes it turn: the moment of inertia `inertia` × m r² (0.5 a solid disc, 1 a
    /// ring) and the spin, radians per second counter-clockwise.
    #[must_use]
    pub fn turning(mut self, inertia: f64, spin: f64) -> Self {
        self.inertia = inertia;
        self.spin = spin;
        self
    }

    /// Makes the particle fixed.
    #[must_use]
    pub fn fixed(mut self) -> Self {
        self.fixed = true;
        self
    }
}

/// One end of a spring.
#[derive(Clone, Debug, PartialEq)]
pub enum Endpoint {
    /// The particle with this name.
    Particle(String),
    /// A fixed point in the world, metres.
    Point(Vector),
}

impl From<&str> for Endpoint {
    fn from(name: &str) -> Self {
        Self::Particle(name.to_owned())
    }
}

impl From<[f64; 2]> for Endpoint {
    fn from(point: [f64; 2]) -> Self {
        Self::Point(point.into())
    }
}

/// A Hooke spring with damping along its axis: F = −k·(L − L0) − b·v∥ (the paper's 23–24).
#[derive(Clone, Debug, PartialEq)]
pub struct Spring {
    /// Unique among all objects of the scene.
    pub name: String,
    /// First end.
    pub from: Endpoint,
    /// Second end.
    pub to: Endpoint,
    /// k, newtons per metre, >= 0.
    pub stiffness: f64,
    /// L0, metres, >= 0.
    pub natural_length: f64,
    /// b, newton-seconds per metre, >= 0. Default 0.
    pub damping: f64,
}

impl Spring {
    /// An undamped spring between two ends.
    #[must_use]
    pub fn new(
        name: impl Into<String>,
        from: impl Into<Endpoint>,
        to: impl Into<Endpoint>,
        stiffness: f64,
        natural_length: f64,
    ) -> Self {
        Self {
            name: name.into(),
            from: from.into(),
            to: to.into(),
            stiffness,
            natural_length,
            damping: 0.0,
        }
    }

    /// Sets the damping, newton-seconds per metre.
    #[must_use]
    pub fn damping(mut self, damping: f64) -> Self {
        self.damping = damping;
        self
    }
}

/// A rigid rod or an inextensible string between two ends: a distance constraint,
/// enforced exactly (no stiffness, no stretch). A rod keeps its ends at its length; a
/// string keeps them at most that far apart and snaps taut with its restitution.
#[derive(Clone, Debug, PartialEq)]
pub struct Tie {
    /// Unique among all objects of the scene.
    pub name: String,
    /// A rod or a string.
    pub kind: TieKind,
    /// First end.
    pub from: Endpoint,
    /// Second end.
    pub to: Endpoint,
    /// Metres, > 0. A file that leaves it out gets the distance between the ends at the
    /// scene's start.
    pub length: f64,
    /// Strings only: the restitution when it snaps taut, 0..=1 (0: the ends stop moving
    /// apart, like a rope jerked tight). Default 0.
    pub restitution: f64,
}

impl Tie {
    /// A rod of `length` metres between two ends.
    #[must_use]
    pub fn rod(
        name: impl Into<String>,
        from: impl Into<Endpoint>,
        to: impl Into<Endpoint>,
        length: f64,
    ) -> Self {
        Self {
            name: name.into(),
            kind: TieKind::Rod,
            from: from.into(),
            to: to.into(),
            length,
            restitution: 0.0,
        }
    }

    /// A string of `length` metres between two ends, snapping taut inelastically.
    #[must_use]
    pub fn string(
        name: impl Into<String>,
        from: impl Into<Endpoint>,
        to: impl Into<Endpoint>,
        length: f64,
    ) -> Self {
        Self {
            kind: TieKind::String,
            ..Self::rod(name, from, to, length)
        }
    }

    /// Sets the restitution of a string snapping taut.
    #[must_use]
    pub fn restitution(mut self, restitution: f64) -> Self {
        self.restitution = restitution;
        self
    }
}

/// A solid ramp: every point within `thickness / 2` of the segment `from`–`to`.
#[derive(Clone, Debug, PartialEq)]
pub struct Ramp {
    /// Unique among all objects of the scene.
    pub name: String,
    /// One end of the segment, metres.
    pub from: Vector,
    /// The other end, metres.
    pub to: Vector,
    /// Metres, >= 0. Default 0.1.
    pub thickness: f64,
    /// Coefficient of restitution of impacts on the ramp, 0..=1. Default 1.
    pub restitution: f64,
    /// Coefficient of friction, kinetic (and static, unless [`Self::static_friction`]
    /// says otherwise), >= 0. Default 0.
    pub friction: f64,
    /// Coefficient of static friction for rigid bodies resting on it, >= `friction`;
    /// `None`: `friction`. (Particles hold and slide with `friction`.)
    pub static_friction: Option<f64>,
}

impl Ramp {
    /// A frictionless, perfectly elastic ramp 0.1 m thick.
    #[must_use]
    pub fn new(name: impl Into<String>, from: impl Into<Vector>, to: impl Into<Vector>) -> Self {
        Self {
            name: name.into(),
            from: from.into(),
            to: to.into(),
            thickness: Self::DEFAULT_THICKNESS,
            restitution: 1.0,
            friction: 0.0,
            static_friction: None,
        }
    }

    /// The thickness a ramp gets when the file does not say, metres.
    pub const DEFAULT_THICKNESS: f64 = 0.1;

    /// Sets the thickness, metres.
    #[must_use]
    pub fn thickness(mut self, thickness: f64) -> Self {
        self.thickness = thickness;
        self
    }

    /// Sets the restitution.
    #[must_use]
    pub fn restitution(mut self, restitution: f64) -> Self {
        self.restitution = restitution;
        self
    }

    /// Sets the friction coefficient.
    #[must_use]
    pub fn friction(mut self, friction: f64) -> Self {
        self.friction = friction;
        self
    }

    /// Its slope: the direction from `from` to `to`, degrees counter-clockwise from +x
    /// (0 for a ramp of no length).
    pub fn angle(&self) -> f64 {
        let d = self.to.to_dvec2() - self.from.to_dvec2();
        if d == DVec2::ZERO {
            0.0
        } else {
            d.y.atan2(d.x).to_degrees()
        }
    }

    /// The length of its segment, metres.
    pub fn length(&self) -> f64 {
        self.from.to_dvec2().distance(self.to.to_dvec2())
    }

    /// The end `to` that gives it `angle` (degrees from +x) and `length` from `from`, in
    /// the form `to` is written in (Cartesian or polar from the origin).
    pub fn end_for(&self, angle: f64, length: f64) -> Vector {
        let end = self.from.to_dvec2() + DVec2::from_angle(angle.to_radians()) * length;
        let end = Vector::cartesian(end.x, end.y);
        match self.to {
            Vector::Cartesian(_) => end,
            Vector::Polar { .. } => end.to_polar(),
        }
    }

    /// Where the centre of a disc of `radius` lies when it touches the ramp's upper face
    /// `along` metres from `from` along the segment: above the point by half the
    /// thickness and the radius, along the face's normal (the one pointing up; for a
    /// vertical ramp, the one pointing to −x).
    pub fn touching(&self, along: f64, radius: f64) -> DVec2 {
        let from = self.from.to_dvec2();
        let direction = (self.to.to_dvec2() - from)
            .try_normalize()
            .unwrap_or(DVec2::X);
        let mut normal = direction.perp();
        if normal.y < 0.0 || (normal.y == 0.0 && normal.x > 0.0) {
            normal = -normal;
        }
        from + direction * along + normal * (0.5 * self.thickness + radius)
    }
}

/// An axis-aligned reflecting box, metres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Lower-left corner.
    pub min: Vector,
    /// Upper-right corner.
    pub max: Vector,
    /// Coefficient of friction of the four walls, ≥ 0: a particle sliding along a wall
    /// feels μN against its motion, and a turning one is gripped at its contact point.
    /// Default 0.
    pub friction: f64,
    /// Coefficient of static friction of the walls for rigid bodies, >= `friction`;
    /// `None`: `friction`.
    pub static_friction: Option<f64>,
}

/// Fields and constants that apply to the whole scene.
#[derive(Clone, Debug, PartialEq)]
pub struct World {
    /// Uniform gravitational field, metres per second squared. Default `[0, -9.81]`.
    pub gravity: Vector,
    /// Whether particles attract each other by Newtonian gravitation. Default true.
    pub gravitation: bool,
    /// G, N·m²/kg². Default 6.6742e-11 (the paper's value).
    pub gravitational_constant: f64,
    /// Whether charged particles interact by Coulomb's law. Default true.
    pub electrostatics: bool,
    /// k, N·m²/C². Default 8.988e9.
    pub coulomb_constant: f64,
    /// Plummer softening length ε of both pair laws, metres: a pair at distance r
    /// pulls with G m₁ m₂ r/(r² + ε²)^{3/2} (likewise Coulomb), the force of two
    /// smeared-out bodies, so that close passes of point stars stay finite. Default 0
    /// (the exact inverse-square laws).
    pub softening: f64,
    /// The density of the air, kg/m³, ≥ 0: what a particle's `drag_coefficient` pushes
    /// against. Default 1.2 (air at 20 °C at sea level).
    pub air_density: f64,
    /// A uniform magnetic field `B_z`, tesla (out of the screen positive): a force
    /// q v × B on every moving charged particle, which turns it without working on it.
    /// Default 0.
    pub magnetic_field: f64,
    /// Whether particles strike and rest on each other. Default true; false lets them
    /// pass through each other (a star cluster's softened points), while ramps and the
    /// bounds still stop them.
    pub collisions: bool,
    /// Coefficient of restitution of particle–particle impacts, 0..=1. Default 1.
    pub restitution: f64,
    /// Coefficient of friction between particles, ≥ 0: at an impact between two turning
    /// particles the tangential impulse grips their contact points (Coulomb: sticking
    /// within μ times the normal impulse, sliding beyond). Default 0.
    pub friction: f64,
    /// An optional reflecting box.
    pub bounds: Option<Bounds>,
}

impl World {
    /// The paper's gravitational constant, N·m²/kg².
    pub const DEFAULT_GRAVITATIONAL_CONSTANT: f64 = 6.6742e-11;
    /// The paper's Coulomb constant, N·m²/C².
    pub const DEFAULT_COULOMB_CONSTANT: f64 = 8.988e9;
    /// Air at 20 °C and sea level, kg/m³.
    pub const DEFAULT_AIR_DENSITY: f64 = 1.2;

    /// A world with no uniform field and everything else at its default.
    #[must_use]
    pub fn weightless() -> Self {
        Self {
            gravity: Vector::ZERO,
            ..Self::default()
        }
    }

    /// The uniform field of the default world (g = 9.81 m/s² down) and no pair forces:
    /// a classroom's world, where bodies fall and nothing attracts.
    #[must_use]
    pub fn gravity_only() -> Self {
        Self {
            gravitation: false,
            electrostatics: false,
            ..Self::default()
        }
    }

    /// No uniform field and no pair forces: bodies move only as springs, ties, contacts
    /// and their own applied accelerations make them.
    #[must_use]
    pub fn no_forces() -> Self {
        Self {
            gravity: Vector::ZERO,
            ..Self::gravity_only()
        }
    }
}

impl Default for World {
    fn default() -> Self {
        Self {
            gravity: Vector::cartesian(0.0, -9.81),
            gravitation: true,
            gravitational_constant: Self::DEFAULT_GRAVITATIONAL_CONSTANT,
            electrostatics: true,
            coulomb_constant: Self::DEFAULT_COULOMB_CONSTANT,
            softening: 0.0,
            air_density: Self::DEFAULT_AIR_DENSITY,
            magnetic_field: 0.0,
            collisions: true,
            restitution: 1.0,
            friction: 0.0,
            bounds: None,
        }
    }
}

/// How pairwise gravitation is summed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum PairForces {
    /// Every pair, exactly: O(n²).
    #[default]
    Direct,
    /// A Barnes–Hut quadtree: distant groups act through their total mass at their
    /// centre of mass, O(n log n), with the error set by the opening angle. Coulomb
    /// forces (charges of both signs, which a group's total does not represent) stay
    /// direct.
    Tree,
}

impl PairForces {
    /// Both modes.
    pub const ALL: [Self; 2] = [Self::Direct, Self::Tree];

    /// The scene-file name: `direct` or `tree`.
    pub const fn as_str(self) -> &'static str {
        match self {
            Self::Direct => "direct",
            Self::Tree => "tree",
        }
    }
}

/// How the scene is integrated and played back.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// Default [`crate::Integrator::Rk4`].
    pub integrator: crate::Integrator,
    /// Seconds; for `dopri5` the largest step. Default 0.001.
    pub time_step: f64,
    /// `dopri5` only: relative and absolute error per step. Default 1e-9.
    pub tolerance: f64,
    /// App playback: simulated seconds per real second. Default 1.
    pub time_scale: f64,
    /// Seconds: the instant the scene's state describes. Default 0; a state saved at
    /// time T keeps T, so a run from it continues the clock.
    pub start_time: f64,
    /// How pairwise gravitation is summed. Default direct.
    pub pair_forces: PairForces,
    /// The tree's opening angle θ: a group of size s at distance d acts as one body
    /// when s/d < θ. Default 0.5.
    pub opening_angle: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            integrator: crate::Integrator::Rk4,
            time_step: 0.001,
            tolerance: 1e-9,
            time_scale: 1.0,
            start_time: 0.0,
            pair_forces: PairForces::Direct,
            opening_angle: 0.5,
        }
    }
}

/// A whole scene: what a scene file holds.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Scene {
    /// A title, optional.
    pub name: Option<String>,
    /// A longer description, optional.
    pub description: Option<String>,
    /// Fields and constants.
    pub world: World,
    /// Integration and playback.
    pub simulation: Settings,
    /// In file order; CSV columns follow this order.
    pub particles: Vec<Particle>,
    /// In file order.
    pub springs: Vec<Spring>,
    /// Rods and strings: the rods in file order, then the strings in file order.
    pub ties: Vec<Tie>,
    /// In file order.
    pub ramps: Vec<Ramp>,
    /// Rigid bodies, in file order; CSV columns follow the particles' in this order.
    pub bodies: Vec<Body>,
    /// Pins and hinges: the pins in file order, then the hinges in file order; CSV
    /// columns follow the bodies' in this order.
    pub joints: Vec<Joint>,
    /// Forces of one's own (`[[force]]`), in file order.
    pub forces: Vec<Force>,
    /// The app's graphs when the scene opens (`[[graph]]`), in file order.
    pub graphs: Vec<Graph>,
    /// The app's experiment series (`[[series]]`), in file order.
    pub series: Vec<Series>,
    /// The app's framing when the scene opens (`[view]`).
    pub view: Option<View>,
    /// What the scene teaches (`[lesson]`).
    pub lesson: Option<Lesson>,
    /// The app's measuring instruments where the scene was saved (`[instruments]`).
    pub instruments: Option<Instruments>,
}

impl Scene {
    /// An empty scene with the default world.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Replaces the world.
    #[must_use]
    pub fn with_world(mut self, world: World) -> Self {
        self.world = world;
        self
    }

    /// Replaces the integration settings.
    #[must_use]
    pub fn with_settings(mut self, settings: Settings) -> Self {
        self.simulation = settings;
        self
    }

    /// Sets the integrator and the time step (seconds).
    #[must_use]
    pub fn with_integrator(mut self, integrator: crate::Integrator, time_step: f64) -> Self {
        self.simulation.integrator = integrator;
        self.simulation.time_step = time_step;
        self
    }

    /// Adds a particle.
    #[must_use]
    pub fn with_particle(mut self, particle: Particle) -> Self {
        self.particles.push(particle);
        self
    }

    /// Adds a spring.
    #[must_use]
    pub fn with_spring(mut self, spring: Spring) -> Self {
        self.springs.push(spring);
        self
    }

    /// Adds a rod or a string.
    #[must_use]
    pub fn with_tie(mut self, tie: Tie) -> Self {
        self.ties.push(tie);
        self
    }

    /// Adds a ramp.
    #[must_use]
    pub fn with_ramp(mut self, ramp: Ramp) -> Self {
        self.ramps.push(ramp);
        self
    }

    /// Adds a rigid body.
    #[must_use]
    pub fn with_body(mut self, body: Body) -> Self {
        self.bodies.push(body);
        self
    }

    /// Adds a force of one's own.
    #[must_use]
    pub fn with_force(mut self, force: Force) -> Self {
        self.forces.push(force);
        self
    }

    /// Adds a pin or a hinge.
    #[must_use]
    pub fn with_joint(mut self, joint: Joint) -> Self {
        self.joints.push(joint);
        self
    }

    /// The index of the particle with this name.
    pub fn particle_index(&self, name: &str) -> Option<usize> {
        self.particles.iter().position(|p| p.name == name)
    }

    /// Every particle's index by name, the first of a repeated name (as
    /// [`Self::particle_index`] finds it): for looking up many names at once, where a
    /// search each would cost springs × particles comparisons.
    pub fn particle_indices(&self) -> std::collections::HashMap<&str, usize> {
        let mut indices = std::collections::HashMap::with_capacity(self.particles.len());
        for (i, particle) in self.particles.iter().enumerate() {
            indices.entry(particle.name.as_str()).or_insert(i);
        }
        indices
    }

    /// Where an end is at the scene's start, metres; `None` for a particle that does
    /// not exist.
    pub fn end_position(&self, end: &Endpoint) -> Option<DVec2> {
        match end {
            Endpoint::Particle(name) => self
                .particle_index(name)
                .map(|i| self.particles[i].position.to_dvec2()),
            Endpoint::Point(point) => Some(point.to_dvec2()),
        }
    }

    /// The distance between two ends at the scene's start, metres.
    pub fn distance(&self, from: &Endpoint, to: &Endpoint) -> Option<f64> {
        Some(self.end_position(from)?.distance(self.end_position(to)?))
    }

    /// The particles' names, in file order.
    pub fn particle_names(&self) -> Vec<String> {
        self.particles.iter().map(|p| p.name.clone()).collect()
    }
}

/// [`say`] with numbers for `$a`, `$b`, `$c`, `$d`, written as Rust writes them.
pub(crate) fn say_numbers(id: &str, numbers: &[f64]) -> String {
    let written: Vec<String> = numbers.iter().map(ToString::to_string).collect();
    let args: Vec<(&str, &str)> = ["a", "b", "c", "d"]
        .into_iter()
        .zip(&written)
        .map(|(name, text)| (name, text.as_str()))
        .collect();
    say(id, &args)
}
