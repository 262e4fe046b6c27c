//! A quantity's period from its maxima: the true cycle, or a plain "cannot tell".
//!
//! The mean gap between successive maxima is a period only when a cycle has one maximum.
//! Past 90° a pendulum's x has three a swing (at 90° going up, at 90° coming down, and at
//! the far turning point, where x is a local maximum below zero), so the mean gap is a
//! third of the swing's period. The true cycle is found as the smallest number k of
//! maxima that repeats: every span over k maxima the same length, and the heights of
//! every k-th maximum changing one way (a decay, a growth, or none) rather than turning
//! back, as they do when a cycle's maxima of different heights are taken for cycles of
//! their own. Two whole cycles must agree, so three maxima at the least are needed; a
//! motion whose maxima repeat at no k (chaos, a transient, beats) has no period.

/// How far the spans over one cycle may differ from their mean, relative to it. Located
/// maxima are good to some 1e-9 s and a graph's sampled ones to some 1e-7 s; a damped
/// pendulum's period drifts as its amplitude falls (under 2 % from 30° to rest), and a
/// cycle mistaken for one of k maxima too few has spans that differ by far more than
/// this (at 170° a pendulum's x has gaps of some 1.1 s and 1.5 s).
const SPAN_TOLERANCE: f64 = 1e-2;

/// A change in height between maxima a cycle apart that counts as one, as a fraction of
/// the spread of the heights (with a floor at the rounding of the values themselves).
const HEIGHT_TOLERANCE: f64 = 1e-3;

/// A quantity's period read off its maxima.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cycle {
    /// The mean duration of one cycle, seconds (or the unit of the maxima's abscissa).
    pub period: f64,
    /// How many whole cycles the mean spans.
    pub cycles: usize,
    /// How many maxima one cycle holds.
    pub maxima_per_cycle: usize,
}

/// Why maxima give no period.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoCycle {
    /// Fewer than three maxima: no two cycles to compare.
    TooFew(usize),
    /// This many maxima, repeating at no number of them.
    Irregular(usize),
}

/// The cycle of the maxima `(at, height)` in ascending `at`: the smallest number of
/// maxima after which both their spacing and their heights repeat.
///
/// # Errors
/// Fewer than three maxima, or none that repeat.
pub fn cycle(maxima: &[(f64, f64)]) -> Result<Cycle, NoCycle> {
    let n = maxima.len();
    if n < 3 {
        return Err(NoCycle::TooFew(n));
    }
    let at = |i: usize| maxima[i].0;
    let height = |i: usize| maxima[i].1;
    let (low, high, largest) = maxima.iter().fold(
        (f64::INFINITY, f64::NEG_INFINITY, 0.0_f64),
        |(low, high, largest), &(_, h)| (low.min(h), high.max(h), largest.max(h.abs())),
    );
    let significant = (HEIGHT_TOLERANCE * (high - low))
        .max(1e-9 * largest)
        .max(f64::MIN_POSITIVE);
    // Two whole cycles at the least, so that one can be compared with the next.
    for k in 1..=(n - 1) / 2 {
        let spans = n - k;
        let mean = (0..spans).map(|i| at(i + k) - at(i)).sum::<f64>() / spans as f64;
        if !(mean > 0.0 && mean.is_finite()) {
            continue;
        }
        let regular =
            (0..spans).all(|i| ((at(i + k) - at(i)) - mean).abs() <= SPAN_TOLERANCE * mean);
        let turns_back = (0..n.saturating_sub(2 * k)).any(|i| {
            let first = height(i + k) - height(i);
            let second = height(i + 2 * k) - height(i + k);
            (first > significant && second < -significant)
                || (first < -significant && second > significant)
        });
        if regular && !turns_back {
            let cycles = (n - 1) / k;
            return Ok(Cycle {
                period: (at(cycles * k) - at(0)) / cycles as f64,
                cycles,
                maxima_per_cycle: k,
            });
        }
    }
    Err(NoCycle::Irregular(n))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI, TAU};

    /// The maxima of `f` sampled at 100,000 instants over `until`, each the best sample
    /// (good to the sampling interval, far inside the tolerances).
    fn maxima_of(f: impl Fn(f64) -> f64, until: f64) -> Vec<(f64, f64)> {
        let n = 100_000_u32;
        let h = until / f64::from(n);
        (1..n)
            .filter_map(|i| {
                let t = f64::from(i) * h;
                let (a, b, c) = (f(t - h), f(t), f(t + h));
                (b > a && b >= c).then_some((t, b))
            })
            .collect()
    }

    #[test]
    fn a_cosine_has_one_maximum_a_cycle() {
        let found = cycle(&maxima_of(|t| (TAU * t / 1.5).cos(), 10.0)).expect("a cycle");
        assert!((found.period - 1.5).abs() < 1e-3, "{found:?}");
        assert_eq!(found.maxima_per_cycle, 1, "one maximum a cycle");
        assert_eq!(found.cycles, 5, "six maxima after t = 0 within 10 s");
    }

    #[test]
    fn a_decay_is_still_one_maximum_a_cycle() {
        let found =
            cycle(&maxima_of(|t| (-0.3 * t).exp() * (TAU * t).cos(), 8.0)).expect("a cycle");
        assert!((found.period - 1.0).abs() < 1e-3, "{found:?}");
        assert_eq!(found.maxima_per_cycle, 1, "one maximum a cycle");
    }

    /// Equally spaced maxima of two heights (cos 2t + 0.2 cos t: 1.2 at 0, 0.8 at π): the
    /// spans agree at one maximum a cycle, the heights turn back, so the cycle is 2π.
    #[test]
    fn maxima_of_two_heights_equally_spaced_are_one_cycle() {
        let found = cycle(&maxima_of(|t| (2.0 * t).cos() + 0.2 * t.cos(), 30.0)).expect("a cycle");
        assert!((found.period - TAU).abs() < 1e-3, "{found:?}");
        assert_eq!(found.maxima_per_cycle, 2, "two maxima a cycle");
    }

    /// A pendulum's x past 90° as the sine of an angle swinging beyond ±90° (a sine of
    /// period 2 s stands in for the swing: the shape of x, not the dynamics, is tested).
    #[test]
    fn x_past_ninety_degrees_has_three_maxima_a_swing() {
        let amplitude = 0.6 * PI;
        let found =
            cycle(&maxima_of(|t| (amplitude * (PI * t).sin()).sin(), 9.0)).expect("a cycle");
        assert!((found.period - 2.0).abs() < 1e-3, "{found:?}");
        assert_eq!(found.maxima_per_cycle, 3, "three maxima a swing");
    }

    #[test]
    fn two_maxima_cannot_tell() {
        assert_eq!(
            cycle(&[(0.0, 1.0), (1.0, 1.0)]),
            Err(NoCycle::TooFew(2)),
            "two maxima are one gap, nothing to compare it with"
        );
    }

    /// Two frequencies in no simple ratio (1 and √2) repeat at no number of maxima.
    #[test]
    fn a_motion_that_never_repeats_has_no_period() {
        let maxima = maxima_of(|t| t.cos() + (2.0_f64.sqrt() * t + FRAC_PI_2).cos(), 60.0);
        assert!(
            matches!(cycle(&maxima), Err(NoCycle::Irregular(_))),
            "{:?}",
            cycle(&maxima)
        );
    }
}
