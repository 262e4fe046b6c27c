//! The uniform field and each particle's constant applied acceleration: a = g + `a_applied`,
//! independent of mass. Potential energy −m (g + `a_applied`)·r.

use glam::DVec2;

/// The acceleration a particle gets from the field and its applied acceleration
/// (`field` already holds their sum; zero for a fixed particle).
#[inline]
pub(crate) fn acceleration(field: DVec2) -> DVec2 {
    field
}

/// Potential energy, joules, of mass `m` at `position` in the field.
pub(crate) fn potential(m: f64, field: DVec2, position: DVec2) -> f64 {
    -m * field.dot(position)
}
