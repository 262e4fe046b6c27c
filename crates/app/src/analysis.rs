//! What a graph reads off its samples: the value under the pointer, the maxima, minima
//! and zero crossings of a series, and the period from the maxima's cycle.
//!
//! The samples are the simulation's own instants (every 5 ms at a 1 ms step, `recording.rs`).
//! A maximum or minimum is the vertex of the parabola through the extreme sample and its
//! two neighbours, good to a few 1e-7 s for a smooth motion sampled every 5 ms (the
//! vertex's error grows as the sampling interval cubed); a zero crossing is where the
//! straight line between the two samples around it crosses 0. These are the graph's
//! estimates while a run plays; once it stops, `plots.rs` locates each in the run
//! between the samples around it, as the stopwatch's events are (`physics::Watch`,
//! `Simulation::extreme_until`).

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
        if !(maximum || minimum) || b.total_cmp(&c).is_eq() {
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

/// The series' cycle from its maxima ([`physics::cycle`]: the smallest number of maxima
/// that repeats), or why it has none; `None` with fewer than two maxima, where no period
/// is worth a word.
pub fn period(extremes: &[Extreme]) -> Option<Result<physics::Cycle, physics::NoCycle>> {
    let maxima: Vec<(f64, f64)> = extremes
        .iter()
        .filter(|e| e.maximum)
        .map(|e| (e.x, e.value))
        .collect();
    (maxima.len() >= 2).then(|| physics::cycle(&maxima))
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
    Some(if x1 <= x0 {
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
            assert!(
                (max.x - expected).abs() < 1e-6,
                "max {k}: {} against {expected}",
                max.x
            );
            assert!((max.value - 2.5).abs() < 1e-6, "{}", max.value);
        }
        for (k, min) in minima.iter().enumerate() {
            let expected = (k as f64 + 0.5) * period_theory;
            assert!((min.x - expected).abs() < 1e-6, "min {k}: {}", min.x);
            assert!((min.value + 1.5).abs() < 1e-6, "{}", min.value);
        }
        let cycle = period(&found)
            .expect("two maxima at least")
            .expect("a regular cycle");
        assert_eq!(cycle.cycles, 2, "three maxima");
        let period = cycle.period;
        assert!(
            (period - period_theory).abs() < 1e-7,
            "{period} against {period_theory}"
        );
        let first_zero = (-0.25_f64).acos() / omega;
        let zeros = zeros(&x, &y);
        assert!(
            (zeros[0] - first_zero).abs() < 1e-5,
            "{} against {first_zero}",
            zeros[0]
        );
        assert_eq!(zeros.len(), 6, "at (±acos(−¼) + 2πk)/ω before 10 s");
        let under = value_at(&x, &y, 1.2345).expect("inside");
        assert!((under - (2.0 * (omega * 1.2345).cos() + 0.5)).abs() < 1e-4);
        assert_eq!(value_at(&x, &y, -1.0), None);
    }
}

/// A model a series can be fitted with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Model {
    /// y = a + b x.
    Line,
    /// y = a + b x + c x².
    Parabola,
    /// y = A sin(ω x + φ) + c.
    Sine,
    /// y = A e^(−x/τ) + c.
    Decay,
}

impl Model {
    pub const ALL: [Self; 4] = [Self::Line, Self::Parabola, Self::Sine, Self::Decay];

    /// The parameters' names, in the order of [`Fit::parameters`].
    pub fn names(self) -> &'static [&'static str] {
        match self {
            Self::Line => &["a", "b"],
            Self::Parabola => &["a", "b", "c"],
            Self::Sine => &["A", "ω", "φ", "c"],
            Self::Decay => &["A", "τ", "c"],
        }
    }

    /// The model's value at `x` for parameters `p`.
    pub fn value(self, p: &[f64], x: f64) -> f64 {
        match self {
            Self::Line => p[0] + p[1] * x,
            Self::Parabola => p[0] + p[1] * x + p[2] * x * x,
            Self::Sine => p[0] * (p[1] * x + p[2]).sin() + p[3],
            Self::Decay => p[0] * (-x / p[1]).exp() + p[2],
        }
    }

    /// ∂value/∂p at `x`.
    fn gradient(self, p: &[f64], x: f64) -> Vec<f64> {
        match self {
            Self::Line => vec![1.0, x],
            Self::Parabola => vec![1.0, x, x * x],
            Self::Sine => {
                let (s, c) = (p[1] * x + p[2]).sin_cos();
                vec![s, p[0] * x * c, p[0] * c, 1.0]
            }
            Self::Decay => {
                let e = (-x / p[1]).exp();
                vec![e, p[0] * e * x / (p[1] * p[1]), 1.0]
            }
        }
    }
}

/// A least-squares fit: the parameters, their standard uncertainties (from the
/// residuals' scatter and the fit's curvature, σ² (JᵀJ)⁻¹), and the RMS residual.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit {
    pub model: Model,
    pub parameters: Vec<f64>,
    pub uncertainties: Vec<f64>,
    pub rms: f64,
}

/// The least-squares fit of `model` to the samples `(x, y)`: linear models solved
/// directly, the sine and the decay by Gauss–Newton with Levenberg's damping from a
/// start read off the data (the period from the zero crossings, the decay's scale from
/// where it falls to 1/e). `None` with too few samples or when it does not converge.
pub fn fit(model: Model, x: &[f64], y: &[f64]) -> Option<Fit> {
    let n = x.len().min(y.len());
    let p = model.names().len();
    if n <= p {
        return None;
    }
    let (x, y) = (&x[..n], &y[..n]);
    let mut params = start(model, x, y)?;
    let mut lambda = 1e-3;
    let rss = |p: &[f64]| -> f64 {
        x.iter()
            .zip(y)
            .map(|(&xi, &yi)| (yi - model.value(p, xi)).powi(2))
            .sum()
    };
    let mut current = rss(&params);
    for _ in 0..200 {
        let (jtj, jtr) = normal_equations(model, &params, x, y);
        let mut damped = jtj.clone();
        for (k, row) in damped.iter_mut().enumerate() {
            row[k] += lambda * jtj[k][k].max(1e-300);
        }
        let Some(step) = solve(damped, jtr) else {
            lambda *= 10.0;
            continue;
        };
        let trial: Vec<f64> = params.iter().zip(&step).map(|(a, b)| a + b).collect();
        let next = rss(&trial);
        if next.is_finite() && next <= current {
            let converged = (current - next) <= 1e-15 * current.max(1e-300);
            params = trial;
            current = next;
            lambda = (lambda / 10.0).max(1e-12);
            if converged {
                break;
            }
        } else {
            lambda *= 10.0;
            if lambda > 1e12 {
                break;
            }
        }
    }
    let (jtj, _) = normal_equations(model, &params, x, y);
    let sigma2 = current / (n - p) as f64;
    let inverse = invert(&jtj)?;
    let uncertainties = (0..p)
        .map(|k| (sigma2 * inverse[k][k]).max(0.0).sqrt())
        .collect();
    if model == Model::Sine && params[0] < 0.0 {
        // One form for one curve: A > 0, φ in (−π, π].
        params[0] = -params[0];
        params[2] += std::f64::consts::PI;
    }
    if model == Model::Sine {
        params[2] = (params[2] + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
            - std::f64::consts::PI;
    }
    params.iter().all(|v| v.is_finite()).then(|| Fit {
        model,
        parameters: params,
        uncertainties,
        rms: (current / n as f64).sqrt(),
    })
}

/// Where the iterations start.
fn start(model: Model, x: &[f64], y: &[f64]) -> Option<Vec<f64>> {
    let n = x.len();
    let mean = y.iter().sum::<f64>() / n as f64;
    Some(match model {
        Model::Line => vec![0.0; 2],
        Model::Parabola => vec![0.0; 3],
        Model::Sine => {
            let centred: Vec<f64> = y.iter().map(|v| v - mean).collect();
            let crossings = zeros(x, &centred);
            let omega = if crossings.len() >= 2 {
                let span = crossings[crossings.len() - 1] - crossings[0];
                std::f64::consts::PI * (crossings.len() - 1) as f64 / span
            } else {
                std::f64::consts::TAU / (x[n - 1] - x[0])
            };
            // With ω fixed the model is linear in (A cos φ, A sin φ, c): solved directly.
            let rows: Vec<[f64; 3]> = x
                .iter()
                .map(|&t| [(omega * t).sin(), (omega * t).cos(), 1.0])
                .collect();
            let (s, c, offset) = linear_fit3(&rows, y)?;
            vec![s.hypot(c), omega, c.atan2(s), offset]
        }
        Model::Decay => {
            let last = y[n - 1];
            let first = y[0] - last;
            let target = last + first / std::f64::consts::E;
            let fallen = x
                .iter()
                .zip(y)
                .find(|(_, v)| (**v - target) * first.signum() <= 0.0)
                .map_or(x[n - 1] - x[0], |(t, _)| t - x[0]);
            vec![first, fallen.max(1e-12), last]
        }
    })
}

/// The least-squares (a, b, c) of y ≈ a r₀ + b r₁ + c r₂ over the rows.
fn linear_fit3(rows: &[[f64; 3]], y: &[f64]) -> Option<(f64, f64, f64)> {
    let mut ata = vec![vec![0.0; 3]; 3];
    let mut aty = vec![0.0; 3];
    for (row, &v) in rows.iter().zip(y) {
        for i in 0..3 {
            aty[i] += row[i] * v;
            for j in 0..3 {
                ata[i][j] += row[i] * row[j];
            }
        }
    }
    let s = solve(ata, aty)?;
    Some((s[0], s[1], s[2]))
}

/// `JᵀJ` and `Jᵀr` at parameters `p`.
fn normal_equations(model: Model, p: &[f64], x: &[f64], y: &[f64]) -> (Vec<Vec<f64>>, Vec<f64>) {
    let m = p.len();
    let mut jtj = vec![vec![0.0; m]; m];
    let mut jtr = vec![0.0; m];
    for (&xi, &yi) in x.iter().zip(y) {
        let g = model.gradient(p, xi);
        let r = yi - model.value(p, xi);
        for i in 0..m {
            jtr[i] += g[i] * r;
            for j in 0..m {
                jtj[i][j] += g[i] * g[j];
            }
        }
    }
    (jtj, jtr)
}

/// `a` x = `b` by Gaussian elimination with partial pivoting; `None` if singular.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for col in 0..n {
        let pivot = (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() < 1e-300 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let (upper, lower) = a.split_at_mut(col + 1);
        let pivot_row = &upper[col];
        for (offset, row) in lower.iter_mut().enumerate() {
            let f = row[col] / pivot_row[col];
            for (value, above) in row.iter_mut().zip(pivot_row).skip(col) {
                *value -= f * above;
            }
            b[col + 1 + offset] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The inverse of `a`, column by column.
fn invert(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let columns: Option<Vec<Vec<f64>>> = (0..n)
        .map(|k| {
            let mut e = vec![0.0; n];
            e[k] = 1.0;
            solve(a.to_vec(), e)
        })
        .collect();
    let columns = columns?;
    Some(
        (0..n)
            .map(|i| (0..n).map(|j| columns[j][i]).collect())
            .collect(),
    )
}

#[cfg(test)]
mod fit_tests {
    use super::*;

    /// Each model recovers the parameters of data it generated, exactly but for rounding
    /// (1e-8 relative), from the start read off the data; with a small deterministic
    /// scatter added (±1e-3) the parameters move by about their stated uncertainty.
    #[test]
    fn each_model_recovers_its_parameters() {
        let x: Vec<f64> = (0..1500).map(|k| f64::from(k) * 0.005).collect();
        let cases = [
            (Model::Line, vec![0.5, -1.25]),
            (Model::Parabola, vec![10.0, 2.0, -4.905]),
            (Model::Sine, vec![1.7, 2.06, 0.4, -0.25]),
            (Model::Decay, vec![3.0, 1.5, 0.2]),
        ];
        for (model, truth) in cases {
            let y: Vec<f64> = x.iter().map(|&t| model.value(&truth, t)).collect();
            let found = fit(model, &x, &y).unwrap_or_else(|| panic!("{model:?} fits"));
            for (k, (got, want)) in found.parameters.iter().zip(&truth).enumerate() {
                assert!(
                    (got - want).abs() <= 1e-8 * want.abs().max(1.0),
                    "{model:?} {}: {got} against {want}",
                    model.names()[k]
                );
            }
            assert!(found.rms < 1e-9, "{model:?}: rms {}", found.rms);
            // A scatter of ±1e-3 (a fixed pattern, not random): the parameters move by
            // about their uncertainty, never by ten of them.
            let scattered: Vec<f64> = y
                .iter()
                .enumerate()
                .map(|(k, v)| v + 1e-3 * ((k as f64) * 12.9898).sin())
                .collect();
            let noisy = fit(model, &x, &scattered).expect("fits");
            for (k, want) in truth.iter().enumerate() {
                let (got, sigma) = (noisy.parameters[k], noisy.uncertainties[k]);
                assert!(sigma > 0.0, "{model:?}: an uncertainty");
                assert!(
                    (got - want).abs() < 10.0 * sigma,
                    "{model:?} {}: {got} ± {sigma} against {want}",
                    model.names()[k]
                );
            }
        }
    }
}
