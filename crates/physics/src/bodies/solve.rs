//! The small complementarity problems of a body's contacts, solved exactly: find x with
//! w = M x + q, where the first `n` unknowns are contact forces or impulses (x ≥ 0,
//! w ≥ 0, x·w = 0: a contact pushes only while it touches) and the rest are free (w = 0:
//! friction that holds a patch still). A body against the walls and ramps touches at a
//! handful of points, so every set of pushing contacts is tried, fewest first, and the
//! first that satisfies every condition is the answer; more contacts (a row of dominoes,
//! a stack) are solved by principal pivoting, one contact brought to its condition at a
//! time (Dantzig's method as Baraff gives it for contact forces). Both are exact to
//! rounding, where an iterative solver would stop at a tolerance.

/// The most contacts whose every combination is tried (2⁸ small solves); beyond, the
/// problem is solved by pivoting.
const MOST_TRIED: usize = 8;

/// Solves the mixed problem; `None` when no solution is found (a degenerate arrangement
/// whose every system is singular).
pub(crate) fn solve(m: &[Vec<f64>], q: &[f64], n: usize) -> Option<Vec<f64>> {
    if n <= MOST_TRIED {
        every_combination(m, q, n)
    } else {
        pivoting(m, q, n)
    }
}

/// The first set of pushing contacts, fewest first, whose solution meets every
/// condition.
fn every_combination(m: &[Vec<f64>], q: &[f64], n: usize) -> Option<Vec<f64>> {
    let size = q.len();
    let free: Vec<usize> = (n..size).collect();
    let scale = q
        .iter()
        .fold(0.0_f64, |s, v| s.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    let mut subsets: Vec<u32> = (0..1_u32 << n).collect();
    subsets.sort_by_key(|s| s.count_ones());
    for subset in subsets {
        let active: Vec<usize> = (0..n)
            .filter(|&k| subset & (1 << k) != 0)
            .chain(free.iter().copied())
            .collect();
        let Some(values) = solve_linear(m, q, &active) else {
            continue;
        };
        let mut x = vec![0.0; size];
        for (&k, &v) in active.iter().zip(&values) {
            x[k] = v;
        }
        let largest = x[..n].iter().fold(0.0_f64, |s, v| s.max(v.abs()));
        let pushes = x[..n].iter().all(|&v| v >= -1e-12 * largest);
        let apart = (0..n).filter(|&k| subset & (1 << k) == 0).all(|k| {
            let w: f64 = (0..size).map(|j| m[k][j] * x[j]).sum::<f64>() + q[k];
            w >= -1e-9 * scale
        });
        if pushes && apart {
            for v in &mut x[..n] {
                *v = v.max(0.0);
            }
            return Some(x);
        }
    }
    None
}

/// Principal pivoting: the free unknowns held to their conditions from the start, then
/// each contact whose condition fails driven to it — its force grows, the forces of the
/// contacts held at zero acceleration (the clamped set) following it, until its own
/// acceleration reaches zero or another contact changes sides (a clamped one's force
/// reaching zero, a separating one's acceleration reaching zero), which is then moved
/// across and the drive goes on. The answer is solved once more on the final set and
/// checked.
fn pivoting(m: &[Vec<f64>], q: &[f64], n: usize) -> Option<Vec<f64>> {
    let size = q.len();
    let scale = q
        .iter()
        .fold(0.0_f64, |s, v| s.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    let tolerance = 1e-12 * scale;
    let mut clamped: Vec<usize> = (n..size).collect();
    let mut x = vec![0.0; size];
    for (&k, v) in clamped.iter().zip(solve_linear(m, q, &clamped)?) {
        x[k] = v;
    }
    let product = |x: &[f64]| -> Vec<f64> {
        (0..size)
            .map(|r| (0..size).map(|c| m[r][c] * x[c]).sum::<f64>())
            .collect()
    };
    let mut w: Vec<f64> = product(&x).iter().zip(q).map(|(a, b)| a + b).collect();
    let mut settled: Vec<bool> = vec![false; n];
    for d in 0..n {
        if w[d] >= -tolerance {
            settled[d] = true;
            continue;
        }
        let mut done = false;
        for _ in 0..4 * size + 4 {
            let column: Vec<f64> = (0..size).map(|r| m[r][d]).collect();
            let mut dx = vec![0.0; size];
            dx[d] = 1.0;
            for (&k, v) in clamped.iter().zip(solve_linear(m, &column, &clamped)?) {
                dx[k] = v;
            }
            let dw = product(&dx);
            if dw[d] <= 0.0 {
                return None;
            }
            let (mut step, mut blocking) = (-w[d] / dw[d], d);
            for &k in clamped.iter().filter(|&&k| k < n) {
                if dx[k] < 0.0 && -x[k] / dx[k] < step {
                    (step, blocking) = ((-x[k] / dx[k]).max(0.0), k);
                }
            }
            for k in (0..n).filter(|&k| settled[k] && !clamped.contains(&k)) {
                if dw[k] < 0.0 && -w[k] / dw[k] < step {
                    (step, blocking) = ((-w[k] / dw[k]).max(0.0), k);
                }
            }
            for k in 0..size {
                x[k] += step * dx[k];
                w[k] += step * dw[k];
            }
            if blocking == d {
                clamped.push(d);
                done = true;
                break;
            }
            if let Some(at) = clamped.iter().position(|&k| k == blocking) {
                clamped.remove(at);
                x[blocking] = 0.0;
            } else {
                clamped.push(blocking);
                w[blocking] = 0.0;
            }
        }
        if !done {
            return None;
        }
        settled[d] = true;
    }
    // Solved again on the final set, which rounding over many pivots leaves less exact.
    let mut x = vec![0.0; size];
    for (&k, v) in clamped.iter().zip(solve_linear(m, q, &clamped)?) {
        x[k] = v;
    }
    let w: Vec<f64> = product(&x).iter().zip(q).map(|(a, b)| a + b).collect();
    let largest = x[..n].iter().fold(0.0_f64, |s, v| s.max(v.abs()));
    let met = (0..n).all(|k| x[k] >= -1e-12 * largest && w[k] >= -1e-9 * scale);
    met.then(|| {
        for v in &mut x[..n] {
            *v = v.max(0.0);
        }
        x
    })
}

/// The rows and columns `active` of M x = −q, by Gaussian elimination with partial
/// pivoting; `None` when singular.
fn solve_linear(m: &[Vec<f64>], q: &[f64], active: &[usize]) -> Option<Vec<f64>> {
    let k = active.len();
    if k == 0 {
        return Some(Vec::new());
    }
    let mut a: Vec<Vec<f64>> = active
        .iter()
        .map(|&r| {
            let mut row: Vec<f64> = active.iter().map(|&c| m[r][c]).collect();
            row.push(-q[r]);
            row
        })
        .collect();
    let norm = a
        .iter()
        .flat_map(|row| row[..k].iter())
        .fold(0.0_f64, |s, v| s.max(v.abs()));
    for col in 0..k {
        let pivot = (col..k).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() <= 1e-12 * norm {
            return None;
        }
        a.swap(col, pivot);
        let (above, below) = a.split_at_mut(col + 1);
        let pivot_row = &above[col];
        for row in below {
            let factor = row[col] / pivot_row[col];
            for (value, &p) in row.iter_mut().zip(pivot_row).skip(col) {
                *value -= factor * p;
            }
        }
    }
    let mut x = vec![0.0; k];
    for row in (0..k).rev() {
        let sum: f64 = (row + 1..k).map(|c| a[row][c] * x[c]).sum();
        x[row] = (a[row][k] - sum) / a[row][row];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two contacts of a body that pushes on both, one that pushes on one only, and a
    /// free unknown solved with them.
    #[test]
    fn complementarity_is_met() {
        let m = vec![vec![2.0, 1.0], vec![1.0, 2.0]];
        let x = solve(&m, &[-3.0, -3.0], 2).expect("solved");
        assert!((x[0] - 1.0).abs() < 1e-15 && (x[1] - 1.0).abs() < 1e-15);
        let x = solve(&m, &[-2.0, 3.0], 2).expect("solved");
        assert!((x[0] - 1.0).abs() < 1e-15 && x[1] == 0.0);
        let x = solve(&m, &[1.0, 1.0], 2).expect("solved");
        assert_eq!(x, vec![0.0, 0.0]);
        let free = vec![vec![1.0, 1.0], vec![1.0, 3.0]];
        let x = solve(&free, &[-1.0, 1.0], 1).expect("solved");
        assert!((x[0] - 2.0).abs() < 1e-15 && (x[1] + 1.0).abs() < 1e-15);
    }

    /// Pivoting finds what trying every combination finds, on problems of a row of
    /// contacts (a chain of unit masses, some pushed apart and some together) with a
    /// free unknown.
    #[test]
    fn pivoting_agrees_with_every_combination() {
        for seed in 0..200_u32 {
            let size = 6 + (seed % 3) as usize;
            let n = size - (seed % 2) as usize;
            let mut state = u64::from(seed).wrapping_mul(6_364_136_223_846_793_005) + 1;
            let mut random = || {
                state = state
                    .wrapping_mul(6_364_136_223_846_793_005)
                    .wrapping_add(1_442_695_040_888_963_407);
                (state >> 11) as f64 / (1_u64 << 53) as f64 - 0.5
            };
            // M = A Aᵀ + I/10: symmetric, positive definite, as a contact problem's.
            let a: Vec<Vec<f64>> = (0..size)
                .map(|_| (0..size).map(|_| random()).collect())
                .collect();
            let m: Vec<Vec<f64>> = (0..size)
                .map(|i| {
                    (0..size)
                        .map(|j| {
                            (0..size).map(|k| a[i][k] * a[j][k]).sum::<f64>()
                                + if i == j { 0.1 } else { 0.0 }
                        })
                        .collect()
                })
                .collect();
            let q: Vec<f64> = (0..size).map(|_| random()).collect();
            let tried = every_combination(&m, &q, n).expect("solved");
            let pivoted = pivoting(&m, &q, n).expect("solved");
            for (t, p) in tried.iter().zip(&pivoted) {
                assert!(
                    (t - p).abs() < 1e-9,
                    "seed {seed}: {tried:?} against {pivoted:?}"
                );
            }
        }
    }
}
