//! The simulation's side of rods and strings ([`crate::constraints`]): which strings are
//! taut at the start of each step, the instant inside a step at which a string snaps taut
//! or goes slack, and the projection back onto the links' lengths after each step.

use glam::DVec2;

use super::Simulation;
use super::SimulationError;
use crate::tuning::{EVENT_ITERATIONS, EVENT_TIME_TOLERANCE};
use crate::tuning::{FULL_LENGTH, TIE_HELD};

impl Simulation {
    /// At construction: the positions and velocities projected onto the rods (and onto
    /// strings stretched past their length), and the strings' modes chosen.
    pub(super) fn begin_ties_at_start(&mut self) {
        if self.forces.constraints.is_empty() {
            return;
        }
        // A tie not held at the start is found again by the first step, which says so.
        // One already held (a saved state's) is left exactly as it is.
        if !self
            .forces
            .constraints
            .holds(&self.state.position, &self.state.velocity)
        {
            let _ = self.project_onto_ties();
        }
        self.begin_ties(self.time_step);
    }

    /// At the start of a step of `h`: a slack string at full length whose ends separate
    /// snaps taut now; then each string's mode is chosen. Returns whether velocities or
    /// modes changed.
    pub(super) fn begin_ties(&mut self, h: f64) -> bool {
        let constraints = &mut self.forces.constraints;
        // Rods are always taut: only strings have modes to choose.
        if !constraints
            .links
            .iter()
            .any(crate::constraints::Link::is_string)
        {
            return false;
        }
        let (x, v, w) = (
            &self.state.position,
            &mut self.state.velocity,
            &self.forces.inverse_mass[..],
        );
        let mut changed = false;
        for k in 0..constraints.links.len() {
            let length = constraints.links[k].length;
            if constraints.links[k].is_string()
                && !constraints.taut[k]
                && constraints.slack(k, x) <= FULL_LENGTH * length
                && constraints.separation_speed(k, x, v) * h > FULL_LENGTH * length
            {
                constraints.snap(k, x, v, w);
                changed = true;
            }
        }
        let mut a = vec![DVec2::ZERO; x.len()];
        self.forces
            .free_accelerations(self.state.time, x, v, &mut a);
        let constraints = &mut self.forces.constraints;
        constraints.choose_taut(x, v, w, &a, h) || changed
    }

    /// Where each string's event stands at the current state: a taut string's tension
    /// (N), a slack string's room to its length (m). Positive until the event; a rod's
    /// entry means nothing. The tensions, when needed, are solved once for all.
    fn tie_event_values(&self) -> Vec<f64> {
        let constraints = &self.forces.constraints;
        let links = 0..constraints.links.len();
        let taut_strings = links
            .clone()
            .any(|k| constraints.taut[k] && constraints.links[k].is_string());
        let tensions = if taut_strings {
            self.forces
                .tensions(self.state.time, &self.state.position, &self.state.velocity)
        } else {
            Vec::new()
        };
        links
            .map(|k| {
                if constraints.taut[k] {
                    tensions.get(k).copied().unwrap_or(0.0)
                } else {
                    constraints.slack(k, &self.state.position)
                }
            })
            .collect()
    }

    /// After a trial step of `taken` seconds: the first string to snap taut or go slack
    /// inside it, and when (seconds into the step). The state is then the one integrated
    /// from the step's start to that instant. Each event is located by the Illinois
    /// variant of regula falsi on the integrated state, to [`EVENT_TIME_TOLERANCE`]; the
    /// instant returned is the bracket's far side, where the event has just happened.
    pub(super) fn find_tie_event(&mut self, taken: f64) -> Option<(usize, f64)> {
        let constraints = &self.forces.constraints;
        if constraints.is_empty() {
            return None;
        }
        let values = self.tie_event_values();
        let due: Vec<(usize, f64)> = (0..constraints.links.len())
            .filter(|&k| constraints.links[k].is_string() && values[k] <= 0.0)
            .map(|k| (k, values[k]))
            .collect();
        if due.is_empty() {
            return None;
        }
        let end = self.state.clone();
        let mut first: Option<(usize, f64)> = None;
        for (k, at_end) in due {
            self.state.clone_from(&self.start);
            let at_start = self.tie_event_values()[k];
            if at_start.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                continue; // due since the start: the next step's start deals with it
            }
            let time = self.locate(k, (at_start, at_end), taken);
            if first.is_none_or(|(_, t)| time < t) {
                first = Some((k, time));
            }
        }
        match first {
            Some((_, time)) => self.integrate_from_start(time),
            None => self.state = end,
        }
        first
    }

    /// The instant in (0, `taken`] at which string `k`'s event value, `values` at the two
    /// ends of the step, turns negative.
    fn locate(&mut self, k: usize, values: (f64, f64), taken: f64) -> f64 {
        let ((mut lo, mut f_lo), (mut hi, mut f_hi)) = ((0.0, values.0), (taken, values.1));
        let mut side = 0;
        for _ in 0..EVENT_ITERATIONS {
            if hi - lo <= EVENT_TIME_TOLERANCE {
                break;
            }
            let secant = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
            let t = if secant > lo && secant < hi {
                secant
            } else {
                0.5 * (lo + hi)
            };
            self.integrate_from_start(t);
            let f = self.tie_event_values()[k];
            if f > 0.0 {
                (lo, f_lo) = (t, f);
                if side == 1 {
                    f_hi *= 0.5;
                }
                side = 1;
            } else {
                (hi, f_hi) = (t, f);
                if side == -1 {
                    f_lo *= 0.5;
                }
                side = -1;
            }
        }
        hi
    }

    /// Applies string `k`'s event at the current state: a slack string snaps taut, a
    /// taut one goes slack.
    pub(super) fn apply_tie_event(&mut self, k: usize) {
        let constraints = &mut self.forces.constraints;
        if constraints.taut[k] {
            constraints.taut[k] = false;
        } else {
            constraints.snap(
                k,
                &self.state.position,
                &mut self.state.velocity,
                &self.forces.inverse_mass,
            );
        }
    }

    /// Puts the positions and velocities back onto the links' lengths and rates.
    ///
    /// # Errors
    /// A link the projection could not bring within [`TIE_HELD`] of its length (forces
    /// far too strong for the time step, masses too unequal for f64 to tie, lengths that
    /// cannot all hold): a run that went on would answer wrong in silence.
    pub(super) fn project_onto_ties(&mut self) -> Result<(), SimulationError> {
        let worst = self.forces.constraints.project(
            &mut self.state.position,
            &mut self.state.velocity,
            &self.forces.inverse_mass,
        );
        if worst <= TIE_HELD {
            return Ok(());
        }
        let constraints = &self.forces.constraints;
        match constraints.most_stretched(&self.state.position) {
            // NaN counts as not held.
            Some((k, off)) if off.is_nan() || off > TIE_HELD => {
                let tie = self.tie_names[k].clone();
                let time = self.state.time;
                // Rounding within a few times of the bound is what keeps the link from it:
                // the projection itself converges to far below.
                let rounding = constraints.rounding(k, &self.state.position);
                Err(if rounding > TIE_HELD / 4.0 {
                    SimulationError::TieTooFar {
                        tie,
                        time,
                        length: constraints.length(k),
                    }
                } else {
                    SimulationError::TieNotHeld { tie, time }
                })
            }
            _ => Ok(()),
        }
    }

    /// Each rod's and string's tension now, N (pulling positive, 0 for a slack string),
    /// in the order of [`crate::Scene::ties`].
    pub fn tensions(&self) -> Vec<f64> {
        self.forces
            .tensions(self.state.time, &self.state.position, &self.state.velocity)
    }
}
