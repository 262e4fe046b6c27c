//! Resting contact after a step: removes every approach between touching bodies with
//! inelastic impulses, then corrects overlaps beyond the tolerance.
//!
//! Sequential impulses with warm starting (as in Box2D): each contact starts from the
//! impulse it needed in the last step, which already carries the weight of whatever rests
//! on it, and sweeps adjust the accumulated impulse, never below zero (a contact can
//! push, not pull). Without warm starting a pile n balls deep needs some n² sweeps to
//! pass its weight down and sinks in the meantime.
//!
//! Each contact's normal and effective mass are fixed for the solve (they change
//! negligibly within it), so a sweep costs a dot product per contact. The rows are laid
//! out for the sweep: the pairs column by column, taken several at a time in vectors
//! ([`columns`]), the surface contacts (a few) as rows of particle, normal, inverse mass
//! and accumulated impulse side by side, so the inner loops touch nothing else. Pairs
//! are swept before surfaces, each with the result of sweeping them in ascending order,
//! as the touching lists are (in an order that gives the same bits and lets the
//! processor overlap rows, [`Schedule`], the rows built or copied into it before the warm
//! starts): the result does not depend on anything but the scene.

mod columns;

use glam::DVec2;

use self::columns::PairColumns;
use super::obstacles::Obstacle;
use super::{separation, smaller};
use crate::state::State;
use crate::tuning::{ALLOWED_OVERLAP, CORRECTION, POSITION_SWEEPS, RESTING_SWEEPS};

/// The speed below which the sweeps count a contact as settled, m/s, when a resting
/// contact approaches at `resting_speed`: what they leave of an approach (or of a slip)
/// is below it, so a speed this small on a resting particle is the solver's, not motion.
pub(crate) fn settled_speed(resting_speed: f64) -> f64 {
    1e-4 * resting_speed.max(1e-9)
}

/// What every row of the solver accumulates.
#[derive(Clone, Copy, Debug)]
struct Accumulator {
    /// The effective mass, kg: the impulse per unit of approach speed removed. Zero for a
    /// row left out of this solve (a blow being passed on, or immovable bodies), which
    /// then never changes: the sweep has no branch for it.
    mass: f64,
    /// Accumulated impulse, N·s.
    impulse: f64,
}

impl Accumulator {
    /// A row removing `inverse_mass` (1/kg) of approach speed per unit of impulse.
    fn new(inverse_mass: f64) -> Self {
        Self {
            mass: if inverse_mass > 0.0 {
                1.0 / inverse_mass
            } else {
                0.0
            },
            impulse: 0.0,
        }
    }
}

/// A touching pair in the solver: particles `i < j`, the normal from `i` towards `j`.
/// Built one at a time and set into the [`PairColumns`] the sweeps take; as a [`Row`] it
/// is also swept alone, the arithmetic the columns' lanes are tested against.
#[derive(Clone, Copy, Debug)]
struct PairRow {
    i: u32,
    j: u32,
    normal: DVec2,
    /// 1/m of each particle, 1/kg.
    inverse_mass_i: f64,
    inverse_mass_j: f64,
    solved: Accumulator,
    /// The distance between the centres, along `normal`, below which the overlap is
    /// corrected: the radii less the tolerance, metres.
    reach: f64,
    /// 1 / (2 × the distance between the centres when the row was built), 1/m: the
    /// curvature of the distance across the normal.
    bend: f64,
    /// The share of an overlap corrected in a sweep over the sum of the inverse masses,
    /// kg; zero when both particles are fixed.
    correction: f64,
}

/// A particle touching a surface, the normal from the surface towards the particle.
#[derive(Clone, Copy, Debug)]
struct SurfaceRow {
    particle: u32,
    obstacle: u32,
    normal: DVec2,
    /// 1/m, 1/kg.
    inverse_mass: f64,
    solved: Accumulator,
    /// The particle's position along `normal` below which its overlap is corrected,
    /// metres: where it was when the row was built, plus the overlap beyond the
    /// tolerance then.
    reach: f64,
}

/// Friction where a particle rests on a surface with friction, answering the normal
/// impulse of its [`SurfaceRow`]: the surface's normal force from the smooth forces
/// carries its own friction (`forces/normal.rs`), and this row is friction's share of
/// the push that other particles press it into the surface with (a disc wedged between
/// a wall and a disc, a disc rolling on a floor that a disc above pushes along). Coulomb:
/// the impulse that stops its contact point slipping, at most μ times the normal row's.
#[derive(Clone, Copy, Debug)]
struct FrictionRow {
    /// The normal row's place in the arranged surface rows.
    surface: u32,
    particle: u32,
    /// The surface's tangent (its normal turned a quarter counter-clockwise).
    tangent: DVec2,
    /// μ, the surface's coefficient of (kinetic) friction.
    friction: f64,
    /// The friction impulse the smooth normal force leaves unused over the step, N·s:
    /// friction may give that besides μ times the normal row's impulse.
    spare: f64,
    /// 1/m, 1/kg.
    inverse_mass: f64,
    /// The impulse per unit of slip stopped, kg: 1 / (w (1 + 1/k)) for a particle that
    /// turns (its spin takes a share), 1 / w for a point.
    mass: f64,
    /// Metres, and the spin an impulse of 1 N·s along the tangent gives, −w / (k r)
    /// rad/s (its torque at the contact point −r n); 0 for a point.
    radius: f64,
    spin_per_impulse: f64,
    /// Accumulated impulse along the tangent, N·s.
    impulse: f64,
}

impl FrictionRow {
    /// Its contact point's velocity along the tangent, m/s: v·t − ω r.
    fn slip(&self, velocity: &[DVec2], spin: &[f64]) -> f64 {
        let p = self.particle as usize;
        let turning = if self.spin_per_impulse == 0.0 {
            0.0
        } else {
            spin[p] * self.radius
        };
        velocity[p].dot(self.tangent) - turning
    }
}

/// One sweep of the friction rows, each bounded by its normal row's accumulated impulse
/// in `surfaces`. Returns the largest change of a slip it made, m/s.
fn sweep_friction(
    rows: &mut [FrictionRow],
    surfaces: &[SurfaceRow],
    velocity: &mut [DVec2],
    spin: &mut [f64],
) -> f64 {
    let mut largest: f64 = 0.0;
    for row in rows {
        let limit = row.friction * surfaces[row.surface as usize].solved.impulse + row.spare;
        let wanted = row.impulse - row.slip(velocity, spin) * row.mass;
        let accumulated = wanted.max(-limit).min(limit);
        let change = accumulated - row.impulse;
        row.impulse = accumulated;
        let p = row.particle as usize;
        velocity[p] += row.tangent * (change * row.inverse_mass);
        if row.spin_per_impulse != 0.0 {
            spin[p] += change * row.spin_per_impulse;
        }
        largest = largest.max((change / row.mass).abs());
    }
    largest
}

/// A contact as the sweeps see it.
trait Row {
    /// Approach speed along the normal, m/s, positive when closing.
    fn approach(&self, velocity: &[DVec2]) -> f64;
    /// Applies an impulse of `amount` N·s along the normal.
    fn push(&self, amount: f64, velocity: &mut [DVec2]);
    /// The approach speed removed per unit of impulse, 1/kg.
    fn inverse_mass(&self) -> f64;
    fn solved(&mut self) -> &mut Accumulator;
}

impl Row for PairRow {
    fn approach(&self, velocity: &[DVec2]) -> f64 {
        (velocity[self.i as usize] - velocity[self.j as usize]).dot(self.normal)
    }

    /// The paper's 8–10.
    fn push(&self, amount: f64, velocity: &mut [DVec2]) {
        let impulse = self.normal * amount;
        velocity[self.i as usize] -= impulse * self.inverse_mass_i;
        velocity[self.j as usize] += impulse * self.inverse_mass_j;
    }

    fn inverse_mass(&self) -> f64 {
        self.inverse_mass_i + self.inverse_mass_j
    }

    fn solved(&mut self) -> &mut Accumulator {
        &mut self.solved
    }
}

impl Row for SurfaceRow {
    fn approach(&self, velocity: &[DVec2]) -> f64 {
        -velocity[self.particle as usize].dot(self.normal)
    }

    /// The paper's 17–22.
    fn push(&self, amount: f64, velocity: &mut [DVec2]) {
        velocity[self.particle as usize] += self.normal * (amount * self.inverse_mass);
    }

    fn inverse_mass(&self) -> f64 {
        self.inverse_mass
    }

    fn solved(&mut self) -> &mut Accumulator {
        &mut self.solved
    }
}

/// Warm-starts the rows, each built with its impulse of the last step (scaled to this
/// one), in their order: a row that is a blow being passed on (approaching faster than
/// `resting_speed`, and `struck`: one of its particles was struck in this step) is left
/// out, its effective mass zeroed; any other applies its impulse. Returns whether any
/// did.
///
/// The surface rows' (the pairs' is [`PairColumns::warm_start`], the same arithmetic),
/// done over the rows arranged in the schedule's order, not as they are built: each row's
/// test reads the velocities the rows before it with a particle in common left, so in
/// the lists' order, where most rows share a particle with the one before, each waited
/// for the last (measured: 24 µs of the 40 µs that building the settled 1,000-ball
/// pile's rows took).
fn warm_start<R: Row>(
    rows: &mut [R],
    velocity: &mut [DVec2],
    resting_speed: f64,
    struck: impl Fn(&R) -> bool,
) -> bool {
    let mut any = false;
    for row in rows {
        if row.approach(velocity) > resting_speed && struck(row) {
            row.solved().mass = 0.0;
        }
        let solved = row.solved();
        let last = solved.impulse;
        if solved.mass == 0.0 || last <= 0.0 {
            solved.impulse = 0.0;
            continue;
        }
        row.push(last, velocity);
        any = true;
    }
    any
}

/// One Gauss–Seidel sweep: each row's accumulated impulse becomes the one that stops its
/// approach, kept from pulling in total. Returns the largest change of an approach speed
/// it made (m/s), or `None` when no row changed.
///
/// The loop has no branch: a row left out has a zero effective mass and pushes nothing,
/// and pushing nothing adds zero to the velocities.
fn sweep<R: Row>(rows: &mut [R], velocity: &mut [DVec2]) -> Option<f64> {
    let mut largest: f64 = 0.0;
    let mut any = false;
    for row in rows {
        let solved = *row.solved();
        let approach = row.approach(velocity);
        // Comparisons, not `f64::max`: WebAssembly has no instruction with its rule for
        // NaN, so there it is a call to `fmax`, which a V8 profile of the pit
        // (`benches/wasm`) found mostly called from here.
        let accumulated = solved.impulse + approach * solved.mass;
        let accumulated = if accumulated > 0.0 { accumulated } else { 0.0 };
        let change = accumulated - solved.impulse;
        row.push(change, velocity);
        row.solved().impulse = accumulated;
        let changed_by = (change * row.inverse_mass()).abs();
        if changed_by > largest {
            largest = changed_by;
        }
        any |= change != 0.0;
    }
    any.then_some(largest)
}

/// The last step's impulses, read for this step's contacts in ascending order: both lists
/// are sorted by key, so one pass through the old list finds every match.
struct Remembered<'a> {
    last: &'a [((u32, u32), f64)],
}

impl<'a> Remembered<'a> {
    fn new(last: &'a [((u32, u32), f64)]) -> Self {
        Self { last }
    }

    /// The impulse of the contact `key` in the last step, N·s, or 0 for a new contact.
    /// Keys must be asked for in ascending order.
    fn impulse(&mut self, key: (u32, u32)) -> f64 {
        while self.last.first().is_some_and(|&(k, _)| k < key) {
            self.last = &self.last[1..];
        }
        match self.last.first() {
            Some(&(k, impulse)) if k == key => impulse,
            _ => 0.0,
        }
    }
}

/// What the resting solver needs of the contacts around it.
pub(crate) struct Touching<'a> {
    /// Pairs (i < j) touching at the start of the step, ascending.
    pub pairs: &'a [(u32, u32)],
    /// (particle, obstacle) touching at the start of the step, ascending.
    pub surfaces: &'a [(u32, u32)],
    pub obstacles: &'a [Obstacle],
    /// Metres, per particle.
    pub radius: &'a [f64],
    /// 1/kg, per particle; zero for fixed particles.
    pub inverse_mass: &'a [f64],
    /// k = I/(m r²) per particle, when any turns.
    pub inertia: Option<&'a [f64]>,
    /// Per surface contact, in `surfaces`' order: the friction its smooth normal force
    /// leaves unused, m/s² ([`super::surfaces::StartContacts::spare_friction`]).
    pub spare_friction: &'a [f64],
}

/// The resting solver's memory from step to step, and its scratch rows.
#[derive(Clone, Debug, Default)]
pub(crate) struct RestingSolver {
    /// Each touching pair's and surface contact's impulse in the last step, by key, for
    /// warm starting; and that step's length, seconds.
    last_pairs: Vec<((u32, u32), f64)>,
    last_surfaces: Vec<((u32, u32), f64)>,
    last_step: f64,
    /// The rows, in the order the sweeps take them ([`Schedule`]).
    pairs: PairColumns,
    surfaces: Vec<SurfaceRow>,
    friction: Vec<FrictionRow>,
    schedule: Schedule,
    /// Scratch: the rows as built, in the touching lists' order.
    built_surfaces: Vec<SurfaceRow>,
    /// Scratch: whether each particle touches another, for the friction rows.
    pushed: Vec<bool>,
}

impl RestingSolver {
    /// Frees the rows and their schedule, which every solve builds again; the last
    /// impulses stay.
    pub fn drop_scratch(&mut self) {
        self.pairs = PairColumns::default();
        self.surfaces = Vec::new();
        self.friction = Vec::new();
        self.schedule = Schedule::default();
        self.built_surfaces = Vec::new();
        self.pushed = Vec::new();
    }

    /// The bytes of the last impulses, by length.
    pub fn memory_bytes(&self) -> usize {
        (self.last_pairs.len() + self.last_surfaces.len()) * size_of::<((u32, u32), f64)>()
    }

    /// Solves the resting contacts after a step of `h`. A fast approach of a particle for
    /// which `is_struck` holds (an impact struck it in this step) is a blow being passed
    /// on (a row of touching balls), left to the impacts at the start of the next step,
    /// which give it its restitution. Returns whether anything changed.
    pub fn solve(
        &mut self,
        touching: &Touching<'_>,
        state: &mut State,
        h: f64,
        resting_speed: f64,
        is_struck: impl Fn(usize) -> bool,
        spin: &mut [f64],
    ) -> bool {
        // Scaled down after a longer step, never up after a shorter one: what a short
        // step's rows took is mostly the approach they stopped, not the weight they
        // carried (which grows with the step), and scaled by the steps' ratio (a step
        // cut to a rolling start some 1e-20 s in, then a whole one) it became a blow of
        // millions of m/s that the sweeps could not take back. The weight missing after
        // a short step is found by the sweeps.
        let warm = if self.last_step > 0.0 {
            (h / self.last_step).min(1.0)
        } else {
            0.0
        };
        let (position, velocity) = (&state.position, &mut state.velocity);
        let w = touching.inverse_mass;
        let mut changed = false;
        // The schedule first, from the touching lists: each pair row is built straight
        // into its place in the columns.
        self.schedule.order(
            velocity.len(),
            touching.pairs.iter().copied(),
            touching.surfaces.iter().map(|&(p, _)| (p, p)),
        );
        self.pairs.resize(touching.pairs.len());
        let mut last_pairs = Remembered::new(&self.last_pairs);
        for (&(i, j), &place) in touching.pairs.iter().zip(&self.schedule.pair_places) {
            let (a, b) = (i as usize, j as usize);
            let (distance, normal) = separation(position[b] - position[a]);
            let radius = (touching.radius[a], touching.radius[b]);
            let mut solved = Accumulator::new(w[a] + w[b]);
            // Warm start: last step's impulse, scaled to this step (applied below).
            solved.impulse = last_pairs.impulse((i, j)) * warm;
            self.pairs.set(
                place as usize,
                &PairRow {
                    i,
                    j,
                    normal,
                    inverse_mass_i: w[a],
                    inverse_mass_j: w[b],
                    solved,
                    reach: radius.0 + radius.1 - ALLOWED_OVERLAP * smaller(radius.0, radius.1),
                    bend: if distance > 0.0 { 0.5 / distance } else { 0.0 },
                    // CORRECTION / (w[a] + w[b]) to the bit, one division fewer: CORRECTION
                    // is a power of two.
                    correction: CORRECTION * solved.mass,
                },
            );
        }
        self.built_surfaces.clear();
        let mut last_surfaces = Remembered::new(&self.last_surfaces);
        for &(p, k) in touching.surfaces {
            let at = position[p as usize];
            let (distance, normal) = touching.obstacles[k as usize].shape.distance(at);
            let radius = touching.radius[p as usize];
            let mut solved = Accumulator::new(w[p as usize]);
            solved.impulse = last_surfaces.impulse((p, k)) * warm; // applied below
            self.built_surfaces.push(SurfaceRow {
                particle: p,
                obstacle: k,
                normal,
                inverse_mass: w[p as usize],
                solved,
                reach: at.dot(normal) + radius * (1.0 - ALLOWED_OVERLAP) - distance,
            });
        }
        arrange(
            &self.built_surfaces,
            &self.schedule.surfaces,
            &mut self.surfaces,
        );
        self.build_friction(touching, h);
        changed |= self.pairs.warm_start(velocity, resting_speed, &is_struck);
        changed |= warm_start(&mut self.surfaces, velocity, resting_speed, |r| {
            is_struck(r.particle as usize)
        });
        let tolerance = settled_speed(resting_speed);
        for _ in 0..RESTING_SWEEPS {
            let pairs = self.pairs.sweep(&self.schedule.pair_levels, velocity);
            let surfaces = sweep(&mut self.surfaces, velocity);
            let friction = if self.friction.is_empty() {
                None
            } else {
                let slipped = sweep_friction(&mut self.friction, &self.surfaces, velocity, spin);
                (slipped > 0.0).then_some(slipped)
            };
            let largest = match (pairs, surfaces, friction) {
                (None, None, None) => break,
                (a, b, c) => a.unwrap_or(0.0).max(b.unwrap_or(0.0)).max(c.unwrap_or(0.0)),
            };
            changed = true;
            if largest <= tolerance {
                break;
            }
        }
        changed |= self.correct_overlaps(&mut state.position);
        // Remembered by key, ascending: each row back in its place in the touching lists.
        self.last_pairs.clear();
        self.last_pairs.resize(self.pairs.len(), ((0, 0), 0.0));
        let rows = &self.pairs;
        for (row, &k) in self.schedule.pairs.iter().enumerate() {
            self.last_pairs[k as usize] = ((rows.i[row], rows.j[row]), rows.impulse[row]);
        }
        self.last_surfaces.clear();
        self.last_surfaces
            .resize(self.surfaces.len(), ((0, 0), 0.0));
        for (row, &k) in self.surfaces.iter().zip(&self.schedule.surfaces) {
            self.last_surfaces[k as usize] = ((row.particle, row.obstacle), row.solved.impulse);
        }
        self.last_step = h;
        changed
    }

    /// The friction rows of the arranged surface rows whose surface has friction and
    /// whose particle touches another (which alone can push it on the surface: a lone
    /// particle's normal row only takes an approach of rounding, and its friction is the
    /// smooth normal force's), for a step of `h`, in their order.
    fn build_friction(&mut self, touching: &Touching<'_>, h: f64) {
        self.friction.clear();
        let frictional = |row: &SurfaceRow| {
            touching.obstacles[row.obstacle as usize].friction > 0.0 && row.inverse_mass > 0.0
        };
        if !self.surfaces.iter().any(frictional) {
            return;
        }
        let pushed = &mut self.pushed;
        pushed.clear();
        pushed.resize(touching.radius.len(), false);
        for &(i, j) in touching.pairs {
            pushed[i as usize] = true;
            pushed[j as usize] = true;
        }
        for ((place, row), &contact) in (0_u32..).zip(&self.surfaces).zip(&self.schedule.surfaces) {
            let p = row.particle as usize;
            if !frictional(row) || !pushed[p] {
                continue;
            }
            let friction = touching.obstacles[row.obstacle as usize].friction;
            let k = touching.inertia.map_or(0.0, |inertia| inertia[p]);
            let (w, radius) = (row.inverse_mass, touching.radius[p]);
            let (turns, spin_per_impulse) = if k > 0.0 {
                (w / k, -w / (k * radius))
            } else {
                (0.0, 0.0)
            };
            self.friction.push(FrictionRow {
                surface: place,
                particle: row.particle,
                tangent: row.normal.perp(),
                friction,
                spare: touching
                    .spare_friction
                    .get(contact as usize)
                    .map_or(0.0, |a| a * h / w),
                inverse_mass: w,
                mass: 1.0 / (w + turns),
                radius,
                spin_per_impulse,
                impulse: 0.0,
            });
        }
    }

    /// Pushes apart overlaps beyond the tolerance, a share at a time over a few sweeps
    /// (Gauss–Seidel on positions). Returns whether anything moved.
    ///
    /// Each row measures its gap along the normal it was built with: a pair's is the
    /// distance between the centres projected on it, a surface's the particle's position
    /// along it. The corrections are some 1e-4 m, so that is the exact distance to within
    /// (1e-4)²/0.2 m for balls of 0.1 m, a thousandth of the tolerance, and never more than
    /// it (a projection is no longer than the distance, and the distance to a convex
    /// surface grows at least as fast as along its normal): an overlap is never left
    /// uncorrected. It costs a dot product a row where the exact distance costs a square
    /// root and a division, in four sweeps over every row of a pile (in a settling pile
    /// nearly every row needs correcting in each).
    fn correct_overlaps(&self, position: &mut [DVec2]) -> bool {
        let mut changed = false;
        for _ in 0..POSITION_SWEEPS {
            let mut moved = self.pairs.correct(&self.schedule.pair_levels, position);
            for row in &self.surfaces {
                let p = row.particle as usize;
                let excess = row.reach - position[p].dot(row.normal);
                let excess = if excess > 0.0 { excess } else { 0.0 };
                position[p] += row.normal * excess;
                moved |= excess > 0.0;
            }
            changed |= moved;
            if !moved {
                break; // nothing left to correct
            }
        }
        changed
    }
}

/// `built` in `order`, into `rows`: the sweeps then walk the rows front to back, with no
/// index to look up and each row next to the one before it in memory (the pit's rows,
/// some 200 kB, were taken in a scattered order eight times a step). The surface rows;
/// the pair rows are built straight into their place ([`PairColumns::set`]).
fn arrange<R: Copy>(built: &[R], order: &[u32], rows: &mut Vec<R>) {
    rows.clear();
    rows.extend(order.iter().map(|&k| built[k as usize]));
}

/// The order the sweeps take the rows in: any order that keeps every two rows with a
/// particle in common in their order in the lists gives the same bits (rows with no
/// particle in common commute: each changes only its own particles' velocities), and
/// this one takes first every row that waits for none before it, then every row that
/// waits only for those, and so on (the rows in ascending order within each level).
/// In the lists' own order most rows share a particle with the row just before them,
/// so each waits for the last one's result (a chain of some twenty cycles a row); in
/// levels, neighbouring rows are independent and the processor overlaps them. The
/// settled 1,000-ball pile's 2,650 touching pairs fall into about 160 levels; the solver
/// took 146–148 µs a step in ascending order and 98 µs in levels (`bench --scene pit
/// --particles 1000 --seconds 3 --threads 1`, two alternating runs each: 3,429–3,495 →
/// 4,184 steps per second), and the examples' CSVs are identical.
#[derive(Clone, Debug, Default)]
struct Schedule {
    pairs: Vec<u32>,
    surfaces: Vec<u32>,
    /// Where each level of the pairs ends in `pairs` (four rows of a level at a time
    /// have no particle in common, [`columns`]).
    pair_levels: Vec<u32>,
    /// Each pair's place in that order, in the lists' order (`pairs` inverted).
    pair_places: Vec<u32>,
    levels: Levels,
}

impl Schedule {
    /// Orders the rows of the pairs and of the surfaces (each row given by its two
    /// particles, the same twice for a surface) over `n` particles.
    fn order(
        &mut self,
        n: usize,
        pairs: impl Iterator<Item = (u32, u32)>,
        surfaces: impl Iterator<Item = (u32, u32)>,
    ) {
        self.levels.order(n, pairs, &mut self.pairs);
        self.pair_levels.clone_from(&self.levels.count);
        self.pair_places.clear();
        self.pair_places.resize(self.pairs.len(), 0);
        for (place, &k) in (0_u32..).zip(&self.pairs) {
            self.pair_places[k as usize] = place;
        }
        self.levels.order(n, surfaces, &mut self.surfaces);
    }
}

/// The levels of one list of rows, and what finding them works in.
#[derive(Clone, Debug, Default)]
struct Levels {
    /// Per particle: the level after the last row that touched it.
    ready: Vec<u32>,
    /// Per row: its level.
    level: Vec<u32>,
    /// Per level: its rows; after [`Levels::order`], where its rows end in the order.
    count: Vec<u32>,
}

impl Levels {
    /// `order` becomes the rows sorted by level, ascending within a level.
    fn order(&mut self, n: usize, rows: impl Iterator<Item = (u32, u32)>, order: &mut Vec<u32>) {
        self.ready.clear();
        self.ready.resize(n, 0);
        self.level.clear();
        self.count.clear();
        for (i, j) in rows {
            let (i, j) = (i as usize, j as usize);
            let level = self.ready[i].max(self.ready[j]);
            self.ready[i] = level + 1;
            self.ready[j] = level + 1;
            self.level.push(level);
            if self.count.len() <= level as usize {
                self.count.resize(level as usize + 1, 0);
            }
            self.count[level as usize] += 1;
        }
        // Counting sort: each level's first place, then the rows in order.
        let mut start = 0;
        for count in &mut self.count {
            let rows = *count;
            *count = start;
            start += rows;
        }
        order.clear();
        order.resize(self.level.len(), 0);
        for (k, &level) in (0_u32..).zip(&self.level) {
            let place = &mut self.count[level as usize];
            order[*place as usize] = k;
            *place += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contacts::obstacles::Shape;

    /// Two balls of 0.1 m at rest at `position`, touching, one of them (`on_floor`) on a
    /// floor at height `floor`, solved as one step's resting contacts; where they end.
    fn on_a_floor(
        floor: f64,
        position: [DVec2; 2],
        inverse_mass: [f64; 2],
        on_floor: u32,
    ) -> Vec<DVec2> {
        let obstacles = [Obstacle {
            target: crate::ImpactTarget::Wall,
            shape: Shape::HalfPlane {
                point: DVec2::new(0.0, floor),
                normal: DVec2::Y,
            },
            restitution: 0.0,
            friction: 0.0,
            static_friction: 0.0,
        }];
        let touching = Touching {
            pairs: &[(0, 1)],
            surfaces: &[(on_floor, 0)],
            obstacles: &obstacles,
            radius: &[0.1, 0.1],
            inverse_mass: &inverse_mass,
            inertia: None,
            spare_friction: &[],
        };
        let mut state = State {
            time: 0.0,
            position: position.to_vec(),
            velocity: vec![DVec2::ZERO; 2],
        };
        RestingSolver::default().solve(&touching, &mut state, 1e-3, 0.02, |_| false, &mut []);
        state.position
    }

    /// A step's remembered impulses are never scaled up by a longer step after it. Disc B
    /// (1 kg, 0.2 m) is wedged between a wall and disc A, which sits in the corner of the
    /// floor and the other wall (a box 0.6 m wide): the sweeps pass a push round the wedge
    /// slowly, so what is left of one shows. A step of 1e-20 s (a rolling start located
    /// at rounding) stops B's leftover approach of 1e-5 m/s, an impulse of 1e-5 N·s; the
    /// next step, 1e-3 s, needs only what stops gravity's 9.81 mm/s. Scaled by the steps'
    /// ratio, 1e17, the remembered impulse was a blow the eight sweeps could not take
    /// back (billions of m/s); a step never needs more than its own approach removed: no
    /// speed may end above the 9.81 mm/s the step brought.
    #[test]
    fn a_short_steps_impulses_are_not_scaled_up() {
        let wall = |point: DVec2, normal: DVec2| Obstacle {
            target: crate::ImpactTarget::Wall,
            shape: Shape::HalfPlane { point, normal },
            restitution: 0.0,
            friction: 0.0,
            static_friction: 0.0,
        };
        let obstacles = [
            wall(DVec2::ZERO, DVec2::Y),
            wall(DVec2::new(-0.3, 0.0), DVec2::X),
            wall(DVec2::new(0.3, 0.0), DVec2::NEG_X),
        ];
        let touching = Touching {
            pairs: &[(0, 1)],
            surfaces: &[(0, 0), (0, 2), (1, 1)],
            obstacles: &obstacles,
            radius: &[0.2, 0.2],
            inverse_mass: &[1.0, 1.0],
            inertia: None,
            spare_friction: &[],
        };
        let mut state = State {
            time: 0.0,
            position: vec![
                DVec2::new(0.1, 0.2),
                DVec2::new(-0.1, 0.2 + 0.2 * 3f64.sqrt()),
            ],
            velocity: vec![DVec2::ZERO, DVec2::new(0.0, -1e-5)],
        };
        let mut solver = RestingSolver::default();
        solver.solve(&touching, &mut state, 1e-20, 0.02, |_| false, &mut []);
        state.velocity = vec![DVec2::new(0.0, -9.81e-3); 2];
        solver.solve(&touching, &mut state, 1e-3, 0.02, |_| false, &mut []);
        for (disc, v) in ["A", "B"].iter().zip(&state.velocity) {
            assert!(v.length() <= 9.81e-3, "{disc} ends at {v} m/s");
        }
    }

    /// The overlap correction measures each pair's gap as the corrections before it left
    /// it, not only along the line the row was built with. Ball B (index 1) overlaps a
    /// fixed ball A at the origin by 1 % of the radius, side by side, and sinks into a
    /// floor under it, at rest. The first sweep pushes it off A by half its excess
    /// overlap (the radii less the tolerance, 0.1999 m, less the distance 0.198 m) and
    /// then lifts it clear of the floor, to the tolerance below the floor's contact
    /// (0.0999 m above the floor).
    /// - Sunk by half its radius, B is lifted to 0.0499 m, its centre 0.205 m from A's:
    ///   nothing overlaps beyond the tolerance, so nothing moves again. Closed form:
    ///   B ends at (0.19895, 0.0499), to rounding (held to 1e-12 m). Measured along the
    ///   normal alone the distance would still be 0.19895 m, and the three sweeps left
    ///   would push B 0.8 mm further along x.
    /// - Sunk by 0.0851 m, B is lifted to 0.0148 m, still overlapping A, and each sweep
    ///   left pushes it along the row's normal by half the excess of the exact distance
    ///   √(x² + 0.0148²): x = 0.199300787 m after all four. The solver's distance is the
    ///   projection plus its curvature across the normal at the distance the row was
    ///   built with, 0.198 m, off by 0.5 % of the curvature's 5.5e-4 m here: held to
    ///   1e-5 m (measured 3.5e-6 m). Twice the curvature ends 3.5e-4 m off.
    #[test]
    fn an_overlap_is_measured_where_the_corrections_before_it_left_it() {
        // Where the floor is, where the exact correction leaves B, and within what.
        let cases = [
            (
                -0.05,
                DVec2::new(0.198 + 0.5 * (0.1999 - 0.198), 0.0499),
                1e-12,
            ),
            (-0.0851, DVec2::new(0.199_300_786_845_876, 0.0148), 1e-5),
        ];
        for (floor, expected, tolerance) in cases {
            let position = on_a_floor(floor, [DVec2::ZERO, DVec2::new(0.198, 0.0)], [0.0, 1.0], 1);
            let off = position[1].distance(expected);
            assert!(
                off < tolerance,
                "floor at {floor}: B at {}, {off:e} m off",
                position[1]
            );
            assert_eq!(position[0], DVec2::ZERO, "the fixed ball moved");
        }
    }

    /// A surface's correction can push its ball into another, and the sweeps go on until
    /// nothing moves. Ball B (1 kg) is sunk 0.05 m into a floor under it; ball C (2 kg)
    /// rests on it 0.19995 m away, 5e-5 m short of correcting. The first sweep lifts B to
    /// 0.0499 m (the tolerance below the floor's contact), 0.15005 m under C: 0.04985 m
    /// beyond the tolerance. Each sweep after pushes the pair apart by half that, shared
    /// by their inverse masses (1 and 0.5 /kg), C up by a sixth of it, and the floor puts B
    /// back: the excess shrinks by 5/6 a sweep. Closed form after the four sweeps: B at
    /// 0.0499 m, C raised by 0.04985 × (1 + 5/6 + 25/36)/6 = 0.04985 × 91/216 m (both
    /// centres on one vertical, so the corrections are exact: held to 1e-12 m). A sweep
    /// that took only the pairs' corrections as movement would stop after the first.
    #[test]
    fn a_correction_that_pushes_a_ball_into_another_is_followed_by_more_sweeps() {
        let position = on_a_floor(
            -0.05,
            [DVec2::ZERO, DVec2::new(0.0, 0.19995)],
            [1.0, 0.5],
            0,
        );
        let expected = [
            DVec2::new(0.0, 0.0499),
            DVec2::new(0.0, 0.19995 + 0.04985 * 91.0 / 216.0),
        ];
        for (ball, (at, expected)) in ["B", "C"].iter().zip(position.iter().zip(expected)) {
            let off = at.distance(expected);
            assert!(off < 1e-12, "{ball} at {at}, {off:e} m off");
        }
    }

    /// The random tangle of [`the_schedule_gives_the_bits_of_ascending_order`]: `n`
    /// particles' velocities, 400 distinct pairs' rows and 30 surface rows, both lists
    /// ascending.
    fn random_tangle(n: u32) -> (Vec<DVec2>, Vec<PairRow>, Vec<SurfaceRow>) {
        let mut random = crate::testing::uniform(7);
        let inverse_mass: Vec<f64> = (0..n)
            .map(|i| if i % 10 == 3 { 0.0 } else { 0.2 + random() })
            .collect();
        let velocity: Vec<DVec2> = (0..n)
            .map(|_| DVec2::new(random() - 0.5, random() - 0.5))
            .collect();
        let mut keys = std::collections::BTreeSet::new();
        while keys.len() < 400 {
            let pick = |u: f64| (0..n).find(|&k| f64::from(k + 1) > u * f64::from(n));
            let (Some(a), Some(b)) = (pick(random()), pick(random())) else {
                continue;
            };
            if a != b {
                keys.insert((a.min(b), a.max(b)));
            }
        }
        let pairs: Vec<PairRow> = keys
            .into_iter()
            .map(|(i, j)| {
                let angle = random() * std::f64::consts::TAU;
                let (w_i, w_j) = (inverse_mass[i as usize], inverse_mass[j as usize]);
                let mut solved = Accumulator::new(w_i + w_j);
                solved.impulse = if random() < 0.2 { 0.0 } else { random() * 0.1 };
                PairRow {
                    i,
                    j,
                    normal: DVec2::from_angle(angle),
                    inverse_mass_i: w_i,
                    inverse_mass_j: w_j,
                    solved,
                    reach: 0.2,
                    bend: 2.5,
                    correction: CORRECTION * solved.mass,
                }
            })
            .collect();
        let mut surfaces: Vec<SurfaceRow> = (0..30_u32)
            .map(|k| {
                let p = (k * 7) % n;
                SurfaceRow {
                    particle: p,
                    obstacle: k % 3,
                    normal: DVec2::from_angle(random() * std::f64::consts::TAU),
                    inverse_mass: inverse_mass[p as usize],
                    solved: Accumulator::new(inverse_mass[p as usize]),
                    reach: 0.1,
                }
            })
            .collect();
        surfaces.sort_by_key(|r| (r.particle, r.obstacle));
        (velocity, pairs, surfaces)
    }

    /// Warm starts and velocity sweeps over a random tangle of rows taken in the
    /// [`Schedule`]'s order, the pairs in columns and four (two in WebAssembly) rows of a
    /// level at a time ([`columns`]), give the same bits as the rows taken one at a time
    /// in ascending order: 60 particles of random masses (a tenth of them fixed), 400
    /// distinct pairs drawn at random (so that many rows share particles, in every
    /// pattern) and 30 surface rows, warm starts (some rows cold, some left out as blows)
    /// and eight sweeps each way. The pairs fall into far fewer levels than rows, and no
    /// level has two rows with a particle in common (a row made to wait for one of its
    /// particles only, or to leave its particles ready at its own level, fails it).
    #[test]
    fn the_schedule_gives_the_bits_of_ascending_order() {
        let n = 60_u32;
        let (velocity, mut pairs, surfaces) = random_tangle(n);
        let mut schedule = Schedule::default();
        schedule.order(
            n as usize,
            pairs.iter().map(|r| (r.i, r.j)),
            surfaces.iter().map(|r| (r.particle, r.particle)),
        );
        assert_levels_overlap_rows(n as usize, &pairs, &schedule.pairs);
        // Warm starts first (a seventh of the particles struck, so that some rows are
        // blows left out), then the sweeps; the impulses compared in the lists' order.
        let struck = |p: u32| p % 7 == 2;
        let bits = |v: &[DVec2]| -> Vec<u64> {
            v.iter()
                .flat_map(|v| [v.x.to_bits(), v.y.to_bits()])
                .collect()
        };
        let impulses = |pairs: Vec<f64>, surfaces: &[SurfaceRow], order: &[u32]| {
            let mut impulses: Vec<u64> = pairs.iter().map(|i| i.to_bits()).collect();
            impulses.resize(pairs.len() + surfaces.len(), 0);
            for (row, &k) in surfaces.iter().zip(order) {
                impulses[pairs.len() + k as usize] = row.solved.impulse.to_bits();
            }
            impulses
        };
        // One at a time, in ascending order.
        let (before, zero) = (
            pairs.iter().filter(|r| r.solved.mass == 0.0).count(),
            pairs.iter().filter(|r| r.solved.impulse == 0.0).count(),
        );
        let mut ascending_surfaces = surfaces.clone();
        let mut v = velocity.clone();
        let mut columns = PairColumns::default();
        columns.resize(pairs.len());
        for (k, row) in pairs.iter().enumerate() {
            columns.set(schedule.pair_places[k] as usize, row);
        }
        warm_start(&mut pairs, &mut v, 0.3, |r| struck(r.i) || struck(r.j));
        warm_start(&mut ascending_surfaces, &mut v, 0.3, |r| struck(r.particle));
        // What each sweep of the pairs says (the largest change of an approach, which
        // the solver stops on), each way too.
        let mut said = Vec::new();
        for _ in 0..8 {
            said.push(sweep(&mut pairs, &mut v));
            sweep(&mut ascending_surfaces, &mut v);
        }
        let ascending_order: Vec<u32> = (0_u32..).take(surfaces.len()).collect();
        let expected = (
            bits(&v),
            impulses(
                pairs.iter().map(|r| r.solved.impulse).collect(),
                &ascending_surfaces,
                &ascending_order,
            ),
        );
        // Some rows are left out as blows and some start cold, so both branches are met.
        let blows = pairs.iter().filter(|r| r.solved.mass == 0.0).count();
        assert!(blows > before + 20, "{} blows", blows - before);
        assert!(zero > 20, "{zero} rows without a last impulse");
        // In the schedule's order, the pairs in columns.
        let mut arranged_surfaces = Vec::new();
        arrange(&surfaces, &schedule.surfaces, &mut arranged_surfaces);
        let mut v = velocity.clone();
        columns.warm_start(&mut v, 0.3, |p| p % 7 == 2); // `struck`, by index
        warm_start(&mut arranged_surfaces, &mut v, 0.3, |r| struck(r.particle));
        let mut said_in_lanes = Vec::new();
        for _ in 0..8 {
            said_in_lanes.push(columns.sweep(&schedule.pair_levels, &mut v));
            sweep(&mut arranged_surfaces, &mut v);
        }
        assert_eq!(said_in_lanes, said);
        assert!(said.iter().all(|s| s.is_some_and(|largest| largest > 0.0)));
        let mut in_lists_order = vec![0.0; pairs.len()];
        for (place, &k) in schedule.pairs.iter().enumerate() {
            in_lists_order[k as usize] = columns.impulse[place];
        }
        let scheduled = (
            bits(&v),
            impulses(in_lists_order, &arranged_surfaces, &schedule.surfaces),
        );
        assert!(expected == scheduled, "the scheduled sweeps differ");
    }

    /// A chain of balls, each row in a level of its own (so every row is taken alone, none
    /// in lanes): each sweep over the columns says what the rows' sweep in ascending order
    /// says (whether any row changed, and by how much at most), sweep after sweep until
    /// nothing changes.
    #[test]
    fn rows_taken_alone_say_what_changed() {
        let (velocity, tangle, _) = random_tangle(60);
        let mut pairs: Vec<PairRow> = (0_u32..)
            .zip(tangle)
            .take(5)
            .map(|(k, mut row)| {
                (row.i, row.j) = (k, k + 1);
                row
            })
            .collect();
        let mut schedule = Schedule::default();
        schedule.order(60, pairs.iter().map(|r| (r.i, r.j)), std::iter::empty());
        assert_eq!(schedule.pair_levels.len(), pairs.len(), "a level a row");
        let mut columns = PairColumns::default();
        columns.resize(pairs.len());
        for (k, row) in pairs.iter().enumerate() {
            columns.set(schedule.pair_places[k] as usize, row);
        }
        let (mut alone, mut in_columns) = (velocity.clone(), velocity);
        let mut said = Vec::new();
        for _ in 0..30 {
            let expected = sweep(&mut pairs, &mut alone);
            assert_eq!(
                columns.sweep(&schedule.pair_levels, &mut in_columns),
                expected
            );
            said.push(expected);
        }
        assert!(
            said.first().is_some_and(Option::is_some),
            "nothing to solve"
        );
        assert!(
            said.last().is_some_and(Option::is_none),
            "never settled: {said:?}"
        );
    }

    /// Four pairs of balls in one level (taken in one vector), each pair flying apart
    /// with an impulse left from the last step: the sweep takes each impulse back to
    /// zero, and the largest change it reports is the largest of those falls, as the rows
    /// taken one at a time report it (a fall is a negative change: its size counts).
    #[test]
    fn a_sweep_in_lanes_measures_falling_impulses() {
        let mut pairs: Vec<PairRow> = (0..4_u32)
            .map(|k| {
                let mut solved = Accumulator::new(2.0);
                solved.impulse = 0.5 + f64::from(k);
                PairRow {
                    i: 2 * k,
                    j: 2 * k + 1,
                    normal: DVec2::X,
                    inverse_mass_i: 1.0,
                    inverse_mass_j: 1.0,
                    solved,
                    reach: 0.2,
                    bend: 2.5,
                    correction: CORRECTION * solved.mass,
                }
            })
            .collect();
        // Apart at 10 m/s: far more than any impulse here can stop.
        let velocity: Vec<DVec2> = (0..8)
            .map(|p| DVec2::new(if p % 2 == 0 { -5.0 } else { 5.0 }, 0.0))
            .collect();
        let mut schedule = Schedule::default();
        schedule.order(8, pairs.iter().map(|r| (r.i, r.j)), std::iter::empty());
        assert_eq!(schedule.pair_levels, [4], "one level of four rows");
        let mut columns = PairColumns::default();
        columns.resize(pairs.len());
        for (k, row) in pairs.iter().enumerate() {
            columns.set(schedule.pair_places[k] as usize, row);
        }
        let (mut alone, mut in_lanes) = (velocity.clone(), velocity);
        let expected = sweep(&mut pairs, &mut alone);
        // The largest fall, 3.5 N·s, over the pair's 1/2 kg: 7 m/s.
        assert_eq!(expected, Some(7.0));
        assert_eq!(
            columns.sweep(&schedule.pair_levels, &mut in_lanes),
            expected
        );
        assert!(columns.impulse.iter().all(|&impulse| impulse == 0.0));
    }

    /// The position sweeps over the columns, four (two in WebAssembly) rows of a level
    /// at a time, give the bits of taking the rows one at a time: the random tangle's
    /// 400 pairs between 60 particles placed at random in a square of 0.3 m, their
    /// overlaps corrected by four sweeps each way (most rows overlap, and the
    /// lanes are met: the levels hold several rows each).
    #[test]
    fn position_sweeps_in_lanes_give_the_bits_of_one_row_at_a_time() {
        let n = 60_u32;
        let (_, pairs, _) = random_tangle(n);
        let mut random = crate::testing::uniform(11);
        let position: Vec<DVec2> = (0..n)
            .map(|_| DVec2::new(random(), random()) * 0.3)
            .collect();
        let mut schedule = Schedule::default();
        schedule.order(
            n as usize,
            pairs.iter().map(|r| (r.i, r.j)),
            std::iter::empty(),
        );
        let mut columns = PairColumns::default();
        columns.resize(pairs.len());
        for (k, row) in pairs.iter().enumerate() {
            columns.set(schedule.pair_places[k] as usize, row);
        }
        let overlapping = pairs
            .iter()
            .filter(|r| position[r.i as usize].distance(position[r.j as usize]) < r.reach)
            .count();
        assert!(overlapping > 200, "{overlapping} overlapping rows");
        let (mut lanes, mut alone) = (position.clone(), position.clone());
        for _ in 0..POSITION_SWEEPS {
            assert!(columns.correct(&schedule.pair_levels, &mut lanes));
            assert!(columns.correct_one_at_a_time(0..pairs.len(), &mut alone));
        }
        let bits = |p: &[DVec2]| -> Vec<u64> {
            p.iter()
                .flat_map(|p| [p.x.to_bits(), p.y.to_bits()])
                .collect()
        };
        assert!(
            bits(&lanes) == bits(&alone),
            "the lanes moved the balls otherwise"
        );
        // With every reach far below the distances, nothing overlaps: nothing moves, and
        // both say so.
        columns.reach.fill(-1e3);
        let mut lanes = position.clone();
        assert!(!columns.correct(&schedule.pair_levels, &mut lanes));
        assert!(!columns.correct_one_at_a_time(0..pairs.len(), &mut lanes));
        assert!(bits(&lanes) == bits(&position), "balls apart moved");
    }

    /// The pairs' levels: far fewer than the rows, and no two rows of a level sharing a
    /// particle (what lets the processor overlap them); `scheduled` is their order.
    fn assert_levels_overlap_rows(n: usize, pairs: &[PairRow], scheduled: &[u32]) {
        let (mut levels, mut pair_order) = (Levels::default(), Vec::new());
        levels.order(n, pairs.iter().map(|r| (r.i, r.j)), &mut pair_order);
        assert_eq!(pair_order, scheduled);
        assert!(
            levels.count.len() < 100, // 55 for the test's 400 rows
            "{} levels for {} rows",
            levels.count.len(),
            pairs.len()
        );
        let mut level_start = 0;
        for &level_end in &levels.count {
            let mut seen = std::collections::HashSet::new();
            for &k in &pair_order[level_start as usize..level_end as usize] {
                let row = &pairs[k as usize];
                assert!(
                    seen.insert(row.i) && seen.insert(row.j),
                    "a level shares a particle"
                );
            }
            level_start = level_end;
        }
    }
}
