//! What the unit tests share.

/// Numbers uniform in [0, 1) from `seed`, the same on every machine (a 64-bit linear
/// congruential generator, its top 53 bits): random scenes that every run repeats.
pub(crate) fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1_u64 << 53) as f64
    }
}
