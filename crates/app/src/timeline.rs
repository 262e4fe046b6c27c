//! The time machine: every run is kept as keyframes, copies of the simulation taken every
//! so many steps, so that any step of it can be shown again exactly. The simulation is
//! deterministic — a copy stepped again gives the bits the run had — so the state at
//! step k is the keyframe at or before k, stepped forward to k.
//!
//! A keyframe is [`Simulation::keyframe`]: a copy without the buffers each step fills
//! again (about 83 bytes a ball in a resting pile, against some 900 for a whole
//! copy). Memory is bounded however long the run: the keyframes together stay within
//! `BUDGET_BYTES` (as [`Simulation::keyframe_bytes`] counts them), and at most
//! [`MOST_KEYFRAMES`]. When the budget is used, every other one is dropped and the
//! interval doubles, so a long run keeps its whole length at a coarser spacing, and
//! going back to a moment costs at most one interval of steps.

use physics::Simulation;

/// What all keyframes together may take, bytes; a browser tab gets less. Chosen so that a
/// ten-minute recording of the 1,000-ball pit keeps a keyframe every 100 steps, and going
/// back anywhere in it replays at most 99 steps (`newtonlab bench --scene scrub --seconds
/// 600`; docs/performance.md has the figures).
#[cfg(not(target_arch = "wasm32"))]
const BUDGET_BYTES: usize = 512 << 20;
#[cfg(target_arch = "wasm32")]
const BUDGET_BYTES: usize = 64 << 20;
/// The most keyframes, however small the scene.
pub const MOST_KEYFRAMES: usize = 8192;
/// The first interval between keyframes, steps.
const FIRST_INTERVAL: u64 = 50;

/// The most keyframes kept for a scene whose keyframes take `bytes` each.
pub fn most_keyframes(bytes: usize) -> usize {
    (BUDGET_BYTES / bytes.max(1)).clamp(8, MOST_KEYFRAMES)
}

/// The keyframes of one run.
#[derive(Clone, Debug, Default)]
pub struct Timeline {
    /// (steps since Play, the simulation then), ascending; the first is step 0.
    keyframes: Vec<(u64, Simulation)>,
    /// Steps between keyframes.
    interval: u64,
    /// The run's newest step, and the newest state (the live end of the run).
    pub end: u64,
    pub live: Option<Simulation>,
    /// The step shown when the user went back in time, if they did.
    pub shown: Option<u64>,
}

impl Timeline {
    /// A timeline for a run starting at `simulation`.
    pub fn start(simulation: &Simulation) -> Self {
        Self {
            keyframes: vec![(0, simulation.keyframe())],
            interval: FIRST_INTERVAL,
            end: 0,
            live: None,
            shown: None,
        }
    }

    /// Notes that the run took a step and is now at `simulation`.
    pub fn after_step(&mut self, simulation: &Simulation) {
        self.end += 1;
        if self.end.is_multiple_of(self.interval) {
            let most = most_keyframes(simulation.keyframe_bytes());
            if self.keyframes.len() >= most {
                self.thin();
            }
            if self.end.is_multiple_of(self.interval) {
                self.keyframes.push((self.end, simulation.keyframe()));
            }
        }
    }

    /// Drops every keyframe not on the doubled interval.
    fn thin(&mut self) {
        self.interval *= 2;
        let interval = self.interval;
        self.keyframes.retain(|(step, _)| step % interval == 0);
    }

    /// Steps between keyframes now.
    pub fn interval(&self) -> u64 {
        self.interval
    }

    /// What the keyframes hold together, bytes (as [`Simulation::keyframe_bytes`]
    /// counts).
    pub fn bytes(&self) -> usize {
        self.keyframes
            .iter()
            .map(|(_, keyframe)| keyframe.keyframe_bytes())
            .sum()
    }

    /// How many keyframes are kept.
    pub fn len(&self) -> usize {
        self.keyframes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.keyframes.is_empty()
    }

    /// The run's state at `step` (at most the newest): a copy of the keyframe at or before
    /// it, stepped on. `None` if stepping failed (it did not in the run, so it cannot
    /// here, but a message beats a panic).
    pub fn state_at(&self, step: u64) -> Option<Simulation> {
        let step = step.min(self.end);
        let (at, keyframe) = self.keyframes.iter().rev().find(|(at, _)| *at <= step)?;
        let mut simulation = keyframe.clone();
        for _ in *at..step {
            simulation.step().ok()?;
        }
        // Nothing of the replay is news: its impacts were logged when the run made them.
        let _ = simulation.take_impacts();
        Some(simulation)
    }

    /// The run's state at the instant `time` (within the run), exactly there: the last
    /// step at or before it, stepped on to `time` (a step cut short, as `step_to` cuts
    /// the last step of a run). With the step it was reached from. `None` outside the run
    /// or if stepping failed.
    pub fn state_at_time(&self, time: f64) -> Option<(u64, Simulation)> {
        let (at, keyframe) = self
            .keyframes
            .iter()
            .rev()
            .find(|(_, k)| k.time() <= time)?;
        let mut simulation = keyframe.clone();
        let mut step = *at;
        while step < self.end && simulation.time() + simulation.time_step() <= time {
            simulation.step().ok()?;
            step += 1;
        }
        if simulation.time() < time {
            simulation.step_to(time).ok()?;
        }
        let _ = simulation.take_impacts();
        Some((step, simulation))
    }

    /// The first instant after `after` (if `forward`) or the last before it at which one
    /// of `events` happens, located inside its step, within the run; `None` if none does.
    /// Searched from keyframes: forward from the one at or before `after` to the run's
    /// end, backward in spans that double from there towards the start.
    pub fn event_near(
        &self,
        events: &[(physics::Reading, f64, physics::Direction)],
        after: f64,
        forward: bool,
        end_time: f64,
    ) -> Option<f64> {
        // Not the instant itself: a turning point shown is not the next one.
        let margin = 1e-9;
        let located = |from: &Simulation, until: f64| -> Vec<f64> {
            let mut simulation = from.clone();
            let mut watch = physics::Watch::of_readings(events.to_vec(), &simulation);
            simulation
                .step_to_watching(until, &mut watch)
                .map(|found| found.iter().map(physics::Located::time).collect())
                .unwrap_or_default()
        };
        let before = self
            .keyframes
            .iter()
            .rposition(|(_, k)| k.time() <= after)?;
        if forward {
            let from = &self.keyframes[before].1;
            return located(from, end_time)
                .into_iter()
                .find(|&t| t > after + margin);
        }
        let mut span = 1;
        loop {
            let first = before.saturating_sub(span);
            let from = &self.keyframes[first].1;
            let found = located(from, after)
                .into_iter()
                .rfind(|&t| t < after - margin);
            if found.is_some() || first == 0 {
                return found;
            }
            span *= 2;
        }
    }

    /// `quantity` found in the run's objects; `None` if the run has no such object.
    pub fn reading(&self, quantity: &physics::Quantity) -> Option<physics::Reading> {
        quantity.reading(&self.keyframes.first()?.1).ok()
    }

    /// Takes from `budget` (particle-steps) what locating something between `from` and
    /// `until` costs at most, if it holds that much: the steps from a keyframe there,
    /// and a hundred trials across the span (each a few steps of its own).
    pub fn pay_for(&self, (from, until): (f64, f64), budget: &mut f64) -> bool {
        let Some((_, first)) = self.keyframes.first() else {
            return false;
        };
        let across = ((until - from) / first.time_step()).ceil().max(1.0);
        let cost = first.len() as f64 * (self.interval as f64 + 100.0 * across);
        let paid = cost <= *budget;
        if paid {
            *budget -= cost;
        }
        paid
    }

    /// The run's state at the instant between `from` and `until` (the samples around a
    /// sampled maximum or minimum) at which `reading` is at its `turn`
    /// ([`Simulation::extreme_until`]); `None` outside the run or if stepping failed.
    pub fn extreme_between(
        &self,
        reading: physics::Reading,
        (from, until): (f64, f64),
        turn: physics::Turn,
    ) -> Option<Simulation> {
        let (_, start) = self.state_at_time(from)?;
        start.extreme_until(reading, until, turn).ok()
    }

    /// The first instant between `from` and `until` at which `reading` crosses `value`,
    /// located inside its step; `None` if it does not within the run.
    pub fn crossing_between(
        &self,
        reading: physics::Reading,
        value: f64,
        (from, until): (f64, f64),
    ) -> Option<f64> {
        let (_, mut simulation) = self.state_at_time(from)?;
        let event = (reading, value, physics::Direction::Either);
        let mut watch = physics::Watch::of_readings(vec![event], &simulation);
        let found = simulation.step_to_watching(until, &mut watch).ok()?;
        found.first().map(physics::Located::time)
    }

    /// Forgets everything after `step`: the run goes on from there as a new branch.
    pub fn truncate(&mut self, step: u64) {
        self.keyframes.retain(|(at, _)| *at <= step);
        self.end = step;
        self.live = None;
        self.shown = None;
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use physics::DVec2;

    /// The bits of a simulation's positions and velocities (also the run loop's tests').
    pub(crate) fn bits(simulation: &Simulation) -> Vec<u64> {
        let bits = |v: &DVec2| [v.x.to_bits(), v.y.to_bits()];
        simulation
            .positions()
            .iter()
            .chain(simulation.velocities())
            .flat_map(bits)
            .collect()
    }

    /// Any step of a run of the 1,000-ball pit, shown again from the keyframes, has the
    /// bits the run had there, through the thinning of a run longer than the keyframes.
    #[test]
    fn any_step_comes_back_bit_for_bit() {
        let scene = physics::example("ball-pit").unwrap().scene().unwrap();
        let mut simulation = Simulation::new(&scene).unwrap();
        let mut timeline = Timeline::start(&simulation);
        let mut states = vec![bits(&simulation)];
        for _ in 0..1200 {
            simulation.step().unwrap();
            timeline.after_step(&simulation);
            states.push(bits(&simulation));
        }
        assert!(timeline.len() >= 2, "keyframes taken");
        for step in [0_usize, 1, 49, 50, 777, 1199, 1200] {
            let shown = timeline.state_at(step as u64).expect("replayed");
            assert!(shown.time() > 0.0 || step == 0);
            assert!(bits(&shown) == states[step], "step {step}");
        }
    }

    /// A run far longer than the keyframes keeps its whole length: the interval doubles
    /// and the count stays within the bound.
    #[test]
    fn keyframes_stay_bounded_and_span_the_run() {
        let scene = physics::example("collision").unwrap().scene().unwrap();
        let mut simulation = Simulation::new(&scene).unwrap();
        let mut timeline = Timeline::start(&simulation);
        let most = most_keyframes(simulation.keyframe_bytes());
        for _ in 0..FIRST_INTERVAL * most as u64 * 3 {
            simulation.step().unwrap();
            timeline.after_step(&simulation);
            assert!(timeline.len() <= most, "{} keyframes", timeline.len());
        }
        assert_eq!(timeline.keyframes[0].0, 0, "the start is kept");
        let last = timeline.keyframes.last().unwrap().0;
        assert!(
            timeline.end - last <= timeline.interval,
            "the end is near a keyframe"
        );
    }
}
