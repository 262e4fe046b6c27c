//! The smooth forces: everything that depends only on positions and velocities at an
//! instant (impacts are impulses, handled by the contact code). One file per law (the
//! two pair laws share [`pair`]; [`direct`] and [`tree`] are two ways to sum them); this
//! module owns the per-particle constants they read and sums them into accelerations.

pub(crate) mod direct;
pub(crate) mod drag;
pub(crate) mod magnetic;
pub(crate) mod normal;
pub(crate) mod own;
pub(crate) mod pair;
mod response;
pub(crate) mod spring;
pub(crate) mod tree;
pub(crate) mod uniform;

use std::sync::Arc;

use glam::DVec2;

use crate::constraints::Constraints;
use crate::scene::{PairForces, Scene};
pub(crate) use normal::SurfaceContact;
pub(crate) use spring::SpringLink;

/// Power the smooth dissipative forces take out of the motion, watts, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Power {
    /// Spring damping.
    pub damping: f64,
    /// Surface friction.
    pub friction: f64,
    /// Air resistance.
    pub drag: f64,
}

/// The constants of every force law, in runtime form (SI, indexed by particle).
#[derive(Clone, Debug)]
pub(crate) struct ForceModel {
    /// Kilograms.
    pub mass: Arc<[f64]>,
    /// 1/kg; zero for fixed particles, which is what keeps them still.
    pub inverse_mass: Arc<[f64]>,
    /// Coulombs.
    pub charge: Arc<[f64]>,
    /// The uniform field plus the particle's own applied acceleration, m/s²; zero for
    /// fixed particles.
    pub uniform: Arc<[DVec2]>,
    /// G when gravitation is on.
    pub gravitational_constant: Option<f64>,
    /// k when electrostatics is on.
    pub coulomb_constant: Option<f64>,
    /// ε², m²: both pair laws read r² + ε² where they would read r² (0: the exact laws).
    pub softening2: f64,
    /// The particles that take part in pairwise forces, ascending.
    pub interacting: Vec<usize>,
    /// Those of them with a charge, ascending.
    pub charged: Vec<usize>,
    /// The opening angle when gravitation is summed with a tree.
    pub tree: Option<f64>,
    pub springs: Vec<SpringLink>,
    /// Each particle's springs (indices into `springs`), ascending.
    pub springs_at: Arc<[Box<[u32]>]>,
    /// Rods and strings: their forces are added last, answering all the others.
    pub constraints: Constraints,
    /// The threads the direct pair sum may use.
    pub workers: crate::parallel::Workers,
    /// Particles resting on or sliding along a ramp or wall during the current step.
    pub surface_contacts: Vec<SurfaceContact>,
    /// The moving particles with air resistance, ascending.
    pub drag: Vec<drag::Drag>,
    /// The moving charged particles in the magnetic field, ascending, each with q `B_z`.
    pub magnetic: Vec<(usize, f64)>,
    /// The scene's forces of its own (`[[force]]`).
    pub own: Vec<own::OwnForce>,
}

impl ForceModel {
    /// Builds the model of a valid scene.
    pub fn new(scene: &Scene) -> Self {
        let gravity = scene.world.gravity.to_dvec2();
        let gravitational_constant = (scene.world.gravitation
            && scene.world.gravitational_constant != 0.0)
            .then_some(scene.world.gravitational_constant);
        let coulomb_constant = (scene.world.electrostatics && scene.world.coulomb_constant != 0.0)
            .then_some(scene.world.coulomb_constant);
        let particles = &scene.particles;
        let interacting: Vec<usize> = (0..particles.len())
            .filter(|&i| gravitational_constant.is_some() || particles[i].charge != 0.0)
            .filter(|_| gravitational_constant.is_some() || coulomb_constant.is_some())
            .collect();
        let charged = interacting
            .iter()
            .copied()
            .filter(|&i| particles[i].charge != 0.0)
            .collect();
        let index = |end| scene.end(end);
        let springs: Vec<SpringLink> = scene
            .springs
            .iter()
            .map(|s| SpringLink {
                from: index(&s.from),
                to: index(&s.to),
                stiffness: s.stiffness,
                natural_length: s.natural_length,
                damping: s.damping,
            })
            .collect();
        let inverse_mass: Vec<f64> = particles
            .iter()
            .map(|p| if p.fixed { 0.0 } else { 1.0 / p.mass })
            .collect();
        Self {
            mass: particles.iter().map(|p| p.mass).collect(),
            constraints: Constraints::new(scene.links(), &inverse_mass),
            inverse_mass: inverse_mass.into(),
            charge: particles.iter().map(|p| p.charge).collect(),
            uniform: particles
                .iter()
                .map(|p| {
                    if p.fixed {
                        DVec2::ZERO
                    } else {
                        gravity + p.acceleration.to_dvec2()
                    }
                })
                .collect(),
            gravitational_constant,
            coulomb_constant,
            softening2: scene.world.softening * scene.world.softening,
            interacting,
            charged,
            tree: (scene.simulation.pair_forces == PairForces::Tree)
                .then_some(scene.simulation.opening_angle),
            springs_at: spring::each_particles(&springs, particles.len()),
            springs,
            surface_contacts: Vec::new(),
            workers: crate::parallel::Workers::default(),
            drag: drag::Drag::of(particles, scene.world.air_density),
            magnetic: magnetic::of(particles, scene.world.magnetic_field),
            own: own::OwnForce::of(scene),
        }
    }

    /// The distance the pair laws read between points `a` and `b`: √(r² + ε²), the
    /// plain distance when there is no softening (the same bits).
    pub fn pair_distance(&self, a: DVec2, b: DVec2) -> f64 {
        pair::distance(a, b, self.softening2)
    }

    pub fn is_fixed(&self, i: usize) -> bool {
        self.inverse_mass[i] == 0.0
    }

    /// Accelerations (m/s²) of every particle at time `t` (seconds), positions `x` and
    /// velocities `v`.
    ///
    /// Pairwise and spring forces are summed as forces first, each applied equal and
    /// opposite, so the total internal force is zero up to rounding and momentum is
    /// conserved; then divided by mass.
    pub fn accelerations(&self, t: f64, x: &[DVec2], v: &[DVec2], out: &mut [DVec2]) {
        let pressed = self.accelerations_off_surfaces(t, x, v, out);
        // Last: a surface answers the sum of all the other forces (with the rods, where
        // they hold the particle: then only its friction is left).
        for (k, contact) in self.surface_contacts.iter().enumerate() {
            contact.apply_pressed(
                &mut out[contact.particle],
                pressed.get(k).copied().flatten(),
            );
        }
    }

    /// Whether an evaluation shares its pair sum out among threads (when there are
    /// several): the direct sum of many bodies, or a tree over many leaves.
    pub(crate) fn shares_pairs(&self) -> bool {
        match self.tree {
            None => direct::is_blocked(self.interacting.len()),
            Some(_) => {
                direct::is_blocked(self.charged.len())
                    || self.interacting.len() >= crate::tuning::SPLIT_LEAVES * crate::tuning::LEAF
            }
        }
    }

    /// The accelerations of every force but the surfaces' — but for the normal force of
    /// a surface that a particle held by a rod or string rests on, which the links
    /// answer with: for each surface contact, how hard it presses so (m/s²), or `None`
    /// (empty when no link holds a resting particle).
    pub(crate) fn accelerations_off_surfaces(
        &self,
        t: f64,
        x: &[DVec2],
        v: &[DVec2],
        out: &mut [DVec2],
    ) -> Vec<Option<f64>> {
        self.free_accelerations(t, x, v, out);
        if self.constraints.is_empty() {
            return Vec::new();
        }
        let w = &self.inverse_mass;
        if self.surface_contacts.is_empty() {
            self.constraints.add_forces(x, v, w, out);
            return Vec::new();
        }
        let resting: Vec<(usize, DVec2)> = self
            .surface_contacts
            .iter()
            .map(|c| (c.particle, c.normal))
            .collect();
        self.constraints
            .add_forces_with_surfaces(x, v, w, out, &resting)
    }

    /// Whether every particle's acceleration is constant through a step: no pairwise
    /// forces, springs, rods or strings, so each feels only the field, its applied
    /// acceleration and the surfaces' answer to them (fixed for the step).
    pub fn accelerations_are_constant(&self) -> bool {
        self.interacting.is_empty()
            && self.springs.is_empty()
            && self.constraints.is_empty()
            && !self.has_own_varying_forces()
    }

    /// Whether a force varies through a step on a particle alone: air resistance, the
    /// magnetic field (both change with its velocity), a force of one's own.
    pub fn has_own_varying_forces(&self) -> bool {
        !self.drag.is_empty() || !self.magnetic.is_empty() || !self.own.is_empty()
    }

    /// The accelerations of the fields, pairwise forces and springs: everything the
    /// rods, strings and surfaces answer.
    pub fn free_accelerations(&self, t: f64, x: &[DVec2], v: &[DVec2], out: &mut [DVec2]) {
        out.fill(DVec2::ZERO);
        self.pairwise(x, out);
        for link in &self.springs {
            link.add_forces(x, v, out);
        }
        for drag in &self.drag {
            drag.add_force(v, out);
        }
        magnetic::add_forces(&self.magnetic, v, out);
        for own in &self.own {
            own.add_forces(t, (x, v), self, out);
        }
        for ((a, &field), &w) in out
            .iter_mut()
            .zip(self.uniform.iter())
            .zip(self.inverse_mass.iter())
        {
            *a = uniform::acceleration(field) + *a * w;
        }
    }

    /// Each rod's and string's tension at positions `x` and velocities `v`, N (pulling
    /// positive; 0 for a slack string), in the scene's order of ties.
    pub fn tensions(&self, t: f64, x: &[DVec2], v: &[DVec2]) -> Vec<f64> {
        if self.constraints.is_empty() {
            return Vec::new();
        }
        let mut a = vec![DVec2::ZERO; x.len()];
        self.free_accelerations(t, x, v, &mut a);
        self.constraints.tensions(x, v, &self.inverse_mass, &a)
    }

    /// The power the dissipative forces take out of the motion at positions `x` and
    /// velocities `v`, watts, by kind. Friction is the part of a surface's force along
    /// the surface; its power is −F·v.
    pub fn dissipation(&self, t: f64, x: &[DVec2], v: &[DVec2]) -> Power {
        if !self.dissipates() {
            return Power::default();
        }
        let damping = self.springs.iter().map(|s| s.damping_power(x, v)).sum();
        let drag = self.drag.iter().map(|d| d.power(v)).sum();
        let mut friction = 0.0;
        if self.surface_contacts.iter().any(|c| c.friction > 0.0) {
            let mut a = vec![DVec2::ZERO; x.len()];
            let pressed = self.accelerations_off_surfaces(t, x, v, &mut a);
            // A turning particle's friction also works on its spin, which is not here:
            // the step's end books it (`Simulation::book_turning`).
            for (k, contact) in self.surface_contacts.iter().enumerate() {
                if contact.turning.is_some() {
                    continue;
                }
                let p = contact.particle;
                let before = a[p];
                contact.apply_pressed(&mut a[p], pressed.get(k).copied().flatten());
                let change = a[p] - before;
                let along = change - contact.normal * change.dot(contact.normal);
                friction -= self.mass[p] * along.dot(v[p]);
            }
        }
        Power {
            damping,
            friction,
            drag,
        }
    }

    /// The work the surfaces' normal forces did on particles that moved into or off
    /// them over a step from `start` to `end` (positions; `v` the velocities at the
    /// end), joules: the normal force at the end times the displacement along the
    /// normal, exact when the force is constant over the step, as a uniform field's
    /// support is. A particle resting or sliding on a surface does not move along its
    /// normal, and its surface does no work; one struck inside the step does: pushed
    /// into its floor, it sinks until the resting contacts stop it, and the floor's
    /// support takes m g × the depth from the motion. Particles that stayed on their
    /// surface (to 1e-12 of their radius) cost nothing to check: the forces are
    /// evaluated only when one moved along its normal.
    pub fn surface_normal_work(
        &self,
        t: f64,
        start: &[DVec2],
        end: &[DVec2],
        v: &[DVec2],
        radius: &[f64],
    ) -> f64 {
        let depth = |c: &SurfaceContact| (end[c.particle] - start[c.particle]).dot(c.normal);
        if self
            .surface_contacts
            .iter()
            .all(|c| depth(c).abs() <= 1e-12 * radius[c.particle])
        {
            return 0.0;
        }
        let mut a = vec![DVec2::ZERO; end.len()];
        let pressed = self.accelerations_off_surfaces(t, end, v, &mut a);
        let mut work = 0.0;
        for (k, contact) in self.surface_contacts.iter().enumerate() {
            let p = contact.particle;
            let before = a[p];
            let held = pressed.get(k).copied().flatten();
            contact.apply_pressed(&mut a[p], held);
            let pressing = held.unwrap_or_else(|| (a[p] - before).dot(contact.normal));
            work += self.mass[p] * pressing * depth(contact);
        }
        work
    }

    /// The bytes of the springs, rods and strings and the surfaces' contacts, by length
    /// (for [`crate::Simulation::keyframe_bytes`]).
    pub fn links_bytes(&self) -> usize {
        self.springs.len() * size_of::<SpringLink>()
            + self.constraints.links.len() * (size_of::<crate::constraints::Link>() + 1)
            + self.surface_contacts.len() * size_of::<SurfaceContact>()
            + (self.interacting.len() + self.charged.len()) * size_of::<usize>()
    }

    /// Whether any force dissipates smoothly now: a damped spring, air resistance, or
    /// friction on a surface a particle rests on.
    pub fn dissipates(&self) -> bool {
        self.springs.iter().any(|s| s.damping != 0.0)
            || !self.drag.is_empty()
            || self.surface_contacts.iter().any(|c| c.friction > 0.0)
    }

    /// Whether an acceleration may change with the velocities at fixed positions: a damped
    /// spring or friction, a rod or string (whose pull holds the centripetal v²/L), or
    /// the magnetic field.
    pub fn depends_on_velocity(&self) -> bool {
        self.dissipates() || !self.constraints.is_empty() || self.has_own_varying_forces()
    }

    /// Σ ½ m v² over the moving particles, joules.
    pub fn kinetic_energy(&self, v: &[DVec2]) -> f64 {
        v.iter()
            .zip(self.mass.iter())
            .zip(self.inverse_mass.iter())
            .filter(|&(_, &w)| w > 0.0)
            .map(|((v, m), _)| 0.5 * m * v.length_squared())
            .sum()
    }

    /// Gravitation and Coulomb. Directly, in one pass over the pairs: both are central
    /// inverse-square laws, so one distance computation serves both. With a tree,
    /// gravitation through the tree and Coulomb directly among the charged particles.
    fn pairwise(&self, x: &[DVec2], force: &mut [DVec2]) {
        if self.interacting.len() < 2 {
            return; // no pair (the ball pit): not even the sum's scratch columns
        }
        let g = self.gravitational_constant.unwrap_or(0.0);
        let k = self.coulomb_constant.unwrap_or(0.0);
        match self.tree {
            None => self.direct(x, force, g, k, &self.interacting),
            Some(theta) => {
                if g != 0.0 {
                    tree::gravitation(
                        (g, self.softening2),
                        theta,
                        &self.interacting,
                        (x, &self.mass),
                        &self.workers,
                        force,
                    );
                }
                if k != 0.0 {
                    self.direct(x, force, 0.0, k, &self.charged);
                }
            }
        }
    }

    /// Gravitation (G = `g`) and Coulomb (`k`) between every pair of `ids`: the
    /// symmetric direct sum in SIMD lanes ([`direct`]).
    fn direct(&self, x: &[DVec2], force: &mut [DVec2], g: f64, k: f64, ids: &[usize]) {
        direct::add_forces(
            (g, k, self.softening2),
            ids,
            (x, &self.mass, &self.charge),
            |i| self.is_fixed(i),
            &self.workers,
            force,
        );
    }
}
