//! The small complementarity problems of a body's contacts, solved exactly: find x with
//! w = M x + q, where the first `n` unknowns are contact forces or impulses (x ≥ 0,
//! w ≥ 0, x·w = 0: a contact pushes only while it touches) and the rest are free (w = 0:
//! friction that holds a patch still). A body against the walls and ramps touches at a
//! handful of points, so every set of pushing contacts is tried, fewest first, and the
//! first that satisfies every condition is the answer: exact to rounding, where an
//! iterative solver would stop at a tolerance.

/// The most contacts whose every combination is tried (2⁸ small solves); beyond, the
/// deepest are kept (a body on the walls and ramps touches at four points at most).
pub(crate) const MOST_CONTACTS: usize = 8;

/// Solves the mixed problem; `None` when no combination satisfies it (a degenerate
/// arrangement whose every system is singular).
pub(crate) fn solve(m: &[Vec<f64>], q: &[f64], n: usize) -> Option<Vec<f64>> {
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
}
