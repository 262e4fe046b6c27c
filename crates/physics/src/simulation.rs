//! A running scene: built from a [`Scene`], advanced in time, read at any instant.
//!
//! One step, in order (the whole pipeline is [`Simulation::advance`]):
//! 1. contacts at the start: impacts happening now are applied, and particles resting on
//!    ramps and walls are put under their normal force and friction; strings at full
//!    length whose ends separate snap taut, and each string is chosen taut or slack;
//! 2. the smooth forces (fields, pairs, springs, surfaces, and the exact forces of rods
//!    and taut strings) are integrated over a trial step of at most the time step;
//! 3. a string that snapped taut or went slack inside the trial step shortens it to that
//!    instant (`simulation/ties.rs`);
//! 4. impacts inside the (trial) step are located and applied in time order: on their
//!    paths for particles moved only by the field; for particles feeling pairwise forces
//!    or springs, by integrating those particles alone to exactly that instant and on to
//!    the step's end (`simulation/coupled.rs`); with rods or strings, by integrating the
//!    whole system to that instant, where the step ends; then the string's event, unless
//!    an impact came first;
//! 5. resting contacts between particles are resolved (no approach, no growing overlap);
//! 6. positions and velocities are projected back onto the rods' and strings' lengths;
//! 7. the new state is checked for non-finite values, which stop the run with the
//!    particle's name and the time.
//!
//! `step_to(t)` shortens the last step so that it lands exactly on `t`: a sample at
//! `t` is the state at `t`, not at the nearest step.

mod books;
mod coupled;
mod error;
mod read;
mod step;
mod ties;

use crate::impact::{ImpactRecord, ImpactTarget};
pub use books::Ledger;
use books::{effective_mass, impact_energy_lost};
pub use error::SimulationError;

use glam::DVec2;

use crate::contacts::{Contacts, Impact};
use crate::diagnostics;
use crate::forces::ForceModel;
use crate::integrators::{self, Workspace};
use crate::method::Integrator;
use crate::profile::{Clock, Profile, Profiler};
use crate::scene::error::LoadError;
use crate::scene::{Particle, Scene, Vector};
use crate::state::State;
use crate::turning::{Kick, Sizes};

/// What [`Simulation::step_to_observed`] calls after each step: the state before it and
/// after.
pub(crate) type Observer<'a> =
    dyn FnMut(&Simulation, &Simulation) -> Result<(), SimulationError> + Send + 'a;

/// A scene in motion.
#[derive(Clone, Debug)]
pub struct Simulation {
    /// Shared between copies: a keyframe of the time machine does not copy them.
    names: std::sync::Arc<[String]>,
    /// The rods' and strings' names, in the order of [`Scene::ties`].
    tie_names: std::sync::Arc<[String]>,
    /// The springs' names, in the order of [`Scene::springs`].
    spring_names: std::sync::Arc<[String]>,
    radius: std::sync::Arc<[f64]>,
    forces: ForceModel,
    contacts: Contacts,
    /// The coupled particles as a system of their own, for their impacts inside a step.
    coupled: Option<coupled::CoupledSystem>,
    state: State,
    /// The rigid bodies, moved through each step the particles take.
    pub(crate) bodies: crate::bodies::Bodies,
    /// The state at the start of the step being taken, to integrate again from it when
    /// an impact interrupts the step.
    start: State,
    integrator: Integrator,
    time_step: f64,
    tolerance: f64,
    work: Workspace,
    steps: u64,
    /// Impacts so far, when asked for with [`Simulation::record_impacts`].
    impact_log: Option<Vec<ImpactRecord>>,
    /// Where the energy taken out of the motion went, when asked for.
    ledger: Option<Ledger>,
    /// Time per stage, when a clock is lent with [`Simulation::set_clock`].
    profiler: Profiler,
}

impl Simulation {
    /// Builds the runtime state of a scene, at its start time (0 unless it was saved
    /// from a run).
    ///
    /// # Errors
    /// The scene's problems, as [`Scene::validate`] lists them.
    pub fn new(scene: &Scene) -> Result<Self, LoadError> {
        let problems = scene.validate();
        if !problems.is_empty() {
            return Err(LoadError { problems });
        }
        let particles = &scene.particles;
        let forces = ForceModel::new(scene);
        let contacts = Contacts::new(scene, &forces);
        let coupled = coupled::CoupledSystem::new(&forces, contacts.coupled());
        let mut simulation = Self {
            names: scene.particle_names().into(),
            tie_names: scene.ties.iter().map(|t| t.name.clone()).collect(),
            spring_names: scene.springs.iter().map(|s| s.name.clone()).collect(),
            radius: particles.iter().map(|p| p.radius).collect(),
            contacts,
            coupled,
            forces,
            bodies: crate::bodies::Bodies::new(scene),
            start: State::default(),
            state: State {
                time: scene.simulation.start_time,
                position: particles.iter().map(|p| p.position.to_dvec2()).collect(),
                velocity: particles.iter().map(Particle::initial_velocity).collect(),
            },
            integrator: scene.simulation.integrator,
            time_step: scene.simulation.time_step,
            tolerance: scene.simulation.tolerance,
            work: Workspace::default(),
            steps: 0,
            impact_log: None,
            ledger: None,
            profiler: Profiler::default(),
        };
        simulation.begin_ties_at_start();
        simulation.bodies.settle(simulation.time_step);
        // Contacts from the start: a particle placed on a ramp is held by it at t = 0.
        simulation.contacts.begin_step(
            &mut simulation.state,
            &mut simulation.forces,
            simulation.time_step,
            &mut simulation.profiler,
        );
        Ok(simulation)
    }

    /// `scene` (the one this simulation was built from) with the state reached: each
    /// particle's position and velocity now, in Cartesian form, and the start time now.
    /// A simulation built from it continues this one; what it does not carry is the
    /// contact solver's memory (its warm start) and dopri5's last step size, so a
    /// continued run agrees to rounding, not bit for bit.
    #[must_use]
    pub fn saved_state(&self, scene: &Scene) -> Scene {
        let mut saved = scene.clone();
        for (i, particle) in saved.particles.iter_mut().enumerate() {
            let (x, v) = (self.state.position[i], self.state.velocity[i]);
            particle.position = Vector::cartesian(x.x, x.y);
            if !particle.fixed {
                particle.velocity = Vector::cartesian(v.x, v.y);
            }
            if let Some(turning) = self.contacts.turning.as_ref().filter(|_| particle.turns()) {
                particle.spin = turning.spin[i];
                particle.angle = turning.angle[i];
            }
        }
        self.bodies.save_into(&mut saved);
        saved.simulation.start_time = self.state.time;
        saved
    }

    /// Starts the energy ledger at zero, read with [`Self::ledger`].
    pub fn keep_ledger(&mut self) {
        self.ledger = Some(Ledger::default());
    }

    /// The energy ledger since [`Self::keep_ledger`], if it was started.
    pub fn ledger(&self) -> Option<Ledger> {
        self.ledger
    }

    /// Starts keeping a log of impacts, read with [`Self::take_impacts`].
    pub fn record_impacts(&mut self) {
        self.impact_log.get_or_insert_with(Vec::new);
        self.contacts.logs_start = true;
    }

    /// The impacts since the last call (empty unless [`Self::record_impacts`] was called).
    pub fn take_impacts(&mut self) -> Vec<ImpactRecord> {
        self.impact_log
            .as_mut()
            .map(std::mem::take)
            .unwrap_or_default()
    }

    /// Starts measuring the time each stage of the step takes, read with
    /// [`Self::profile`], with `clock` (seconds since any fixed instant); `None` stops.
    /// The work that may be split across threads is timed too (whether it is split or
    /// not), for [`Profile::parallel_seconds`].
    pub fn set_clock(&mut self, clock: Option<Clock>) {
        self.profiler = Profiler::new(clock);
        // One timing for both copies of the workers, the forces' and the contacts'.
        let mut workers = self.contacts.workers.clone();
        workers.time_regions(clock);
        self.forces.workers = workers.clone();
        self.contacts.workers = workers;
    }

    /// Seconds spent in each stage since [`Self::set_clock`], and in work that may be
    /// split across threads.
    pub fn profile(&self) -> Profile {
        let mut profile = self.profiler.profile;
        profile.parallel = self.contacts.workers.region_seconds();
        profile
    }

    /// Lets the contact search and the direct pair sum use `threads` threads (0 or 1:
    /// the calling thread only; default 1). The results are bit-identical for every
    /// thread count. Builds without threads (wasm32, or without the `parallel` feature)
    /// always use one.
    pub fn set_threads(&mut self, threads: usize) {
        let mut workers = crate::parallel::Workers::new(threads);
        workers.keep_timing(&self.contacts.workers);
        self.forces.workers = workers.clone();
        self.contacts.workers = workers;
    }

    /// The threads the contact search uses.
    pub fn threads(&self) -> usize {
        self.contacts.workers.threads()
    }

    /// Simulated time, seconds.
    pub fn time(&self) -> f64 {
        self.state.time
    }

    /// The number of particles.
    pub fn len(&self) -> usize {
        self.state.len()
    }

    /// Whether the scene has no particles.
    pub fn is_empty(&self) -> bool {
        self.state.len() == 0
    }

    /// A copy of this simulation without its scratch buffers (the step's start, the
    /// integrator's stages, the contact search's lists, the broad phase's grid), which
    /// every step fills again before it reads them, and sharing what never changes (the
    /// names, masses, charges, fields, radii): stepped on, it gives the same bits as
    /// this simulation would (`tests/determinism.rs`), in about a tenth of the memory.
    /// The time machine's keyframes are such copies.
    #[must_use]
    pub fn keyframe(&self) -> Self {
        let mut copy = self.clone();
        copy.start = State::default();
        copy.work.drop_scratch();
        copy.contacts.drop_scratch();
        if let Some(coupled) = &mut copy.coupled {
            coupled.drop_scratch();
        }
        copy
    }

    /// About how many bytes a [`Self::keyframe`] of this simulation holds: its arrays
    /// counted by length (an estimate: it leaves out allocators' rounding). What never
    /// changes in a run — the names, masses, charges, fields and radii — is shared
    /// between copies and not counted.
    pub fn keyframe_bytes(&self) -> usize {
        let n = self.len();
        let per_particle = 2 * size_of::<DVec2>() // the state
            + 1; // whether coupled
        let kept_acceleration = self
            .work
            .start_acceleration
            .as_ref()
            .map_or(0, |a| a.len() * size_of::<DVec2>());
        size_of::<Self>()
            + n * per_particle
            + self.contacts.memory_bytes()
            + self.forces.links_bytes()
            + kept_acceleration
            + self.bodies.state_bytes()
    }

    /// Advances by one time step.
    ///
    /// # Errors
    /// When the state becomes non-finite or the adaptive integrator fails.
    pub fn step(&mut self) -> Result<(), SimulationError> {
        self.step_to(self.state.time + self.time_step)
    }

    /// Advances to exactly `time` seconds (nothing happens if that is not in the future).
    ///
    /// # Errors
    /// When the state becomes non-finite or the adaptive integrator fails; the state is
    /// then the one at which the failure was found.
    pub fn step_to(&mut self, time: f64) -> Result<(), SimulationError> {
        self.step_to_observed(time, None)
    }

    /// [`Self::step_to`], calling `observe(before, after)` after every step with a
    /// [`Self::keyframe`] of the state before it (taken only when there is an observer)
    /// and the state after. The steps are the same, with the same bits, either way.
    pub(crate) fn step_to_observed(
        &mut self,
        time: f64,
        observe: Option<&mut Observer<'_>>,
    ) -> Result<(), SimulationError> {
        // Run on a thread of the pool when a step has work to share out: see
        // `Workers::inside` (entering the pool costs more than a small scene's step
        // wins back).
        let shares = self.forces.shares_pairs() || self.state.len() >= crate::tuning::STRIPS_FROM;
        if shares && self.contacts.workers.threads() > 1 {
            let workers = self.contacts.workers.clone();
            return workers.inside(|| self.step_to_here(time, observe));
        }
        self.step_to_here(time, observe)
    }

    /// [`Self::step_to_observed`] on the calling thread.
    fn step_to_here(
        &mut self,
        time: f64,
        mut observe: Option<&mut Observer<'_>>,
    ) -> Result<(), SimulationError> {
        // Every loop here is bounded: dopri5 may take many more steps than the time step
        // implies (a close pass), but not a thousand times more on average over the
        // interval: that says the time step is far too long for the motion, and would
        // take seconds for a handful of particles.
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a count of steps, capped far below u64::MAX"
        )]
        let limit = ((time - self.state.time) / self.time_step)
            .ceil()
            .clamp(1.0, 1e12) as u64
            * 1_000;
        let mut taken_steps = 0_u64;
        while self.state.time < time {
            taken_steps += 1;
            if taken_steps > limit {
                return Err(SimulationError::TooManySteps {
                    time: self.state.time,
                    target: time,
                    time_step: self.time_step,
                    limit,
                });
            }
            let before = observe.is_some().then(|| self.keyframe());
            let remaining = time - self.state.time;
            // Within a hair of the target, one step lands on it: no sliver steps.
            let last = remaining <= self.time_step * (1.0 + 1e-9);
            let step = if last { remaining } else { self.time_step };
            self.check_drag(step)?;
            self.advance(step, last.then_some(time))?;
            if let (Some(observe), Some(before)) = (observe.as_deref_mut(), before) {
                observe(&before, self)?;
            }
        }
        Ok(())
    }

    /// Whether a fixed-step method can follow every particle's air resistance over a
    /// step of `h` ([`crate::tuning::DRAG_STEP`]); dopri5 shrinks its steps to it.
    fn check_drag(&self, h: f64) -> Result<(), SimulationError> {
        if self.integrator == Integrator::Dopri5 {
            return Ok(());
        }
        let velocity = &self.state.velocity;
        for drag in &self.forces.drag {
            let rate = drag.rate(velocity, self.forces.mass[drag.particle]);
            if rate * h > crate::tuning::DRAG_STEP {
                return Err(SimulationError::DragTooStrong {
                    particle: self.names[drag.particle].clone(),
                    time: self.state.time,
                    decay: 1.0 / rate,
                    time_step: h,
                });
            }
        }
        Ok(())
    }

    fn check_finite(&self) -> Result<(), SimulationError> {
        match self.state.first_non_finite() {
            Some(i) => Err(SimulationError::NonFinite {
                particle: self.names[i].clone(),
                time: self.state.time,
            }),
            None => Ok(()),
        }
    }

    /// Adds the impacts applied in this step to the log, if one is kept.
    /// An impact just applied to particles tied by rods or strings, answered through
    /// them ([`crate::constraints::Constraints::answer_impact`]): the contact's impulse
    /// becomes the tied system's, and its record the effective mass that took it.
    fn answer_through_ties(&mut self, impact: Impact) {
        if self.forces.constraints.is_empty() {
            return;
        }
        let (_, normal, _) = self.contacts.measure(impact, &self.state);
        let row = match impact {
            Impact::Obstacle(p, _) => vec![(p, normal)],
            Impact::Pair(i, j) => vec![(i, -normal), (j, normal)],
        };
        let constraints = &self.forces.constraints;
        if !row.iter().any(|&(p, _)| constraints.touches(p)) {
            return; // nothing it struck is tied
        }
        let before = self.state.velocity.clone();
        let Some(further) = self.forces.constraints.answer_impact(
            &self.state.position,
            &mut self.state.velocity,
            &self.forces.inverse_mass,
            &row,
        ) else {
            return;
        };
        let w = &self.forces.inverse_mass;
        let Some(applied) = self.contacts.report.applied.last_mut() else {
            return;
        };
        let change = applied.approach * (1.0 + applied.restitution);
        let impulse = effective_mass(applied, w) * change + further;
        if impulse < 0.0 || change <= 0.0 {
            // The links would have the contact pull: the impact stands alone, and the
            // step's projection answers it as before.
            self.state.velocity = before;
            return;
        }
        applied.tied = Some(impulse / change);
    }

    fn log_impacts(&mut self) {
        if let Some(log) = &mut self.impact_log {
            let w = &self.forces.inverse_mass;
            for applied in &self.contacts.report.applied {
                let (particle, other) = match applied.impact {
                    Impact::Pair(i, j) => (i, ImpactTarget::Particle(j)),
                    Impact::Obstacle(p, k) => (p, self.contacts.obstacle_target(k)),
                };
                let (u, e) = (applied.approach, applied.restitution);
                log.push(ImpactRecord {
                    time: self.start.time + applied.time,
                    particle,
                    other,
                    impulse: effective_mass(applied, w) * (1.0 + e) * u,
                    normal_speed_before: u,
                    normal_speed_after: e * u,
                    kinetic_energy_lost: impact_energy_lost(applied, w) + applied.grip.lost,
                });
            }
        }
    }

    /// The instant, seconds into the trial step of `taken` just integrated, at which the
    /// first turning particle that slips on its surface stops slipping, if one does:
    /// where the slip of its contact point, v·t − ω r, reaches zero. Its spin changes at
    /// a fixed rate through the step, and under forces fixed for the step so does its
    /// velocity: the slip is linear, and one interpolation finds the instant; otherwise
    /// the secant method refines it on the integrated state. The state is then the one at
    /// the instant returned.
    fn find_rolling_start(&mut self, taken: f64) -> Option<f64> {
        let turning = self.contacts.turning.as_ref()?;
        let start = turning.slips(&self.start.velocity, &self.radius, 0.0);
        if start.is_empty() {
            return None;
        }
        let end = turning.slips(&self.state.velocity, &self.radius, taken);
        let (index, mut time) = start
            .iter()
            .zip(&end)
            .enumerate()
            .filter(|(_, ((_, s0), (_, s1)))| {
                *s0 != 0.0 && (s1.signum() != s0.signum() || *s1 == 0.0)
            })
            .map(|(k, ((_, s0), (_, s1)))| (k, taken * (s0 / (s0 - s1))))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        if !(time > 0.0 && time < taken) {
            return None;
        }
        let p = start[index].0;
        let (mut before, mut after) = ((0.0, start[index].1), (taken, end[index].1));
        for _ in 0..4 {
            self.integrate_from_start(time);
            let turning = self.contacts.turning.as_ref()?;
            let slip = turning.slips(&self.state.velocity, &self.radius, time)[index].1;
            let scale =
                self.state.velocity[p].length() + (turning.start_spin[p] * self.radius[p]).abs();
            if slip.abs() <= crate::tuning::ROLLING * scale {
                break;
            }
            if slip.signum() == before.1.signum() {
                before = (time, slip);
            } else {
                after = (time, slip);
            }
            let refined = before.0 + (after.0 - before.0) * (before.1 / (before.1 - after.1));
            if !(refined > before.0 && refined < after.0) {
                break;
            }
            time = refined;
        }
        Some(time)
    }

    /// Turns the turning particles through the step just taken (`taken` seconds; the
    /// impacts inside it are those applied from `begun` on). Returns the energy their
    /// slipping on surfaces took, joules.
    fn end_turning(&mut self, taken: f64, begun: usize) -> f64 {
        let Some(turning) = &mut self.contacts.turning else {
            return 0.0;
        };
        let mut kicks = Vec::new();
        for applied in &self.contacts.report.applied[begun..] {
            let (first, second) = match applied.impact {
                Impact::Pair(i, j) => (i, Some(j)),
                Impact::Obstacle(p, _) => (p, None),
            };
            kicks.push(Kick {
                time: applied.time,
                particle: first,
                velocity: applied.kick.0,
                spin: applied.grip.spin.0,
            });
            if let Some(j) = second {
                kicks.push(Kick {
                    time: applied.time,
                    particle: j,
                    velocity: applied.kick.1,
                    spin: applied.grip.spin.1,
                });
            }
        }
        let sizes = Sizes {
            mass: &self.forces.mass,
            radius: &self.radius,
        };
        turning.end_step(taken, &self.start, &self.state, sizes, &kicks)
    }

    /// Adds friction's share of the step to the ledger: at impacts between turning
    /// bodies (those at the step's start, applied from `begun` back, were booked with
    /// the impacts by [`Self::begin`]'s energy) and in slipping, `slipped` joules.
    fn book_friction(&mut self, begun: usize, slipped: f64) {
        let Some(ledger) = &mut self.ledger else {
            return;
        };
        let applied = &self.contacts.report.applied;
        let at_start: f64 = applied[..begun].iter().map(|a| a.grip.lost).sum();
        let inside: f64 = applied[begun..].iter().map(|a| a.grip.lost).sum();
        ledger.friction += at_start + inside + slipped;
        ledger.impacts -= at_start;
    }

    /// Integrates from the step's start to the instant of `impact`, first estimated at
    /// `estimate` seconds into a step of `limit`, refined by Newton's method on the gap of
    /// the integrated state (the path used to find it is only an interpolation). Returns
    /// the time integrated.
    fn integrate_to_impact(&mut self, estimate: f64, limit: f64, impact: Impact) -> f64 {
        let reach = self.contacts.reach(impact);
        refine_instant(estimate, Bracket { after: 0.0, limit }, reach, |time| {
            self.integrate_from_start(time);
            let (gap, _, approach) = self.contacts.measure(impact, &self.state);
            (gap, approach)
        })
    }

    /// The state integrated from the step's start for `time` seconds, exactly.
    fn integrate_from_start(&mut self, time: f64) {
        self.state.clone_from(&self.start);
        integrators::advance_exactly(
            self.integrator,
            &self.forces,
            &mut self.state,
            time,
            &mut self.work,
        );
    }
}

/// Where an instant may lie, seconds into a step: after `after`, at `limit` at most.
#[derive(Clone, Copy, Debug)]
struct Bracket {
    after: f64,
    limit: f64,
}

impl Bracket {
    /// After `after`, at `limit` at most.
    const fn new(after: f64, limit: f64) -> Self {
        Self { after, limit }
    }
}

/// The instant of an impact by Newton's method on its gap: `gap_at(t)` brings the state
/// to `t` seconds into the step (integrating it) and returns the gap and the approach
/// speed there. Starts at `estimate`, stays inside (`after`, `limit`], and stops within
/// 1e-12 of the impact's `reach`, when the bodies no longer approach, or after four
/// tries; the state is then the one at the instant returned.
fn refine_instant(
    estimate: f64,
    Bracket { after, limit }: Bracket,
    reach: f64,
    mut gap_at: impl FnMut(f64) -> (f64, f64),
) -> f64 {
    let tolerance = 1e-12 * reach;
    let mut time = estimate;
    for attempt in 0..4 {
        let (gap, approach) = gap_at(time);
        if gap.abs() <= tolerance || approach <= 0.0 || attempt == 3 {
            break;
        }
        let refined = time + gap / approach;
        if !(refined > after && refined <= limit) || (refined - time).abs() <= f64::EPSILON * time {
            break;
        }
        time = refined;
    }
    time
}
