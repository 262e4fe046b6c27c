//! Adaptive Dormand–Prince 5(4) (Dormand & Prince 1980; Hairer, Nørsett & Wanner,
//! *Solving ODEs I*, II.5), on (x, v)' = (v, a(x, v)).
//!
//! Each step computes a fifth-order solution and, from the same seven stages, a
//! fourth-order one; their difference estimates the local error. A step is accepted when
//! every component's error is within `tolerance · (1 + |y|)` (the tolerance serves as
//! both absolute and relative bound, maximum norm so a single particle in a close
//! encounter is never averaged away by a crowd at rest); the next step is scaled by
//! 0.9·err^(−1/5) within [0.2, 5]. First same as last: the seventh stage is the
//! acceleration at the new state, reused as the first stage of the next step. Not
//! symplectic; its energy error is bounded by the tolerance per step.

use crate::forces::ForceModel;
use crate::integrators::Workspace;
use crate::state::State;

// The Butcher tableau. Stage s is evaluated at t + C[s]·h.
const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
pub(crate) const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// Fifth-order weights minus fourth-order weights: the error estimate.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17_253.0 / 339_200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// The controller failed: the step needed is too small to make progress in f64.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StepTooSmall;

/// Step-size memory between calls.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Controller {
    /// The step the error estimate proposed last, seconds.
    pub next_step: Option<f64>,
}

/// Advances `state` by one accepted step of at most `max_step` seconds and returns the
/// step taken.
pub(crate) fn step(
    forces: &ForceModel,
    state: &mut State,
    max_step: f64,
    tolerance: f64,
    work: &mut Workspace,
    controller: &mut Controller,
) -> Result<f64, StepTooSmall> {
    let n = state.len();
    work.prepare(7, n);
    let first = work.take_start_acceleration(forces, state);
    work.accelerations[0].copy_from_slice(&first);
    work.velocities[0].copy_from_slice(&state.velocity);
    let mut h = controller.next_step.map_or(max_step, |h| h.min(max_step));
    // A step cut short (to land on a requested instant, or by the largest step) says
    // nothing against the longer step proposed before it.
    let mut cut_short = controller.next_step.filter(|&previous| max_step < previous);
    loop {
        let error = attempt(forces, state, h, tolerance, work);
        let factor = if error == 0.0 {
            5.0
        } else {
            (0.9 * error.powf(-0.2)).clamp(0.2, 5.0)
        };
        if error <= 1.0 {
            let Workspace {
                accelerations,
                stage,
                ..
            } = work;
            std::mem::swap(&mut state.position, &mut stage.position);
            std::mem::swap(&mut state.velocity, &mut stage.velocity);
            state.time += h;
            let proposal = h * factor;
            controller.next_step =
                Some(cut_short.map_or(proposal, |previous| previous.max(proposal)));
            let mut first = first;
            first.copy_from_slice(&accelerations[6]);
            work.start_acceleration = Some(first);
            return Ok(h);
        }
        h *= factor;
        cut_short = None;
        // NaN h (from a NaN error estimate) fails this comparison too.
        if h.partial_cmp(&(1e-14 * state.time.abs().max(1.0))) != Some(std::cmp::Ordering::Greater)
        {
            work.start_acceleration = Some(first);
            return Err(StepTooSmall);
        }
    }
}

/// One step of exactly `h`, accepted whatever its error estimate.
pub(crate) fn step_exactly(forces: &ForceModel, state: &mut State, h: f64, work: &mut Workspace) {
    let n = state.len();
    work.prepare(7, n);
    forces.accelerations(
        state.time,
        &state.position,
        &state.velocity,
        &mut work.accelerations[0],
    );
    work.velocities[0].copy_from_slice(&state.velocity);
    attempt(forces, state, h, 1.0, work);
    std::mem::swap(&mut state.position, &mut work.stage.position);
    std::mem::swap(&mut state.velocity, &mut work.stage.velocity);
}

/// Computes the seven stages for a step of `h`, leaves the fifth-order solution in
/// `work.stage` and returns the scaled error norm (≤ 1 to accept).
fn attempt(
    forces: &ForceModel,
    state: &State,
    h: f64,
    tolerance: f64,
    work: &mut Workspace,
) -> f64 {
    let n = state.len();
    let Workspace {
        accelerations: ka,
        velocities: kv,
        stage,
        ..
    } = work;
    for s in 1..7 {
        for i in 0..n {
            let mut dx = glam::DVec2::ZERO;
            let mut dv = glam::DVec2::ZERO;
            for j in 0..s {
                dx += kv[j][i] * A[s][j];
                dv += ka[j][i] * A[s][j];
            }
            stage.position[i] = state.position[i] + dx * h;
            stage.velocity[i] = state.velocity[i] + dv * h;
        }
        debug_assert!(C[s] <= 1.0, "stages lie within the step");
        kv[s].copy_from_slice(&stage.velocity);
        forces.accelerations(
            state.time + C[s] * h,
            &stage.position,
            &stage.velocity,
            &mut ka[s],
        );
    }
    // The seventh stage was evaluated at the fifth-order solution itself (A[6] are its
    // weights), which is what `stage` holds now.
    let mut worst: f64 = 0.0;
    for i in 0..n {
        let mut ex = glam::DVec2::ZERO;
        let mut ev = glam::DVec2::ZERO;
        for j in 0..7 {
            ex += kv[j][i] * E[j];
            ev += ka[j][i] * E[j];
        }
        let scale = |y0: f64, y1: f64| tolerance * (1.0 + y0.abs().max(y1.abs()));
        let (x0, x1, v0, v1) = (
            state.position[i],
            stage.position[i],
            state.velocity[i],
            stage.velocity[i],
        );
        worst = worst
            .max((ex.x * h).abs() / scale(x0.x, x1.x))
            .max((ex.y * h).abs() / scale(x0.y, x1.y))
            .max((ev.x * h).abs() / scale(v0.x, v1.x))
            .max((ev.y * h).abs() / scale(v0.y, v1.y));
    }
    if worst.is_nan() { f64::INFINITY } else { worst }
}

#[cfg(test)]
mod tableau_tests {
    use super::*;

    /// The consistency conditions of a Runge–Kutta tableau: each stage's time is the sum
    /// of its row (Σⱼ aₛⱼ = cₛ), the fifth-order weights (the last row, first same as
    /// last) sum to 1, and the error weights, a difference of two consistent rules, to 0.
    #[test]
    fn the_tableau_is_consistent() {
        for (s, row) in A.iter().enumerate() {
            let sum: f64 = row.iter().sum();
            assert!(
                (sum - C[s]).abs() < 1e-15,
                "stage {s}: row sums to {sum}, c = {}",
                C[s]
            );
        }
        let weights: f64 = A[6].iter().sum();
        assert!(
            (weights - 1.0).abs() < 1e-15,
            "fifth-order weights sum to {weights}"
        );
        let error: f64 = E.iter().sum();
        assert!(error.abs() < 1e-15, "error weights sum to {error}");
    }
}
