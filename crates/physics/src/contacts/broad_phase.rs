//! Which particles could touch: a uniform grid rebuilt every step, so finding candidate
//! pairs costs O(n log n) instead of O(n²).
//!
//! Every particle's box (its swept path, grown by its radius) is entered in each grid cell
//! it overlaps; the entries are sorted by cell, and the particles sharing a cell are
//! candidates. A pair sharing several cells is reported once, from the first cell of the
//! overlap of their boxes. Sorting rather than hashing keeps the output order, and so
//! the whole simulation, deterministic. The cell size follows the typical box, so one
//! huge or fast particle does not make every cell huge: a box covering more than
//! `MAX_CELLS` cells is instead tested against every other box.

#![expect(
    clippy::cast_possible_truncation,
    reason = "u32 particle indices, as in the contacts module"
)]

use glam::DVec2;

/// Boxes covering more cells than this are tested against everything.
const MAX_CELLS: i64 = 64;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Aabb {
    pub min: DVec2,
    pub max: DVec2,
}

impl Aabb {
    /// The box of `points`, grown by `margin` on every side.
    pub fn around(points: &[DVec2], margin: f64) -> Self {
        let (mut min, mut max) = (points[0], points[0]);
        for p in &points[1..] {
            min = min.min(*p);
            max = max.max(*p);
        }
        Self {
            min: min - DVec2::splat(margin),
            max: max + DVec2::splat(margin),
        }
    }

    pub fn overlaps(&self, other: &Self) -> bool {
        self.min.x <= other.max.x
            && other.min.x <= self.max.x
            && self.min.y <= other.max.y
            && other.min.y <= self.max.y
    }
}

/// Reusable buffers.
#[derive(Clone, Debug, Default)]
pub(crate) struct BroadPhase {
    /// (cell key, particle), sorted.
    entries: Vec<(u64, u32)>,
    oversized: Vec<u32>,
    pairs: Vec<(u32, u32)>,
    extents: Vec<f64>,
    cell: f64,
}

impl BroadPhase {
    /// Candidate pairs (i < j) whose boxes overlap, in ascending order; `skip(i, j)`
    /// excludes pairs that need no test (two fixed particles).
    pub fn pairs(&mut self, boxes: &[Aabb], skip: impl Fn(usize, usize) -> bool) -> &[(u32, u32)] {
        self.entries.clear();
        self.oversized.clear();
        self.pairs.clear();
        if boxes.len() < 2 {
            return &self.pairs;
        }
        self.extents.clear();
        self.extents
            .extend(boxes.iter().map(|b| (b.max - b.min).max_element()));
        let middle = self.extents.len() / 2;
        let cell = self
            .extents
            .select_nth_unstable_by(middle, f64::total_cmp)
            .1
            .max(1e-9);
        self.cell = cell;
        let cell_of = |p: DVec2| cell_of(p, cell);
        for (i, b) in boxes.iter().enumerate() {
            let (lo, hi) = (cell_of(b.min), cell_of(b.max));
            if (hi.0 - lo.0 + 1).saturating_mul(hi.1 - lo.1 + 1) > MAX_CELLS
                || !b.min.is_finite()
                || !b.max.is_finite()
            {
                self.oversized.push(i as u32);
                continue;
            }
            for x in lo.0..=hi.0 {
                for y in lo.1..=hi.1 {
                    self.entries.push((key(x, y), i as u32));
                }
            }
        }
        self.entries.sort_unstable();
        let mut start = 0;
        while start < self.entries.len() {
            let (cell_key, _) = self.entries[start];
            let mut end = start + 1;
            while end < self.entries.len() && self.entries[end].0 == cell_key {
                end += 1;
            }
            for a in start..end {
                for b in a + 1..end {
                    let (i, j) = (self.entries[a].1 as usize, self.entries[b].1 as usize);
                    let (bi, bj) = (&boxes[i], &boxes[j]);
                    // Report from the first cell of the overlap only.
                    let first = cell_of(bi.min.max(bj.min));
                    if key(first.0, first.1) == cell_key && bi.overlaps(bj) && !skip(i, j) {
                        self.pairs.push((i as u32, j as u32));
                    }
                }
            }
            start = end;
        }
        for &big in &self.oversized {
            for (other, b) in boxes.iter().enumerate() {
                let big = big as usize;
                let already = self.oversized.contains(&(other as u32)) && other < big;
                if other != big
                    && !already
                    && b.overlaps(&boxes[big])
                    && !skip(big.min(other), big.max(other))
                {
                    self.pairs
                        .push((big.min(other) as u32, big.max(other) as u32));
                }
            }
        }
        self.pairs.sort_unstable();
        &self.pairs
    }

    /// Every particle entered by the last [`Self::pairs`] whose cells `query` touches,
    /// appended to `out` (possibly more than once); a superset of those whose boxes overlap.
    pub fn query(&self, query: &Aabb, out: &mut Vec<u32>) {
        out.extend_from_slice(&self.oversized);
        if self.entries.is_empty() {
            return;
        }
        let (lo, hi) = (cell_of(query.min, self.cell), cell_of(query.max, self.cell));
        if (hi.0 - lo.0 + 1).saturating_mul(hi.1 - lo.1 + 1) > MAX_CELLS * MAX_CELLS
            || !query.min.is_finite()
            || !query.max.is_finite()
        {
            out.extend(self.entries.iter().map(|e| e.1));
            return;
        }
        for x in lo.0..=hi.0 {
            let (first, last) = (key(x, lo.1), key(x, hi.1));
            let start = self.entries.partition_point(|e| e.0 < first);
            for entry in &self.entries[start..] {
                if entry.0 > last {
                    break;
                }
                out.push(entry.1);
            }
        }
    }
}

/// One sortable number per cell, ordered as (x, y): coordinates clamped to i32 (cells that
/// far out only merge, which costs tests, never misses a pair) and offset to unsigned.
fn key(x: i64, y: i64) -> u64 {
    let clamp = |c: i64| {
        (c.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) - i64::from(i32::MIN)).cast_unsigned()
    };
    (clamp(x) << 32) | clamp(y)
}

#[expect(
    clippy::cast_possible_truncation,
    reason = "cell indices of finite boxes; saturating casts are harmless"
)]
fn cell_of(p: DVec2, cell: f64) -> (i64, i64) {
    ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the O(n²) answer on a cloud of boxes of mixed sizes.
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
        let mut expected = Vec::new();
        for i in 0..boxes.len() {
            for j in i + 1..boxes.len() {
                if boxes[i].overlaps(&boxes[j]) {
                    expected.push((i as u32, j as u32));
                }
            }
        }
        let mut broad = BroadPhase::default();
        assert_eq!(
            broad.pairs(&boxes, |_, _| false),
            expected.as_slice(),
            "grid = brute force"
        );
        assert!(
            expected.len() > 100,
            "the test has overlaps to find: {}",
            expected.len()
        );
    }
}
