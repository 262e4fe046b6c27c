//! Contact physics: impacts between particles and with ramps and walls, and resting or
//! sliding contact.
//!
//! Two regimes, told apart by the approach speed at contact:
//! - **Impacts** (approach faster than `resting_speed`): the instant of contact is found
//!   within the step ([`time_of_impact`]) and an impulse is applied there: the paper's
//!   8–10 between particles (with the world's restitution; fixed particles have infinite
//!   mass) and 17–22 on a ramp or wall (v∥ kept, v⊥ reversed and scaled by the surface's
//!   restitution). How the rest of the step follows depends on the particles:
//!   - an *uncoupled* particle (no pairwise force, no spring) has an acceleration that
//!     does not depend on the state within the step, so an impulse Δv at τ changes its
//!     path exactly by Δv (t − τ). Impacts among uncoupled particles are therefore
//!     processed in time order inside the step, each patching the two paths and
//!     searching them again against their neighbours: a thousand balls crashing into a
//!     pile cost one step, not one step per impact;
//!   - an impact involving a *coupled* particle changes the forces on every particle it
//!     pulls, so its path cannot be patched: with rk4 everything it pulls answers the
//!     impulse by a short series of the forces' answer, otherwise the coupled particles,
//!     a closed system of their own, are integrated again to exactly that instant and on
//!     to the step's end with the impulse applied; their paths start again there, and the
//!     search goes on inside the step (`simulation/coupled.rs`). An impact that drives a
//!     coupled particle into the surface it rests on bounces it off there and then (with
//!     rk4; what it then drives into is struck at that instant too,
//!     [`Contacts::closing_at`]), or ends the step (the other methods). With rods or
//!     strings, or while anything dissipates smoothly, the impact ends the step: the whole
//!     system is integrated to its instant ([`Contacts::patch`], [`Contacts::apply`]).
//! - **Resting contact** (slower approach, or touching at the start of a step): a particle
//!   on a ramp or wall is held there for the step by a normal force with friction, part
//!   of the smooth forces ([`crate::forces::normal`]); touching particles are kept apart by
//!   inelastic impulses after the step and a small position correction. Without this
//!   regime a ball settling on a floor would bounce ever lower with infinitely many
//!   impacts in finite time ("inelastic collapse").
//!
//! The stages of a step, one file each, each with its state in a named struct that
//! [`Contacts`] holds:
//! 1. [`surfaces`]: at the start of the step, what touches ([`surfaces::StartContacts`]),
//!    the impacts happening now, and the normal force and friction of resting particles;
//! 2. [`impacts`]: after the trial step, each particle's path and the search for impacts
//!    inside it, applied in time order ([`impacts::ImpactSearch`]); the instant of
//!    contact on a path is [`time_of_impact`]'s, the candidate pairs [`broad_phase`]'s;
//! 3. [`resting`]: after the step, the resting solver ([`resting::RestingSolver`]).
//!
//! `Simulation::advance` calls them in that order.
//!
//! `resting_speed` is twice what the forces can change an approach speed by in one step
//! (2·a·h, with a the largest acceleration seen in the last step): an approach slower than
//! that is indistinguishable, at this step, from a particle pressed onto a surface.

// Particle indices are stored as u32 in contact lists, halving their memory; a scene has
// far fewer than 2³² particles (the stages' files narrow them on purpose).

pub(crate) mod broad_phase;
mod impacts;
pub(crate) mod obstacles;
pub(crate) mod resting;
mod strips;
mod surfaces;
pub(crate) mod time_of_impact;

use glam::DVec2;

use self::broad_phase::{Aabb, Proxies};
use self::impacts::ImpactSearch;
pub(crate) use self::impacts::{Members, hermite, hermite_position};
use self::obstacles::{Obstacle, Shape};
use self::resting::{RestingSolver, Touching};
use self::strips::Strips;
use self::surfaces::StartContacts;
use crate::forces::ForceModel;
use crate::impact::ImpactTarget;
use crate::parallel::Workers;
use crate::scene::Scene;
use crate::state::State;
use crate::tuning::{FAT_RADII, FAT_STEPS, FAT_TRAVEL_RADII, TOUCHING};
use crate::turning::{Body, Grip, Turning};

/// An instant inside a step: `time` seconds into a step of `step` seconds.
#[derive(Clone, Copy, Debug)]
pub(crate) struct InStep {
    pub time: f64,
    pub step: f64,
}

/// What hits what.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Impact {
    /// Particles `i < j`.
    Pair(usize, usize),
    /// A particle and an obstacle, by its index among the contacts' obstacles (the ramps,
    /// then the walls: [`Contacts::obstacle_target`] says which).
    Obstacle(usize, usize),
}

impl Impact {
    /// Whether particle `i` takes part.
    pub fn involves(self, i: usize) -> bool {
        match self {
            Self::Pair(p, q) => p == i || q == i,
            Self::Obstacle(p, _) => p == i,
        }
    }
}

/// The contact state of a simulation.
#[derive(Clone, Debug)]
pub(crate) struct Contacts {
    /// The ramps, then the world's four walls.
    obstacles: Vec<Obstacle>,
    ramps: usize,
    /// The world's bounds, where the walls are: a box strictly inside is clear of all
    /// four ([`Self::obstacles_near`]).
    walls: Option<Aabb>,
    radius: std::sync::Arc<[f64]>,
    /// Particle–particle restitution.
    restitution: f64,
    /// Whether particles strike and rest on each other (`[world] collisions`): without,
    /// no pair of particles is ever looked for, and only the obstacles stop them.
    collisions: bool,
    /// The largest acceleration seen in the last step, m/s².
    acceleration_scale: f64,
    proxies: Proxies,
    boxes: Vec<Aabb>,
    /// What touches at the start of the step ([`surfaces`]).
    touching: StartContacts,
    /// The search for impacts inside the step ([`impacts`]).
    search: ImpactSearch,
    /// The resting solver after the step ([`resting`]).
    resting: RestingSolver,
    /// The impacts at the step's start, strip by strip ([`strips`]).
    strips: Strips,
    /// The threads the searches may use.
    pub workers: Workers,
    /// Whether each particle feels a pairwise force or a spring (see the module doc).
    coupled: Vec<bool>,
    /// What the contacts did in this step, for the ledger and the log of impacts.
    pub report: StepReport,
    /// Whether the impacts at the step's start are kept in `applied` for a log of
    /// impacts: nothing else reads them but turning particles' books (the books read
    /// those inside the step), and keeping tens of thousands a step is a measurable
    /// share of a pile's.
    pub logs_start: bool,
    /// The spins, when any particle turns.
    pub turning: Option<Turning>,
}

/// What the contacts did in one step, begun afresh at its start
/// ([`Contacts::begin_step`]) and read by the ledger and the log of impacts.
#[derive(Clone, Debug, Default)]
pub(crate) struct StepReport {
    /// The impacts applied, in order: those of the step's start, then those inside it.
    pub applied: Vec<Applied>,
    /// The kinetic energy taken by catching coupled particles that an impact inside the
    /// step left sinking slowly into their surfaces (`simulation/coupled.rs`), J.
    pub caught: f64,
    /// The work the surfaces' normal force did on coupled particles a blow sent off them
    /// inside the step, up to the blow (`simulation/coupled/response.rs`), J: their
    /// contacts are off the step's books after it.
    pub released: f64,
}

impl StepReport {
    /// Begun afresh, keeping the list's memory.
    fn clear(&mut self) {
        self.applied.clear();
        self.caught = 0.0;
        self.released = 0.0;
    }
}

/// An impact as it was applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Applied {
    /// Seconds into the step.
    pub time: f64,
    pub impact: Impact,
    /// The approach speed along the normal before, m/s (positive).
    pub approach: f64,
    /// The restitution it was given: the separation speed after is `restitution ×
    /// approach`.
    pub restitution: f64,
    /// Friction's part, between turning bodies: the velocity and spin changes of the
    /// impact's first and second particle ([`particles_of`]), and the energy it took.
    pub grip: Grip,
    /// The whole velocity changes of the first and the second particle, m/s.
    pub kick: (DVec2, DVec2),
    /// The contact's effective mass, kg, when rods or strings answered the impact with
    /// it (the struck particle carries what it is tied to); `None`: the particles' own.
    pub tied: Option<f64>,
}

impl Contacts {
    pub fn new(scene: &Scene, forces: &ForceModel) -> Self {
        let obstacles = obstacles::obstacles(scene);
        Self {
            ramps: scene.ramps.len(),
            walls: scene.world.bounds.map(|bounds| Aabb {
                min: bounds.min.to_dvec2(),
                max: bounds.max.to_dvec2(),
            }),
            obstacles,
            radius: scene.particles.iter().map(|p| p.radius).collect(),
            restitution: scene.world.restitution,
            collisions: scene.world.collisions,
            acceleration_scale: forces
                .uniform
                .iter()
                .map(|a| a.length())
                .fold(0.0, f64::max),
            proxies: Proxies::default(),
            boxes: Vec::new(),
            touching: StartContacts::default(),
            search: ImpactSearch::default(),
            resting: RestingSolver::default(),
            strips: Strips::default(),
            workers: Workers::default(),
            coupled: (0..scene.particles.len())
                .map(|i| {
                    !forces.is_fixed(i)
                        && (forces.interacting.contains(&i)
                            || forces.springs.iter().any(|s| s.touches(i))
                            || forces.constraints.touches(i))
                })
                .collect(),
            report: StepReport::default(),
            logs_start: false,
            turning: Turning::new(scene),
        }
    }

    /// Frees what each step builds again before it reads it: the broad phase's carried
    /// boxes and grid (rebuilt from scratch when missing; the pairs it finds are those
    /// whose boxes overlap, whatever boxes it carried), the boxes, the touching lists,
    /// the impact search's lists and the resting solver's rows. The resting solver's
    /// memory of the last impulses, which the next step starts from, stays.
    pub fn drop_scratch(&mut self) {
        self.proxies = Proxies::default();
        self.boxes = Vec::new();
        self.touching = StartContacts::default();
        self.search = ImpactSearch::default();
        self.resting.drop_scratch();
        self.strips = Strips::default();
        self.report.applied = Vec::new();
    }

    /// The bytes of what [`Self::drop_scratch`] keeps, by length.
    pub fn memory_bytes(&self) -> usize {
        self.obstacles.len() * size_of::<Obstacle>() + self.resting.memory_bytes()
    }

    /// Whether each particle feels a pairwise force, a spring, a rod or a string.
    pub fn coupled(&self) -> &[bool] {
        &self.coupled
    }

    /// What obstacle `k` (of [`Impact::Obstacle`]) is in the scene: a ramp or a wall.
    pub fn obstacle_target(&self, k: usize) -> ImpactTarget {
        self.obstacles[k].target
    }

    /// The first particle (of those `moving` says move) whose centre has left the world's
    /// bounds, by more than a millionth of the box: a particle too fast for the time step
    /// to resolve its impacts with the walls (1e13 m/s in a box of 10 m).
    pub fn escaped(&self, x: &[DVec2], moving: impl Fn(usize) -> bool) -> Option<usize> {
        let walls = self.walls?;
        let slack = 1e-6 * (walls.max - walls.min).length();
        let (min, max) = (walls.min - slack, walls.max + slack);
        // Written so that a NaN position counts as inside: non-finite values are named
        // by their own check.
        (0..x.len()).find(|&i| {
            moving(i) && (x[i].x < min.x || x[i].y < min.y || x[i].x > max.x || x[i].y > max.y)
        })
    }

    /// How many of the obstacles, from the first, a particle whose reach lies in `reach`
    /// may touch: all, or only the ramps when the box lies strictly inside the walls.
    /// Then [`Shape::clear_of_box`] would find it clear of each wall by the same
    /// comparisons (a wall's normal is a unit axis, so its test is one coordinate's), and
    /// most particles skip the walls with one test instead of four.
    fn obstacles_near(&self, reach: &Aabb) -> usize {
        match self.walls {
            Some(walls) if reach.strictly_inside(&walls) => self.ramps,
            _ => self.obstacles.len(),
        }
    }

    pub fn resting_speed(&self, h: f64) -> f64 {
        2.0 * self.acceleration_scale * h + 1e-12
    }

    /// The restitution an impact approaching at `approach` gets: its surface's (or the
    /// world's), or 0 when the approach is no faster than a resting contact's.
    fn restitution_at(&self, impact: Impact, approach: f64, resting_speed: f64) -> f64 {
        if approach > resting_speed {
            self.restitution_of(impact)
        } else {
            0.0
        }
    }

    fn restitution_of(&self, impact: Impact) -> f64 {
        match impact {
            Impact::Pair(..) => self.restitution,
            Impact::Obstacle(_, k) => self.obstacles[k].restitution,
        }
    }

    /// Gap (metres, negative when overlapping), unit normal (from the first body, or the
    /// surface, towards the particle) and approach speed (m/s, positive when closing).
    pub fn measure(&self, impact: Impact, state: &State) -> (f64, DVec2, f64) {
        let (first, second) = particles_of(impact);
        let at = |i: usize| (state.position[i], state.velocity[i]);
        self.geometry(impact, at(first), second.map(at))
    }

    /// [`Self::measure`] from the (position, velocity) of the first particle and, for a
    /// pair, the second.
    fn geometry(
        &self,
        impact: Impact,
        (xi, vi): (DVec2, DVec2),
        second: Option<(DVec2, DVec2)>,
    ) -> (f64, DVec2, f64) {
        match (impact, second) {
            (Impact::Pair(i, j), Some((xj, vj))) => {
                let (distance, normal) = separation(xj - xi);
                (
                    distance - self.radius[i] - self.radius[j],
                    normal,
                    (vi - vj).dot(normal),
                )
            }
            (Impact::Obstacle(p, k), _) | (Impact::Pair(p, k), None) => {
                let (distance, normal) = self.obstacles[k].shape.distance(xi);
                (distance - self.radius[p], normal, -vi.dot(normal))
            }
        }
    }

    /// Applies an impact's impulse along `normal` to `state` (the paper's 8–10 or
    /// 17–22: the approach reversed and scaled by the restitution), with friction's
    /// between turning bodies, and records it.
    fn strike(&mut self, applied: Applied, normal: DVec2, state: &mut State, forces: &ForceModel) {
        let (first, second) = particles_of(applied.impact);
        let velocities = (state.velocity[first], second.map(|j| state.velocity[j]));
        let applied = self.impulse(applied, normal, velocities, forces);
        state.velocity[first] += applied.kick.0;
        if let Some(j) = second {
            state.velocity[j] += applied.kick.1;
        }
        self.turn(&applied);
        self.report.applied.push(applied);
    }

    /// `applied` with its friction and whole velocity changes worked out, for particles
    /// moving at `velocities` (the second's for a pair) just before it.
    fn impulse(
        &self,
        mut applied: Applied,
        normal: DVec2,
        velocities: (DVec2, Option<DVec2>),
        forces: &ForceModel,
    ) -> Applied {
        let change = applied.approach * (1.0 + applied.restitution);
        applied.grip = self.grip(&applied, normal, velocities, forces);
        let (dv_first, dv_second) = velocity_changes(applied.impact, normal, change, forces);
        applied.kick = (dv_first + applied.grip.dv.0, dv_second + applied.grip.dv.1);
        applied
    }

    /// Friction's part of an impact (`applied`, without it yet) whose particles move at
    /// `velocities` just before it: nothing unless both bodies turn (or cannot move)
    /// and their surfaces grip.
    fn grip(
        &self,
        applied: &Applied,
        normal: DVec2,
        (v_first, v_second): (DVec2, Option<DVec2>),
        forces: &ForceModel,
    ) -> Grip {
        let Some(turning) = &self.turning else {
            return Grip::default();
        };
        let w = &forces.inverse_mass;
        let body = |p: usize, velocity: DVec2| Body {
            inverse_mass: w[p],
            inertia: turning.inertia[p],
            radius: self.radius[p],
            velocity,
            spin: turning.spin_at(p, applied.time, velocity, self.radius[p]),
        };
        let change = applied.approach * (1.0 + applied.restitution);
        let grip = match (applied.impact, v_second) {
            (Impact::Pair(i, j), Some(v_j)) => {
                let inverse = w[i] + w[j];
                if inverse == 0.0 {
                    return Grip::default();
                }
                Grip::at_impact(
                    turning.friction,
                    normal,
                    change / inverse,
                    (body(i, v_first), body(j, v_j)),
                )
            }
            (Impact::Obstacle(p, k), _) | (Impact::Pair(p, k), None) => {
                if w[p] == 0.0 {
                    return Grip::default();
                }
                // The surface is the first body (the normal points from it), the
                // particle the second: their changes swap to the impact's order.
                Grip::at_impact(
                    self.obstacles[k].friction,
                    normal,
                    change / w[p],
                    (Body::SURFACE, body(p, v_first)),
                )
                .map(|grip| Grip {
                    dv: (grip.dv.1, DVec2::ZERO),
                    spin: (grip.spin.1, 0.0),
                    lost: grip.lost,
                })
            }
        };
        grip.unwrap_or_default()
    }

    /// Applies an impact's spin changes.
    fn turn(&mut self, applied: &Applied) {
        if let Some(turning) = &mut self.turning
            && applied.grip != Grip::default()
        {
            let (first, second) = particles_of(applied.impact);
            turning.spin[first] += applied.grip.spin.0;
            if let Some(j) = second {
                turning.spin[j] += applied.grip.spin.1;
            }
        }
    }

    /// The reach of an impact: the distance scale its gap is judged against.
    pub fn reach(&self, impact: Impact) -> f64 {
        match impact {
            Impact::Pair(i, j) => self.radius[i] + self.radius[j],
            Impact::Obstacle(p, k) => self.radius[p] + half_thickness(&self.obstacles[k].shape),
        }
    }

    /// Resting contact after a step of `h` ([`resting`]). `struck` is an impact applied
    /// outside [`Self::resolve_impacts`]; its particles, and those impacts inside the
    /// step changed, keep a fast approach for the next step's impacts. Returns whether
    /// anything changed.
    pub fn settle(
        &mut self,
        state: &mut State,
        forces: &ForceModel,
        h: f64,
        struck: Option<Impact>,
    ) -> bool {
        let resting_speed = self.resting_speed(h);
        let (inertia, spin) = match &mut self.turning {
            Some(turning) => (Some(&turning.inertia[..]), &mut turning.spin[..]),
            None => (None, &mut [][..]),
        };
        let touching = Touching {
            pairs: &self.touching.pairs,
            surfaces: &self.touching.surfaces,
            obstacles: &self.obstacles,
            radius: &self.radius,
            inverse_mass: &forces.inverse_mass,
            inertia,
            spare_friction: &self.touching.spare_friction,
        };
        let is_changed = &self.search.is_changed;
        let is_struck = |i: usize| {
            struck.is_some_and(|impact| impact.involves(i))
                || is_changed.get(i).copied().unwrap_or(false)
        };
        self.resting
            .solve(&touching, state, h, resting_speed, is_struck, spin)
    }
}

/// The larger of `a` and `b` by a comparison, `b` when `a` is NaN (as `f64::max`
/// gives it). `f64::max` has no WebAssembly instruction with its rule for NaN and is a
/// call to `fmax` there, which V8's profile of the browser's pit (`benches/wasm`) found in
/// the loops that use these.
#[inline]
pub(crate) fn larger(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

/// The smaller of `a` and `b` by a comparison, `b` when `a` is NaN (see [`larger`]).
#[inline]
pub(crate) fn smaller(a: f64, b: f64) -> f64 {
    if a < b { a } else { b }
}

/// How far a particle's fat box reaches beyond its box, metres.
fn fat_margin(radius: f64, velocity: DVec2, h: f64) -> f64 {
    FAT_RADII * radius + smaller(FAT_STEPS * velocity.length() * h, FAT_TRAVEL_RADII * radius)
}

fn half_thickness(shape: &Shape) -> f64 {
    match *shape {
        Shape::Capsule { radius, .. } => radius,
        Shape::HalfPlane { .. } => 0.0,
    }
}

/// The length of the offset between two centres and its direction (the contact normal).
pub(crate) fn separation(offset: DVec2) -> (f64, DVec2) {
    let distance = offset.length();
    // Coincident centres have no direction between them; any will do.
    let normal = if distance > 0.0 {
        offset / distance
    } else {
        DVec2::X
    };
    (distance, normal)
}

/// The particles of an impact: the first, and the second of a pair.
fn particles_of(impact: Impact) -> (usize, Option<usize>) {
    match impact {
        Impact::Pair(i, j) => (i, Some(j)),
        Impact::Obstacle(p, _) => (p, None),
    }
}

/// The velocity changes that make the approach speed along `normal` drop by `change`:
/// the paper's 8–10 with `j = change / (1/m_A + 1/m_B)` for a pair, 17–22 for a surface.
fn velocity_changes(
    impact: Impact,
    normal: DVec2,
    change: f64,
    forces: &ForceModel,
) -> (DVec2, DVec2) {
    match impact {
        Impact::Pair(i, j) => {
            let (wi, wj) = (forces.inverse_mass[i], forces.inverse_mass[j]);
            if wi + wj == 0.0 {
                return (DVec2::ZERO, DVec2::ZERO);
            }
            let impulse = normal * (change / (wi + wj));
            (-impulse * wi, impulse * wj)
        }
        Impact::Obstacle(..) => (normal * change, DVec2::ZERO),
    }
}
