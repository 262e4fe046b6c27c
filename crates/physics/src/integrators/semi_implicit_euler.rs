//! Semi-implicit (symplectic) Euler: v' = v + a(x, v) h, then x' = x + v' h.
//!
//! First order, but symplectic for position-dependent forces: it conserves a modified
//! energy, so the energy error of an undamped oscillator or an orbit stays bounded over
//! any number of periods instead of drifting.

use crate::forces::ForceModel;
use crate::integrators::{self, Workspace};
use crate::state::State;

pub(crate) fn step(forces: &ForceModel, state: &mut State, h: f64, work: &mut Workspace) {
    integrators::from_accelerations(forces, state, work, |x, v, a| {
        *v += a * h;
        *x += *v * h;
    });
}
