//! One step as named stages over one [`StepContext`]: [`Simulation::advance`] calls
//! them in order, each reading what the earlier ones left in the context and timed into
//! the profile under its [`Stage`]:
//!
//! 1. [`Simulation::contacts_at_start`] ([`Stage::BroadPhase`], [`Stage::StartContacts`]):
//!    impacts due now, surfaces catching particles, strings snapping taut or going slack;
//!    the step's start kept to integrate again from;
//! 2. [`Simulation::integrate`] ([`Stage::Integration`]): the trial step of the smooth
//!    forces, then [`Simulation::events_inside`]: shortened to a string's event or a
//!    turning particle starting to roll;
//! 3. [`Simulation::impacts_inside`] ([`Stage::TimeOfImpact`], [`Stage::CoupledImpacts`]):
//!    impacts on the paths through the step, applied in time order; a coupled impact
//!    answered inside the step, or the whole system integrated to one that ends it; the
//!    step's length is then final, and [`Simulation::end_time`] sets the clock;
//! 4. [`Simulation::resting`] ([`Stage::RestingSolver`]): a string's event applied,
//!    touching particles kept apart, turning particles turned, and the ledger's books;
//! 5. [`Simulation::projection`]: positions and velocities back onto the rods' and
//!    taut strings' lengths;
//! 6. [`Simulation::end_step`]: the rigid bodies moved through the step, and the checks.

use super::{Simulation, SimulationError, diagnostics, impact_energy_lost};
use crate::contacts::Impact;
use crate::forces::Power;
use crate::integrators;
use crate::profile::Stage;

/// What one step carries from stage to stage.
pub(super) struct StepContext {
    /// The longest the step may be, seconds: the time step, or less to land on a target.
    max_step: f64,
    /// The instant the step lands on when it is taken whole: the end of a run, whose
    /// clock then reads it exactly rather than the start plus the step's length.
    lands_on: Option<f64>,
    /// The step as taken so far, seconds: the trial step, then shortened to the first
    /// event or impact that ends it.
    pub(super) taken: f64,
    /// How many impacts had been applied before this step's own: the contacts' applied
    /// impacts from this index on are those inside the step.
    begun: usize,
    /// With a ledger: what the step's start took.
    start_books: Option<StartBooks>,
    /// A string that snaps taut or goes slack inside the step: its index and instant,
    /// applied at the step's end.
    tie_event: Option<(usize, f64)>,
    /// The impact the step ends at, the whole system integrated to it.
    struck: Option<Impact>,
    /// With a ledger: the dissipated power over the step, when it was measured before the
    /// impact that ends the step was applied.
    power_before_struck: Option<PowerOverStep>,
    /// Whether a stage after the integration moved anything: the acceleration the
    /// integrator kept for the next step's start is then not that state's, and the step's
    /// end forgets it ([`Simulation::advance`], the one place that does).
    pub(super) moved: bool,
}

/// What the step's start took from the motion impulsively (impacts due, surfaces
/// catching, strings snapping; less the potential energy a catch's lift gave), joules,
/// and the dissipated power then.
#[derive(Clone, Copy)]
struct StartBooks {
    caught: f64,
    power: Power,
}

/// The dissipated power (damping, friction, drag) half way through the step and at its end.
#[derive(Clone, Copy, Default)]
struct PowerOverStep {
    middle: Power,
    end: Power,
}

/// The ledger's view of the step just before the resting solver.
#[derive(Clone, Copy)]
struct EndBooks {
    power: PowerOverStep,
    /// The kinetic energy then, joules.
    kinetic: f64,
    /// The work of surfaces' normal forces on particles moving along their normals, and
    /// what surfaces released, joules.
    supported: f64,
}

impl Simulation {
    /// One step of at most `max_step` seconds, landing on `lands_on` when taken whole:
    /// every stage in order.
    pub(super) fn advance(
        &mut self,
        max_step: f64,
        lands_on: Option<f64>,
    ) -> Result<(), SimulationError> {
        self.profiler.start();
        let mut step = self.contacts_at_start(max_step, lands_on);
        self.integrate(&mut step)?;
        self.events_inside(&mut step);
        self.profiler.lap(Stage::Integration);
        self.impacts_inside(&mut step);
        self.end_time(&step);
        self.log_impacts();
        let books = self.books_before_settling(&step);
        self.resting(&mut step, books);
        self.profiler.lap(Stage::RestingSolver);
        self.projection(&mut step)?;
        if step.moved {
            self.work.start_acceleration = None;
        }
        self.end_step(step.taken)
    }

    /// Stage 1: what happens at the step's start ([`Self::begin`]), the start kept, and
    /// the turning particles' spins noted.
    fn contacts_at_start(&mut self, max_step: f64, lands_on: Option<f64>) -> StepContext {
        let start_books = self.begin(max_step);
        let begun = self.contacts.report.applied.len();
        self.start.clone_from(&self.state);
        if let Some(turning) = &mut self.contacts.turning {
            turning.begin_step();
        }
        StepContext {
            max_step,
            lands_on,
            taken: max_step,
            begun,
            start_books,
            tie_event: None,
            struck: None,
            power_before_struck: None,
            moved: false,
        }
    }

    /// Stage 2: the smooth forces over the trial step, by the coupled particles' own
    /// system where it is split ([`Self::split_trial_step`]), else by the scene's method.
    fn integrate(&mut self, step: &mut StepContext) -> Result<(), SimulationError> {
        step.taken = if self.split_trial_step(step.max_step) {
            step.max_step
        } else {
            integrators::advance(
                self.integrator,
                &self.forces,
                &mut self.state,
                step.max_step,
                self.tolerance,
                &mut self.work,
            )
            .map_err(|_| SimulationError::StepTooSmall {
                time: self.state.time,
                tolerance: self.tolerance,
            })?
        };
        // A blown-up trial step stops here: the searches below assume a sane state.
        self.check_finite()
    }

    /// Stage 2, its end: the trial step shortened to a string's event or a turning
    /// particle starting to roll ([`Self::shorten_trial_step`]).
    fn events_inside(&mut self, step: &mut StepContext) {
        (step.tie_event, step.taken) = self.shorten_trial_step(step.taken);
    }

    /// Stage 3: the impacts on the paths through the step, in time order; the first that
    /// interrupts it answered inside the step for coupled particles, or the step ended
    /// at it, the whole system integrated there.
    fn impacts_inside(&mut self, step: &mut StepContext) {
        let interruption = self.contacts.resolve_impacts(
            &self.start,
            &mut self.state,
            step.taken,
            &self.forces,
            &mut self.profiler,
        );
        step.moved |= self.contacts.changed_paths();
        if let Some(first) = interruption.filter(|_| self.coupled_in_step()) {
            self.coupled_impacts_in_step(first, step);
            self.profiler.lap(Stage::CoupledImpacts);
        } else if let Some((time, impact)) = interruption {
            // The impact comes first; a string's event, if still due, is found again.
            step.tie_event = None;
            let trial = step.taken;
            step.taken = self.integrate_to_impact(time, trial, impact);
            self.contacts.patch(&mut self.state, step.taken, trial);
            if self.ledger.is_some() {
                step.power_before_struck = Some(self.power_over_step(step.taken));
            }
            self.contacts
                .apply(impact, &mut self.state, &self.forces, step.taken);
            self.answer_through_ties(impact);
            step.moved = true;
            step.struck = Some(impact);
            self.profiler.lap(Stage::CoupledImpacts);
        }
    }

    /// The clock, once the step's length is final (the impacts inside it found): the
    /// one place it is set. The stages before integrate states of their own times; the
    /// simulation's reads the start plus the step taken, or the instant it lands on.
    fn end_time(&mut self, step: &StepContext) {
        self.state.time = match step.lands_on {
            Some(end) if step.taken >= step.max_step => end,
            _ => self.start.time + step.taken,
        };
    }

    /// With a ledger, what it needs of the step before the resting solver moves anything.
    fn books_before_settling(&self, step: &StepContext) -> Option<EndBooks> {
        self.ledger.map(|_| {
            let power = step
                .power_before_struck
                .unwrap_or_else(|| self.power_over_step(step.taken));
            let supported = self.forces.surface_normal_work(
                self.state.time,
                &self.start.position,
                &self.state.position,
                &self.state.velocity,
                &self.radius,
            ) + self.contacts.report.released;
            EndBooks {
                power,
                kinetic: self.forces.kinetic_energy(&self.state.velocity),
                supported,
            }
        })
    }

    /// Stage 4: a string's event applied, the turning particles turned through the
    /// step, resting contact ([`Self::settle`]), and the step booked. The turning comes
    /// first: a rolling particle's spin follows what the smooth forces did to its speed,
    /// and the resting solver's pushes then turn it only through the friction they meet.
    fn resting(&mut self, step: &mut StepContext, books: Option<EndBooks>) {
        if let Some((k, _)) = step.tie_event {
            self.apply_tie_event(k);
            step.moved = true;
        }
        let slipped = self.end_turning(step.taken, step.begun);
        let spinning = books.map(|_| self.rotational_energy());
        let lifted = self.settle(step);
        if let (Some(start), Some(end)) = (step.start_books, books) {
            // What the resting solver's friction took from the spins, with its pushes.
            let despun = spinning.unwrap_or(0.0) - self.rotational_energy();
            self.book(step, start, end, end.supported + lifted - despun);
            self.book_friction(step.begun, slipped);
        }
    }

    /// Stage 5: positions and velocities back onto the rods' and taut strings' lengths.
    fn projection(&mut self, step: &mut StepContext) -> Result<(), SimulationError> {
        if !self.forces.constraints.is_empty() {
            step.moved = true;
            // A value gone non-finite is the first thing wrong, and says so.
            self.project_onto_ties()
                .or_else(|tie| self.check_finite().and(Err(tie)))?;
        }
        Ok(())
    }

    /// Stage 6, the step's last: the bodies moved through it, the count, and the checks
    /// that every value is finite and every particle still inside the bounds.
    fn end_step(&mut self, taken: f64) -> Result<(), SimulationError> {
        let books = self.bodies.advance(self.integrator, taken);
        if let Some((pulley, body)) = self.bodies.pulley_reached() {
            return Err(SimulationError::PulleyReached {
                pulley,
                body,
                time: self.state.time,
            });
        }
        if let Some(ledger) = &mut self.ledger {
            ledger.impacts += books.impacts;
            ledger.friction += books.friction;
            ledger.motors += books.motors;
        }
        self.steps += 1;
        self.check_finite()?;
        if let Some(i) = self
            .contacts
            .escaped(&self.state.position, |i| !self.forces.is_fixed(i))
        {
            return Err(SimulationError::LeftBounds {
                particle: self.names[i].clone(),
                time: self.state.time,
                speed: self.state.velocity[i].length(),
            });
        }
        Ok(())
    }

    /// The step's start: impacts due now, strings snapping taut, surfaces catching
    /// particles. With a ledger, returns the energy they took (the kinetic energy, less
    /// the potential energy a catch's lift onto its surface gave) and the dissipated power
    /// then.
    fn begin(&mut self, max_step: f64) -> Option<StartBooks> {
        let before = self
            .ledger
            .map(|_| (self.kinetic_energy(), self.state.position.clone()));
        let caught = self.contacts.begin_step(
            &mut self.state,
            &mut self.forces,
            max_step,
            &mut self.profiler,
        );
        // What the start moved is not where the last step's kept acceleration was taken.
        if caught | self.begin_ties(max_step) {
            self.work.start_acceleration = None;
        }
        before.map(|(kinetic, position)| {
            let (x, v) = (&self.state.position, &self.state.velocity);
            let lifted = diagnostics::potential_change(&self.forces, &position, x);
            let caught = kinetic - self.kinetic_energy() - lifted;
            StartBooks {
                caught,
                power: self.forces.dissipation(self.state.time, x, v),
            }
        })
    }

    /// Resting contact at the step's end ([`Contacts::settle`]). With a ledger, returns
    /// the potential energy its position correction gave (a pile at rest sinks ½ g h² a
    /// step under gravity, and the correction lifts it back), or 0.
    fn settle(&mut self, step: &mut StepContext) -> f64 {
        let before = self.ledger.map(|_| self.state.position.clone());
        step.moved |= self
            .contacts
            .settle(&mut self.state, &self.forces, step.taken, step.struck);
        before.map_or(0.0, |position| {
            diagnostics::potential_change(&self.forces, &position, &self.state.position)
        })
    }

    /// The dissipated power (damping, friction) half way through the step just taken
    /// (`taken` seconds from `self.start` to `self.state`), on the cubic through both
    /// ends' positions and velocities, and at its end.
    fn power_over_step(&self, taken: f64) -> PowerOverStep {
        if !self.forces.dissipates() {
            return PowerOverStep::default();
        }
        let (start, end) = (&self.start, &self.state);
        let h = taken;
        let (mut x, mut v) = (Vec::with_capacity(end.len()), Vec::with_capacity(end.len()));
        for i in 0..end.len() {
            let (x0, v0, x1, v1) = (
                start.position[i],
                start.velocity[i],
                end.position[i],
                end.velocity[i],
            );
            x.push((x0 + x1) * 0.5 + (v0 - v1) * (h / 8.0));
            v.push((x1 - x0) * (1.5 / h) - (v0 + v1) * 0.25);
        }
        PowerOverStep {
            middle: self.forces.dissipation(start.time + 0.5 * h, &x, &v),
            end: self
                .forces
                .dissipation(end.time, &end.position, &end.velocity),
        }
    }

    /// Adds the step to the ledger: `start` is what its start took impulsively and the
    /// dissipated power there; `end`, the power over it and the kinetic energy before the
    /// resting solver; the impacts inside it are those applied from the context's
    /// `begun` on; `moved` is the energy the contacts gave the motion otherwise: the
    /// potential energy of particles they moved (a correction lifting a sunken pile) and
    /// the work of surfaces' normal forces on particles moving along their normals.
    fn book(&mut self, step: &StepContext, start: StartBooks, end: EndBooks, moved: f64) {
        let Some(ledger) = &mut self.ledger else {
            return;
        };
        let (p0, pm, p1) = (start.power, end.power.middle, end.power.end);
        // Simpson's rule over the step.
        let simpson =
            |of: fn(&Power) -> f64| (of(&p0) + 4.0 * of(&pm) + of(&p1)) * step.taken / 6.0;
        ledger.damping += simpson(|p| p.damping);
        ledger.friction += simpson(|p| p.friction);
        ledger.drag += simpson(|p| p.drag);
        let w = &self.forces.inverse_mass;
        let in_step: f64 = self.contacts.report.applied[step.begun..]
            .iter()
            .map(|applied| impact_energy_lost(applied, w))
            .sum();
        let settled = end.kinetic - self.forces.kinetic_energy(&self.state.velocity);
        ledger.impacts += start.caught + in_step + self.contacts.report.caught + settled - moved;
    }

    /// The trial step of `taken` seconds just integrated, shortened to the first event
    /// inside it: a string snapping taut or going slack (returned, to apply at the step's
    /// end), or a turning particle starting to roll. Returns the event and the step.
    fn shorten_trial_step(&mut self, mut taken: f64) -> (Option<(usize, f64)>, f64) {
        let mut tie_event = self.find_tie_event(taken);
        if let Some((_, time)) = tie_event {
            taken = time;
        }
        if let Some(time) = self.find_rolling_start(taken) {
            // Slipping stops first: the step ends there, and a string's event, if still
            // due, is found again.
            tie_event = None;
            taken = time;
        }
        (tie_event, taken)
    }
}
