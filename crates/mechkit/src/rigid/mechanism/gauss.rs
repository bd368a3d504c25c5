//! The small dense solver of the joints' multipliers: Gaussian elimination with partial
//! pivoting that leaves out redundant constraints.

use crate::Real;

/// Solves `a x = b` (`n × n`, row-major) by Gaussian elimination with partial pivoting; a
/// pivot at rounding level (a redundant constraint) gives that multiplier 0.
pub(super) fn gauss(a: &mut [Real], mut b: Vec<Real>, n: usize) -> Vec<Real> {
    let scale = a.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let tiny = scale * 1e-13;
    let mut perm: Vec<usize> = (0..n).collect();
    let mut skip = vec![false; n];
    for col in 0..n {
        let piv = (col..n)
            .max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
            .unwrap_or(col);
        if a[piv * n + col].abs() <= tiny {
            skip[col] = true;
            continue;
        }
        if piv != col {
            for k in 0..n {
                a.swap(piv * n + k, col * n + k);
            }
            b.swap(piv, col);
            perm.swap(piv, col);
        }
        for i in col + 1..n {
            let f = a[i * n + col] / a[col * n + col];
            if f != 0.0 {
                for k in col..n {
                    a[i * n + k] -= f * a[col * n + k];
                }
                b[i] -= f * b[col];
            }
        }
    }
    let mut x = vec![0.0; n];
    for col in (0..n).rev() {
        if skip[col] {
            continue;
        }
        let s: Real = (col + 1..n).map(|k| a[col * n + k] * x[k]).sum();
        x[col] = (b[col] - s) / a[col * n + col];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::gauss;

    #[test]
    fn gauss_solves_and_skips_redundant_rows() {
        let mut a = vec![2.0, 1.0, 1.0, 3.0];
        let x = gauss(&mut a, vec![3.0, 5.0], 2);
        assert!((x[0] - 0.8).abs() < 1e-15 && (x[1] - 1.4).abs() < 1e-15);
        let mut a = vec![1.0, 1.0, 1.0, 1.0];
        let x = gauss(&mut a, vec![2.0, 2.0], 2);
        assert!((x[0] + x[1] - 2.0).abs() < 1e-15);
    }
}
