//! `NewtonLab`'s claims against theory, in groups: what `newtonlab validate` prints and
//! Python's `newtonlab.validate()` returns. `paper` is the paper's section 4 (its tables,
//! with simulation, theory and error columns); the other groups hold what `NewtonLab`
//! added since (rods, strings, the integrators' orders, the tree, softening, the energy
//! ledger, friction, saved states, events, drag, series, turning, rigid bodies, joints,
//! forces) to
//! closed forms or to computations written here apart from the simulation's code, each
//! check to a tolerance stated beside it.

mod bodies;
mod books;
mod drag;
mod events;
mod experiments;
pub mod figures;
mod forces;
mod joints;
mod methods;
mod paper_method;
pub mod report;
mod series;
mod theory;
mod threads;
mod ties;
mod turning;

use figures::Figure;
use report::Report;

/// Why a validation could not finish, apart from a check that missed.
#[derive(Debug)]
pub enum Failure {
    /// A simulation failed, or did not match theory.
    Simulation(String),
    /// A built-in scene or an argument was bad.
    Input(String),
}

/// A group of checks, named as `--only` takes it.
#[expect(
    missing_docs,
    reason = "each group says what it proves in `Group::statement`"
)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    Paper,
    Rods,
    Strings,
    Integrators,
    Tree,
    Softening,
    Ledger,
    Friction,
    SavedState,
    Events,
    Drag,
    Series,
    Turning,
    Bodies,
    Joints,
    Forces,
    Threads,
}

impl Group {
    /// Every group, in the report's order.
    pub const ALL: [Self; 17] = [
        Self::Paper,
        Self::Rods,
        Self::Strings,
        Self::Integrators,
        Self::Tree,
        Self::Softening,
        Self::Ledger,
        Self::Friction,
        Self::SavedState,
        Self::Events,
        Self::Drag,
        Self::Series,
        Self::Turning,
        Self::Bodies,
        Self::Joints,
        Self::Forces,
        Self::Threads,
    ];

    /// Its name, as `--only` takes it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Paper => "paper",
            Self::Rods => "rods",
            Self::Strings => "strings",
            Self::Integrators => "integrators",
            Self::Tree => "tree",
            Self::Softening => "softening",
            Self::Ledger => "ledger",
            Self::Friction => "friction",
            Self::SavedState => "saved-state",
            Self::Events => "events",
            Self::Drag => "drag",
            Self::Series => "series",
            Self::Turning => "turning",
            Self::Bodies => "bodies",
            Self::Joints => "joints",
            Self::Forces => "forces",
            Self::Threads => "threads",
        }
    }

    /// What the group proves, in one line.
    pub fn statement(self) -> &'static str {
        match self {
            Self::Paper => {
                "the paper's section 4 (kinematics, collision, ramps, springs, inverse-square bounces) against closed forms"
            }
            Self::Rods => {
                "a rod pendulum keeps the elliptic-integral period at any amplitude; rods between unequal masses keep momentum and the centre of mass"
            }
            Self::Strings => {
                "a string goes slack where its tension vanishes, the ball flies on the parabola, and the string snaps taut where the parabola meets its length"
            }
            Self::Integrators => {
                "each integrator converges at its order (halving the step divides the error by 2^order); the symplectic ones keep a bounded energy error"
            }
            Self::Tree => {
                "the Barnes–Hut tree's forces and potential energy agree with the direct sum"
            }
            Self::Softening => {
                "both pair laws are softened alike in the motion, the energy and the probe"
            }
            Self::Ledger => {
                "the energy ledger books what damping, friction and impacts take; the books close"
            }
            Self::Friction => {
                "friction on ramps: g(sin θ − μ cos θ), held while tan θ ≤ μ, stopping at v₀²/2μg"
            }
            Self::SavedState => "a saved state reopens and continues its run",
            Self::Events => {
                "events are located inside a step: a landing (also at a 0.05 s step), a pendulum's turning points, a spring's maxima at their closed-form instants"
            }
            Self::Drag => {
                "air resistance: linear drag's exponentials, quadratic drag's tanh fall to the terminal speed, and the energy it takes in the books"
            }
            Self::Series => {
                "laws measured as series: a pendulum's period against its amplitude, a baseball's range against its angle with drag; a series' runs reach both ends of its range"
            }
            Self::Turning => {
                "bodies that turn: Galileo's inclined plane (slider, disc, ring), a bowled ball's slip-to-roll instant, a backspun one that reverses, then rolls, spin at an impact, a disc pushing a ring along a gripping floor"
            }
            Self::Bodies => {
                "rigid bodies: moments of inertia from their outlines, free flight on the parabola with a steady turn, under each method"
            }
            Self::Forces => {
                "forces from what a student knows: drag from C_d and ρ, the magnetic field's cyclotron orbit, forces written as expressions (in time under every method; an anharmonic period and its books)"
            }
            Self::Threads => {
                "the same bits on one thread and on many: the pair sum in blocks, contacts in strips"
            }
            Self::Joints => {
                "pins, hinges, motors and pulleys: a physical pendulum's period at small and large amplitude, a seesaw balanced by torques and one that turns, a motor's spin-up and its work, a limit's stop, Atwood machines"
            }
        }
    }
}

impl std::str::FromStr for Group {
    type Err = String;

    fn from_str(name: &str) -> Result<Self, String> {
        Self::ALL
            .into_iter()
            .find(|g| g.name() == name)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::ALL.iter().map(|g| g.name()).collect();
                format!("no group '{name}'; the groups are {}", names.join(", "))
            })
    }
}

/// The threads each simulation of a validation may use: set by [`validate`] for the
/// simulations it starts (`experiments::start`), which are many and deep in the groups.
static THREADS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(1);

/// Runs `groups`, the paper's held to `tolerance` (relative to each quantity's scale;
/// the other groups state their own), each simulation's step on `threads` threads (the
/// same bits for any number): the report of every check, and the figures.
///
/// # Errors
/// A built-in scene that does not load, or a simulation that fails outright; a check
/// that misses is in the report, not an error.
pub fn validate(
    groups: &[Group],
    tolerance: f64,
    threads: usize,
) -> Result<(Report, Vec<Figure>), Failure> {
    THREADS.store(threads, std::sync::atomic::Ordering::Relaxed);
    let mut report = Report::new(tolerance);
    let mut figures = Vec::new();
    for &group in groups {
        report.group = group.name();
        let (report, figures) = (&mut report, &mut figures);
        match group {
            Group::Paper => {
                experiments::processing_time(report)?;
                experiments::kinematics(report)?;
                experiments::collision(report)?;
                experiments::ramps(report)?;
                experiments::springs(report, figures)?;
                experiments::inverse_square(report, figures)?;
                paper_method::paper_method(report, figures)?;
            }
            Group::Rods => ties::rods(report)?,
            Group::Strings => ties::strings(report, figures)?,
            Group::Integrators => methods::integrators(report, figures)?,
            Group::Tree => methods::tree(report)?,
            Group::Softening => methods::softening(report)?,
            Group::Ledger => books::ledger(report)?,
            Group::Friction => books::friction(report)?,
            Group::SavedState => books::saved_state(report)?,
            Group::Events => events::events(report)?,
            Group::Drag => drag::drag(report)?,
            Group::Series => series::series(report)?,
            Group::Turning => turning::turning(report)?,
            Group::Bodies => bodies::bodies(report)?,
            Group::Joints => joints::joints(report)?,
            Group::Forces => forces::forces(report)?,
            Group::Threads => threads::threads(report)?,
        }
    }
    Ok((report, figures))
}
