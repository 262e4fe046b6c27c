//! Pins and hinges: bodies held to the world or to each other at a point, moved together
//! as one mechanism.
//!
//! Each joint is two constraints, the x and y of its point on body b less its point on a
//! (a pin's a is the world: its point never moves). The forces that keep them are the
//! Lagrange multipliers λ making the points' relative acceleration zero under every other
//! force, J W Jᵀ λ = −(J W F + J̇ u), with J the constraints' rows over the bodies' (x, y,
//! angle), W each body's (1/m, 1/m, 1/I) and J̇ u the points' turning term −ω² r. The
//! joint's reaction on b is (λx, λy) at its point. The integration method steps this
//! motion as it steps the particles' (`stepping.rs`); after each step the points are put
//! back together by a mass-weighted Gauss–Newton projection (to 1e-12 m) and the
//! velocities projected onto the constraints, as rods are (`crate::constraints`).
//!
//! A motor drives b's spin relative to a's: with a constant torque, or towards a target
//! spin with at most a largest torque. Away from the target it turns at that largest
//! torque; the instant it reaches the target is located inside the step (regula falsi on
//! the integration from the step's start), and from there it holds the spin with one
//! more constraint, whose multiplier is the torque it takes — as long as that stays
//! within the largest torque, judged at each step's start.
//!
//! Jointed bodies do not yet meet walls, ramps or other bodies (docs/physics.md).

use glam::{DVec2, DVec3};

use super::stepping::{self, Slope};
use crate::Integrator;
use crate::scene::Motor;

/// How close the joined points are put, as a fraction of the mechanism's size.
const POSITION_TOLERANCE: f64 = 1e-13;
/// Gauss–Newton iterations at most: from the drift of one step, two suffice.
const PROJECTION_ITERATIONS: usize = 8;
/// The located reach of a target spin, seconds: the bracket's width at most.
const EVENT_WIDTH: f64 = 1e-12;
/// Falsi trials at most to find a motor's reach of its target spin.
const MOST_TRIALS: usize = 100;
/// A pivot of the joint system smaller than this fraction of its diagonal belongs to a
/// constraint that others imply (two pins on one body): it takes no force of its own.
const DEPENDENT: f64 = 1e-12;

/// A joint in runtime form.
#[derive(Clone, Debug)]
pub(crate) struct Held {
    /// The body held: a pin's, a hinge's b (an index among the bodies).
    pub b: usize,
    /// A hinge's other body; `None` for a pin.
    pub a: Option<usize>,
    /// The point in b's frame, m.
    pub anchor_b: DVec2,
    /// A pin's point in the world, or the point in a's frame, m.
    pub anchor_a: DVec2,
    pub motor: Option<Motor>,
    /// b's angle less a's at which the joint's angle reads 0, degrees.
    pub reference: f64,
}

/// How a target-spin motor acts through a stretch of time.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Drive {
    /// A constant torque on b (and its opposite on a), N·m.
    Torque(f64),
    /// Holding b's spin relative to a's at the target, rad/s.
    Hold(f64),
}

/// The bodies' masses and inertias, and the joints among them.
pub(crate) struct Mechanism<'a> {
    pub joints: &'a [Held],
    /// Each body's (1/m, 1/m, 1/I); zero for a fixed one.
    pub inverse: Vec<DVec3>,
    /// Each body's weight and no torque, N.
    pub weight: Vec<DVec3>,
}

/// A constraint row: its coefficients on b and on a (if a moves), and J̇ u.
struct Row {
    b: (usize, DVec3),
    a: Option<(usize, DVec3)>,
    bias: f64,
}

/// The joint's points now: b's point, a's point, and the arms from b's and a's centroids.
fn points(joint: &Held, q: &[DVec3]) -> (DVec2, DVec2, DVec2, DVec2) {
    let arm = |i: usize, anchor: DVec2| DVec2::from_angle(q[i].z).rotate(anchor);
    let r_b = arm(joint.b, joint.anchor_b);
    let p_b = q[joint.b].truncate() + r_b;
    match joint.a {
        None => (p_b, joint.anchor_a, r_b, DVec2::ZERO),
        Some(a) => {
            let r_a = arm(a, joint.anchor_a);
            (p_b, q[a].truncate() + r_a, r_b, r_a)
        }
    }
}

/// Relative spin, b's less a's.
fn relative_spin(joint: &Held, u: &[DVec3]) -> f64 {
    u[joint.b].z - joint.a.map_or(0.0, |a| u[a].z)
}

impl Mechanism<'_> {
    /// The rows of the joints' points, then one per holding motor, at positions `q`.
    fn rows(&self, q: &[DVec3], u: &[DVec3], drives: &[Option<Drive>]) -> Vec<Row> {
        let mut rows = Vec::with_capacity(2 * self.joints.len());
        for joint in self.joints {
            let (_, _, r_b, r_a) = points(joint, q);
            let turning = |i: usize, r: DVec2| -u[i].z * u[i].z * r;
            let bias = turning(joint.b, r_b) - joint.a.map_or(DVec2::ZERO, |a| turning(a, r_a));
            rows.push(Row {
                b: (joint.b, DVec3::new(1.0, 0.0, -r_b.y)),
                a: joint.a.map(|a| (a, DVec3::new(-1.0, 0.0, r_a.y))),
                bias: bias.x,
            });
            rows.push(Row {
                b: (joint.b, DVec3::new(0.0, 1.0, r_b.x)),
                a: joint.a.map(|a| (a, DVec3::new(0.0, -1.0, -r_a.x))),
                bias: bias.y,
            });
        }
        for (joint, drive) in self.joints.iter().zip(drives) {
            if let Some(Drive::Hold(_)) = drive {
                rows.push(Row {
                    b: (joint.b, DVec3::Z),
                    a: joint.a.map(|a| (a, -DVec3::Z)),
                    bias: 0.0,
                });
            }
        }
        rows
    }

    /// J W Jᵀ of `rows`.
    fn matrix(&self, rows: &[Row]) -> Vec<Vec<f64>> {
        let entries = |row: &Row| [Some(row.b), row.a];
        rows.iter()
            .map(|r| {
                rows.iter()
                    .map(|s| {
                        let mut sum = 0.0;
                        for (i, jr) in entries(r).into_iter().flatten() {
                            for (k, js) in entries(s).into_iter().flatten() {
                                if i == k {
                                    sum += (jr * self.inverse[i]).dot(js);
                                }
                            }
                        }
                        sum
                    })
                    .collect()
            })
            .collect()
    }

    /// W Jᵀ λ added to `out`: what the multipliers do to each body.
    fn apply(&self, rows: &[Row], lambda: &[f64], out: &mut [DVec3]) {
        for (row, &l) in rows.iter().zip(lambda) {
            for (i, j) in [Some(row.b), row.a].into_iter().flatten() {
                out[i] += self.inverse[i] * j * l;
            }
        }
    }

    /// J x of `rows`.
    fn times(rows: &[Row], x: &[DVec3]) -> Vec<f64> {
        rows.iter()
            .map(|row| {
                [Some(row.b), row.a]
                    .into_iter()
                    .flatten()
                    .map(|(i, j)| j.dot(x[i]))
                    .sum()
            })
            .collect()
    }

    /// The applied forces: weights and the motors' torques under `drives`.
    fn applied(&self, drives: &[Option<Drive>]) -> Vec<DVec3> {
        let mut force = self.weight.clone();
        for (joint, drive) in self.joints.iter().zip(drives) {
            if let Some(Drive::Torque(torque)) = drive {
                force[joint.b].z += torque;
                if let Some(a) = joint.a {
                    force[a].z -= torque;
                }
            }
        }
        force
    }

    /// The accelerations at (`q`, `u`) and the multipliers: each joint's reaction on b
    /// (x, y), then each holding motor's torque.
    fn accelerations(
        &self,
        q: &[DVec3],
        u: &[DVec3],
        drives: &[Option<Drive>],
    ) -> (Vec<DVec3>, Vec<f64>) {
        let force = self.applied(drives);
        let free: Vec<DVec3> = force
            .iter()
            .zip(&self.inverse)
            .map(|(&f, &w)| f * w)
            .collect();
        let rows = self.rows(q, u, drives);
        let rhs: Vec<f64> = Self::times(&rows, &free)
            .iter()
            .zip(&rows)
            .map(|(jf, row)| -(jf + row.bias))
            .collect();
        let lambda = solve(self.matrix(&rows), rhs);
        let mut a = free;
        self.apply(&rows, &lambda, &mut a);
        (a, lambda)
    }

    /// Each motor's drive at (`q`, `u`): a constant torque; a target spin held when it is
    /// reached and the torque holding it is within the largest, else the largest torque
    /// towards it.
    fn drives(&self, q: &[DVec3], u: &[DVec3]) -> Vec<Option<Drive>> {
        let mut drives: Vec<Option<Drive>> = self
            .joints
            .iter()
            .map(|joint| match joint.motor? {
                Motor::Torque(torque) => Some(Drive::Torque(torque)),
                Motor::Spin { spin, max_torque } => {
                    let off = relative_spin(joint, u) - spin;
                    Some(if reached(off, spin) {
                        Drive::Hold(spin)
                    } else {
                        Drive::Torque(-max_torque.copysign(off))
                    })
                }
            })
            .collect();
        if drives.iter().any(|d| matches!(d, Some(Drive::Hold(_)))) {
            let (_, lambda) = self.accelerations(q, u, &drives);
            let mut k = 2 * self.joints.len();
            for (joint, drive) in self.joints.iter().zip(&mut drives) {
                if let (Some(Drive::Hold(_)), Some(Motor::Spin { max_torque, .. })) =
                    (*drive, joint.motor)
                {
                    if lambda[k].abs() > max_torque {
                        *drive = Some(Drive::Torque(max_torque.copysign(lambda[k])));
                    }
                    k += 1;
                }
            }
        }
        drives
    }

    /// Puts the joined points together and the velocities onto the joints (and the held
    /// spins onto their targets).
    fn project(&self, q: &mut [DVec3], u: &mut [DVec3], drives: &[Option<Drive>], size: f64) {
        for _ in 0..PROJECTION_ITERATIONS {
            let gaps: Vec<DVec2> = self
                .joints
                .iter()
                .map(|joint| {
                    let (p_b, p_a, _, _) = points(joint, q);
                    p_b - p_a
                })
                .collect();
            let worst = gaps
                .iter()
                .fold(0.0, |w: f64, g| w.max(g.abs().max_element()));
            if worst <= POSITION_TOLERANCE * size {
                break;
            }
            let rows = self.rows(q, u, &vec![None; drives.len()]);
            let rhs: Vec<f64> = gaps.iter().flat_map(|g| [-g.x, -g.y]).collect();
            let delta = solve(self.matrix(&rows), rhs);
            self.apply(&rows, &delta, q);
        }
        let rows = self.rows(q, u, drives);
        let targets = self
            .joints
            .iter()
            .flat_map(|_| [0.0, 0.0])
            .chain(drives.iter().filter_map(|d| match d {
                Some(Drive::Hold(spin)) => Some(*spin),
                _ => None,
            }));
        let rhs: Vec<f64> = Self::times(&rows, u)
            .iter()
            .zip(targets)
            .map(|(ju, target)| target - ju)
            .collect();
        let mu = solve(self.matrix(&rows), rhs);
        self.apply(&rows, &mu, u);
    }

    /// The work the motors do while the bodies go from `q0` to `q1` under `drives` over
    /// `h` seconds, J: a constant torque's τ Δθ; a held spin's torque (at the two ends,
    /// averaged) times the angle turned.
    fn work(
        &self,
        (q0, u0): (&[DVec3], &[DVec3]),
        (q1, u1): (&[DVec3], &[DVec3]),
        drives: &[Option<Drive>],
    ) -> f64 {
        let turned = |joint: &Held| {
            let angle = |q: &[DVec3]| q[joint.b].z - joint.a.map_or(0.0, |a| q[a].z);
            angle(q1) - angle(q0)
        };
        let held = |q, u| self.accelerations(q, u, drives).1;
        let mut holding = None;
        let mut k = 2 * self.joints.len();
        let mut work = 0.0;
        for (joint, drive) in self.joints.iter().zip(drives) {
            match drive {
                Some(Drive::Torque(torque)) => work += torque * turned(joint),
                Some(Drive::Hold(_)) => {
                    let (start, end) = holding.get_or_insert_with(|| (held(q0, u0), held(q1, u1)));
                    work += 0.5 * (start[k] + end[k]) * turned(joint);
                    k += 1;
                }
                None => {}
            }
        }
        work
    }

    /// Moves the bodies through `h` seconds with `method`: the motors' drives judged at
    /// the start, and again wherever a motor reaches its target spin inside the step.
    /// Returns the motors' work.
    pub fn advance(
        &self,
        method: Integrator,
        (q, u): (&mut [DVec3], &mut [DVec3]),
        h: f64,
        size: f64,
    ) -> f64 {
        let mut left = h;
        let mut work = 0.0;
        // Each pass either finishes the step or reaches one more target: a motor's
        // reach is counted once per joint and step at most.
        for pass in 0..=self.joints.len() {
            let drives = self.drives(q, u);
            let (q0, u0) = (q.to_vec(), u.to_vec());
            let moved = |dt: f64| {
                let (mut q, mut u) = (q0.clone(), u0.clone());
                let slope: &Slope = &|q, u| self.accelerations(q, u, &drives).0;
                stepping::step(method, &mut q, &mut u, dt, slope);
                (q, u)
            };
            let (mut q1, mut u1) = moved(left);
            // The last pass takes what is left of the step whatever happens in it.
            let reach = (pass < self.joints.len())
                .then(|| self.first_reach(&drives, &u0, &u1))
                .flatten();
            let mut dt = left;
            if let Some(k) = reach {
                dt = self.locate(k, left, &moved);
                (q1, u1) = moved(dt);
            }
            let mut after = drives.clone();
            if let (Some(k), Some(Motor::Spin { spin, .. })) =
                (reach, reach.and_then(|k| self.joints[k].motor))
            {
                after[k] = Some(Drive::Hold(spin));
            }
            self.project(&mut q1, &mut u1, &after, size);
            work += self.work((&q0, &u0), (&q1, &u1), &drives);
            q.copy_from_slice(&q1);
            u.copy_from_slice(&u1);
            left -= dt;
            if reach.is_none() || left <= 0.0 {
                break;
            }
        }
        work
    }

    /// The first motor (by joint order) driven at its largest torque whose spin passed
    /// its target between `u0` and `u1`.
    fn first_reach(&self, drives: &[Option<Drive>], u0: &[DVec3], u1: &[DVec3]) -> Option<usize> {
        self.joints
            .iter()
            .zip(drives)
            .position(|(joint, drive)| match (drive, joint.motor) {
                (Some(Drive::Torque(_)), Some(Motor::Spin { spin, .. })) => {
                    let (before, after) = (
                        relative_spin(joint, u0) - spin,
                        relative_spin(joint, u1) - spin,
                    );
                    !reached(before, spin) && (reached(after, spin) || before * after < 0.0)
                }
                _ => false,
            })
    }

    /// The time into a stretch of `left` seconds at which joint `k`'s motor reaches its
    /// target spin (regula falsi, Illinois): the first trial found at or past it.
    fn locate(&self, k: usize, left: f64, moved: &dyn Fn(f64) -> (Vec<DVec3>, Vec<DVec3>)) -> f64 {
        let joint = &self.joints[k];
        let Some(Motor::Spin { spin, .. }) = joint.motor else {
            return left;
        };
        let off = |dt: f64| relative_spin(joint, &moved(dt).1) - spin;
        let (mut lo, mut hi) = (0.0, left);
        let (mut f_lo, mut f_hi) = (off(lo), off(hi));
        let mut side = 0;
        for _ in 0..MOST_TRIALS {
            if hi - lo <= EVENT_WIDTH {
                break;
            }
            let mut t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
            if !(t > lo && t < hi) {
                t = 0.5 * (lo + hi);
            }
            let f = off(t);
            if reached(f, spin) {
                return t;
            }
            if f * f_lo > 0.0 {
                (lo, f_lo) = (t, f);
                if side == -1 {
                    f_hi *= 0.5;
                }
                side = -1;
            } else {
                (hi, f_hi) = (t, f);
                if side == 1 {
                    f_lo *= 0.5;
                }
                side = 1;
            }
        }
        hi
    }

    /// Each joint's reaction on b (N) and the torque its motor gives b (N·m) at (`q`,
    /// `u`).
    pub fn reactions(&self, q: &[DVec3], u: &[DVec3]) -> (Vec<DVec3>, Vec<(DVec2, f64)>) {
        let drives = self.drives(q, u);
        let (a, lambda) = self.accelerations(q, u, &drives);
        let mut k = 2 * self.joints.len();
        let out = self
            .joints
            .iter()
            .zip(&drives)
            .enumerate()
            .map(|(j, (_, drive))| {
                let force = DVec2::new(lambda[2 * j], lambda[2 * j + 1]);
                let torque = match drive {
                    Some(Drive::Torque(t)) => *t,
                    Some(Drive::Hold(_)) => {
                        k += 1;
                        lambda[k - 1]
                    }
                    None => 0.0,
                };
                (force, torque)
            })
            .collect();
        (a, out)
    }
}

/// Whether a spin `off` rad/s from its target `spin` has reached it: to rounding.
fn reached(off: f64, spin: f64) -> bool {
    off.abs() <= 1e-12 * spin.abs().max(1.0)
}

/// Solves the symmetric positive semi-definite system `m` x = `b` by Cholesky, a
/// dependent row (a pivot under [`DEPENDENT`] of its diagonal) taking x = 0.
fn solve(mut m: Vec<Vec<f64>>, b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    let mut used = vec![true; n];
    for k in 0..n {
        let diagonal = m[k][k];
        for j in 0..k {
            if used[j] {
                m[k][k] -= m[k][j] * m[k][j];
            }
        }
        if m[k][k] <= DEPENDENT * diagonal.max(f64::MIN_POSITIVE) {
            used[k] = false;
            continue;
        }
        m[k][k] = m[k][k].sqrt();
        for i in k + 1..n {
            for j in 0..k {
                if used[j] {
                    m[i][k] -= m[i][j] * m[k][j];
                }
            }
            m[i][k] /= m[k][k];
        }
    }
    let mut y = b;
    for i in 0..n {
        if !used[i] {
            y[i] = 0.0;
            continue;
        }
        for j in 0..i {
            if used[j] {
                y[i] -= m[i][j] * y[j];
            }
        }
        y[i] /= m[i][i];
    }
    for i in (0..n).rev() {
        if !used[i] {
            continue;
        }
        for j in i + 1..n {
            if used[j] {
                y[i] -= m[j][i] * y[j];
            }
        }
        y[i] /= m[i][i];
    }
    y
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The solver on a system with a row the others imply: the dependent row takes
    /// nothing and the rest are solved exactly.
    #[test]
    fn a_dependent_row_takes_nothing() {
        let m = vec![
            vec![4.0, 2.0, 6.0],
            vec![2.0, 3.0, 5.0],
            vec![6.0, 5.0, 11.0],
        ];
        let x = solve(m, vec![2.0, 1.0, 3.0]);
        assert!(x[2].abs() < 1e-15, "{x:?}");
        assert!((4.0 * x[0] + 2.0 * x[1] - 2.0).abs() < 1e-12, "{x:?}");
        assert!((2.0 * x[0] + 3.0 * x[1] - 1.0).abs() < 1e-12, "{x:?}");
    }
}
