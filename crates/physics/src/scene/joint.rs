//! Pins and hinges (`[[pin]]`, `[[hinge]]`): a body held to the world at a point, or two
//! bodies sharing one, each turning freely about it unless a motor drives it.

use glam::DVec2;

use super::Vector;

/// What drives a joint's turning.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motor {
    /// A constant torque, N·m, counter-clockwise on the body (a hinge's `b`; `a` feels the
    /// opposite): `motor = { torque = 2.0 }`.
    Torque(f64),
    /// A target spin, rad/s (a hinge's `b` relative to `a`), reached and held with at most
    /// `max_torque` N·m: `motor = { spin = 2.0, max_torque = 5.0 }`.
    Spin {
        /// rad/s, counter-clockwise.
        spin: f64,
        /// N·m, > 0.
        max_torque: f64,
    },
}

/// Which kind of joint, with what it holds the body to.
#[derive(Clone, Debug, PartialEq)]
pub enum JointKind {
    /// `[[pin]]`: the body is held to the world at [`Joint::at`].
    Pin,
    /// `[[hinge]]`: the body [`Joint::body`] (the file's `b`) shares a point with `a`.
    Hinge {
        /// The other body's name (the file's `a`).
        a: String,
        /// The shared point in `a`'s frame, metres: where `at` is on `a` at the start when
        /// left out (a saved state writes it, so that continuing is exact).
        anchor_a: Option<DVec2>,
    },
    /// `[[pulley]]`: an ideal string from `a` over a wheel centred at [`Joint::at`] (the
    /// file's `position`) to [`Joint::body`] (the file's `b`), each end at a centroid.
    Pulley {
        /// The body on the string's other end (the file's `a`).
        a: String,
        /// The wheel's radius, m, > 0.
        radius: f64,
        /// The wheel's mass, kg, ≥ 0: 0 is a massless, frictionless wheel.
        mass: f64,
        /// The wheel's I/(m r²): 0.5 for a disc.
        inertia: f64,
        /// The wheel's spin, rad/s counter-clockwise (what a saved state continues from).
        spin: f64,
        /// The string's length, m; the start's when left out.
        length: Option<f64>,
    },
}

/// A pin or a hinge.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// Unique among all objects of the scene; default `pin1`, `hinge1`, …
    pub name: String,
    /// A pin or a hinge, with a hinge's other body.
    pub kind: JointKind,
    /// The body held (a pin's `body`, a hinge's `b`).
    pub body: String,
    /// The joint's point in the world at the start, metres.
    pub at: Vector,
    /// The point in [`Self::body`]'s frame, metres: `at` seen from the body at the start
    /// when left out.
    pub anchor: Option<DVec2>,
    /// What drives it, if anything.
    pub motor: Option<Motor>,
    /// Degrees: the body's angle (a hinge's: b's less a's) at which the joint's `angle`
    /// reads 0; the start's when left out.
    pub reference_angle: Option<f64>,
    /// The least and the most the joint's `angle` may be, degrees: it stops dead at
    /// either (a seesaw's board on the ground). `None`: it turns freely.
    pub limits: Option<(f64, f64)>,
}

impl Joint {
    /// A pin holding `body` to the world at `at`, with no motor.
    #[must_use]
    pub fn pin(name: impl Into<String>, body: impl Into<String>, at: impl Into<Vector>) -> Self {
        Self {
            name: name.into(),
            kind: JointKind::Pin,
            body: body.into(),
            at: at.into(),
            anchor: None,
            motor: None,
            reference_angle: None,
            limits: None,
        }
    }

    /// A hinge joining `b` to `a` at `at`, with no motor.
    #[must_use]
    pub fn hinge(
        name: impl Into<String>,
        a: impl Into<String>,
        b: impl Into<String>,
        at: impl Into<Vector>,
    ) -> Self {
        Self {
            kind: JointKind::Hinge {
                a: a.into(),
                anchor_a: None,
            },
            ..Self::pin(name, b, at)
        }
    }

    /// The same joint driven by `motor`.
    #[must_use]
    pub fn motor(mut self, motor: Motor) -> Self {
        self.motor = Some(motor);
        self
    }

    /// The same joint turning only between `lower` and `upper` degrees of its angle.
    #[must_use]
    pub fn limits(mut self, lower: f64, upper: f64) -> Self {
        self.limits = Some((lower, upper));
        self
    }

    /// A pulley: a string from `a` over a wheel of `radius` m at `position` to `b`, the
    /// wheel of `mass` kg a disc (I = m r²/2).
    #[must_use]
    pub fn pulley(
        name: impl Into<String>,
        (a, b): (impl Into<String>, impl Into<String>),
        position: impl Into<Vector>,
        radius: f64,
        mass: f64,
    ) -> Self {
        Self {
            kind: JointKind::Pulley {
                a: a.into(),
                radius,
                mass,
                inertia: 0.5,
                spin: 0.0,
                length: None,
            },
            ..Self::pin(name, b, position)
        }
    }

    /// `pin`, `hinge` or `pulley`, as a scene file writes the table.
    pub const fn kind_str(&self) -> &'static str {
        match self.kind {
            JointKind::Pin => "pin",
            JointKind::Hinge { .. } => "hinge",
            JointKind::Pulley { .. } => "pulley",
        }
    }

    /// The other body of a hinge or a pulley (its `a`); `None` for a pin.
    pub fn other(&self) -> Option<&str> {
        match &self.kind {
            JointKind::Pin => None,
            JointKind::Hinge { a, .. } | JointKind::Pulley { a, .. } => Some(a),
        }
    }

    /// A pulley wheel's moment of inertia about its axle, kg·m² (m · inertia · r²); 0 for
    /// a massless wheel and for a pin or a hinge.
    pub fn wheel_inertia(&self) -> f64 {
        match self.kind {
            JointKind::Pulley {
                radius,
                mass,
                inertia,
                ..
            } => mass * inertia * radius * radius,
            _ => 0.0,
        }
    }

    /// Whether it is a pulley.
    pub const fn is_pulley(&self) -> bool {
        matches!(self.kind, JointKind::Pulley { .. })
    }
}

/// `at` as seen from a body whose centroid is at `position`, turned `angle` degrees: the
/// point in its frame.
pub(crate) fn in_frame(at: DVec2, position: DVec2, angle: f64) -> DVec2 {
    DVec2::from_angle(-angle.to_radians()).rotate(at - position)
}
