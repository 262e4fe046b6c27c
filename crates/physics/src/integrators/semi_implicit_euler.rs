//! Semi-implicit (symplectic) Euler: v' = v + a(x, v) h, then x' = x + v' h.
//!
//! First order, but symplectic for position-dependent forces: it conserves a modified
//! energy, so the energy error of an undamped oscillator or an orbit stays bounded over
//! any number of periods instead of drifting.

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
        *v += *a * h;
        *x += *v * h;
    }
}
