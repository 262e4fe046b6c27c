//! Which method advances a scene in time: the name a scene file gives it. The methods
//! themselves are in [`crate::integrators`]; this vocabulary sits below the scene so that
//! a scene can name one.

use std::fmt;
use std::str::FromStr;

/// The method that advances a scene in time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Integrator {
    /// Explicit Euler, the paper's method: first order, gains energy. Kept to show why
    /// better methods exist.
    Euler,
    /// Semi-implicit (symplectic) Euler: first order, bounded energy error.
    SemiImplicitEuler,
    /// Velocity Verlet: second order, symplectic and time-reversible.
    Verlet,
    /// Classical Runge–Kutta: fourth order. The default.
    #[default]
    Rk4,
    /// Position-extended Forest–Ruth-like: fourth order and symplectic, for long runs
    /// of orbits and oscillators.
    Pefrl,
    /// Adaptive Dormand–Prince 5(4): error per step under the scene's tolerance, the time
    /// step as its largest step.
    Dopri5,
}

impl Integrator {
    /// Every method, in order of sophistication.
    pub const ALL: [Self; 6] = [
        Self::Euler,
        Self::SemiImplicitEuler,
        Self::Verlet,
        Self::Rk4,
        Self::Pefrl,
        Self::Dopri5,
    ];

    /// The scene-file name: `euler`, `semi-implicit-euler`, `verlet`, `rk4`, `pefrl`,
    /// `dopri5`.
    pub const fn as_str(self) -> &'static str {
        match self {
            Self::Euler => "euler",
            Self::SemiImplicitEuler => "semi-implicit-euler",
            Self::Verlet => "verlet",
            Self::Rk4 => "rk4",
            Self::Pefrl => "pefrl",
            Self::Dopri5 => "dopri5",
        }
    }

    /// A one-line description for menus and tooltips.
    pub const fn describe(self) -> &'static str {
        match self {
            Self::Euler => "explicit Euler, 1st order, gains energy (the paper's method)",
            Self::SemiImplicitEuler => "semi-implicit Euler, 1st order, symplectic",
            Self::Verlet => "velocity Verlet, 2nd order, symplectic",
            Self::Rk4 => "classical Runge–Kutta, 4th order",
            Self::Pefrl => "PEFRL (Forest–Ruth-like), 4th order, symplectic",
            Self::Dopri5 => "adaptive Dormand–Prince 5(4), error under the tolerance",
        }
    }
}

impl fmt::Display for Integrator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The name is not one of the integrators.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown integrator '{0}'")]
pub struct UnknownIntegrator(pub String);

impl FromStr for Integrator {
    type Err = UnknownIntegrator;

    fn from_str(name: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|i| i.as_str() == name)
            .ok_or_else(|| UnknownIntegrator(name.to_owned()))
    }
}
