//! Rods and strings: distance constraints, enforced exactly.
//!
//! A rod keeps its two ends at its length L; a taut string does the same and a slack one
//! does nothing. Each holding link k is the constraint C = ½ (|d|² − L²) = 0, with d the
//! vector from its `from` end to its `to` end.
//!
//! - **Forces**, in every force evaluation, so every integrator sees them: the link forces
//!   are the Lagrange multipliers λ that make C̈ = 0 for every holding link under all the
//!   other forces. Link k pulls `from` by λₖ d and `to` by −λₖ d, so its tension is
//!   λₖ |d|. C̈ = d·(`a_to` − `a_from`) + |`v_to` − `v_from`|² is linear in λ: a small
//!   symmetric positive (semi-)definite system M λ = b per *island* (links joined through
//!   a moving particle), solved by Cholesky. A link that depends on others (three rods
//!   pinning one particle in the plane) gets no force of its own.
//! - **Drift**: C̈ = 0 holds C at 0 only up to the integrator's error, so after each step
//!   the positions are projected back onto C = 0 (Gauss–Newton in the mass metric: the
//!   smallest mass-weighted move) and the velocities onto Ċ = 0. The velocity projection
//!   is orthogonal in the kinetic-energy metric: it can only remove kinetic energy, never
//!   add it, and what it removes is of the integrator's order.
//! - **Strings change mode at events located in time**, like impacts: a slack string
//!   reaching its length while its ends separate snaps taut with an impulse (the ends then
//!   separate at −e times the speed they had, e the string's restitution); a taut string
//!   whose tension would turn negative (it would have to push) goes slack. The simulation
//!   finds the instant of either by integrating again from the step's start
//!   ([`crate::Simulation`]).
//!
//! Every system here is built the same way: `M_ck` = −`d_c`·`d_k` (s(k, `to_c`) − s(k,
//! `from_c`)), with s(k, p) = +1/mₚ when p is link k's `from`, −1/mₚ when it is its `to`,
//! and 0 otherwise (a fixed point or a fixed particle never moves: 1/m = 0). An impulse
//! or a position shift δ along the links changes (Ċ or C) by −M δ.

use glam::DVec2;

use crate::tuning::{FULL_LENGTH, PROJECTION_ITERATIONS, PROJECTION_TOLERANCE};

/// What a [`crate::Tie`] holds its ends to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TieKind {
    /// `[[rod]]`: exactly its length, pushing or pulling.
    Rod,
    /// `[[string]]`: at most its length, only pulling; slack when shorter.
    String,
}

impl TieKind {
    /// The scene-file name: `rod` or `string`.
    pub const fn as_str(self) -> &'static str {
        match self {
            Self::Rod => "rod",
            Self::String => "string",
        }
    }
}

/// One end of a rod, string or spring in runtime form.
#[derive(Clone, Copy, Debug)]
pub(crate) enum End {
    /// The particle at this index.
    Particle(usize),
    /// A fixed point, metres.
    Point(DVec2),
}

impl End {
    pub fn position(self, x: &[DVec2]) -> DVec2 {
        match self {
            Self::Particle(i) => x[i],
            Self::Point(p) => p,
        }
    }

    pub fn velocity(self, v: &[DVec2]) -> DVec2 {
        match self {
            Self::Particle(i) => v[i],
            Self::Point(_) => DVec2::ZERO,
        }
    }

    pub fn add_force(self, force: &mut [DVec2], f: DVec2) {
        if let Self::Particle(i) = self {
            force[i] += f;
        }
    }
}

/// A link in runtime form.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Link {
    pub from: End,
    pub to: End,
    /// Metres.
    pub length: f64,
    pub kind: TieKind,
    /// A string's restitution when it snaps taut.
    pub restitution: f64,
}

impl Link {
    pub fn d(&self, x: &[DVec2]) -> DVec2 {
        self.to.position(x) - self.from.position(x)
    }

    fn relative_velocity(&self, v: &[DVec2]) -> DVec2 {
        self.to.velocity(v) - self.from.velocity(v)
    }

    /// s(self, p) of the module doc.
    fn share(&self, end: End, w: &[f64]) -> f64 {
        let End::Particle(p) = end else {
            return 0.0;
        };
        let mut s = 0.0;
        if matches!(self.from, End::Particle(q) if q == p) {
            s += w[p];
        }
        if matches!(self.to, End::Particle(q) if q == p) {
            s -= w[p];
        }
        s
    }

    /// Moves (or kicks) the ends by δ along the link: `from` by δ d / m, `to` by −δ d / m.
    fn shift(&self, d: DVec2, delta: f64, w: &[f64], out: &mut [DVec2]) {
        if let End::Particle(i) = self.from {
            out[i] += d * (delta * w[i]);
        }
        if let End::Particle(i) = self.to {
            out[i] -= d * (delta * w[i]);
        }
    }

    /// Its row of J for the vector `d` from `from` to `to`: Ċ = d·(`v_to` − `v_from`).
    fn rows(&self, d: DVec2) -> Vec<(usize, DVec2)> {
        let mut entries = Vec::with_capacity(2);
        if let End::Particle(p) = self.to {
            entries.push((p, d));
        }
        if let End::Particle(p) = self.from {
            entries.push((p, -d));
        }
        entries
    }

    /// Whether particle `i` is at one of its ends.
    pub fn touches(&self, i: usize) -> bool {
        matches!(self.from, End::Particle(p) if p == i)
            || matches!(self.to, End::Particle(p) if p == i)
    }

    /// Whether it is a string.
    pub fn is_string(&self) -> bool {
        self.kind == TieKind::String
    }
}

/// The rods and strings of a simulation, and which strings are taut.
#[derive(Clone, Debug, Default)]
pub(crate) struct Constraints {
    pub links: Vec<Link>,
    /// Whether each link holds now: a rod always, a string while taut.
    pub taut: Vec<bool>,
    /// Links joined through a moving particle, solved together; each ascending.
    islands: Vec<Vec<usize>>,
}

impl Constraints {
    /// The constraints of these links, with `w` each particle's 1/m.
    pub fn new(links: Vec<Link>, w: &[f64]) -> Self {
        let taut = links.iter().map(|l| !l.is_string()).collect();
        let islands = islands(&links, w);
        Self {
            links,
            taut,
            islands,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.links.is_empty()
    }

    /// Whether particle `i` is tied by a rod or string.
    pub fn touches(&self, i: usize) -> bool {
        self.links.iter().any(|l| l.touches(i))
    }

    /// The holding links of each island, with their vectors d at `x`.
    fn holding<'a>(&'a self, x: &'a [DVec2]) -> impl Iterator<Item = Vec<(usize, DVec2)>> + 'a {
        self.islands.iter().filter_map(move |island| {
            let active: Vec<(usize, DVec2)> = island
                .iter()
                .filter(|&&k| self.taut[k])
                .map(|&k| (k, self.links[k].d(x)))
                .collect();
            (!active.is_empty()).then_some(active)
        })
    }

    /// M of the module doc for the links `active` (with their d), row-major.
    fn matrix(&self, active: &[(usize, DVec2)], w: &[f64]) -> Vec<f64> {
        let m = active.len();
        let mut matrix = vec![0.0; m * m];
        for (c, &(lc, dc)) in active.iter().enumerate() {
            let link_c = &self.links[lc];
            for (k, &(lk, dk)) in active.iter().enumerate() {
                let link_k = &self.links[lk];
                let coupling = link_k.share(link_c.to, w) - link_k.share(link_c.from, w);
                matrix[c * m + k] = -dc.dot(dk) * coupling;
            }
        }
        matrix
    }

    /// Adds the link forces to the accelerations `a` of every other force (m/s²) at
    /// positions `x` and velocities `v`. Returns nothing; [`Self::multipliers`] gives λ.
    pub fn add_forces(&self, x: &[DVec2], v: &[DVec2], w: &[f64], a: &mut [DVec2]) {
        for active in self.holding(x) {
            let lambda = self.multipliers(&active, v, w, a);
            for (&(k, d), l) in active.iter().zip(lambda) {
                self.links[k].shift(d, l, w, a);
            }
        }
    }

    /// [`Self::add_forces`] where particles rest on surfaces (`contacts`: each resting
    /// particle with the surface's unit normal towards it): in an island that holds one
    /// of them, the links and those surfaces answer the other forces together (J W Jᵀ Λ
    /// = −(J a + |`v_rel`|²) over the links' rows and the surfaces' n·a = 0, a surface that
    /// would pull left out and the rest solved again), so a pendulum pressed against a
    /// wall rests there: the wall takes what the rod does not. Returns, for each contact,
    /// how hard its surface presses (m/s², the normal force over the mass) when it was
    /// answered so, `None` when no link holds its particle (the surface answers alone,
    /// after the links, as before).
    pub fn add_forces_with_surfaces(
        &self,
        x: &[DVec2],
        v: &[DVec2],
        w: &[f64],
        a: &mut [DVec2],
        contacts: &[(usize, DVec2)],
    ) -> Vec<Option<f64>> {
        let mut pressed = vec![None; contacts.len()];
        for active in self.holding(x) {
            let resting: Vec<usize> = (0..contacts.len())
                .filter(|&c| {
                    active
                        .iter()
                        .any(|&(k, _)| self.links[k].touches(contacts[c].0))
                })
                .collect();
            if resting.is_empty() {
                let lambda = self.multipliers(&active, v, w, a);
                for (&(k, d), l) in active.iter().zip(lambda) {
                    self.links[k].shift(d, l, w, a);
                }
                continue;
            }
            let mut rows: Vec<(Vec<(usize, DVec2)>, f64)> = active
                .iter()
                .map(|&(k, d)| {
                    let link = &self.links[k];
                    (link.rows(d), link.relative_velocity(v).length_squared())
                })
                .collect();
            let links = rows.len();
            rows.extend(resting.iter().map(|&c| (vec![contacts[c]], 0.0)));
            let mut included = vec![true; rows.len()];
            let lambda = loop {
                let lambda = solve_rows(&rows, &included, w, a);
                let pulling = (links..rows.len())
                    .filter(|&r| included[r] && lambda[r] < 0.0)
                    .min_by(|&r, &s| lambda[r].total_cmp(&lambda[s]));
                match pulling {
                    Some(r) => included[r] = false,
                    None => break lambda,
                }
            };
            apply_rows(&rows, &lambda, w, a);
            for (r, &c) in (links..rows.len()).zip(&resting) {
                if included[r] {
                    pressed[c] = Some(lambda[r] * w[contacts[c].0]);
                }
            }
        }
        pressed
    }

    /// λ of the holding links `active` of one island, given the accelerations `a` of
    /// every other force.
    fn multipliers(
        &self,
        active: &[(usize, DVec2)],
        v: &[DVec2],
        w: &[f64],
        a: &[DVec2],
    ) -> Vec<f64> {
        let mut matrix = self.matrix(active, w);
        let mut b: Vec<f64> = active
            .iter()
            .map(|&(k, d)| {
                let link = &self.links[k];
                let relative = link.relative_velocity(v);
                d.dot(link.to.velocity(a) - link.from.velocity(a)) + relative.length_squared()
            })
            .collect();
        solve(active.len(), &mut matrix, &mut b);
        b
    }

    /// Each link's tension, N (pulling is positive; 0 for a slack string), given the
    /// accelerations `a` of every other force.
    pub fn tensions(&self, x: &[DVec2], v: &[DVec2], w: &[f64], a: &[DVec2]) -> Vec<f64> {
        let mut tension = vec![0.0; self.links.len()];
        for active in self.holding(x) {
            let lambda = self.multipliers(&active, v, w, a);
            for (&(k, d), l) in active.iter().zip(lambda) {
                tension[k] = l * d.length();
            }
        }
        tension
    }

    /// Projects positions onto the links' lengths (holding links, and slack strings
    /// stretched past their length) and then velocities onto the holding links' rates.
    /// Returns the largest length error left, relative to the length (0 when it
    /// converged to rounding).
    pub fn project(&self, x: &mut [DVec2], v: &mut [DVec2], w: &[f64]) -> f64 {
        let mut worst = 0.0_f64;
        for island in &self.islands {
            worst = worst.max(self.project_positions(island, x, w));
            let active: Vec<(usize, DVec2)> = island
                .iter()
                .filter(|&&k| self.taut[k])
                .map(|&k| (k, self.links[k].d(x)))
                .collect();
            if active.is_empty() {
                continue;
            }
            let rates: Vec<f64> = active
                .iter()
                .map(|&(k, d)| d.dot(self.links[k].relative_velocity(v)))
                .collect();
            self.kick(&active, rates, w, v);
        }
        worst
    }

    /// Answers an impact through the links: after the impact's own impulse on the
    /// particles of `row` (each with its part of the contact's normal: the contact's
    /// separation speed is Σ gₚ·vₚ), the impulses along the holding links of their
    /// islands and a further impulse along the contact that keep that separation speed
    /// and leave every link's rate at zero, solved together (J W Jᵀ Λ = −J v, the
    /// contact's row last so that a contact the links already decide gets none). A ball
    /// on a rod to a heavy partner that strikes a wall stops the partner through the rod
    /// instead of bouncing alone and being pulled back through the wall. Returns the
    /// contact's further impulse (N·s, pushing positive), or `None` when no holding link
    /// touches the particles.
    pub fn answer_impact(
        &self,
        x: &[DVec2],
        v: &mut [DVec2],
        w: &[f64],
        row: &[(usize, DVec2)],
    ) -> Option<f64> {
        let touched = |island: &&Vec<usize>| {
            island
                .iter()
                .any(|&k| self.taut[k] && row.iter().any(|&(p, _)| self.links[k].touches(p)))
        };
        let mut rows: Vec<(Vec<(usize, DVec2)>, f64)> = self
            .islands
            .iter()
            .filter(touched)
            .flatten()
            .filter(|&&k| self.taut[k])
            .map(|&k| (self.links[k].rows(self.links[k].d(x)), 0.0))
            .collect();
        if rows.is_empty() {
            return None;
        }
        // The contact's rate is kept as it is: its offset cancels it exactly.
        let separation: f64 = row.iter().map(|&(p, g)| g.dot(v[p])).sum();
        rows.push((row.to_vec(), -separation));
        let lambda = solve_rows(&rows, &vec![true; rows.len()], w, v);
        apply_rows(&rows, &lambda, w, v);
        lambda.last().copied()
    }

    /// Whether every link already holds at `x` and `v` to rounding: each rod (and each
    /// string at its full length) at its length to [`PROJECTION_TOLERANCE`], with its ends
    /// neither closing nor separating by more than 1e-13 of their relative speed (a
    /// state a step's projection left: a saved state). Projecting it again would move it
    /// by an ulp, and a run continued from a saved state would no longer be the run that
    /// saved it, bit for bit.
    pub fn holds(&self, x: &[DVec2], v: &[DVec2]) -> bool {
        self.links.iter().all(|link| {
            let d = link.d(x);
            let length = link.length;
            let off = 0.5 * (d.length_squared() - length * length) / (length * length);
            let at_length = off.abs() <= PROJECTION_TOLERANCE;
            match link.kind {
                TieKind::String if off < -PROJECTION_TOLERANCE => true, // slack
                _ if !at_length => false,
                _ => {
                    let u = link.relative_velocity(v);
                    d.dot(u).abs() <= 1e-13 * d.length() * u.length()
                }
            }
        })
    }

    /// The link furthest from its length at `x` (a rod either way, a string only
    /// stretched), and how far, relative to its length.
    pub fn most_stretched(&self, x: &[DVec2]) -> Option<(usize, f64)> {
        self.links
            .iter()
            .enumerate()
            .map(|(k, link)| {
                let off = link.d(x).length() / link.length - 1.0;
                let off = match link.kind {
                    TieKind::Rod => off.abs(),
                    TieKind::String => off.max(0.0),
                };
                (k, off)
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// Link `k`'s length, m.
    pub fn length(&self, k: usize) -> f64 {
        self.links[k].length
    }

    /// The relative error in link `k`'s length that the rounding of its ends' positions
    /// alone leaves: a link far from the origin for its length cannot be held closer.
    pub fn rounding(&self, k: usize, x: &[DVec2]) -> f64 {
        let link = &self.links[k];
        let far = link
            .from
            .position(x)
            .abs()
            .max_element()
            .max(link.to.position(x).abs().max_element());
        4.0 * far * f64::EPSILON / link.length
    }

    /// Gauss–Newton on C = 0 for the links of `island` that must hold at `x`.
    fn project_positions(&self, island: &[usize], x: &mut [DVec2], w: &[f64]) -> f64 {
        let mut error = 0.0;
        for _ in 0..PROJECTION_ITERATIONS {
            let active: Vec<(usize, DVec2)> = island
                .iter()
                .map(|&k| (k, self.links[k].d(x)))
                .filter(|&(k, d)| self.taut[k] || d.length_squared() > self.links[k].length.powi(2))
                .collect();
            let c: Vec<f64> = active
                .iter()
                .map(|&(k, d)| {
                    let length = self.links[k].length;
                    0.5 * (d.length_squared() - length * length)
                })
                .collect();
            error = active
                .iter()
                .zip(&c)
                .map(|(&(k, _), c)| (c / self.links[k].length.powi(2)).abs())
                .fold(0.0, f64::max);
            if error <= PROJECTION_TOLERANCE {
                return 0.0;
            }
            self.kick(&active, c, w, x);
        }
        // |C|/L² is about the relative length error.
        error
    }

    /// Solves M δ = `rhs` for the links `active` and shifts `target` (positions or
    /// velocities) by δ along each link: afterwards C (or Ċ) has changed by −rhs.
    fn kick(&self, active: &[(usize, DVec2)], mut rhs: Vec<f64>, w: &[f64], target: &mut [DVec2]) {
        let mut matrix = self.matrix(active, w);
        solve(active.len(), &mut matrix, &mut rhs);
        for (&(k, d), delta) in active.iter().zip(rhs) {
            self.links[k].shift(d, delta, w, target);
        }
    }

    /// The rate at which link `k`'s ends separate, m/s (negative: approaching).
    pub fn separation_speed(&self, k: usize, x: &[DVec2], v: &[DVec2]) -> f64 {
        let link = &self.links[k];
        let d = link.d(x);
        let length = d.length();
        if length > 0.0 {
            d.dot(link.relative_velocity(v)) / length
        } else {
            0.0
        }
    }

    /// How far string `k` is from its length, m (negative: stretched past it).
    pub fn slack(&self, k: usize, x: &[DVec2]) -> f64 {
        self.links[k].length - self.links[k].d(x).length()
    }

    /// Snaps string `k` taut: an impulse along it and every holding link of its island,
    /// so that its ends separate at −e times their speed before and the holding links
    /// keep their lengths' rates at zero. The string is then taut if e = 0.
    pub fn snap(&mut self, k: usize, x: &[DVec2], v: &mut [DVec2], w: &[f64]) {
        let island = self
            .islands
            .iter()
            .find(|island| island.contains(&k))
            .cloned()
            .unwrap_or_else(|| vec![k]);
        let active: Vec<(usize, DVec2)> = island
            .iter()
            .filter(|&&j| self.taut[j] || j == k)
            .map(|&j| (j, self.links[j].d(x)))
            .collect();
        let e = self.links[k].restitution;
        let rhs: Vec<f64> = active
            .iter()
            .map(|&(j, d)| {
                let rate = d.dot(self.links[j].relative_velocity(v));
                if j == k { (1.0 + e) * rate } else { rate }
            })
            .collect();
        self.kick(&active, rhs, w, v);
        self.taut[k] = e == 0.0;
    }

    /// Decides at the start of a step which strings are taut: those at full length whose
    /// ends do not approach faster than a hair per step of `h`, and whose tension, with
    /// all of them holding, pulls; a string that would push (or carries nothing) is let
    /// go, the most negative first, until every tension pulls. `a` is the accelerations of every other force.
    /// Returns whether any string changed.
    pub fn choose_taut(
        &mut self,
        x: &[DVec2],
        v: &[DVec2],
        w: &[f64],
        a: &[DVec2],
        h: f64,
    ) -> bool {
        let before = self.taut.clone();
        for k in 0..self.links.len() {
            let link = &self.links[k];
            if link.is_string() {
                let full = self.slack(k, x) <= FULL_LENGTH * link.length;
                let approaching = self.separation_speed(k, x, v) * h < -FULL_LENGTH * link.length;
                self.taut[k] = full && !approaching;
            }
        }
        for _ in 0..=self.links.len() {
            let tension = self.tensions(x, v, w, a);
            let pushing = (0..self.links.len())
                .filter(|&k| self.taut[k] && self.links[k].is_string() && tension[k] <= 0.0)
                .min_by(|&i, &j| tension[i].total_cmp(&tension[j]));
            match pushing {
                Some(k) => self.taut[k] = false,
                None => break,
            }
        }
        before != self.taut
    }
}

/// Groups links into islands: two links share an island when they share a moving
/// particle (a fixed point or fixed particle transmits nothing).
fn islands(links: &[Link], w: &[f64]) -> Vec<Vec<usize>> {
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut parent: Vec<usize> = (0..links.len()).collect();
    let mut owner: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    for (k, link) in links.iter().enumerate() {
        for end in [link.from, link.to] {
            if let End::Particle(p) = end
                && w[p] > 0.0
            {
                match owner.get(&p) {
                    Some(&other) => {
                        let (a, b) = (root(&mut parent, k), root(&mut parent, other));
                        parent[a.max(b)] = a.min(b);
                    }
                    None => {
                        owner.insert(p, k);
                    }
                }
            }
        }
    }
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut index: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    for k in 0..links.len() {
        let r = root(&mut parent, k);
        let g = *index.entry(r).or_insert_with(|| {
            groups.push(Vec::new());
            groups.len() - 1
        });
        groups[g].push(k);
    }
    groups
}

/// Λ for the rows (J's entries by particle, and the rate each adds: J a + c = 0 is
/// wanted) that are `included` (the others get 0): J W Jᵀ Λ = −(J a + c).
fn solve_rows(
    rows: &[(Vec<(usize, DVec2)>, f64)],
    included: &[bool],
    w: &[f64],
    a: &[DVec2],
) -> Vec<f64> {
    let m = rows.len();
    let mut matrix = vec![0.0; m * m];
    let mut b = vec![0.0; m];
    for (r, (first, c)) in rows.iter().enumerate() {
        if !included[r] {
            // A row of its own: Λ = 0.
            matrix[r * m + r] = 1.0;
            continue;
        }
        b[r] = -(first.iter().map(|&(p, g)| g.dot(a[p])).sum::<f64>() + c);
        for (s, (second, _)) in rows.iter().enumerate() {
            if included[s] {
                matrix[r * m + s] = weighted_dot(first, second, w);
            }
        }
    }
    solve(m, &mut matrix, &mut b);
    b
}

/// Adds W Jᵀ Λ to `out` (velocities or accelerations): each row's Λ along its entries.
fn apply_rows(rows: &[(Vec<(usize, DVec2)>, f64)], lambda: &[f64], w: &[f64], out: &mut [DVec2]) {
    for ((entries, _), l) in rows.iter().zip(lambda) {
        for &(p, g) in entries {
            out[p] += g * (w[p] * l);
        }
    }
}

/// Σ wₚ g·h over the particles two rows of J share.
fn weighted_dot(first: &[(usize, DVec2)], second: &[(usize, DVec2)], w: &[f64]) -> f64 {
    first
        .iter()
        .map(|&(p, g)| {
            second
                .iter()
                .filter(|&&(q, _)| q == p)
                .map(|&(_, h)| w[p] * g.dot(h))
                .sum::<f64>()
        })
        .sum()
}

/// Solves M x = b in place (`b` becomes x) for a symmetric positive semi-definite M of
/// size m (row-major, overwritten by its Cholesky factor). A row that depends on the
/// rows before it (its pivot vanishes to rounding) gets x = 0 and is left out.
fn solve(m: usize, matrix: &mut [f64], b: &mut [f64]) {
    let mut dependent = vec![false; m];
    for j in 0..m {
        let scale = matrix[j * m + j];
        let mut pivot = scale;
        for k in 0..j {
            pivot -= matrix[j * m + k] * matrix[j * m + k];
        }
        // Not above the threshold (NaN included): dependent.
        if pivot.partial_cmp(&(1e-10 * scale)) != Some(std::cmp::Ordering::Greater) {
            dependent[j] = true;
            for i in j..m {
                matrix[i * m + j] = 0.0;
            }
            continue;
        }
        let l = pivot.sqrt();
        matrix[j * m + j] = l;
        for i in j + 1..m {
            let mut s = matrix[i * m + j];
            for k in 0..j {
                s -= matrix[i * m + k] * matrix[j * m + k];
            }
            matrix[i * m + j] = s / l;
        }
    }
    for i in 0..m {
        if dependent[i] {
            b[i] = 0.0;
            continue;
        }
        let mut s = b[i];
        for k in 0..i {
            s -= matrix[i * m + k] * b[k];
        }
        b[i] = s / matrix[i * m + i];
    }
    for i in (0..m).rev() {
        if dependent[i] {
            b[i] = 0.0;
            continue;
        }
        let mut s = b[i];
        for k in i + 1..m {
            s -= matrix[k * m + i] * b[k];
        }
        b[i] = s / matrix[i * m + i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solve_gives_zero_for_a_dependent_row_and_solves_the_rest() {
        // Rows 0 and 2 equal: the third equation repeats the first.
        let mut matrix = vec![4.0, 2.0, 4.0, 2.0, 3.0, 2.0, 4.0, 2.0, 4.0];
        let mut b = vec![2.0, 5.0, 2.0];
        solve(3, &mut matrix, &mut b);
        // 4x + 2y = 2, 2x + 3y = 5: x = −0.5, y = 2.
        assert!(
            (b[0] + 0.5).abs() < 1e-12 && (b[1] - 2.0).abs() < 1e-12,
            "{b:?}"
        );
        assert_eq!(b[2].to_bits(), 0.0_f64.to_bits());
    }

    /// A dependent row *before* independent ones, at scales from 1e-6 to 1e8 (the
    /// threshold is relative to the row's own diagonal): M = J Jᵀ with J's second row three
    /// times its first, so the pivot of row 1 vanishes only to rounding. The solution
    /// leaves row 1 out (x₁ = 0 exactly) and solves the rest: for b = M x with
    /// x = (1, 0, 2, −1), it returns x to 1e-9. A dependent row's column must be cleared
    /// for the rows after it, and a threshold not scaled with the diagonal takes rounding
    /// for a pivot at one end of the range or every row for dependent at the other.
    #[test]
    fn solve_leaves_out_a_dependent_row_in_the_middle_at_any_scale() {
        let rows = [
            [0.1, 0.3, 0.7],
            [0.3, 0.9, 2.1],
            [0.2, -0.5, 0.4],
            [1.1, 0.6, -0.3],
        ];
        let x = [1.0, 0.0, 2.0, -1.0];
        for scale in [1e-3, 1.0, 1e4] {
            let j: Vec<[f64; 3]> = rows.iter().map(|r| r.map(|v| v * scale)).collect();
            let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            let mut matrix: Vec<f64> = (0..16).map(|k| dot(&j[k / 4], &j[k % 4])).collect();
            let mut b: Vec<f64> = (0..4)
                .map(|r| (0..4).map(|c| matrix[r * 4 + c] * x[c]).sum())
                .collect();
            solve(4, &mut matrix, &mut b);
            assert_eq!(b[1].to_bits(), 0.0_f64.to_bits(), "scale {scale}: {b:?}");
            for k in [0, 2, 3] {
                assert!((b[k] - x[k]).abs() < 1e-9, "scale {scale}: {b:?}");
            }
        }
    }

    /// Five independent rows, every pair coupled (M = J Jᵀ dense, as an island of five
    /// links sharing particles is not, but the elimination must not care): b = M x gives
    /// back x to 1e-9. The third row on is where each entry sums over the rows before it
    /// (a chain of three links, the tests' largest island, has zeros there).
    #[test]
    fn solve_solves_a_dense_system_of_five_rows() {
        let rows = [
            [1.0, 0.2, 0.3, 0.1, 0.5],
            [0.4, 1.1, 0.2, 0.6, 0.1],
            [0.3, 0.5, 0.9, 0.2, 0.7],
            [0.6, 0.1, 0.4, 1.2, 0.3],
            [0.2, 0.8, 0.1, 0.3, 1.0],
        ];
        let dot = |a: &[f64; 5], b: &[f64; 5]| a.iter().zip(b).map(|(p, q)| p * q).sum::<f64>();
        let mut matrix: Vec<f64> = (0..25).map(|k| dot(&rows[k / 5], &rows[k % 5])).collect();
        let x = [1.0, -2.0, 0.5, 3.0, -1.5];
        let mut b: Vec<f64> = (0..5)
            .map(|r| (0..5).map(|c| matrix[r * 5 + c] * x[c]).sum())
            .collect();
        solve(5, &mut matrix, &mut b);
        for k in 0..5 {
            assert!((b[k] - x[k]).abs() < 1e-9, "{b:?}");
        }
    }
}
