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

/// An experiment series the app runs (`[[series]]`): a setting varied over a range, each
/// run measured, and optionally the law expected ([`crate::series`] runs it; `run`
/// ignores it).
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The setting varied, as `sweep --vary` names it (`Ball.velocity.angle`).
    pub vary: String,
    /// The first value.
    pub from: f64,
    /// The last value (reached when the steps reach it).
    pub to: f64,
    /// The step between values.
    pub step: f64,
    /// How long each run lasts, seconds.
    pub until: f64,
    /// What each run is measured for, as `sweep --measure` writes it.
    pub measure: Vec<String>,
    /// The law expected of the first measure, an expression of the varied value
    /// ([`super::series::Theory`]).
    pub theory: Option<String>,
}

impl Series {
    /// What is wrong with the series on `scene`, each with its key: a setting the scene
    /// does not have, a range with no values, a run that ends before the scene starts,
    /// measures that do not read or name objects it lacks, a theory that does not read.
    /// ([`Scene::validate`] lists these at their lines; the app shows them beside the
    /// series without checking the whole scene each frame.)
    pub fn problems(&self, scene: &Scene) -> Vec<(&'static str, String)> {
        use super::series::{Measure, Setting, Theory, range_values};
        let mut problems = Vec::new();
        if let Err(why) = Setting::parse(&self.vary, scene) {
            problems.push(("vary", why));
        }
        if range_values(self.from, self.to, self.step).is_none() {
            let text = format!("{}:{}:{}", self.from, self.to, self.step);
            let why = super::series::range_problem(&text, self.from, self.to, self.step);
            problems.push(("step", why));
        }
        if !(self.until.is_finite() && self.until > scene.simulation.start_time) {
            let until = self.until.to_string();
            problems.push((
                "until",
                super::say("scene-series-until", &[("until", &until)]),
            ));
        } else if let Ok(sweep) = self.sweep(scene)
            && let Err(why) = sweep.extent(scene)
        {
            problems.push(("until", why));
        }
        for text in &self.measure {
            if let Err(why) = Measure::parse(text).and_then(|m| m.check_in(scene)) {
                problems.push(("measure", why));
            }
        }
        if let Some(theory) = &self.theory
            && let Err(why) = Theory::parse(theory, scene, &self.vary)
        {
            problems.push(("theory", why));
        }
        problems
    }

    /// The series as a [`super::series::Sweep`] on `scene`.
    ///
    /// # Errors
    /// A setting, range or measure that does not read (in words).
    pub fn sweep(&self, scene: &Scene) -> Result<super::series::Sweep, String> {
        let text = format!("{}={}:{}:{}", self.vary, self.from, self.to, self.step);
        Ok(super::series::Sweep {
            varies: vec![super::series::Vary::parse(&text, scene)?],
            until: self.until,
            measures: self
                .measure
                .iter()
                .map(|m| super::series::Measure::parse(m))
                .collect::<Result<_, _>>()?,
            trace: false,
        })
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
    /// The canvas's toggles as the scene was saved (each `None`: the app's default):
    /// trails, velocity, acceleration and force arrows, names.
    pub trails: Option<bool>,
    /// Velocity arrows.
    pub velocity: Option<bool>,
    /// Acceleration arrows.
    pub acceleration: Option<bool>,
    /// Force arrows.
    pub force: Option<bool>,
    /// Particles' names.
    pub names: Option<bool>,
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
    /// Renames every reference to the particle, rod or string `old` in the graphs, the
    /// series and the view, as renaming a particle does for its springs.
    pub(super) fn rename_in_presentation(&mut self, old: &str, new: &str) {
        if let Some(instruments) = &mut self.instruments {
            instruments.rename(old, new);
        }
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
        for series in &mut self.series {
            if let Some(rest) = series.vary.strip_prefix(old).filter(|r| r.starts_with('.')) {
                series.vary = format!("{new}{rest}");
            }
            for text in &mut series.measure {
                if let Ok(mut measure) = super::series::Measure::parse(text) {
                    measure.quantities_mut().into_iter().for_each(rename);
                    *text = measure.to_string();
                }
            }
        }
        if let Some(Follow::Particle(name)) = self.view.as_mut().and_then(|v| v.follow.as_mut())
            && name == old
        {
            new.clone_into(name);
        }
    }

    /// Drops every reference to the object `name` (a particle, a body, a rod or string, a
    /// joint) from the graphs, the series (each series about it) and the view (a graph's
    /// x axis falls back to time), as deleting a particle does for its springs.
    pub(super) fn forget_in_presentation(&mut self, name: &str) {
        let names = |quantity: &Quantity| match quantity {
            Quantity::Particle(n, _) | Quantity::Link(n, _) | Quantity::Joint(n, _) => n == name,
            _ => false,
        };
        for graph in &mut self.graphs {
            if names(&graph.x) {
                graph.x = Quantity::Time;
            }
            graph.y.retain(|y| !names(y));
        }
        // A series about the object is about nothing once it is gone.
        self.series.retain(|series| {
            let varies = series
                .vary
                .strip_prefix(name)
                .is_some_and(|rest| rest.starts_with('.'));
            let measures = series.measure.iter().any(|text| {
                super::series::Measure::parse(text)
                    .is_ok_and(|mut m| m.quantities_mut().into_iter().any(|q| names(q)))
            });
            !(varies || measures)
        });
        if let Some(view) = &mut self.view
            && view.follow == Some(Follow::Particle(name.to_owned()))
        {
            view.follow = None;
        }
    }
}
