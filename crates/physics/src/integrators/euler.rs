//! Explicit Euler, the paper's equations 1–2: x' = x + v h, v' = v + a(x, v) h.
//!
//! First order: the global error shrinks only in proportion to h. It is not symplectic:
//! on an undamped oscillator each step multiplies the energy by 1 + (ωh)², so the
//! amplitude grows without bound — the paper's spring peaked at 15.85 instead of 15.
//! Kept to show why better methods exist.

use crate::forces::ForceModel;
use crate::integrators::{self, Workspace};
use crate::state::State;

pub(crate) fn step(forces: &ForceModel, state: &mut State, h: f64, work: &mut Workspace) {
    integrators::from_accelerations(forces, state, work, |x, v, a| {
        *x += *v * h;
        *v += a * h;
    });
}
