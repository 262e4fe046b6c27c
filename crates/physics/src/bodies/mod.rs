//! Rigid bodies in motion (`[[body]]`): each one's centroid, velocity, angle and spin,
//! moved through the step the particles took.
//!
//! A body feels the uniform field at its centroid, which gives it no torque, and the
//! forces of the walls, ramps and other bodies it touches (`contact.rs` finds where,
//! `island.rs` moves bodies that may touch one another together): between events its
//! accelerations are constant, and the integration methods take their own step on that
//! motion — euler x + v h, semi-implicit euler x + (v + a h) h, and the others (verlet,
//! rk4, pefrl, dopri5), whose error vanishes for a constant acceleration,
//! x + v h + a h²/2 — so that a body under euler departs from the parabola exactly as a
//! particle beside it does. Bodies do not yet meet particles: they pass through them
//! (docs/scene-format.md says so).

mod contact;
mod island;
mod joints;
mod solve;
mod stepping;

use std::sync::Arc;

use glam::{DVec2, DVec3};

pub use contact::Applied;
use contact::{Pose, Rigid};
use island::Island;
pub use joints::pulley_path;
use joints::{Held, Mechanism, Reaction};

use crate::contacts::obstacles::{self, Obstacle};
use crate::diagnostics::{Diagnostics, ParticleReadout};
use crate::forces::uniform;
use crate::scene::Vector;
use crate::{Integrator, JointKind, Scene};

/// What the surfaces took from the bodies' energy in a step, joules.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Taken {
    pub impacts: f64,
    pub friction: f64,
    /// What the joints' motors gave, joules.
    pub motors: f64,
}

/// A pin's, a hinge's or a pulley's state now.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JointReadout {
    /// A pulley's string tension on a's side and on b's, N (equal for a massless wheel).
    pub tensions: [f64; 2],
    /// A pulley's wheel spin, rad/s.
    pub wheel_spin: f64,
    /// b's angle less a's (a pin's: the body's) from the joint's reference, degrees,
    /// counter-clockwise, unwrapped.
    pub angle: f64,
    /// The joint's force on b (a pin's body), N.
    pub force: DVec2,
    /// The motor's torque on b, N·m (0 without a motor).
    pub torque: f64,
    /// The joint's point in the world, m.
    pub at: DVec2,
}

/// The bodies of a scene, in scene order: what never changes shared between copies (a
/// keyframe of the time machine), the state in arrays.
#[derive(Clone, Debug, Default)]
pub(crate) struct Bodies {
    names: Arc<[String]>,
    mass: Arc<[f64]>,
    /// About the centroid, kg·m².
    inertia: Arc<[f64]>,
    /// Each outline about its centroid, in the body's frame.
    outline: Arc<[Vec<DVec2>]>,
    fixed: Arc<[bool]>,
    /// The farthest vertex from the centroid, m.
    radius: Arc<[f64]>,
    /// Each body's restitution, kinetic and static friction, met by another body's.
    coefficients: Arc<[(f64, f64, f64)]>,
    /// Whether bodies meet each other (`[world] collisions`).
    collide: bool,
    /// The walls and ramps.
    solids: Arc<[Obstacle]>,
    /// The pins, hinges and pulleys, in scene order.
    joints: Arc<[Held]>,
    joint_names: Arc<[String]>,
    /// The bodies the joints hold (fixed ones too), in scene order: they move together,
    /// and meet nothing yet.
    jointed: Arc<[usize]>,
    /// The mechanism's size, m: the widest jointed body's reach or the farthest pin from
    /// the origin, what the joints are held to a fraction of.
    jointed_size: f64,
    /// What each joint did to its bodies at the last step's end (or the start).
    reactions: Vec<Reaction>,
    /// Each pulley wheel with inertia: its I (kg·m²), and its spin (rad/s), in joint
    /// order; the mechanism's coordinates after the jointed bodies'.
    wheels: Arc<[f64]>,
    wheel_spin: Vec<f64>,
    /// The kinetic energy the joints took at the start (velocities that moved them
    /// apart, made consistent), J.
    start_loss: Option<f64>,
    /// The uniform field, m/s².
    gravity: DVec2,
    /// Each body's acceleration through the last step (or at the start): the field's
    /// and the surfaces' it rests on.
    acceleration: Vec<DVec2>,
    /// The scene's time step, s: how slow an approach comes to rest.
    time_step: f64,
    /// The centroids, m.
    position: Vec<DVec2>,
    /// m/s.
    velocity: Vec<DVec2>,
    /// Degrees counter-clockwise, unwrapped: kept in the unit the scene file writes, so
    /// that a saved state reads back to the bit.
    angle: Vec<f64>,
    /// Radians per second, counter-clockwise.
    spin: Vec<f64>,
}

/// The scene's joints in runtime form, their bodies numbered among `jointed` (the bodies
/// in joints, in scene order). A scene that passed validation names only bodies.
fn held(scene: &Scene, jointed: &[usize]) -> Vec<Held> {
    let index = |name: &str| {
        let body = scene.bodies.iter().position(|b| b.name == name)?;
        jointed.binary_search(&body).ok().map(|k| (body, k))
    };
    let mut wheel = jointed.len();
    scene
        .joints
        .iter()
        .filter_map(|joint| {
            let (body_b, b) = index(&joint.body)?;
            if let JointKind::Pulley {
                a, radius, length, ..
            } = &joint.kind
            {
                let (body_a, a) = index(a)?;
                let centre = joint.at.to_dvec2();
                let ends = |i: usize| scene.bodies[i].position.to_dvec2();
                let length = length.unwrap_or_else(|| {
                    joints::string_length(centre, *radius, ends(body_a), ends(body_b))
                });
                let spins = joint.wheel_inertia() > 0.0;
                let pulley = joints::Pulley {
                    centre,
                    radius: *radius,
                    length,
                    wheel: spins.then(|| {
                        wheel += 1;
                        wheel - 1
                    }),
                };
                return Some(Held {
                    b,
                    a: Some(a),
                    anchor_b: DVec2::ZERO,
                    anchor_a: DVec2::ZERO,
                    motor: None,
                    reference: 0.0,
                    limits: None,
                    pulley: Some(pulley),
                });
            }
            let frame = |i: usize| {
                let body = &scene.bodies[i];
                (body.position.to_dvec2(), body.angle)
            };
            let (position_b, angle_b) = frame(body_b);
            let at = joint.at.to_dvec2();
            let anchor_b = joint
                .anchor
                .unwrap_or_else(|| crate::scene::in_frame(at, position_b, angle_b));
            let (a, anchor_a, angle_a) = match &joint.kind {
                JointKind::Pin | JointKind::Pulley { .. } => (None, at, 0.0),
                JointKind::Hinge { a, anchor_a } => {
                    let (body_a, a) = index(a)?;
                    let (position_a, angle_a) = frame(body_a);
                    let anchor =
                        anchor_a.unwrap_or_else(|| crate::scene::in_frame(at, position_a, angle_a));
                    (Some(a), anchor, angle_a)
                }
            };
            let reference = joint.reference_angle.unwrap_or(angle_b - angle_a);
            Some(Held {
                b,
                a,
                anchor_b,
                anchor_a,
                motor: joint.motor,
                reference,
                limits: joint.limits.map(|(lower, upper)| {
                    (
                        (reference + lower).to_radians(),
                        (reference + upper).to_radians(),
                    )
                }),
                pulley: None,
            })
        })
        .collect()
}

/// Each pulley wheel with inertia, in joint order: its I (kg·m²) and its spin (rad/s).
fn wheels(scene: &Scene) -> (Vec<f64>, Vec<f64>) {
    scene
        .joints
        .iter()
        .filter_map(|joint| match joint.kind {
            JointKind::Pulley { spin, .. } if joint.wheel_inertia() > 0.0 => {
                Some((joint.wheel_inertia(), spin))
            }
            _ => None,
        })
        .unzip()
}

/// The root of `i`'s group in a union–find forest, halving the path on the way.
fn find(root: &mut [usize], mut i: usize) -> usize {
    while root[i] != i {
        root[i] = root[root[i]];
        i = root[i];
    }
    i
}

impl Bodies {
    pub fn new(scene: &Scene) -> Self {
        let bodies = &scene.bodies;
        let jointed: Vec<usize> = (0..bodies.len())
            .filter(|&i| {
                let name = bodies[i].name.as_str();
                scene
                    .joints
                    .iter()
                    .any(|j| j.body == name || j.other() == Some(name))
            })
            .collect();
        let (wheel_inertia, wheel_spin) = wheels(scene);
        let moving = |b: &crate::Body, v: Vector, spin: f64| {
            if b.fixed {
                (DVec2::ZERO, 0.0)
            } else {
                (v.to_dvec2(), spin)
            }
        };
        Self {
            names: bodies.iter().map(|b| b.name.clone()).collect(),
            mass: bodies.iter().map(crate::Body::total_mass).collect(),
            inertia: bodies.iter().map(crate::Body::inertia).collect(),
            outline: bodies.iter().map(crate::Body::local_outline).collect(),
            fixed: bodies.iter().map(|b| b.fixed).collect(),
            radius: bodies
                .iter()
                .map(|b| {
                    b.local_outline()
                        .iter()
                        .fold(0.0, |r: f64, v| r.max(v.length()))
                })
                .collect(),
            coefficients: bodies
                .iter()
                .map(|b| (b.restitution, b.friction, b.static_friction()))
                .collect(),
            collide: scene.world.collisions,
            solids: obstacles::obstacles(scene).into(),
            joints: held(scene, &jointed).into(),
            joint_names: scene.joints.iter().map(|j| j.name.clone()).collect(),
            jointed: jointed.into(),
            jointed_size: 0.0,
            reactions: Vec::new(),
            wheels: wheel_inertia.into(),
            wheel_spin,
            start_loss: None,
            gravity: scene.world.gravity.to_dvec2(),
            acceleration: Vec::new(),
            time_step: scene.simulation.time_step,
            position: bodies.iter().map(|b| b.position.to_dvec2()).collect(),
            velocity: bodies
                .iter()
                .map(|b| moving(b, b.velocity, b.spin).0)
                .collect(),
            angle: bodies.iter().map(|b| b.angle).collect(),
            spin: bodies
                .iter()
                .map(|b| moving(b, b.velocity, b.spin).1)
                .collect(),
        }
    }

    pub fn len(&self) -> usize {
        self.position.len()
    }

    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// The acceleration of body `i`, m/s²: the field's and the surfaces', none for a
    /// fixed one.
    fn acceleration(&self, i: usize) -> DVec2 {
        if self.fixed[i] {
            DVec2::ZERO
        } else {
            self.acceleration.get(i).copied().unwrap_or(self.gravity)
        }
    }

    fn pose(&self, i: usize) -> Pose {
        Pose {
            position: self.position[i],
            velocity: self.velocity[i],
            angle: self.angle[i],
            spin: self.spin[i],
        }
    }

    fn rigid(&self, i: usize) -> Rigid<'_> {
        let (restitution, friction, static_friction) = self.coefficients[i];
        Rigid {
            mass: self.mass[i],
            inertia: self.inertia[i],
            outline: &self.outline[i],
            radius: self.radius[i],
            gravity: self.gravity,
            fixed: self.fixed[i],
            restitution,
            friction,
            static_friction,
        }
    }

    /// The bodies that may touch one another while each moves at most `travel` metres,
    /// in groups, each in scene order: moving bodies joined through the moving bodies
    /// near them, with the fixed bodies near any of them (a fixed body joins no two
    /// groups, so a floor of boxes does not make one island of everything on it).
    fn islands(&self, travel: f64) -> Vec<Vec<usize>> {
        let n = self.len();
        let reach =
            2.0 * travel + island::TOUCHING * self.radius.iter().fold(0.0, |r: f64, &x| r.max(x));
        let near = |i: usize, j: usize| {
            self.collide
                && self.position[i].distance(self.position[j]) - self.radius[i] - self.radius[j]
                    <= reach
        };
        let mut root: Vec<usize> = (0..n).collect();
        let moving: Vec<usize> = (0..n)
            .filter(|&i| !self.fixed[i] && self.jointed.binary_search(&i).is_err())
            .collect();
        for (a, &i) in moving.iter().enumerate() {
            for &j in &moving[a + 1..] {
                if near(i, j) {
                    let (ri, rj) = (find(&mut root, i), find(&mut root, j));
                    root[ri.max(rj)] = ri.min(rj);
                }
            }
        }
        let mut groups: Vec<Vec<usize>> = Vec::new();
        let mut group_of = vec![usize::MAX; n];
        for &i in &moving {
            let r = find(&mut root, i);
            if group_of[r] == usize::MAX {
                group_of[r] = groups.len();
                groups.push(Vec::new());
            }
            groups[group_of[r]].push(i);
        }
        for group in &mut groups {
            let fixed: Vec<usize> = (0..n)
                .filter(|&f| self.fixed[f] && group.iter().any(|&i| near(i, f)))
                .collect();
            group.extend(fixed);
            group.sort_unstable();
        }
        groups
    }

    fn island(&self, members: &[usize]) -> (Island<'_>, Vec<Pose>) {
        (
            Island {
                members: members.iter().map(|&i| self.rigid(i)).collect(),
                solids: &self.solids,
                collide: self.collide,
            },
            members.iter().map(|&i| self.pose(i)).collect(),
        )
    }

    /// Finds what each body's accelerations are at the start, under what it rests on
    /// (a step of `h` sets how slow an approach comes to rest).
    pub fn settle(&mut self, h: f64) {
        self.time_step = h;
        self.acceleration = vec![self.gravity; self.len()];
        for members in self.islands(0.0) {
            let (island, poses) = self.island(&members);
            let pushes = island.now(&poses, h).0;
            for (&i, push) in members.iter().zip(pushes) {
                self.acceleration[i] = push.linear;
            }
        }
        // From what a saved state keeps as it was (the bodies' sizes, the pins' points),
        // so that a run continued from one projects exactly as the straight run.
        self.jointed_size = self
            .jointed
            .iter()
            .map(|&i| self.radius[i])
            .chain(
                self.joints
                    .iter()
                    .filter(|j| j.a.is_none())
                    .map(|j| j.anchor_a.abs().max_element()),
            )
            .chain(
                self.joints
                    .iter()
                    .filter_map(|j| j.pulley)
                    .map(|p| p.centre.abs().max_element() + p.radius),
            )
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE);
        if !self.joints.is_empty() {
            let (mechanism, mut q, mut u) = self.mechanism();
            self.start_loss = mechanism.start(&mut q, &mut u, self.jointed_size);
            if self.start_loss.is_some() {
                self.take_jointed(&q, &u);
            }
        }
        self.read_joints();
    }

    /// Writes the mechanism's positions and velocities back into the jointed bodies
    /// and the wheels.
    fn take_jointed(&mut self, q: &[DVec3], u: &[DVec3]) {
        for (k, &i) in self.jointed.iter().enumerate() {
            if self.fixed[i] {
                continue;
            }
            self.position[i] = q[k].truncate();
            self.angle[i] = q[k].z.to_degrees();
            self.velocity[i] = u[k].truncate();
            self.spin[i] = u[k].z;
        }
        for (k, spin) in self.wheel_spin.iter_mut().enumerate() {
            *spin = u[self.jointed.len() + k].z;
        }
    }

    /// The kinetic energy the joints took at the start from velocities that moved them
    /// apart, J; `None` where the velocities were consistent with them.
    pub fn start_loss(&self) -> Option<f64> {
        self.start_loss
    }

    /// The mechanism of the jointed bodies, and their positions (x, y, angle in radians)
    /// and velocities.
    fn mechanism(&self) -> (Mechanism<'_>, Vec<DVec3>, Vec<DVec3>) {
        let mechanism = Mechanism {
            joints: &self.joints,
            inverse: self
                .jointed
                .iter()
                .map(|&i| {
                    if self.fixed[i] {
                        DVec3::ZERO
                    } else {
                        let w = 1.0 / self.mass[i];
                        DVec3::new(w, w, 1.0 / self.inertia[i])
                    }
                })
                .chain(self.wheels.iter().map(|&inertia| DVec3::Z / inertia))
                .collect(),
            weight: self
                .jointed
                .iter()
                .map(|&i| (self.gravity * self.mass[i]).extend(0.0))
                .chain(self.wheels.iter().map(|_| DVec3::ZERO))
                .collect(),
        };
        // A wheel's angle plays no part: only its spin is kept.
        let q = self
            .jointed
            .iter()
            .map(|&i| self.position[i].extend(self.angle[i].to_radians()))
            .chain(self.wheels.iter().map(|_| DVec3::ZERO))
            .collect();
        let u = self
            .jointed
            .iter()
            .map(|&i| self.velocity[i].extend(self.spin[i]))
            .chain(self.wheel_spin.iter().map(|&spin| DVec3::Z * spin))
            .collect();
        (mechanism, q, u)
    }

    /// The jointed bodies' accelerations and the joints' reactions now.
    fn read_joints(&mut self) {
        if self.joints.is_empty() {
            return;
        }
        self.acceleration.resize(self.len(), self.gravity);
        let (mechanism, q, u) = self.mechanism();
        let (a, reactions) = mechanism.reactions(&q, &u);
        self.reactions = reactions;
        for (k, &i) in self.jointed.iter().enumerate() {
            if !self.fixed[i] {
                self.acceleration[i] = a[k].truncate();
            }
        }
    }

    /// Moves the jointed bodies through `h` seconds with `method`; returns the motors'
    /// work and what the limits' stops took.
    fn advance_jointed(&mut self, method: Integrator, h: f64) -> joints::Books {
        if self.joints.is_empty() {
            return joints::Books::default();
        }
        let (mechanism, mut q, mut u) = self.mechanism();
        let books = mechanism.advance(method, (&mut q, &mut u), h, self.jointed_size);
        self.take_jointed(&q, &u);
        self.read_joints();
        books
    }

    /// The forces on body `i` now, each where it acts: its weight at the centroid, then
    /// the normal force and friction of each surface or body it rests on.
    pub fn forces(&self, i: usize) -> Vec<Applied> {
        let weight = Applied {
            arm: DVec2::ZERO,
            force: self.gravity * self.mass[i],
            friction: false,
        };
        let mut forces = vec![weight];
        if self.fixed[i] {
            return forces;
        }
        if let Ok(k) = self.jointed.binary_search(&i) {
            for (joint, reaction) in self.joints.iter().zip(&self.reactions) {
                let turn =
                    |anchor: DVec2| DVec2::from_angle(self.angle[i].to_radians()).rotate(anchor);
                if joint.b == k {
                    forces.push(Applied {
                        arm: turn(joint.anchor_b),
                        force: reaction.on_b,
                        friction: false,
                    });
                } else if joint.a == Some(k) {
                    forces.push(Applied {
                        arm: turn(joint.anchor_a),
                        force: reaction.on_a,
                        friction: false,
                    });
                }
            }
            return forces;
        }
        let Some(members) = self.islands(0.0).into_iter().find(|g| g.contains(&i)) else {
            return forces;
        };
        let (island, poses) = self.island(&members);
        let me = members.iter().position(|&m| m == i);
        forces.extend(
            island
                .now(&poses, self.time_step)
                .1
                .into_iter()
                .filter(|&(body, _)| Some(body) == me)
                .map(|(_, applied)| applied),
        );
        forces
    }

    /// Moves every body through a step of `h` seconds taken with `method`; returns what
    /// the surfaces took from the bodies' energy in it.
    pub fn advance(&mut self, method: Integrator, h: f64) -> Taken {
        self.acceleration.resize(self.len(), self.gravity);
        // How far any body may go in the step, with room for what an impact gives it.
        let fastest = (0..self.len())
            .filter(|&i| !self.fixed[i])
            .map(|i| {
                self.velocity[i].length()
                    + self.gravity.length() * h
                    + self.spin[i].abs() * self.radius[i]
            })
            .fold(0.0, f64::max);
        let jointed = self.advance_jointed(method, h);
        let mut taken = Taken {
            impacts: jointed.stopped,
            motors: jointed.work,
            ..Taken::default()
        };
        for members in self.islands(2.0 * fastest * h) {
            let (island, mut poses) = self.island(&members);
            let (pushes, books) = island.advance(&mut poses, method, h);
            taken.impacts += books.impacts;
            taken.friction += books.friction;
            for ((&i, pose), push) in members.iter().zip(poses).zip(pushes) {
                if self.fixed[i] {
                    continue;
                }
                self.acceleration[i] = push.linear;
                self.position[i] = pose.position;
                self.velocity[i] = pose.velocity;
                self.angle[i] = pose.angle;
                self.spin[i] = pose.spin;
            }
        }
        taken
    }

    /// Everything about body `i` now.
    pub fn readout(&self, i: usize) -> ParticleReadout {
        let (m, x, v, spin) = (
            self.mass[i],
            self.position[i],
            self.velocity[i],
            self.spin[i],
        );
        let moving = !self.fixed[i];
        let rotational_energy = if moving {
            0.5 * self.inertia[i] * spin * spin
        } else {
            0.0
        };
        let translational = if moving {
            0.5 * m * v.length_squared()
        } else {
            0.0
        };
        ParticleReadout {
            position: x,
            velocity: v,
            acceleration: self.acceleration(i),
            speed: v.length(),
            kinetic_energy: translational + rotational_energy,
            momentum: if moving { m * v } else { DVec2::ZERO },
            spin,
            angle: self.angle[i],
            rotational_energy,
            angular_momentum: if moving {
                m * x.perp_dot(v) + self.inertia[i] * spin
            } else {
                0.0
            },
        }
    }

    /// Adds the bodies' energies and momenta to `diagnostics`; fixed bodies, which never
    /// move, count none (as fixed particles).
    pub fn add_to(&self, diagnostics: &mut Diagnostics) {
        for i in 0..self.len() {
            if self.fixed[i] {
                continue;
            }
            let readout = self.readout(i);
            diagnostics.energy.kinetic += readout.kinetic_energy;
            diagnostics.energy.uniform +=
                uniform::potential(self.mass[i], self.gravity, readout.position);
            diagnostics.momentum += readout.momentum;
            diagnostics.angular_momentum += readout.angular_momentum;
        }
        // A pulley's wheel turns about its fixed axle: kinetic energy and spin, no
        // momentum.
        for (&inertia, &spin) in self.wheels.iter().zip(&self.wheel_spin) {
            diagnostics.energy.kinetic += 0.5 * inertia * spin * spin;
            diagnostics.angular_momentum += inertia * spin;
        }
    }

    /// Writes the state reached into `scene`'s bodies and joints (each joint's anchors and
    /// reference angle as they were, so that continuing is exact).
    pub fn save_into(&self, scene: &mut Scene) {
        if scene.joints.len() == self.joints.len() {
            for (j, (saved, joint)) in scene.joints.iter_mut().zip(self.joints.iter()).enumerate() {
                match &mut saved.kind {
                    JointKind::Pulley { spin, length, .. } => {
                        *spin = self.joint(j).wheel_spin;
                        *length = joint.pulley.map(|p| p.length);
                        continue;
                    }
                    JointKind::Hinge { anchor_a, .. } => {
                        *anchor_a = Some(joint.anchor_a);
                        let at = self.joint(j).at;
                        saved.at = Vector::cartesian(at.x, at.y);
                    }
                    JointKind::Pin => {}
                }
                saved.anchor = Some(joint.anchor_b);
                saved.reference_angle = Some(joint.reference);
            }
        }
        for (i, body) in scene.bodies.iter_mut().enumerate() {
            let x = self.position[i];
            body.position = Vector::cartesian(x.x, x.y);
            body.angle = self.angle[i];
            if !body.fixed {
                let v = self.velocity[i];
                body.velocity = Vector::cartesian(v.x, v.y);
                body.spin = self.spin[i];
            }
        }
    }

    pub fn names(&self) -> &[String] {
        &self.names
    }

    pub fn joint_names(&self) -> &[String] {
        &self.joint_names
    }

    pub fn has_motors(&self) -> bool {
        self.joints.iter().any(|j| j.motor.is_some())
    }

    pub fn is_pin(&self, j: usize) -> bool {
        self.joints[j].a.is_none()
    }

    /// The first pulley (and the body) that a body on its string has been pulled up to:
    /// their bounding circles meet, and the string's run on that side is about to end.
    pub fn pulley_reached(&self) -> Option<(String, String)> {
        self.joints.iter().enumerate().find_map(|(j, joint)| {
            let pulley = joint.pulley?;
            [Some(joint.b), joint.a]
                .into_iter()
                .flatten()
                .find_map(|k| {
                    let i = self.jointed[k];
                    (self.position[i].distance(pulley.centre) <= pulley.radius + self.radius[i])
                        .then(|| (self.joint_names[j].clone(), self.names[i].clone()))
                })
        })
    }

    pub fn is_pulley(&self, j: usize) -> bool {
        self.joints[j].pulley.is_some()
    }

    /// Joint `j`'s angle, reaction and motor torque now, and where it is.
    pub fn joint(&self, j: usize) -> JointReadout {
        let joint = &self.joints[j];
        let b = self.jointed[joint.b];
        let angle_a = joint.a.map_or(0.0, |a| self.angle[self.jointed[a]]);
        let reaction = self.reactions.get(j).copied().unwrap_or_default();
        if let Some(pulley) = joint.pulley {
            let wheel_spin = match pulley.wheel {
                Some(w) => self.wheel_spin[w - self.jointed.len()],
                // A massless wheel turns with the string (no slip): b's run shortens.
                None => 0.0,
            };
            return JointReadout {
                tensions: reaction.tensions,
                wheel_spin,
                angle: 0.0,
                force: reaction.on_b,
                torque: 0.0,
                at: pulley.centre,
            };
        }
        JointReadout {
            tensions: [0.0; 2],
            wheel_spin: 0.0,
            angle: self.angle[b] - angle_a - joint.reference,
            force: reaction.on_b,
            torque: reaction.torque,
            at: self.position[b]
                + DVec2::from_angle(self.angle[b].to_radians()).rotate(joint.anchor_b),
        }
    }

    /// Body `i`'s outline in the world now, counter-clockwise.
    pub fn world_outline(&self, i: usize) -> Vec<DVec2> {
        let turn = DVec2::from_angle(self.angle[i].to_radians());
        self.outline[i]
            .iter()
            .map(|&v| self.position[i] + turn.rotate(v))
            .collect()
    }

    /// About how many bytes the state holds.
    pub fn state_bytes(&self) -> usize {
        self.len() * (2 * size_of::<DVec2>() + 2 * size_of::<f64>())
    }
}

impl Scene {
    /// The forces on body `i` at the scene's start, each where it acts: its free-body
    /// diagram before Play ([`crate::Simulation::body_forces`] while it runs).
    /// A scene being edited may not be valid yet: forces that are not finite (a body of
    /// no mass or no area) are left out rather than drawn.
    pub fn body_forces(&self, i: usize) -> Vec<Applied> {
        let mut bodies = Bodies::new(self);
        if i >= bodies.len() {
            return Vec::new();
        }
        bodies.read_joints();
        bodies
            .forces(i)
            .into_iter()
            .filter(|f| f.force.is_finite() && f.arm.is_finite())
            .collect()
    }
}
