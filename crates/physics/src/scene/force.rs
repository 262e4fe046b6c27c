//! `[[force]]`: a force of one's own on particles, written as expressions of the
//! particle's position, velocity, mass and charge and of time, with the potential energy
//! that the ledger books when one is given.

use std::fmt;

use glam::DVec2;

use super::say;

/// A force law written in the scene: `fx` and `fy` in newtons, on the particles named in
/// `on` (every particle when empty).
#[derive(Clone, Debug, PartialEq)]
pub struct Force {
    /// Unique among all objects.
    pub name: String,
    /// The particles it acts on; empty: every particle.
    pub on: Vec<String>,
    /// The force's x component, N: an expression of `x`, `y`, `vx`, `vy`, `t`, `m`, `q`, `pi`.
    pub fx: String,
    /// The force's y component, N.
    pub fy: String,
    /// Its potential energy on one particle, J, an expression of the position, mass and
    /// charge alone (`x`, `y`, `m`, `q`): the ledger books it as potential energy, so the
    /// books close when the force is −∇U.
    pub potential: Option<String>,
}

impl Force {
    /// A force named `name` with components `fx` and `fy` (expressions, N) on every
    /// particle, without a potential.
    #[must_use]
    pub fn new(name: impl Into<String>, fx: impl Into<String>, fy: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            on: Vec::new(),
            fx: fx.into(),
            fy: fy.into(),
            potential: None,
        }
    }

    /// Limits it to the particles named.
    #[must_use]
    pub fn on<S: Into<String>>(mut self, names: impl IntoIterator<Item = S>) -> Self {
        self.on = names.into_iter().map(Into::into).collect();
        self
    }

    /// Gives it a potential energy, J (an expression of `x`, `y`, `m`, `q`).
    #[must_use]
    pub fn potential(mut self, potential: impl Into<String>) -> Self {
        self.potential = Some(potential.into());
        self
    }
}

/// What a force's expressions may name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Variable {
    X,
    Y,
    Vx,
    Vy,
    T,
    M,
    Q,
    Pi,
}

/// The names of [`Variable`], as an expression writes them.
pub const VARIABLES: [&str; 8] = ["x", "y", "vx", "vy", "t", "m", "q", "pi"];

impl Variable {
    const ALL: [Self; 8] = [
        Self::X,
        Self::Y,
        Self::Vx,
        Self::Vy,
        Self::T,
        Self::M,
        Self::Q,
        Self::Pi,
    ];

    fn named(name: &str) -> Option<Self> {
        VARIABLES
            .iter()
            .position(|&v| v == name)
            .map(|k| Self::ALL[k])
    }

    /// Whether a potential energy may name it: a potential of the position (with the
    /// mass and charge as constants), so that its force is −∇U.
    fn in_potential(self) -> bool {
        !matches!(self, Self::Vx | Self::Vy | Self::T)
    }
}

/// One particle where a law is evaluated.
#[derive(Clone, Copy, Debug)]
pub(crate) struct At {
    pub t: f64,
    pub position: DVec2,
    pub velocity: DVec2,
    pub mass: f64,
    pub charge: f64,
}

/// One expression of a force, parsed, with the variable of each of its slots.
#[derive(Clone)]
pub(crate) struct Law {
    expression: exmex::FlatEx<f64>,
    slots: Vec<Variable>,
}

impl fmt::Debug for Law {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use exmex::Express as _;
        f.write_str(self.expression.unparse())
    }
}

impl Law {
    /// Reads `text`; `potential` says whether it is a potential energy (which may name
    /// the position, mass and charge only).
    ///
    /// # Errors
    /// It is no expression, or names something else, in words.
    pub fn parse(text: &str, potential: bool) -> Result<Self, String> {
        use exmex::Express as _;
        if let Some(reason) = crate::units::too_big(text.trim()) {
            return Err(reason);
        }
        let spelled = text.trim().replace('π', "pi").replace("**", "^");
        let expression = exmex::FlatEx::<f64>::parse(&spelled)
            .map_err(|_| say("scene-force-unreadable", &[("text", text.trim())]))?;
        let mut slots = Vec::new();
        for name in expression.var_names() {
            let variable = Variable::named(name)
                .filter(|v| !potential || v.in_potential())
                .ok_or_else(|| {
                    let names: Vec<&str> = Variable::ALL
                        .iter()
                        .zip(VARIABLES)
                        .filter(|(v, _)| !potential || v.in_potential())
                        .map(|(_, name)| name)
                        .collect();
                    let id = if potential {
                        "scene-force-potential-name"
                    } else {
                        "scene-force-unknown-name"
                    };
                    say(id, &[("name", name), ("names", &names.join(", "))])
                })?;
            slots.push(variable);
        }
        Ok(Self { expression, slots })
    }

    /// Whether it names the velocity or the time.
    pub fn varies_with_motion(&self) -> bool {
        self.slots
            .iter()
            .any(|v| matches!(v, Variable::Vx | Variable::Vy | Variable::T))
    }

    /// Its value at `at` (NaN where the expression has none).
    pub fn at(&self, at: &At) -> f64 {
        use exmex::Express as _;
        let mut values = [0.0; 8];
        for (value, variable) in values.iter_mut().zip(&self.slots) {
            *value = match variable {
                Variable::X => at.position.x,
                Variable::Y => at.position.y,
                Variable::Vx => at.velocity.x,
                Variable::Vy => at.velocity.y,
                Variable::T => at.t,
                Variable::M => at.mass,
                Variable::Q => at.charge,
                Variable::Pi => std::f64::consts::PI,
            };
        }
        self.expression
            .eval(&values[..self.slots.len()])
            .unwrap_or(f64::NAN)
    }
}
