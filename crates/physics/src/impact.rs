//! The impact log's vocabulary: what a particle hit, and the row an impact leaves. It sits
//! below the contacts that find impacts and the simulation that logs them.

/// An impact that happened: when, and between what.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactRecord {
    /// Seconds, located to the instant of contact.
    pub time: f64,
    /// The particle (the first of a pair, in scene order).
    pub particle: usize,
    /// What it hit.
    pub other: ImpactTarget,
    /// The impulse along the contact normal, N·s.
    pub impulse: f64,
    /// The approach speed along the normal just before, m/s.
    pub normal_speed_before: f64,
    /// The separation speed along the normal just after, m/s: the restitution times the
    /// approach.
    pub normal_speed_after: f64,
    /// The kinetic energy the impact took, J: ½ μ (1 − e²) u² with μ the effective mass.
    pub kinetic_energy_lost: f64,
}

/// What a particle hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImpactTarget {
    /// Another particle, by index.
    Particle(usize),
    /// A ramp, by index in the scene's ramps.
    Ramp(usize),
    /// A wall of the world's bounds.
    Wall,
}
