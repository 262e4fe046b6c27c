//! A uniform magnetic field `B_z` (out of the screen positive) on moving charged
//! particles: F = q v × B = q B (`v_y`, −`v_x`). Always perpendicular to the velocity, it
//! turns a particle without working on it (the ledger books nothing): a free charge
//! circles at radius m |v| / (|q| B) with period 2π m / (|q| B), a positive charge
//! clockwise when `B_z` > 0.

use glam::DVec2;

use crate::scene::Particle;

/// Each moving charged particle of `particles` with its q `B_z` (C·T), ascending; none when
/// `field` (tesla) is zero.
pub(crate) fn of(particles: &[Particle], field: f64) -> Vec<(usize, f64)> {
    if field == 0.0 {
        return Vec::new();
    }
    particles
        .iter()
        .enumerate()
        .filter(|(_, p)| !p.fixed && p.charge != 0.0)
        .map(|(i, p)| (i, p.charge * field))
        .collect()
}

/// The force on a charge moving at `v` with q `B_z` = `qb`, newtons.
#[inline]
pub(crate) fn force(qb: f64, v: DVec2) -> DVec2 {
    DVec2::new(v.y, -v.x) * qb
}

/// Adds each particle's q v × B at velocities `v` to its entry of `force`.
pub(crate) fn add_forces(charges: &[(usize, f64)], v: &[DVec2], force: &mut [DVec2]) {
    for &(i, qb) in charges {
        force[i] += self::force(qb, v[i]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_force_is_q_v_cross_b() {
        // v = x̂, B = ẑ: v × B = x̂ × ẑ = −ŷ.
        assert_eq!(force(2.0, DVec2::X), DVec2::new(0.0, -2.0));
        // Perpendicular to the velocity: no work.
        let v = DVec2::new(3.0, -4.0);
        assert!(force(0.7, v).dot(v).abs() <= f64::EPSILON);
    }
}
