//! Pins, hinges and pulleys: bodies held to the world or to each other, moved together as
//! one mechanism.
//!
//! A pin or a hinge is two constraints, the x and y of its point on body b less its point
//! on a (a pin's a is the world: its point never moves); a pulley is one, its string's
//! length (two with a wheel of inertia, one per run). The forces that keep them are the
//! Lagrange multipliers λ making the constraints' second derivatives zero under every
//! other force, J W Jᵀ λ = −(J W F + J̇ u), with J the constraints' rows over the bodies'
//! (x, y, angle), W each body's (1/m, 1/m, 1/I) and J̇ u the turning terms (−ω² r of a
//! point, v⊥²/run of a string's run). The integration method steps this motion as it
//! steps the particles' (`stepping.rs`); after each step the constraints are put back by
//! a mass-weighted Gauss–Newton projection (to 1e-13 of the mechanism's size) and the
//! velocities projected onto them, as rods are (`crate::constraints`).
//!
//! A motor drives b's spin relative to a's: with a constant torque, or towards a target
//! spin with at most a largest torque. Away from the target it turns at that largest
//! torque; the instant it reaches the target is located inside the step (regula falsi on
//! the integration from the step's start), and from there it holds the spin with one
//! more constraint, whose multiplier is the torque it takes — as long as that stays
//! within the largest torque, judged at each step's start. A joint's limits are located
//! the same way; at one the joint stops dead (a velocity projection: the plastic impulse)
//! and rests against it while the limit pushes.
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
/// How narrowly an event (a target spin reached, a limit met) is located, seconds: the
/// bracket's width at most.
const EVENT_WIDTH: f64 = 1e-12;
/// Falsi trials at most to find a motor's reach of its target spin or a limit.
const MOST_TRIALS: usize = 100;
/// A joint within this of a limit (radians) is at it.
const AT_LIMIT: f64 = 1e-9;
/// A joint turning away from a limit slower than this (rad/s) is resting against it.
const AT_REST: f64 = 1e-9;
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
    /// The least and the most of b's angle less a's, radians (the file's limits from the
    /// reference).
    pub limits: Option<(f64, f64)>,
    /// A pulley's wheel and string, from a over the wheel to b (the anchors are then the
    /// centroids, 0).
    pub pulley: Option<Pulley>,
}

/// An ideal string from body a over a wheel to body b, each end at a centroid.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pulley {
    /// The wheel's centre, m.
    pub centre: DVec2,
    /// m, > 0.
    pub radius: f64,
    /// The string's length: both straight runs and the arc over the wheel, m.
    pub length: f64,
    /// The wheel's coordinate in the mechanism (its spin) when it has inertia; a
    /// massless wheel has none.
    pub wheel: Option<usize>,
}

/// Where a string from `p` meets a wheel of `radius` at `centre`: the tangent point's
/// angle on the wheel and the straight run's length. `side` −1 for the string's a end
/// (the string comes up the wheel's left, seen with a on the left), +1 for its b end.
fn tangent(centre: DVec2, radius: f64, p: DVec2, side: f64) -> (f64, f64) {
    let d = p - centre;
    let distance = d.length();
    let run = (distance * distance - radius * radius).max(0.0).sqrt();
    let beta = (radius / distance).min(1.0).acos();
    (d.y.atan2(d.x) + side * beta, run)
}

/// The string's geometry with its ends at `a` and `b`: its whole length, and for each end
/// the unit vector along the straight run towards the end and the run's length.
fn string(pulley: &Pulley, a: DVec2, b: DVec2) -> (f64, [(DVec2, f64); 2]) {
    let (c, r) = (pulley.centre, pulley.radius);
    let (angle_a, run_a) = tangent(c, r, a, -1.0);
    let (angle_b, run_b) = tangent(c, r, b, 1.0);
    let wrap = (angle_a - angle_b).rem_euclid(std::f64::consts::TAU);
    let along = |angle: f64, p: DVec2, run: f64| {
        let touch = c + DVec2::from_angle(angle) * r;
        ((p - touch) / run.max(f64::MIN_POSITIVE), run)
    };
    (
        run_a + run_b + r * wrap,
        [along(angle_a, a, run_a), along(angle_b, b, run_b)],
    )
}

/// The string's whole length with its ends at `a` and `b` over a wheel of `radius` at
/// `centre`, m: what a pulley holds.
pub(crate) fn string_length(centre: DVec2, radius: f64, a: DVec2, b: DVec2) -> f64 {
    let pulley = Pulley {
        centre,
        radius,
        length: 0.0,
        wheel: None,
    };
    string(&pulley, a, b).0
}

/// The points where a string from `a` over a wheel of `radius` at `centre` to `b` leaves
/// the wheel towards each end (the app draws the string through them).
pub fn pulley_path(centre: DVec2, radius: f64, a: DVec2, b: DVec2) -> [DVec2; 2] {
    let touch = |p, side| centre + DVec2::from_angle(tangent(centre, radius, p, side).0) * radius;
    [touch(a, -1.0), touch(b, 1.0)]
}

/// What a joint's constraints do to its bodies at one instant.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Reaction {
    /// The force on b, N (a pulley's: its string's pull on b).
    pub on_b: DVec2,
    /// The force on a, N.
    pub on_a: DVec2,
    /// The motor's torque on b, N·m.
    pub torque: f64,
    /// A pulley's string tension on a's side and on b's, N.
    pub tensions: [f64; 2],
}

/// How a target-spin motor acts through a stretch of time.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Drive {
    /// A constant torque on b (and its opposite on a), N·m.
    Torque(f64),
    /// Holding b's spin relative to a's at the target, rad/s.
    Hold(f64),
}

/// Which of its limits a joint rests against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Lower,
    Upper,
}

/// How each joint acts through a stretch of time: its motor's drive and the limit it
/// rests against, if any.
#[derive(Clone, Debug, PartialEq)]
struct Modes {
    drives: Vec<Option<Drive>>,
    stops: Vec<Option<Side>>,
}

/// Something that changes a joint's mode inside a step.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Event {
    /// Joint k's motor reaches its target spin.
    Reach(usize),
    /// Joint k reaches one of its limits.
    Limit(usize, Side),
}

/// The bodies' masses and inertias, and the joints among them.
pub(crate) struct Mechanism<'a> {
    pub joints: &'a [Held],
    /// Each body's (1/m, 1/m, 1/I); zero for a fixed one.
    pub inverse: Vec<DVec3>,
    /// Each body's weight and no torque, N.
    pub weight: Vec<DVec3>,
}

/// What a stretch of motion gave and took, J.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Books {
    /// The motors' work.
    pub work: f64,
    /// The kinetic energy the limits' stops took.
    pub stopped: f64,
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

/// Relative spin, b's less a's, rad/s.
fn relative_spin(joint: &Held, u: &[DVec3]) -> f64 {
    u[joint.b].z - joint.a.map_or(0.0, |a| u[a].z)
}

/// Relative angle, b's less a's, radians.
fn relative_angle(joint: &Held, q: &[DVec3]) -> f64 {
    q[joint.b].z - joint.a.map_or(0.0, |a| q[a].z)
}

/// How far joint `joint` is inside its limit `side` (radians; negative beyond it).
fn inside(joint: &Held, side: Side, q: &[DVec3]) -> f64 {
    let Some((lower, upper)) = joint.limits else {
        return f64::INFINITY;
    };
    let angle = relative_angle(joint, q);
    match side {
        Side::Lower => angle - lower,
        Side::Upper => upper - angle,
    }
}

impl Mechanism<'_> {
    /// How many rows joint `joint` has in the motion (`moving`) or in the projection of
    /// positions: a point two; a pulley one (the string's length), or two in the motion
    /// when its wheel has inertia (a string's run on each side).
    fn count(joint: &Held, moving: bool) -> usize {
        match joint.pulley {
            None => 2,
            Some(pulley) if moving && pulley.wheel.is_some() => 2,
            Some(_) => 1,
        }
    }

    /// How many multipliers the joints' own rows take in the motion: the holding motors'
    /// and the limits' follow them.
    fn joint_count(&self) -> usize {
        self.joints.iter().map(|j| Self::count(j, true)).sum()
    }

    /// A pulley's rows: the string's length (one row), or in the motion with a wheel of
    /// inertia one per run, each turning the wheel.
    fn pulley_rows(joint: &Held, (q, u): (&[DVec3], &[DVec3]), moving: bool, rows: &mut Vec<Row>) {
        let (Some(pulley), Some(a)) = (joint.pulley, joint.a) else {
            return;
        };
        let b = joint.b;
        let (_, [(along_a, run_a), (along_b, run_b)]) =
            string(&pulley, q[a].truncate(), q[b].truncate());
        // Each run turns at v⊥/run: its length's second derivative gains v⊥²/run.
        let turning = |v: DVec3, along: DVec2, run: f64| {
            let across = v.truncate().perp_dot(along);
            across * across / run.max(f64::MIN_POSITIVE)
        };
        let (bias_a, bias_b) = (turning(u[a], along_a, run_a), turning(u[b], along_b, run_b));
        match pulley.wheel {
            Some(w) if moving => {
                let rim = DVec3::Z * pulley.radius;
                rows.push(Row {
                    b: (a, along_a.extend(0.0)),
                    a: Some((w, -rim)),
                    bias: bias_a,
                });
                rows.push(Row {
                    b: (b, along_b.extend(0.0)),
                    a: Some((w, rim)),
                    bias: bias_b,
                });
            }
            _ => rows.push(Row {
                b: (b, along_b.extend(0.0)),
                a: Some((a, along_a.extend(0.0))),
                bias: bias_a + bias_b,
            }),
        }
    }

    /// The rows of the joints, then one per holding motor, then one per limit rested
    /// against, at (`q`, `u`).
    fn rows(&self, q: &[DVec3], u: &[DVec3], modes: &Modes) -> Vec<Row> {
        self.rows_for(q, u, modes, true)
    }

    /// [`Self::rows`] in the motion, or (`moving` false) for the projection of positions.
    fn rows_for(&self, q: &[DVec3], u: &[DVec3], modes: &Modes, moving: bool) -> Vec<Row> {
        let mut rows = Vec::with_capacity(2 * self.joints.len());
        for joint in self.joints {
            if joint.pulley.is_some() {
                Self::pulley_rows(joint, (q, u), moving, &mut rows);
                continue;
            }
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
        let turning_row = |joint: &Held| Row {
            b: (joint.b, DVec3::Z),
            a: joint.a.map(|a| (a, -DVec3::Z)),
            bias: 0.0,
        };
        for (joint, drive) in self.joints.iter().zip(&modes.drives) {
            if let Some(Drive::Hold(_)) = drive {
                rows.push(turning_row(joint));
            }
        }
        for (joint, stop) in self.joints.iter().zip(&modes.stops) {
            if stop.is_some() {
                rows.push(turning_row(joint));
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

    /// The applied forces: weights and the motors' torques under `modes`.
    fn applied(&self, modes: &Modes) -> Vec<DVec3> {
        let mut force = self.weight.clone();
        for (joint, drive) in self.joints.iter().zip(&modes.drives) {
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
    /// (x, y), then each holding motor's torque, then each limit's.
    fn accelerations(&self, q: &[DVec3], u: &[DVec3], modes: &Modes) -> (Vec<DVec3>, Vec<f64>) {
        let force = self.applied(modes);
        let free: Vec<DVec3> = force
            .iter()
            .zip(&self.inverse)
            .map(|(&f, &w)| f * w)
            .collect();
        let rows = self.rows(q, u, modes);
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

    /// Each joint's mode at (`q`, `u`). A motor of constant torque gives it; a motor
    /// towards a spin holds it when reached and the torque holding it is within the
    /// largest, else turns at the largest towards it. A joint at a limit and not leaving
    /// it rests against it while the limit pushes (never pulls).
    fn modes(&self, q: &[DVec3], u: &[DVec3]) -> Modes {
        let drives = self
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
        let stops = self
            .joints
            .iter()
            .map(|joint| {
                let spin = relative_spin(joint, u);
                [Side::Lower, Side::Upper].into_iter().find(|&side| {
                    let leaving = match side {
                        Side::Lower => spin > AT_REST,
                        Side::Upper => spin < -AT_REST,
                    };
                    inside(joint, side, q) <= AT_LIMIT && !leaving
                })
            })
            .collect();
        let mut modes = Modes { drives, stops };
        let holds = modes
            .drives
            .iter()
            .filter(|d| matches!(d, Some(Drive::Hold(_))))
            .count();
        if holds == 0 && modes.stops.iter().all(Option::is_none) {
            return modes;
        }
        let (_, lambda) = self.accelerations(q, u, &modes);
        let mut k = self.joint_count();
        for (joint, drive) in self.joints.iter().zip(&mut modes.drives) {
            if let (Some(Drive::Hold(_)), Some(Motor::Spin { max_torque, .. })) =
                (*drive, joint.motor)
            {
                if lambda[k].abs() > max_torque {
                    *drive = Some(Drive::Torque(max_torque.copysign(lambda[k])));
                }
                k += 1;
            }
        }
        let mut k = self.joint_count() + holds;
        for stop in &mut modes.stops {
            if let Some(side) = *stop {
                let pulls = match side {
                    Side::Lower => lambda[k] < 0.0,
                    Side::Upper => lambda[k] > 0.0,
                };
                if pulls {
                    *stop = None;
                }
                k += 1;
            }
        }
        modes
    }

    /// Puts the joined points together (and the joints at a limit onto it) and the
    /// velocities onto the joints (the held spins onto their targets, the joints at a
    /// limit to rest against it).
    fn project(&self, q: &mut [DVec3], u: &mut [DVec3], modes: &Modes, size: f64) {
        let at_limits = Modes {
            drives: vec![None; self.joints.len()],
            stops: modes.stops.clone(),
        };
        for _ in 0..PROJECTION_ITERATIONS {
            let gaps: Vec<f64> = self
                .joints
                .iter()
                .flat_map(|joint| {
                    if let (Some(pulley), Some(a)) = (joint.pulley, joint.a) {
                        let (length, _) = string(&pulley, q[a].truncate(), q[joint.b].truncate());
                        return vec![length - pulley.length];
                    }
                    let (p_b, p_a, _, _) = points(joint, q);
                    let gap = p_b - p_a;
                    vec![gap.x, gap.y]
                })
                .chain(
                    self.joints
                        .iter()
                        .zip(&modes.stops)
                        .filter_map(|(joint, stop)| {
                            // The constraint's value, the angle less the limit (its row's J is
                            // +1 on b's angle).
                            stop.map(|side| match side {
                                Side::Lower => inside(joint, side, q),
                                Side::Upper => -inside(joint, side, q),
                            })
                        }),
                )
                .collect();
            let own: usize = self.joints.iter().map(|j| Self::count(j, false)).sum();
            let points_off = gaps[..own].iter().fold(0.0, |w: f64, g| w.max(g.abs()));
            let angles_off = gaps[own..].iter().fold(0.0, |w: f64, g| w.max(g.abs()));
            if points_off <= POSITION_TOLERANCE * size && angles_off <= POSITION_TOLERANCE {
                break;
            }
            let rows = self.rows_for(q, u, &at_limits, false);
            let rhs: Vec<f64> = gaps.iter().map(|g| -g).collect();
            let delta = solve(self.matrix(&rows), rhs);
            self.apply(&rows, &delta, q);
        }
        let rows = self.rows(q, u, modes);
        let targets = std::iter::repeat_n(0.0, self.joint_count())
            .chain(modes.drives.iter().filter_map(|d| match d {
                Some(Drive::Hold(spin)) => Some(*spin),
                _ => None,
            }))
            .chain(modes.stops.iter().flatten().map(|_| 0.0));
        let rhs: Vec<f64> = Self::times(&rows, u)
            .iter()
            .zip(targets)
            .map(|(ju, target)| target - ju)
            .collect();
        let mu = solve(self.matrix(&rows), rhs);
        self.apply(&rows, &mu, u);
    }

    /// Velocities at the start that move a joint apart (a hinge's two points, a pulley's
    /// string stretching): projected onto the joints, as after a step — the plastic
    /// impulse that makes them consistent. Returns the kinetic energy that took, or `None`
    /// where they were consistent already (to 1e-9 of the fastest speed: a saved state's
    /// rounding, which must not be touched for its run to continue bit for bit).
    pub fn start(&self, q: &mut [DVec3], u: &mut [DVec3], size: f64) -> Option<f64> {
        let modes = self.modes(q, u);
        let plain = Modes {
            drives: vec![None; self.joints.len()],
            stops: modes.stops.clone(),
        };
        let rows = self.rows(q, u, &plain);
        let fastest = u.iter().fold(0.0, |f: f64, v| {
            f.max(v.truncate().length()).max(v.z.abs() * size)
        });
        let apart = Self::times(&rows, u)
            .iter()
            .fold(0.0, |w: f64, x| w.max(x.abs()));
        if apart <= 1e-9 * fastest.max(f64::MIN_POSITIVE) {
            return None;
        }
        let before = self.kinetic(u);
        self.project(q, u, &plain, size);
        Some(before - self.kinetic(u))
    }

    /// The kinetic energy of velocities `u`, J.
    fn kinetic(&self, u: &[DVec3]) -> f64 {
        let term = |v: f64, w: f64| if w > 0.0 { 0.5 * v * v / w } else { 0.0 };
        u.iter()
            .zip(&self.inverse)
            .map(|(v, w)| term(v.x, w.x) + term(v.y, w.y) + term(v.z, w.z))
            .sum()
    }

    /// The work the motors do while the bodies go from `q0` to `q1` under `modes`, J: a
    /// constant torque's τ Δθ; a held spin's torque (at the two ends, averaged) times
    /// the angle turned.
    fn work(
        &self,
        (q0, u0): (&[DVec3], &[DVec3]),
        (q1, u1): (&[DVec3], &[DVec3]),
        modes: &Modes,
    ) -> f64 {
        let turned = |joint: &Held| relative_angle(joint, q1) - relative_angle(joint, q0);
        let held = |q, u| self.accelerations(q, u, modes).1;
        let mut holding = None;
        let mut k = self.joint_count();
        let mut work = 0.0;
        for (joint, drive) in self.joints.iter().zip(&modes.drives) {
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

    /// Moves the bodies through `h` seconds with `method`: the joints' modes judged at
    /// the start, and again wherever a motor reaches its target spin or a joint its
    /// limit inside the step (a limit stops the joint dead: the stop takes the kinetic
    /// energy of the approach, as a seesaw's board landing).
    pub fn advance(
        &self,
        method: Integrator,
        (q, u): (&mut [DVec3], &mut [DVec3]),
        h: f64,
        size: f64,
    ) -> Books {
        let mut left = h;
        let mut books = Books::default();
        // Each pass finishes the step or changes one joint's mode; the last takes what
        // is left of the step whatever happens in it.
        let passes = 2 * self.joints.len() + 1;
        for pass in 0..passes {
            let modes = self.modes(q, u);
            let (q0, u0) = (q.to_vec(), u.to_vec());
            let moved = |dt: f64| {
                let (mut q, mut u) = (q0.clone(), u0.clone());
                let slope: &Slope = &|q, u| self.accelerations(q, u, &modes).0;
                stepping::step(method, &mut q, &mut u, dt, slope);
                (q, u)
            };
            let (mut q1, mut u1) = moved(left);
            let events = if pass + 1 < passes {
                self.events(&modes, (&q0, &u0), (&q1, &u1))
            } else {
                Vec::new()
            };
            let mut dt = left;
            let mut first = None;
            for event in events {
                let at = self.locate(event, left, &moved);
                if at < dt || first.is_none() {
                    (dt, first) = (at, Some(event));
                }
            }
            if first.is_some() {
                (q1, u1) = moved(dt);
            }
            let mut after = modes.clone();
            match first {
                Some(Event::Reach(k)) => {
                    if let Some(Motor::Spin { spin, .. }) = self.joints[k].motor {
                        after.drives[k] = Some(Drive::Hold(spin));
                    }
                }
                Some(Event::Limit(k, side)) => after.stops[k] = Some(side),
                None => {}
            }
            let before = self.kinetic(&u1);
            self.project(&mut q1, &mut u1, &after, size);
            if matches!(first, Some(Event::Limit(..))) {
                books.stopped += before - self.kinetic(&u1);
            }
            books.work += self.work((&q0, &u0), (&q1, &u1), &modes);
            q.copy_from_slice(&q1);
            u.copy_from_slice(&u1);
            left -= dt;
            if first.is_none() || left <= 0.0 {
                break;
            }
        }
        books
    }

    /// The events between (`q0`, `u0`) and (`q1`, `u1`) under `modes`: motors driven at
    /// their largest torque whose spin passed the target, and joints free of a limit
    /// that went past it.
    fn events(
        &self,
        modes: &Modes,
        (q0, u0): (&[DVec3], &[DVec3]),
        (q1, u1): (&[DVec3], &[DVec3]),
    ) -> Vec<Event> {
        let mut events = Vec::new();
        for (k, joint) in self.joints.iter().enumerate() {
            if let (Some(Drive::Torque(_)), Some(Motor::Spin { spin, .. })) =
                (modes.drives[k], joint.motor)
            {
                let (before, after) = (
                    relative_spin(joint, u0) - spin,
                    relative_spin(joint, u1) - spin,
                );
                if !reached(before, spin) && (reached(after, spin) || before * after < 0.0) {
                    events.push(Event::Reach(k));
                }
            }
            if modes.stops[k].is_none() {
                for side in [Side::Lower, Side::Upper] {
                    if inside(joint, side, q0) > 0.0 && inside(joint, side, q1) < 0.0 {
                        events.push(Event::Limit(k, side));
                    }
                }
            }
        }
        events
    }

    /// The time into a stretch of `left` seconds at which `event` happens (regula falsi,
    /// Illinois): the first trial found at or past it.
    fn locate(
        &self,
        event: Event,
        left: f64,
        moved: &dyn Fn(f64) -> (Vec<DVec3>, Vec<DVec3>),
    ) -> f64 {
        let value = |dt: f64| {
            let (q, u) = moved(dt);
            match event {
                Event::Reach(k) => {
                    let joint = &self.joints[k];
                    let spin = match joint.motor {
                        Some(Motor::Spin { spin, .. }) => spin,
                        _ => 0.0,
                    };
                    let off = relative_spin(joint, &u) - spin;
                    // Reached counts as crossed: the search stops there.
                    if reached(off, spin) { 0.0 } else { off }
                }
                Event::Limit(k, side) => inside(&self.joints[k], side, &q),
            }
        };
        let (mut lo, mut hi) = (0.0, left);
        let (mut f_lo, mut f_hi) = (value(lo), value(hi));
        let mut side = 0;
        for _ in 0..MOST_TRIALS {
            if hi - lo <= EVENT_WIDTH {
                break;
            }
            let mut t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
            if !(t > lo && t < hi) {
                t = 0.5 * (lo + hi);
            }
            let f = value(t);
            if f == 0.0 {
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

    /// The accelerations at (`q`, `u`), and what each joint does to its bodies.
    pub fn reactions(&self, q: &[DVec3], u: &[DVec3]) -> (Vec<DVec3>, Vec<Reaction>) {
        let modes = self.modes(q, u);
        let (a, lambda) = self.accelerations(q, u, &modes);
        let plain = Modes {
            drives: vec![None; self.joints.len()],
            stops: vec![None; self.joints.len()],
        };
        let rows = self.rows(q, u, &plain);
        let mut k = self.joint_count();
        let mut first = 0;
        let out = self
            .joints
            .iter()
            .zip(&modes.drives)
            .map(|(joint, drive)| {
                let ours = first..first + Self::count(joint, true);
                first = ours.end;
                // A row pulls a body by its multiplier times its coefficients there.
                let (rows, lambda) = (&rows, &lambda);
                let on = |body: usize| -> DVec2 {
                    let mut sum = DVec2::ZERO;
                    for r in ours.clone() {
                        for (i, j) in [Some(rows[r].b), rows[r].a].into_iter().flatten() {
                            if i == body {
                                sum += j.truncate() * lambda[r];
                            }
                        }
                    }
                    sum
                };
                let on_b = on(joint.b);
                let on_a = joint.a.map_or(-on_b, &on);
                let tensions = match joint.pulley {
                    None => [0.0; 2],
                    Some(_) => [-lambda[ours.start], -lambda[ours.end - 1]],
                };
                let torque = match drive {
                    Some(Drive::Torque(t)) => *t,
                    Some(Drive::Hold(_)) => {
                        k += 1;
                        lambda[k - 1]
                    }
                    None => 0.0,
                };
                Reaction {
                    on_b,
                    on_a,
                    torque,
                    tensions,
                }
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
