//! Why a run stopped: every failure of the simulation, in words that name the object,
//! the instant and what to change.

/// Why a simulation stopped.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SimulationError {
    /// A position or velocity became infinite or NaN, or ran away beyond 1e150.
    #[error("{}", crate::scene::say("run-non-finite", &[("time", &time.to_string()), ("particle", particle)]))]
    NonFinite {
        /// The first particle, in scene order, with a non-finite value.
        particle: String,
        /// Seconds.
        time: f64,
    },
    /// A quantity of the state (an acceleration, an energy) is infinite or NaN though
    /// the positions and velocities are finite: bodies so close that the force between
    /// them overflows.
    #[error("{}", crate::scene::say("run-value-not-finite", &[("time", &time.to_string()), ("quantity", quantity), ("value", &value.to_string())]))]
    ValueNotFinite {
        /// The column: `NAME.ax`, `potential_energy`, ….
        quantity: String,
        /// What it came out as: inf, −inf or NaN.
        value: f64,
        /// Seconds.
        time: f64,
    },
    /// The adaptive integrator could not meet its tolerance with any step f64 can take.
    #[error("{}", crate::scene::say("run-step-too-small", &[("time", &time.to_string()), ("tolerance", &tolerance.to_string())]))]
    StepTooSmall {
        /// Seconds.
        time: f64,
        /// The scene's tolerance.
        tolerance: f64,
    },
    /// Reaching the requested instant took far more adaptive steps than the time step
    /// implies: the time step is far too long for the motion.
    #[error("{}", crate::scene::say("run-too-many-steps", &[
        ("time", &time.to_string()),
        ("target", &format!("{target:e}")),
        ("limit", &limit.to_string()),
        ("step", &format!("{time_step:e}")),
    ]))]
    TooManySteps {
        /// Seconds, where it stopped.
        time: f64,
        /// Seconds, the instant asked for.
        target: f64,
        /// The scene's time step, seconds.
        time_step: f64,
        /// The steps allowed.
        limit: u64,
    },
    /// A particle left the world's bounds: too fast for the time step to resolve its
    /// impacts with the walls.
    #[error("{}", crate::scene::say("run-left-bounds", &[("time", &time.to_string()), ("particle", particle), ("speed", &format!("{speed:.3e}"))]))]
    LeftBounds {
        /// The particle's name.
        particle: String,
        /// Seconds.
        time: f64,
        /// Its speed then, m/s.
        speed: f64,
    },
    /// Air resistance too strong for a fixed time step: the method would multiply the
    /// velocity at each step instead of following its decay.
    #[error("{}", crate::scene::say("run-drag-too-strong", &[
        ("time", &time.to_string()),
        ("particle", particle),
        ("decay", &format!("{decay:.3e}")),
        ("step", &time_step.to_string()),
    ]))]
    DragTooStrong {
        /// The particle's name.
        particle: String,
        /// Seconds.
        time: f64,
        /// The time its velocity takes to fall by e, seconds: the longest step to take.
        decay: f64,
        /// The step it was to take, seconds.
        time_step: f64,
    },
    /// A rod or a string could not be held at its length (forces far too strong for the
    /// time step, masses too unequal for f64 to tie, or lengths that cannot all hold).
    #[error("{}", crate::scene::say("run-tie-not-held", &[("time", &time.to_string()), ("tie", tie)]))]
    TieNotHeld {
        /// The rod's or string's name.
        tie: String,
        /// Seconds.
        time: f64,
    },
    /// A body on a pulley's string was pulled up to the wheel: the string has no run left
    /// on its side.
    #[error("{}", crate::scene::say("run-pulley-reached", &[("time", &time.to_string()), ("pulley", pulley), ("body", body)]))]
    PulleyReached {
        /// The pulley's name.
        pulley: String,
        /// The body's name.
        body: String,
        /// Seconds.
        time: f64,
    },
    /// A rod or a string so far from the origin for its length that f64's rounding of its
    /// ends' positions alone keeps it from being held to a billionth of its length.
    #[error("{}", crate::scene::say("run-tie-too-far", &[("time", &time.to_string()), ("tie", tie), ("length", &length.to_string())]))]
    TieTooFar {
        /// The rod's or string's name.
        tie: String,
        /// Seconds.
        time: f64,
        /// Its length, m.
        length: f64,
    },
}
