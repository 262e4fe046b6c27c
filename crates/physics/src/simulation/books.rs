//! What a run records of its energy: the ledger of what the dissipative parts of the
//! physics took, and the energy an impact takes.

use crate::contacts::{Applied, Impact};

/// The energy the dissipative parts of the physics took out of the motion since the
/// ledger was started, joules. With the kinetic and potential energy it closes: kinetic +
/// potential + these − the starting energy is what is left, the residual: the
/// integrator's error.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Ledger {
    /// Spring damping: ∫ b (closing speed)² dt, by Simpson's rule over each step.
    pub damping: f64,
    /// Friction: ∫ −F·v dt of the surfaces' tangential force on points, the same way;
    /// for turning particles, what it takes at impacts and in slipping (exactly: its
    /// force is fixed through a step, `crate::turning`).
    pub friction: f64,
    /// Air resistance: ∫ (b |v|² + c |v|³) dt, the same way.
    pub drag: f64,
    /// Impacts and resting contact: ½ μ (1 − e²) u² per impact, the kinetic energy the
    /// resting contacts' inelastic impulses remove, less the potential energy their
    /// position correction adds (a pile at rest sinks by ½ g h² a step under gravity and is
    /// lifted back: each step the impulses take ½ m (g h)² and the lift gives it back, so
    /// a pile at rest dissipates nothing, as it should).
    pub impacts: f64,
    /// The work the joints' motors did on the bodies (energy given, not taken): a
    /// constant torque's τ Δθ exactly, a held spin's to the integrator's order.
    pub motors: f64,
}

impl Ledger {
    /// What left the motion, joules: everything taken less what the motors gave.
    pub fn total(&self) -> f64 {
        self.damping + self.friction + self.impacts + self.drag - self.motors
    }
}

/// The effective mass of an impact, kg: 1/(1/mᵢ + 1/mⱼ) for a pair, m against a
/// surface (0 when nothing can move). `w` is each particle's 1/m.
pub(super) fn effective_mass(applied: &Applied, w: &[f64]) -> f64 {
    if let Some(tied) = applied.tied {
        return tied;
    }
    let inverse = match applied.impact {
        Impact::Pair(i, j) => w[i] + w[j],
        Impact::Obstacle(p, _) => w[p],
    };
    if inverse > 0.0 { 1.0 / inverse } else { 0.0 }
}

/// The kinetic energy an impact takes, joules: ½ μ (1 − e²) u², the approach u becoming
/// a separation e·u.
pub(super) fn impact_energy_lost(applied: &Applied, w: &[f64]) -> f64 {
    let (u, e) = (applied.approach, applied.restitution);
    0.5 * effective_mass(applied, w) * (1.0 - e * e) * u * u
}
