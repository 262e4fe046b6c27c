//! What the app shows when a scene opens: its graphs (`[[graph]]`) and its framing
//! (`[view]`). The simulation never reads them; they are part of the scene so that an
//! example opens with the graphs that teach it and a saved scene reopens as it was left.
//! `check` validates them like everything else: a graph naming a particle that does not
//! exist is an error with its line and column.

use glam::DVec2;

use super::Scene;
use crate::quantity::Quantity;

/// A graph: quantities against time, or against another quantity (a phase plot).
#[derive(Clone, Debug, PartialEq)]
pub struct Graph {
    /// A heading, optional.
    pub title: Option<String>,
    /// The horizontal axis: time, or a quantity (a phase plot).
    pub x: Quantity,
    /// The plotted quantities, one series each.
    pub y: Vec<Quantity>,
}

impl Graph {
    /// `y` against time.
    pub fn against_time(y: impl IntoIterator<Item = Quantity>) -> Self {
        Self {
            title: None,
            x: Quantity::Time,
            y: y.into_iter().collect(),
        }
    }

    /// The quantities named `y` (`"ball.y"`, as a scene file writes them) against time.
    ///
    /// # Errors
    /// The first name that is no quantity, and why ([`Quantity::parse`]).
    pub fn of<S: AsRef<str>>(y: impl IntoIterator<Item = S>) -> Result<Self, String> {
        let y = y
            .into_iter()
            .map(|text| Quantity::parse(text.as_ref()))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Self::against_time(y))
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

impl Scene {
    /// Renames every reference to the particle, rod or string `old` in the graphs and the
    /// view, as renaming a particle does for its springs.
    pub(super) fn rename_in_presentation(&mut self, old: &str, new: &str) {
        let rename = |quantity: &mut Quantity| match quantity {
            Quantity::Particle(name, _) | Quantity::Link(name, _) if name == old => {
                new.clone_into(name);
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
        let names = |quantity: &Quantity| match quantity {
            Quantity::Particle(n, _) | Quantity::Link(n, _) => n == name,
            _ => false,
        };
        for graph in &mut self.graphs {
            if names(&graph.x) {
                graph.x = Quantity::Time;
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
