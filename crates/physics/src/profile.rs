//! Where a step's time goes, stage by stage (Box2D's `b2Profile`).
//!
//! The library reads no clock: the caller lends one with [`crate::Simulation::set_clock`]
//! (`std::time::Instant` natively, `performance.now()` in a browser). Without a clock
//! nothing is measured and a stage boundary costs one branch.

/// A clock: seconds since any fixed instant.
pub type Clock = fn() -> f64;

/// The stages of a step (`Simulation::advance`), in the order they run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// Candidate pairs from the uniform grid (at the start of the step, and of the swept
    /// paths after integration).
    BroadPhase,
    /// Touching contacts at the start of the step: impacts happening now, particles put
    /// under their surfaces' normal force and friction.
    StartContacts,
    /// The smooth forces integrated over the step.
    Integration,
    /// Impacts searched on the paths through the step, and applied in time order.
    TimeOfImpact,
    /// Impacts of coupled particles (under pair forces or springs) inside the step: with
    /// rk4 answered by the forces, else integrated again; or the whole system integrated
    /// to the instant of one that ends the step.
    CoupledImpacts,
    /// The resting-contact solver and the overlap correction.
    RestingSolver,
}

impl Stage {
    /// Every stage, in order.
    pub const ALL: [Self; 6] = [
        Self::BroadPhase,
        Self::StartContacts,
        Self::Integration,
        Self::TimeOfImpact,
        Self::CoupledImpacts,
        Self::RestingSolver,
    ];

    /// A short name for reports.
    pub const fn name(self) -> &'static str {
        match self {
            Self::BroadPhase => "broad phase",
            Self::StartContacts => "contacts at start",
            Self::Integration => "integration",
            Self::TimeOfImpact => "time of impact",
            Self::CoupledImpacts => "coupled impacts",
            Self::RestingSolver => "resting solver",
        }
    }
}

/// Seconds spent in each stage since the clock was set, summed over steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Profile {
    seconds: [f64; Stage::ALL.len()],
    /// Seconds in work that may be split across threads (inside the stages).
    pub(crate) parallel: f64,
}

impl Profile {
    /// Seconds spent in `stage`.
    pub fn seconds(&self, stage: Stage) -> f64 {
        self.seconds[stage as usize]
    }

    /// Seconds in all stages together.
    pub fn total(&self) -> f64 {
        self.seconds.iter().sum()
    }

    /// Seconds, inside the stages, spent in work that may be split across threads (the
    /// contact search's pieces, the pair sums, the tree's leaves), whether it was split
    /// or not. Measured on one thread, it is the work more threads could share.
    pub fn parallel_seconds(&self) -> f64 {
        self.parallel.min(self.total())
    }

    /// Amdahl's law on a profile measured on one thread: the speed-up `threads` threads
    /// would give if the work that may be split were split perfectly and the rest stayed
    /// serial, 1 / (s + p / threads). An upper bound: splitting costs something.
    pub fn amdahl(&self, threads: usize) -> f64 {
        let total = self.total();
        if total <= 0.0 {
            return 1.0;
        }
        let p = self.parallel_seconds() / total;
        1.0 / ((1.0 - p) + p / threads.max(1) as f64)
    }
}

/// A running stopwatch over the stages: [`Self::lap`] books the time since the last lap
/// to a stage.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Profiler {
    clock: Option<Clock>,
    last: f64,
    pub profile: Profile,
}

impl Profiler {
    pub fn new(clock: Option<Clock>) -> Self {
        Self {
            clock,
            last: clock.map_or(0.0, |now| now()),
            profile: Profile::default(),
        }
    }

    /// Starts timing from now (at the start of a step).
    pub fn start(&mut self) {
        if let Some(now) = self.clock {
            self.last = now();
        }
    }

    /// Books the time since the last lap (or start) to `stage`.
    pub fn lap(&mut self, stage: Stage) {
        if let Some(now) = self.clock {
            let now = now();
            self.profile.seconds[stage as usize] += now - self.last;
            self.last = now;
        }
    }
}
