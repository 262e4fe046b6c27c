//! Impacts of coupled particles inside the step, without ending it.
//!
//! A particle that feels pairwise forces or springs is *coupled*: an impulse on it
//! changes the forces on the others it pulls, so its impact cannot be patched onto a path
//! as an uncoupled particle's is. The coupled particles (with the fixed ones that pull
//! on them) form a system of their own, closed: no force on them comes from outside it
//! but the fields and the surfaces they rest on. With rk4, an impact of a coupled particle
//! `τ` seconds into the step is applied on that system's motion through the step and
//! answered to first order and beyond by everything the struck particle pulls, without
//! integrating again ([`response`]). With the other methods that system alone is
//! integrated from its last impact (or the step's start) to exactly `τ` (refined by
//! Newton's method on its gap), the impulse applied, and the system integrated on to the
//! step's end. Either way its paths then start again at `τ`
//! ([`Contacts::restart_paths`]) and the search goes on inside the same step.
//!
//! So a coupled impact costs a response (rk4) or an integration of the coupled particles,
//! not a new step of everything (broad phase, trial step, impact search, resting solver).
//! Integrating again, the state at each impact is the integrator's, from the state at the
//! impact before it, as when each impact ended the step. Newton's method integrates
//! once, to the instant the search estimated; its corrections (of order 1e-10 s) carry
//! that state on by its acceleration to second order instead of integrating again
//! ([`CARRIED`]), which leaves out terms of order 1e-21 m. The integration to the step's
//! end and the one to the next impact start from the same state: with rk4 the second
//! reuses the first's first stage ([`KnownStart`]), one evaluation of four, same bits.
//!
//! Not used (each coupled impact still ends the step) with rods or strings, whose events
//! and projections are the whole step's, with forces on a particle alone that the
//! members' single accelerations leave out (the magnetic field, forces of one's own), and while anything dissipates smoothly (a damped
//! spring, friction under a particle): the energy ledger integrates that power over the
//! step from its two ends, which an impulse inside it would break.

mod response;

use std::sync::Arc;

use crate::constraints::Constraints;
use crate::constraints::End;
use crate::contacts::{Impact, Members};
use crate::forces::{ForceModel, SpringLink, SurfaceContact};
use crate::integrators::{self, KnownStart, Workspace};
use crate::method::Integrator;
use crate::profile::Stage;
use crate::state::State;

use super::step::StepContext;
use super::{Bracket, Simulation, refine_instant};
use crate::tuning::CARRIED;

/// The coupled particles as a system of their own.
#[derive(Clone, Debug)]
pub(super) struct CoupledSystem {
    /// Its particles, ascending: every coupled one, and the fixed ones that pull on them
    /// by a pairwise force or a spring.
    members: Arc<[usize]>,
    /// Each particle's index among the members.
    local: Arc<[Option<u32>]>,
    /// The force model of the members alone, without surfaces (each step's are added).
    model: Arc<ForceModel>,
    /// What a step with coupled impacts works in: filled again each such step.
    scratch: Option<Box<Scratch>>,
}

#[derive(Clone, Debug)]
struct Scratch {
    /// The model with this step's surface contacts and threads.
    forces: ForceModel,
    /// The members' integrated state `from` seconds into the step, after the impulse of
    /// the impact there.
    segment: State,
    from: f64,
    /// The members' state at an instant being tried.
    at: State,
    /// The members' state at the step's end, integrated from `segment`.
    end: State,
    work: Workspace,
    /// The acceleration at the segment's start, once an integration from it computed it.
    segment_start: KnownStart,
    /// The last instant `at` was integrated to in this segment, the state there and (once
    /// asked for) its accelerations: Newton's next tries at an impact's instant start
    /// from it ([`Scratch::move_to`]).
    integrated: Option<f64>,
    base: State,
    base_acceleration: KnownStart,
    /// With rk4: the members' motion through the step ([`response`]).
    motion: response::Motion,
    /// The members' state through the trial step ([`Simulation::split_trial_step`]).
    trial: State,
}

impl CoupledSystem {
    /// The coupled system of a simulation's particles, or `None` when there is none or
    /// impacts must end the step (rods or strings; see the module doc).
    pub fn new(forces: &ForceModel, coupled: &[bool]) -> Option<Self> {
        if !forces.constraints.is_empty()
            || forces.has_own_varying_forces()
            || !coupled.contains(&true)
        {
            return None;
        }
        let pulls = |i: usize| {
            forces.interacting.binary_search(&i).is_ok()
                || forces.springs.iter().any(|s| s.touches(i))
        };
        let members: Vec<usize> = (0..coupled.len())
            .filter(|&i| coupled[i] || (forces.is_fixed(i) && pulls(i)))
            .collect();
        let mut local = vec![None; coupled.len()];
        for (k, &i) in members.iter().enumerate() {
            local[i] = Some(u32::try_from(k).ok()?);
        }
        let model = restricted(forces, &members, &local);
        Some(Self {
            members: members.into(),
            local: local.into(),
            model: Arc::new(model),
            scratch: None,
        })
    }

    /// Frees the scratch space (keyframes hold none).
    pub fn drop_scratch(&mut self) {
        self.scratch = None;
    }

    /// Starts a step's coupled impacts: the members at the step's `start`, under this
    /// step's surfaces and threads.
    fn begin(&mut self, start: &State, forces: &ForceModel) -> &mut Scratch {
        let members = Arc::clone(&self.members);
        let scratch = self.prepare(forces);
        let segment = &mut scratch.segment;
        segment.time = start.time;
        segment.position.clear();
        segment.velocity.clear();
        segment
            .position
            .extend(members.iter().map(|&i| start.position[i]));
        segment
            .velocity
            .extend(members.iter().map(|&i| start.velocity[i]));
        scratch.from = 0.0;
        scratch.segment_start.forget();
        scratch.integrated = None;
        scratch
    }

    /// The scratch space with the members' model under this step's surfaces and threads
    /// (from the whole system's `forces`).
    fn prepare(&mut self, forces: &ForceModel) -> &mut Scratch {
        let model = &self.model;
        let scratch = self.scratch.get_or_insert_with(|| {
            Box::new(Scratch {
                forces: ForceModel::clone(model),
                segment: State::default(),
                from: 0.0,
                at: State::default(),
                end: State::default(),
                work: Workspace::default(),
                segment_start: KnownStart::default(),
                integrated: None,
                base: State::default(),
                base_acceleration: KnownStart::default(),
                motion: response::Motion::default(),
                trial: State::default(),
            })
        });
        scratch.forces.workers = forces.workers.clone();
        scratch.forces.surface_contacts.clear();
        let local = &self.local;
        scratch
            .forces
            .surface_contacts
            .extend(forces.surface_contacts.iter().filter_map(|contact| {
                let particle = local[contact.particle]? as usize;
                Some(crate::forces::SurfaceContact {
                    particle,
                    ..*contact
                })
            }));
        scratch
    }
}

impl Scratch {
    /// `at` becomes the members' state `time` seconds into a step of `h`: integrated from
    /// the segment's start, or carried by its acceleration from the last instant it was
    /// integrated to, when that is within [`CARRIED`] of the step.
    fn move_to(&mut self, time: f64, h: f64, method: Integrator) {
        if let Some(integrated) = self.integrated
            && (time - integrated).abs() <= CARRIED * h
        {
            let acceleration = self.base_acceleration.of(&self.forces, &self.base);
            let delta = time - integrated;
            self.at.clone_from(&self.base);
            self.at.time = self.base.time + delta;
            for ((x, v), a) in self
                .at
                .position
                .iter_mut()
                .zip(&mut self.at.velocity)
                .zip(acceleration)
            {
                *x += *v * delta + *a * (0.5 * delta * delta);
                *v += *a * delta;
            }
            return;
        }
        self.at.clone_from(&self.segment);
        integrators::advance_exactly_from(
            method,
            &self.forces,
            &mut self.at,
            time - self.from,
            &mut self.work,
            &mut self.segment_start,
        );
        self.integrated = Some(time);
        self.base.clone_from(&self.at);
        self.base_acceleration.forget();
    }

    /// The state in `at` (`time` seconds into a step of `h`, after an impulse) starts
    /// the next segment, and `end` is integrated from it to the step's end.
    fn restart(&mut self, time: f64, h: f64, method: Integrator) {
        self.segment.clone_from(&self.at);
        self.from = time;
        self.integrated = None;
        self.end.clone_from(&self.segment);
        self.segment_start.forget();
        integrators::advance_exactly_from(
            method,
            &self.forces,
            &mut self.end,
            h - time,
            &mut self.work,
            &mut self.segment_start,
        );
    }
}

/// The force model of the `members` alone, indexed by `local`.
fn restricted(forces: &ForceModel, members: &[usize], local: &[Option<u32>]) -> ForceModel {
    let pick = |&i: &usize| local[i].map(|k| k as usize);
    let end = |end: End| match end {
        End::Particle(i) => local[i].map(|k| End::Particle(k as usize)),
        End::Point(point) => Some(End::Point(point)),
    };
    let springs: Vec<SpringLink> = forces
        .springs
        .iter()
        .filter_map(|s| {
            Some(SpringLink {
                from: end(s.from)?,
                to: end(s.to)?,
                ..*s
            })
        })
        .collect();
    ForceModel {
        mass: members.iter().map(|&i| forces.mass[i]).collect(),
        inverse_mass: members.iter().map(|&i| forces.inverse_mass[i]).collect(),
        charge: members.iter().map(|&i| forces.charge[i]).collect(),
        uniform: members.iter().map(|&i| forces.uniform[i]).collect(),
        gravitational_constant: forces.gravitational_constant,
        coulomb_constant: forces.coulomb_constant,
        softening2: forces.softening2,
        interacting: forces.interacting.iter().filter_map(pick).collect(),
        charged: forces.charged.iter().filter_map(pick).collect(),
        tree: forces.tree,
        springs_at: crate::forces::spring::each_particles(&springs, members.len()),
        springs,
        constraints: Constraints::default(),
        workers: forces.workers.clone(),
        surface_contacts: Vec::new(),
        drag: forces
            .drag
            .iter()
            .filter_map(|d| {
                Some(crate::forces::drag::Drag {
                    particle: pick(&d.particle)?,
                    ..*d
                })
            })
            .collect(),
        magnetic: forces
            .magnetic
            .iter()
            .filter_map(|&(i, qb)| Some((pick(&i)?, qb)))
            .collect(),
        // Never built with forces of one's own (`CoupledSystem::new`).
        own: Vec::new(),
    }
}

impl Simulation {
    /// rk4's trial step of `h` seconds with the coupled particles alone integrated by
    /// rk4, under their own model, and every other particle by its exact constant-
    /// acceleration motion, x + v h + a h²/2 (what rk4 gives it, to rounding: no pair
    /// force or spring acts on it, and the field, the surfaces' answer and their
    /// friction are constant through the step). One evaluation of everything's forces (rk4's
    /// first stage, kept in `self.work`), then three of the coupled particles' alone,
    /// instead of four of everything's: the mixed scene of 1,000 balls integrates its
    /// 200 coupled ones and 800 others. Returns false, doing nothing, where it does not
    /// apply (another method, no coupled system, every particle coupled, or a force that
    /// varies on a particle alone — air resistance, the magnetic field — under which no
    /// particle's acceleration can be taken as constant).
    pub(super) fn split_trial_step(&mut self, h: f64) -> bool {
        let Some(system) = self.coupled.as_mut() else {
            return false;
        };
        let n = self.state.len();
        if self.integrator != Integrator::Rk4
            || system.members.len() == n
            || self.forces.has_own_varying_forces()
        {
            return false;
        }
        let members = Arc::clone(&system.members);
        let scratch = system.prepare(&self.forces);
        let (trial, state) = (&mut scratch.trial, &mut self.state);
        trial.time = state.time;
        for (mine, whole) in [
            (&mut trial.position, &state.position),
            (&mut trial.velocity, &state.velocity),
        ] {
            mine.clear();
            mine.extend(members.iter().map(|&i| whole[i]));
        }
        // Everything moved by its acceleration at the start (rk4's first stage, left in
        // `self.work`), then the coupled particles integrated again from the start.
        integrators::ballistic(&self.forces, state, h, &mut self.work);
        let start = &self.work.accelerations[0];
        let known: Vec<glam::DVec2> = members.iter().map(|&i| start[i]).collect();
        integrators::rk4::step_knowing(&scratch.forces, trial, h, &mut scratch.work, Some(&known));
        write_members(&members, trial, state);
        state.time += h;
        true
    }

    /// Whether the coupled impact just found can be handled inside the step.
    pub(super) fn coupled_in_step(&self) -> bool {
        self.coupled.is_some() && !self.forces.dissipates()
    }

    /// Applies the coupled impacts of a step of `taken` seconds in time order, `first`
    /// the first of them, each at its instant on the coupled system's integrated state,
    /// and goes on with the impact search after each (see the module doc). The step's
    /// context then holds the step taken: as it was, or the instant of an impact that drove a coupled particle
    /// into the surface it rests on faster than a resting contact's speed, where the step
    /// then ends (so that the next step starts with that impact, as it did when every
    /// coupled impact ended the step: the surface's support of a sinking coupled particle
    /// is not constant over the step, and the energy ledger could not book its work). A
    /// slower one is caught on its surface at once ([`catch_on_surfaces`]), as the next
    /// step's start would, and the step goes on. (With rk4 a faster one bounces off its
    /// surface there and then, and the step goes on too: [`response`].)
    pub(super) fn coupled_impacts_in_step(&mut self, first: (f64, Impact), step: &mut StepContext) {
        let taken = step.taken;
        if self.integrator == Integrator::Rk4 && !self.forces.has_stiff_springs(taken) {
            // rk4 keeps no acceleration for the next step: `moved` changes nothing.
            step.taken = self.coupled_responses_in_step(first, taken);
            step.moved = true;
            return;
        }
        let Some(system) = self.coupled.as_mut() else {
            return;
        };
        let method = self.integrator;
        let local = Arc::clone(&system.local);
        let members = Arc::clone(&system.members);
        let scratch = system.begin(&self.start, &self.forces);
        let mut restarted = false;
        let mut next = Some(first);
        while let Some((estimate, impact)) = next {
            let (from, reach) = (scratch.from, self.contacts.reach(impact));
            let contacts = &self.contacts;
            let within = Bracket::new(from, taken);
            let time = refine_instant(estimate.max(from), within, reach, |time| {
                scratch.move_to(time, taken, method);
                let at = Members {
                    local: &local,
                    state: &mut scratch.at,
                };
                let (gap, _, approach) = contacts.measure_coupled(impact, time, taken, &at);
                (gap, approach)
            });
            let mut at = Members {
                local: &local,
                state: &mut scratch.at,
            };
            if self
                .contacts
                .strike_coupled(impact, time, taken, &mut at, &self.forces)
            {
                let resting_speed = self.contacts.resting_speed(taken);
                let struck = |p: usize| impact.involves(p);
                let caught = catch_on_surfaces(
                    &struck,
                    &self.forces,
                    &local,
                    &mut scratch.at,
                    resting_speed,
                );
                let Some(energy) = caught else {
                    write_members(&members, &scratch.at, &mut self.state);
                    self.contacts.end_at(time, taken, &mut self.state, &local);
                    step.taken = time;
                    step.moved = true;
                    return;
                };
                self.contacts.report.caught += energy;
                scratch.restart(time, taken, method);
                self.contacts.restart_paths(
                    &members,
                    (&scratch.segment, &scratch.end),
                    time,
                    taken,
                    &self.forces,
                );
                restarted = true;
            }
            self.profiler.lap(Stage::CoupledImpacts);
            next = self.contacts.resume_impacts(
                &mut self.state,
                taken,
                &self.forces,
                &mut self.profiler,
            );
        }
        if restarted {
            write_members(&members, &scratch.end, &mut self.state);
            step.moved = true;
        }
    }
}

/// Puts each member's state in `members_state` (indexed like `members`) into `state`.
fn write_members(members: &[usize], members_state: &State, state: &mut State) {
    for (k, &p) in members.iter().enumerate() {
        state.position[p] = members_state.position[k];
        state.velocity[p] = members_state.velocity[k];
    }
}

/// After an impact (`at`: the coupled system's state just after it; `struck`: whether a
/// particle was struck by it): `None` when it left a struck coupled particle moving into a
/// surface it rests on faster than `resting_speed`,
/// for which the step must end there (the next step's start applies that impact).
/// Otherwise each of them moving into its surface more slowly is caught there, as the
/// next step's start would catch it: its velocity into the surface is taken away (an
/// impact that slow has no restitution), and the kinetic energy that took, joules, is
/// returned. Without the catch such a particle would sink through the rest of the step,
/// whose support the ledger could not book; ending the step for it cost a whole pass
/// through the pipeline (half the steps that ended early in the mixed scene).
fn catch_on_surfaces(
    struck: &dyn Fn(usize) -> bool,
    forces: &ForceModel,
    local: &[Option<u32>],
    at: &mut State,
    resting_speed: f64,
) -> Option<f64> {
    let into = |contact: &SurfaceContact, at: &State| {
        let k = local[contact.particle]? as usize;
        struck(contact.particle).then(|| (k, -at.velocity[k].dot(contact.normal)))
    };
    if forces
        .surface_contacts
        .iter()
        .any(|contact| into(contact, at).is_some_and(|(_, approach)| approach > resting_speed))
    {
        return None;
    }
    let mut energy = 0.0;
    for contact in &forces.surface_contacts {
        if let Some((k, approach)) = into(contact, at).filter(|&(_, approach)| approach > 0.0) {
            at.velocity[k] += contact.normal * approach;
            energy += 0.5 * forces.mass[contact.particle] * approach * approach;
        }
    }
    Some(energy)
}
