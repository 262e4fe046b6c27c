//! Coulomb's law between every pair of charged particles (the paper's 26):
//! F = k q1 q2 / r², repulsive for like charges. Potential energy k q1 q2 / r.

/// Repulsion strength k q1 q2, N·m².
#[inline]
pub(crate) fn strength(coulomb_constant: f64, q1: f64, q2: f64) -> f64 {
    coulomb_constant * q1 * q2
}

/// Potential energy, joules, of a pair at distance `r`.
pub(crate) fn potential(coulomb_constant: f64, q1: f64, q2: f64, r: f64) -> f64 {
    strength(coulomb_constant, q1, q2) / r
}
