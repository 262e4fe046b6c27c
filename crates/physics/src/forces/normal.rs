//! The normal force and friction of a surface a particle rests on or slides along (the
//! paper's 13–16, generalised to any direction of the other forces).
//!
//! The surface pushes back exactly as hard as the other forces press the particle into
//! it, N = max(0, −m a·n), so the particle neither sinks nor jumps. Friction of
//! coefficient μ then opposes the sliding with μN (kinetic), or, for a particle at rest,
//! cancels the pull along the surface while it is within μN (static) — the particle stays
//! put while |tan θ| ≤ μ on a ramp at θ. Which of the two applies, and the direction of
//! sliding, are decided at the start of each step, so the force is smooth within it.

use glam::DVec2;

/// A particle held on a surface for the current step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SurfaceContact {
    pub particle: usize,
    /// Unit normal of the surface, pointing towards the particle.
    pub normal: DVec2,
    /// Coefficient of friction, static and kinetic.
    pub friction: f64,
    /// Unit direction of sliding, or `None` when at rest (static friction).
    pub sliding: Option<DVec2>,
    /// For a particle that turns, how friction grips it (`sliding` is then unused).
    pub turning: Option<Grip>,
}

/// How a surface's friction acts on a particle that turns (`crate::turning`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Grip {
    /// Rolling without slipping: friction takes `share` = k/(1 + k) of the pull along the
    /// surface (a disc, k = ½, rolls down a slope at ⅔ g sin θ), at most μN.
    Rolls { share: f64 },
    /// Slipping: a friction acceleration of `friction` m/s² along the surface's tangent
    /// (the normal turned a quarter counter-clockwise), μN fixed at the step's start so
    /// that the spin, which the integrators do not see, takes the same impulse.
    Slips { friction: f64 },
}

impl SurfaceContact {
    /// Adds the surface's normal and friction accelerations to `a`, the particle's
    /// acceleration from every other force.
    pub fn apply(&self, a: &mut DVec2) {
        self.apply_pressed(a, None);
    }

    /// [`Self::apply`], or, with `pressed`, friction alone for a surface whose normal
    /// force (`pressed`, m/s²) is in `a` already: the rods holding the particle and the
    /// surface answered the other forces together.
    pub fn apply_pressed(&self, a: &mut DVec2, pressed: Option<f64>) {
        let pressing = if let Some(pressing) = pressed {
            pressing
        } else {
            let pressing = -a.dot(self.normal);
            if pressing <= 0.0 {
                return; // pulled away from the surface: it exerts nothing
            }
            *a += self.normal * pressing;
            pressing
        };
        if self.friction == 0.0 || pressing <= 0.0 {
            return;
        }
        let limit = self.friction * pressing;
        if let Some(grip) = self.turning {
            let tangent = self.normal.perp();
            let friction = match grip {
                Grip::Rolls { share } => (-a.dot(tangent) * share).max(-limit).min(limit),
                Grip::Slips { friction } => friction,
            };
            *a += tangent * friction;
        } else if let Some(direction) = self.sliding {
            *a -= direction * limit;
        } else {
            let tangent = self.normal.perp();
            let pull = a.dot(tangent);
            // Not `clamp`, which panics on a NaN bound: a non-finite force here is the
            // run's failure to report (the step's finiteness check), not a crash.
            *a -= tangent * pull.max(-limit).min(limit);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Static friction holds a pull within μN and caps one beyond it; a non-finite
    /// acceleration (coincident bodies' infinite pull) passes through as non-finite,
    /// without a panic.
    #[test]
    fn friction_caps_the_pull_and_a_nan_passes_through() {
        let contact = SurfaceContact {
            particle: 0,
            normal: DVec2::Y,
            friction: 0.5,
            sliding: None,
            turning: None,
        };
        let mut held = DVec2::new(3.0, -10.0);
        contact.apply(&mut held);
        assert_eq!(held, DVec2::ZERO, "3 within 0.5 × 10: held");
        let mut slipping = DVec2::new(8.0, -10.0);
        contact.apply(&mut slipping);
        assert_eq!(slipping, DVec2::new(3.0, 0.0), "8 − 0.5 × 10");
        for bad in [f64::NAN, f64::INFINITY] {
            let mut a = DVec2::new(bad, -bad);
            contact.apply(&mut a);
            assert!(!a.is_finite(), "{a}");
        }
    }
}
