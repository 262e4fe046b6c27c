//! Rigid bodies in motion (`[[body]]`): each one's centroid, velocity, angle and spin,
//! moved through the step the particles took.
//!
//! A body feels the uniform field at its centroid, which gives it no torque: its centroid
//! moves with a constant acceleration g and it turns at a constant spin. The integration
//! methods then take their own step on that motion — euler x + v h, semi-implicit euler
//! x + (v + g h) h, and the others (verlet, rk4, pefrl, dopri5), whose error vanishes
//! for a constant acceleration, x + v h + g h²/2 — so that a body under euler departs
//! from the parabola exactly as a particle beside it does. Contacts of bodies with
//! anything else are not part of the step yet: bodies pass through walls, ramps,
//! particles and each other (docs/scene-format.md says so).

use std::sync::Arc;

use glam::DVec2;

use crate::diagnostics::{Diagnostics, ParticleReadout};
use crate::forces::uniform;
use crate::scene::Vector;
use crate::{Integrator, Scene, Simulation};

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
    /// The uniform field, m/s².
    gravity: DVec2,
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

impl Bodies {
    pub fn new(scene: &Scene) -> Self {
        let bodies = &scene.bodies;
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
            gravity: scene.world.gravity.to_dvec2(),
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

    /// The acceleration of body `i`, m/s²: the field's, none for a fixed one.
    fn acceleration(&self, i: usize) -> DVec2 {
        if self.fixed[i] {
            DVec2::ZERO
        } else {
            self.gravity
        }
    }

    /// Moves every body through a step of `h` seconds taken with `method`.
    pub fn advance(&mut self, method: Integrator, h: f64) {
        for i in 0..self.len() {
            if self.fixed[i] {
                continue;
            }
            let a = self.acceleration(i);
            let (x, v) = (&mut self.position[i], &mut self.velocity[i]);
            match method {
                Integrator::Euler => {
                    *x += *v * h;
                    *v += a * h;
                }
                Integrator::SemiImplicitEuler => {
                    *v += a * h;
                    *x += *v * h;
                }
                Integrator::Verlet | Integrator::Rk4 | Integrator::Pefrl | Integrator::Dopri5 => {
                    *x += *v * h + a * (0.5 * h * h);
                    *v += a * h;
                }
            }
            self.angle[i] += (self.spin[i] * h).to_degrees();
        }
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
    }

    /// Writes the state reached into `scene`'s bodies.
    pub fn save_into(&self, scene: &mut Scene) {
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

impl Simulation {
    /// The rigid bodies' names, in scene order.
    pub fn body_names(&self) -> &[String] {
        self.bodies.names()
    }

    /// Everything about body `i` now: its centroid's position, velocity and acceleration,
    /// its angle (degrees, unwrapped) and spin, its energy and momenta.
    pub fn body(&self, i: usize) -> ParticleReadout {
        self.bodies.readout(i)
    }

    /// Body `i`'s outline in the world now, counter-clockwise, metres.
    pub fn body_outline(&self, i: usize) -> Vec<DVec2> {
        self.bodies.world_outline(i)
    }
}
