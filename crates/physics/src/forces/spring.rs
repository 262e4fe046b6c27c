//! Hooke springs with damping along the spring axis (the paper's 23–24):
//! the tension T = k (L − L0) + b (`v_to` − `v_from`)·u pulls the ends together along the
//! unit vector u from `from` to `to`. Potential energy k (L − L0)² / 2.

use glam::DVec2;

pub(crate) use crate::constraints::End;

#[derive(Clone, Copy, Debug)]
pub(crate) struct SpringLink {
    pub from: End,
    pub to: End,
    /// N/m.
    pub stiffness: f64,
    /// m.
    pub natural_length: f64,
    /// N·s/m.
    pub damping: f64,
}

impl SpringLink {
    /// Adds the spring's forces on its ends to `force`.
    pub fn add_forces(&self, x: &[DVec2], v: &[DVec2], force: &mut [DVec2]) {
        let f = self.force_on_from(x, v);
        self.from.add_force(force, f);
        self.to.add_force(force, -f);
    }

    /// The spring's force on its `from` end, N (on `to`, the opposite).
    pub fn force_on_from(&self, x: &[DVec2], v: &[DVec2]) -> DVec2 {
        let d = self.to.position(x) - self.from.position(x);
        let length = d.length();
        if length > 0.0 {
            let axis = d / length;
            let closing_speed = (self.to.velocity(v) - self.from.velocity(v)).dot(axis);
            axis * (self.stiffness * (length - self.natural_length) + self.damping * closing_speed)
        } else {
            // Ends at one point: the axis is undefined and the elastic force
            // −k (L − L0) u has no direction; only damping of the relative motion remains.
            (self.to.velocity(v) - self.from.velocity(v)) * self.damping
        }
    }

    /// The power its damping takes out of the motion, watts (≥ 0): b times the square of
    /// the closing speed (of the relative velocity when the ends meet).
    pub fn damping_power(&self, x: &[DVec2], v: &[DVec2]) -> f64 {
        let d = self.to.position(x) - self.from.position(x);
        let relative = self.to.velocity(v) - self.from.velocity(v);
        let length = d.length();
        let speed_squared = if length > 0.0 {
            let closing = relative.dot(d / length);
            closing * closing
        } else {
            relative.length_squared()
        };
        self.damping * speed_squared
    }

    /// Whether particle `i` is at one of the ends.
    pub fn touches(&self, i: usize) -> bool {
        matches!(self.from, End::Particle(p) if p == i)
            || matches!(self.to, End::Particle(p) if p == i)
    }

    /// Current length, metres.
    pub fn length(&self, x: &[DVec2]) -> f64 {
        (self.to.position(x) - self.from.position(x)).length()
    }

    /// Elastic potential energy, joules.
    pub fn potential(&self, x: &[DVec2]) -> f64 {
        let stretch = self.length(x) - self.natural_length;
        0.5 * self.stiffness * stretch * stretch
    }
}

/// Each of `n` particles' springs: the indices into `springs` of those at it, ascending.
pub(crate) fn each_particles(springs: &[SpringLink], n: usize) -> std::sync::Arc<[Box<[u32]>]> {
    let mut at = vec![Vec::new(); n];
    for (index, spring) in springs.iter().enumerate() {
        let index = u32::try_from(index).unwrap_or(u32::MAX);
        for end in [spring.from, spring.to] {
            if let End::Particle(i) = end
                && at[i].last() != Some(&index)
            {
                at[i].push(index);
            }
        }
    }
    at.into_iter().map(Vec::into_boxed_slice).collect()
}
