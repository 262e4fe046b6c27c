//! Every tuning constant of the simulation in one place, as Box2D keeps its `constants.h`
//! and rapier its `IntegrationParameters`: each with its unit, why it has its value, and
//! what breaks if it changes. The constants of a method itself (PEFRL's and
//! Dormand–Prince's coefficients) stay with the method; the scene's defaults stay with
//! the scene.
//!
//! Two kinds: thresholds that decide what the physics does (touching, full length,
//! trusted), where a change moves answers and the tests against theory say by how much;
//! and sizes that only decide how fast it runs (blocks, leaves, items per thread), where
//! a change moves no bit — the determinism tests hold that — only the time.

// ---------------------------------------------------------------------------------------
// Contacts
// ---------------------------------------------------------------------------------------

/// Contact closer than this fraction of the reach (the sum of the radii, or a radius plus
/// half a ramp's thickness) counts as touching; dimensionless. Why: rounding leaves a
/// resting ball a few ulps off its floor, and the band must hold it. Larger, and balls a
/// visible hair apart are treated as touching (held, struck at the step's start); smaller,
/// and resting contact flickers between touching and not, with impacts at every step.
pub(crate) const TOUCHING: f64 = 1e-6;

/// A turning particle on a surface whose contact point slips slower than this fraction
/// of its speeds (along the surface, and of its rim) rolls; dimensionless. Why: the
/// instant slipping stops is located to rounding, which leaves a slip of some ulps of
/// those speeds; smaller, and the step after it would locate that rounding's crossing
/// again; larger, and a slipping ball would be caught rolling early (the catch changes
/// its spin by at most this fraction, so 1e-9 is below anything a run reports).
pub(crate) const ROLLING: f64 = 1e-9;

/// A particle's fat box (the broad phase's) is its box grown by this fraction of its
/// radius, plus its travel over [`FAT_STEPS`] steps; dimensionless. Why: a resting pile
/// keeps its boxes for many steps and a ball in flight gets a new one every few. Only the
/// speed depends on it: a quarter of a radius made 10,000 falling balls rebuild the grid
/// twice as often; larger boxes give the exact tests more candidates.
pub(crate) const FAT_RADII: f64 = 0.5;

/// Steps of travel a fat box is grown by. Only the speed depends on it (see
/// [`FAT_RADII`]).
pub(crate) const FAT_STEPS: f64 = 4.0;

/// The travel added to a fat box is at most this many radii. Why: tiny, fast bodies (the
/// clusters' stars of 0.1 µm at 30 m/s and 5 ms steps) would otherwise get boxes hundreds
/// of thousands of radii wide, and a dense cluster millions of candidate pairs. Balls in
/// a pit never reach it. Only the speed depends on it.
pub(crate) const FAT_TRAVEL_RADII: f64 = 2.0;

/// Overlap tolerated between resting particles before their positions are corrected, as
/// a fraction of the smaller radius. Why: well under the 1 % a user could see. Larger,
/// and piles visibly sink into each other; smaller, and the correction works every step
/// against rounding, adding and booking energy for nothing.
pub(crate) const ALLOWED_OVERLAP: f64 = 1e-3;

/// Fraction of the excess overlap corrected per position sweep; dimensionless. Why:
/// gentle enough not to pop a pile, and a power of two so that a row's share (this times
/// its effective mass) is exact to the bit. Near 1, piles jitter; much smaller, overlaps
/// linger.
pub(crate) const CORRECTION: f64 = 0.5;

/// Position sweeps of the resting solver per step. Fewer, and deep piles keep more
/// overlap; more costs time for little (the velocity sweeps leave the load to sink again
/// each step).
pub(crate) const POSITION_SWEEPS: usize = 4;

/// The most velocity sweeps of the resting solver per step (it stops earlier when no
/// contact approaches). Why: the warm start carries a pile's weight from step to step,
/// so one step's sweeps only pass on what changed in it. In a settling pile the sweeps
/// never meet their convergence test, so this count is the solver's cost. With 16 the
/// 1,000-ball pit's largest overlap while crashing was 1.77 % of a radius, with 8 0.98 %
/// (`tests/ball_pit.rs` holds it under 2.5 %); with 6, piles rest at 1.6 %.
pub(crate) const RESTING_SWEEPS: usize = 8;

/// Bodies of a coupled impact this fraction of their reach apart at its refined instant
/// are not touching; dimensionless. Why: the refinement stops within 1e-12 of the reach
/// for a real contact, so anything this far apart is a false alarm. Smaller than the
/// refinement's reach, and real impacts are dropped; much larger, and near misses are
/// struck.
pub(crate) const APART: f64 = 1e-6;

/// A coupled particle's path is searched again after an impact of the coupled system
/// only if it moved by more than this fraction of its radius. Why: far below the touching
/// band ([`TOUCHING`]), a kept path can only miss an impact that grazes deeper than the
/// band by less than this, which the resting solver then holds. Larger, and grazing
/// impacts are missed; smaller costs searches.
pub(crate) const RESTART: f64 = 1e-9;

/// Depth of the time-of-impact subdivision: the instant of contact is found to 2⁻⁴⁴
/// (about 6e-14) of the step. Shallower, and the instants are coarser than the
/// integrator's error; deeper reaches rounding.
pub(crate) const MAX_DEPTH: u32 = 44;

/// How far, as a fraction of the reach, a relative path may bend off a straight line and
/// still be solved as one (the root of a quadratic). Why: rounding alone bends a straight
/// path by some 1e-16. Larger, and curved paths' impacts are found off their curve;
/// smaller, and straight paths take the slower subdivision.
pub(crate) const STRAIGHT: f64 = 1e-12;

// ---------------------------------------------------------------------------------------
// Rods and strings
// ---------------------------------------------------------------------------------------

/// How close to its length a string must be to count as at full length, relative. Why:
/// the projection puts a taut string at its length to about 1e-15; a slack one reaching
/// it is found by the event search to 1e-12 s. Larger, and a string snaps taut early by
/// as much; smaller than the projection's rounding, and a taut string counts as slack.
pub(crate) const FULL_LENGTH: f64 = 1e-9;

/// The position projection onto the links' lengths stops when every |C| / L² is below
/// this (about the relative length error); dimensionless. Why: rounding. Larger, and
/// rods drift in length; smaller cannot be met.
pub(crate) const PROJECTION_TOLERANCE: f64 = 1e-15;

/// A rod or string further than this from its length after the projection (relative to
/// the length) ends the run with [`crate::SimulationError::TieNotHeld`]; dimensionless.
/// Why: a converged projection leaves rounding, 1e-15, so a billionth is far above it
/// and a length anyone could read off a row (nine digits) is the length asked for; a link
/// too far from the origin for its length to be held so (its ends' positions rounded to
/// more than this) is told apart, [`crate::SimulationError::TieTooFar`].
pub(crate) const TIE_HELD: f64 = 1e-9;

/// Most Gauss–Newton iterations of the position projection. It converges quadratically
/// in a few; the bound only stops a degenerate island (links that cannot all hold), whose
/// remaining error is reported.
pub(crate) const PROJECTION_ITERATIONS: usize = 50;

/// A string's slack or taut instant is located to this many seconds (the bracket's
/// width). Why: far below any step and the integrator's error over one. Larger, and the
/// string pushes or flies for that long (the flight leaves its parabola by v times it).
pub(crate) const EVENT_TIME_TOLERANCE: f64 = 1e-12;

/// Most iterations of the string event search (Illinois regula falsi, falling back to
/// bisection): bisection alone reaches [`EVENT_TIME_TOLERANCE`] of a 1 s step in 40.
pub(crate) const EVENT_ITERATIONS: usize = 100;

// ---------------------------------------------------------------------------------------
// Coupled impacts (particles on springs or feeling pair forces)
// ---------------------------------------------------------------------------------------

/// How near (a fraction of the step) an instant must be to the last one the coupled
/// system was integrated to for its state to be carried there by its acceleration
/// (x + v δ + a δ²/2) instead of integrated again. Why: the rest of that Taylor series is
/// of order (jerk) δ³, some 1e-21 m for δ = 1e-7 s at the 1 ms step, far below the
/// integrator's own error over a step; Newton's corrections to an impact's instant are
/// some 3e-7 of the step. Larger, and the carried state's error reaches the integrator's;
/// smaller, and each correction costs a whole integration of the coupled system.
pub(crate) const CARRIED: f64 = 1e-4;

/// The largest fifth-order term of a blow's answer over the rest of the step that leaves
/// the series trusted, as a fraction of the kick's displacement. Why: the terms left out
/// are that term times the step over the pull's time scale, smaller again. Larger, and a
/// hard blow's answer errs (the paper's 4.7 with rk4 returns 3.7e-10 m off its start
/// answered, 1.9e-11 m integrated); smaller, and more steps end at their impacts.
pub(crate) const TRUSTED: f64 = 1e-6;

/// The largest (ω S)² — the first answer's acceleration over the rest of the step S per
/// unit kick — that leaves the series trusted. Why: beyond it (ω S > 0.1) the pull turns
/// the motion within the step. Larger, and stiff springs' answers err (the energy ledger
/// of a 753 N/m spring on a 17 g ball reached 0.55 of E₀); smaller costs integrations.
pub(crate) const STIFF: f64 = 1e-2;

/// The most strikes one blow passes on at its instant inside the step; beyond them the
/// step ends there and the next step's start passes on the rest. Only the cost depends
/// on it: both roads are exact.
pub(crate) const PASSES: usize = 1024;

// ---------------------------------------------------------------------------------------
// Failure
// ---------------------------------------------------------------------------------------

/// A position or velocity beyond this size (m, m/s) counts as a run that has blown up,
/// like a non-finite one. Why: the scene's own numbers are at most 1e100, and squares of
/// 1e150 still fit in an f64; anything larger is on its way to infinity. Smaller, and
/// legitimate extreme scenes fail; larger, and a blow-up is caught only at infinity.
pub(crate) const RUNAWAY: f64 = 1e150;

/// The largest drag rate × time step (`Drag::rate`) a fixed-step method is asked to
/// follow. Why: at 1 the velocity decays by e in one step, which the methods still follow
/// without overshooting (Euler's stops the particle in one step, no more); past their
/// stability (2 for Euler's, semi-implicit Euler's and Verlet's, 2.79 for rk4) every step
/// multiplies the velocity and energy comes from nothing. Higher, and a run can gain
/// energy silently; lower, and ordinary air resistance at coarse steps is refused.
pub(crate) const DRAG_STEP: f64 = 1.0;

// ---------------------------------------------------------------------------------------
// Speed only: none of these moves a bit (the determinism tests hold it)
// ---------------------------------------------------------------------------------------

/// From this many bodies on, the direct pair sum is summed in [`BLOCKS`] blocks of rows,
/// each into its own force buffer, the buffers added in block order, so that threads can
/// take blocks and the bits do not depend on how many there are. Fewer bodies are one
/// block. The bits change once at this size, never with the thread count.
pub(crate) const BLOCKED_FROM: usize = 256;

/// Blocks of the direct pair sum: 16 or 32 were slower on one and two threads, 2 or 4 the
/// same.
pub(crate) const BLOCKS: usize = 8;

/// Bodies per leaf of the Barnes–Hut tree: below this a square is summed directly. 32
/// against 16 or 64: the fewest walks for near sums the SIMD lanes make cheap. It changes
/// which squares are opened, so the forces' bits (within the tree's accuracy).
pub(crate) const LEAF: usize = 32;

/// Deepest square of the tree: bodies closer than 2⁻⁴⁸ of the whole extent share a leaf.
pub(crate) const TREE_DEPTH: u32 = 48;

/// Leaves from which a tree's sums are shared out among threads: each leaf's walk and
/// sums cost as much as waking a thread, so even a small tree pays for the pool, unlike
/// the cheap items of [`MIN_ITEMS`] (docs/performance.md, "Threads").
pub(crate) const SPLIT_LEAVES: usize = 32;

/// Pieces of shared-out work per thread, so that a thread that finishes early takes
/// another's (so enough that an uneven piece does not leave a thread idle).
#[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
pub(crate) const PIECES_PER_THREAD: usize = 4;

/// Fewer items than this run on the calling thread when it is outside the pool: waking
/// a thread costs more than sharing out fewer cheap items wins (the pits measured split
/// from smaller counts ran slower on two threads than on one: docs/performance.md,
/// "Threads").
pub(crate) const MIN_ITEMS: usize = 16_384;

/// [`MIN_ITEMS`] for a step running on a thread of the pool (one of [`STRIPS_FROM`]
/// particles or more), whose threads are awake and take a share at once.
#[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
pub(crate) const MIN_ITEMS_IN_POOL: usize = 4_096;

/// From this many particles the impacts at a step's start are swept strip by strip
/// (`contacts/strips.rs`), so that threads can share the sweep: the sweep's order, and so
/// the bits, change once at this size, never with the thread count.
pub(crate) const STRIPS_FROM: usize = 4_096;

/// Particles per strip, about: fewer make more pairs cross between strips (swept on one
/// thread) and blows more passes to cross them, more leave fewer pieces to share among
/// many threads. The settling 10,000-ball pit on one thread: 185 steps a second with
/// strips of 512, 191 with 1,024, 200 with 2,048 (205–207 swept in ascending order).
pub(crate) const PARTICLES_PER_STRIP: usize = 1_024;

/// The most strips.
pub(crate) const STRIPS: usize = 32;
