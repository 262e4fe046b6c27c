//! The resting solver's pair rows column by column, in the order the sweeps take them,
//! and the sweeps over them: four rows at a time in AVX2 where the processor has it, two
//! in WebAssembly's 128-bit vectors, one at a time elsewhere.
//!
//! Rows of one level of the [`super::Schedule`] have no particle in common, so several
//! of them can be taken at once: their particles' velocities (or positions) gathered
//! into vectors, x in one and y in another, each lane doing the operations one row alone
//! does, in the same order (no fused multiply-add), and scattered back. The result is
//! the bits of taking the rows one at a time, and each sweep reports the same largest
//! change (`the_schedule_gives_the_bits_of_ascending_order`,
//! `a_sweep_in_lanes_measures_falling_impulses`,
//! `position_sweeps_in_lanes_give_the_bits_of_one_row_at_a_time`; in the browser, the
//! end-to-end test's ball pit against the desktop's); a level's last rows, fewer than a
//! vector, are taken one at a time. Each row is built straight into its place in the
//! columns (the schedule is found first, from the touching lists).
//!
//! Why lanes: a settled pile's velocity sweeps are most of the resting solver's time,
//! and four rows at once cut them by about a quarter (docs/performance.md). Columns
//! swept one row at a time would be slower than rows, so the lanes are what pays.

// pulp compiles `with_simd` once per instruction set, and what it calls gets that
// instruction set only when inlined into it.
#![expect(
    clippy::inline_always,
    reason = "the lanes' helpers must inline into with_simd"
)]

use glam::DVec2;

use super::PairRow;

/// The pair rows, a column per field, in the schedule's order.
#[derive(Clone, Debug, Default)]
pub(super) struct PairColumns {
    /// The particles, i < j.
    pub i: Vec<u32>,
    pub j: Vec<u32>,
    /// The normal from i towards j.
    pub nx: Vec<f64>,
    pub ny: Vec<f64>,
    /// 1/m of each particle, 1/kg.
    pub wi: Vec<f64>,
    pub wj: Vec<f64>,
    /// The effective mass, kg (zero for a row left out), and the accumulated impulse,
    /// N·s: [`super::Accumulator`]'s.
    pub mass: Vec<f64>,
    pub impulse: Vec<f64>,
    /// [`PairRow`]'s overlap correction: `reach`, `bend`, `correction`.
    pub reach: Vec<f64>,
    pub bend: Vec<f64>,
    pub correction: Vec<f64>,
}

impl PairColumns {
    pub fn len(&self) -> usize {
        self.i.len()
    }

    /// Room for `n` rows (what is in them is left for [`Self::set`] to overwrite).
    pub fn resize(&mut self, n: usize) {
        self.i.resize(n, 0);
        self.j.resize(n, 0);
        for column in [
            &mut self.nx,
            &mut self.ny,
            &mut self.wi,
            &mut self.wj,
            &mut self.mass,
            &mut self.impulse,
            &mut self.reach,
            &mut self.bend,
            &mut self.correction,
        ] {
            column.resize(n, 0.0);
        }
    }

    /// Row `k` becomes `row`.
    pub fn set(&mut self, k: usize, row: &PairRow) {
        self.i[k] = row.i;
        self.j[k] = row.j;
        self.nx[k] = row.normal.x;
        self.ny[k] = row.normal.y;
        self.wi[k] = row.inverse_mass_i;
        self.wj[k] = row.inverse_mass_j;
        self.mass[k] = row.solved.mass;
        self.impulse[k] = row.solved.impulse;
        self.reach[k] = row.reach;
        self.bend[k] = row.bend;
        self.correction[k] = row.correction;
    }

    fn normal(&self, k: usize) -> DVec2 {
        DVec2::new(self.nx[k], self.ny[k])
    }

    /// [`super::warm_start`] over the columns: a row approaching faster than
    /// `resting_speed` with a `struck` particle is left out (its mass zeroed); any other
    /// applies its impulse. Returns whether any did.
    pub fn warm_start(
        &mut self,
        velocity: &mut [DVec2],
        resting_speed: f64,
        struck: impl Fn(usize) -> bool,
    ) -> bool {
        let mut any = false;
        for k in 0..self.len() {
            let (i, j, normal) = (self.i[k] as usize, self.j[k] as usize, self.normal(k));
            if (velocity[i] - velocity[j]).dot(normal) > resting_speed && (struck(i) || struck(j)) {
                self.mass[k] = 0.0;
            }
            let last = self.impulse[k];
            if self.mass[k] == 0.0 || last <= 0.0 {
                self.impulse[k] = 0.0;
                continue;
            }
            let impulse = normal * last;
            velocity[i] -= impulse * self.wi[k];
            velocity[j] += impulse * self.wj[k];
            any = true;
        }
        any
    }

    /// One velocity sweep ([`super::sweep`]) over the rows, level by level (`levels`:
    /// where each ends): returns the largest change of an approach speed it made, or
    /// `None` when no row changed.
    pub fn sweep(&mut self, levels: &[u32], velocity: &mut [DVec2]) -> Option<f64> {
        #[cfg(target_arch = "x86_64")]
        if let Some(simd) = pulp::x86::V3::try_new() {
            return pulp::Simd::vectorize(
                simd,
                InLanes {
                    simd,
                    columns: self,
                    levels,
                    velocity,
                },
            );
        }
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            pairs_of_rows::sweep(self, levels, velocity)
        }
        #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
        {
            let _ = levels;
            let mut sums = Sums::default();
            self.rows_one_at_a_time(0..self.len(), velocity, &mut sums);
            sums.result()
        }
    }

    /// The sweep of rows `rows`, one at a time, into `sums`: the arithmetic of
    /// [`super::sweep`] for a [`PairRow`].
    #[inline(always)]
    fn rows_one_at_a_time(
        &mut self,
        rows: std::ops::Range<usize>,
        velocity: &mut [DVec2],
        sums: &mut Sums,
    ) {
        for k in rows {
            let (i, j, normal) = (self.i[k] as usize, self.j[k] as usize, self.normal(k));
            let approach = (velocity[i] - velocity[j]).dot(normal);
            let accumulated = self.impulse[k] + approach * self.mass[k];
            let accumulated = if accumulated > 0.0 { accumulated } else { 0.0 };
            let change = accumulated - self.impulse[k];
            let impulse = normal * change;
            velocity[i] -= impulse * self.wi[k];
            velocity[j] += impulse * self.wj[k];
            self.impulse[k] = accumulated;
            let changed_by = (change * (self.wi[k] + self.wj[k])).abs();
            if changed_by > sums.largest {
                sums.largest = changed_by;
            }
            sums.any |= change != 0.0;
        }
    }

    /// Pushes apart overlaps beyond the tolerance: one position sweep of
    /// [`super::RestingSolver::correct_overlaps`] over the pairs, level by level
    /// (`levels`, as for [`Self::sweep`]). Returns whether any moved.
    pub fn correct(&self, levels: &[u32], position: &mut [DVec2]) -> bool {
        #[cfg(target_arch = "x86_64")]
        if let Some(simd) = pulp::x86::V3::try_new() {
            return pulp::Simd::vectorize(
                simd,
                CorrectInLanes {
                    simd,
                    columns: self,
                    levels,
                    position,
                },
            );
        }
        #[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
        {
            pairs_of_rows::correct(self, levels, position)
        }
        #[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
        {
            let _ = levels;
            self.correct_one_at_a_time(0..self.len(), position)
        }
    }

    /// The position sweep of rows `rows`, one at a time: whether any moved.
    #[inline(always)]
    pub fn correct_one_at_a_time(
        &self,
        rows: std::ops::Range<usize>,
        position: &mut [DVec2],
    ) -> bool {
        let mut moved = false;
        for k in rows {
            let (i, j, normal) = (self.i[k] as usize, self.j[k] as usize, self.normal(k));
            let offset = position[j] - position[i];
            let across = normal.perp_dot(offset);
            let excess = self.reach[k] - (offset.dot(normal) + across * across * self.bend[k]);
            let excess = if excess > 0.0 { excess } else { 0.0 };
            let shift = normal * (excess * self.correction[k]);
            position[i] -= shift * self.wi[k];
            position[j] += shift * self.wj[k];
            moved |= excess * self.correction[k] > 0.0;
        }
        moved
    }
}

/// A position sweep four rows at a time, in AVX2.
#[cfg(target_arch = "x86_64")]
struct CorrectInLanes<'a> {
    simd: pulp::x86::V3,
    columns: &'a PairColumns,
    levels: &'a [u32],
    position: &'a mut [DVec2],
}

#[cfg(target_arch = "x86_64")]
impl pulp::WithSimd for CorrectInLanes<'_> {
    type Output = bool;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) -> bool {
        let CorrectInLanes {
            simd,
            columns: c,
            levels,
            position,
        } = self;
        let avx = simd.avx;
        let zero = avx._mm256_setzero_pd();
        let mut shifted = zero;
        let mut moved = false;
        let mut start = 0;
        for &end in levels {
            let end = end as usize;
            let mut k = start;
            while k + 4 <= end {
                let (i, j) = (four(&c.i, k), four(&c.j, k));
                let ((pix, piy), (pjx, pjy)) =
                    (gather(simd, i, position), gather(simd, j, position));
                let (nx, ny) = (load(simd, &c.nx, k), load(simd, &c.ny, k));
                let (ox, oy) = (avx._mm256_sub_pd(pjx, pix), avx._mm256_sub_pd(pjy, piy));
                // n.perp_dot(o) = nx oy − ny ox; o.dot(n) = ox nx + oy ny.
                let across =
                    avx._mm256_sub_pd(avx._mm256_mul_pd(nx, oy), avx._mm256_mul_pd(ny, ox));
                let along = avx._mm256_add_pd(avx._mm256_mul_pd(ox, nx), avx._mm256_mul_pd(oy, ny));
                let excess = avx._mm256_sub_pd(
                    load(simd, &c.reach, k),
                    avx._mm256_add_pd(
                        along,
                        avx._mm256_mul_pd(
                            avx._mm256_mul_pd(across, across),
                            load(simd, &c.bend, k),
                        ),
                    ),
                );
                let excess = avx._mm256_max_pd(excess, zero);
                let share = avx._mm256_mul_pd(excess, load(simd, &c.correction, k));
                let (sx, sy) = (avx._mm256_mul_pd(nx, share), avx._mm256_mul_pd(ny, share));
                let (wi, wj) = (load(simd, &c.wi, k), load(simd, &c.wj, k));
                scatter(
                    simd,
                    (
                        avx._mm256_sub_pd(pix, avx._mm256_mul_pd(sx, wi)),
                        avx._mm256_sub_pd(piy, avx._mm256_mul_pd(sy, wi)),
                    ),
                    i,
                    position,
                );
                scatter(
                    simd,
                    (
                        avx._mm256_add_pd(pjx, avx._mm256_mul_pd(sx, wj)),
                        avx._mm256_add_pd(pjy, avx._mm256_mul_pd(sy, wj)),
                    ),
                    j,
                    position,
                );
                // share > 0, one row's test.
                shifted = avx._mm256_or_pd(
                    shifted,
                    avx._mm256_cmp_pd::<{ core::arch::x86_64::_CMP_GT_OQ }>(share, zero),
                );
                k += 4;
            }
            moved |= c.correct_one_at_a_time(k..end, position);
            start = end;
        }
        moved | (avx._mm256_movemask_pd(shifted) != 0)
    }
}

/// What a sweep gathers: the largest change of an approach speed, and whether any row
/// changed.
#[derive(Default)]
struct Sums {
    largest: f64,
    any: bool,
}

impl Sums {
    fn result(&self) -> Option<f64> {
        self.any.then_some(self.largest)
    }
}

/// A sweep four rows at a time, in AVX2.
#[cfg(target_arch = "x86_64")]
struct InLanes<'a> {
    simd: pulp::x86::V3,
    columns: &'a mut PairColumns,
    levels: &'a [u32],
    velocity: &'a mut [DVec2],
}

#[cfg(target_arch = "x86_64")]
impl pulp::WithSimd for InLanes<'_> {
    type Output = Option<f64>;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) -> Option<f64> {
        let InLanes {
            simd,
            columns: c,
            levels,
            velocity,
        } = self;
        let avx = simd.avx;
        let (zero, sign) = (avx._mm256_setzero_pd(), avx._mm256_set1_pd(-0.0));
        let (mut largest, mut changed) = (zero, zero);
        let mut sums = Sums::default();
        let mut start = 0;
        for &end in levels {
            let end = end as usize;
            let mut k = start;
            while k + 4 <= end {
                let (i, j) = (four(&c.i, k), four(&c.j, k));
                let ((vix, viy), (vjx, vjy)) =
                    (gather(simd, i, velocity), gather(simd, j, velocity));
                let (nx, ny) = (load(simd, &c.nx, k), load(simd, &c.ny, k));
                let approach = avx._mm256_add_pd(
                    avx._mm256_mul_pd(avx._mm256_sub_pd(vix, vjx), nx),
                    avx._mm256_mul_pd(avx._mm256_sub_pd(viy, vjy), ny),
                );
                let before = load(simd, &c.impulse, k);
                let accumulated =
                    avx._mm256_add_pd(before, avx._mm256_mul_pd(approach, load(simd, &c.mass, k)));
                // max(a, 0) is `if a > 0 { a } else { 0 }` to the bit: −0 and NaN give
                // the second operand, +0.
                let accumulated = avx._mm256_max_pd(accumulated, zero);
                let change = avx._mm256_sub_pd(accumulated, before);
                let (px, py) = (avx._mm256_mul_pd(nx, change), avx._mm256_mul_pd(ny, change));
                let (wi, wj) = (load(simd, &c.wi, k), load(simd, &c.wj, k));
                scatter(
                    simd,
                    (
                        avx._mm256_sub_pd(vix, avx._mm256_mul_pd(px, wi)),
                        avx._mm256_sub_pd(viy, avx._mm256_mul_pd(py, wi)),
                    ),
                    i,
                    velocity,
                );
                scatter(
                    simd,
                    (
                        avx._mm256_add_pd(vjx, avx._mm256_mul_pd(px, wj)),
                        avx._mm256_add_pd(vjy, avx._mm256_mul_pd(py, wj)),
                    ),
                    j,
                    velocity,
                );
                let stored: [f64; 4] = pulp::cast(accumulated);
                c.impulse[k..k + 4].copy_from_slice(&stored);
                let changed_by = avx
                    ._mm256_andnot_pd(sign, avx._mm256_mul_pd(change, avx._mm256_add_pd(wi, wj)));
                largest = avx._mm256_max_pd(changed_by, largest);
                // change != 0, one row's test (a NaN counts).
                changed = avx._mm256_or_pd(
                    changed,
                    avx._mm256_cmp_pd::<{ core::arch::x86_64::_CMP_NEQ_UQ }>(change, zero),
                );
                k += 4;
            }
            c.rows_one_at_a_time(k..end, velocity, &mut sums);
            start = end;
        }
        let lanes: [f64; 4] = pulp::cast(largest);
        for lane in lanes {
            if lane > sums.largest {
                sums.largest = lane;
            }
        }
        sums.any |= avx._mm256_movemask_pd(changed) != 0;
        sums.result()
    }
}

/// The four values of `column` from `k` on.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn four<T: Copy + Default>(column: &[T], k: usize) -> [T; 4] {
    column[k..k + 4].try_into().unwrap_or_default()
}

/// The four values of `column` from `k` on, as a vector.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn load(_: pulp::x86::V3, column: &[f64], k: usize) -> core::arch::x86_64::__m256d {
    pulp::cast(four(column, k))
}

/// Four particles' velocities as their x in one vector and their y in another:
/// (x0 y0 x2 y2) and (x1 y1 x3 y3), then the lows and the highs of those.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn gather(
    simd: pulp::x86::V3,
    particles: [u32; 4],
    velocity: &[DVec2],
) -> (core::arch::x86_64::__m256d, core::arch::x86_64::__m256d) {
    use core::arch::x86_64::__m128d;
    let avx = simd.avx;
    let v: [__m128d; 4] = particles.map(|p| pulp::cast(velocity[p as usize].to_array()));
    let first = avx._mm256_insertf128_pd::<1>(avx._mm256_castpd128_pd256(v[0]), v[2]);
    let second = avx._mm256_insertf128_pd::<1>(avx._mm256_castpd128_pd256(v[1]), v[3]);
    (
        avx._mm256_unpacklo_pd(first, second),
        avx._mm256_unpackhi_pd(first, second),
    )
}

/// [`gather`] undone: the particles' velocities from their x and y.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn scatter(
    simd: pulp::x86::V3,
    (x, y): (core::arch::x86_64::__m256d, core::arch::x86_64::__m256d),
    particles: [u32; 4],
    velocity: &mut [DVec2],
) {
    let avx = simd.avx;
    let (first, second) = (avx._mm256_unpacklo_pd(x, y), avx._mm256_unpackhi_pd(x, y));
    let v: [[f64; 2]; 4] = [
        pulp::cast(avx._mm256_castpd256_pd128(first)),
        pulp::cast(avx._mm256_castpd256_pd128(second)),
        pulp::cast(avx._mm256_extractf128_pd::<1>(first)),
        pulp::cast(avx._mm256_extractf128_pd::<1>(second)),
    ];
    for (p, v) in particles.into_iter().zip(v) {
        velocity[p as usize] = DVec2::from_array(v);
    }
}

/// The sweeps two rows at a time in WebAssembly's 128-bit vectors: the same operations
/// lane by lane as one row at a time, so the same bits.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod pairs_of_rows {
    use core::arch::wasm32::{
        f64x2, f64x2_abs, f64x2_add, f64x2_extract_lane, f64x2_gt, f64x2_mul, f64x2_ne, f64x2_pmax,
        f64x2_sub, v128, v128_any_true, v128_or,
    };

    use glam::DVec2;

    use super::{PairColumns, Sums};

    fn two(column: &[f64], k: usize) -> v128 {
        f64x2(column[k], column[k + 1])
    }

    fn gather(particles: (usize, usize), v: &[DVec2]) -> (v128, v128) {
        let (a, b) = (v[particles.0], v[particles.1]);
        (f64x2(a.x, b.x), f64x2(a.y, b.y))
    }

    fn scatter((x, y): (v128, v128), particles: (usize, usize), v: &mut [DVec2]) {
        v[particles.0] = DVec2::new(f64x2_extract_lane::<0>(x), f64x2_extract_lane::<0>(y));
        v[particles.1] = DVec2::new(f64x2_extract_lane::<1>(x), f64x2_extract_lane::<1>(y));
    }

    fn particles(column: &[u32], k: usize) -> (usize, usize) {
        (column[k] as usize, column[k + 1] as usize)
    }

    /// `pmax(0, a)` is `if 0 < a { a } else { 0 }`: `if a > 0 { a } else { 0 }` to the bit.
    fn positive(a: v128) -> v128 {
        f64x2_pmax(f64x2(0.0, 0.0), a)
    }

    pub fn sweep(c: &mut PairColumns, levels: &[u32], velocity: &mut [DVec2]) -> Option<f64> {
        let zero = f64x2(0.0, 0.0);
        let (mut largest, mut changed) = (zero, zero);
        let mut sums = Sums::default();
        let mut start = 0;
        for &end in levels {
            let end = end as usize;
            let mut k = start;
            while k + 2 <= end {
                let (i, j) = (particles(&c.i, k), particles(&c.j, k));
                let ((vix, viy), (vjx, vjy)) = (gather(i, velocity), gather(j, velocity));
                let (nx, ny) = (two(&c.nx, k), two(&c.ny, k));
                let approach = f64x2_add(
                    f64x2_mul(f64x2_sub(vix, vjx), nx),
                    f64x2_mul(f64x2_sub(viy, vjy), ny),
                );
                let before = two(&c.impulse, k);
                let accumulated = positive(f64x2_add(before, f64x2_mul(approach, two(&c.mass, k))));
                let change = f64x2_sub(accumulated, before);
                let (px, py) = (f64x2_mul(nx, change), f64x2_mul(ny, change));
                let (wi, wj) = (two(&c.wi, k), two(&c.wj, k));
                scatter(
                    (
                        f64x2_sub(vix, f64x2_mul(px, wi)),
                        f64x2_sub(viy, f64x2_mul(py, wi)),
                    ),
                    i,
                    velocity,
                );
                scatter(
                    (
                        f64x2_add(vjx, f64x2_mul(px, wj)),
                        f64x2_add(vjy, f64x2_mul(py, wj)),
                    ),
                    j,
                    velocity,
                );
                c.impulse[k] = f64x2_extract_lane::<0>(accumulated);
                c.impulse[k + 1] = f64x2_extract_lane::<1>(accumulated);
                let changed_by = f64x2_abs(f64x2_mul(change, f64x2_add(wi, wj)));
                largest = f64x2_pmax(largest, changed_by);
                changed = v128_or(changed, f64x2_ne(change, zero));
                k += 2;
            }
            c.rows_one_at_a_time(k..end, velocity, &mut sums);
            start = end;
        }
        for lane in [
            f64x2_extract_lane::<0>(largest),
            f64x2_extract_lane::<1>(largest),
        ] {
            if lane > sums.largest {
                sums.largest = lane;
            }
        }
        sums.any |= v128_any_true(changed);
        sums.result()
    }

    pub fn correct(c: &PairColumns, levels: &[u32], position: &mut [DVec2]) -> bool {
        let zero = f64x2(0.0, 0.0);
        let mut shifted = zero;
        let mut moved = false;
        let mut start = 0;
        for &end in levels {
            let end = end as usize;
            let mut k = start;
            while k + 2 <= end {
                let (i, j) = (particles(&c.i, k), particles(&c.j, k));
                let ((pix, piy), (pjx, pjy)) = (gather(i, position), gather(j, position));
                let (nx, ny) = (two(&c.nx, k), two(&c.ny, k));
                let (ox, oy) = (f64x2_sub(pjx, pix), f64x2_sub(pjy, piy));
                let across = f64x2_sub(f64x2_mul(nx, oy), f64x2_mul(ny, ox));
                let along = f64x2_add(f64x2_mul(ox, nx), f64x2_mul(oy, ny));
                let excess = positive(f64x2_sub(
                    two(&c.reach, k),
                    f64x2_add(along, f64x2_mul(f64x2_mul(across, across), two(&c.bend, k))),
                ));
                let share = f64x2_mul(excess, two(&c.correction, k));
                let (sx, sy) = (f64x2_mul(nx, share), f64x2_mul(ny, share));
                let (wi, wj) = (two(&c.wi, k), two(&c.wj, k));
                scatter(
                    (
                        f64x2_sub(pix, f64x2_mul(sx, wi)),
                        f64x2_sub(piy, f64x2_mul(sy, wi)),
                    ),
                    i,
                    position,
                );
                scatter(
                    (
                        f64x2_add(pjx, f64x2_mul(sx, wj)),
                        f64x2_add(pjy, f64x2_mul(sy, wj)),
                    ),
                    j,
                    position,
                );
                shifted = v128_or(shifted, f64x2_gt(share, zero));
                k += 2;
            }
            moved |= c.correct_one_at_a_time(k..end, position);
            start = end;
        }
        moved | v128_any_true(shifted)
    }
}
