//! The quantities a run can be asked for, by the names of `run`'s CSV columns: what
//! graphs plot, events watch and measures read (`docs/cli.md`, "Quantities"). A
//! [`Quantity`] names its object; [`Quantity::reading`] finds the object in a simulation
//! once, and [`crate::Simulation::read`] then reads the value at any state.

mod event;

use std::fmt;

use glam::DVec2;

pub use event::{Direction, Event, Turn};

/// A quantity of one particle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Of {
    /// Position, x.
    X,
    /// Position, y.
    Y,
    /// Velocity, x.
    Vx,
    /// Velocity, y.
    Vy,
    /// |v|.
    Speed,
    /// Acceleration by the smooth forces, x.
    Ax,
    /// Acceleration by the smooth forces, y.
    Ay,
    /// ½ m v² + ½ I ω².
    KineticEnergy,
    /// A turning particle's orientation, degrees counter-clockwise, unwrapped.
    Angle,
    /// A turning particle's spin ω, radians per second counter-clockwise.
    Spin,
    /// m x × v + I ω about the origin.
    AngularMomentum,
}

impl Of {
    /// Every particle quantity, in menu order.
    pub const ALL: [Self; 11] = [
        Self::X,
        Self::Y,
        Self::Vx,
        Self::Vy,
        Self::Speed,
        Self::Ax,
        Self::Ay,
        Self::KineticEnergy,
        Self::Angle,
        Self::Spin,
        Self::AngularMomentum,
    ];

    /// Whether it is offered only for scenes with a turning particle: the angle and the
    /// spin (0 for a point), and the angular momentum.
    pub fn turns(self) -> bool {
        matches!(self, Self::Angle | Self::Spin | Self::AngularMomentum)
    }

    /// The key after the dot in `A.vx`.
    pub fn key(self) -> &'static str {
        match self {
            Self::X => "x",
            Self::Y => "y",
            Self::Vx => "vx",
            Self::Vy => "vy",
            Self::Speed => "speed",
            Self::Ax => "ax",
            Self::Ay => "ay",
            Self::KineticEnergy => "kinetic_energy",
            Self::Angle => "angle",
            Self::Spin => "spin",
            Self::AngularMomentum => "angular_momentum",
        }
    }

    /// The SI unit (degrees for the angle, as the scene file writes angles).
    pub fn unit(self) -> &'static str {
        match self {
            Self::X | Self::Y => "m",
            Self::Vx | Self::Vy | Self::Speed => "m/s",
            Self::Ax | Self::Ay => "m/s²",
            Self::KineticEnergy => "J",
            Self::Angle => "°",
            Self::Spin => "rad/s",
            Self::AngularMomentum => "kg·m²/s",
        }
    }
}

/// A quantity of a rod, string or spring: of the line from its `from` end to its `to` end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LinkOf {
    /// The force a rod or string carries, N (pulling positive; 0 for a slack string).
    Tension,
    /// Degrees from the downward vertical, counter-clockwise positive, in (−180, 180]: a
    /// pendulum's angle when the link runs from the pivot to the bob.
    Angle,
    /// The distance between the ends, m.
    Length,
}

impl LinkOf {
    /// Every link quantity, in menu order.
    pub const ALL: [Self; 3] = [Self::Angle, Self::Length, Self::Tension];

    /// The key after the dot in `rod.angle`.
    pub fn key(self) -> &'static str {
        match self {
            Self::Tension => "tension",
            Self::Angle => "angle",
            Self::Length => "length",
        }
    }

    /// The SI unit (degrees for the angle, as the scene file writes angles).
    pub fn unit(self) -> &'static str {
        match self {
            Self::Tension => "N",
            Self::Angle => "°",
            Self::Length => "m",
        }
    }
}

/// A quantity of a pin or a hinge.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum JointOf {
    /// The body's turn (a hinge's b less a) from the joint's reference, degrees,
    /// unwrapped (written `NAME.angle`, as a link's).
    Angle,
    /// The joint's force on the body it holds (a hinge's b), x, N.
    ForceX,
    /// The same, y.
    ForceY,
    /// The motor's torque on the body, N·m.
    Torque,
    /// A pulley's string tension on a's side, N.
    TensionA,
    /// A pulley's string tension on b's side, N.
    TensionB,
}

impl JointOf {
    /// The joint quantities other than the angle (which `NAME.angle` reads), by key.
    pub const FORCES: [Self; 5] = [
        Self::ForceX,
        Self::ForceY,
        Self::Torque,
        Self::TensionA,
        Self::TensionB,
    ];

    /// The key after the dot in `pin.force_x`.
    pub fn key(self) -> &'static str {
        match self {
            Self::Angle => "angle",
            Self::ForceX => "force_x",
            Self::ForceY => "force_y",
            Self::Torque => "torque",
            Self::TensionA => "tension_a",
            Self::TensionB => "tension_b",
        }
    }

    /// The SI unit (degrees for the angle).
    pub fn unit(self) -> &'static str {
        match self {
            Self::Angle => "°",
            Self::ForceX | Self::ForceY | Self::TensionA | Self::TensionB => "N",
            Self::Torque => "N·m",
        }
    }
}

/// A quantity of the whole system.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Total {
    /// Σ ½ m v².
    KineticEnergy,
    /// Every potential energy together.
    PotentialEnergy,
    /// Kinetic plus potential.
    TotalEnergy,
    /// Σ m vₓ of the moving particles.
    MomentumX,
    /// Σ m `v_y` of the moving particles.
    MomentumY,
    /// Σ m x × v + I ω of the moving particles, about the origin.
    AngularMomentum,
}

impl Total {
    /// Every system quantity, in menu order.
    pub const ALL: [Self; 6] = [
        Self::KineticEnergy,
        Self::PotentialEnergy,
        Self::TotalEnergy,
        Self::MomentumX,
        Self::MomentumY,
        Self::AngularMomentum,
    ];

    /// As written in a scene file.
    pub fn key(self) -> &'static str {
        match self {
            Self::KineticEnergy => "kinetic_energy",
            Self::PotentialEnergy => "potential_energy",
            Self::TotalEnergy => "total_energy",
            Self::MomentumX => "momentum_x",
            Self::MomentumY => "momentum_y",
            Self::AngularMomentum => "angular_momentum",
        }
    }

    /// The SI unit.
    pub fn unit(self) -> &'static str {
        match self {
            Self::KineticEnergy | Self::PotentialEnergy | Self::TotalEnergy => "J",
            Self::MomentumX | Self::MomentumY => "kg·m/s",
            Self::AngularMomentum => "kg·m²/s",
        }
    }
}

/// A quantity, with its object named.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Simulated time, `t`.
    Time,
    /// `NAME.of`.
    Particle(String, Of),
    /// A system quantity.
    Total(Total),
    /// `NAME.tension`, `NAME.angle`, `NAME.length` of a rod, string or spring (and
    /// `NAME.angle` of a joint, a turning particle or a body).
    Link(String, LinkOf),
    /// `NAME.force_x`, `NAME.force_y`, `NAME.torque` of a pin or a hinge.
    Joint(String, JointOf),
}

impl Quantity {
    /// Reads `t`, `NAME.x|y|vx|vy|speed|ax|ay|kinetic_energy`, `LINK.angle|length|tension`,
    /// `kinetic_energy`, `potential_energy`, `total_energy`, `momentum_x` or `momentum_y`.
    /// Whether the object exists is the scene's question ([`crate::Scene::validate`]) or
    /// the simulation's ([`Self::reading`]).
    ///
    /// # Errors
    /// What the text should have been.
    pub fn parse(text: &str) -> Result<Self, String> {
        // `time` as well as `t`: a lesson's question reads "time at EVENT" as people say it.
        if text == "t" || text == "time" {
            return Ok(Self::Time);
        }
        if let Some(total) = Total::ALL.into_iter().find(|t| t.key() == text) {
            return Ok(Self::Total(total));
        }
        if let Some((name, key)) = text.rsplit_once('.')
            && !name.is_empty()
        {
            if let Some(of) = LinkOf::ALL.into_iter().find(|of| of.key() == key) {
                return Ok(Self::Link(name.to_owned(), of));
            }
            if let Some(of) = JointOf::FORCES.into_iter().find(|of| of.key() == key) {
                return Ok(Self::Joint(name.to_owned(), of));
            }
            return match Of::ALL.into_iter().find(|of| of.key() == key) {
                Some(of) => Ok(Self::Particle(name.to_owned(), of)),
                None => Err(newtonlab_i18n::tr_text(
                    "scene-quantity-of-particle",
                    &[("text", text), ("keys", &Of::ALL.map(Of::key).join(", "))],
                )),
            };
        }
        Err(newtonlab_i18n::tr_text(
            "scene-not-a-quantity",
            &[
                ("text", text),
                ("keys", &Total::ALL.map(Total::key).join(", ")),
            ],
        ))
    }

    /// The unit, `s` for time.
    pub fn unit(&self) -> &'static str {
        match self {
            Self::Time => "s",
            Self::Particle(_, of) => of.unit(),
            Self::Total(total) => total.unit(),
            Self::Link(_, of) => of.unit(),
            Self::Joint(_, of) => of.unit(),
        }
    }

    /// [`Self::reading`] among the objects of these names, in the simulation's order.
    pub(crate) fn find(&self, names: &Names<'_>) -> Result<Reading, String> {
        let Names {
            particles,
            ties,
            springs,
            bodies,
            joints,
            pulleys,
        } = *names;
        let find = |names: &[String], name: &str| names.iter().position(|n| n == name);
        match self {
            Self::Time => Ok(Reading::Time),
            Self::Total(total) => Ok(Reading::Total(*total)),
            Self::Particle(name, of) => find(particles, name)
                .map(|i| Reading::Particle(i, *of))
                .or_else(|| find(bodies, name).map(|i| Reading::Body(i, *of)))
                .ok_or_else(|| {
                    let both: Vec<String> = particles.iter().chain(bodies).cloned().collect();
                    unknown("quantity-no-particle", self, name, &both)
                }),
            Self::Link(name, of) => {
                if let Some(k) = find(ties, name) {
                    return Ok(Reading::Link(Link::Tie(k), *of));
                }
                if *of == LinkOf::Angle
                    && let Some(j) = find(joints, name)
                {
                    if find(pulleys, name).is_some() {
                        return Err(unknown("quantity-no-link", self, name, ties));
                    }
                    return Ok(Reading::Joint(j, JointOf::Angle));
                }
                // `NAME.angle` of a particle or a body: a turning particle's orientation,
                // a body's.
                if *of == LinkOf::Angle && find(springs, name).is_none() {
                    if let Some(i) = find(particles, name) {
                        return Ok(Reading::Particle(i, Of::Angle));
                    }
                    if let Some(i) = find(bodies, name) {
                        return Ok(Reading::Body(i, Of::Angle));
                    }
                }
                match (find(springs, name), of) {
                    (Some(_), LinkOf::Tension) => Err(newtonlab_i18n::tr_text(
                        "quantity-spring-tension",
                        &[("text", &self.to_string()), ("name", name)],
                    )),
                    (Some(k), _) => Ok(Reading::Link(Link::Spring(k), *of)),
                    (None, _) => {
                        let links: Vec<String> = ties.iter().chain(springs).cloned().collect();
                        Err(unknown("quantity-no-link", self, name, &links))
                    }
                }
            }
            Self::Joint(name, of @ (JointOf::TensionA | JointOf::TensionB)) => find(joints, name)
                .filter(|_| find(pulleys, name).is_some())
                .map(|j| Reading::Joint(j, *of))
                .ok_or_else(|| unknown("quantity-no-pulley", self, name, pulleys)),
            Self::Joint(name, of) => find(joints, name)
                .map(|j| Reading::Joint(j, *of))
                .ok_or_else(|| unknown("quantity-no-joint", self, name, joints)),
        }
    }
}

/// The objects' names of a scene or a simulation, by kind, in scene order.
#[derive(Clone, Copy)]
pub(crate) struct Names<'a> {
    pub particles: &'a [String],
    pub ties: &'a [String],
    pub springs: &'a [String],
    pub bodies: &'a [String],
    pub joints: &'a [String],
    pub pulleys: &'a [String],
}

/// That `quantity` names `name`, which is not among `names`.
fn unknown(message: &str, quantity: &Quantity, name: &str, names: &[String]) -> String {
    let there = if names.is_empty() {
        "—".to_owned()
    } else {
        names.join(", ")
    };
    newtonlab_i18n::tr_text(
        message,
        &[
            ("text", &quantity.to_string()),
            ("name", name),
            ("names", &there),
        ],
    )
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Time => f.write_str("t"),
            Self::Particle(name, of) => write!(f, "{name}.{}", of.key()),
            Self::Total(total) => f.write_str(total.key()),
            Self::Link(name, of) => write!(f, "{name}.{}", of.key()),
            Self::Joint(name, of) => write!(f, "{name}.{}", of.key()),
        }
    }
}

/// A rod or string, or a spring, by its index in the scene's ties or springs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Link {
    /// The rod or string at this index of the scene's ties.
    Tie(usize),
    /// The spring at this index of the scene's springs.
    Spring(usize),
}

/// One end of a rod, string or spring.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Anchor {
    /// The particle at this index.
    Particle(usize),
    /// A fixed point, metres.
    Point(DVec2),
}

impl Anchor {
    /// Where the end is when the particles are at `x`.
    pub fn position(self, x: &[DVec2]) -> DVec2 {
        match self {
            Self::Particle(i) => x[i],
            Self::Point(p) => p,
        }
    }
}

/// A [`Quantity`] with its object found in a simulation ([`Quantity::reading`]), or a
/// particle's side of a line (a light gate's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reading {
    /// Simulated time.
    Time,
    /// A quantity of the particle at this index.
    Particle(usize, Of),
    /// A quantity of the rigid body at this index (of its centroid, for position,
    /// velocity and acceleration).
    Body(usize, Of),
    /// A quantity of the whole system.
    Total(Total),
    /// A quantity of a rod, string or spring.
    Link(Link, LinkOf),
    /// A quantity of the pin or hinge at this index.
    Joint(usize, JointOf),
    /// How far the particle at this index is past the line through `point` along its unit
    /// `normal`, metres: it crosses 0 where the particle's centre crosses the line.
    Side {
        /// The particle's index.
        particle: usize,
        /// A point of the line.
        point: DVec2,
        /// The line's unit normal: the positive side.
        normal: DVec2,
    },
}

impl Reading {
    /// The reading whose value is this one's rate of change, where the simulation has one
    /// that is exactly that: a position's velocity. (An acceleration read by
    /// [`crate::Simulation::read`] is the smooth forces' and leaves out a rod's pull, so a
    /// velocity has none here.)
    pub fn rate(self) -> Option<Self> {
        match self {
            Self::Particle(i, Of::X) => Some(Self::Particle(i, Of::Vx)),
            Self::Particle(i, Of::Y) => Some(Self::Particle(i, Of::Vy)),
            _ => None,
        }
    }
}

/// The angle of `d` from the downward vertical, counter-clockwise positive, degrees in
/// (−180, 180]: [`LinkOf::Angle`] of a link whose ends are `d` apart.
pub fn angle_from_down(d: DVec2) -> f64 {
    d.x.atan2(-d.y).to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantities_read_back_as_written() {
        for text in [
            "t",
            "A.x",
            "ball 2.vy",
            "B.kinetic_energy",
            "total_energy",
            "momentum_y",
            "rod.angle",
            "s 1.length",
            "string.tension",
            "pin.force_x",
            "hinge 2.torque",
        ] {
            let quantity = Quantity::parse(text).unwrap();
            assert_eq!(quantity.to_string(), text);
        }
        assert_eq!(
            Quantity::parse("a.b.speed"),
            Ok(Quantity::Particle("a.b".to_owned(), Of::Speed)),
            "the last dot splits"
        );
        for bad in ["", "x", "A.z", ".x", "energy"] {
            assert!(Quantity::parse(bad).is_err(), "{bad:?} refused");
        }
    }

    /// The angle from the downward vertical, counter-clockwise: straight down 0°, to the
    /// right 90° (the downward vertical turned a quarter counter-clockwise), to the left
    /// −90°, straight up 180°.
    #[test]
    fn angles_are_from_the_downward_vertical_counter_clockwise() {
        for (d, expected) in [
            (DVec2::new(0.0, -1.0), 0.0),
            (DVec2::new(1.0, 0.0), 90.0),
            (DVec2::new(-1.0, 0.0), -90.0),
            (DVec2::new(0.0, 1.0), 180.0),
            (DVec2::new(1.0, -1.0), 45.0),
        ] {
            let angle = angle_from_down(d);
            assert!((angle - expected).abs() < 1e-12, "{d}: {angle}°");
        }
    }
}
