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
    Applied, Contacts, Impact, TOUCHING, fat_margin, half_thickness, particles_of, velocity_changes,
};
use crate::forces::ForceModel;
use crate::profile::{Profiler, Stage};
use crate::state::State;

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
    neighbours: Vec<u32>,
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
        self.search.queue.extend(found.drain(..).map(Reverse));

        let mut interruption = None;
        let mut budget = 20 * n + 100;
        while let Some(Reverse(event)) = self.search.queue.pop() {
            let (first, second) = particles_of(event.impact);
            if (
                self.search.versions[first],
                second.map_or(0, |j| self.search.versions[j]),
            ) != event.versions
            {
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
            self.search.queue.extend(found.drain(..).map(Reverse));
        }
        for &p in &self.search.changed {
            let (x, v) = self.search.paths[p as usize].at(h, h);
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
        self.search.paths.clear();
        self.search.paths.extend((0..n).map(|i| Path {
            start: (start.position[i], start.velocity[i]),
            end: (end.position[i], end.velocity[i]),
            kick: DVec2::ZERO,
            kick_moment: DVec2::ZERO,
        }));
        self.search.versions.clear();
        self.search.versions.resize(n, 0);
        for &p in &self.search.changed {
            self.search.is_changed[p as usize] = false;
        }
        self.search.is_changed.resize(n, false);
        self.search.changed.clear();
        self.search.escaped.clear();
        self.search.queue.clear();
        self.search.controls.clear();
        self.search
            .controls
            .extend(self.search.paths.iter().map(|path| path.after(0.0, h)));
        self.boxes.clear();
        self.boxes.extend(
            self.search
                .controls
                .iter()
                .zip(self.radius.iter())
                .map(|(controls, r)| Aabb::around(controls, *r)),
        );
    }

    /// The pairs whose swept boxes overlap and that do not touch, ascending.
    fn swept_candidates(&mut self, start: &State, h: f64, forces: &ForceModel) -> Vec<(u32, u32)> {
        // Touching pairs are the resting solver's: both lists are ascending, so one walk
        // through the touching list takes them out.
        let mut touching = self.touching.pairs.as_slice();
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
        let (xi, vi) = self.search.paths[first].at(event.time, h);
        let other = second.map(|j| self.search.paths[j].at(event.time, h));
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
            let path = &mut self.search.paths[p];
            path.kick += dv;
            path.kick_moment += dv * event.time;
            self.search.versions[p] += 1;
            if !self.search.is_changed[p] {
                self.search.is_changed[p] = true;
                self.search.changed.push(p as u32);
            }
        }
        for &(p, dv) in &moved {
            if dv == DVec2::ZERO || forces.is_fixed(p) {
                continue;
            }
            let bounds = Aabb::around(&self.search.paths[p].after(event.time, h), self.radius[p]);
            if !self.proxies.fat(p).contains(&bounds) && !self.search.escaped.contains(&(p as u32))
            {
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
                    || (forces.is_fixed(p) && forces.is_fixed(q))
                    || self.touching.by_particle.contains(p, q as u32)
                {
                    continue;
                }
                let pair = (p.min(q), p.max(q));
                if let Some(event) = self.search_pair(pair.0, pair.1, event.time, h) {
                    found.push(event);
                }
            }
            self.search.neighbours = neighbours;
            self.search_obstacles(p, event.time, h, found);
        }
    }

    /// The control points of `p`'s path from `from` seconds to the end of the step.
    fn path_after(&self, p: usize, from: f64, h: f64) -> [DVec2; 4] {
        if from == 0.0 && !self.search.is_changed[p] {
            self.search.controls[p]
        } else {
            self.search.paths[p].after(from, h)
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
            versions: (self.search.versions[i], self.search.versions[j]),
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
                    .touching
                    .surfaces
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
                    versions: (self.search.versions[p], 0),
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
        let applied = Applied {
            time: h,
            impact,
            approach,
            restitution,
        };
        self.strike(applied, normal, state, forces);
    }
}
