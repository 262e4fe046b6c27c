//! What the app shows when a scene opens: its graphs (`[[graph]]`) and its framing
//! (`[view]`). The simulation never reads them; they are part of the scene so that an
//! example opens with the graphs that teach it and a saved scene reopens as it was left.
//! `check` validates them like everything else: a graph naming a particle that does not
//! exist is an error with its line and column.

use std::fmt;

use glam::DVec2;

use super::Scene;

/// A graph: quantities against time, or against another quantity (a phase plot).
#[derive(Clone, Debug, PartialEq)]
pub struct Graph {
    /// A heading, optional.
    pub title: Option<String>,
    /// The horizontal axis: `"t"` or a quantity (see [`Quantity::parse`]).
    pub x: String,
    /// The plotted quantities, one series each.
    pub y: Vec<String>,
}

impl Graph {
    /// `y` against time.
    pub fn against_time(y: impl IntoIterator<Item = impl Into<String>>) -> Self {
        Self {
            title: None,
            x: "t".to_owned(),
            y: y.into_iter().map(Into::into).collect(),
        }
    }
}

/// How the app frames the scene when it opens.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct View {
    /// The world point at the canvas's centre, metres; default: the scene's centre.
    pub center: Option<DVec2>,
    /// Metres visible across the canvas; default: whatever fits the scene.
    pub width: Option<f64>,
    /// A particle to follow, or every particle.
    pub follow: Option<Follow>,
}

/// What the camera keeps in view while the scene plays.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Follow {
    /// The particle of this name, kept at the centre.
    Particle(String),
    /// Every particle (`"all"`).
    All,
}

impl Follow {
    /// As written in a scene file.
    pub fn as_str(&self) -> &str {
        match self {
            Self::Particle(name) => name,
            Self::All => "all",
        }
    }

    /// From a scene file's text: `"all"`, or a particle's name.
    pub fn parse(text: &str) -> Self {
        if text == "all" {
            Self::All
        } else {
            Self::Particle(text.to_owned())
        }
    }
}

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
    /// ½ m v².
    KineticEnergy,
}

impl Of {
    /// Every particle quantity, in menu order.
    pub const ALL: [Self; 8] = [
        Self::X,
        Self::Y,
        Self::Vx,
        Self::Vy,
        Self::Speed,
        Self::Ax,
        Self::Ay,
        Self::KineticEnergy,
    ];

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
        }
    }

    /// The SI unit.
    pub fn unit(self) -> &'static str {
        match self {
            Self::X | Self::Y => "m",
            Self::Vx | Self::Vy | Self::Speed => "m/s",
            Self::Ax | Self::Ay => "m/s²",
            Self::KineticEnergy => "J",
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
}

impl Total {
    /// Every system quantity, in menu order.
    pub const ALL: [Self; 5] = [
        Self::KineticEnergy,
        Self::PotentialEnergy,
        Self::TotalEnergy,
        Self::MomentumX,
        Self::MomentumY,
    ];

    /// As written in a scene file.
    pub fn key(self) -> &'static str {
        match self {
            Self::KineticEnergy => "kinetic_energy",
            Self::PotentialEnergy => "potential_energy",
            Self::TotalEnergy => "total_energy",
            Self::MomentumX => "momentum_x",
            Self::MomentumY => "momentum_y",
        }
    }

    /// The SI unit.
    pub fn unit(self) -> &'static str {
        match self {
            Self::KineticEnergy | Self::PotentialEnergy | Self::TotalEnergy => "J",
            Self::MomentumX | Self::MomentumY => "kg·m/s",
        }
    }
}

/// Something a graph can plot, with the particle named.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Simulated time, `t`.
    Time,
    /// `NAME.of`.
    Particle(String, Of),
    /// A system quantity.
    Total(Total),
    /// `NAME.tension`: the force a rod or string carries, N (pulling positive).
    Tension(String),
}

impl Quantity {
    /// Reads `t`, `NAME.x|y|vx|vy|speed|ax|ay|kinetic_energy`, `ROD.tension`, `kinetic_energy`,
    /// `potential_energy`, `total_energy`, `momentum_x` or `momentum_y`. Whether the
    /// particle exists is the scene's question ([`Scene::validate`]).
    ///
    /// # Errors
    /// What the text should have been.
    pub fn parse(text: &str) -> Result<Self, String> {
        if text == "t" {
            return Ok(Self::Time);
        }
        if let Some(total) = Total::ALL.into_iter().find(|t| t.key() == text) {
            return Ok(Self::Total(total));
        }
        if let Some((name, key)) = text.rsplit_once('.')
            && !name.is_empty()
        {
            if key == "tension" {
                return Ok(Self::Tension(name.to_owned()));
            }
            return match Of::ALL.into_iter().find(|of| of.key() == key) {
                Some(of) => Ok(Self::Particle(name.to_owned(), of)),
                None => Err(crate::scene::say(
                    "scene-quantity-of-particle",
                    &[("text", text), ("keys", &Of::ALL.map(Of::key).join(", "))],
                )),
            };
        }
        Err(crate::scene::say(
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
            Self::Tension(_) => "N",
        }
    }
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Time => f.write_str("t"),
            Self::Particle(name, of) => write!(f, "{name}.{}", of.key()),
            Self::Total(total) => f.write_str(total.key()),
            Self::Tension(name) => write!(f, "{name}.tension"),
        }
    }
}

impl Scene {
    /// Renames every reference to the particle, rod or string `old` in the graphs and the
    /// view, as renaming a particle does for its springs.
    pub(super) fn rename_in_presentation(&mut self, old: &str, new: &str) {
        let rename = |text: &mut String| match Quantity::parse(text) {
            Ok(Quantity::Particle(name, of)) if name == old => {
                *text = Quantity::Particle(new.to_owned(), of).to_string();
            }
            Ok(Quantity::Tension(name)) if name == old => {
                *text = Quantity::Tension(new.to_owned()).to_string();
            }
            _ => {}
        };
        for graph in &mut self.graphs {
            rename(&mut graph.x);
            graph.y.iter_mut().for_each(rename);
        }
        if let Some(Follow::Particle(name)) = self.view.as_mut().and_then(|v| v.follow.as_mut())
            && name == old
        {
            new.clone_into(name);
        }
    }

    /// Drops every reference to the particle, rod or string `name` from the graphs and
    /// the view (a graph's x axis falls back to time), as deleting a particle does for
    /// its springs.
    pub(super) fn forget_in_presentation(&mut self, name: &str) {
        let names = |text: &str| match Quantity::parse(text) {
            Ok(Quantity::Particle(n, _) | Quantity::Tension(n)) => n == name,
            _ => false,
        };
        for graph in &mut self.graphs {
            if names(&graph.x) {
                "t".clone_into(&mut graph.x);
            }
            graph.y.retain(|y| !names(y));
        }
        if let Some(view) = &mut self.view
            && view.follow == Some(Follow::Particle(name.to_owned()))
        {
            view.follow = None;
        }
    }
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
}
