//! Forces of one's own (`[[force]]`): each an expression of a particle's position,
//! velocity, mass and charge and of time, summed with the other forces at every
//! evaluation; with a potential energy, booked as such.

use glam::DVec2;

use crate::scene::force::{At, Law};
use crate::scene::{Force, Scene};

/// One `[[force]]` of a valid scene, parsed, on its moving particles.
#[derive(Clone, Debug)]
pub(crate) struct OwnForce {
    /// The moving particles it acts on, ascending.
    pub on: Vec<usize>,
    fx: Law,
    fy: Law,
    potential: Option<Law>,
}

impl OwnForce {
    /// The forces of `scene` (valid: every expression reads, every name is a particle).
    pub fn of(scene: &Scene) -> Vec<Self> {
        scene
            .forces
            .iter()
            .filter_map(|force| Self::new(force, scene))
            .collect()
    }

    fn new(force: &Force, scene: &Scene) -> Option<Self> {
        let moving = |i: &usize| !scene.particles[*i].fixed;
        let on: Vec<usize> = if force.on.is_empty() {
            (0..scene.particles.len()).filter(moving).collect()
        } else {
            let mut on: Vec<usize> = force
                .on
                .iter()
                .filter_map(|name| scene.particle_index(name))
                .filter(moving)
                .collect();
            on.sort_unstable();
            on.dedup();
            on
        };
        Some(Self {
            on,
            fx: Law::parse(&force.fx, false).ok()?,
            fy: Law::parse(&force.fy, false).ok()?,
            potential: match &force.potential {
                Some(u) => Some(Law::parse(u, true).ok()?),
                None => None,
            },
        })
    }

    /// Whether it has a potential energy.
    pub fn has_potential(&self) -> bool {
        self.potential.is_some()
    }

    /// The force at `at`, newtons.
    pub fn force(&self, at: &At) -> DVec2 {
        DVec2::new(self.fx.at(at), self.fy.at(at))
    }

    /// Adds its force on each of its particles at time `t`, positions `x` and
    /// velocities `v` to `force`.
    pub fn add_forces(
        &self,
        t: f64,
        (x, v): (&[DVec2], &[DVec2]),
        model: &super::ForceModel,
        force: &mut [DVec2],
    ) {
        for &i in &self.on {
            force[i] += self.force(&at(t, (x, v), model, i));
        }
    }

    /// Its potential energy over its particles at positions `x`, joules (0 without one).
    pub fn potential(&self, x: &[DVec2], model: &super::ForceModel) -> f64 {
        let Some(u) = &self.potential else {
            return 0.0;
        };
        self.on
            .iter()
            .map(|&i| u.at(&at(0.0, (x, x), model, i)))
            .fold(0.0, |sum, e| sum + e)
    }
}

/// Particle `i` at time `t`, positions `x` and velocities `v`.
fn at(t: f64, (x, v): (&[DVec2], &[DVec2]), model: &super::ForceModel, i: usize) -> At {
    At {
        t,
        position: x[i],
        velocity: v[i],
        mass: model.mass[i],
        charge: model.charge[i],
    }
}
