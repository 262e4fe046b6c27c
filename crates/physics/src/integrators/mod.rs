//! Time integration of the smooth motion: one file per method, all advancing positions
//! and velocities under [`ForceModel::accelerations`] by one step of a given size.
//!
//! | method                | order | conserves                                             |
//! |-----------------------|-------|-------------------------------------------------------|
//! | `euler`               | 1     | nothing; an undamped oscillator gains energy          |
//! | `semi-implicit-euler` | 1     | symplectic: energy error bounded, no drift            |
//! | `verlet`              | 2     | symplectic, time-reversible: bounded energy error     |
//! | `rk4`                 | 4     | nothing exactly; tiny error, slow drift               |
//! | `pefrl`               | 4     | symplectic: bounded energy error, ~100× Verlet's less |
//! | `dopri5`              | 5(4)  | nothing exactly; error held under the tolerance       |
//!
//! All are exact (to rounding) for constant acceleration, except `euler` and
//! `semi-implicit-euler`, which are off by a·h·t/2.

pub(crate) mod dopri5;
pub(crate) mod euler;
pub(crate) mod pefrl;
pub(crate) mod rk4;
pub(crate) mod semi_implicit_euler;
pub(crate) mod verlet;

use glam::DVec2;

use crate::method::Integrator;

use crate::forces::ForceModel;
use crate::state::State;

/// Scratch arrays reused from step to step, so stepping allocates nothing.
#[derive(Clone, Debug, Default)]
pub(crate) struct Workspace {
    /// Stage accelerations (rk4 uses 4, dopri5 7).
    pub accelerations: Vec<Vec<DVec2>>,
    /// Stage velocities.
    pub velocities: Vec<Vec<DVec2>>,
    /// A stage's positions and velocities.
    pub stage: State,
    /// The acceleration at the current state, when known: velocity Verlet and dopri5
    /// (first same as last) reuse the end of one step as the start of the next. Anything
    /// that changes the state outside a step must clear it.
    pub start_acceleration: Option<Vec<DVec2>>,
    /// The adaptive method's step-size memory.
    pub controller: dopri5::Controller,
}

impl Workspace {
    /// Frees the stages, which every step writes before it reads them (see
    /// [`crate::Simulation::keyframe`]); the kept acceleration and the step-size memory
    /// stay.
    pub fn drop_scratch(&mut self) {
        self.accelerations = Vec::new();
        self.velocities = Vec::new();
        self.stage = State::default();
    }

    /// Makes room for `stages` stages of `n` particles.
    pub fn prepare(&mut self, stages: usize, n: usize) {
        for list in [&mut self.accelerations, &mut self.velocities] {
            list.resize_with(stages.max(list.len()), Vec::new);
            for v in list.iter_mut() {
                v.resize(n, DVec2::ZERO);
            }
        }
        self.stage.position.resize(n, DVec2::ZERO);
        self.stage.velocity.resize(n, DVec2::ZERO);
    }

    /// The acceleration at `state`, from the cache when valid.
    pub fn take_start_acceleration(&mut self, forces: &ForceModel, state: &State) -> Vec<DVec2> {
        self.start_acceleration.take().unwrap_or_else(|| {
            let mut a = vec![DVec2::ZERO; state.len()];
            forces.accelerations(state.time, &state.position, &state.velocity, &mut a);
            a
        })
    }
}

/// Advances `state` by exactly `h` seconds, whatever the method: the adaptive one takes a
/// single step of `h` without error control (used to integrate to an impact found inside
/// a step the controller already accepted, so it is no larger than an accepted step).
pub(crate) fn advance_exactly(
    method: Integrator,
    forces: &ForceModel,
    state: &mut State,
    h: f64,
    work: &mut Workspace,
) {
    work.start_acceleration = None;
    match method {
        Integrator::Euler => euler::step(forces, state, h, work),
        Integrator::SemiImplicitEuler => semi_implicit_euler::step(forces, state, h, work),
        Integrator::Verlet => verlet::step(forces, state, h, work),
        Integrator::Rk4 => rk4::step(forces, state, h, work),
        Integrator::Pefrl => pefrl::step(forces, state, h, work),
        Integrator::Dopri5 => dopri5::step_exactly(forces, state, h, work),
    }
    state.time += h;
    work.start_acceleration = None;
}

/// The acceleration at a state that is used more than once, once something computed it
/// (rk4's first stage, or [`KnownStart::of`]): the coupled system integrates from one
/// impact's state to the step's end and again to the next impact.
#[derive(Clone, Debug, Default)]
pub(crate) struct KnownStart {
    acceleration: Vec<DVec2>,
    known: bool,
}

impl KnownStart {
    /// The state changed: its acceleration is not known.
    pub fn forget(&mut self) {
        self.known = false;
    }

    /// The acceleration at `state` under `forces`, computed the first time it is asked
    /// for since [`Self::forget`].
    pub fn of(&mut self, forces: &ForceModel, state: &State) -> &[DVec2] {
        if !self.known {
            self.acceleration.clear();
            self.acceleration.resize(state.len(), DVec2::ZERO);
            forces.accelerations(
                state.time,
                &state.position,
                &state.velocity,
                &mut self.acceleration,
            );
            self.known = true;
        }
        &self.acceleration
    }
}

/// [`advance_exactly`] from a state integrated from before with the same `start`: with
/// rk4 the first of its four evaluations is the one already made, with the same bits.
/// Other methods integrate as [`advance_exactly`] does.
pub(crate) fn advance_exactly_from(
    method: Integrator,
    forces: &ForceModel,
    state: &mut State,
    h: f64,
    work: &mut Workspace,
    start: &mut KnownStart,
) {
    if method != Integrator::Rk4 {
        advance_exactly(method, forces, state, h, work);
        return;
    }
    work.start_acceleration = None;
    let known = start.known.then_some(start.acceleration.as_slice());
    rk4::step_knowing(forces, state, h, work, known);
    if !start.known {
        start.acceleration.clone_from(&work.accelerations[0]);
        start.known = true;
    }
    state.time += h;
}

/// Advances `state` by one step of at most `max_step` seconds (exactly `max_step` for
/// the fixed-step methods) and returns the step taken, seconds.
pub(crate) fn advance(
    method: Integrator,
    forces: &ForceModel,
    state: &mut State,
    max_step: f64,
    tolerance: f64,
    work: &mut Workspace,
) -> Result<f64, dopri5::StepTooSmall> {
    let fixed = match method {
        Integrator::Euler => euler::step,
        Integrator::SemiImplicitEuler => semi_implicit_euler::step,
        Integrator::Verlet => verlet::step,
        Integrator::Rk4 if forces.accelerations_are_constant() => ballistic,
        Integrator::Rk4 => rk4::step,
        Integrator::Pefrl => pefrl::step,
        Integrator::Dopri5 => {
            let mut controller = work.controller;
            let taken = dopri5::step(forces, state, max_step, tolerance, work, &mut controller);
            work.controller = controller;
            return taken;
        }
    };
    fixed(forces, state, max_step, work);
    state.time += max_step;
    Ok(max_step)
}

/// rk4's step where every particle's acceleration is constant through it (the field, an
/// applied acceleration, and the surfaces' answer to them: no pair forces, springs, rods
/// or strings): x + v h + a h²/2, v + a h, which rk4 gives exactly for such motion, here
/// from one evaluation instead of four (it agrees with rk4's arithmetic to rounding, not
/// bit for bit; docs/performance.md has what it saves).
pub(crate) fn ballistic(forces: &ForceModel, state: &mut State, h: f64, work: &mut Workspace) {
    from_accelerations(forces, state, work, |x, v, a| {
        *x += *v * h + a * (0.5 * h * h);
        *v += a * h;
    });
}

/// The accelerations at `state`, evaluated once, and `update` of each particle's position
/// and velocity with its acceleration: the one-evaluation methods.
pub(crate) fn from_accelerations(
    forces: &ForceModel,
    state: &mut State,
    work: &mut Workspace,
    update: impl Fn(&mut DVec2, &mut DVec2, DVec2),
) {
    work.prepare(1, state.len());
    let a = &mut work.accelerations[0];
    forces.accelerations(state.time, &state.position, &state.velocity, a);
    for ((x, v), a) in state
        .position
        .iter_mut()
        .zip(&mut state.velocity)
        .zip(a.iter())
    {
        update(x, v, *a);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every method's name prints as the scene file spells it and parses back; the
    /// descriptions the app shows are distinct and say the method's order.
    #[test]
    fn names_round_trip_and_descriptions_say_the_order() {
        for integrator in Integrator::ALL {
            let name = integrator.to_string();
            assert_eq!(name, integrator.as_str(), "Display is the file's name");
            assert_eq!(
                name.parse::<Integrator>(),
                Ok(integrator),
                "{name} parses back"
            );
            let description = integrator.describe();
            assert!(
                ["1st", "2nd", "4th", "5(4)"]
                    .iter()
                    .any(|order| description.contains(order)),
                "{name}: '{description}' says its order"
            );
        }
        let mut descriptions: Vec<&str> = Integrator::ALL.iter().map(|i| i.describe()).collect();
        descriptions.sort_unstable();
        descriptions.dedup();
        assert_eq!(
            descriptions.len(),
            Integrator::ALL.len(),
            "one description each"
        );
        assert!(
            "leapfrog".parse::<Integrator>().is_err(),
            "an unknown name is an error"
        );
    }
}
