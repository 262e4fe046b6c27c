//! Newtonian gravitation between every pair of particles (the paper's 25):
//! F = G m1 m2 / r², attractive. Potential energy −G m1 m2 / r.

/// Attraction strength G m1 m2, N·m².
#[inline]
pub(crate) fn strength(gravitational_constant: f64, m1: f64, m2: f64) -> f64 {
    gravitational_constant * m1 * m2
}

/// Potential energy, joules, of a pair at distance `r`.
pub(crate) fn potential(gravitational_constant: f64, m1: f64, m2: f64, r: f64) -> f64 {
    -strength(gravitational_constant, m1, m2) / r
}
