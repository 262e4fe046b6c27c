//! Explicit Euler, the paper's equations 1–2: x' = x + v h, v' = v + a(x, v) h.
//!
//! First order: the global error shrinks only in proportion to h. It is not symplectic:
//! on an undamped oscillator each step multiplies the energy by 1 + (ωh)², so the
//! amplitude grows without bound — the paper's spring peaked at 15.85 instead of 15.
//! Kept to show why better methods exist.

use crate::forces::ForceModel;
use crate::integrators::Workspace;
use crate::state::State;

pub(crate) fn step(forces: &ForceModel, state: &mut State, h: f64, work: &mut Workspace) {
    work.prepare(1, state.len());
    let a = &mut work.accelerations[0];
    forces.accelerations(&state.position, &state.velocity, a);
    for ((x, v), a) in state
        .position
        .iter_mut()
        .zip(&mut state.velocity)
        .zip(a.iter())
    {
        *x += *v * h;
        *v += *a * h;
    }
}
