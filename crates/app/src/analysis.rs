//! What a graph reads off its samples: the value under the pointer, the maxima, minima
//! and zero crossings of a series, and the period from successive maxima.
//!
//! The samples are the simulation's own instants (every 5 ms at a 1 ms step, `recording.rs`).
//! A maximum or minimum is the vertex of the parabola through the extreme sample and its
//! two neighbours, good to a few 1e-7 s for a smooth motion sampled every 5 ms (the
//! vertex's error grows as the sampling interval cubed); a zero crossing is where the
//! straight line between the two samples around it crosses 0. Instants that must be
//! exact are the events' (`physics::Watch`: the stopwatch, the time machine's jumps,
//! `run --events`); these are for reading a graph.

/// A turning value of a series: where, and how much.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extreme {
    pub x: f64,
    pub value: f64,
    /// A maximum (else a minimum).
    pub maximum: bool,
}

/// The maxima and minima of the series `(x, y)` (x ascending), each refined to the
/// vertex of the parabola through it and its neighbours. A flat run of equal samples is
/// no extreme.
pub fn extrema(x: &[f64], y: &[f64]) -> Vec<Extreme> {
    let n = x.len().min(y.len());
    let mut found = Vec::new();
    for k in 1..n.saturating_sub(1) {
        let (a, b, c) = (y[k - 1], y[k], y[k + 1]);
        let maximum = b > a && b >= c;
        let minimum = b < a && b <= c;
        if !(maximum || minimum) || b == c {
            continue;
        }
        let (x0, x1, x2) = (x[k - 1], x[k], x[k + 1]);
        found.push(vertex((x0, a), (x1, b), (x2, c), maximum));
    }
    found
}

/// The vertex of the parabola through three points (the middle one the extreme sample).
fn vertex(p0: (f64, f64), p1: (f64, f64), p2: (f64, f64), maximum: bool) -> Extreme {
    let ((x0, y0), (x1, y1), (x2, y2)) = (p0, p1, p2);
    // Divided differences: y = y1 + d1 (x − x1) + d2 (x − x0)(x − x1)... written about x1.
    let d01 = (y1 - y0) / (x1 - x0);
    let d12 = (y2 - y1) / (x2 - x1);
    let curvature = (d12 - d01) / (x2 - x0);
    if curvature == 0.0 || !curvature.is_finite() {
        return Extreme {
            x: x1,
            value: y1,
            maximum,
        };
    }
    // The slope at x1 of the parabola is d01 + curvature (x1 − x0).
    let slope = d01 + curvature * (x1 - x0);
    let shift = (-slope / (2.0 * curvature)).clamp(x0 - x1, x2 - x1);
    Extreme {
        x: x1 + shift,
        value: y1 + slope * shift + curvature * shift * shift,
        maximum,
    }
}

/// Where the series crosses 0 (a sample exactly on 0 counts once), by the straight line
/// between the samples around each crossing.
pub fn zeros(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len().min(y.len());
    let mut found = Vec::new();
    for k in 1..n {
        let (a, b) = (y[k - 1], y[k]);
        if a == 0.0 && k == 1 {
            found.push(x[0]);
        }
        if b == 0.0 {
            found.push(x[k]);
        } else if a != 0.0 && a.signum() != b.signum() {
            found.push(x[k - 1] + (x[k] - x[k - 1]) * a / (a - b));
        }
    }
    found
}

/// The mean interval between successive maxima, and how many intervals it averages.
pub fn period(extremes: &[Extreme]) -> Option<(f64, usize)> {
    let maxima: Vec<f64> = extremes.iter().filter(|e| e.maximum).map(|e| e.x).collect();
    let intervals = maxima.len().checked_sub(1).filter(|&n| n > 0)?;
    Some(((maxima[intervals] - maxima[0]) / intervals as f64, intervals))
}

/// The series' value at `at`, on the straight line between the samples around it (the
/// value under the pointer); `None` outside the samples.
pub fn value_at(x: &[f64], y: &[f64], at: f64) -> Option<f64> {
    let n = x.len().min(y.len());
    if n == 0 || at < x[0] || at > x[n - 1] {
        return None;
    }
    let k = x[..n].partition_point(|&xi| xi < at);
    if k == 0 {
        return Some(y[0]);
    }
    let (x0, x1, y0, y1) = (x[k - 1], x[k], y[k - 1], y[k]);
    Some(if x1 == x0 {
        y1
    } else {
        y0 + (y1 - y0) * (at - x0) / (x1 - x0)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y = 2 cos(ω t) + 0.5 sampled every 5 ms (a pendulum's sampling) for 10 s, ω = 2.06:
    /// the maxima at 2πk/ω to 1e-6 s and 2.5 to 1e-6, the minima between, the zeros where
    /// cos = −1/4 to 1e-5 s (a chord's error), and the period from the maxima to 1e-7 s.
    #[test]
    fn a_sampled_cosine_gives_its_extremes_zeros_and_period() {
        let omega = 2.06;
        let period_theory = std::f64::consts::TAU / omega;
        let x: Vec<f64> = (0..2000).map(|k| f64::from(k) * 0.005).collect();
        let y: Vec<f64> = x.iter().map(|t| 2.0 * (omega * t).cos() + 0.5).collect();
        let found = extrema(&x, &y);
        let maxima: Vec<&Extreme> = found.iter().filter(|e| e.maximum).collect();
        let minima: Vec<&Extreme> = found.iter().filter(|e| !e.maximum).collect();
        assert_eq!(maxima.len(), 3, "the first sample is no extreme: {found:?}");
        for (k, max) in maxima.iter().enumerate() {
            let expected = (k + 1) as f64 * period_theory;
            assert!((max.x - expected).abs() < 1e-6, "max {k}: {} against {expected}", max.x);
            assert!((max.value - 2.5).abs() < 1e-6, "{}", max.value);
        }
        for (k, min) in minima.iter().enumerate() {
            let expected = (k as f64 + 0.5) * period_theory;
            assert!((min.x - expected).abs() < 1e-6, "min {k}: {}", min.x);
            assert!((min.value + 1.5).abs() < 1e-6, "{}", min.value);
        }
        let (period, intervals) = period(&found).expect("two maxima at least");
        assert_eq!(intervals, 2);
        assert!((period - period_theory).abs() < 1e-7, "{period} against {period_theory}");
        let first_zero = (-0.25_f64).acos() / omega;
        let zeros = zeros(&x, &y);
        assert!((zeros[0] - first_zero).abs() < 1e-5, "{} against {first_zero}", zeros[0]);
        assert_eq!(zeros.len(), 6, "at (±acos(−¼) + 2πk)/ω before 10 s");
        let under = value_at(&x, &y, 1.2345).expect("inside");
        assert!((under - (2.0 * (omega * 1.2345).cos() + 0.5)).abs() < 1e-4);
        assert_eq!(value_at(&x, &y, -1.0), None);
    }
}
