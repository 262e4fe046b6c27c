//! Impacts inside a step: each particle's path through the step, the search for the
//! first instant two paths (or a path and a surface) meet ([`super::time_of_impact`]),
//! and the impacts applied in time order — inside the step for uncoupled particles,
//! or handed back to the caller for a coupled one (see the module above).

// Particle indices are u32 in the contact lists, as in the module above.
#![expect(
    clippy::cast_possible_truncation,
    reason = "u32 particle indices, see contacts/mod.rs"
)]

use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

use glam::DVec2;

use super::broad_phase::Aabb;
use super::time_of_impact::{Region, control_points, earliest_entry};
use super::{
    Applied, Contacts, Impact, InStep, TOUCHING, fat_margin, half_thickness, larger, particles_of,
    velocity_changes,
};
use crate::forces::ForceModel;
use crate::profile::{Profiler, Stage};
use crate::state::State;
use crate::tuning::{APART, RESTART};
use crate::turning::Grip;

/// The impact search's state through one step.
#[derive(Clone, Debug, Default)]
pub(super) struct ImpactSearch {
    /// Each particle's path through the step.
    paths: Vec<Path>,
    /// Each path's Bézier control points over the whole step, before any impact changed
    /// it: computed once a step, read by every search that starts at the step's start.
    controls: Vec<[DVec2; 4]>,
    /// Bumped when a particle's path changes, to recognise stale queued impacts.
    versions: Vec<u32>,
    /// Particles whose paths impacts changed during this step, and the same as flags.
    changed: Vec<u32>,
    pub is_changed: Vec<bool>,
    /// Changed particles whose new path left their fat box, so the broad phase may not
    /// find them: every search after an impact also tries these.
    escaped: Vec<u32>,
    queue: BinaryHeap<Reverse<Event>>,
    /// How many more impacts this step may apply inside itself.
    budget: usize,
    neighbours: Vec<u32>,
    /// Scratch: the candidate pairs whose swept boxes overlap, not touching.
    candidates: Vec<(u32, u32)>,
}

/// A particle's path through the step: the cubic Hermite curve through the integrator's
/// state at both ends, plus the kicks of the impacts applied inside the step. Kicks only
/// ever come in time order and the path is only read after the latest, so their running
/// sums suffice: a kick Δv at τ adds Δv (t − τ) to every later position.
///
/// A coupled particle's path starts again at each impact of the coupled system: from its
/// integrated state then (`from` seconds into the step) to its integrated state at the
/// step's end.
#[derive(Clone, Copy, Debug)]
struct Path {
    /// Seconds into the step where the curve starts (0, or a coupled impact's instant).
    from: f64,
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
        let span = h - self.from;
        let (position, velocity) = if span > 0.0 {
            let s = ((t - self.from) / span).clamp(0.0, 1.0);
            hermite(((x0, v0), (x1, v1)), span, s)
        } else {
            (x0, v0) // a curve that starts at the step's end
        };
        (
            position + self.kick * t - self.kick_moment,
            velocity + self.kick,
        )
    }

    /// At most how far this path gets from `old` between this path's start and the end of
    /// a step of `h`, for an `old` path with no kick after this one's start (a coupled
    /// particle's: its paths start again rather than take kicks). Both are cubic Hermite
    /// curves over the same interval there, and their difference is one too: its end
    /// points' basis functions are positive and sum to one, so they contribute at most
    /// the larger end-point distance; its tangents' basis functions peak at 4/27.
    fn apart_from(&self, old: &Self, h: f64) -> f64 {
        let (x0, v0) = old.at(self.from, h);
        let (x1, v1) = old.at(h, h);
        let ((start, start_velocity), (end, end_velocity)) = (self.start, self.end);
        (start - x0).length().max((end - x1).length())
            + 4.0 / 27.0
                * (h - self.from)
                * ((start_velocity - v0).length() + (end_velocity - v1).length())
    }

    /// Bézier control points of the path from `from` to the end of a step of `h`.
    fn after(&self, from: f64, h: f64) -> [DVec2; 4] {
        let ((x0, v0), (x1, v1)) = (self.start, self.end);
        let span = h - self.from;
        let p = control_points(x0, v0, x1, v1, span);
        // From the curve's own start and with no kick (every path as the step begins, a
        // thousand of them a step in the pit): the points themselves. The general case
        // below gives the same numbers (a split at 0, and kicks of zero), but its
        // arithmetic is a measurable share of the time of impact (`bench --scene pit`);
        // it can differ only in the sign of a zero.
        #[expect(
            clippy::float_cmp,
            reason = "exactly the curve's start: no split at all"
        )]
        let at_start = from == self.from;
        if at_start && self.kick == DVec2::ZERO && self.kick_moment == DVec2::ZERO {
            return p;
        }
        let u = if span > 0.0 {
            ((from - self.from) / span).clamp(0.0, 1.0)
        } else {
            1.0
        };
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

/// The cubic Hermite curve from position and velocity `start` to `end` over `span`
/// seconds: its position and velocity at the fraction `s` of the span.
pub(crate) fn hermite(
    ((x0, v0), (x1, v1)): ((DVec2, DVec2), (DVec2, DVec2)),
    span: f64,
    s: f64,
) -> (DVec2, DVec2) {
    let s2 = s * s;
    let position = hermite_position(((x0, v0), (x1, v1)), span, s);
    let velocity = (x1 - x0) * ((6.0 * s - 6.0 * s2) / span)
        + v0 * (3.0 * s2 - 4.0 * s + 1.0)
        + v1 * (3.0 * s2 - 2.0 * s);
    (position, velocity)
}

/// [`hermite`]'s position alone, for what only reads where a body is.
pub(crate) fn hermite_position(
    ((x0, v0), (x1, v1)): ((DVec2, DVec2), (DVec2, DVec2)),
    span: f64,
    s: f64,
) -> DVec2 {
    let (s2, s3) = (s * s, s * s * s);
    x0 * (2.0 * s3 - 3.0 * s2 + 1.0)
        + v0 * (span * (s3 - 2.0 * s2 + s))
        + x1 * (3.0 * s2 - 2.0 * s3)
        + v1 * (span * (s3 - s2))
}

/// The coupled particles' integrated state at an instant inside the step: what a coupled
/// impact is measured and applied on.
pub(crate) struct Members<'a> {
    /// Each particle's index in `state`, `None` for particles outside the coupled system.
    pub local: &'a [Option<u32>],
    pub state: &'a mut State,
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
    /// Processes the impacts within the step from `start` to `end` (`h` seconds) in time
    /// order. Impacts among uncoupled particles are applied inside the step and `end` is
    /// patched with their effect once no coupled impact is left. The first impact
    /// involving a coupled particle stops the processing: it is returned (seconds into
    /// the step), and the caller integrates the system to that instant, lays
    /// [`Self::patch`] over it and applies [`Self::apply`].
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
        // The largest field and the largest change of velocity over the step, by their
        // squares: a square root and a division are monotonic and correctly rounded, so
        // taking them once of the largest gives the bits of the largest of each particle's
        // (one of each a particle cost the time of impact 2–3 µs a step at 1,000 balls and
        // 25 µs at 10,000).
        let field = forces
            .uniform
            .iter()
            .fold(0.0, |largest, a| larger(a.length_squared(), largest));
        let change = (0..n).fold(0.0, |largest, i| {
            larger(end.velocity[i].distance_squared(start.velocity[i]), largest)
        });
        self.acceleration_scale = larger(change.sqrt() / h, field.sqrt());
        if !self.collisions && self.obstacles.is_empty() {
            return None; // nothing a particle could strike: no paths to build
        }
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
        self.search.candidates = candidates;
        self.search.queue.extend(found.drain(..).map(Reverse));
        self.search.budget = 20 * n + 100;
        self.resume_impacts(end, h, forces, profiler)
    }

    /// Goes on processing the impacts found inside the step (see
    /// [`Self::resolve_impacts`]) after a coupled impact was applied
    /// ([`Self::strike_coupled`], [`Self::restart_paths`]): the next coupled impact is
    /// returned, or, when none is left, `end` patched with the paths impacts changed.
    pub fn resume_impacts(
        &mut self,
        end: &mut State,
        h: f64,
        forces: &ForceModel,
        profiler: &mut Profiler,
    ) -> Option<(f64, Impact)> {
        let mut found = Vec::new();
        let mut interruption = None;
        while let Some(Reverse(event)) = self.search.queue.pop() {
            let (first, second) = particles_of(event.impact);
            if (
                self.search.versions[first],
                second.map_or(0, |j| self.search.versions[j]),
            ) != event.versions
            {
                continue; // found on a path an earlier impact has since changed
            }
            if self.search.budget == 0 {
                break; // pathological: leave the rest to the resting solver
            }
            self.search.budget -= 1;
            if self.coupled[first] || second.is_some_and(|j| self.coupled[j]) {
                interruption = Some((event.time, event.impact));
                break;
            }
            self.strike_inside(event.impact, event.time, h, None, forces, &mut found);
            self.search.queue.extend(found.drain(..).map(Reverse));
        }
        // The caller integrates again (or, for a coupled impact, resumes here) when
        // interrupted: `end` is patched once the step's impacts are all applied.
        if interruption.is_none() {
            for &p in &self.search.changed {
                let (x, v) = self.search.paths[p as usize].at(h, h);
                end.position[p as usize] = x;
                end.velocity[p as usize] = v;
            }
        }
        profiler.lap(Stage::TimeOfImpact);
        interruption
    }

    /// Each particle's path through the step, unchanged by impacts yet, with its control
    /// points and swept box; and the impact bookkeeping of the last step cleared.
    fn start_paths(&mut self, start: &State, end: &State, h: f64) {
        let n = start.len();
        // Each particle's on its own: built on different threads, each in its place.
        self.workers.map_into(n, &mut self.search.paths, |i| Path {
            from: 0.0,
            start: (start.position[i], start.velocity[i]),
            end: (end.position[i], end.velocity[i]),
            kick: DVec2::ZERO,
            kick_moment: DVec2::ZERO,
        });
        self.search.versions.clear();
        self.search.versions.resize(n, 0);
        for &p in &self.search.changed {
            self.search.is_changed[p as usize] = false;
        }
        self.search.is_changed.resize(n, false);
        self.search.changed.clear();
        self.search.escaped.clear();
        self.search.queue.clear();
        let paths = &self.search.paths;
        self.workers
            .map_into(n, &mut self.search.controls, |i| paths[i].after(0.0, h));
        let (controls, radius) = (&self.search.controls, &self.radius);
        self.workers.map_into(n, &mut self.boxes, |i| {
            Aabb::around(&controls[i], radius[i])
        });
    }

    /// The pairs whose swept boxes overlap and that do not touch, ascending.
    fn swept_candidates(&mut self, start: &State, h: f64, forces: &ForceModel) -> Vec<(u32, u32)> {
        let mut swept = std::mem::take(&mut self.search.candidates);
        swept.clear();
        if !self.collisions {
            return swept;
        }
        // Touching pairs are the resting solver's: both lists are ascending, so one walk
        // through the touching list takes them out.
        let touching = self.touching.pairs.as_slice();
        let (radius, boxes) = (&self.radius, &self.boxes);
        let candidates = self.proxies.update(
            boxes,
            |i| fat_margin(radius[i], start.velocity[i], h),
            |i, j| forces.is_fixed(i) && forces.is_fixed(j),
            &self.workers,
        );
        // Each candidate is tested on its own: pieces of the list go to different threads,
        // each starting its walk through the touching list where its first pair would be.
        self.workers
            .collect_into(candidates.len(), &mut swept, |range, swept| {
                let Some(first) = candidates.get(range.start) else {
                    return;
                };
                let mut next_touching = touching.partition_point(|t| t < first);
                // A plain loop, as the touching test's (an iterator's filter is a call
                // through a reference to the closure in WebAssembly).
                for &pair in &candidates[range] {
                    if !boxes[pair.0 as usize].overlaps(&boxes[pair.1 as usize]) {
                        continue;
                    }
                    while touching.get(next_touching).is_some_and(|t| *t < pair) {
                        next_touching += 1;
                    }
                    if touching.get(next_touching) != Some(&pair) {
                        swept.push(pair);
                    }
                }
            });
        swept
    }

    /// Whether impacts inside the last step changed any path.
    pub fn changed_paths(&self) -> bool {
        !self.search.changed.is_empty()
    }

    /// Overwrites the particles whose paths impacts changed with their state `time`
    /// seconds into the step (`h`), after the system was integrated to `time`.
    pub fn patch(&self, state: &mut State, time: f64, h: f64) {
        for &p in &self.search.changed {
            let (x, v) = self.search.paths[p as usize].at(time, h);
            state.position[p as usize] = x;
            state.velocity[p as usize] = v;
        }
    }

    /// Applies an impact at `time` seconds into the step, measured where its particles
    /// are then: on the coupled system's integrated state (`members`) for coupled ones,
    /// on their paths for the others. The impulse goes into `members` for coupled
    /// particles (whose paths [`Self::restart_paths`] starts again) and kicks the others'
    /// paths, which are searched again. Returns whether an impulse was applied (none when
    /// the bodies no longer approach).
    fn strike_inside(
        &mut self,
        impact: Impact,
        time: f64,
        h: f64,
        mut members: Option<&mut Members<'_>>,
        forces: &ForceModel,
        found: &mut Vec<Event>,
    ) -> bool {
        let (gap, normal, approach) = self.measure_inside(impact, time, h, members.as_deref());
        // A coupled impact is measured on the integrated state: bodies still apart there
        // make no impact (an event found on a path since started again), however they
        // move. Free impacts are measured on the path they were found on.
        let apart = members.is_some() && gap > APART * self.reach(impact);
        if approach <= 0.0 || apart {
            return false;
        }
        let restitution = self.restitution_at(impact, approach, self.resting_speed(h));
        let mut applied = Applied {
            time,
            impact,
            approach,
            restitution,
            grip: Grip::default(),
            kick: (DVec2::ZERO, DVec2::ZERO),
            tied: None,
        };
        let (first, second) = particles_of(impact);
        if self.turning.is_some() {
            let velocities = self.velocities_inside(impact, time, h, members.as_deref());
            applied.grip = self.grip(&applied, normal, velocities, forces);
            self.turn(&applied);
        }
        let (dv_first, dv_second) =
            velocity_changes(impact, normal, approach * (1.0 + restitution), forces);
        applied.kick = (dv_first + applied.grip.dv.0, dv_second + applied.grip.dv.1);
        let (dv_first, dv_second) = applied.kick;
        self.report.applied.push(applied);
        let mut kicked = Vec::with_capacity(2);
        for (p, dv) in std::iter::once((first, dv_first)).chain(second.map(|j| (j, dv_second))) {
            if dv == DVec2::ZERO {
                continue;
            }
            if let Some((k, m)) = members.as_deref_mut().and_then(|m| Some((m.local[p]?, m))) {
                m.state.velocity[k as usize] += dv;
                self.mark_changed(p);
            } else {
                self.kick(p, dv, time);
                kicked.push(p);
            }
        }
        for p in kicked {
            if !forces.is_fixed(p) {
                self.search_again(p, time, h, forces, found);
            }
        }
        true
    }

    /// Adds a kick of `dv` at `time` to `p`'s path, and counts `p` as struck.
    fn kick(&mut self, p: usize, dv: DVec2, time: f64) {
        let path = &mut self.search.paths[p];
        path.kick += dv;
        path.kick_moment += dv * time;
        self.search.versions[p] += 1;
        self.mark_changed(p);
    }

    fn mark_changed(&mut self, p: usize) {
        if !self.search.is_changed[p] {
            self.search.is_changed[p] = true;
            self.search.changed.push(p as u32);
        }
    }

    /// Searches `p`'s changed path from `time` on against its neighbours and the
    /// obstacles.
    fn search_again(
        &mut self,
        p: usize,
        time: f64,
        h: f64,
        forces: &ForceModel,
        found: &mut Vec<Event>,
    ) {
        // Each box holds its particle's path from its last change to the step's end, so
        // two that do not overlap cannot meet from here on (nor a box and an obstacle
        // it is clear of).
        // (Its path has changed, so this is `paths[p].after`, found once for the box and
        // for every neighbour's search.)
        let own = self.path_after(p, time, h);
        let bounds = Aabb::around(&own, self.radius[p]);
        self.boxes[p] = bounds;
        if !self.collisions {
            self.search_obstacles(p, time, h, found);
            return;
        }
        if !self.proxies.fat(p).contains(&bounds) && !self.search.escaped.contains(&(p as u32)) {
            self.search.escaped.push(p as u32);
        }
        self.search.neighbours.clear();
        self.proxies.query(&bounds, &mut self.search.neighbours);
        self.search
            .neighbours
            .extend_from_slice(&self.search.escaped);
        self.search.neighbours.sort_unstable();
        self.search.neighbours.dedup();
        let neighbours = std::mem::take(&mut self.search.neighbours);
        for &q in &neighbours {
            let q = q as usize;
            if q == p
                || !bounds.overlaps(&self.boxes[q])
                || (forces.is_fixed(p) && forces.is_fixed(q))
                || self.touching.touch(p, q)
            {
                continue;
            }
            let other = self.path_after(q, time, h);
            let event = if p < q {
                self.search_paths(p, q, (&own, &other), time, h)
            } else {
                self.search_paths(q, p, (&other, &own), time, h)
            };
            found.extend(event);
        }
        self.search.neighbours = neighbours;
        self.search_obstacles(p, time, h, found);
    }

    /// The control points of `p`'s path from `from` seconds to the end of the step.
    fn path_after(&self, p: usize, from: f64, h: f64) -> [DVec2; 4] {
        if from == 0.0 && self.search.versions[p] == 0 {
            self.search.controls[p]
        } else {
            self.search.paths[p].after(from, h)
        }
    }

    /// The first impact of particles `i < j` after `after` seconds into the step.
    fn search_pair(&self, i: usize, j: usize, after: f64, h: f64) -> Option<Event> {
        let (a, b) = (self.path_after(i, after, h), self.path_after(j, after, h));
        self.search_paths(i, j, (&a, &b), after, h)
    }

    /// [`Self::search_pair`] with the particles' paths from `after` on, `(a, b)`.
    fn search_paths(
        &self,
        i: usize,
        j: usize,
        (a, b): (&[DVec2; 4], &[DVec2; 4]),
        after: f64,
        h: f64,
    ) -> Option<Event> {
        let from = after;
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
            versions: (self.search.versions[i], self.search.versions[j]),
        })
    }

    /// The first impact of particle `p` with each obstacle after `after` seconds.
    fn search_obstacles(&self, p: usize, after: f64, h: f64, found: &mut Vec<Event>) {
        let from = after;
        // Its swept box holds its path from its last change on (see `search_again`): most
        // particles are clear of every obstacle, and need nothing else.
        let (bounds, mut path) = (self.boxes[p], None);
        let near = self.obstacles_near(&bounds);
        for (k, obstacle) in self.obstacles[..near].iter().enumerate() {
            if obstacle.shape.clear_of_box(bounds.min, bounds.max) || self.touched_at_start(p, k) {
                continue;
            }
            let path = path.get_or_insert_with(|| self.path_after(p, from, h));
            let reach = self.radius[p] + half_thickness(&obstacle.shape);
            if obstacle.shape.distance(path[0]).0 - self.radius[p] <= TOUCHING * reach {
                continue;
            }
            let (regions, count) = Region::around(&obstacle.shape, self.radius[p]);
            let first = regions[..count]
                .iter()
                .flatten()
                .filter_map(|region| earliest_entry(region, path))
                .fold(f64::INFINITY, f64::min);
            if first.is_finite() {
                found.push(Event {
                    time: from + first * (h - from),
                    impact: Impact::Obstacle(p, k),
                    versions: (self.search.versions[p], 0),
                });
            }
        }
    }

    /// Gap, normal and approach ([`Self::measure`]) of a coupled impact `time` seconds
    /// into the step: the coupled particles' integrated state there is `members`, the
    /// others' their paths.
    pub fn measure_coupled(
        &self,
        impact: Impact,
        time: f64,
        h: f64,
        members: &Members<'_>,
    ) -> (f64, DVec2, f64) {
        self.measure_inside(impact, time, h, Some(members))
    }

    /// [`Self::measure`] `time` seconds into the step, each particle taken from
    /// `members` if it is one of them, else from its path.
    fn measure_inside(
        &self,
        impact: Impact,
        time: f64,
        h: f64,
        members: Option<&Members<'_>>,
    ) -> (f64, DVec2, f64) {
        let (first, second) = particles_of(impact);
        let at = |p| self.motion_inside(p, time, h, members);
        self.geometry(impact, at(first), second.map(at))
    }

    /// The velocities of an impact's particles `time` seconds into the step, as
    /// [`Self::measure_inside`] finds them.
    fn velocities_inside(
        &self,
        impact: Impact,
        time: f64,
        h: f64,
        members: Option<&Members<'_>>,
    ) -> (DVec2, Option<DVec2>) {
        let (first, second) = particles_of(impact);
        let velocity = |p| self.motion_inside(p, time, h, members).1;
        (velocity(first), second.map(velocity))
    }

    /// Particle `p`'s position and velocity `time` seconds into the step: on the
    /// coupled system's integrated state for its members, on its path otherwise.
    fn motion_inside(
        &self,
        p: usize,
        time: f64,
        h: f64,
        members: Option<&Members<'_>>,
    ) -> (DVec2, DVec2) {
        match members.and_then(|m| Some((m.local[p]? as usize, m))) {
            Some((k, m)) => (m.state.position[k], m.state.velocity[k]),
            None => self.search.paths[p].at(time, h),
        }
    }

    /// Applies a coupled impact at `time` seconds into the step on the coupled system's
    /// integrated state `members` ([`Self::strike_inside`]); its uncoupled partner's
    /// impacts found again join the queue. Returns whether an impulse was applied.
    pub fn strike_coupled(
        &mut self,
        impact: Impact,
        time: f64,
        h: f64,
        members: &mut Members<'_>,
        forces: &ForceModel,
    ) -> bool {
        let mut found = Vec::new();
        let struck = self.strike_inside(impact, time, h, Some(members), forces, &mut found);
        self.search.queue.extend(found.into_iter().map(Reverse));
        struck
    }

    /// The impacts of particle `p` with the surfaces it rested on at the step's start
    /// that it closes on faster than a resting contact's speed at `at` while still apart from them (by less than a resting contact's speed
    /// times the step: it left them that slowly), each with the instant it meets the
    /// surface at that speed. The impact search leaves the surfaces a particle rests on to
    /// the resting contacts; a blow that sends it back into one makes an impact there.
    pub fn closing_on_rests(
        &self,
        p: usize,
        at: InStep,
        members: &Members<'_>,
    ) -> Vec<(f64, Impact)> {
        let InStep { time, step: h } = at;
        let resting_speed = self.resting_speed(h);
        let first = self
            .touching
            .surfaces
            .partition_point(|&(q, _)| (q as usize) < p);
        self.touching.surfaces[first..]
            .iter()
            .take_while(|&&(q, _)| q as usize == p)
            .filter_map(|&(_, k)| {
                let impact = Impact::Obstacle(p, k as usize);
                let (gap, _, approach) = self.measure_inside(impact, time, h, Some(members));
                (gap > TOUCHING * self.reach(impact) && approach > resting_speed)
                    .then(|| (time + gap / approach, impact))
            })
            .collect()
    }

    /// Whether particle `p` touched obstacle `k` at the step's start.
    fn touched_at_start(&self, p: usize, k: usize) -> bool {
        self.touching
            .surfaces
            .binary_search(&(p as u32, k as u32))
            .is_ok()
    }

    /// Whether `impact` is with a surface its particle touched at the step's start (one
    /// [`Self::closing_on_rests`] queued: the impact search leaves those surfaces alone).
    pub fn with_a_rest(&self, impact: Impact) -> bool {
        match impact {
            Impact::Obstacle(p, k) => self.touched_at_start(p, k),
            Impact::Pair(..) => false,
        }
    }

    /// Queues `impact` of a coupled particle, expected `time` seconds into the step, for
    /// the search to take in time order ([`Self::resume_impacts`]).
    pub fn expect(&mut self, impact: Impact, time: f64) {
        let (first, second) = particles_of(impact);
        let versions = (
            self.search.versions[first],
            second.map_or(0, |j| self.search.versions[j]),
        );
        self.search.queue.push(Reverse(Event {
            time,
            impact,
            versions,
        }));
    }

    /// The particles that may touch particle `p` where it is at `position` (the broad
    /// phase's candidates, ascending; none when particles do not collide).
    pub fn neighbours_at(&self, p: usize, position: DVec2) -> Vec<usize> {
        if !self.collisions {
            return Vec::new();
        }
        let bounds = Aabb::around(&[position], self.radius[p] * (1.0 + TOUCHING));
        let mut neighbours = Vec::new();
        self.proxies.query(&bounds, &mut neighbours);
        neighbours.extend_from_slice(&self.search.escaped);
        neighbours.sort_unstable();
        neighbours.dedup();
        neighbours
            .into_iter()
            .map(|q| q as usize)
            .filter(|&q| q != p)
            .collect()
    }

    /// The contacts of particle `p` (its `neighbours`, [`Self::neighbours_at`], and the
    /// obstacles) that touch at `at` and close faster than a
    /// resting contact's speed, in a fixed order: what a blow at that instant passes on
    /// at once, as the step's start passes a blow along a row of touching balls. Coupled
    /// particles are read from `members`, the others from their paths.
    pub fn closing_at(
        &self,
        p: usize,
        neighbours: &[usize],
        at: InStep,
        members: &Members<'_>,
        forces: &ForceModel,
    ) -> Vec<Impact> {
        let InStep { time, step: h } = at;
        let resting_speed = self.resting_speed(h);
        let closing = |impact: Impact| {
            let (gap, _, approach) = self.measure_inside(impact, time, h, Some(members));
            gap <= TOUCHING * self.reach(impact) && approach > resting_speed
        };
        let position = match members.local[p] {
            Some(k) => members.state.position[k as usize],
            None => self.search.paths[p].at(time, h).0,
        };
        let bounds = Aabb::around(&[position], self.radius[p] * (1.0 + TOUCHING));
        let pairs = neighbours
            .iter()
            .filter(|&&q| !(forces.is_fixed(p) && forces.is_fixed(q)))
            .map(|&q| Impact::Pair(p.min(q), p.max(q)));
        let obstacles = (0..self.obstacles_near(&bounds))
            .filter(|&k| !self.obstacles[k].shape.clear_of_box(bounds.min, bounds.max))
            .map(|k| Impact::Obstacle(p, k));
        pairs
            .chain(obstacles)
            .filter(|&impact| closing(impact))
            .collect()
    }

    /// Ends the step at `time` seconds into it (of `h`): every particle outside the
    /// coupled system (`local` is `None` for them) is put where its path is then.
    pub fn end_at(&self, time: f64, h: f64, state: &mut State, local: &[Option<u32>]) {
        for (p, path) in self.search.paths.iter().enumerate() {
            if local[p].is_none() {
                (state.position[p], state.velocity[p]) = path.at(time, h);
            }
        }
    }

    /// The coupled system's paths start again at `time` seconds into the step, from its
    /// integrated state `at` then to `end` at the step's end (both indexed like
    /// `members`), after an impact changed it. A path that moves by less than
    /// [`RESTART`] of its particle's radius anywhere in the rest of the step is kept,
    /// with the impacts already found on it; the others are searched again.
    pub fn restart_paths(
        &mut self,
        members: &[usize],
        (at, end): (&State, &State),
        time: f64,
        h: f64,
        forces: &ForceModel,
    ) {
        for (k, &p) in members.iter().enumerate() {
            _ = self.restart_path(
                p,
                (
                    (at.position[k], at.velocity[k]),
                    (end.position[k], end.velocity[k]),
                ),
                time,
                h,
                forces,
            );
        }
    }

    /// Whether particle `p`'s path is kept when its motion moved by at most `moved`
    /// metres anywhere in the rest of the step ([`RESTART`]).
    pub fn keeps_path(&self, p: usize, moved: f64) -> bool {
        moved <= RESTART * self.radius[p]
    }

    /// Particle `p`'s path starts again at `time` seconds into the step, from `start`
    /// (position and velocity) then to `end` at the step's end, unless it moves by less
    /// than [`RESTART`] of its radius ([`Self::restart_paths`]); a fixed particle's
    /// never moves. Returns whether it started again.
    pub fn restart_path(
        &mut self,
        p: usize,
        (start, end): ((DVec2, DVec2), (DVec2, DVec2)),
        time: f64,
        h: f64,
        forces: &ForceModel,
    ) -> bool {
        if forces.is_fixed(p) {
            return false;
        }
        let path = Path {
            from: time,
            start,
            end,
            kick: DVec2::ZERO,
            kick_moment: DVec2::ZERO,
        };
        if path.apart_from(&self.search.paths[p], h) <= RESTART * self.radius[p] {
            return false;
        }
        self.search.paths[p] = path;
        self.search.versions[p] += 1;
        let mut found = Vec::new();
        self.search_again(p, time, h, forces, &mut found);
        self.search.queue.extend(found.into_iter().map(Reverse));
        true
    }

    /// Applies the impulse of an impact returned by [`Self::resolve_impacts`], now that the
    /// state is at its instant. A slow one is inelastic: the bodies come to rest in contact.
    pub fn apply(&mut self, impact: Impact, state: &mut State, forces: &ForceModel, h: f64) {
        let (_, normal, approach) = self.measure(impact, state);
        if approach <= 0.0 {
            return;
        }
        let restitution = self.restitution_at(impact, approach, self.resting_speed(h));
        let applied = Applied {
            time: h,
            impact,
            approach,
            restitution,
            grip: Grip::default(),
            kick: (DVec2::ZERO, DVec2::ZERO),
            tied: None,
        };
        self.strike(applied, normal, state, forces);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn path(from: f64, start: (DVec2, DVec2), end: (DVec2, DVec2)) -> Path {
        Path {
            from,
            start,
            end,
            kick: DVec2::ZERO,
            kick_moment: DVec2::ZERO,
        }
    }

    /// The largest distance between two paths over `from..=h`, sampled at 3,001 instants
    /// (s = 1/3, where a start tangent's basis function peaks, among them).
    fn sampled_apart(new: &Path, old: &Path, h: f64) -> f64 {
        (0..=3000)
            .map(|k| {
                let t = new.from + (h - new.from) * f64::from(k) / 3000.0;
                new.at(t, h).0.distance(old.at(t, h).0)
            })
            .fold(0.0, f64::max)
    }

    /// `apart_from` bounds the distance of a restarted path from the old one on 2,000
    /// random pairs (the old path starting earlier, as a coupled path before an impact),
    /// and is exact where one term alone differs: only the end point (the bound is that
    /// distance) or only a tangent (4/27 of the span times it). A bound too small would
    /// keep a path that moved, and its impacts found on the old one.
    #[test]
    fn a_restarted_paths_distance_from_the_old_one_is_bounded_and_the_bound_is_tight() {
        let mut uniform = crate::testing::uniform(99);
        let mut random = move || uniform() * 2.0 - 1.0;
        let h = 1e-3;
        for _ in 0..2000 {
            let mut vector = |scale: f64| DVec2::new(random(), random()) * scale;
            let old = path(0.0, (vector(1.0), vector(3.0)), (vector(1.0), vector(3.0)));
            let from = (vector(1.0).x * 0.5 + 0.5) * h;
            let new = path(
                from,
                (old.at(from, h).0 + vector(1e-4), vector(3.0)),
                (vector(1.0), vector(3.0)),
            );
            let (bound, apart) = (new.apart_from(&old, h), sampled_apart(&new, &old, h));
            assert!(
                apart <= bound * (1.0 + 1e-12),
                "{apart} apart, bound {bound}"
            );
        }
        let from = 4e-4;
        let old = path(
            0.0,
            (DVec2::new(0.1, 0.2), DVec2::new(1.0, -2.0)),
            (DVec2::new(0.3, -0.1), DVec2::new(0.5, 0.5)),
        );
        let on_old = |t| old.at(t, h);
        let shifted_end = path(
            from,
            on_old(from),
            (on_old(h).0 + DVec2::new(3e-5, -4e-5), on_old(h).1),
        );
        let turned = path(
            from,
            (on_old(from).0, on_old(from).1 + DVec2::new(0.6, 0.8)),
            on_old(h),
        );
        let turned_at_end = path(
            from,
            on_old(from),
            (on_old(h).0, on_old(h).1 - DVec2::new(0.8, 0.6)),
        );
        for (new, exact) in [
            (shifted_end, 5e-5),
            (turned, 4.0 / 27.0 * (h - from)),
            (turned_at_end, 4.0 / 27.0 * (h - from)),
        ] {
            let (bound, apart) = (new.apart_from(&old, h), sampled_apart(&new, &old, h));
            assert!(
                (bound - exact).abs() <= 1e-9 * exact,
                "bound {bound}, exactly {exact}"
            );
            assert!(
                (apart - exact).abs() <= 1e-6 * exact,
                "{apart} apart, exactly {exact}"
            );
        }
    }
}
