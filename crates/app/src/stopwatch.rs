//! The stopwatch: simulated time between two events — pressing Play, an impact, a
//! particle crossing the tape's line (a light gate), a typed event such as
//! `rod.angle crosses 0 down`, or a press of Stop — each the Nth of its kind since the
//! watch was armed, so a full period is the 1st and 3rd crossing of the vertical. In lap
//! mode it keeps every interval of a run, with their mean.
//!
//! Every instant is the one the simulation located: impacts to 1e-9 s, the gate and typed
//! events inside their step to 1e-12 s (`watching.rs`), never between frames. It can be
//! armed before Play.

use physics::ImpactRecord;

use crate::watching::{Cue, Wanted};

/// What starts or stops the stopwatch: the scene format's words
/// (`[instruments.stopwatch]`), so that a scene keeps them.
pub use physics::Trigger;

/// A trigger in the user's words.
pub fn label(trigger: Trigger) -> String {
    crate::i18n::tr(match trigger {
        Trigger::Hand => "stopwatch-by-hand",
        Trigger::Play => "stopwatch-on-play",
        Trigger::Impact => "stopwatch-impact",
        Trigger::Gate => "stopwatch-gate",
        Trigger::Event => "stopwatch-event",
    })
}

/// The trigger a watched instant is.
fn trigger_of(cue: Cue) -> Trigger {
    match cue {
        Cue::Event => Trigger::Event,
        Cue::Gate => Trigger::Gate,
    }
}

/// Where the stopwatch stands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum State {
    /// Showing the last interval (0 at first).
    Stopped,
    /// Waiting for its start.
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
    /// Which occurrence of `start_on` starts it, counted from the arming (1 the first).
    pub start_nth: u32,
    /// Which occurrence of `stop_on` stops it, counted from the arming too, so that the
    /// 1st and the 3rd crossing of a pendulum's vertical are a period.
    pub stop_nth: u32,
    /// The event `Trigger::Event` waits for, as typed.
    pub event: String,
    /// Whether it keeps going, a lap at every stop, until stopped by hand.
    pub lap_mode: bool,
    pub state: State,
    /// The interval measured, seconds: the last one, or the running one so far.
    pub reading: f64,
    /// The laps of lap mode, seconds.
    pub laps: Vec<f64>,
    /// Why the typed event cannot be watched, if it cannot.
    pub problem: Option<String>,
    /// Occurrences since the arming: of the start's kind, of the stop's kind.
    counted: (u32, u32),
    /// When the current lap began.
    lap_from: f64,
    /// The impacts already seen (the recording's count).
    seen: usize,
    /// Whether a run was there at the last update.
    had_run: bool,
}

impl Default for Stopwatch {
    fn default() -> Self {
        Self {
            shown: false,
            start_on: Trigger::Hand,
            stop_on: Trigger::Hand,
            start_nth: 1,
            stop_nth: 1,
            event: String::new(),
            lap_mode: false,
            state: State::Stopped,
            reading: 0.0,
            laps: Vec::new(),
            problem: None,
            counted: (0, 0),
            lap_from: 0.0,
            seen: 0,
            had_run: false,
        }
    }
}

impl Stopwatch {
    /// A new stopwatch, its window `shown` or not (a new scene keeps the window, not the
    /// reading).
    pub fn shown_as(shown: bool) -> Self {
        Self {
            shown,
            ..Self::default()
        }
    }

    /// The stopwatch a scene keeps: shown, set as it was saved, and armed when anything
    /// but a hand starts it, so that the run's first instants count.
    pub fn from_saved(saved: &physics::Stopwatch) -> Self {
        Self {
            shown: true,
            start_on: saved.start,
            start_nth: saved.start_count,
            stop_on: saved.stop,
            stop_nth: saved.stop_count,
            event: saved.event.clone().unwrap_or_default(),
            lap_mode: saved.laps,
            state: if saved.start == Trigger::Hand {
                State::Stopped
            } else {
                State::Armed
            },
            ..Self::default()
        }
    }

    /// The typed event as the parser and the scene file read it: trimmed, a decimal
    /// comma typed in German or Spanish written as a point.
    fn event_text(&self) -> String {
        crate::format::typed(self.event.trim())
    }

    /// Why the typed event cannot be watched on `scene`, said as it is typed (before
    /// Play): it does not read, or it names nothing in the scene. `None` when no trigger
    /// waits for a typed event, or the event reads.
    pub fn event_problem(&self, scene: &physics::Scene) -> Option<String> {
        let waits = self.start_on == Trigger::Event || self.stop_on == Trigger::Event;
        let event = &self.event_text();
        if !waits || event.is_empty() {
            return None;
        }
        physics::Event::parse(event)
            .and_then(|e| e.quantity.check_in(scene))
            .err()
    }

    /// What a scene keeps of it: its settings, when it is shown or set to anything but
    /// the hand. An event that does not read on `scene`, or a gate without a tape
    /// (`has_tape`), is kept as the hand (the window shows why meanwhile): a file that
    /// would not open again is never written.
    pub fn saved(&self, scene: &physics::Scene, has_tape: bool) -> Option<physics::Stopwatch> {
        let event = &self.event_text();
        let event_reads = physics::Event::parse(event)
            .and_then(|e| e.quantity.check_in(scene))
            .is_ok();
        let kept = |trigger: Trigger| match trigger {
            Trigger::Event if !event_reads => Trigger::Hand,
            Trigger::Gate if !has_tape => Trigger::Hand,
            other => other,
        };
        let saved = physics::Stopwatch {
            start: kept(self.start_on),
            start_count: self.start_nth.max(1),
            stop: kept(self.stop_on),
            stop_count: self.stop_nth.max(1),
            event: event_reads.then(|| event.to_owned()),
            laps: self.lap_mode,
        };
        (self.shown || saved != physics::Stopwatch::default()).then_some(saved)
    }

    /// The measure of a lesson's question whose answer is this stopwatch's reading, as a
    /// series writes it: from Play to the Nth occurrence of a typed event that reads on
    /// `scene`, a scene starting at t = 0 (the measure is the event's instant), no laps.
    /// None for what no measure says (a gate, impacts, the hand).
    pub fn question(&self, scene: &physics::Scene) -> Option<String> {
        let event = &self.event_text();
        let reads = physics::Event::parse(event)
            .and_then(|e| e.quantity.check_in(scene))
            .is_ok();
        let timed = self.start_on == Trigger::Play && self.stop_on == Trigger::Event;
        if !(timed && reads && !self.lap_mode && scene.simulation.start_time == 0.0) {
            return None;
        }
        Some(match self.stop_nth {
            0 | 1 => format!("t at {event}"),
            n => format!("t at {event} #{n}"),
        })
    }

    /// Sets it to time a full period at the light gate: the 1st to the 3rd crossing of
    /// the tape (a pendulum crosses a gate through its pivot twice a period).
    pub fn period_at_the_gate(&mut self) {
        (self.start_on, self.start_nth) = (Trigger::Gate, 1);
        (self.stop_on, self.stop_nth) = (Trigger::Gate, 3);
    }

    /// Sets it to time the flight between the 1st and the 2nd impact (a bounce).
    pub fn between_impacts(&mut self) {
        (self.start_on, self.start_nth) = (Trigger::Impact, 1);
        (self.stop_on, self.stop_nth) = (Trigger::Impact, 2);
    }

    /// Start pressed at simulated time `now`: counting at once by hand, else armed (also
    /// before Play: the run's first instants count).
    pub fn start(&mut self, now: f64) {
        self.reading = 0.0;
        self.laps.clear();
        self.counted = (0, 0);
        self.state = if self.start_on == Trigger::Hand {
            self.lap_from = now;
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

    /// Back to zero, stopped, its laps forgotten.
    pub fn reset(&mut self) {
        self.state = State::Stopped;
        self.reading = 0.0;
        self.laps.clear();
    }

    /// The run started playing at simulated time `now`.
    pub fn played(&mut self, now: f64) {
        if self.state == State::Armed && self.start_on == Trigger::Play {
            self.begin(now);
        }
    }

    /// What the run must watch for it: the typed event and the gate, where they start or
    /// stop it while it waits or runs.
    pub fn wanted(&self, gate: Option<(physics::DVec2, physics::DVec2)>) -> Wanted {
        let waiting = matches!(self.state, State::Armed | State::Running(_));
        let uses = |trigger| waiting && (self.start_on == trigger || self.stop_on == trigger);
        Wanted {
            event: (uses(Trigger::Event) && !self.event.trim().is_empty())
                .then(|| self.event_text()),
            gate: gate.filter(|_| uses(Trigger::Gate)),
        }
    }

    /// The mean lap, seconds, once there is one.
    pub fn mean_lap(&self) -> Option<f64> {
        (!self.laps.is_empty()).then(|| self.laps.iter().sum::<f64>() / self.laps.len() as f64)
    }

    /// After the frame's physics: the run is at `now`; `impacts` are all the run's
    /// impacts so far; `cues` the gate's and the typed event's instants since the last
    /// update. Each starts or stops the watch at its own instant, in time order.
    pub fn update(&mut self, now: f64, impacts: &[ImpactRecord], cues: &[(Cue, f64)]) {
        self.had_run = true;
        let mut instants: Vec<(Trigger, f64)> = impacts
            .iter()
            .skip(self.seen)
            .map(|i| (Trigger::Impact, i.time))
            .chain(cues.iter().map(|&(cue, t)| (trigger_of(cue), t)))
            .collect();
        self.seen = impacts.len();
        instants.sort_by(|a, b| a.1.total_cmp(&b.1));
        for (trigger, t) in instants {
            self.occurred(trigger, t);
        }
        if let State::Running(since) = self.state {
            self.reading = now - since;
        }
    }

    /// `trigger` happened at `t`.
    fn occurred(&mut self, trigger: Trigger, t: f64) {
        if self.state == State::Stopped {
            return;
        }
        let starts = trigger == self.start_on;
        let stops = trigger == self.stop_on;
        if starts {
            self.counted.0 += 1;
        }
        if stops {
            self.counted.1 += 1;
        }
        match self.state {
            State::Armed if starts && self.counted.0 == self.start_nth => self.begin(t),
            State::Running(since) if stops && t > since => {
                let every = self.lap_every();
                let due = self.counted.1 >= self.stop_nth
                    && (self.counted.1 - self.stop_nth).is_multiple_of(every);
                if !due {
                    return;
                }
                if self.lap_mode {
                    self.laps.push(t - self.lap_from);
                    self.lap_from = t;
                } else {
                    self.reading = t - since;
                    self.state = State::Stopped;
                }
            }
            _ => {}
        }
    }

    fn begin(&mut self, t: f64) {
        self.state = State::Running(t);
        self.lap_from = t;
    }

    /// Occurrences of the stop's kind per lap: the span from the start to the stop when
    /// one kind does both (the 1st to the 3rd crossing: every two), else every one.
    fn lap_every(&self) -> u32 {
        if self.start_on == self.stop_on && self.stop_nth > self.start_nth {
            self.stop_nth - self.start_nth
        } else {
            1
        }
    }

    /// Forgets the run (after Reset, or a new Play): impacts start afresh; a watch that
    /// was running waits again for its start.
    pub fn forget_run(&mut self) {
        if !self.had_run {
            return;
        }
        self.had_run = false;
        self.seen = 0;
        self.counted = (0, 0);
        if matches!(self.state, State::Running(_)) {
            self.state = State::Stopped;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn impact(time: f64) -> ImpactRecord {
        ImpactRecord {
            time,
            particle: 0,
            other: physics::ImpactTarget::Wall,
            impulse: 1.0,
            normal_speed_before: 1.0,
            normal_speed_after: 1.0,
            kinetic_energy_lost: 0.0,
        }
    }

    /// Started by one impact and stopped by the next, the reading is the time between
    /// their located instants, whatever the frames.
    #[test]
    fn impacts_start_and_stop_it_at_their_instants() {
        let mut watch = Stopwatch {
            start_on: Trigger::Impact,
            stop_on: Trigger::Impact,
            stop_nth: 2,
            ..Stopwatch::default()
        };
        watch.start(0.0);
        assert_eq!(watch.state, State::Armed);
        watch.update(0.5, &[], &[]);
        watch.update(1.0, &[impact(0.8125)], &[]);
        assert_eq!(watch.state, State::Running(0.8125));
        watch.update(1.5, &[impact(0.8125)], &[]);
        assert_eq!(watch.reading.to_bits(), (1.5_f64 - 0.8125).to_bits());
        watch.update(2.0, &[impact(0.8125), impact(1.90625)], &[]);
        assert_eq!(watch.state, State::Stopped);
        assert_eq!(watch.reading.to_bits(), (1.90625_f64 - 0.8125).to_bits());
    }

    /// A full period from a gate the bob crosses twice a period: the 1st and 3rd
    /// crossings; in lap mode every two crossings make a lap, and their mean is the
    /// period.
    #[test]
    fn the_first_and_third_crossing_are_a_period_and_laps_repeat_it() {
        let crossings: Vec<(Cue, f64)> = (0..7).map(|k| (Cue::Gate, 0.5 + f64::from(k))).collect();
        let mut watch = Stopwatch {
            start_on: Trigger::Gate,
            stop_on: Trigger::Gate,
            stop_nth: 3,
            ..Stopwatch::default()
        };
        watch.start(0.0);
        watch.update(10.0, &[], &crossings);
        assert_eq!(watch.state, State::Stopped);
        assert_eq!(
            watch.reading.to_bits(),
            2.0_f64.to_bits(),
            "1st at 0.5, 3rd at 2.5"
        );
        watch.lap_mode = true;
        watch.start(10.0);
        let later: Vec<(Cue, f64)> = crossings.iter().map(|&(c, t)| (c, t + 10.0)).collect();
        watch.update(20.0, &[], &later);
        assert_eq!(watch.laps, vec![2.0, 2.0, 2.0], "laps of 2 crossings");
        assert_eq!(watch.mean_lap(), Some(2.0));
        assert!(
            matches!(watch.state, State::Running(_)),
            "until stopped by hand"
        );
    }

    /// Armed before Play with "start on Play", it starts at the run's start.
    #[test]
    fn armed_before_play_it_starts_with_the_run() {
        let mut watch = Stopwatch {
            start_on: Trigger::Play,
            stop_on: Trigger::Event,
            event: "bob.vx crosses 0".to_owned(),
            ..Stopwatch::default()
        };
        watch.start(0.0);
        assert_eq!(watch.state, State::Armed);
        assert!(
            watch.wanted(None).event.is_some(),
            "the event is watched while armed"
        );
        watch.played(0.0);
        watch.update(1.2, &[], &[(Cue::Event, 1.0764)]);
        assert_eq!(watch.state, State::Stopped);
        assert_eq!(watch.reading.to_bits(), 1.0764_f64.to_bits());
    }
}
