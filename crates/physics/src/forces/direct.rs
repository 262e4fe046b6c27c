//! The direct sum of gravitation and Coulomb ([`super::pair`]'s laws) over every pair of
//! a set of bodies, laid out for SIMD.
//!
//! Each pair is visited once (the force on j is minus the force on i). The bodies are
//! copied into structure-of-arrays form, and for each body i its partners j > i are
//! taken two groups of [`LANES`] at a time, in vectors: `pulp` compiles the loop for
//! AVX-512, AVX2 and SSE4.2, and [`dispatch`] picks at run time (AVX2 on Intel's
//! processors, the widest elsewhere; simd128 in the browser, plain arithmetic
//! elsewhere). Every lane does the same IEEE 754
//! operations — a square root, a shared division, no reciprocal-square-root estimate
//! (whose bits differ between processors), no fused multiply-add — and the lanes'
//! partial sums are combined in a fixed order. So the result is the same bits on every
//! processor and in WebAssembly (tested by running each instruction set), and differs
//! from summing one pair at a time only by rounding (tested to 1e-12 relative per
//! force). A row's last partners, fewer than two groups, are two groups padded with
//! bodies that every pair masks out (a lone pair would cost a square root and a
//! division that no lane shares; docs/performance.md has the gain).
//! Scenes of up to 16 bodies are summed one pair at a time, so they get exactly the
//! plain loop's numbers.
//!
//! Many bodies are summed in blocks of rows on the simulation's threads
//! ([`BLOCKED_FROM`]), each block into its own buffer, the buffers added in a fixed
//! order: bit-identical for any number of threads.
//!
//! The divider is the bottleneck (`newtonlab bench --scene cloud`), hence the shared
//! division; docs/performance.md has the rates per machine.

// pulp compiles `with_simd` once per instruction set, and what it calls gets that
// instruction set only when inlined into it.
#![expect(
    clippy::inline_always,
    reason = "pulp's kernels must inline into with_simd"
)]

use glam::DVec2;
use pulp::{Arch, Simd, WithSimd};

use super::pair;
use crate::parallel::Workers;
use crate::tuning::{BLOCKED_FROM, BLOCKS};

/// Partners per group: one AVX-512 vector. The grouping, not the hardware, fixes the
/// order of the sums.
pub(crate) const LANES: usize = 8;

/// The bodies of one sum in structure-of-arrays form.
#[derive(Clone, Default)]
struct Bodies {
    x: Vec<f64>,
    y: Vec<f64>,
    /// G·m, N·m²/kg.
    gm: Vec<f64>,
    /// k·q, N·m²/C.
    kq: Vec<f64>,
    /// The plain mass and charge, for the other factor of each pair.
    mass: Vec<f64>,
    charge: Vec<f64>,
    /// 1 for a body that moves, 0 for a fixed one: a pair of fixed bodies is skipped
    /// (they may even coincide).
    moves: Vec<f64>,
    /// ε², m², added to every pair's r² (adding 0 changes no bit: r² ≥ 0).
    softening2: f64,
}

impl Bodies {
    /// The bodies past the last real one, up to `len`: at the origin, of no mass or
    /// charge, and `moves` −1, so that a pair with one of them is masked out like a pair
    /// of fixed bodies (the sum of the two `moves` is never positive).
    fn pad_to(&mut self, len: usize) {
        for column in [
            &mut self.x,
            &mut self.y,
            &mut self.gm,
            &mut self.kq,
            &mut self.mass,
            &mut self.charge,
        ] {
            column.resize(len, 0.0);
        }
        self.moves.resize(len, -1.0);
    }
}

/// Adds to `force` (N, indexed by particle) the gravitation (G = `g`) and Coulomb
/// (k = `k`) forces, softened by ε² = `softening2` (r² + ε² for r², 0 for the exact
/// laws), between every pair of the particles `ids`, with positions `x`,
/// masses `mass`, charges `charge`, and `fixed(i)` for a particle that never moves;
/// on `workers`' threads for many bodies, with the same bits for any number of them.
pub(crate) fn add_forces(
    constants: (f64, f64, f64),
    ids: &[usize],
    (x, mass, charge): (&[DVec2], &[f64], &[f64]),
    fixed: impl Fn(usize) -> bool,
    workers: &Workers,
    force: &mut [DVec2],
) {
    let (g, k, softening2) = constants;
    let n = ids.len();
    let padded = padded_len(n);
    SCRATCH.with_borrow_mut(|scratch| {
        let Scratch { bodies, fx, fy } = scratch;
        // Column by column: each a tight loop.
        let fill = |column: &mut Vec<f64>, value: &dyn Fn(usize) -> f64| {
            column.clear();
            column.extend(ids.iter().map(|&i| value(i)));
        };
        fill(&mut bodies.x, &|i| x[i].x);
        fill(&mut bodies.y, &|i| x[i].y);
        fill(&mut bodies.gm, &|i| g * mass[i]);
        fill(&mut bodies.kq, &|i| k * charge[i]);
        fill(&mut bodies.mass, &|i| mass[i]);
        fill(&mut bodies.charge, &|i| charge[i]);
        fill(&mut bodies.moves, &|i| if fixed(i) { 0.0 } else { 1.0 });
        bodies.softening2 = softening2;
        bodies.pad_to(padded);
        let bodies = &*bodies;
        let add = |sums: &[(&[f64], &[f64])], force: &mut [DVec2]| {
            for (a, &i) in ids.iter().enumerate() {
                let mut sum = DVec2::ZERO;
                for (fx, fy) in sums {
                    sum += DVec2::new(fx[a], fy[a]);
                }
                force[i] += sum;
            }
        };
        if !is_blocked(n) {
            // One block, on this thread, into buffers kept from call to call: the
            // coupled group of a mixed scene (some hundred bodies) is summed tens of times
            // a step, and allocating the columns and buffers each time shows in a profile.
            for buffer in [&mut *fx, &mut *fy] {
                buffer.clear();
                buffer.resize(padded, 0.0);
            }
            pairs(bodies, n, 0..n, fx, fy);
            add(&[(fx, fy)], force);
            return;
        }
        let rows = blocks(n);
        let sums = workers.map(rows.len() - 1, |b| {
            let (mut fx, mut fy) = (vec![0.0; padded], vec![0.0; padded]);
            pairs(bodies, n, rows[b]..rows[b + 1], &mut fx, &mut fy);
            (fx, fy)
        });
        let sums: Vec<(&[f64], &[f64])> = sums.iter().map(|(x, y)| (&x[..], &y[..])).collect();
        add(&sums, force);
    });
}

thread_local! {
    /// The columns of the bodies and a single block's forces, kept from sum to sum.
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::default();
}

/// See [`SCRATCH`].
#[derive(Default)]
struct Scratch {
    bodies: Bodies,
    fx: Vec<f64>,
    fy: Vec<f64>,
}

/// How many bodies the columns of `n` hold: 2 × [`LANES`] more for the padded tails,
/// none for a scene small enough to be summed one pair at a time.
fn padded_len(n: usize) -> usize {
    n + if n > 2 * LANES { 2 * LANES } else { 0 }
}

/// Whether a sum over `n` bodies is split into blocks that the threads share.
pub(crate) fn is_blocked(n: usize) -> bool {
    n >= BLOCKED_FROM
}

/// The first row of each block and the end, for `n` bodies: blocks of about equal
/// numbers of pairs (row i has n − 1 − i), one block below [`BLOCKED_FROM`].
fn blocks(n: usize) -> Vec<usize> {
    if !is_blocked(n) {
        return vec![0, n];
    }
    let total = n * (n - 1) / 2;
    let mut starts = vec![0];
    let mut done = 0;
    for i in 0..n {
        if done * BLOCKS >= total * starts.len() && starts.len() < BLOCKS {
            starts.push(i);
        }
        done += n - 1 - i;
    }
    starts.push(n);
    starts
}

/// The force on body i (x, y, G mᵢ, k qᵢ, moves) from body j (x, y, mⱼ, qⱼ, moves), N:
/// (dx, dy) times (G mᵢ mⱼ − k qᵢ qⱼ) / (r² + ε²)^{3/2}, or zero when neither moves;
/// `softening2` is ε².
#[inline]
fn pull(i: (f64, f64, f64, f64, f64), j: (f64, f64, f64, f64, f64), softening2: f64) -> (f64, f64) {
    let ((xi, yi, gmi, kqi, moves_i), (xj, yj, mj, qj, moves_j)) = (i, j);
    let plain = pulp::Scalar::new();
    let (dx, dy) = (xj - xi, yj - yi);
    let r2 = pair::softened_square(plain, dx, dy, softening2);
    let s = pair::strength(plain, gmi, mj, kqi, qj) / pair::cube(plain, r2);
    let s = if moves_i + moves_j > 0.0 { s } else { 0.0 };
    (dx * s, dy * s)
}

/// The symmetric pair loop over the pairs whose first body is in `rows`, in the vectors
/// [`dispatch`] picks.
fn pairs(b: &Bodies, real: usize, rows: std::ops::Range<usize>, fx: &mut [f64], fy: &mut [f64]) {
    dispatch(Rows {
        b,
        real,
        range: rows,
        fx,
        fy,
    });
}

/// Runs `work` in the vectors that sum pairs fastest on this processor: AVX2 on Intel's,
/// which lower their clock for heavy 512-bit arithmetic while taking square roots and
/// divisions no faster per lane in 512 bits than in 256 (the pair loop's bottleneck:
/// 9.6–9.7e8 pairs a second in AVX2 against 8.8–8.9e8 in AVX-512 on an Intel Xeon,
/// `bench --scene cloud --particles 1000 --threads 1`, alternating); elsewhere the widest
/// the processor has (AMD's cores keep their clock at 512 bits), chosen by `pulp`. Every
/// instruction set gives the same bits (`every_instruction_set_gives_the_same_bits`), so
/// the choice changes only the speed.
#[inline]
pub(super) fn dispatch<W: WithSimd>(work: W) -> W::Output {
    #[cfg(target_arch = "x86_64")]
    if is_intel()
        && let Some(v3) = pulp::x86::V3::try_new()
    {
        return Simd::vectorize(v3, work);
    }
    Arch::new().dispatch(work)
}

/// Whether the processor is Intel's (its CPUID vendor string), asked once.
#[cfg(target_arch = "x86_64")]
fn is_intel() -> bool {
    static INTEL: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *INTEL.get_or_init(|| {
        let vendor = std::arch::x86_64::__cpuid(0);
        let bytes: Vec<u8> = [vendor.ebx, vendor.edx, vendor.ecx]
            .iter()
            .flat_map(|word| word.to_le_bytes())
            .collect();
        bytes == b"GenuineIntel"
    })
}

/// [`pairs`]' work, for `pulp` to compile once per instruction set.
struct Rows<'a> {
    b: &'a Bodies,
    /// The real bodies; `b` holds as many or, padded, 2 × [`LANES`] more.
    real: usize,
    range: std::ops::Range<usize>,
    fx: &'a mut [f64],
    fy: &'a mut [f64],
}

impl WithSimd for Rows<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: Simd>(self, simd: S) {
        let Rows {
            b,
            real: n,
            range,
            fx,
            fy,
        } = self;
        for i in range {
            let body = (b.x[i], b.y[i], b.gm[i], b.kq[i], b.moves[i]);
            let mut sums = ([0.0; LANES], [0.0; LANES]);
            let mut j = i + 1;
            // A moving body's pairs all count: only a fixed one's need the mask.
            let fixed = b.moves[i] == 0.0;
            while j + 2 * LANES <= n {
                if fixed {
                    groups::<S, true>(simd, b, body, j, &mut sums, (fx, fy));
                } else {
                    groups::<S, false>(simd, b, body, j, &mut sums, (fx, fy));
                }
                j += 2 * LANES;
            }
            // The last partners, padded to two groups and masked like a fixed body's
            // (a lone pair costs a square root and a division no lane shares).
            if b.x.len() > n && j < n {
                groups::<S, true>(simd, b, body, j, &mut sums, (fx, fy));
                j = n;
            }
            let (mut tx, mut ty) = (0.0, 0.0);
            for j in j..n {
                let partner = (b.x[j], b.y[j], b.mass[j], b.charge[j], b.moves[j]);
                let (px, py) = pull(body, partner, b.softening2);
                tx += px;
                ty += py;
                fx[j] -= px;
                fy[j] -= py;
            }
            fx[i] += sum_lanes(&sums.0) + tx;
            fy[i] += sum_lanes(&sums.1) + ty;
        }
    }
}

/// The forces on body `i` from the 2 × [`LANES`] bodies from `j` on: added to `i`'s
/// lane sums and taken from the partners' forces `f`, a whole vector at a time (eight
/// lanes are one AVX-512 vector, two AVX2 or four SSE4.2 ones, eight plain numbers).
/// The two groups share one division, the reciprocal of the product of their r³; each
/// pair's strength is multiplied by the other group's r³ and by it (the divider is the
/// kernel's bottleneck; the products stay far inside f64's range for any distance
/// between 1e-50 and 1e50 m). For a `FIXED` body i, pairs with fixed partners give
/// nothing.
#[inline(always)]
fn groups<S: Simd, const FIXED: bool>(
    simd: S,
    b: &Bodies,
    i: Body<f64>,
    j: usize,
    sums: &mut ([f64; LANES], [f64; LANES]),
    f: (&mut [f64], &mut [f64]),
) {
    let (xi, yi, gmi, kqi, moves_i) = i;
    let splat = |value| simd.splat_f64s(value);
    let body = (splat(xi), splat(yi), splat(gmi), splat(kqi), splat(moves_i));
    let (ax, ay) = (
        S::as_mut_simd_f64s(&mut sums.0).0,
        S::as_mut_simd_f64s(&mut sums.1).0,
    );
    let (fx, fy) = f;
    let (fx_a, fx_b) = fx[j..j + 2 * LANES].split_at_mut(LANES);
    let (fy_a, fy_b) = fy[j..j + 2 * LANES].split_at_mut(LANES);
    let (fx_a, fx_b) = (S::as_mut_simd_f64s(fx_a).0, S::as_mut_simd_f64s(fx_b).0);
    let (fy_a, fy_b) = (S::as_mut_simd_f64s(fy_a).0, S::as_mut_simd_f64s(fy_b).0);
    for k in 0..ax.len() {
        let (dx_a, dy_a, strength_a, cube_a) = geometry::<S, FIXED>(simd, b, body, j, k);
        let (dx_b, dy_b, strength_b, cube_b) = geometry::<S, FIXED>(simd, b, body, j + LANES, k);
        let shared = simd.div_f64s(splat(1.0), simd.mul_f64s(cube_a, cube_b));
        let s_a = simd.mul_f64s(simd.mul_f64s(strength_a, cube_b), shared);
        let s_b = simd.mul_f64s(simd.mul_f64s(strength_b, cube_a), shared);
        let (px_a, py_a) = (simd.mul_f64s(dx_a, s_a), simd.mul_f64s(dy_a, s_a));
        let (px_b, py_b) = (simd.mul_f64s(dx_b, s_b), simd.mul_f64s(dy_b, s_b));
        ax[k] = simd.add_f64s(simd.add_f64s(ax[k], px_a), px_b);
        ay[k] = simd.add_f64s(simd.add_f64s(ay[k], py_a), py_b);
        fx_a[k] = simd.sub_f64s(fx_a[k], px_a);
        fy_a[k] = simd.sub_f64s(fy_a[k], py_a);
        fx_b[k] = simd.sub_f64s(fx_b[k], px_b);
        fy_b[k] = simd.sub_f64s(fy_b[k], py_b);
    }
}

/// For vector `k` of the group from `j`: dx, dy, the pair's strength G mᵢ mⱼ − k qᵢ qⱼ
/// and r³ (softened: (r² + ε²)^{3/2}). For a `FIXED` body i, a fixed partner's strength is 0 and its r³ 1 (two
/// fixed bodies may coincide: the shared division stays finite).
#[inline(always)]
fn geometry<S: Simd, const FIXED: bool>(
    simd: S,
    b: &Bodies,
    (xi, yi, gmi, kqi, moves_i): Body<S::f64s>,
    j: usize,
    k: usize,
) -> (S::f64s, S::f64s, S::f64s, S::f64s) {
    let dx = simd.sub_f64s(lanes::<S>(&b.x, j)[k], xi);
    let dy = simd.sub_f64s(lanes::<S>(&b.y, j)[k], yi);
    let r2 = pair::softened_square(simd, dx, dy, simd.splat_f64s(b.softening2));
    let strength = pair::strength(
        simd,
        gmi,
        lanes::<S>(&b.mass, j)[k],
        kqi,
        lanes::<S>(&b.charge, j)[k],
    );
    let cube = pair::cube(simd, r2);
    if FIXED {
        let moves = simd.add_f64s(moves_i, lanes::<S>(&b.moves, j)[k]);
        let moving = simd.greater_than_f64s(moves, simd.splat_f64s(0.0));
        (
            dx,
            dy,
            simd.select_f64s(moving, strength, simd.splat_f64s(0.0)),
            simd.select_f64s(moving, cube, simd.splat_f64s(1.0)),
        )
    } else {
        (dx, dy, strength, cube)
    }
}

/// Body i as the pair loop reads it: x, y, G mᵢ, k qᵢ, and 1 if it moves (0 if fixed),
/// each as a number or splat across a vector.
type Body<V> = (V, V, V, V, V);

/// The [`LANES`] values from `j` on, as vectors.
#[inline(always)]
pub(super) fn lanes<S: Simd>(values: &[f64], j: usize) -> &[S::f64s] {
    S::as_simd_f64s(&values[j..j + LANES]).0
}

/// The lanes' sum in a fixed order: pairs, then pairs of pairs.
#[inline]
pub(super) fn sum_lanes(a: &[f64; LANES]) -> f64 {
    ((a[0] + a[1]) + (a[2] + a[3])) + ((a[4] + a[5]) + (a[6] + a[7]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The symmetric loop over every row in vectors of `simd`'s width, the bodies
    /// padded as [`add_forces`] pads them.
    fn forces_in<S: Simd>(simd: S, b: &Bodies) -> (Vec<f64>, Vec<f64>) {
        padded(b, |padded, n, fx, fy| {
            Rows {
                b: padded,
                real: n,
                range: 0..n,
                fx,
                fy,
            }
            .with_simd(simd);
        })
    }

    /// The forces `sum` adds up over `b` padded as [`add_forces`] pads it, given the
    /// number of real bodies and padded force buffers.
    fn padded(
        b: &Bodies,
        sum: impl FnOnce(&Bodies, usize, &mut [f64], &mut [f64]),
    ) -> (Vec<f64>, Vec<f64>) {
        let n = b.x.len();
        let mut padded = b.clone();
        padded.pad_to(padded_len(n));
        let (mut fx, mut fy) = (vec![0.0; padded_len(n)], vec![0.0; padded_len(n)]);
        sum(&padded, n, &mut fx, &mut fy);
        fx.truncate(n);
        fy.truncate(n);
        (fx, fy)
    }

    /// Every instruction set the processor has (AVX-512, AVX2, SSE2 on x86-64) gives
    /// the same bits as plain arithmetic: the lanes' order of summation is fixed by the
    /// grouping, and each lane does the same correctly rounded operations.
    #[test]
    fn every_instruction_set_gives_the_same_bits() {
        let mut b = Bodies::default();
        for i in 0..37_u32 {
            let t = f64::from(i);
            b.x.push((t * 1.7).sin() * 40.0);
            b.y.push((t * 0.9).cos() * 25.0 + t);
            b.mass.push(1.0 + t * t);
            b.charge.push(if i % 3 == 0 { -1e-4 } else { 2e-4 } * t);
            b.gm.push(6.674e-11 * b.mass[i as usize]);
            b.kq.push(8.988e9 * b.charge[i as usize]);
            b.moves.push(if i == 5 || i == 6 { 0.0 } else { 1.0 });
        }
        b.softening2 = 0.7;
        let plain = forces_in(pulp::Scalar::new(), &b);
        assert!(
            plain
                .0
                .iter()
                .chain(&plain.1)
                .all(|f| f.is_finite() && *f != 0.0)
        );
        #[cfg(target_arch = "x86_64")]
        {
            use pulp::x86::{V2, V3, V4};
            let widths = [
                V2::try_new().map(|simd| forces_in(simd, &b)),
                V3::try_new().map(|simd| forces_in(simd, &b)),
                V4::try_new().map(|simd| forces_in(simd, &b)),
            ];
            for forces in widths.into_iter().flatten() {
                assert_eq!(forces, plain);
            }
        }
        let dispatched = padded(&b, |padded, n, fx, fy| pairs(padded, n, 0..n, fx, fy));
        assert_eq!(dispatched, plain);
    }

    /// On an Intel processor with AVX2 the pair loop runs in AVX2 (see [`dispatch`]);
    /// elsewhere in what `pulp` picks. The vendor is read from what Linux says of the
    /// processor, independently of the CPUID instruction the dispatch asks (elsewhere
    /// the test only checks that the choice is one of the two).
    #[test]
    fn intel_processors_sum_in_avx2() {
        struct Width;
        impl WithSimd for Width {
            type Output = &'static str;
            #[inline(always)]
            fn with_simd<S: Simd>(self, _: S) -> &'static str {
                std::any::type_name::<S>()
            }
        }
        let chosen = dispatch(Width);
        let widest = Arch::new().dispatch(Width);
        #[cfg(target_arch = "x86_64")]
        {
            let avx2 = pulp::x86::V3::try_new().map(|_| std::any::type_name::<pulp::x86::V3>());
            let linux_says = std::fs::read_to_string("/proc/cpuinfo")
                .ok()
                .and_then(|info| {
                    info.lines()
                        .find(|line| line.starts_with("vendor_id"))
                        .map(|line| line.contains("GenuineIntel"))
                });
            match (linux_says, avx2) {
                (Some(true), Some(avx2)) => assert_eq!(chosen, avx2),
                (Some(false), _) | (_, None) => assert_eq!(chosen, widest),
                (None, Some(avx2)) => assert!(chosen == avx2 || chosen == widest),
            }
        }
        #[cfg(not(target_arch = "x86_64"))]
        assert_eq!(chosen, widest);
    }

    /// The plain loop the kernel replaced: one pair at a time, in order, with the
    /// pair laws softened by ε² = `softening2`.
    fn one_pair_at_a_time(
        (g, k, softening2): (f64, f64, f64),
        bodies: &[(DVec2, f64, f64, bool)],
    ) -> Vec<DVec2> {
        let mut force = vec![DVec2::ZERO; bodies.len()];
        for (i, &(xi, mi, qi, fixed_i)) in bodies.iter().enumerate() {
            for (j, &(xj, mj, qj, fixed_j)) in bodies.iter().enumerate().skip(i + 1) {
                if fixed_i && fixed_j {
                    continue;
                }
                let d = xj - xi;
                let r2 = d.length_squared() + softening2;
                let f = d * ((g * mi * mj - k * qi * qj) / (r2 * r2.sqrt()));
                force[i] += f;
                force[j] -= f;
            }
        }
        force
    }

    /// 203 bodies (not a multiple of the lanes: the tail too) of masses and charges of
    /// both signs over six orders of magnitude, two of them fixed at one point: every
    /// force within 1e-12 of the plain loop's, relative to the sum of the magnitudes of
    /// the pair forces on the body (the scale rounding works at; a net force can cancel
    /// to far less). The fixed pair that coincides gives no NaN, nor a body at the
    /// origin, where the padding sits (a pair with the padding is masked out). With the
    /// exact laws and with a softening of 3 m (against a box of 100 m: most pairs feel
    /// it, the nearest ones by orders of magnitude).
    #[test]
    fn the_lanes_agree_with_one_pair_at_a_time() {
        let mut random = crate::testing::uniform(12_345);
        let mut bodies: Vec<(DVec2, f64, f64, bool)> = (0..203)
            .map(|_| {
                let x = DVec2::new(random() * 100.0 - 50.0, random() * 100.0 - 50.0);
                let mass = 10f64.powf(random() * 6.0);
                let charge = (random() - 0.5) * 1e-3;
                (x, mass, charge, false)
            })
            .collect();
        bodies[7] = (DVec2::new(1.0, 1.0), 5.0, 1e-4, true);
        bodies[150] = (DVec2::new(1.0, 1.0), 5.0, -1e-4, true);
        // At the padding's own place: its pairs with the padding must stay masked.
        bodies[190] = (DVec2::ZERO, 3.0, 2e-4, false);
        let (g, k) = (6.674e-11, 8.988e9);
        let ids: Vec<usize> = (0..bodies.len()).collect();
        let x: Vec<DVec2> = bodies.iter().map(|b| b.0).collect();
        let mass: Vec<f64> = bodies.iter().map(|b| b.1).collect();
        let charge: Vec<f64> = bodies.iter().map(|b| b.2).collect();
        for softening2 in [0.0, 9.0] {
            let expected = one_pair_at_a_time((g, k, softening2), &bodies);
            let mut force = vec![DVec2::ZERO; bodies.len()];
            add_forces(
                (g, k, softening2),
                &ids,
                (&x, &mass, &charge),
                |i| bodies[i].3,
                &Workers::default(),
                &mut force,
            );
            for i in 0..bodies.len() {
                let scale: f64 = (0..bodies.len())
                    .filter(|&j| j != i && !(bodies[i].3 && bodies[j].3))
                    .map(|j| {
                        let (a, b) = (bodies[i], bodies[j]);
                        let r2 = a.0.distance_squared(b.0) + softening2;
                        (g * a.1 * b.1 - k * a.2 * b.2).abs() * a.0.distance(b.0) / (r2 * r2.sqrt())
                    })
                    .sum();
                let error = force[i].distance(expected[i]) / scale;
                assert!(force[i].is_finite(), "body {i}: {}", force[i]);
                assert!(
                    error < 1e-12,
                    "body {i}, ε² = {softening2}: {} against {} ({error:e})",
                    force[i],
                    expected[i]
                );
            }
        }
    }
}
