//! Events: a quantity crossing a value (`Bob.vx crosses 0 down`), located in time as
//! exactly as impacts are, by stepping to the instant rather than interpolating samples.
//!
//! A [`Watch`] follows a run step by step ([`Simulation::step_to_watching`]): after each
//! step it reads every event's quantity, and where one has crossed its value since the
//! step began it finds the instant inside the step by integrating again from the step's
//! start to trial instants (each a single shorter step, exactly what the integrator gives
//! there) and closing in on the crossing by regula falsi (the Illinois variant, which
//! keeps a bracket and never stalls on one side). It stops when the bracket is 1e-12 s
//! wide or as narrow as f64 allows, and reports the first instant found past the
//! crossing, with the whole state there. The run itself is not touched: it takes the same
//! steps with the same bits as without a watch.
//!
//! A quantity that jumps (a velocity at an impact) crosses at the jump: the instant found
//! is the impact's. Within one step at most one crossing of each event is seen (the first
//! if a quantity went there and back, which needs a motion faster than the step can
//! follow anyway). A start exactly on the value is not a crossing, nor is touching the
//! value without passing it.

use crate::quantity::{Direction, Event, LinkOf, Reading, Turn};
use crate::simulation::{Simulation, SimulationError};

/// An event that happened: which, and the whole state at its instant.
#[derive(Clone, Debug)]
pub struct Located {
    /// Its index among the watch's events.
    pub event: usize,
    /// The simulation at the instant ([`Simulation::time`]), to read anything of.
    pub at: Simulation,
}

impl Located {
    /// The instant, seconds.
    pub fn time(&self) -> f64 {
        self.at.time()
    }
}

/// Events followed through a run.
#[derive(Clone, Debug)]
pub struct Watch {
    /// Each event's quantity as found in the simulation, its value and direction.
    events: Vec<(Reading, f64, Direction)>,
    /// Each event's quantity at the end of the last step.
    last: Vec<f64>,
}

/// The bracket's width at which an instant counts as found, seconds.
const FOUND: f64 = 1e-12;
/// A change of a quantity, relative to its size, that is rounding rather than motion: a
/// few ulps of the readings' last operations.
const ROUNDING: f64 = 16.0 * f64::EPSILON;
/// Trial instants per event at most: far more than regula falsi needs, but a bound.
const MOST_TRIALS: usize = 200;

impl Watch {
    /// A watch of `events` in `simulation`, from its present state on.
    ///
    /// # Errors
    /// An event names an object the simulation does not have.
    pub fn new(events: &[Event], simulation: &Simulation) -> Result<Self, String> {
        let events = events
            .iter()
            .map(|e| Ok((e.quantity.reading(simulation)?, e.value, e.direction)))
            .collect::<Result<Vec<_>, String>>()?;
        Ok(Self::of_readings(events, simulation))
    }

    /// A watch of `reading` crossing `value` in `direction`, for each of `events`, in
    /// `simulation` from its present state on (readings found already, or a light gate's
    /// [`Reading::Side`]).
    pub fn of_readings(events: Vec<(Reading, f64, Direction)>, simulation: &Simulation) -> Self {
        let last = events
            .iter()
            .map(|&(reading, _, _)| simulation.read(reading))
            .collect();
        Self { events, last }
    }

    /// How many events it watches.
    pub fn len(&self) -> usize {
        self.events.len()
    }

    /// Whether it watches none.
    pub fn is_empty(&self) -> bool {
        self.events.is_empty()
    }

    /// Looks for crossings in the step from `before` to `after` (the run's own states)
    /// and adds each, located, to `found`, in time order.
    pub(crate) fn after_step(
        &mut self,
        before: &Simulation,
        after: &Simulation,
        found: &mut Vec<Located>,
    ) -> Result<(), SimulationError> {
        let first = found.len();
        for (event, &(reading, value, direction)) in self.events.iter().enumerate() {
            let earlier = self.last[event];
            let now = after.read(reading);
            // A quantity held constant (a rod's length) wanders in its last bits: a
            // change within rounding is no motion, and no crossing. The reading before
            // it is kept, so that a slow drift is seen once it adds up past rounding.
            let scale = earlier.abs().max(now.abs()).max(value.abs());
            if (now - earlier).abs() <= ROUNDING * scale {
                continue;
            }
            self.last[event] = now;
            // A link's angle is read in (−180, 180]: a jump by 360° across ±180 is the
            // link turning on through the top, not a crossing of every value between.
            // Within a step it is followed from where it was (a step turns a link by far
            // less than half a turn).
            let wraps = matches!(reading, Reading::Link(_, LinkOf::Angle));
            let unwrapped = |angle: f64| {
                if wraps {
                    earlier + (angle - earlier - 360.0 * ((angle - earlier) / 360.0).round())
                } else {
                    angle
                }
            };
            let start = earlier - value;
            if crossed(direction, start, unwrapped(now) - value) {
                let at = locate(
                    before,
                    after,
                    |s| unwrapped(s.read(reading)) - value,
                    |g| crossed(direction, start, g),
                )?;
                found.push(Located { event, at });
            }
        }
        found[first..].sort_by(|a, b| a.time().total_cmp(&b.time()));
        Ok(())
    }
}

/// Whether a quantity (minus its value) that was `start` has crossed `direction`-wise by
/// the time it is `now`.
fn crossed(direction: Direction, start: f64, now: f64) -> bool {
    let up = start < 0.0 && now >= 0.0;
    let down = start > 0.0 && now <= 0.0;
    match direction {
        Direction::Either => up || down,
        Direction::Up => up,
        Direction::Down => down,
    }
}

/// The first instant found inside the step from `before` to `after` at which `has`
/// holds of `g` (it does at `after`, not at `before`), with the state there.
fn locate(
    before: &Simulation,
    after: &Simulation,
    g: impl Fn(&Simulation) -> f64,
    has: impl Fn(f64) -> bool,
) -> Result<Simulation, SimulationError> {
    let (mut a, mut ga) = (before.time(), g(before));
    let (mut b, mut gb) = (after.time(), g(after));
    let mut at_b: Option<Simulation> = None;
    // Which end moved last: regula falsi halves the other's weight when one end sticks.
    let mut last_moved = 0_i8;
    for _ in 0..MOST_TRIALS {
        let width = b - a;
        if width <= FOUND || width <= 4.0 * f64::EPSILON * b.abs() {
            break;
        }
        let secant = (a * gb - b * ga) / (gb - ga);
        // Never at an end nor outside (a flat or jumping quantity): then halve.
        let t = if secant > a && secant < b {
            secant
        } else {
            0.5 * (a + b)
        };
        if t <= a || t >= b {
            break; // a and b are neighbouring numbers
        }
        let mut trial = before.keyframe();
        trial.step_to(t)?;
        let gt = g(&trial);
        if has(gt) {
            (b, gb) = (t, gt);
            at_b = Some(trial);
            if last_moved == 1 {
                ga *= 0.5;
            }
            last_moved = 1;
        } else {
            (a, ga) = (t, gt);
            if last_moved == -1 {
                gb *= 0.5;
            }
            last_moved = -1;
        }
    }
    Ok(at_b.unwrap_or_else(|| after.keyframe()))
}

impl Simulation {
    /// [`Self::step_to`] `time`, the same steps with the same bits, watching `watch`'s
    /// events: returns those that happened, each located inside its step, in time order.
    ///
    /// # Errors
    /// As [`Self::step_to`]; a failure while locating an event is the run's failure there.
    pub fn step_to_watching(
        &mut self,
        time: f64,
        watch: &mut Watch,
    ) -> Result<Vec<Located>, SimulationError> {
        let mut found = Vec::new();
        self.step_to_watching_into(time, watch, &mut found)?;
        Ok(found)
    }

    /// [`Self::step_to_watching`], adding the events to `found` as they are located: those
    /// located before a failure are there when it is returned, so that no row computed
    /// before it is lost.
    ///
    /// # Errors
    /// As [`Self::step_to_watching`].
    pub fn step_to_watching_into(
        &mut self,
        time: f64,
        watch: &mut Watch,
        found: &mut Vec<Located>,
    ) -> Result<(), SimulationError> {
        self.step_to_observed(
            time,
            Some(&mut |before: &Simulation, after: &Simulation| {
                watch.after_step(before, after, found)
            }),
        )
    }

    /// [`Self::step_to_watching`], handing each event to `each` at the end of the step it
    /// is located in rather than keeping them: a run with many events holds none (each
    /// is a whole simulation at its instant). An error from `each` stops the run there.
    ///
    /// # Errors
    /// As [`Self::step_to_watching`], or `each`'s.
    pub fn step_to_watching_each(
        &mut self,
        time: f64,
        watch: &mut Watch,
        each: &mut (dyn FnMut(Located) -> Result<(), SimulationError> + Send),
    ) -> Result<(), SimulationError> {
        let mut found = Vec::new();
        self.step_to_observed(
            time,
            Some(&mut |before: &Simulation, after: &Simulation| {
                let located = watch.after_step(before, after, &mut found);
                // Those located before a failure to locate another are rows all the same.
                for event in found.drain(..) {
                    each(event)?;
                }
                located
            }),
        )
    }
}

/// Golden-section trials at most: each narrows the bracket by 0.618, so 120 take it
/// from a second to far below what f64 tells apart.
const MOST_GOLDEN_TRIALS: usize = 120;

impl Simulation {
    /// The state at the instant between this state's and `until` at which `reading` is at
    /// its `turn` — for a span that holds one turning point, as the samples around a
    /// sampled maximum do. Where the reading has an exact rate ([`Reading::rate`]: a
    /// position), the instant is where that rate crosses 0, located as an event (to
    /// 1e-12 s); otherwise it is found by golden-section search on the reading itself,
    /// each trial integrated from this state, to 1e-12 s or as close as the values tell
    /// apart (near a smooth maximum a value changes as the square of the time, so about
    /// the square root of f64's precision, 1e-8 of the span's scale). An end of the span
    /// is the answer when the reading is largest (smallest) there.
    ///
    /// # Errors
    /// A failure while integrating to a trial instant.
    pub fn extreme_until(
        &self,
        reading: Reading,
        until: f64,
        turn: Turn,
    ) -> Result<Self, SimulationError> {
        if let Some(rate) = reading.rate() {
            let direction = match turn {
                Turn::Maximum => Direction::Down,
                Turn::Minimum => Direction::Up,
            };
            let mut run = self.keyframe();
            let mut watch = Watch::of_readings(vec![(rate, 0.0, direction)], &run);
            if let Some(found) = run.step_to_watching(until, &mut watch)?.into_iter().next() {
                return Ok(found.at);
            }
        }
        let sign = match turn {
            Turn::Maximum => 1.0,
            Turn::Minimum => -1.0,
        };
        let at = |t: f64| -> Result<(f64, Self), SimulationError> {
            let mut trial = self.keyframe();
            if t > trial.time() {
                trial.step_to(t)?;
            }
            Ok((sign * trial.read(reading), trial))
        };
        let golden = 0.5 * (5.0_f64.sqrt() - 1.0);
        let (mut a, mut b) = (self.time(), until.max(self.time()));
        let (mut c, mut d) = (b - golden * (b - a), a + golden * (b - a));
        let (mut fc, mut sc) = at(c)?;
        let (mut fd, mut sd) = at(d)?;
        for _ in 0..MOST_GOLDEN_TRIALS {
            if b - a <= FOUND || b - a <= 4.0 * f64::EPSILON * b.abs() {
                break;
            }
            if fc >= fd {
                (b, d, fd, sd) = (d, c, fc, sc);
                c = b - golden * (b - a);
                (fc, sc) = at(c)?;
            } else {
                (a, c, fc, sc) = (c, d, fd, sd);
                d = a + golden * (b - a);
                (fd, sd) = at(d)?;
            }
        }
        let (fa, sa) = at(a)?;
        let (fb, sb) = at(b)?;
        let best = [(fa, sa), (fb, sb), (fc, sc), (fd, sd)]
            .into_iter()
            .max_by(|x, y| x.0.total_cmp(&y.0))
            .map(|(_, s)| s);
        Ok(best.unwrap_or_else(|| self.keyframe()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_crossing_is_strict_at_its_start() {
        assert!(crossed(Direction::Either, -1.0, 0.0));
        assert!(crossed(Direction::Up, -1.0, 2.0));
        assert!(!crossed(Direction::Up, 1.0, -2.0));
        assert!(crossed(Direction::Down, 1.0, -2.0));
        assert!(
            !crossed(Direction::Either, 0.0, 1.0),
            "from the value itself"
        );
        assert!(!crossed(Direction::Either, 1.0, 2.0));
    }
}
