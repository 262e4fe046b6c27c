//! Which particles could touch: a uniform grid, so finding candidate pairs costs O(n)
//! instead of O(n²), built over fat boxes that are carried from step to step
//! ([`Proxies`]), so a step whose particles stay inside them costs a containment test
//! per particle.
//!
//! Each particle's box (its swept path, grown by its radius) is entered once, in the cell
//! of its lower-left corner; the cell is at least as large as the box, so a box can only
//! overlap boxes entered in its own cell or the eight around it. The grid is dense over
//! the boxes' extent and filled by a counting sort (two passes, no comparison sort), and
//! each particle's partners are collected from its 3 × 3 cells, so the pairs come out in
//! ascending order with no sort of the whole list: the output, and so the whole
//! simulation, is deterministic. The cell size follows the typical box (the largest box
//! up to twice the median), so one huge or fast particle does not make every cell huge:
//! a box larger than a cell is instead tested against every other box. The grid holds at most about
//! four cells per particle; a sparse scene gets larger cells, which costs tests, never
//! misses a pair.
//!
//! Box2D and Rapier keep a dynamic tree (or sweep-and-prune lists) of fat boxes from
//! step to step; here the fat boxes are carried the same way, over a grid instead of a
//! tree, which for balls of similar size is simpler and as fast. (Rebuilding the grid
//! every step costs a large share of a settling pile's step: docs/performance.md.)

#![expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "u32 particle indices, as in the contacts module; cell indices of finite boxes, clamped to the grid"
)]

use glam::DVec2;

use super::{larger, smaller};
use crate::parallel::Workers;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Aabb {
    pub min: DVec2,
    pub max: DVec2,
}

impl Aabb {
    /// The box of `points`, grown by `margin` on every side.
    pub fn around(points: &[DVec2], margin: f64) -> Self {
        // Comparisons, not `DVec2::min`/`max`: those are calls in WebAssembly (see
        // `resting::sweep`), and every particle's path box is built here every step.
        let (mut min, mut max) = (points[0], points[0]);
        for p in &points[1..] {
            if p.x < min.x {
                min.x = p.x;
            } else if p.x > max.x {
                max.x = p.x;
            }
            if p.y < min.y {
                min.y = p.y;
            } else if p.y > max.y {
                max.y = p.y;
            }
        }
        Self {
            min: min - DVec2::splat(margin),
            max: max + DVec2::splat(margin),
        }
    }

    /// Whether this box lies inside `outer` without touching its sides (false when
    /// either is not finite).
    #[expect(
        clippy::needless_bitwise_bool,
        reason = "no branches, as in `overlaps`"
    )]
    pub fn strictly_inside(&self, outer: &Self) -> bool {
        (self.min.x > outer.min.x)
            & (self.min.y > outer.min.y)
            & (self.max.x < outer.max.x)
            & (self.max.y < outer.max.y)
    }

    #[expect(
        clippy::needless_bitwise_bool,
        reason = "no branches: measured +10 % on the 1,000-ball pit"
    )]
    pub fn overlaps(&self, other: &Self) -> bool {
        // `&`, not `&&`: four comparisons and no branch (the broad phase's filters run
        // this on every candidate pair, twice a step, and the outcome is hard to predict).
        (self.min.x <= other.max.x)
            & (other.min.x <= self.max.x)
            & (self.min.y <= other.max.y)
            & (other.min.y <= self.max.y)
    }
}

/// Reusable buffers.
#[derive(Clone, Debug, Default)]
pub(crate) struct BroadPhase {
    grid: Grid,
    /// Particles whose box is larger than a cell (or not finite), ascending.
    oversized: Vec<u32>,
    pairs: Vec<(u32, u32)>,
    extents: Vec<f64>,
    /// Scratch: the pairs with the oversized boxes' merged in.
    merged: Vec<(u32, u32)>,
}

/// The dense grid of the last [`BroadPhase::pairs`]: cell `c` holds the particles
/// `members[first[c]..first[c + 1]]`, ascending.
#[derive(Clone, Debug, Default)]
struct Grid {
    origin: DVec2,
    cell: f64,
    columns: usize,
    rows: usize,
    first: Vec<u32>,
    members: Vec<u32>,
    /// Each particle's cell, or `None` for an oversized one.
    cell_of: Vec<Option<u32>>,
}

impl Grid {
    /// The cell's column and row of a point, clamped to the grid.
    fn locate(&self, p: DVec2) -> (usize, usize) {
        // Truncation is the floor once negatives are clamped to 0 (and NaN goes to 0):
        // `f64::floor` is a call into libm on baseline x86-64, and this runs twice per
        // particle per step.
        let c = (p - self.origin) / self.cell;
        let c = DVec2::new(larger(c.x, 0.0), larger(c.y, 0.0));
        (
            (c.x as usize).min(self.columns - 1),
            (c.y as usize).min(self.rows - 1),
        )
    }

    fn members(&self, column: usize, row: usize) -> &[u32] {
        let c = row * self.columns + column;
        &self.members[self.first[c] as usize..self.first[c + 1] as usize]
    }

    /// Fills the grid with the boxes that fit a cell, by a counting sort on their cells.
    fn fill(&mut self, boxes: &[Aabb], oversized: &mut Vec<u32>) {
        self.cell_of.clear();
        oversized.clear();
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for (i, b) in boxes.iter().enumerate() {
            let size = b.max - b.min;
            if b.min.is_finite() && b.max.is_finite() && size.max_element() <= self.cell {
                lo = DVec2::new(smaller(b.min.x, lo.x), smaller(b.min.y, lo.y));
                hi = DVec2::new(larger(b.min.x, hi.x), larger(b.min.y, hi.y));
                self.cell_of.push(Some(0));
            } else {
                oversized.push(i as u32);
                self.cell_of.push(None);
            }
        }
        let fitting = boxes.len() - oversized.len();
        if fitting == 0 {
            (self.columns, self.rows) = (1, 1);
            self.first.clear();
            self.first.extend([0, 0]);
            self.members.clear();
            return;
        }
        // At most about four cells per particle: a sparse scene gets larger cells. The
        // sizes are worked out in f64, so boxes near the ends of the f64 range (whose
        // span overflows) get one cell for all rather than a wrapped-around count.
        let span = hi - lo;
        let limit = (4 * fitting + 64) as f64;
        self.cell = self.cell.max((span.x * span.y / limit).sqrt());
        self.origin = lo;
        let dimensions = |cell: f64| ((span.x / cell).floor() + 1.0, (span.y / cell).floor() + 1.0);
        let (mut columns, mut rows) = dimensions(self.cell);
        if !(span.is_finite() && self.cell.is_finite()) {
            (self.cell, columns, rows) = (f64::INFINITY, 1.0, 1.0);
        }
        while columns * rows > 2.0 * limit {
            self.cell *= 2.0;
            (columns, rows) = dimensions(self.cell);
        }
        (self.columns, self.rows) = (columns as usize, rows as usize);
        let cells = self.columns * self.rows;
        self.first.clear();
        self.first.resize(cells + 1, 0);
        for (i, b) in boxes.iter().enumerate() {
            if self.cell_of[i].is_some() {
                let (column, row) = self.locate(b.min);
                let c = row * self.columns + column;
                self.cell_of[i] = Some(c as u32);
                self.first[c + 1] += 1;
            }
        }
        for c in 0..cells {
            self.first[c + 1] += self.first[c];
        }
        self.members.clear();
        self.members.resize(fitting, 0);
        // Entered in particle order, so each cell's members are ascending.
        let mut next = self.first.clone();
        for (i, c) in self.cell_of.iter().enumerate() {
            if let Some(c) = *c {
                let slot = &mut next[c as usize];
                self.members[*slot as usize] = i as u32;
                *slot += 1;
            }
        }
    }
}

impl BroadPhase {
    /// Candidate pairs (i < j) whose boxes overlap, in ascending order; `skip(i, j)`
    /// excludes pairs that need no test (two fixed particles).
    pub fn pairs(
        &mut self,
        boxes: &[Aabb],
        skip: impl Fn(usize, usize) -> bool + Sync,
        workers: &Workers,
    ) -> &[(u32, u32)] {
        self.pairs.clear();
        if boxes.len() < 2 {
            self.grid.cell_of.clear();
            self.oversized.clear();
            return &self.pairs;
        }
        self.extents.clear();
        self.extents.extend(
            boxes
                .iter()
                .map(|b| (b.max - b.min).max_element())
                .filter(|e| e.is_finite()),
        );
        let typical = if self.extents.is_empty() {
            1.0
        } else {
            let middle = self.extents.len() / 2;
            *self
                .extents
                .select_nth_unstable_by(middle, f64::total_cmp)
                .1
        };
        // The smallest cell that holds every box up to twice the typical size: as
        // small as possible, since a particle is tested against all of its 3 × 3 cells.
        let cell = self
            .extents
            .iter()
            .copied()
            .filter(|&e| e <= 2.0 * typical)
            .fold(typical, f64::max);
        self.grid.cell = cell.max(1e-9);
        self.grid.fill(boxes, &mut self.oversized);
        let grid = &self.grid;
        // Each particle's partners in the grid are found on their own, so ranges of
        // particles can be searched on different threads and joined in order.
        workers.collect_into(boxes.len(), &mut self.pairs, |range, pairs| {
            let mut partners = Vec::new();
            for i in range {
                let Some(c) = grid.cell_of[i] else {
                    continue; // oversized: below
                };
                partners.clear();
                let (column, row) = (c as usize % grid.columns, c as usize / grid.columns);
                let bi = &boxes[i];
                // Tested first, sorted after: in a dense cluster a particle's 3 × 3
                // cells hold ten times as many boxes as overlap its own, and sorting
                // them all took a fifth of a step.
                for y in row.saturating_sub(1)..=(row + 1).min(grid.rows - 1) {
                    for x in column.saturating_sub(1)..=(column + 1).min(grid.columns - 1) {
                        // A plain loop: as an iterator's filter the test was a call
                        // through a reference to the closure, 2.7 times as slow in
                        // WebAssembly as natively (V8's profile of `benches/wasm`).
                        for &j in grid.members(x, y) {
                            if j as usize > i
                                && bi.overlaps(&boxes[j as usize])
                                && !skip(i, j as usize)
                            {
                                partners.push(j);
                            }
                        }
                    }
                }
                partners.sort_unstable();
                pairs.extend(partners.iter().map(|&j| (i as u32, j)));
            }
        });
        self.pair_oversized(boxes, &skip);
        &self.pairs
    }

    /// Adds the pairs of the oversized boxes (a star flung out of a cluster sweeps a box
    /// hundreds of cells wide), each found by a query over the cells it covers rather
    /// than against every box, and sorts the pairs again.
    fn pair_oversized(&mut self, boxes: &[Aabb], skip: &impl Fn(usize, usize) -> bool) {
        if self.oversized.is_empty() {
            return;
        }
        let is_oversized = |j: usize| self.grid.cell_of[j].is_none();
        let mut found = Vec::new();
        let mut candidates = Vec::new();
        for &o in &self.oversized {
            let o = o as usize;
            candidates.clear();
            self.query(&boxes[o], &mut candidates);
            candidates.sort_unstable();
            candidates.dedup();
            for &j in &candidates {
                let j = j as usize;
                // Two oversized boxes are paired from the first.
                if j == o || (j < o && is_oversized(j)) {
                    continue;
                }
                let (a, b) = (o.min(j), o.max(j));
                if boxes[o].overlaps(&boxes[j]) && !skip(a, b) {
                    found.push((a as u32, b as u32));
                }
            }
        }
        // The grid's pairs are ascending already: the few found here are sorted and
        // merged in, rather than every pair sorted again (a sixth of a step of a
        // 100,000-body cluster, on one thread whatever the number).
        found.sort_unstable();
        merge(&self.pairs, &found, &mut self.merged);
        std::mem::swap(&mut self.pairs, &mut self.merged);
    }

    /// Every particle entered by the last [`Self::pairs`] whose box could overlap
    /// `query`, appended to `out` (possibly more than once); a superset of those whose
    /// boxes overlap.
    pub fn query(&self, query: &Aabb, out: &mut Vec<u32>) {
        out.extend_from_slice(&self.oversized);
        let grid = &self.grid;
        if grid.members.is_empty() {
            return;
        }
        if !query.min.is_finite() || !query.max.is_finite() {
            out.extend_from_slice(&grid.members);
            return;
        }
        // A member's box starts in its cell and is at most a cell wide: those starting
        // up to a cell below and left of the query can reach into it.
        let (lo, hi) = (
            grid.locate(query.min - DVec2::splat(grid.cell)),
            grid.locate(query.max),
        );
        for y in lo.1..=hi.1 {
            for x in lo.0..=hi.0 {
                out.extend_from_slice(grid.members(x, y));
            }
        }
    }
}

/// Two ascending lists of pairs as one ascending list, in `out`.
fn merge(a: &[(u32, u32)], b: &[(u32, u32)], out: &mut Vec<(u32, u32)>) {
    out.clear();
    out.reserve(a.len() + b.len());
    let (mut a, mut b) = (a.iter().peekable(), b.iter().peekable());
    while let (Some(&&x), Some(&&y)) = (a.peek(), b.peek()) {
        if x < y {
            out.push(x);
            a.next();
        } else {
            out.push(y);
            b.next();
        }
    }
    out.extend(a);
    out.extend(b);
}

/// The broad phase carried from step to step, as Box2D's and Rapier's are: each particle
/// has a *fat* box, its box grown by a margin, and the candidate pairs are those whose fat
/// boxes overlap. A step asks [`Self::update`] with its boxes; while every box stays
/// inside its fat box the candidates stand as they are and the grid is not touched. A
/// particle that leaves its fat box gets a new one and its pairs are found again against
/// the grid (and the other particles that moved since it was built); when more than an
/// eighth of the particles have moved, the grid is rebuilt.
///
/// The candidates are a superset of the pairs whose boxes overlap, found from fat boxes
/// that depend on the history of the run; callers filter them with the boxes of the step,
/// so what they keep does not depend on that history.
#[derive(Clone, Debug, Default)]
pub(crate) struct Proxies {
    fat: Vec<Aabb>,
    broad: BroadPhase,
    /// Pairs (i < j) whose fat boxes overlap, ascending.
    pairs: Vec<(u32, u32)>,
    /// Particles whose fat box changed since the grid was built, and the same as flags.
    moved: Vec<u32>,
    is_moved: Vec<bool>,
    /// Scratch: the particles whose fat box changes in this update, as flags.
    is_new: Vec<bool>,
    new_pairs: Vec<(u32, u32)>,
    merged: Vec<(u32, u32)>,
    partners: Vec<u32>,
}

impl Aabb {
    /// Whether `other` lies inside this box (false when either is not finite).
    pub fn contains(&self, other: &Self) -> bool {
        self.min.x <= other.min.x
            && self.min.y <= other.min.y
            && other.max.x <= self.max.x
            && other.max.y <= self.max.y
    }

    fn grown(&self, margin: f64) -> Self {
        Self {
            min: self.min - DVec2::splat(margin),
            max: self.max + DVec2::splat(margin),
        }
    }
}

impl Proxies {
    /// Candidate pairs (i < j) for `boxes`, ascending: every pair whose boxes overlap is
    /// among them, and `skip(i, j)` pairs are not. A box that left its fat box gets a new
    /// one, grown by `margin(i)` metres.
    pub fn update(
        &mut self,
        boxes: &[Aabb],
        margin: impl Fn(usize) -> f64,
        skip: impl Fn(usize, usize) -> bool + Sync,
        workers: &Workers,
    ) -> &[(u32, u32)] {
        let n = boxes.len();
        if self.fat.len() != n {
            self.fat.clear();
            self.fat
                .extend(boxes.iter().enumerate().map(|(i, b)| b.grown(margin(i))));
            self.rebuild(skip, workers);
            return &self.pairs;
        }
        let mut any = false;
        for (i, b) in boxes.iter().enumerate() {
            if !self.fat[i].contains(b) {
                self.fat[i] = b.grown(margin(i));
                self.is_new[i] = true;
                if !self.is_moved[i] {
                    self.is_moved[i] = true;
                    self.moved.push(i as u32);
                }
                any = true;
            }
        }
        if !any {
            return &self.pairs;
        }
        if self.moved.len() > n / 8 {
            self.rebuild(skip, workers);
        } else {
            self.refresh(&skip);
        }
        &self.pairs
    }

    /// Builds the grid and every pair from the fat boxes.
    fn rebuild(&mut self, skip: impl Fn(usize, usize) -> bool + Sync, workers: &Workers) {
        let n = self.fat.len();
        self.broad.pairs(&self.fat, skip, workers);
        // Taken, not copied: the broad phase builds its list anew each time.
        std::mem::swap(&mut self.pairs, &mut self.broad.pairs);
        self.moved.clear();
        self.is_moved.clear();
        self.is_moved.resize(n, false);
        self.is_new.clear();
        self.is_new.resize(n, false);
    }

    /// Finds the pairs of the particles whose fat box just changed (flagged `is_new`)
    /// again: against the grid, where the particles that have not moved since it was
    /// built are entered as they are, and against every particle that has moved.
    fn refresh(&mut self, skip: &impl Fn(usize, usize) -> bool) {
        let is_new = &self.is_new;
        self.pairs
            .retain(|&(i, j)| !is_new[i as usize] && !is_new[j as usize]);
        self.new_pairs.clear();
        for &p in &self.moved {
            let p = p as usize;
            if !self.is_new[p] {
                continue;
            }
            self.partners.clear();
            self.broad.query(&self.fat[p], &mut self.partners);
            self.partners.extend_from_slice(&self.moved);
            for &q in &self.partners {
                let q = q as usize;
                // A moved particle may sit in the grid where it was: its fat box now
                // is the one tested.
                if q == p || !self.fat[p].overlaps(&self.fat[q]) || skip(p.min(q), p.max(q)) {
                    continue;
                }
                self.new_pairs.push((p.min(q) as u32, p.max(q) as u32));
            }
        }
        self.new_pairs.sort_unstable();
        self.new_pairs.dedup();
        merge(&self.pairs, &self.new_pairs, &mut self.merged);
        std::mem::swap(&mut self.pairs, &mut self.merged);
        for &p in &self.moved {
            self.is_new[p as usize] = false;
        }
    }

    /// Particle `p`'s fat box, as of the last update.
    pub fn fat(&self, p: usize) -> &Aabb {
        &self.fat[p]
    }

    /// Appends to `out` the particles whose fat boxes overlap `query` (possibly more
    /// than once), so every particle whose box of the last update does.
    pub fn query(&self, query: &Aabb, out: &mut Vec<u32>) {
        let start = out.len();
        self.broad.query(query, out);
        out.extend_from_slice(&self.moved);
        let mut kept = start;
        for k in start..out.len() {
            let q = out[k];
            if self.fat[q as usize].overlaps(query) {
                out[kept] = q;
                kept += 1;
            }
        }
        out.truncate(kept);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Boxes near both ends of the f64 range (a span that overflows), and boxes over a
    /// span of 1e200 across by 1 high (a column count beyond usize): the same pairs as a
    /// brute-force search. (A ball at 1e300 m/s once made the grid index out of bounds;
    /// validation now refuses such a speed, and the grid works out its sizes in f64, with
    /// one cell for all when the span overflows.)
    #[test]
    fn boxes_at_the_ends_of_the_range_are_paired_without_overflow() {
        let at = |x: f64, y: f64| Aabb {
            min: DVec2::new(x, y),
            max: DVec2::new(x + x.abs() * 1e-3 + 1.0, y + 1.0),
        };
        let overflowing = [at(-1e308, 0.0), at(1e308, 0.0), at(0.0, 0.0), at(0.0, 0.5)];
        let wide = [at(0.0, 0.0), at(1e200, 0.0), at(1e200, 0.5), at(0.0, 0.5)];
        for boxes in [&overflowing[..], &wide[..]] {
            let mut broad = BroadPhase::default();
            let found = broad.pairs(boxes, |_, _| false, &Workers::new(1)).to_vec();
            assert_eq!(found, brute_force(boxes));
        }
    }

    fn brute_force(boxes: &[Aabb]) -> Vec<(u32, u32)> {
        let mut expected = Vec::new();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                if boxes[i].overlaps(&boxes[j]) {
                    expected.push((i as u32, j as u32));
                }
            }
        }
        expected
    }

    /// Against the O(n²) answer on a cloud of boxes of mixed sizes; and every box that
    /// overlaps a query is among those the query returns.
    #[test]
    fn finds_exactly_the_overlapping_pairs() {
        let mut boxes = Vec::new();
        for i in 0..300_u32 {
            let angle = f64::from(i) * 2.399_963;
            let r = f64::from(i).sqrt() * 0.8;
            let size = if i % 97 == 0 {
                40.0
            } else {
                0.3 + f64::from(i % 7) * 0.2
            };
            let c = DVec2::new(r * angle.cos(), r * angle.sin());
            boxes.push(Aabb {
                min: c,
                max: c + DVec2::splat(size),
            });
        }
        let expected = brute_force(&boxes);
        let mut broad = BroadPhase::default();
        assert_eq!(
            broad.pairs(&boxes, |_, _| false, &Workers::default()),
            expected.as_slice(),
            "grid = brute force"
        );
        assert!(
            expected.len() > 100,
            "the test has overlaps to find: {}",
            expected.len()
        );
        let mut found = Vec::new();
        for (k, query) in boxes.iter().enumerate() {
            found.clear();
            broad.query(query, &mut found);
            for (j, other) in boxes.iter().enumerate() {
                if query.overlaps(other) {
                    assert!(found.contains(&(j as u32)), "query {k} misses box {j}");
                }
            }
        }
    }

    /// A sparse scene (clusters a million metres apart) gets larger cells, not a huge
    /// grid; a non-finite box is tested against everything; the answer stays exact.
    #[test]
    fn sparse_and_non_finite_boxes_are_exact_too() {
        let mut boxes = Vec::new();
        for cluster in 0..4_u32 {
            let centre = DVec2::new(f64::from(cluster) * 1e6, -f64::from(cluster) * 3e5);
            for i in 0..50_u32 {
                let c = centre + DVec2::new(f64::from(i % 7) * 0.15, f64::from(i / 7) * 0.15);
                boxes.push(Aabb {
                    min: c,
                    max: c + DVec2::splat(0.2),
                });
            }
        }
        boxes.push(Aabb {
            min: DVec2::splat(f64::NEG_INFINITY),
            max: DVec2::splat(f64::INFINITY),
        });
        let expected = brute_force(&boxes);
        let mut broad = BroadPhase::default();
        assert_eq!(
            broad.pairs(&boxes, |_, _| false, &Workers::default()),
            expected.as_slice(),
            "grid = brute force"
        );
        assert!(
            broad.grid.first.len() < 4 * boxes.len() + 200,
            "the grid stays small: {} cells",
            broad.grid.first.len()
        );
    }

    /// Boxes that jitter, drift and jump over many updates: after each update the
    /// candidates, ascending and without repeats, include every overlapping pair (and
    /// skip the skipped), and a query finds every box that overlaps it. Both paths are
    /// taken: a few moved boxes (pairs found again) and many (the grid rebuilt).
    #[test]
    fn carried_pairs_always_cover_the_overlaps() {
        let n = 400_u32;
        let mut centres: Vec<DVec2> = (0..n)
            .map(|i| DVec2::new(f64::from(i % 20) * 0.25, f64::from(i / 20) * 0.25))
            .collect();
        let mut proxies = Proxies::default();
        let skip = |i: usize, j: usize| i.is_multiple_of(50) && j.is_multiple_of(50);
        let (mut refreshed, mut rebuilt) = (0, 0);
        for step in 0..200_u32 {
            for (i, c) in (0_u32..).zip(centres.iter_mut()) {
                let phase = f64::from(i * 7 + step * 13);
                // Most jitter a little; every 37th drifts; every few steps one jumps.
                *c += DVec2::new(phase.sin(), phase.cos()) * 1e-3;
                if i.is_multiple_of(37) {
                    *c += DVec2::new(0.01, -0.004);
                }
                if (i + step).is_multiple_of(97) {
                    *c = DVec2::new(phase.sin().abs() * 5.0, phase.cos().abs() * 5.0);
                }
            }
            if step % 50 == 49 {
                for c in &mut centres {
                    *c += DVec2::splat(0.2); // everything moves: a rebuild
                }
            }
            let boxes: Vec<Aabb> = centres.iter().map(|&c| Aabb::around(&[c], 0.13)).collect();
            let before = (proxies.moved.len(), proxies.fat.len());
            let candidates = proxies
                .update(&boxes, |_| 0.02, skip, &Workers::new(1))
                .to_vec();
            if proxies.moved.is_empty() && before.1 == boxes.len() && step % 50 == 49 {
                rebuilt += 1;
            } else if proxies.moved.len() > before.0 {
                refreshed += 1;
            }
            assert!(
                candidates.windows(2).all(|w| w[0] < w[1]),
                "ascending, once each"
            );
            let expected: Vec<(u32, u32)> = brute_force(&boxes)
                .into_iter()
                .filter(|&(i, j)| !skip(i as usize, j as usize))
                .collect();
            let kept: Vec<(u32, u32)> = candidates
                .iter()
                .copied()
                .filter(|&(i, j)| boxes[i as usize].overlaps(&boxes[j as usize]))
                .collect();
            assert_eq!(kept, expected, "step {step}");
            for (k, query) in boxes.iter().enumerate().step_by(23) {
                let mut found = Vec::new();
                proxies.query(query, &mut found);
                for (j, other) in boxes.iter().enumerate() {
                    if query.overlaps(other) {
                        assert!(
                            found.contains(&(j as u32)),
                            "step {step}: query {k} misses {j}"
                        );
                    }
                }
            }
        }
        assert!(
            refreshed > 50 && rebuilt >= 3,
            "both paths taken: {refreshed} refreshed, {rebuilt} rebuilt"
        );
    }
}
