//! Gravitation summed with a Barnes–Hut quadtree (Barnes and Hut, Nature 324, 1986):
//! the bodies are sorted into nested squares, each square knows its total mass and centre
//! of mass, and a square of side s whose centre of mass is at distance d from a body acts
//! on it as one body of that mass when s < θ·d (θ, the opening angle); otherwise its
//! quarters are looked at, down to leaves of a few bodies summed pair by pair. The cost
//! is O(n log n) instead of O(n²); the error is that of the monopole, of order θ² for
//! the nearest groups accepted: `tests` measures it against the direct sum.
//!
//! A body never acts on itself: a square that contains the body is always opened. The
//! tree is rebuilt for each force evaluation from the positions given, in a fixed order,
//! so the result is the same bits for the same positions. Forces are not summed in
//! equal and opposite pairs, so the total momentum drifts by the error of the forces.

use glam::DVec2;

use crate::parallel::Workers;

/// Bodies per leaf: below this a square is summed directly.
const LEAF: usize = 16;
/// Deepest square: bodies closer than 2⁻⁴⁸ of the whole extent share a leaf.
const DEPTH: u32 = 48;

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
/// the sum over the other bodies approximated as above.
///
/// Each body's sum is its own, so the bodies are shared out among `workers`' threads
/// with the same bits for any number of them.
pub(crate) fn gravitation(
    g: f64,
    theta: f64,
    bodies: &[usize],
    (x, mass): (&[DVec2], &[f64]),
    workers: &Workers,
    force: &mut [DVec2],
) {
    if bodies.len() < 2 {
        return;
    }
    let tree = Tree::build(bodies, x, mass);
    let mut accelerations = Vec::with_capacity(bodies.len());
    workers.collect_into(bodies.len(), &mut accelerations, |range, out| {
        out.extend(
            bodies[range]
                .iter()
                .map(|&i| tree.acceleration(i, theta, x, mass)),
        );
    });
    for (&i, a) in bodies.iter().zip(accelerations) {
        force[i] += a * (g * mass[i]);
    }
}

/// The gravitational potential energy of `bodies`, −G Σ mᵢ mⱼ / rᵢⱼ over their pairs,
/// with each body's potential summed through the tree as its force is (monopole and
/// quadrupole of each cell far enough away): the energy to the accuracy of the forces.
/// The bodies are shared out among `workers`' threads and their terms added in order:
/// the same bits for any number of threads.
pub(crate) fn potential_energy(
    g: f64,
    theta: f64,
    bodies: &[usize],
    (x, mass): (&[DVec2], &[f64]),
    workers: &Workers,
) -> f64 {
    if bodies.len() < 2 {
        return 0.0;
    }
    let tree = Tree::build(bodies, x, mass);
    let mut terms = Vec::with_capacity(bodies.len());
    workers.collect_into(bodies.len(), &mut terms, |range, out| {
        out.extend(
            bodies[range]
                .iter()
                .map(|&i| mass[i] * tree.inverse_distance_sum(i, theta, x, mass)),
        );
    });
    // Each pair is counted from both ends.
    -0.5 * g * terms.iter().sum::<f64>()
}

/// What a walk of the tree meets.
enum Term<'a> {
    /// A cell far enough away to act as a whole: the cell, D from the body to its
    /// centre of mass, and |D|².
    Far(&'a Node, DVec2, f64),
    /// Another body, one at a time.
    Near(usize),
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
        if end - start <= LEAF || depth >= DEPTH {
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
        scratch.clear();
        let mut ends = [0; 4];
        for (q, end_of_quarter) in ends.iter_mut().enumerate() {
            scratch.extend(
                self.order[start..end]
                    .iter()
                    .copied()
                    .filter(|&i| quarter(x[i]) == q),
            );
            *end_of_quarter = start + scratch.len();
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

    /// Walks the tree for body `i`, giving `visit` each cell far enough away (its side
    /// under `theta` times its distance, and `i` not inside it) and every other body of
    /// the cells that are not.
    fn walk(&self, i: usize, theta: f64, x: &[DVec2], mut visit: impl FnMut(Term<'_>)) {
        let xi = x[i];
        let mut stack = Vec::with_capacity(4 * DEPTH as usize);
        stack.push(0_usize);
        while let Some(n) = stack.pop() {
            let node = &self.nodes[n];
            if node.mass == 0.0 {
                continue;
            }
            let d = node.centre - xi;
            let r2 = d.length_squared();
            let inside = xi.cmpge(node.corner).all() && xi.cmplt(node.corner + node.side).all();
            if !inside && node.side * node.side < theta * theta * r2 {
                visit(Term::Far(node, d, r2));
                continue;
            }
            match node.quarters {
                Some(quarters) => stack.extend(quarters.into_iter().rev()),
                None => self.order[node.start..node.end]
                    .iter()
                    .filter(|&&j| j != i)
                    .for_each(|&j| visit(Term::Near(j))),
            }
        }
    }

    /// Σ mⱼ (xⱼ − xᵢ)/|xⱼ − xᵢ|³ over the other bodies, approximated (per kg and per G).
    fn acceleration(&self, i: usize, theta: f64, x: &[DVec2], mass: &[f64]) -> DVec2 {
        let xi = x[i];
        let mut sum = DVec2::ZERO;
        self.walk(i, theta, x, |term| match term {
            Term::Far(node, d, r2) => {
                // Monopole and quadrupole: with D from the body to the centre,
                // M D/|D|³ − Q D/|D|⁵ + (5/2)(DᵀQD) D/|D|⁷.
                let [xx, xy, yy] = node.quadrupole;
                let qd = DVec2::new(xx * d.x + xy * d.y, xy * d.x + yy * d.y);
                let inverse_r2 = 1.0 / r2;
                let inverse_r3 = inverse_r2.sqrt() * inverse_r2;
                let inverse_r5 = inverse_r3 * inverse_r2;
                sum += d * (node.mass * inverse_r3) - qd * inverse_r5
                    + d * (2.5 * d.dot(qd) * inverse_r5 * inverse_r2);
            }
            Term::Near(j) => {
                let d = x[j] - xi;
                let r2 = d.length_squared();
                sum += d * (mass[j] / (r2 * r2.sqrt()));
            }
        });
        sum
    }

    /// Σ mⱼ / |xⱼ − xᵢ| over the other bodies, approximated like [`Self::acceleration`]:
    /// a far cell's monopole and quadrupole, M/|D| + (DᵀQD)/(2|D|⁵) (per kg and per G).
    fn inverse_distance_sum(&self, i: usize, theta: f64, x: &[DVec2], mass: &[f64]) -> f64 {
        let xi = x[i];
        let mut sum = 0.0;
        self.walk(i, theta, x, |term| match term {
            Term::Far(node, d, r2) => {
                let [xx, xy, yy] = node.quadrupole;
                let qd = DVec2::new(xx * d.x + xy * d.y, xy * d.x + yy * d.y);
                let inverse_r = 1.0 / r2.sqrt();
                let inverse_r5 = inverse_r * inverse_r * inverse_r * inverse_r * inverse_r;
                sum += node.mass * inverse_r + 0.5 * d.dot(qd) * inverse_r5;
            }
            Term::Near(j) => sum += mass[j] / x[j].distance(xi),
        });
        sum
    }
}
