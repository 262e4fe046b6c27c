// pulp compiles `with_simd` once per instruction set, and what it calls gets that
// instruction set only when inlined into it.
#![expect(
    clippy::inline_always,
    reason = "pulp's kernels must inline into with_simd"
)]
//! Gravitation summed with a Barnes–Hut quadtree (Barnes and Hut, Nature 324, 1986):
//! the bodies are sorted into nested squares, each square knows its total mass, centre
//! of mass and quadrupole, and a square of side s whose centre of mass is at distance d
//! from a body acts on it as a whole when s < θ·d (θ, the opening angle); otherwise its
//! quarters are looked at, down to leaves of a few bodies summed pair by pair. The cost
//! is O(n log n) instead of O(n²); the error is that of the quadrupole expansion, of
//! order θ³ for the nearest groups accepted: `tests/pair_forces.rs` measures it against
//! the direct sum.
//!
//! The tree is walked once per leaf, not once per body (Barnes, J. Comput. Phys. 87,
//! 1990): a square acts as a whole on all the leaf's bodies when the rule holds for d
//! the distance to the nearest point of the box around them, so for each body too. The
//! walk gives each leaf a list of far squares and near bodies, which every body of the
//! leaf sums in SIMD lanes (as [`super::direct`], the same bits on every instruction
//! set). Walking once per leaf is about twice as fast as once per body (`newtonlab bench
//! --scene cluster`), with a smaller error: a leaf's nearest point is stricter.
//!
//! A body never acts on itself: a square that reaches into its leaf's box is always
//! opened, and a near body at the body's own position is skipped. The tree is rebuilt
//! for each force evaluation from the positions given, in a fixed order, so the result
//! is the same bits for the same positions, on any number of threads. Forces are not
//! summed in equal and opposite pairs, so the total momentum drifts by the error of the
//! forces.

use glam::DVec2;

use pulp::{Simd, WithSimd};

use super::direct::{LANES, lanes, sum_lanes};
use super::pair;
use crate::parallel::Workers;
use crate::tuning::{LEAF, SPLIT_LEAVES, TREE_DEPTH};

struct Node {
    /// The square: lower-left corner and side, metres.
    corner: DVec2,
    side: f64,
    /// Total mass (kg) and centre of mass.
    mass: f64,
    centre: DVec2,
    /// The traceless quadrupole about the centre of mass, Σ m (3 r rᵀ − |r|² I), kg·m²:
    /// its xx, xy and yy components.
    quadrupole: [f64; 3],
    /// The bodies in it, as a range of the sorted order.
    start: usize,
    end: usize,
    /// Its four quarters, when it was split.
    quarters: Option<[usize; 4]>,
}

/// Adds the quadrupole of mass `m` at `r` from a centre: m (3 r rᵀ − |r|² I).
fn add_quadrupole(q: &mut [f64; 3], m: f64, r: DVec2) {
    let r2 = r.length_squared();
    q[0] += m * (3.0 * r.x * r.x - r2);
    q[1] += m * 3.0 * r.x * r.y;
    q[2] += m * (3.0 * r.y * r.y - r2);
}

/// Adds G mᵢ Σ mⱼ (xⱼ − xᵢ)/|xⱼ − xᵢ|³ to `force[i]` for each body i of `bodies`, with
/// the sum over the other bodies approximated as above; `(g, softening2)` are G and ε²,
/// which stands beside every r² (Plummer softening: r² + ε² in a near pair's law and in
/// a far cell's expansion, where it changes the quadrupole's term by a part in ε²/r²).
///
/// Each body's sum is its own, so the bodies are shared out among `workers`' threads
/// with the same bits for any number of them.
pub(crate) fn gravitation(
    (g, softening2): (f64, f64),
    theta: f64,
    bodies: &[usize],
    (x, mass): (&[DVec2], &[f64]),
    workers: &Workers,
    force: &mut [DVec2],
) {
    if bodies.len() < 2 {
        return;
    }
    let accelerations = per_body(theta, bodies, (x, mass), workers, |lists, i| {
        (i, lists.acceleration(x[i], softening2))
    });
    for (i, a) in accelerations {
        force[i] += a * (g * mass[i]);
    }
}

/// The gravitational potential energy of `bodies`, −G Σ mᵢ mⱼ / rᵢⱼ over their pairs
/// (softened: rᵢⱼ² + ε² for rᵢⱼ², with `(g, softening2)` G and ε²),
/// with each body's potential summed through the tree as its force is (monopole and
/// quadrupole of each cell far enough away): the energy to the accuracy of the forces.
/// The bodies are shared out among `workers`' threads and their terms added in order:
/// the same bits for any number of threads.
pub(crate) fn potential_energy(
    (g, softening2): (f64, f64),
    theta: f64,
    bodies: &[usize],
    (x, mass): (&[DVec2], &[f64]),
    workers: &Workers,
) -> f64 {
    if bodies.len() < 2 {
        return 0.0;
    }
    let terms = per_body(theta, bodies, (x, mass), workers, |lists, i| {
        mass[i] * lists.inverse_distance_sum(x[i], softening2)
    });
    // Each pair is counted from both ends.
    -0.5 * g * terms.iter().sum::<f64>()
}

/// `sum(lists, i)` for every body i of `bodies`, in the tree's order, with `lists` what
/// i's leaf feels: the leaves are shared out among `workers`' threads, each leaf walked
/// once, and the results kept in order (the same for any number of threads).
fn per_body<T: Send>(
    theta: f64,
    bodies: &[usize],
    (x, mass): (&[DVec2], &[f64]),
    workers: &Workers,
    sum: impl Fn(&Interactions, usize) -> T + Sync,
) -> Vec<T> {
    let tree = Tree::build(bodies, x, mass);
    let leaves = tree.leaves();
    let mut results = Vec::with_capacity(bodies.len());
    workers.collect_into_from(SPLIT_LEAVES, leaves.len(), &mut results, |range, out| {
        let mut lists = Interactions::default();
        for &leaf in &leaves[range] {
            tree.interactions(leaf, theta, (x, mass), &mut lists);
            out.extend(tree.bodies_of(leaf).iter().map(|&i| sum(&lists, i)));
        }
    });
    results
}

/// What the bodies of one leaf feel from the rest of the tree (Barnes' grouping, J.
/// Comput. Phys. 87, 1990: one walk for all the bodies of a leaf instead of one each),
/// in structure-of-arrays form for the SIMD sums.
#[derive(Default)]
struct Interactions {
    /// Cells far enough from every body of the leaf to act as a whole: centre of mass,
    /// mass and quadrupole (xx, xy, yy).
    far: [Vec<f64>; 6],
    /// The bodies of the leaves that are not, the leaf's own included: position, mass.
    near: [Vec<f64>; 3],
    /// The walk's squares still to visit (kept from leaf to leaf).
    stack: Vec<usize>,
}

struct Tree {
    nodes: Vec<Node>,
    order: Vec<usize>,
}

impl Tree {
    fn build(bodies: &[usize], x: &[DVec2], mass: &[f64]) -> Self {
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for &i in bodies {
            lo = lo.min(x[i]);
            hi = hi.max(x[i]);
        }
        let side = (hi - lo).max_element().max(f64::MIN_POSITIVE) * (1.0 + 1e-9);
        let mut tree = Self {
            nodes: Vec::new(),
            order: bodies.to_vec(),
        };
        let mut scratch = Vec::with_capacity(bodies.len());
        tree.split(lo, side, 0, bodies.len(), 0, x, mass, &mut scratch);
        tree
    }

    /// Builds the node for `order[start..end]` in the square at `corner` of `side`, and
    /// its quarters; returns its index.
    #[expect(
        clippy::too_many_arguments,
        reason = "one recursive builder; its state is the square and the range"
    )]
    fn split(
        &mut self,
        corner: DVec2,
        side: f64,
        start: usize,
        end: usize,
        depth: u32,
        x: &[DVec2],
        mass: &[f64],
        scratch: &mut Vec<usize>,
    ) -> usize {
        let index = self.nodes.len();
        self.nodes.push(Node {
            corner,
            side,
            mass: 0.0,
            centre: DVec2::ZERO,
            quadrupole: [0.0; 3],
            start,
            end,
            quarters: None,
        });
        if end - start <= LEAF || depth >= TREE_DEPTH {
            let (mut total, mut moment) = (0.0, DVec2::ZERO);
            for &i in &self.order[start..end] {
                total += mass[i];
                moment += x[i] * mass[i];
            }
            let centre = if total > 0.0 { moment / total } else { corner };
            let mut quadrupole = [0.0; 3];
            for &i in &self.order[start..end] {
                add_quadrupole(&mut quadrupole, mass[i], x[i] - centre);
            }
            let node = &mut self.nodes[index];
            node.mass = total;
            node.centre = centre;
            node.quadrupole = quadrupole;
            return index;
        }
        // Sort the range into the quarters, keeping the order within each: lower-left,
        // lower-right, upper-left, upper-right.
        let half = side / 2.0;
        let middle = corner + DVec2::splat(half);
        let quarter = |p: DVec2| usize::from(p.x >= middle.x) + 2 * usize::from(p.y >= middle.y);
        // A stable counting sort: one pass counts the quarters, one places the bodies.
        let mut counts = [0; 4];
        for &i in &self.order[start..end] {
            counts[quarter(x[i])] += 1;
        }
        let mut next = [0; 4];
        for q in 1..4 {
            next[q] = next[q - 1] + counts[q - 1];
        }
        let ends: [usize; 4] = std::array::from_fn(|q| start + next[q] + counts[q]);
        scratch.clear();
        scratch.resize(end - start, 0);
        for &i in &self.order[start..end] {
            let slot = &mut next[quarter(x[i])];
            scratch[*slot] = i;
            *slot += 1;
        }
        self.order[start..end].copy_from_slice(scratch);
        let mut first = start;
        let mut children = [0; 4];
        for (q, child) in children.iter_mut().enumerate() {
            let offset = DVec2::new(
                if q % 2 == 1 { half } else { 0.0 },
                if q >= 2 { half } else { 0.0 },
            );
            *child = self.split(
                corner + offset,
                half,
                first,
                ends[q],
                depth + 1,
                x,
                mass,
                scratch,
            );
            first = ends[q];
        }
        let (mut total, mut moment) = (0.0, DVec2::ZERO);
        for &c in &children {
            total += self.nodes[c].mass;
            moment += self.nodes[c].centre * self.nodes[c].mass;
        }
        let centre = if total > 0.0 { moment / total } else { middle };
        // The quarters' quadrupoles, moved to this centre (the parallel-axis rule).
        let mut quadrupole = [0.0; 3];
        for &c in &children {
            let child = &self.nodes[c];
            for (sum, q) in quadrupole.iter_mut().zip(child.quadrupole) {
                *sum += q;
            }
            add_quadrupole(&mut quadrupole, child.mass, child.centre - centre);
        }
        let node = &mut self.nodes[index];
        node.mass = total;
        node.centre = centre;
        node.quadrupole = quadrupole;
        node.quarters = Some(children);
        index
    }

    /// The leaves that hold bodies, in the bodies' sorted order.
    fn leaves(&self) -> Vec<usize> {
        (0..self.nodes.len())
            .filter(|&n| {
                self.nodes[n].quarters.is_none() && self.nodes[n].end > self.nodes[n].start
            })
            .collect()
    }

    /// The bodies of node `n`.
    fn bodies_of(&self, n: usize) -> &[usize] {
        &self.order[self.nodes[n].start..self.nodes[n].end]
    }

    /// Walks the tree once for all the bodies of `leaf`: a cell acts as a whole when its
    /// side is under `theta` times the distance from its centre of mass to the nearest
    /// point of the box around the leaf's bodies, and its square does not reach into that
    /// box. Every body of the leaf is at least that far, so each meets Barnes and Hut's
    /// rule for itself; the rest are opened down to their bodies.
    fn interactions(
        &self,
        leaf: usize,
        theta: f64,
        (x, mass): (&[DVec2], &[f64]),
        lists: &mut Interactions,
    ) {
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for &i in self.bodies_of(leaf) {
            lo = lo.min(x[i]);
            hi = hi.max(x[i]);
        }
        lists.far.iter_mut().for_each(Vec::clear);
        lists.near.iter_mut().for_each(Vec::clear);
        let stack = &mut lists.stack;
        stack.clear();
        stack.push(0_usize);
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n];
            if node.mass == 0.0 {
                continue;
            }
            let gap = (lo - node.centre).max(node.centre - hi).max(DVec2::ZERO);
            let reaches = (node.corner.cmple(hi) & (node.corner + node.side).cmpge(lo)).all();
            if !reaches && node.side * node.side < theta * theta * gap.length_squared() {
                let [xx, xy, yy] = node.quadrupole;
                let cell = [node.centre.x, node.centre.y, node.mass, xx, xy, yy];
                for (list, value) in lists.far.iter_mut().zip(cell) {
                    list.push(value);
                }
                continue;
            }
            match node.quarters {
                Some(quarters) => stack.extend(quarters.into_iter().rev()),
                None => {
                    for &j in self.bodies_of(n) {
                        for (list, value) in lists.near.iter_mut().zip([x[j].x, x[j].y, mass[j]]) {
                            list.push(value);
                        }
                    }
                }
            }
        }
    }
}

impl Interactions {
    /// Σ mⱼ (xⱼ − xᵢ)/|xⱼ − xᵢ|³ over the other bodies, approximated (per kg and per G):
    /// a far cell's monopole and quadrupole, the near bodies one at a time.
    fn acceleration(&self, p: DVec2, softening2: f64) -> DVec2 {
        super::direct::dispatch(Sum {
            lists: self,
            p,
            softening2,
            potential: false,
        })
    }

    /// Σ mⱼ / |xⱼ − xᵢ| over the other bodies, approximated like [`Self::acceleration`]:
    /// a far cell's monopole and quadrupole, M/|D| + (DᵀQD)/(2|D|⁵) (per kg and per G).
    fn inverse_distance_sum(&self, p: DVec2, softening2: f64) -> f64 {
        super::direct::dispatch(Sum {
            lists: self,
            p,
            softening2,
            potential: true,
        })
        .x
    }
}

/// The sums of [`Interactions`] at a body at `p` (a near body at `p` itself is skipped):
/// the acceleration, or in x the inverse-distance sum when `potential`. In [`LANES`]
/// lanes, each summed on its own and the lanes added in a fixed order, so the bits do
/// not depend on the instruction set, as in [`super::direct`].
struct Sum<'a> {
    lists: &'a Interactions,
    p: DVec2,
    /// ε², beside every r².
    softening2: f64,
    potential: bool,
}

impl WithSimd for Sum<'_> {
    type Output = DVec2;

    #[inline(always)]
    fn with_simd<S: Simd>(self, simd: S) -> DVec2 {
        let Sum {
            lists,
            p,
            softening2,
            potential,
        } = self;
        let at = (p, softening2);
        let mut sums = ([0.0; LANES], [0.0; LANES]);
        let plain = pulp::Scalar::new();
        let tail = add_terms(
            simd,
            &lists.far,
            &mut sums,
            |cell| far_term(simd, at, cell, potential),
            |cell| far_term(plain, at, cell, potential),
        ) + add_terms(
            simd,
            &lists.near,
            &mut sums,
            |body| near_term(simd, at, body, potential),
            |body| near_term(plain, at, body, potential),
        );
        DVec2::new(sum_lanes(&sums.0), sum_lanes(&sums.1)) + tail
    }
}

/// Adds `vector(entry)` for the entries of the lists (one list per quantity, all of one
/// length) to the lane sums, [`LANES`] entries at a time, and returns the sum of
/// `plain(entry)` over the entries left over.
#[inline(always)]
fn add_terms<S: Simd, const K: usize>(
    simd: S,
    lists: &[Vec<f64>; K],
    sums: &mut ([f64; LANES], [f64; LANES]),
    vector: impl Fn([S::f64s; K]) -> (S::f64s, S::f64s),
    plain: impl Fn([f64; K]) -> (f64, f64),
) -> DVec2 {
    let len = lists[0].len();
    let whole = len - len % LANES;
    for j in (0..whole).step_by(LANES) {
        let entries: [&[S::f64s]; K] = std::array::from_fn(|k| lanes::<S>(&lists[k], j));
        let (ax, ay) = (
            S::as_mut_simd_f64s(&mut sums.0).0,
            S::as_mut_simd_f64s(&mut sums.1).0,
        );
        for v in 0..ax.len() {
            let (x, y) = vector(std::array::from_fn(|k| entries[k][v]));
            ax[v] = simd.add_f64s(ax[v], x);
            ay[v] = simd.add_f64s(ay[v], y);
        }
    }
    (whole..len)
        .map(|j| plain(std::array::from_fn(|k| lists[k][j])))
        .fold(DVec2::ZERO, |tail, (x, y)| tail + DVec2::new(x, y))
}

/// A far cell's pull on a body at `p` per kg and per G, with D from the body to the
/// cell's centre: M D/|D|³ − Q D/|D|⁵ + (5/2)(DᵀQD) D/|D|⁷ (monopole and quadrupole),
/// or in x M/|D| + (DᵀQD)/(2|D|⁵) when `potential`; |D|² is softened to |D|² + ε².
#[inline(always)]
fn far_term<S: Simd>(
    simd: S,
    (p, softening2): (DVec2, f64),
    cell: [S::f64s; 6],
    potential: bool,
) -> (S::f64s, S::f64s) {
    let [cx, cy, m, xx, xy, yy] = cell;
    let (add, sub, mul) = (
        |a, b| simd.add_f64s(a, b),
        |a, b| simd.sub_f64s(a, b),
        |a, b| simd.mul_f64s(a, b),
    );
    let splat = |value| simd.splat_f64s(value);
    let dx = sub(cx, splat(p.x));
    let dy = sub(cy, splat(p.y));
    let r2 = pair::softened_square(simd, dx, dy, splat(softening2));
    let (qdx, qdy) = (add(mul(xx, dx), mul(xy, dy)), add(mul(xy, dx), mul(yy, dy)));
    let dqd = add(mul(dx, qdx), mul(dy, qdy));
    let inverse_r2 = simd.div_f64s(splat(1.0), r2);
    let inverse_r = simd.sqrt_f64s(inverse_r2);
    let inverse_r3 = mul(inverse_r, inverse_r2);
    let inverse_r5 = mul(inverse_r3, inverse_r2);
    if potential {
        let value = add(mul(m, inverse_r), mul(mul(splat(0.5), dqd), inverse_r5));
        return (value, splat(0.0));
    }
    let radial = add(
        mul(m, inverse_r3),
        mul(mul(mul(splat(2.5), dqd), inverse_r5), inverse_r2),
    );
    (
        sub(mul(dx, radial), mul(qdx, inverse_r5)),
        sub(mul(dy, radial), mul(qdy, inverse_r5)),
    )
}

/// A near body's pull on a body at `p` per kg and per G, m D/|D|³, or in x m/|D| when
/// `potential`, with |D|² softened to |D|² + ε²; nothing from a body at `p` itself.
#[inline(always)]
fn near_term<S: Simd>(
    simd: S,
    (p, softening2): (DVec2, f64),
    body: [S::f64s; 3],
    potential: bool,
) -> (S::f64s, S::f64s) {
    let [bx, by, m] = body;
    let zero = simd.splat_f64s(0.0);
    let dx = simd.sub_f64s(bx, simd.splat_f64s(p.x));
    let dy = simd.sub_f64s(by, simd.splat_f64s(p.y));
    let d2 = simd.add_f64s(simd.mul_f64s(dx, dx), simd.mul_f64s(dy, dy));
    let other = simd.greater_than_f64s(d2, zero);
    let r2 = pair::softened_square(simd, dx, dy, simd.splat_f64s(softening2));
    if potential {
        let value = simd.div_f64s(m, simd.sqrt_f64s(r2));
        return (simd.select_f64s(other, value, zero), zero);
    }
    let s = simd.div_f64s(m, pair::cube(simd, r2));
    let s = simd.select_f64s(other, s, zero);
    (simd.mul_f64s(dx, s), simd.mul_f64s(dy, s))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sums at one point, in vectors of `simd`'s width: the pull, and the
    /// inverse-distance sum.
    /// A softening that every sum below feels.
    const SOFTENING2: f64 = 0.4;

    fn sums_in<S: Simd>(simd: S, lists: &Interactions, p: DVec2) -> (DVec2, DVec2) {
        let pull = Sum {
            lists,
            p,
            softening2: SOFTENING2,
            potential: false,
        }
        .with_simd(simd);
        let potential = Sum {
            lists,
            p,
            softening2: SOFTENING2,
            potential: true,
        }
        .with_simd(simd);
        (pull, potential)
    }

    /// Every instruction set the processor has gives the same bits as plain arithmetic,
    /// for far cells and near bodies (the body itself among them, skipped) in numbers
    /// that are not multiples of the lanes.
    #[test]
    fn every_instruction_set_gives_the_same_bits() {
        let mut lists = Interactions::default();
        for k in 0..29_u32 {
            let t = f64::from(k);
            let cell = [30.0 * t.sin(), 20.0 + t, 1.0 + t, 0.3 * t, -0.1 * t, 0.2];
            for (list, value) in lists.far.iter_mut().zip(cell) {
                list.push(value);
            }
        }
        let p = DVec2::new(0.25, -0.5);
        for k in 0..21_u32 {
            let t = f64::from(k);
            let body = if k == 9 {
                [p.x, p.y, 4.0]
            } else {
                [(1.3 * t).cos() * 3.0, (0.7 * t).sin() * 2.0, 1.0 + 0.1 * t]
            };
            for (list, value) in lists.near.iter_mut().zip(body) {
                list.push(value);
            }
        }
        let plain = sums_in(pulp::Scalar::new(), &lists, p);
        assert!(plain.0.is_finite() && plain.1.x.is_finite() && plain.1.x > 0.0);
        #[cfg(target_arch = "x86_64")]
        {
            use pulp::x86::{V2, V3, V4};
            let widths = [
                V2::try_new().map(|simd| sums_in(simd, &lists, p)),
                V3::try_new().map(|simd| sums_in(simd, &lists, p)),
                V4::try_new().map(|simd| sums_in(simd, &lists, p)),
            ];
            for sums in widths.into_iter().flatten() {
                assert_eq!(sums, plain);
            }
        }
        assert_eq!(
            (
                lists.acceleration(p, SOFTENING2),
                lists.inverse_distance_sum(p, SOFTENING2)
            ),
            (plain.0, plain.1.x)
        );
    }
}
