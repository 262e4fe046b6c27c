//! The stopwatch: simulated time between two events, started and stopped by hand, by the
//! next impact, or by a particle crossing the tape measure's line (a light gate).
//!
//! An impact's instant is the one the simulation located (to 1e-9 s). A crossing of the
//! gate is found between two frames, its instant interpolated linearly between them: good
//! to the motion's curvature over a frame, a few milliseconds of simulated time at most at
//! real-time speed.

use physics::{DVec2, ImpactRecord};

/// What starts or stops the stopwatch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trigger {
    /// The Start and Stop buttons.
    Hand,
    /// The next impact of any two things.
    Impact,
    /// A particle's centre crossing the tape measure's line.
    Gate,
}

impl Trigger {
    pub const ALL: [Self; 3] = [Self::Hand, Self::Impact, Self::Gate];

    pub fn label(self) -> String {
        crate::i18n::tr(match self {
            Self::Hand => "stopwatch-by-hand",
            Self::Impact => "stopwatch-next-impact",
            Self::Gate => "stopwatch-gate",
        })
    }
}

/// Where the stopwatch stands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum State {
    /// Showing the last interval (0 at first).
    Stopped,
    /// Waiting for its start event.
    Armed,
    /// Counting since this simulated time, seconds.
    Running(f64),
}

/// The stopwatch.
#[derive(Clone, Debug)]
pub struct Stopwatch {
    pub shown: bool,
    pub start_on: Trigger,
    pub stop_on: Trigger,
    pub state: State,
    /// The interval measured, seconds: the last one, or the running one so far.
    pub reading: f64,
    /// The impacts already seen (the recording's count).
    seen: usize,
    /// The simulated time and positions at the last update, for the gate.
    last: Option<(f64, Vec<DVec2>)>,
}

impl Default for Stopwatch {
    fn default() -> Self {
        Self {
            shown: false,
            start_on: Trigger::Hand,
            stop_on: Trigger::Hand,
            state: State::Stopped,
            reading: 0.0,
            seen: 0,
            last: None,
        }
    }
}

impl Stopwatch {
    /// Start pressed at simulated time `now`: counting at once by hand, else armed.
    pub fn start(&mut self, now: f64) {
        self.reading = 0.0;
        self.state = if self.start_on == Trigger::Hand {
            State::Running(now)
        } else {
            State::Armed
        };
    }

    /// Stop pressed at `now`.
    pub fn stop(&mut self, now: f64) {
        if let State::Running(since) = self.state {
            self.reading = now - since;
        }
        self.state = State::Stopped;
    }

    /// Back to zero, stopped.
    pub fn reset(&mut self) {
        self.state = State::Stopped;
        self.reading = 0.0;
    }

    /// After the frame's physics: the run is at `now` with `positions`; `impacts` are all
    /// the run's impacts so far; `gate` is the tape's line, if laid. Events since the
    /// last update start or stop the watch at their own instants.
    pub fn update(
        &mut self,
        now: f64,
        positions: &[DVec2],
        impacts: &[ImpactRecord],
        gate: Option<(DVec2, DVec2)>,
    ) {
        if self.state == State::Stopped {
            // Nothing to wait for: note what has happened, keep no copy of the positions.
            self.seen = impacts.len();
            self.last = None;
            return;
        }
        let new_impacts: Vec<f64> = impacts.iter().skip(self.seen).map(|i| i.time).collect();
        self.seen = impacts.len();
        let mut crossings = match (&self.last, gate) {
            (Some((then, before)), Some(line)) if *then < now => {
                crossings(line, (*then, before), (now, positions))
            }
            _ => Vec::new(),
        };
        crossings.sort_by(f64::total_cmp);
        let gate_used = self.start_on == Trigger::Gate || self.stop_on == Trigger::Gate;
        self.last = gate_used.then(|| (now, positions.to_vec()));
        let events = |trigger: Trigger| match trigger {
            Trigger::Hand => Vec::new(),
            Trigger::Impact => new_impacts.clone(),
            Trigger::Gate => crossings.clone(),
        };
        if self.state == State::Armed
            && let Some(&t) = events(self.start_on).first()
        {
            self.state = State::Running(t);
        }
        if let State::Running(since) = self.state {
            match events(self.stop_on).into_iter().find(|&t| t > since) {
                Some(t) => {
                    self.reading = t - since;
                    self.state = State::Stopped;
                }
                None => self.reading = now - since,
            }
        }
    }

    /// Forgets the run (after Reset, or a new Play): impacts and positions start afresh.
    pub fn forget_run(&mut self) {
        self.seen = 0;
        self.last = None;
        if matches!(self.state, State::Running(_)) {
            self.state = State::Stopped;
        }
    }
}

/// The instants at which a particle's centre crossed the segment `line` between the two
/// samples (time, positions), interpolated linearly.
fn crossings(line: (DVec2, DVec2), before: (f64, &[DVec2]), after: (f64, &[DVec2])) -> Vec<f64> {
    let (a, b) = line;
    let along = b - a;
    if along.length_squared() == 0.0 {
        return Vec::new();
    }
    let side = |x: DVec2| along.perp_dot(x - a);
    let within = |x: DVec2| (0.0..=1.0).contains(&((x - a).dot(along) / along.length_squared()));
    let ((t0, x0), (t1, x1)) = (before, after);
    x0.iter()
        .zip(x1)
        .filter_map(|(&p, &q)| {
            let (s0, s1) = (side(p), side(q));
            if s0 == 0.0 || s0.signum() == s1.signum() {
                return None;
            }
            let f = s0 / (s0 - s1);
            let at = p.lerp(q, f);
            within(at).then_some(t0 + (t1 - t0) * f)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ball falling through a horizontal gate at y = 0 between frames at 1.0 s
    /// (y = 0.25) and 1.1 s (y = −0.75): crossing a quarter of the way, at 1.025 s.
    #[test]
    fn a_crossing_is_interpolated_between_frames() {
        let gate = (DVec2::new(-1.0, 0.0), DVec2::new(1.0, 0.0));
        let t = crossings(
            gate,
            (1.0, &[DVec2::new(0.0, 0.25)]),
            (1.1, &[DVec2::new(0.0, -0.75)]),
        );
        assert_eq!(t.len(), 1);
        assert!((t[0] - 1.025).abs() < 1e-12, "{t:?}");
        // Beside the gate, no crossing.
        let beside = crossings(
            gate,
            (1.0, &[DVec2::new(3.0, 0.25)]),
            (1.1, &[DVec2::new(3.0, -0.75)]),
        );
        assert!(beside.is_empty());
    }

    /// Started by one impact and stopped by the next, the reading is the time between
    /// their located instants, whatever the frames.
    #[test]
    fn impacts_start_and_stop_it_at_their_instants() {
        let impact = |time| ImpactRecord {
            time,
            particle: 0,
            other: physics::ImpactTarget::Wall,
            impulse: 1.0,
            normal_speed_before: 1.0,
            normal_speed_after: 1.0,
            kinetic_energy_lost: 0.0,
        };
        let mut watch = Stopwatch {
            start_on: Trigger::Impact,
            stop_on: Trigger::Impact,
            ..Stopwatch::default()
        };
        watch.start(0.0);
        assert_eq!(watch.state, State::Armed);
        let x = [DVec2::ZERO];
        watch.update(0.5, &x, &[], None);
        watch.update(1.0, &x, &[impact(0.8125)], None);
        assert_eq!(watch.state, State::Running(0.8125));
        watch.update(1.5, &x, &[impact(0.8125)], None);
        assert!(
            (watch.reading - 0.6875).abs() < 1e-15,
            "running: {}",
            watch.reading
        );
        watch.update(2.0, &x, &[impact(0.8125), impact(1.90625)], None);
        assert_eq!(watch.state, State::Stopped);
        assert_eq!(watch.reading.to_bits(), (1.90625_f64 - 0.8125).to_bits());
    }
}
