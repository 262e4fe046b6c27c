//! Coupled impacts by the motion's response, without integrating again (rk4).
//!
//! Through a step the coupled particles follow the integrator's motion, known at its two
//! ends. An impact at τ changes a struck particle's velocity by Δv; from then on it moves
//! off that motion by δ(t), and everything it pulls (by a pair law or a spring) feels the
//! difference. With s = t − τ and J = ∂a/∂x the forces' Jacobian
//! ([`crate::forces::ForceModel::displacement_response`]), the departures of all of them
//! obey δ″ = a(x + δ) − a(x), δ(τ) = 0, δ′(τ) = Δv on the struck particle, whose series is
//!
//!   δ = Δv s + α s³/6 + β s⁴/12 + (γ/120 + c/20) s⁵ + …,   α = J Δv,   γ = J α,
//!
//! β and c carrying the Jacobian's change along the motion and the forces' curvature
//! (J′ Δv + ∂J/∂x [Δv, Δv] in β, their next order in c). α is one pass over the struck
//! particle's partners; β and c are fitted to the exact change of their forces halfway
//! through the rest of the step and at its end, the struck particle moved on by Δv s
//! ([`crate::forces::ForceModel::displacement_change`]), less α's part; γ sums J α over
//! the struck particle and those it shares a spring with (the largest answers: a pair
//! law's partner at a distance answers by far less, and its own answer less again). What
//! is left out is of order s⁶ in the position and s⁵ in the velocity (J² Δv s⁵ for the
//! particles γ leaves out). docs/physics.md ("Coupled impacts by the motion's response")
//! gives what each term was measured to be worth.
//!
//! What an impact is measured and applied on must be as exact as the integrator: each
//! involved particle's acceleration is taken as the cubic through its values and rates
//! (∂a/∂x · v, [`crate::forces::ForceModel::acceleration_rate`]) at both ends, integrated
//! from the start, off by order h⁵ in the velocity (an involved particle's acceleration at
//! the step's end is computed when first needed, one pass over its partners). The cubic
//! through the ends' positions and velocities serves what only reads where a particle is
//! (the Jacobian, the impact search's paths); measured on it, an impact's speed would be
//! off by order h³, and on the quintic through the ends' accelerations too, by rk4's error
//! in the end position divided by h. Newton's method finds the instant on the motion's own
//! curve, so the gap closes there exactly; the step still ends at the integrator's state
//! plus the departures.
//!
//! So an impact of a coupled particle costs a few passes over what it pulls instead of
//! integrating every coupled particle again, twice (to the impact and on to the step's
//! end).
//!
//! A surface that holds a particle (its support pressing at the step's start) answers
//! any small change of the others' pull along its normal, either way: that part of an
//! answer, and of a rate of acceleration, is taken away, as the integration's own
//! support takes it. A step that ends at a coupled impact ([`super::catch_on_surfaces`])
//! puts every member where the motion has it then, with every rate measured in bulk.
//!
//! A blow that drives a ball into the surface it rests on (a floor under a pile) bounces
//! it off there and then, and whatever it then closes on at that instant is struck too,
//! coupled balls' contacts followed in turn ([`pass_on`]); a ball a hair above its floor
//! (it was leaving it more slowly than a resting contact's speed) meets it a moment later,
//! an impact queued for the search ([`Contacts::closing_on_rests`]). A ball sent off the
//! surface that held it loses the surface's support for the rest of the step
//! ([`Motion::release`]): without that it would float above its floor after the step
//! (`a_coupled_ball_sent_off_its_floor_by_a_blow_flies_as_thrown_up`). Ending the step at
//! such a blow instead, for the next step's start to pass it on, would cost a whole pass
//! through the pipeline each.
//!
//! Where the series is no description of the motion, the answer is not used. A step
//! whose springs turn their ends by (ω h)² > 1e-2 integrates its coupled impacts again
//! ([`crate::forces::ForceModel::has_stiff_springs`]). An impact whose first answer turns
//! anything by (ω S)² > 1e-2 over the rest of the step ([`STIFF`]), or whose fifth-order
//! term is above 1e-6 of the kick's displacement ([`TRUSTED`]), ends the step, every
//! member where the motion has it; the next step integrates on.
//!
//! Only rk4 uses it: a lower-order method's motion between the ends is its own steps',
//! which the curve would make more exact than the method itself; those integrate again
//! ([`super`]).

use std::borrow::Cow;
use std::sync::Arc;

use glam::DVec2;

use crate::constraints::End;
use crate::contacts::{Contacts, Impact, InStep, Members, hermite, hermite_position};
use crate::forces::ForceModel;
use crate::integrators::Workspace;
use crate::profile::Stage;
use crate::state::State;

use super::super::{Bracket, Simulation, refine_instant};
use super::{Scratch, catch_on_surfaces, write_members};
use crate::tuning::{PASSES, STIFF, TRUSTED};

/// The coupled particles' motion through one step: the integrator's, between its two
/// ends, and each particle's departure from it since the impacts applied so far.
#[derive(Clone, Debug, Default)]
pub(super) struct Motion {
    /// The members' state at the step's start and at the trial step's end, and their
    /// accelerations there.
    start: State,
    start_acceleration: Vec<DVec2>,
    end: State,
    end_acceleration: Vec<Option<DVec2>>,
    /// Each member's rate of acceleration at both ends, once an impact measured it.
    rates: Vec<Option<[DVec2; 2]>>,
    /// Each member's departure from the integrator's motion, the quintic
    /// c0 + c1 t + … + c5 t⁵ of the seconds t into the step.
    departure: Vec<[DVec2; 6]>,
    /// At most how far each member's departure moved it (anywhere up to the step's
    /// end) since its impact search's path last started again.
    moved: Vec<f64>,
    /// Scratch: the members' positions at an impact, the struck one's spring partners,
    /// and the members' answers to it.
    position: Vec<DVec2>,
    partners: Vec<usize>,
    answers: [Vec<DVec2>; 4],
    /// Members a blow sent off a surface that held them, with its normal ([`Self::release`]):
    /// no longer held by it for the rest of the step.
    released: Vec<(usize, DVec2)>,
    /// Each member a surface holds at the step's start, with the surface's normal.
    holding: Vec<(usize, DVec2)>,
}

impl Motion {
    /// A step's motion: the members at the `start` state and the trial step's `end`,
    /// `start_acceleration` the whole system's at the start (rk4's first stage); the
    /// end's are computed under `forces` (the members' model with this step's surfaces)
    /// as impacts need them.
    fn begin(
        &mut self,
        members: &[usize],
        (start, start_acceleration): (&State, &[DVec2]),
        end: &State,
        forces: &ForceModel,
    ) {
        for (mine, whole) in [(&mut self.start, start), (&mut self.end, end)] {
            mine.time = whole.time;
            mine.position.clear();
            mine.position
                .extend(members.iter().map(|&i| whole.position[i]));
            mine.velocity.clear();
            mine.velocity
                .extend(members.iter().map(|&i| whole.velocity[i]));
        }
        self.start_acceleration.clear();
        self.start_acceleration
            .extend(members.iter().map(|&i| start_acceleration[i]));
        self.holding.clear();
        self.holding.extend(
            forces
                .surface_contacts
                .iter()
                .filter(|contact| holds(self.start_acceleration[contact.particle], contact.normal))
                .map(|contact| (contact.particle, contact.normal)),
        );
        self.end_acceleration.clear();
        self.end_acceleration.resize(members.len(), None);
        if forces.tree.is_some() {
            // A tree's sum of one particle's forces is not the direct sum's.
            self.measure_every_end_acceleration(forces);
        }
        self.rates.clear();
        self.rates.resize(members.len(), None);
        self.departure.clear();
        self.departure.resize(members.len(), [DVec2::ZERO; 6]);
        self.moved.clear();
        self.moved.resize(members.len(), 0.0);
        self.released.clear();
    }

    /// Member `k`'s position and velocity `t` seconds into a step of `h`, near enough for
    /// what only reads where it is (the forces' Jacobian, the impact search's paths): the
    /// cubic through the positions and velocities at both ends, off by some h⁴ x⁗/384.
    fn at(&self, k: usize, t: f64, h: f64) -> (DVec2, DVec2) {
        let (x0, v0) = (self.start.position[k], self.start.velocity[k]);
        let (x1, v1) = (self.end.position[k], self.end.velocity[k]);
        let (position, velocity) = if t >= h {
            (x1, v1)
        } else {
            hermite(((x0, v0), (x1, v1)), h, t / h)
        };
        self.departed(k, t, (position, velocity))
    }

    /// [`Self::at`]'s position alone (the same arithmetic): what the Jacobian and the
    /// exact change of the forces read.
    fn position_at(&self, k: usize, t: f64, h: f64) -> DVec2 {
        let (x0, v0) = (self.start.position[k], self.start.velocity[k]);
        let (x1, v1) = (self.end.position[k], self.end.velocity[k]);
        let position = if t >= h {
            x1
        } else {
            hermite_position(((x0, v0), (x1, v1)), h, t / h)
        };
        let [c0, c1, c2, c3, c4, c5] = self.departure[k];
        position + c0 + (c1 + (c2 + (c3 + (c4 + c5 * t) * t) * t) * t) * t
    }

    /// Member `k`'s acceleration at the trial step's end, computed the first time it is
    /// asked for (one pass over its partners, not an evaluation of every member).
    fn end_acceleration(&mut self, k: usize, forces: &ForceModel) -> DVec2 {
        *self.end_acceleration[k].get_or_insert_with(|| {
            forces.acceleration_of(&self.end.position, &self.end.velocity, k)
        })
    }

    /// Every member's acceleration at the trial step's end not yet known, in one
    /// evaluation.
    fn measure_every_end_acceleration(&mut self, forces: &ForceModel) {
        let mut a = vec![DVec2::ZERO; self.end.len()];
        forces.accelerations(
            self.end.time,
            &self.end.position,
            &self.end.velocity,
            &mut a,
        );
        for (known, a) in self.end_acceleration.iter_mut().zip(a) {
            known.get_or_insert(a);
        }
    }

    /// Member `k`'s position and velocity `t` seconds into a step of `h`, as exactly as
    /// the integrator's own: what an impact is measured and applied on. The acceleration
    /// is the cubic through its values and rates at both ends (the rates computed the
    /// first time the member is asked for, under `forces`), integrated from the start:
    /// its error is of order h⁴ in the acceleration, h⁵ in the velocity. (The cubic of
    /// [`Self::at`] is off by order h³ in the velocity.)
    fn exactly(&mut self, k: usize, t: f64, h: f64, forces: &ForceModel) -> (DVec2, DVec2) {
        if t >= h {
            return self.at(k, t, h);
        }
        let a1 = self.end_acceleration(k, forces);
        let [j0, j1] = *self.rates[k].get_or_insert_with(|| {
            let rate = |state: &State, a: DVec2| {
                let rate = forces.acceleration_rate(&state.position, &state.velocity, k);
                supported(forces, k, a, rate)
            };
            [
                rate(&self.start, self.start_acceleration[k]),
                rate(&self.end, a1),
            ]
        });
        let (x0, v0, a0) = (
            self.start.position[k],
            self.start.velocity[k],
            self.start_acceleration[k],
        );
        let s = t / h;
        let (s2, s3) = (s * s, s * s * s);
        let (s4, s5) = (s2 * s2, s2 * s3);
        // The cubic Hermite basis of the acceleration, integrated once and twice from 0.
        let once = [
            s4 / 2.0 - s3 + s,
            s4 / 4.0 - 2.0 * s3 / 3.0 + s2 / 2.0,
            s3 - s4 / 2.0,
            s4 / 4.0 - s3 / 3.0,
        ];
        let twice = [
            s5 / 10.0 - s4 / 4.0 + s2 / 2.0,
            s5 / 20.0 - s4 / 6.0 + s3 / 6.0,
            s4 / 4.0 - s5 / 10.0,
            s5 / 20.0 - s4 / 12.0,
        ];
        let data = [a0, j0 * h, a1, j1 * h];
        let sum = |weights: [f64; 4]| {
            data.iter()
                .zip(weights)
                .fold(DVec2::ZERO, |total, (d, w)| total + *d * w)
        };
        let position = x0 + v0 * t + sum(twice) * (h * h);
        let velocity = v0 + sum(once) * h;
        self.departed(k, t, (position, velocity))
    }

    /// The impact search's paths of the members whose motion moved by more than it keeps
    /// ([`Contacts::keeps_path`]) start again `time` seconds into a step of `h`.
    fn restart_paths(
        &mut self,
        contacts: &mut Contacts,
        members: &[usize],
        (time, h): (f64, f64),
        forces: &ForceModel,
    ) {
        for (k, &p) in members.iter().enumerate() {
            if !contacts.keeps_path(p, self.moved[k]) {
                let (start, end) = (self.at(k, time, h), self.at(k, h, h));
                if contacts.restart_path(p, (start, end), time, h, forces) {
                    self.moved[k] = 0.0;
                }
            }
        }
    }

    /// The parts of `answers` (changes of the members' accelerations) along the normal of
    /// a surface that holds the member at the step's start taken away: the support
    /// answers any small change of the others' pull, either way.
    fn hold(&self, answers: &mut [DVec2]) {
        for &(k, normal) in &self.holding {
            if self.held(k, normal) {
                answers[k] -= normal * answers[k].dot(normal);
            }
        }
    }

    /// Whether a surface of `normal` holds member `k` now: it pressed on it at the step's
    /// start and no blow has sent it off since.
    fn held(&self, k: usize, normal: DVec2) -> bool {
        self.holding.contains(&(k, normal)) && !self.released.contains(&(k, normal))
    }

    /// Member `k`, held by a surface of `normal` until a blow `tau` seconds into a step of
    /// `h` sent it off, moves without the surface's support for the rest of the step: its
    /// departure loses the support's acceleration S(t), where the motion has it at τ and
    /// at the step's end, taken as linear between: δ = −(S₀ σ²/2 + Ṡ σ³/6), σ = t − τ
    /// (the next term, S̈ σ⁴/24, is some 1e-15 m in a 1 ms step); and everything it pulls
    /// answers that, J δ σ⁴/24 (the answer's own next terms are of order J Ṡ σ⁵). S is the
    /// surfaces' answer to the pull with this one among those still holding the member,
    /// less it without: the pull into the surface along its normal when no other surface
    /// holds it; at a corner or in a wedge the answers are not independent. The surface's
    /// normal force then does no work on it in the rest of the step
    /// ([`Simulation::coupled_responses_in_step`] takes its contact off the books);
    /// returns the work it did up to the blow, J.
    fn release(
        &mut self,
        k: usize,
        normal: DVec2,
        (tau, h): (f64, f64),
        forces: &ForceModel,
    ) -> f64 {
        let n = self.start.len();
        let span = h - tau;
        let mut position = std::mem::take(&mut self.position);
        position.resize(n, DVec2::ZERO);
        // The support that stops (S above). Pair laws and springs read no velocity here:
        // no coupled impact is answered inside the step while anything dissipates.
        let support = |position: &[DVec2]| {
            let free = forces.free_acceleration_of(position, &self.start.velocity, k);
            let (mut with, mut without) = (free, free);
            for contact in forces.surface_contacts.iter().filter(|c| c.particle == k) {
                if !self.released.contains(&(k, contact.normal)) {
                    contact.apply(&mut with);
                    if contact.normal != normal {
                        contact.apply(&mut without);
                    }
                }
            }
            with - without
        };
        self.positions_read_by((k, &[]), (h, h), forces, &mut position);
        let end = support(&position);
        self.positions_read_by((k, &[]), (tau, h), forces, &mut position);
        let start = support(&position);
        let slope = if span > 0.0 {
            (end - start) / span
        } else {
            DVec2::ZERO
        };
        let [mut answer, rest @ ..] = std::mem::take(&mut self.answers);
        answer.clear();
        answer.resize(n, DVec2::ZERO);
        forces.displacement_response(&position, k, -start, &mut answer);
        self.released.push((k, normal));
        self.hold(&mut answer);
        let powers = Powers::of(tau, span);
        let z = DVec2::ZERO;
        for (j, answer) in answer.iter().enumerate() {
            let sizes = if j == k {
                [z, z, start / -2.0, slope / -6.0, *answer / 24.0, z]
            } else {
                [z, z, z, z, *answer / 24.0, z]
            };
            self.depart(j, sizes, &powers);
        }
        let [b, c, d] = rest;
        (self.position, self.answers) = (position, [answer, b, c, d]);
        // Until the blow the surface held it, moving along its normal only as slowly as
        // it was leaving it at the step's start: the support's work then, as the books
        // take it for a surface that holds a particle through a whole step (the support
        // where it is now, times the way it went).
        forces.mass[k] * start.dot(self.position_at(k, tau, h) - self.start.position[k])
    }

    /// Every member's rates of acceleration (and accelerations) at both ends of a step of
    /// `h`, for all of them to be put where they are exactly: the rates by central
    /// differences of the accelerations along each end's velocities, ±h/1000. Five
    /// evaluations of the members' forces, where one member's own rate reads its partners
    /// one by one; the difference's error is of order 1e-6² of the rate, its rounding's
    /// some 1e-10 m/s³ in the 1 ms step, which moves a velocity by 1e-14 m/s. A rate
    /// already measured is kept.
    fn measure_every_rate(&mut self, forces: &ForceModel, h: f64) {
        self.measure_every_end_acceleration(forces);
        let epsilon = h * 1e-3;
        let n = self.start.len();
        let mut rates = [vec![DVec2::ZERO; n], vec![DVec2::ZERO; n]];
        let mut moved = State::default();
        let mut a = [vec![DVec2::ZERO; n], vec![DVec2::ZERO; n]];
        for (state, rate) in [&self.start, &self.end].into_iter().zip(&mut rates) {
            for (side, sign) in a.iter_mut().zip([1.0, -1.0]) {
                moved.clone_from(state);
                for (x, v) in moved.position.iter_mut().zip(&state.velocity) {
                    *x += *v * (sign * epsilon);
                }
                forces.accelerations(moved.time, &moved.position, &moved.velocity, side);
            }
            for ((r, plus), minus) in rate.iter_mut().zip(&a[0]).zip(&a[1]) {
                *r = (*plus - *minus) / (2.0 * epsilon);
            }
        }
        for (k, known) in self.rates.iter_mut().enumerate() {
            known.get_or_insert([rates[0][k], rates[1][k]]);
        }
    }

    /// `motion` (a position and velocity of member `k` at `t`) with its departure added.
    fn departed(&self, k: usize, t: f64, (position, velocity): (DVec2, DVec2)) -> (DVec2, DVec2) {
        let [c0, c1, c2, c3, c4, c5] = self.departure[k];
        (
            position + c0 + (c1 + (c2 + (c3 + (c4 + c5 * t) * t) * t) * t) * t,
            velocity + c1 + (c2 * 2.0 + (c3 * 3.0 + (c4 * 4.0 + c5 * (5.0 * t)) * t) * t) * t,
        )
    }

    /// Puts every member but the `written` ones where the motion has it `t` seconds into
    /// a step of `h`, into `state` (a step ending there).
    fn write_the_others(
        &mut self,
        written: &[usize],
        (t, h): (f64, f64),
        state: &mut State,
        forces: &ForceModel,
    ) {
        self.measure_every_rate(forces, h);
        for k in 0..self.start.len() {
            if !written.contains(&k) {
                self.write(k, t, h, state, forces);
            }
        }
    }

    /// Puts member `k`'s state `t` seconds into a step of `h` into `state` ([`Self::exactly`]).
    fn write(&mut self, k: usize, t: f64, h: f64, state: &mut State, forces: &ForceModel) {
        (state.position[k], state.velocity[k]) = self.exactly(k, t, h, forces);
    }

    /// Adds Σ `sizes[n]`·(t − τ)ⁿ to member `k`'s departure (n from 0 to 5), and a bound
    /// on how far that moves the member by the end of the step to its [`Self::moved`]:
    /// `powers` are the powers of −τ and of the rest of the step S, [`Powers::of`].
    fn depart(&mut self, k: usize, sizes: [DVec2; 6], powers: &Powers) {
        // The binomial expansion of (t − τ)ⁿ: C(n, m) (−τ)^(n−m) tᵐ.
        const BINOMIAL: [[f64; 6]; 6] = [
            [1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0, 0.0, 0.0, 0.0],
            [1.0, 2.0, 1.0, 0.0, 0.0, 0.0],
            [1.0, 3.0, 3.0, 1.0, 0.0, 0.0],
            [1.0, 4.0, 6.0, 4.0, 1.0, 0.0],
            [1.0, 5.0, 10.0, 10.0, 5.0, 1.0],
        ];
        if sizes == [DVec2::ZERO; 6] {
            return;
        }
        let c = &mut self.departure[k];
        for (n, size) in sizes.into_iter().enumerate() {
            if size == DVec2::ZERO {
                continue;
            }
            for m in 0..=n {
                c[m] += size * (BINOMIAL[n][m] * powers.tau[n - m]);
            }
            // |x| + |y|, no shorter than the length and without its square root (four
            // a member and impact, for every member a blow answers): it only decides
            // when the search measures whether a path moved ([`Contacts::restart_path`]),
            // so a bound is enough and cheaper than the length.
            self.moved[k] += (size.x.abs() + size.y.abs()) * powers.span[n];
        }
    }

    /// The positions of the members the forces on `k` and on `partners` read, `t`
    /// seconds into a step of `h`, into `position` (the others are left as they are).
    fn positions_read_by(
        &self,
        (k, partners): (usize, &[usize]),
        (t, h): (f64, f64),
        forces: &ForceModel,
        position: &mut [DVec2],
    ) {
        let displaced = || std::iter::once(k).chain(partners.iter().copied());
        if displaced().any(|m| forces.interacting.binary_search(&m).is_ok()) {
            for &j in &forces.interacting {
                position[j] = self.position_at(j, t, h);
            }
        }
        for m in displaced() {
            for (spring, _) in forces.spring_partners(m) {
                for end in [spring.from, spring.to] {
                    if let End::Particle(j) = end {
                        position[j] = self.position_at(j, t, h);
                    }
                }
            }
        }
        position[k] = self.position_at(k, t, h);
    }

    /// Member `k`'s velocity changed by `kick` at `tau` seconds into a step of `h`: its
    /// departure and every member's answer to it (see the module doc). Returns whether
    /// the answer's series can be trusted ([`TRUSTED`]).
    fn kick(&mut self, k: usize, kick: DVec2, (tau, h): (f64, f64), forces: &ForceModel) -> bool {
        if kick == DVec2::ZERO {
            return true;
        }
        let n = self.start.len();
        let span = h - tau;
        let mut partners = std::mem::take(&mut self.partners);
        partners.clear();
        partners.extend(
            forces
                .spring_partners(k)
                .filter_map(|(_, other)| match other {
                    End::Particle(o) => Some(o),
                    End::Point(_) => None,
                }),
        );
        let mut position = std::mem::take(&mut self.position);
        position.resize(n, DVec2::ZERO);
        self.positions_read_by((k, &partners), (tau, h), forces, &mut position);
        // The answer's acceleration in s = t − τ: α s from the Jacobian at τ; β s² + c s³
        // from the exact change of the forces where the struck particle has moved on by
        // Δv s (the Jacobian's change along the motion, and the forces' curvature); γ s³/6
        // (J α s⁵/120 in the position, the velocity's J² Δv s⁴/24: 4e-10 of a kick at
        // ω = 1 /s, 10 ms after it) through the struck particle and those it shares a
        // spring with, whose answers are the largest (a pair law's partner at a distance
        // answers by far less, and its answers less again).
        let [mut alpha, mut beta, mut gamma, mut cubic] = std::mem::take(&mut self.answers);
        for answer in [&mut alpha, &mut beta, &mut gamma, &mut cubic] {
            answer.clear();
            answer.resize(n, DVec2::ZERO);
        }
        forces.displacement_response(&position, k, kick, &mut alpha);
        self.hold(&mut alpha);
        for &m in std::iter::once(&k).chain(&partners) {
            forces.displacement_response(&position, m, alpha[m], &mut gamma);
        }
        if span > 0.0 {
            // The exact changes halfway and at the end, R(s) = A(s) − α s, fitted by
            // β s² + c s³: β = (8 R(S/2) − R(S))/S², c = 2 (R(S) − 4 R(S/2))/S³. (With β
            // from the end alone, β takes c S, which leaves the velocity c S⁴/12 off:
            // 5e-10 of the blow in the paper's 4.7 with rk4, against 1e-12 integrating
            // again. Fitting only where β's part is large saves little: the processing-
            // time scene's blows need it as often.)
            self.positions_read_by((k, &[]), (tau + 0.5 * span, h), forces, &mut position);
            forces.displacement_change(&position, k, kick * (0.5 * span), &mut cubic);
            self.positions_read_by((k, &[]), (h, h), forces, &mut position);
            forces.displacement_change(&position, k, kick * span, &mut beta);
            for ((b, c), a) in beta.iter_mut().zip(&mut cubic).zip(&alpha) {
                let (half, whole) = (*c - *a * (0.5 * span), *b - *a * span);
                *b = (half * 8.0 - whole) / (span * span);
                *c = (whole - half * 4.0) * (2.0 / (span * span * span));
            }
        }
        self.hold(&mut beta);
        self.hold(&mut gamma);
        self.hold(&mut cubic);
        let z = DVec2::ZERO;
        let powers = Powers::of(tau, span);
        // The largest first and fifth-order answers, for the trust rules below.
        // (Their squares compared: the square root is monotonic, so the largest is the
        // same number, with a root a kick instead of two a member.)
        let (mut first, mut last) = (0.0, 0.0);
        for j in 0..n {
            let linear = if j == k { kick } else { z };
            if linear == z && alpha[j] == z && beta[j] == z && gamma[j] == z && cubic[j] == z {
                continue; // nothing it pulls answers: no departure
            }
            let fifth = gamma[j] / 120.0 + cubic[j] / 20.0;
            first = f64::max(first, alpha[j].length_squared());
            last = f64::max(last, fifth.length_squared());
            let sizes = [z, linear, z, alpha[j] / 6.0, beta[j] / 12.0, fifth];
            self.depart(j, sizes, &powers);
        }
        let (first, last) = (first.sqrt(), last.sqrt());
        let trusted = first * span * span <= STIFF * kick.length()
            && last * span.powi(4) <= TRUSTED * kick.length();
        (self.position, self.partners, self.answers) =
            (position, partners, [alpha, beta, gamma, cubic]);
        trusted
    }
}

/// The powers 0 to 5 of −τ and of the rest of the step S after an impact at τ, for
/// [`Motion::depart`]: computed once an impact, not once a member and term.
struct Powers {
    tau: [f64; 6],
    span: [f64; 6],
}

impl Powers {
    fn of(tau: f64, span: f64) -> Self {
        let mut tau_powers = [1.0; 6];
        for p in 1..6 {
            tau_powers[p] = tau_powers[p - 1] * -tau;
        }
        // As `powi` multiplies them (by squaring), so that the bounds keep their bits.
        let (s2, s4) = (span * span, span * span * (span * span));
        Self {
            tau: tau_powers,
            span: [1.0, span, s2, span * s2, s4, span * s4],
        }
    }
}

/// Member `k`'s rate of acceleration `rate` where its acceleration is `acceleration`,
/// less the part along the normal of a surface holding it there (its acceleration has
/// no part into that surface then: the support answers every change of the others).
fn supported(forces: &ForceModel, k: usize, acceleration: DVec2, rate: DVec2) -> DVec2 {
    forces
        .surface_contacts
        .iter()
        .filter(|contact| contact.particle == k && holds(acceleration, contact.normal))
        .fold(rate, |rate, contact| {
            rate - contact.normal * rate.dot(contact.normal)
        })
}

/// Whether a surface of `normal` holds a particle whose acceleration (its answer
/// included) is `acceleration`: the answer took away every part of it into the surface,
/// which a particle pulled away from it would still have.
fn holds(acceleration: DVec2, normal: DVec2) -> bool {
    acceleration.dot(normal) <= 1e-9 * acceleration.length()
}

/// The members an impact involves (none for a particle outside the coupled system).
fn involved(impact: Impact, local: &[Option<u32>]) -> [Option<usize>; 2] {
    match impact {
        Impact::Pair(i, j) => [Some(i), Some(j)],
        Impact::Obstacle(p, _) => [Some(p), None],
    }
    .map(|p| p.and_then(|p| local[p]).map(|k| k as usize))
}

impl Simulation {
    /// [`Self::coupled_impacts_in_step`] with rk4: each coupled impact applied on the
    /// integrator's motion through the step and answered to first order (see the module
    /// doc), no integration again.
    pub(super) fn coupled_responses_in_step(&mut self, first: (f64, Impact), taken: f64) -> f64 {
        let Some(system) = self.coupled.as_mut() else {
            return taken;
        };
        let local = Arc::clone(&system.local);
        let members = Arc::clone(&system.members);
        let scratch = system.begin(&self.start, &self.forces);
        let start_acceleration = start_acceleration(&self.work, &self.forces, &self.start);
        scratch.motion.begin(
            &members,
            (&self.start, &start_acceleration),
            &self.state,
            &scratch.forces,
        );
        scratch.at.clone_from(&scratch.segment);
        let mut restarted = false;
        // The particles a blow sent off the surface that held them.
        let mut released = Vec::new();
        let mut next = Some(first);
        while let Some((estimate, impact)) = next {
            let (from, reach) = (scratch.from, self.contacts.reach(impact));
            let involved = involved(impact, &local);
            let contacts = &self.contacts;
            let (motion, at, forces) = (&mut scratch.motion, &mut scratch.at, &scratch.forces);
            let mut move_to = |time: f64, at: &mut State| {
                for &k in involved.iter().flatten() {
                    motion.write(k, time, taken, at, forces);
                }
            };
            let within = Bracket::new(from, taken);
            let time = refine_instant(estimate.max(from), within, reach, |time| {
                move_to(time, at);
                let members = Members {
                    local: &local,
                    state: at,
                };
                let (gap, _, approach) = contacts.measure_coupled(impact, time, taken, &members);
                (gap, approach)
            });
            move_to(time, at);
            let before = involved.map(|k| k.map(|k| at.velocity[k]));
            let mut members_at = Members {
                local: &local,
                state: at,
            };
            if self
                .contacts
                .strike_coupled(impact, time, taken, &mut members_at, &self.forces)
            {
                let struck: Vec<(usize, DVec2)> = involved
                    .into_iter()
                    .zip(before)
                    .filter_map(|(k, before)| Some((k?, before?)))
                    .collect();
                let off_a_rest = self.contacts.with_a_rest(impact);
                let (trusted, written, rests) = answer_blow(
                    (&mut self.contacts, &self.forces),
                    scratch,
                    (&local, &members),
                    struck,
                    (time, taken),
                    off_a_rest,
                    &mut released,
                );
                if !trusted {
                    // The step ends here, every member where the motion has it now (the
                    // impulses applied), and the next step integrates on from there.
                    let (forces, at) = (&scratch.forces, &mut scratch.at);
                    scratch
                        .motion
                        .write_the_others(&written, (time, taken), at, forces);
                    write_members(&members, at, &mut self.state);
                    self.contacts.end_at(time, taken, &mut self.state, &local);
                    self.forget_surfaces(&released);
                    return time;
                }
                let motion = &mut scratch.motion;
                motion.restart_paths(&mut self.contacts, &members, (time, taken), &self.forces);
                for &(when, impact) in rests.iter().filter(|&&(when, _)| when < taken) {
                    self.contacts.expect(impact, when);
                }
                scratch.from = time;
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
            let motion = &scratch.motion;
            for (k, &p) in members.iter().enumerate() {
                (self.state.position[p], self.state.velocity[p]) = motion.at(k, taken, taken);
            }
        }
        self.forget_surfaces(&released);
        taken
    }

    /// The `released` surface contacts (particle, normal) taken off the step's books: their
    /// surfaces stopped holding them inside the step ([`Motion::release`]), and did no
    /// work on them.
    fn forget_surfaces(&mut self, released: &[(usize, DVec2)]) {
        if !released.is_empty() {
            self.forces
                .surface_contacts
                .retain(|contact| !released.contains(&(contact.particle, contact.normal)));
        }
    }
}

/// The whole system's acceleration at the step's `start`: rk4's first stage of the trial
/// step (in `work`), or evaluated again under `forces` if that is gone.
fn start_acceleration<'a>(
    work: &'a Workspace,
    forces: &ForceModel,
    start: &State,
) -> Cow<'a, [DVec2]> {
    match work.accelerations.first() {
        Some(a) if a.len() == start.len() => Cow::Borrowed(a.as_slice()),
        _ => {
            let mut a = vec![DVec2::ZERO; start.len()];
            forces.accelerations(start.time, &start.position, &start.velocity, &mut a);
            Cow::Owned(a)
        }
    }
}

/// What an impact of coupled particles at `time` seconds into a step of `h` leaves to do
/// on the motion (`struck`: its coupled particles, with their velocities before it, in
/// `scratch.at` after it): a blow into a surface passed on ([`pass_on`]), impacts with
/// rests queued for later ([`Contacts::closing_on_rests`]), slow approaches caught
/// ([`catch_on_surfaces`]), those sent off a holding surface released
/// ([`Motion::release`], added to `released`), and every struck particle's answer.
/// `off_a_rest`: the impact is with a surface the ball touched at the step's start (one
/// queued by [`Contacts::closing_on_rests`]). Returns whether the answers can be trusted
/// (else the step ends at the impact), the members whose state in `scratch.at` is
/// written, and the impacts with rests to queue once the paths start again.
fn answer_blow(
    (contacts, forces): (&mut Contacts, &ForceModel),
    scratch: &mut Scratch,
    (local, members): (&[Option<u32>], &[usize]),
    mut struck: Vec<(usize, DVec2)>,
    (time, h): (f64, f64),
    off_a_rest: bool,
    released: &mut Vec<(usize, DVec2)>,
) -> (bool, Vec<usize>, Vec<(f64, Impact)>) {
    let at = &mut scratch.at;
    let resting_speed = contacts.resting_speed(h);
    // Driven into a surface it rests on faster than a resting contact's speed, a ball
    // bounces off it at once, and passes that on; so does a ball that meets again a
    // surface it had drifted off (it was touching what it now drives into when the blow
    // that sent it there struck: a ball on top of it, say).
    let driven = off_a_rest
        || scratch.forces.surface_contacts.iter().any(|contact| {
            let k = contact.particle;
            struck.iter().any(|&(s, _)| s == k)
                && -at.velocity[k].dot(contact.normal) > resting_speed
        });
    let (passed, written) = if driven {
        pass_on(
            (contacts, forces),
            (&mut scratch.motion, at, &scratch.forces),
            (local, members),
            &mut struck,
            (time, h),
        )
    } else {
        (true, struck.iter().map(|&(k, _)| k).collect())
    };
    // A struck ball that had drifted a hair off the floor holding it (leaving it
    // more slowly than a resting contact's speed) meets it a little later: that
    // impact is queued, found on its motion as any other.
    let members_at = Members { local, state: at };
    let rests: Vec<(f64, Impact)> = struck
        .iter()
        .flat_map(|&(k, _)| {
            contacts.closing_on_rests(members[k], InStep { time, step: h }, &members_at)
        })
        .collect();
    let apart = |p: usize| rests.iter().any(|&(_, impact)| impact.involves(p));
    let is_caught = |p: usize| {
        local[p].is_some_and(|k| struck.iter().any(|&(s, _)| s == k as usize)) && !apart(p)
    };
    let caught = passed
        .then(|| catch_on_surfaces(&is_caught, forces, local, at, resting_speed))
        .flatten();
    let mut trusted = caught.is_some();
    if let Some(energy) = caught {
        contacts.report.caught += energy;
        let motion = &mut scratch.motion;
        // Those sent off the surface that held them first, so that their
        // answers to the blow keep their part along its normal; and those a hair
        // above it (an impact with it queued): they fly free until they meet it.
        for contact in &scratch.forces.surface_contacts {
            let k = contact.particle;
            let normal_speed = at.velocity[k].dot(contact.normal);
            if struck.iter().any(|&(s, _)| s == k)
                && motion.held(k, contact.normal)
                && (normal_speed > resting_speed
                    || (apart(members[k]) && normal_speed < -resting_speed))
            {
                contacts.report.released +=
                    motion.release(k, contact.normal, (time, h), &scratch.forces);
                released.push((members[k], contact.normal));
            }
        }
        for &(k, before) in &struck {
            let kick = at.velocity[k] - before;
            trusted &= motion.kick(k, kick, (time, h), &scratch.forces);
        }
    }
    (trusted, written, rests)
}

/// Passes on at once, at the instant `time` of an impact inside a step of `h`, what it
/// leaves closing on what it touches: `struck` (members, with their velocities before the
/// impact) start the list; each closing contact of a struck member (a surface it was
/// driven into, a ball it drives into another) is struck at that instant, and the coupled
/// particles it strikes are looked at in turn, as the step's start passes a blow along a
/// row of touching balls. (An uncoupled particle struck here passes its blow on at the
/// next step's start, as after any impact inside the step.) A ball driven into the floor
/// that holds it bounces off it there and then, so the step need not end at the impact:
/// ending it cost a whole pass through the pipeline, 294 of the 1,894 passes of the mixed
/// scene of 1,000 balls over 1.6 s. Returns whether it got through within [`PASSES`]
/// strikes, and the members whose state in `at` it wrote.
fn pass_on(
    (contacts, forces): (&mut Contacts, &ForceModel),
    (motion, at, members_forces): (&mut Motion, &mut State, &ForceModel),
    (local, members): (&[Option<u32>], &[usize]),
    struck: &mut Vec<(usize, DVec2)>,
    (time, h): (f64, f64),
) -> (bool, Vec<usize>) {
    let mut pending: Vec<usize> = struck.iter().map(|&(k, _)| k).collect();
    let mut written = pending.clone();
    let mut strikes = 0;
    while let Some(k) = pending.pop() {
        let p = members[k];
        let neighbours = contacts.neighbours_at(p, at.position[k]);
        for &q in &neighbours {
            if let Some(j) = local[q].map(|j| j as usize)
                && !written.contains(&j)
            {
                motion.write(j, time, h, at, members_forces);
                written.push(j);
            }
        }
        let closing = {
            let at = Members { local, state: at };
            contacts.closing_at(p, &neighbours, InStep { time, step: h }, &at, forces)
        };
        for impact in closing {
            if strikes == PASSES {
                return (false, written);
            }
            let coupled = involved(impact, local);
            for j in coupled.into_iter().flatten() {
                if !struck.iter().any(|&(s, _)| s == j) {
                    struck.push((j, at.velocity[j]));
                }
            }
            let mut at = Members { local, state: at };
            if contacts.strike_coupled(impact, time, h, &mut at, forces) {
                strikes += 1;
                for j in coupled.into_iter().flatten() {
                    if !pending.contains(&j) {
                        pending.push(j);
                    }
                }
            }
        }
    }
    (true, written)
}
