//! Playing a scene in real time: the simulation advances in fixed steps of its own time
//! step, as many per frame as the frame's wall time × time scale calls for, decoupled
//! from the frame rate. Stepping stops when a frame's budget of computing time is spent;
//! the debt is then dropped rather than carried (carrying it would freeze the app), and
//! the speed actually achieved is measured and shown, so a slow computer says "running at
//! 0.6× of the requested speed" instead of silently slowing down.

use std::cell::RefCell;
use std::collections::VecDeque;

use physics::{DVec2, Diagnostics, LoadError, Scene, Simulation};
use web_time::Instant;

use crate::recording::Recording;
use crate::timeline::Timeline;
use crate::watching::Watching;

/// The frame time the app keeps to while physics is behind: 30 frames per second.
/// Physics gets what is left of each frame after drawing and the rest of the app
/// (measured, smoothed), within [`LEAST_BUDGET`, `MOST_BUDGET`]: a heavy scene runs as
/// fast as the frame rate allows, and says how far it falls short of real time.
const TARGET_FRAME: f64 = 1.0 / 30.0;
/// Physics per frame at least, seconds: even when drawing alone takes a whole frame.
const LEAST_BUDGET: f64 = 0.004;
/// Physics per frame at most, seconds.
const MOST_BUDGET: f64 = 0.025;
/// Physics on another thread while a frame is drawn, seconds at most: the next frame
/// stops it sooner (see [`Runner::step_ahead`]).
#[cfg(not(target_arch = "wasm32"))]
const AHEAD_BUDGET: f64 = 0.1;
/// Physics per frame on the app's own thread while it steps ahead, seconds at most.
const AHEAD_SYNC_BUDGET: f64 = 0.008;
/// The longest step, seconds of computing, for which the physics steps on while frames
/// are drawn (see [`Runner::steps_ahead`]).
const LONGEST_STEP_AHEAD: f64 = 0.002;
/// Real seconds over which the speed achieved is measured.
const ACHIEVED_WINDOW: f64 = 0.5;
/// A frame longer than this (a stall, a breakpoint) does not ask for more physics.
const LONGEST_FRAME: f64 = 0.1;
/// Points kept per trail.
pub const TRAIL_LENGTH: usize = 400;

/// Earlier runs kept for the graphs: enough to compare a few settings, each recording
/// bounded by its own budget (`recording.rs`).
pub const EARLIER_RUNS: usize = 3;

/// Where the run is.
#[expect(
    clippy::large_enum_variant,
    reason = "one per app, and the simulation is read every frame: a box would only add a pointer"
)]
enum Run {
    /// No run: the scene is being edited (before Play, and after Reset).
    Editing,
    /// The simulation since Play, here to read and to step.
    Here(Simulation),
    /// The simulation stepping on on another thread while the app draws
    /// ([`Runner::step_ahead`]), back at the next frame's [`Runner::catch_up`].
    #[cfg(not(target_arch = "wasm32"))]
    Away(ahead::Stepping),
}

impl Run {
    /// Takes the simulation out, if it is here (the run is then being edited until one is
    /// put back).
    fn take(&mut self) -> Option<Simulation> {
        if matches!(self, Run::Here(_))
            && let Run::Here(simulation) = std::mem::replace(self, Run::Editing)
        {
            return Some(simulation);
        }
        None
    }
}

pub struct Runner {
    /// The run since Play, until Reset.
    run: Run,
    pub playing: bool,
    /// Simulated seconds owed to real time.
    debt: f64,
    /// Simulated seconds per real second achieved, over the last half second or more.
    pub achieved: Option<f64>,
    /// Simulated and real seconds since `achieved` was last measured.
    window: (f64, f64),
    /// Physics steps per second of computing time, smoothed.
    pub steps_per_second: Option<f64>,
    /// Computing time spent on physics per frame, seconds, smoothed.
    pub physics_per_frame: Option<f64>,
    /// The rest of a frame (drawing, the app), seconds, smoothed.
    other_per_frame: Option<f64>,
    /// Physics time of the last frame, seconds.
    last_physics: f64,
    /// The wall time of the last frame, seconds (at most [`LONGEST_FRAME`]).
    last_real_dt: f64,
    /// The last run, sampled from its start: kept after Reset until the next Play.
    pub recording: Option<Recording>,
    /// The runs before it (of this scene, oldest first, at most [`EARLIER_RUNS`]), which
    /// the graphs draw greyed behind the last: a series of runs compared at a glance.
    pub earlier: Vec<Recording>,
    /// Why the simulation stopped, if it failed.
    pub failure: Option<String>,
    /// Total energy when Play built the simulation, joules.
    pub start_energy: f64,
    /// Recent positions of each particle, when trails are shown.
    pub trails: Vec<VecDeque<DVec2>>,
    /// The run's keyframes, to go back to any step of it.
    pub timeline: Option<Timeline>,
    /// The readouts' energies and momentum, and the step and time they are of: summing
    /// a large gravitating scene's potential energy costs a tree walk (longer than a frame
    /// for a star cluster), so a step's is computed once, by the recording when it samples that step,
    /// and not again at every frame that shows it.
    readout: RefCell<Option<(u64, f64, Diagnostics)>>,
    /// Whether the physics steps on while the app draws (desktop only: see
    /// [`Runner::step_ahead`]).
    pub ahead: bool,
    /// Whether each frame steps all the simulated time it owes, however long that takes,
    /// instead of stopping at the frame's budget of computing time: the tests', so that
    /// what a number of frames plays does not depend on the machine's load.
    pub unhurried: bool,
    /// The events the stopwatch waits for, located inside the steps.
    pub watching: Option<Watching>,
}

impl Default for Runner {
    fn default() -> Self {
        Self {
            run: Run::Editing,
            playing: false,
            debt: 0.0,
            achieved: None,
            window: (0.0, 0.0),
            steps_per_second: None,
            physics_per_frame: None,
            other_per_frame: None,
            last_physics: 0.0,
            last_real_dt: 0.0,
            recording: None,
            earlier: Vec::new(),
            failure: None,
            start_energy: 0.0,
            trails: Vec::new(),
            timeline: None,
            readout: RefCell::new(None),
            ahead: false,
            unhurried: false,
            watching: None,
        }
    }
}

impl Runner {
    /// A runner with nothing run yet, stepping as this one does (ahead, unhurried).
    #[must_use]
    pub fn fresh(&self) -> Self {
        Self {
            ahead: self.ahead,
            unhurried: self.unhurried,
            ..Self::default()
        }
    }
}

/// `d` with the step and time of `simulation` it is of.
fn readout_key(simulation: &Simulation, d: Diagnostics) -> (u64, f64, Diagnostics) {
    (simulation.steps_taken(), simulation.time(), d)
}

/// What a step leaves besides the state: its impacts and, when due, a sample in the
/// recording (whose diagnostics the readouts then show) and a keyframe.
fn keep_step(
    simulation: &mut Simulation,
    recording: &mut Option<Recording>,
    timeline: &mut Option<Timeline>,
    readout: &RefCell<Option<(u64, f64, Diagnostics)>>,
) {
    if let Some(recording) = recording {
        recording.note_impacts(simulation.take_impacts());
        if let Some(d) = recording.after_step(simulation) {
            readout.replace(Some(readout_key(simulation, d)));
        }
    }
    if let Some(timeline) = timeline {
        timeline.after_step(simulation);
    }
}

/// One step, watching the stopwatch's events where there are any.
fn step_watching(
    simulation: &mut Simulation,
    watching: &mut Option<Watching>,
) -> Result<(), physics::SimulationError> {
    match watching {
        Some(watching) => watching.step(simulation),
        None => simulation.step(),
    }
}

/// What a run of steps came to.
pub(crate) struct Taken {
    /// Simulated seconds.
    pub simulated: f64,
    pub steps: u32,
    /// Their computing time, seconds.
    pub computing: f64,
    /// Why the simulation stopped, if a step failed.
    pub failure: Option<String>,
    /// Whether the steps ended for want of computing time with a step still owed.
    pub out_of_time: bool,
}

/// The one stepping loop, for the app's own thread and the thread that steps ahead:
/// takes whole steps while one is `owed` (simulated seconds, paid off as they are taken),
/// each kept by [`keep_step`], until a step fails, `stop()` says so before a step, or a
/// step ends past `budget` seconds of computing (so a frame always takes at least one
/// step that is owed).
#[expect(
    clippy::too_many_arguments,
    reason = "the run's parts, borrowed apart so either thread can lend them"
)]
fn take_steps(
    simulation: &mut Simulation,
    recording: &mut Option<Recording>,
    timeline: &mut Option<Timeline>,
    readout: &RefCell<Option<(u64, f64, Diagnostics)>>,
    watching: &mut Option<Watching>,
    owed: &mut f64,
    budget: f64,
    stop: &dyn Fn() -> bool,
) -> Taken {
    let (clock, start) = (Instant::now(), simulation.time());
    let step = simulation.time_step();
    let mut taken = Taken {
        simulated: 0.0,
        steps: 0,
        computing: 0.0,
        failure: None,
        out_of_time: false,
    };
    while *owed >= step * (1.0 - 1e-9) && !stop() {
        if let Err(error) = step_watching(simulation, watching) {
            taken.failure = Some(error.to_string());
            break;
        }
        keep_step(simulation, recording, timeline, readout);
        *owed -= step;
        taken.steps += 1;
        if clock.elapsed().as_secs_f64() > budget {
            taken.out_of_time = *owed >= step * (1.0 - 1e-9);
            break;
        }
    }
    taken.simulated = simulation.time() - start;
    taken.computing = clock.elapsed().as_secs_f64();
    taken
}

impl Runner {
    /// The simulation since Play, until Reset; `None` while the scene is being edited.
    /// (While the run steps on another thread between frames there is none here either,
    /// but every frame takes it back first: [`Self::catch_up`].)
    pub fn simulation(&self) -> Option<&Simulation> {
        if let Run::Here(simulation) = &self.run {
            Some(simulation)
        } else {
            None
        }
    }

    /// [`Self::simulation`], to change.
    pub fn simulation_mut(&mut self) -> Option<&mut Simulation> {
        if let Run::Here(simulation) = &mut self.run {
            Some(simulation)
        } else {
            None
        }
    }

    /// Whether the scene is being edited: no run since Play (or since Reset).
    pub fn is_editing(&self) -> bool {
        matches!(self.run, Run::Editing)
    }

    /// The energies and momentum of the simulation's current state, for the readouts:
    /// computed once per step shown (see the `readout` field).
    pub fn diagnostics(&self) -> Option<Diagnostics> {
        let simulation = self.simulation()?;
        let mut readout = self.readout.borrow_mut();
        if let Some((steps, time, d)) = *readout
            && steps == simulation.steps_taken()
            && time.to_bits() == simulation.time().to_bits()
        {
            return Some(d);
        }
        let d = simulation.diagnostics();
        *readout = Some(readout_key(simulation, d));
        Some(d)
    }

    /// Builds the simulation if there is none.
    ///
    /// # Errors
    /// The scene's problems, if it is invalid.
    pub fn ensure_simulation(&mut self, scene: &Scene) -> Result<(), LoadError> {
        self.catch_up();
        if !self.is_editing() {
            return Ok(());
        }
        let mut simulation = Simulation::new(scene)?;
        // Every core (one in the browser): the same bits for any number.
        simulation.set_threads(physics::every_core());
        simulation.record_impacts();
        simulation.keep_ledger();
        self.start_energy = simulation.diagnostics().energy.total();
        if let Some(last) = self.recording.take().filter(|r| !r.is_empty()) {
            self.earlier.push(last);
            if self.earlier.len() > EARLIER_RUNS {
                self.earlier.remove(0);
            }
        }
        self.recording = Some(Recording::start(&simulation));
        self.timeline = Some(Timeline::start(&simulation));
        self.trails = vec![VecDeque::new(); simulation.len()];
        self.readout = RefCell::new(None);
        self.failure = None;
        self.debt = 0.0;
        self.run = Run::Here(simulation);
        Ok(())
    }

    /// Starts playing (building the simulation first if needed).
    ///
    /// # Errors
    /// The scene's problems, if it is invalid.
    pub fn play(&mut self, scene: &Scene) -> Result<(), LoadError> {
        self.ensure_simulation(scene)?;
        self.branch();
        if self.failure.is_none() {
            self.playing = true;
        }
        Ok(())
    }

    pub fn pause(&mut self) {
        self.catch_up();
        self.playing = false;
        self.debt = 0.0;
    }

    /// Back to the scene as last edited; the recording stays until the next Play.
    pub fn reset(&mut self) {
        self.catch_up();
        *self = Self {
            recording: self.recording.take(),
            earlier: std::mem::take(&mut self.earlier),
            ahead: self.ahead,
            ..Self::default()
        };
    }

    /// One time step, paused.
    ///
    /// # Errors
    /// The scene's problems, if it is invalid.
    pub fn step_once(&mut self, scene: &Scene, trails: bool) -> Result<(), LoadError> {
        self.pause();
        self.ensure_simulation(scene)?;
        // Gone back in time: Step walks forward through the run as it was.
        if let Some(timeline) = &self.timeline
            && let Some(shown) = timeline.shown
        {
            self.go_to(shown + 1);
            return Ok(());
        }
        if let Run::Here(simulation) = &mut self.run {
            match step_watching(simulation, &mut self.watching) {
                Ok(()) => keep_step(
                    simulation,
                    &mut self.recording,
                    &mut self.timeline,
                    &self.readout,
                ),
                Err(error) => self.failure = Some(error.to_string()),
            }
        }
        if trails {
            self.record_trails();
        }
        Ok(())
    }

    /// Advances by one frame that took `real_dt` seconds of wall time, at `time_scale`
    /// simulated seconds per real second (the scene's). Returns whether the simulation
    /// moved.
    pub fn advance(&mut self, real_dt: f64, time_scale: f64, trails: bool) -> bool {
        let stepped_ahead = self.catch_up();
        self.advance_after(real_dt, time_scale, trails, stepped_ahead)
    }

    /// [`Self::advance`] when the run was taken back earlier in the frame, with the
    /// simulated seconds stepped ahead while the last frame was drawn.
    pub fn advance_after(
        &mut self,
        real_dt: f64,
        time_scale: f64,
        trails: bool,
        stepped_ahead: f64,
    ) -> bool {
        if !self.playing {
            return false;
        }
        let ahead = self.steps_ahead();
        let Run::Here(simulation) = &mut self.run else {
            return false;
        };
        let real_dt = real_dt.clamp(0.0, LONGEST_FRAME);
        self.last_real_dt = real_dt;
        if real_dt > 0.0 {
            let other = (real_dt - self.last_physics).max(0.0);
            self.other_per_frame = Some(smooth(self.other_per_frame, other));
        }
        // Stepping ahead while the frame is drawn, the physics has a core of its own for
        // most of the frame: here it pays only what that left owing, briefly.
        let budget = if self.unhurried {
            f64::INFINITY
        } else if ahead {
            AHEAD_SYNC_BUDGET
        } else {
            (TARGET_FRAME - self.other_per_frame.unwrap_or(0.0)).clamp(LEAST_BUDGET, MOST_BUDGET)
        };
        let step = simulation.time_step();
        // What was stepped while the last frame was drawn is paid off what is owed now.
        self.debt += real_dt * time_scale - stepped_ahead;
        let start_time = simulation.time() - stepped_ahead;
        let taken = take_steps(
            simulation,
            &mut self.recording,
            &mut self.timeline,
            &self.readout,
            &mut self.watching,
            &mut self.debt,
            budget,
            &|| false,
        );
        if let Some(failure) = taken.failure {
            self.failure = Some(failure);
            self.playing = false;
        }
        if taken.out_of_time {
            // Behind: drop what is owed instead of carrying it into the next frame.
            self.debt = self.debt.min(step);
        }
        let (steps, computing) = (taken.steps, taken.computing);
        self.last_physics = computing;
        if steps > 0 && computing > 0.0 {
            self.steps_per_second =
                Some(smooth(self.steps_per_second, f64::from(steps) / computing));
        }
        self.physics_per_frame = Some(smooth(self.physics_per_frame, computing));
        // Over half a second at least: a frame takes a step or none, so with steps longer
        // than a frame (the star clusters' 50 ms) a frame's own ratio jumps between 0
        // and several times the truth.
        self.window.0 += simulation.time() - start_time;
        self.window.1 += real_dt;
        let (simulated, real) = self.window;
        if real >= ACHIEVED_WINDOW || self.achieved.is_none() && real > 0.0 {
            self.achieved = Some(simulated / real);
            if real >= ACHIEVED_WINDOW {
                self.window = (0.0, 0.0);
            }
        }
        if trails {
            self.record_trails();
        }
        steps > 0 || stepped_ahead > 0.0
    }

    /// Steps on, on another thread, while the app draws the frame just built: up to what
    /// the next frame will owe if it is as long as the last, until the next frame calls
    /// [`Self::catch_up`] (which waits for the step under way), or for 0.1 s at most
    /// when no frame comes. Drawing (tessellation and painting, after the frame is built)
    /// and physics then share the frame instead of taking turns. Only where the runner
    /// is asked to ([`Self::ahead`]: the desktop app) and threads exist; elsewhere
    /// nothing. The steps are the same steps in the same order, so the run is the same,
    /// bit for bit.
    pub fn step_ahead(&mut self, time_scale: f64) {
        #[cfg(not(target_arch = "wasm32"))]
        {
            if !self.steps_ahead() || !self.playing {
                return;
            }
            let Some(simulation) = self.run.take() else {
                return;
            };
            let owed = self.debt + self.last_real_dt * time_scale;
            self.run = Run::Away(ahead::Stepping::start(
                ahead::Run {
                    simulation,
                    recording: self.recording.take(),
                    timeline: self.timeline.take(),
                    readout: self.readout.take(),
                    watching: self.watching.take(),
                },
                owed,
                AHEAD_BUDGET,
            ));
        }
        #[cfg(target_arch = "wasm32")]
        let _ = time_scale;
    }

    /// Whether the physics steps on while frames are drawn: where asked and threads
    /// exist, and while steps are short. The next frame waits for the step under way, so
    /// long steps would stretch every frame: with steps of several milliseconds on two
    /// cores that the software renderer also uses, frames fall without faster physics
    /// (docs/performance.md has the figures).
    fn steps_ahead(&self) -> bool {
        self.ahead
            && cfg!(not(target_arch = "wasm32"))
            && self
                .steps_per_second
                .is_none_or(|rate| rate * LONGEST_STEP_AHEAD >= 1.0)
    }

    /// Takes back the run from the steps taken while the app drew ([`Self::step_ahead`]),
    /// stopping them after the step under way. Returns the simulated seconds they took.
    pub fn catch_up(&mut self) -> f64 {
        #[cfg(not(target_arch = "wasm32"))]
        if matches!(self.run, Run::Away(_))
            && let Run::Away(stepping) = std::mem::replace(&mut self.run, Run::Editing)
        {
            let (run, taken) = stepping.finish();
            self.run = Run::Here(run.simulation);
            self.recording = run.recording;
            self.timeline = run.timeline;
            self.readout = RefCell::new(run.readout);
            self.watching = run.watching;
            if let Some(failure) = taken.failure {
                self.failure = Some(failure);
                self.playing = false;
            }
            if taken.steps > 0 && taken.computing > 0.0 {
                self.steps_per_second = Some(smooth(
                    self.steps_per_second,
                    f64::from(taken.steps) / taken.computing,
                ));
            }
            return taken.simulated;
        }
        0.0
    }

    /// The speed achieved as a fraction of `time_scale`, when it falls short.
    pub fn shortfall(&self, time_scale: f64) -> Option<f64> {
        let achieved = self.achieved?;
        (self.playing && achieved < 0.95 * time_scale).then_some(achieved / time_scale)
    }

    /// Shows step `step` of the run (paused): the run's state there, from its keyframes.
    /// The newest step is the live end of the run again.
    pub fn go_to(&mut self, step: u64) {
        self.pause();
        let Some(timeline) = &mut self.timeline else {
            return;
        };
        let step = step.min(timeline.end);
        if timeline.live.is_none() {
            timeline.live = self.run.take();
        }
        if step == timeline.end {
            timeline.shown = None;
            if let Some(live) = timeline.live.take() {
                self.run = Run::Here(live);
            }
        } else if let Some(past) = timeline.state_at(step) {
            timeline.shown = Some(step);
            self.run = Run::Here(past);
        }
        self.trails.iter_mut().for_each(VecDeque::clear);
    }

    /// Shows the run at the instant `time` exactly (paused): the state stepped to it from
    /// the step before. The slider shows that step.
    pub fn go_to_time(&mut self, time: f64) {
        self.pause();
        let Some(timeline) = &mut self.timeline else {
            return;
        };
        if timeline.live.is_none() {
            timeline.live = self.run.take();
        }
        let Some(end_time) = timeline.live.as_ref().map(Simulation::time) else {
            return;
        };
        if time >= end_time {
            let end = timeline.end;
            self.go_to(end);
            return;
        }
        if let Some((step, state)) = timeline.state_at_time(time) {
            timeline.shown = Some(step);
            self.run = Run::Here(state);
        }
        self.trails.iter_mut().for_each(VecDeque::clear);
    }

    /// The simulated time of the run's newest state.
    pub fn end_time(&self) -> Option<f64> {
        // Gone back in time, the run's end waits in the timeline; else it is shown.
        let live = self.timeline.as_ref()?.live.as_ref();
        live.or(self.simulation()).map(Simulation::time)
    }

    /// Goes to the next (`forward`) or previous turning point of particle `i`: an instant
    /// where its velocity's x or y component passes through 0, located inside its step.
    /// Returns whether there was one in the run.
    pub fn go_to_turning_point(&mut self, i: usize, forward: bool) -> bool {
        let (Some(now), Some(end), Some(timeline)) = (
            self.simulation().map(Simulation::time),
            self.end_time(),
            &self.timeline,
        ) else {
            return false;
        };
        let zero = |of| {
            (
                physics::Reading::Particle(i, of),
                0.0,
                physics::Direction::Either,
            )
        };
        let events = [zero(physics::Of::Vx), zero(physics::Of::Vy)];
        match timeline.event_near(&events, now, forward, end) {
            Some(t) => {
                self.go_to_time(t);
                true
            }
            None => false,
        }
    }

    /// Goes to the next (`forward`) or previous impact of the run, at its located instant.
    /// Returns whether there was one.
    pub fn go_to_impact(&mut self, forward: bool) -> bool {
        let (Some(now), Some(recording)) =
            (self.simulation().map(Simulation::time), &self.recording)
        else {
            return false;
        };
        let margin = 1e-9;
        let impacts = recording.impacts().iter().map(|i| i.time);
        let found = if forward {
            impacts.filter(|&t| t > now + margin).reduce(f64::min)
        } else {
            impacts.filter(|&t| t < now - margin).reduce(f64::max)
        };
        match found {
            Some(t) => {
                self.go_to_time(t);
                true
            }
            None => false,
        }
    }

    /// One step back in the run.
    pub fn step_back(&mut self) {
        if let Some(timeline) = &self.timeline {
            let now = timeline.shown.unwrap_or(timeline.end);
            self.go_to(now.saturating_sub(1));
        }
    }

    /// Playing from a moment gone back to: the run after it is forgotten (graphs, impacts,
    /// keyframes) and a new one goes on from there.
    fn branch(&mut self) {
        let Some(timeline) = &mut self.timeline else {
            return;
        };
        let Some(step) = timeline.shown else {
            return;
        };
        timeline.truncate(step);
        if let (Some(recording), Run::Here(simulation)) = (&mut self.recording, &self.run) {
            recording.truncate_after(simulation.time());
        }
    }

    fn record_trails(&mut self) {
        let Run::Here(simulation) = &self.run else {
            return;
        };
        self.trails.resize(simulation.len(), VecDeque::new());
        for (trail, &position) in self.trails.iter_mut().zip(simulation.positions()) {
            if trail
                .back()
                .is_none_or(|last| last.distance(position) > 1e-9)
            {
                trail.push_back(position);
                if trail.len() > TRAIL_LENGTH {
                    trail.pop_front();
                }
            }
        }
    }
}

/// An exponential moving average that starts at the first sample (`average` is `None`
/// before it).
fn smooth(average: Option<f64>, sample: f64) -> f64 {
    average.map_or(sample, |average| 0.9 * average + 0.1 * sample)
}

/// The run stepped on another thread while the app draws ([`Runner::step_ahead`]).
#[cfg(not(target_arch = "wasm32"))]
mod ahead {
    use std::sync::Arc;
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::thread::JoinHandle;

    use physics::{Diagnostics, Simulation};

    use super::Taken;
    use crate::recording::Recording;
    use crate::timeline::Timeline;

    /// What a step changes besides the simulation, as the runner keeps it.
    pub struct Run {
        pub simulation: Simulation,
        pub recording: Option<Recording>,
        pub timeline: Option<Timeline>,
        pub readout: Option<(u64, f64, Diagnostics)>,
        pub watching: Option<crate::watching::Watching>,
    }

    /// Steps under way on a thread of their own.
    pub struct Stepping {
        stop: Arc<AtomicBool>,
        thread: Option<JoinHandle<(Run, Taken)>>,
    }

    impl Stepping {
        /// Steps `run` on, at most `owed` simulated seconds (whole steps) and `budget`
        /// seconds of computing, until [`Self::finish`].
        pub fn start(mut run: Run, owed: f64, budget: f64) -> Self {
            let stop = Arc::new(AtomicBool::new(false));
            let stopped = Arc::clone(&stop);
            let thread = std::thread::spawn(move || {
                let readout = std::cell::RefCell::new(run.readout.take());
                let mut owed = owed;
                let taken = super::take_steps(
                    &mut run.simulation,
                    &mut run.recording,
                    &mut run.timeline,
                    &readout,
                    &mut run.watching,
                    &mut owed,
                    budget,
                    &|| stopped.load(Ordering::Relaxed),
                );
                run.readout = readout.into_inner();
                (run, taken)
            });
            Self {
                stop,
                thread: Some(thread),
            }
        }

        /// Stops the steps after the one under way and returns the run.
        pub fn finish(mut self) -> (Run, Taken) {
            self.stop.store(true, Ordering::Relaxed);
            let thread = self.thread.take().expect("joined only here, once");
            match thread.join() {
                Ok(done) => done,
                // A panic in a step: the app has no run to go back to; pass it on, as a
                // panic in a step on the app's own thread would.
                Err(panic) => std::panic::resume_unwind(panic),
            }
        }
    }

    impl Drop for Stepping {
        /// A runner dropped mid-step (the app closing) lets the step end on its own.
        fn drop(&mut self) {
            self.stop.store(true, Ordering::Relaxed);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use physics::Particle;

    /// At time scale 2, ten frames of 1/60 s advance the simulation by 1/3 s (to a step).
    #[test]
    fn real_time_at_the_requested_scale() {
        let scene = Scene::new().with_particle(Particle::new("p", 1.0));
        let mut runner = Runner::default();
        runner.play(&scene).unwrap();
        for _ in 0..10 {
            runner.advance(1.0 / 60.0, 2.0, false);
        }
        let time = runner.simulation().unwrap().time();
        assert!(
            (time - 1.0 / 3.0).abs() <= 0.001 + 1e-9,
            "simulated {time} s"
        );
        runner.pause();
        runner.advance(1.0, 2.0, false);
        assert_eq!(
            runner.simulation().unwrap().time().to_bits(),
            time.to_bits(),
            "paused"
        );
    }

    /// Opening another scene starts a fresh runner that steps as the last did: the
    /// desktop's stepping ahead is not lost to File → Open; an unhurried runner plays all
    /// it owes even past a frame's budget (60 steps of a 1 ms time step in one 0.06 s
    /// frame, whatever the machine's load).
    #[test]
    fn a_fresh_runner_steps_as_the_last_did() {
        let scene = physics::example("pendulum").unwrap().scene().unwrap();
        let old = Runner {
            ahead: true,
            unhurried: true,
            ..Runner::default()
        };
        let mut runner = old.fresh();
        assert!(runner.ahead && runner.unhurried);
        runner.ahead = false;
        runner.play(&scene).unwrap();
        runner.advance(0.06, 1.0, false);
        let time = runner.simulation().unwrap().time();
        assert!((time - 0.06).abs() < 1e-9, "simulated {time} s");
    }

    /// Steps taken on another thread while frames are drawn are the steps taken in place:
    /// after frames that each step ahead while a "drawing" sleeps, the run is bit for bit
    /// a simulation stepped as many times on this thread, it is not ahead of real time
    /// by more than a frame, and the ahead steps were taken (the test could not fail
    /// otherwise).
    #[test]
    fn steps_taken_ahead_are_the_steps_taken_in_place() {
        let scene = physics::generated::ball_pit(200);
        let frame = 1.0 / 60.0;
        let mut runner = Runner {
            ahead: true,
            ..Runner::default()
        };
        runner.play(&scene).unwrap();
        let mut ahead = 0.0;
        for _ in 0..30 {
            let stepped = runner.catch_up();
            ahead += stepped;
            runner.advance_after(frame, 1.0, false, stepped);
            runner.step_ahead(1.0);
            std::thread::sleep(std::time::Duration::from_millis(8));
        }
        ahead += runner.catch_up();
        assert!(ahead > 0.05, "stepped ahead {ahead} s");
        let live = runner.simulation().expect("caught up");
        assert!(
            live.time() <= 31.0 * frame + 1e-9,
            "{} s after 30 frames",
            live.time()
        );
        let mut reference = Simulation::new(&scene).unwrap();
        for _ in 0..live.steps_taken() {
            reference.step().unwrap();
        }
        let bits = crate::timeline::tests::bits;
        assert_eq!(live.time().to_bits(), reference.time().to_bits());
        assert!(bits(live) == bits(&reference), "the same state");
        // The recording sampled the steps taken ahead too (every fifth step of 1 ms).
        let recorded = runner.recording.as_ref().and_then(Recording::last_time);
        assert!(
            recorded.is_some_and(|t| t > live.time() - 0.006),
            "recorded to {recorded:?}"
        );
    }

    /// With steps longer than a frame (50 ms steps at 120 frames a second: a step
    /// every sixth frame), the speed achieved is measured over half a second, not frame
    /// by frame, whose ratio jumps between 0 and 6: a light scene keeps up, and the
    /// figure says 1.0 (within 5 %) at every frame from the first second on (a ratio
    /// smoothed frame by frame swung between 0.86 and 1.28).
    #[test]
    fn the_speed_achieved_is_steady_with_steps_longer_than_a_frame() {
        let mut scene = Scene::new().with_particle(Particle::new("p", 1.0));
        scene.simulation.time_step = 0.05;
        let mut runner = Runner::default();
        runner.play(&scene).unwrap();
        for frame in 0..360 {
            runner.advance(1.0 / 120.0, 1.0, false);
            if frame >= 120 {
                assert!(
                    runner
                        .achieved
                        .is_some_and(|achieved| (achieved - 1.0).abs() < 0.05),
                    "frame {frame}: {:?}",
                    runner.achieved
                );
            }
        }
    }

    /// The readouts' energies are those of the state shown, whether the recording sampled
    /// that step (1 ms steps: every fifth) or not, after stepping, and after going back
    /// in time: a ball falling from rest has ½ m (g t)² of kinetic energy at t.
    #[test]
    fn the_readouts_are_of_the_step_shown() {
        let scene = Scene::new().with_particle(Particle::new("p", 2.0).position([0.0, 10.0]));
        let mut runner = Runner::default();
        let kinetic = |runner: &Runner| runner.diagnostics().expect("a simulation").energy.kinetic;
        let expected = |runner: &Runner| {
            let t = runner.simulation().expect("a simulation").time();
            0.5 * 2.0 * (9.81 * t) * (9.81 * t)
        };
        runner.step_once(&scene, false).unwrap();
        for _ in 0..12 {
            assert!((kinetic(&runner) - expected(&runner)).abs() < 1e-9);
            runner.step_once(&scene, false).unwrap();
        }
        runner.go_to(3);
        let t = runner.simulation().unwrap().time();
        assert!((t - 0.003).abs() < 1e-12, "at step 3: {t}");
        assert!((kinetic(&runner) - expected(&runner)).abs() < 1e-9);
    }
}
