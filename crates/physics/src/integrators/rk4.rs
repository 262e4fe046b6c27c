//! The classical fourth-order Runge–Kutta method on the first-order system
//! (x, v)' = (v, a(x, v)).
//!
//! Fourth order: halving the step divides the global error by 16. Not symplectic, so an
//! orbit's energy drifts, but so slowly at sensible steps (relative 1e-12 per period at
//! 1,000 steps per period) that it is the best default for teaching. Exact for constant
//! acceleration. Four force evaluations per step.

use glam::DVec2;

use crate::forces::ForceModel;
use crate::integrators::Workspace;
use crate::state::State;

pub(crate) fn step(forces: &ForceModel, state: &mut State, h: f64, work: &mut Workspace) {
    step_knowing(forces, state, h, work, None);
}

/// [`step`] from a state whose acceleration is known already (`start`, as a step from
/// the same state computed it): the first of the four evaluations is skipped, with the
/// same bits. After any step, `work.accelerations[0]` is the acceleration at its start.
pub(crate) fn step_knowing(
    forces: &ForceModel,
    state: &mut State,
    h: f64,
    work: &mut Workspace,
    start: Option<&[DVec2]>,
) {
    let n = state.len();
    work.prepare(4, n);
    let Workspace {
        accelerations: ka,
        velocities: kv,
        stage,
        ..
    } = work;
    // Stage s is evaluated at the start plus c_s·h times the previous stage's slopes.
    for (s, c) in [(0, 0.0), (1, 0.5), (2, 0.5), (3, 1.0)] {
        if s == 0 {
            stage.position.copy_from_slice(&state.position);
            stage.velocity.copy_from_slice(&state.velocity);
        } else {
            for i in 0..n {
                stage.position[i] = state.position[i] + kv[s - 1][i] * (c * h);
                stage.velocity[i] = state.velocity[i] + ka[s - 1][i] * (c * h);
            }
        }
        kv[s].copy_from_slice(&stage.velocity);
        match start {
            Some(known) if s == 0 => ka[0].copy_from_slice(known),
            _ => forces.accelerations(
                state.time + c * h,
                &stage.position,
                &stage.velocity,
                &mut ka[s],
            ),
        }
    }
    let sixth = h / 6.0;
    for i in 0..n {
        state.position[i] += (kv[0][i] + 2.0 * kv[1][i] + 2.0 * kv[2][i] + kv[3][i]) * sixth;
        state.velocity[i] += (ka[0][i] + 2.0 * ka[1][i] + 2.0 * ka[2][i] + ka[3][i]) * sixth;
    }
}
