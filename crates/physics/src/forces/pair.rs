//! The pair laws, written once: Newton's gravitation (the paper's 25) and Coulomb's law
//! (26) between two bodies i and j, softened by ε (Plummer: r² + ε² wherever the exact
//! laws read r²):
//!
//!   force on i:        F = c d / (r² + ε²)^{3/2},   c = G mᵢ mⱼ − k qᵢ qⱼ,  d = xⱼ − xᵢ
//!   potential energy:  U = −G mᵢ mⱼ / √(r² + ε²) + k qᵢ qⱼ / √(r² + ε²)
//!
//! Both are central inverse-square laws, so one strength c (positive attracts) and one
//! softened distance serve both. Every sum of them calls these functions: the direct sum
//! (one pair at a time and in SIMD lanes), the tree's near bodies and the softening of
//! its far cells, the impact response's Jacobian, the energy books and the field probe.
//! The kernels are generic over `pulp`'s vectors so the lanes and the plain loop share
//! them (`pulp::Scalar`'s vector is one `f64`); each is a fixed sequence of correctly
//! rounded operations, so every caller gets the same bits for the same numbers.

#![expect(
    clippy::inline_always,
    reason = "pulp's kernels must inline into with_simd"
)]

use glam::DVec2;
use pulp::Simd;

/// r² + ε², m², for a separation (dx, dy) and ε² = `softening2`: the square of the
/// distance the laws read (adding ε² = 0 changes no bit: r² ≥ 0).
#[inline(always)]
pub(crate) fn softened_square<S: Simd>(
    simd: S,
    dx: S::f64s,
    dy: S::f64s,
    softening2: S::f64s,
) -> S::f64s {
    simd.add_f64s(
        simd.add_f64s(simd.mul_f64s(dx, dx), simd.mul_f64s(dy, dy)),
        softening2,
    )
}

/// (r² + ε²)^{3/2}, m³, from `r2` = r² + ε²: the denominator of the force.
#[inline(always)]
pub(crate) fn cube<S: Simd>(simd: S, r2: S::f64s) -> S::f64s {
    simd.mul_f64s(r2, simd.sqrt_f64s(r2))
}

/// The strength c = G mᵢ mⱼ − k qᵢ qⱼ, N·m², from G mᵢ, mⱼ, k qᵢ and qⱼ (the sums keep
/// G mᵢ and k qᵢ per body): positive attracts.
#[inline(always)]
pub(crate) fn strength<S: Simd>(
    simd: S,
    g_mi: S::f64s,
    mj: S::f64s,
    k_qi: S::f64s,
    qj: S::f64s,
) -> S::f64s {
    simd.sub_f64s(simd.mul_f64s(g_mi, mj), simd.mul_f64s(k_qi, qj))
}

/// The plain numbers the scalar callers compute in.
fn plain() -> pulp::Scalar {
    pulp::Scalar::new()
}

/// The strength c of a pair (masses `mi`, `mj`, kg; charges `qi`, `qj`, C) under G = `g`
/// and k = `k` (0 for a law that is off), N·m².
#[inline]
pub(crate) fn pair_strength(g: f64, k: f64, (mi, qi): (f64, f64), (mj, qj): (f64, f64)) -> f64 {
    strength(plain(), g * mi, mj, k * qi, qj)
}

/// The force, N, on a body from a partner `d` away (d = xⱼ − xᵢ) with strength `c`.
#[inline]
pub(crate) fn force(d: DVec2, c: f64, softening2: f64) -> DVec2 {
    d * (c / cube(plain(), softened_square(plain(), d.x, d.y, softening2)))
}

/// The force per unit strength, m⁻², from a partner `d` away: d / (r² + ε²)^{3/2}.
#[inline]
pub(crate) fn per_unit_strength(d: DVec2, softening2: f64) -> DVec2 {
    d / cube(plain(), softened_square(plain(), d.x, d.y, softening2))
}

/// The distance the laws read between `a` and `b`, m: √(r² + ε²), the plain distance
/// when ε = 0 (the same bits).
#[inline]
pub(crate) fn distance(a: DVec2, b: DVec2, softening2: f64) -> f64 {
    let d = b - a;
    softened_square(plain(), d.x, d.y, softening2).sqrt()
}

/// Gravitation's potential energy, J, of masses `m1` and `m2` (kg) at the softened
/// distance `r` (from [`distance`]): −G m₁ m₂ / r.
#[inline]
pub(crate) fn gravitation_potential(g: f64, m1: f64, m2: f64, r: f64) -> f64 {
    -(g * m1 * m2) / r
}

/// Coulomb's potential energy, J, of charges `q1` and `q2` (C) at the softened
/// distance `r`: k q₁ q₂ / r.
#[inline]
pub(crate) fn coulomb_potential(k: f64, q1: f64, q2: f64, r: f64) -> f64 {
    k * q1 * q2 / r
}
