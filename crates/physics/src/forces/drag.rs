//! Air resistance on a particle: linear, F = −b v, and quadratic, F = −c |v| v, against
//! the velocity (c given, or ½ ρ `C_d` π r² from a drag coefficient). Both take energy out of the motion at the rate b |v|² + c |v|³, which
//! the energy ledger books as `dissipated_drag`.

use glam::DVec2;

use crate::scene::Particle;

/// One moving particle's air resistance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Drag {
    /// The particle's index.
    pub particle: usize,
    /// b, kg/s.
    pub linear: f64,
    /// c, kg/m.
    pub quadratic: f64,
}

impl Drag {
    /// Each moving particle's of `particles` that has air resistance in air of density
    /// `air_density` (kg/m³), in order (a fixed particle never moves, so feels none).
    pub fn of(particles: &[Particle], air_density: f64) -> Vec<Self> {
        particles
            .iter()
            .enumerate()
            .map(|(particle, p)| Self {
                particle,
                linear: p.linear_drag,
                quadratic: p.quadratic_drag_in(air_density),
            })
            .filter(|d| !particles[d.particle].fixed && (d.linear > 0.0 || d.quadratic > 0.0))
            .collect()
    }

    /// The force at velocities `v`, newtons.
    pub fn force(&self, v: &[DVec2]) -> DVec2 {
        let v = v[self.particle];
        -(self.linear + self.quadratic * v.length()) * v
    }

    /// Adds the force at velocities `v` to the particle's entry of `force`.
    pub fn add_force(&self, v: &[DVec2], force: &mut [DVec2]) {
        force[self.particle] += self.force(v);
    }

    /// How fast it brings the particle's velocity to rest at velocities `v`, per second
    /// (the largest eigenvalue of −∂F/∂v over the mass: b/m, and 2c|v|/m more for the
    /// quadratic part). A fixed-step method follows the decay only while this rate times
    /// the step stays below [`crate::tuning::DRAG_STEP`]; beyond the methods' stability
    /// (2 for Euler's, 2.79 for rk4) each step overshoots and multiplies the velocity.
    pub fn rate(&self, v: &[DVec2], mass: f64) -> f64 {
        (self.linear + 2.0 * self.quadratic * v[self.particle].length()) / mass
    }

    /// The power it takes out of the motion at velocities `v`, watts: −F·v.
    pub fn power(&self, v: &[DVec2]) -> f64 {
        -self.force(v).dot(v[self.particle])
    }
}
