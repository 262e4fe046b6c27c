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
//!   - an impact involving a *coupled* particle ends the step there: the whole system is
//!     integrated again from the start of the step to exactly that instant (the forces
//!     after the impact differ from the trial's), and the impulse applied.
//! - **Resting contact** (slower approach, or touching at the start of a step): a particle
//!   on a ramp or wall is held there for the step by a normal force with friction, part
//!   of the smooth forces ([`crate::forces::normal`]); touching particles are kept apart by
//!   inelastic impulses after the step and a small position correction. Without this
//!   regime a ball settling on a floor would bounce ever lower with infinitely many
//!   impacts in finite time ("inelastic collapse").
//!
//! `resting_speed` is twice what the forces can change an approach speed by in one step
//! (2·a·h, with a the largest acceleration seen in the last step): an approach slower than
//! that is indistinguishable, at this step, from a particle pressed onto a surface.

// Particle indices are stored as u32 in contact lists, halving their memory; a scene has
// far fewer than 2³² particles.
#![expect(
    clippy::cast_possible_truncation,
    reason = "u32 particle indices, see above"
)]

pub(crate) mod broad_phase;
pub(crate) mod obstacles;
pub(crate) mod resting;
pub(crate) mod time_of_impact;

use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

use glam::DVec2;

use self::broad_phase::{Aabb, Proxies};
use self::obstacles::{Obstacle, Shape};
use self::resting::{RestingSolver, Touching};
use self::time_of_impact::{Region, control_points, earliest_entry};
use crate::forces::{ForceModel, SurfaceContact};
use crate::parallel::Workers;
use crate::profile::{Profiler, Stage};
use crate::scene::Scene;
use crate::state::State;

/// Contact closer than this fraction of the reach (sum of radii, or radius plus half a
/// ramp's thickness) counts as touching.
const TOUCHING: f64 = 1e-6;
/// A particle's fat box (see [`Proxies`]) is its box grown by this fraction of its radius
/// and by its travel over this many steps: a resting pile keeps its fat boxes for many
/// steps, and a ball in flight gets a new one every few. (Half a radius against a
/// quarter: 10,000 falling balls rebuilt the grid half as often, 0.53 against 0.43
/// thousand steps per second; the 1,000-ball pit is the same either way.)
const FAT_RADII: f64 = 0.5;
const FAT_STEPS: f64 = 4.0;
/// The travel added to a fat box is at most this many radii: tiny, fast bodies (stars of
/// 0.1 µm at 30 m/s and 5 ms steps) would otherwise get boxes hundreds of thousands of
/// radii wide, and a dense cluster millions of candidate pairs (the broad phase took
/// half of a step of the 20,000-star cluster). Balls in a pit never reach it (4 steps of
/// 10 m/s at 1 ms is 0.4 radii of 0.1 m).
const FAT_TRAVEL_RADII: f64 = 2.0;
/// What hits what.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Impact {
    /// Particles `i < j`.
    Pair(usize, usize),
    /// A particle and an obstacle.
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
    obstacles: Vec<Obstacle>,
    radius: Vec<f64>,
    /// Particle–particle restitution.
    restitution: f64,
    /// The largest acceleration seen in the last step, m/s².
    acceleration_scale: f64,
    proxies: Proxies,
    boxes: Vec<Aabb>,
    /// Pairs (i < j) touching at the start of the step, ascending.
    touching_pairs: Vec<(u32, u32)>,
    /// (particle, obstacle) touching at the start of the step, ascending.
    touching_obstacles: Vec<(u32, u32)>,
    /// The touching pairs by particle: `p` touches `partners[first[p]..first[p + 1]]`.
    touching_by_particle: Adjacency,
    resting: RestingSolver,
    /// The threads the searches may use.
    pub workers: Workers,
    /// Scratch: each touching contact and its normal at the start of the step.
    start_normals: Vec<(Impact, DVec2)>,
    /// Whether each particle feels a pairwise force or a spring (see the module doc).
    coupled: Vec<bool>,
    /// Each particle's path through the step.
    paths: Vec<Path>,
    /// Each path's Bézier control points over the whole step, before any impact changed
    /// it: computed once a step, read by every search that starts at the step's start.
    controls: Vec<[DVec2; 4]>,
    /// Bumped when a particle's path changes, to recognise stale queued impacts.
    versions: Vec<u32>,
    /// Particles whose paths impacts changed during this step, and the same as flags.
    changed: Vec<u32>,
    is_changed: Vec<bool>,
    /// Changed particles whose new path left their fat box, so the broad phase may not
    /// find them: every search after an impact also tries these.
    escaped: Vec<u32>,
    queue: BinaryHeap<Reverse<Event>>,
    neighbours: Vec<u32>,
    /// The impacts applied in this step.
    pub applied: Vec<Applied>,
}

/// A particle's path through the step: the cubic Hermite curve through the integrator's
/// state at both ends, plus the kicks of the impacts applied inside the step. Kicks only
/// ever come in time order and the path is only read after the latest, so their running
/// sums suffice: a kick Δv at τ adds Δv (t − τ) to every later position.
#[derive(Clone, Copy, Debug)]
struct Path {
    start: (DVec2, DVec2),
    end: (DVec2, DVec2),
    /// Σ Δv of the kicks so far, m/s.
    kick: DVec2,
    /// Σ Δv τ of the kicks so far, m.
    kick_moment: DVec2,
}

impl Path {
    /// Position and velocity at `t` seconds into a step of `h`. At the ends the
    /// integrator's values are returned exactly.
    fn at(&self, t: f64, h: f64) -> (DVec2, DVec2) {
        let ((x0, v0), (x1, v1)) = (self.start, self.end);
        let s = (t / h).clamp(0.0, 1.0);
        let (s2, s3) = (s * s, s * s * s);
        let position = x0 * (2.0 * s3 - 3.0 * s2 + 1.0)
            + v0 * (h * (s3 - 2.0 * s2 + s))
            + x1 * (3.0 * s2 - 2.0 * s3)
            + v1 * (h * (s3 - s2));
        let velocity = (x1 - x0) * ((6.0 * s - 6.0 * s2) / h)
            + v0 * (3.0 * s2 - 4.0 * s + 1.0)
            + v1 * (3.0 * s2 - 2.0 * s);
        (
            position + self.kick * t - self.kick_moment,
            velocity + self.kick,
        )
    }

    /// Bézier control points of the path from `from` to the end of a step of `h`.
    fn after(&self, from: f64, h: f64) -> [DVec2; 4] {
        let ((x0, v0), (x1, v1)) = (self.start, self.end);
        let p = control_points(x0, v0, x1, v1, h);
        let u = (from / h).clamp(0.0, 1.0);
        let q1 = p[1].lerp(p[2], u);
        let q2 = p[2].lerp(p[3], u);
        let r1 = q1.lerp(q2, u);
        let r0 = p[0].lerp(p[1], u).lerp(q1, u);
        let mut points = [r0.lerp(r1, u), r1, q2, p[3]];
        let offset = self.kick * from - self.kick_moment;
        for (m, point) in points.iter_mut().enumerate() {
            *point += offset + self.kick * ((h - from) * m as f64 / 3.0);
        }
        points
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
}

/// An impact found inside the step, valid while both paths are those it was found on.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Event {
    /// Seconds into the step.
    time: f64,
    impact: Impact,
    versions: (u32, u32),
}

impl Eq for Event {}

impl PartialOrd for Event {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Event {
    fn cmp(&self, other: &Self) -> Ordering {
        self.time
            .total_cmp(&other.time)
            .then(self.impact.cmp(&other.impact))
            .then(self.versions.cmp(&other.versions))
    }
}

impl Contacts {
    pub fn new(scene: &Scene, forces: &ForceModel) -> Self {
        let obstacles = obstacles::obstacles(scene);
        Self {
            obstacles,
            radius: scene.particles.iter().map(|p| p.radius).collect(),
            restitution: scene.world.restitution,
            acceleration_scale: forces
                .uniform
                .iter()
                .map(|a| a.length())
                .fold(0.0, f64::max),
            proxies: Proxies::default(),
            boxes: Vec::new(),
            touching_pairs: Vec::new(),
            touching_by_particle: Adjacency::default(),
            touching_obstacles: Vec::new(),
            resting: RestingSolver::default(),
            workers: Workers::default(),
            start_normals: Vec::new(),
            coupled: (0..scene.particles.len())
                .map(|i| {
                    !forces.is_fixed(i)
                        && (forces.interacting.contains(&i)
                            || forces.springs.iter().any(|s| s.touches(i))
                            || forces.constraints.touches(i))
                })
                .collect(),
            paths: Vec::new(),
            controls: Vec::new(),
            versions: Vec::new(),
            changed: Vec::new(),
            is_changed: Vec::new(),
            escaped: Vec::new(),
            queue: BinaryHeap::new(),
            neighbours: Vec::new(),
            applied: Vec::new(),
        }
    }

    /// How many of the obstacles are ramps (the walls come after them).
    pub fn ramp_count(&self) -> usize {
        self.obstacles
            .iter()
            .take_while(|o| matches!(o.shape, Shape::Capsule { .. }))
            .count()
    }

    fn resting_speed(&self, h: f64) -> f64 {
        2.0 * self.acceleration_scale * h + 1e-12
    }

    /// Finds what touches at the start of a step of `h`, applies the impacts happening now
    /// (a struck row of balls passes the blow along here), and puts particles resting on
    /// surfaces under their normal force. Returns whether velocities or the forces
    /// changed.
    pub fn begin_step(
        &mut self,
        state: &mut State,
        forces: &mut ForceModel,
        h: f64,
        profiler: &mut Profiler,
    ) -> bool {
        let had_surface_contacts = !forces.surface_contacts.is_empty();
        self.applied.clear();
        forces.surface_contacts.clear();
        self.find_touching(state, forces, h, profiler);
        let resting_speed = self.resting_speed(h);
        let mut changed = self.impacts_now(state, forces, resting_speed);
        // Friction needs to know how hard the other forces press and pull.
        let frictional = self
            .touching_obstacles
            .iter()
            .any(|&(_, k)| self.obstacles[k as usize].friction > 0.0);
        let mut free = Vec::new();
        if frictional {
            free.resize(state.len(), DVec2::ZERO);
            forces.accelerations(&state.position, &state.velocity, &mut free);
        }
        for &(p, k) in &self.touching_obstacles {
            let (p, obstacle) = (p as usize, &self.obstacles[k as usize]);
            let (distance, normal) = obstacle.shape.distance(state.position[p]);
            let approach = -state.velocity[p].dot(normal);
            if approach < -resting_speed {
                continue; // leaving the surface
            }
            if approach > 0.0 {
                state.velocity[p] += normal * approach;
                changed = true;
            }
            if distance < self.radius[p] {
                // Sit exactly on the surface.
                state.position[p] += normal * (self.radius[p] - distance);
            }
            let tangential = state.velocity[p] - normal * state.velocity[p].dot(normal);
            let sliding = if obstacle.friction > 0.0 {
                let (pressing, pull) =
                    (-free[p].dot(normal), free[p] - normal * free[p].dot(normal));
                let limit = obstacle.friction * pressing.max(0.0);
                if tangential.length() <= limit * h && pull.length() <= limit {
                    // Friction stops it within this step and can hold it: static.
                    state.velocity[p] -= tangential;
                    changed |= tangential != DVec2::ZERO;
                    None
                } else {
                    // Sliding, or about to start sliding the way it is pulled.
                    tangential.try_normalize().or_else(|| pull.try_normalize())
                }
            } else {
                None
            };
            forces.surface_contacts.push(SurfaceContact {
                particle: p,
                normal,
                friction: obstacle.friction,
                sliding,
            });
        }
        profiler.lap(Stage::StartContacts);
        changed || had_surface_contacts || !forces.surface_contacts.is_empty()
    }

    /// Fills the touching lists from the current positions.
    fn find_touching(
        &mut self,
        state: &State,
        forces: &ForceModel,
        h: f64,
        profiler: &mut Profiler,
    ) {
        let n = state.len();
        profiler.lap(Stage::StartContacts);
        self.boxes.clear();
        self.boxes.extend(
            (0..n).map(|i| Aabb::around(&[state.position[i]], self.radius[i] * (1.0 + TOUCHING))),
        );
        let radius = &self.radius;
        let (position, velocity) = (&state.position, &state.velocity);
        self.touching_pairs.clear();
        let candidates = self.proxies.update(
            &self.boxes,
            |i| fat_margin(radius[i], velocity[i], h),
            |i, j| forces.is_fixed(i) && forces.is_fixed(j),
            &self.workers,
        );
        let boxes = &self.boxes;
        self.touching_pairs
            .extend(candidates.iter().copied().filter(|&(i, j)| {
                let (i, j) = (i as usize, j as usize);
                let reach = radius[i] + radius[j];
                boxes[i].overlaps(&boxes[j])
                    && position[i].distance(position[j]) - reach <= TOUCHING * reach
            }));
        self.touching_by_particle.fill(n, &self.touching_pairs);
        profiler.lap(Stage::BroadPhase);
        self.touching_obstacles.clear();
        for p in (0..n).filter(|&p| !forces.is_fixed(p)) {
            for (k, obstacle) in self.obstacles.iter().enumerate() {
                if obstacle
                    .shape
                    .clear_of_box(self.boxes[p].min, self.boxes[p].max)
                {
                    continue;
                }
                let reach = self.radius[p] + half_thickness(&obstacle.shape);
                if obstacle.shape.distance(position[p]).0 - self.radius[p] <= TOUCHING * reach {
                    self.touching_obstacles.push((p as u32, k as u32));
                }
            }
        }
    }

    /// Applies every impact between touching things that approach faster than
    /// `resting_speed`, pass after pass until none does. A contact still approaching after
    /// many passes (a ball squeezed between two others) is made inelastic, which ends it.
    fn impacts_now(&mut self, state: &mut State, forces: &ForceModel, resting_speed: f64) -> bool {
        // Only velocities change here, so each contact's normal is found once.
        let mut contacts = std::mem::take(&mut self.start_normals);
        contacts.clear();
        let pairs = self
            .touching_pairs
            .iter()
            .map(|&(i, j)| Impact::Pair(i as usize, j as usize));
        let obstacles = self
            .touching_obstacles
            .iter()
            .map(|&(p, k)| Impact::Obstacle(p as usize, k as usize));
        contacts.extend(
            pairs
                .chain(obstacles)
                .map(|impact| (impact, self.measure(impact, state).1)),
        );
        let max_passes = 2 * state.len() + 8;
        let mut changed = false;
        for pass in 0..=max_passes {
            let inelastic = pass == max_passes;
            let mut any = false;
            for &(impact, normal) in &contacts {
                let approach = approach_along(impact, normal, state);
                if approach <= resting_speed {
                    continue;
                }
                let restitution = if inelastic {
                    0.0
                } else {
                    self.restitution_at(impact, approach, resting_speed)
                };
                apply_impulse(
                    impact,
                    normal,
                    approach * (1.0 + restitution),
                    state,
                    forces,
                );
                self.applied.push(Applied {
                    time: 0.0,
                    impact,
                    approach,
                    restitution,
                });
                any = true;
            }
            changed |= any;
            if !any {
                break;
            }
        }
        self.start_normals = contacts;
        changed
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

    /// The reach of an impact: the distance scale its gap is judged against.
    pub fn reach(&self, impact: Impact) -> f64 {
        match impact {
            Impact::Pair(i, j) => self.radius[i] + self.radius[j],
            Impact::Obstacle(p, k) => self.radius[p] + half_thickness(&self.obstacles[k].shape),
        }
    }

    /// Processes the impacts within the step from `start` to `end` (`h` seconds) in time
    /// order. Impacts among uncoupled particles are applied inside the step and `end` is
    /// patched with their effect. The first impact involving a coupled particle stops the
    /// processing: it is returned (seconds into the step), and the caller integrates the
    /// system to that instant, lays [`Self::patch`] over it and applies [`Self::apply`].
    /// Touching contacts are the resting solver's and are not searched.
    pub fn resolve_impacts(
        &mut self,
        start: &State,
        end: &mut State,
        h: f64,
        forces: &ForceModel,
        profiler: &mut Profiler,
    ) -> Option<(f64, Impact)> {
        let n = start.len();
        self.acceleration_scale = (0..n)
            .map(|i| end.velocity[i].distance(start.velocity[i]) / h)
            .fold(
                forces
                    .uniform
                    .iter()
                    .map(|a| a.length())
                    .fold(0.0, f64::max),
                f64::max,
            );
        let resting_speed = self.resting_speed(h);
        self.start_paths(start, end, h);
        profiler.lap(Stage::TimeOfImpact);
        let candidates = self.swept_candidates(start, h, forces);
        profiler.lap(Stage::BroadPhase);
        // Every search reads the paths only: pieces of the lists go to different threads,
        // and the events found join in the lists' order.
        let mut found = Vec::new();
        let this = &*self;
        this.workers
            .collect_into(candidates.len(), &mut found, |range, found| {
                for &(i, j) in &candidates[range] {
                    if let Some(event) = this.search_pair(i as usize, j as usize, 0.0, h) {
                        found.push(event);
                    }
                }
            });
        this.workers.collect_into(n, &mut found, |range, found| {
            for p in range.filter(|&p| !forces.is_fixed(p)) {
                this.search_obstacles(p, 0.0, h, found);
            }
        });
        self.queue.extend(found.drain(..).map(Reverse));

        let mut interruption = None;
        let mut budget = 20 * n + 100;
        while let Some(Reverse(event)) = self.queue.pop() {
            let (first, second) = particles_of(event.impact);
            if (self.versions[first], second.map_or(0, |j| self.versions[j])) != event.versions {
                continue; // found on a path an earlier impact has since changed
            }
            if self.coupled[first] || second.is_some_and(|j| self.coupled[j]) {
                interruption = Some((event.time, event.impact));
                break;
            }
            if budget == 0 {
                break; // pathological: leave the rest to the resting solver
            }
            budget -= 1;
            self.apply_local(event, h, resting_speed, forces, &mut found);
            self.queue.extend(found.drain(..).map(Reverse));
        }
        for &p in &self.changed {
            let (x, v) = self.paths[p as usize].at(h, h);
            end.position[p as usize] = x;
            end.velocity[p as usize] = v;
        }
        profiler.lap(Stage::TimeOfImpact);
        interruption
    }

    /// Each particle's path through the step, unchanged by impacts yet, with its control
    /// points and swept box; and the impact bookkeeping of the last step cleared.
    fn start_paths(&mut self, start: &State, end: &State, h: f64) {
        let n = start.len();
        self.paths.clear();
        self.paths.extend((0..n).map(|i| Path {
            start: (start.position[i], start.velocity[i]),
            end: (end.position[i], end.velocity[i]),
            kick: DVec2::ZERO,
            kick_moment: DVec2::ZERO,
        }));
        self.versions.clear();
        self.versions.resize(n, 0);
        for &p in &self.changed {
            self.is_changed[p as usize] = false;
        }
        self.is_changed.resize(n, false);
        self.changed.clear();
        self.escaped.clear();
        self.queue.clear();
        self.controls.clear();
        self.controls
            .extend(self.paths.iter().map(|path| path.after(0.0, h)));
        self.boxes.clear();
        self.boxes.extend(
            self.controls
                .iter()
                .zip(&self.radius)
                .map(|(controls, r)| Aabb::around(controls, *r)),
        );
    }

    /// The pairs whose swept boxes overlap and that do not touch, ascending.
    fn swept_candidates(&mut self, start: &State, h: f64, forces: &ForceModel) -> Vec<(u32, u32)> {
        // Touching pairs are the resting solver's: both lists are ascending, so one walk
        // through the touching list takes them out.
        let mut touching = self.touching_pairs.as_slice();
        let (radius, boxes) = (&self.radius, &self.boxes);
        self.proxies
            .update(
                boxes,
                |i| fat_margin(radius[i], start.velocity[i], h),
                |i, j| forces.is_fixed(i) && forces.is_fixed(j),
                &self.workers,
            )
            .iter()
            .copied()
            .filter(|&(i, j)| boxes[i as usize].overlaps(&boxes[j as usize]))
            .filter(|pair| {
                while touching.first().is_some_and(|t| t < pair) {
                    touching = &touching[1..];
                }
                touching.first() != Some(pair)
            })
            .collect()
    }

    /// Whether impacts inside the last step changed any path.
    pub fn changed_paths(&self) -> bool {
        !self.changed.is_empty()
    }

    /// Overwrites the particles whose paths impacts changed with their state `time`
    /// seconds into the step (`h`), after the system was integrated to `time`.
    pub fn patch(&self, state: &mut State, time: f64, h: f64) {
        for &p in &self.changed {
            let (x, v) = self.paths[p as usize].at(time, h);
            state.position[p as usize] = x;
            state.velocity[p as usize] = v;
        }
    }

    /// Applies an impact between uncoupled particles at its instant inside the step and
    /// searches the changed paths again.
    fn apply_local(
        &mut self,
        event: Event,
        h: f64,
        resting_speed: f64,
        forces: &ForceModel,
        found: &mut Vec<Event>,
    ) {
        let (first, second) = particles_of(event.impact);
        let (xi, vi) = self.paths[first].at(event.time, h);
        let other = second.map(|j| self.paths[j].at(event.time, h));
        let (_, normal, approach) = self.geometry(event.impact, (xi, vi), other);
        if approach <= 0.0 {
            return;
        }
        let restitution = self.restitution_at(event.impact, approach, resting_speed);
        self.applied.push(Applied {
            time: event.time,
            impact: event.impact,
            approach,
            restitution,
        });
        let (dv_first, dv_second) =
            velocity_changes(event.impact, normal, approach * (1.0 + restitution), forces);
        let mut moved = vec![(first, dv_first)];
        if let Some(j) = second {
            moved.push((j, dv_second));
        }
        for &(p, dv) in &moved {
            if dv == DVec2::ZERO {
                continue;
            }
            let path = &mut self.paths[p];
            path.kick += dv;
            path.kick_moment += dv * event.time;
            self.versions[p] += 1;
            if !self.is_changed[p] {
                self.is_changed[p] = true;
                self.changed.push(p as u32);
            }
        }
        for &(p, dv) in &moved {
            if dv == DVec2::ZERO || forces.is_fixed(p) {
                continue;
            }
            let bounds = Aabb::around(&self.paths[p].after(event.time, h), self.radius[p]);
            if !self.proxies.fat(p).contains(&bounds) && !self.escaped.contains(&(p as u32)) {
                self.escaped.push(p as u32);
            }
            self.neighbours.clear();
            self.proxies.query(&bounds, &mut self.neighbours);
            self.neighbours.extend_from_slice(&self.escaped);
            self.neighbours.sort_unstable();
            self.neighbours.dedup();
            let neighbours = std::mem::take(&mut self.neighbours);
            for &q in &neighbours {
                let q = q as usize;
                if q == p
                    || (forces.is_fixed(p) && forces.is_fixed(q))
                    || self.touching_by_particle.contains(p, q as u32)
                {
                    continue;
                }
                let pair = (p.min(q), p.max(q));
                if let Some(event) = self.search_pair(pair.0, pair.1, event.time, h) {
                    found.push(event);
                }
            }
            self.neighbours = neighbours;
            self.search_obstacles(p, event.time, h, found);
        }
    }

    /// The control points of `p`'s path from `from` seconds to the end of the step.
    fn path_after(&self, p: usize, from: f64, h: f64) -> [DVec2; 4] {
        if from == 0.0 && !self.is_changed[p] {
            self.controls[p]
        } else {
            self.paths[p].after(from, h)
        }
    }

    /// The first impact of particles `i < j` after `after` seconds into the step.
    fn search_pair(&self, i: usize, j: usize, after: f64, h: f64) -> Option<Event> {
        let from = after;
        let (a, b) = (self.path_after(i, from, h), self.path_after(j, from, h));
        let relative: [DVec2; 4] = std::array::from_fn(|k| b[k] - a[k]);
        let reach = self.radius[i] + self.radius[j];
        if relative[0].length() - reach <= TOUCHING * reach {
            return None; // touching already: the resting solver's
        }
        let region = Region::Disc {
            centre: DVec2::ZERO,
            reach,
        };
        let s = earliest_entry(&region, &relative)?;
        Some(Event {
            time: from + s * (h - from),
            impact: Impact::Pair(i, j),
            versions: (self.versions[i], self.versions[j]),
        })
    }

    /// The first impact of particle `p` with each obstacle after `after` seconds.
    fn search_obstacles(&self, p: usize, after: f64, h: f64, found: &mut Vec<Event>) {
        let from = after;
        let path = self.path_after(p, from, h);
        let bounds = Aabb::around(&path, self.radius[p]);
        for (k, obstacle) in self.obstacles.iter().enumerate() {
            if obstacle.shape.clear_of_box(bounds.min, bounds.max)
                || self
                    .touching_obstacles
                    .binary_search(&(p as u32, k as u32))
                    .is_ok()
            {
                continue;
            }
            let reach = self.radius[p] + half_thickness(&obstacle.shape);
            if obstacle.shape.distance(path[0]).0 - self.radius[p] <= TOUCHING * reach {
                continue;
            }
            let (regions, count) = Region::around(&obstacle.shape, self.radius[p]);
            let first = regions[..count]
                .iter()
                .flatten()
                .filter_map(|region| earliest_entry(region, &path))
                .fold(f64::INFINITY, f64::min);
            if first.is_finite() {
                found.push(Event {
                    time: from + first * (h - from),
                    impact: Impact::Obstacle(p, k),
                    versions: (self.versions[p], 0),
                });
            }
        }
    }

    /// Applies the impulse of an impact returned by [`Self::resolve_impacts`], now that the
    /// state is at its instant. A slow one is inelastic: the bodies come to rest in contact.
    pub fn apply(&mut self, impact: Impact, state: &mut State, forces: &ForceModel, h: f64) {
        let (_, normal, approach) = self.measure(impact, state);
        if approach <= 0.0 {
            return;
        }
        let restitution = self.restitution_at(impact, approach, self.resting_speed(h));
        apply_impulse(
            impact,
            normal,
            approach * (1.0 + restitution),
            state,
            forces,
        );
        self.applied.push(Applied {
            time: h,
            impact,
            approach,
            restitution,
        });
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
        let touching = Touching {
            pairs: &self.touching_pairs,
            surfaces: &self.touching_obstacles,
            obstacles: &self.obstacles,
            radius: &self.radius,
            inverse_mass: &forces.inverse_mass,
        };
        let is_changed = &self.is_changed;
        let is_struck = |i: usize| {
            struck.is_some_and(|impact| impact.involves(i))
                || is_changed.get(i).copied().unwrap_or(false)
        };
        self.resting
            .solve(&touching, state, h, resting_speed, is_struck)
    }
}

/// Pairs listed by particle (compressed rows): each pair (i, j) under both i and j.
#[derive(Clone, Debug, Default)]
struct Adjacency {
    first: Vec<u32>,
    partners: Vec<u32>,
}

impl Adjacency {
    fn fill(&mut self, n: usize, pairs: &[(u32, u32)]) {
        self.first.clear();
        self.first.resize(n + 1, 0);
        for &(i, j) in pairs {
            self.first[i as usize + 1] += 1;
            self.first[j as usize + 1] += 1;
        }
        for p in 0..n {
            self.first[p + 1] += self.first[p];
        }
        self.partners.clear();
        self.partners.resize(2 * pairs.len(), 0);
        let mut next = self.first.clone();
        for &(i, j) in pairs {
            for (a, b) in [(i, j), (j, i)] {
                let slot = &mut next[a as usize];
                self.partners[*slot as usize] = b;
                *slot += 1;
            }
        }
    }

    /// Whether `p` and `q` are a listed pair.
    fn contains(&self, p: usize, q: u32) -> bool {
        self.partners[self.first[p] as usize..self.first[p + 1] as usize].contains(&q)
    }
}

/// How far a particle's fat box reaches beyond its box, metres.
fn fat_margin(radius: f64, velocity: DVec2, h: f64) -> f64 {
    FAT_RADII * radius + (FAT_STEPS * velocity.length() * h).min(FAT_TRAVEL_RADII * radius)
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

/// The approach speed of an impact along `normal` (m/s, positive when closing), as
/// [`Contacts::measure`] gives it.
fn approach_along(impact: Impact, normal: DVec2, state: &State) -> f64 {
    match impact {
        Impact::Pair(i, j) => (state.velocity[i] - state.velocity[j]).dot(normal),
        Impact::Obstacle(p, _) => -state.velocity[p].dot(normal),
    }
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

fn apply_impulse(
    impact: Impact,
    normal: DVec2,
    change: f64,
    state: &mut State,
    forces: &ForceModel,
) {
    let (first, second) = particles_of(impact);
    let (dv_first, dv_second) = velocity_changes(impact, normal, change, forces);
    state.velocity[first] += dv_first;
    if let Some(j) = second {
        state.velocity[j] += dv_second;
    }
}
