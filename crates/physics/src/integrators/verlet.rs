//! Velocity Verlet: v½ = v + a h/2, x' = x + v½ h, v' = v½ + a(x', ·) h/2.
//!
//! Second order, symplectic and time-reversible for position-dependent forces: the energy
//! error of an orbit oscillates with bounded amplitude and shows no secular growth over
//! any number of periods. Exact for constant acceleration. One force evaluation per step:
//! the acceleration at the end of a step is kept for the start of the next.
//!
//! Velocity-dependent forces (spring damping) need v' before it is known; they are
//! evaluated at the predicted v + a h, which keeps the method second order but makes it
//! no longer symplectic — as it should not be for a dissipative system. The next step
//! then evaluates the acceleration again at the velocity reached (two evaluations a
//! step), as a run started from that state would.

use crate::forces::ForceModel;
use crate::integrators::Workspace;
use crate::state::State;

pub(crate) fn step(forces: &ForceModel, state: &mut State, h: f64, work: &mut Workspace) {
    let n = state.len();
    work.prepare(1, n);
    let start = work.take_start_acceleration(forces, state);
    let predicted = &mut work.stage.velocity;
    for i in 0..n {
        predicted[i] = state.velocity[i] + start[i] * h;
        state.velocity[i] += start[i] * (0.5 * h);
        state.position[i] += state.velocity[i] * h;
    }
    let end = &mut work.accelerations[0];
    forces.accelerations(state.time + h, &state.position, predicted, end);
    for (v, a) in state.velocity.iter_mut().zip(end.iter()) {
        *v += *a * (0.5 * h);
    }
    // Kept only when it is the acceleration at the state reached: with a force that
    // depends on velocity it was taken at the predicted velocity, and the next step
    // evaluates it again at the velocity reached, which is all a saved state carries (a
    // run continued from one is then the run that saved it, bit for bit).
    if !forces.depends_on_velocity() {
        let mut start = start;
        start.copy_from_slice(end);
        work.start_acceleration = Some(start);
    }
}
