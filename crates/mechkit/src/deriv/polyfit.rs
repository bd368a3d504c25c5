//! Weights of least-squares polynomial fits on equally spaced points: the value (or a
//! derivative) at a point of the polynomial of order `p` fitted to `w` samples is a fixed linear
//! combination of the samples. Savitzky-Golay filters are these weights.
//!
//! With the design matrix `Aⱼₖ = zⱼᵏ` (`zⱼ` the positions scaled to [−1, 1], which keeps it well
//! conditioned) factored as `A = QR` by modified Gram-Schmidt with reorthogonalization, the
//! coefficients are `c = R⁻¹Qᵀy` and the estimate `eᵀc = (Q R⁻ᵀe)ᵀ y`, where `eₖ` is the `d`-th
//! derivative of `zᵏ` at the evaluation point. Björck, *Numerical Methods for Least Squares
//! Problems*, SIAM 1996, §2.4 (MGS) and §1.3.

use crate::Real;

/// A least-squares polynomial fit of order `order` to `window` equally spaced points, ready to
/// give weights for any evaluation point and derivative.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PolyFit {
    window: usize,
    /// Scale: positions are `z = (j − centre)/scale`.
    scale: Real,
    /// `Q`, column after column (`order + 1` columns of `window` values).
    q: Vec<Vec<Real>>,
    /// `R` (upper triangular), column after column: column `k` holds `R₀ₖ … Rₖₖ`.
    r: Vec<Vec<Real>>,
}

impl PolyFit {
    /// The fit of order `order` to `window` points; `window > order`.
    pub(crate) fn new(window: usize, order: usize) -> Self {
        assert!(window > order, "a fit needs more points than coefficients");
        let centre = (window - 1) as Real / 2.0;
        let scale = centre.max(1.0);
        let z: Vec<Real> = (0..window).map(|j| (j as Real - centre) / scale).collect();
        let mut q: Vec<Vec<Real>> = Vec::with_capacity(order + 1);
        let mut r: Vec<Vec<Real>> = Vec::with_capacity(order + 1);
        for k in 0..=order {
            let mut v: Vec<Real> = z.iter().map(|z| z.powi(k as i32)).collect();
            let mut column = vec![0.0; k + 1];
            // Two passes of Gram-Schmidt ("twice is enough", Giraud et al. 2005).
            for _ in 0..2 {
                for (rik, qi) in column.iter_mut().zip(&q) {
                    let dot: Real = qi.iter().zip(&v).map(|(a, b)| a * b).sum();
                    *rik += dot;
                    for (vj, qj) in v.iter_mut().zip(qi) {
                        *vj -= dot * qj;
                    }
                }
            }
            let norm = v.iter().map(|x| x * x).sum::<Real>().sqrt();
            column[k] = norm;
            for x in &mut v {
                *x /= norm;
            }
            q.push(v);
            r.push(column);
        }
        Self {
            window,
            scale,
            q,
            r,
        }
    }

    /// The weights `wⱼ` such that `Σ wⱼ yⱼ` is the `deriv`-th derivative, with respect to the
    /// point index `j`, of the fitted polynomial at the (possibly fractional) index `at`.
    pub(crate) fn weights(&self, at: Real, deriv: usize) -> Vec<Real> {
        let n = self.r.len();
        let centre = (self.window - 1) as Real / 2.0;
        let z0 = (at - centre) / self.scale;
        // e_k = d^deriv/dz^deriv z^k at z0, then chain rule for z = (j − centre)/scale.
        let e: Vec<Real> = (0..n)
            .map(|k| {
                if k < deriv {
                    return 0.0;
                }
                let falling: Real = (k - deriv + 1..=k).map(|m| m as Real).product();
                falling * z0.powi((k - deriv) as i32)
            })
            .collect();
        // Solve Rᵀu = e (forward substitution).
        let mut u = vec![0.0; n];
        for k in 0..n {
            let column = &self.r[k];
            let s: Real = column[..k].iter().zip(&u).map(|(r, u)| r * u).sum();
            u[k] = (e[k] - s) / column[k];
        }
        let factor = self.scale.powi(-(deriv as i32));
        (0..self.window)
            .map(|j| factor * (0..n).map(|k| self.q[k][j] * u[k]).sum::<Real>())
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;

    use super::*;

    fn apply(w: &[Real], y: &[Real]) -> Real {
        w.iter().zip(y).map(|(a, b)| a * b).sum()
    }

    #[test]
    fn classic_five_point_quadratic() {
        // Savitzky & Golay (1964), table I: (−3, 12, 17, 12, −3)/35.
        let w = PolyFit::new(5, 2).weights(2.0, 0);
        for (w, c) in w.iter().zip([-3.0, 12.0, 17.0, 12.0, -3.0]) {
            assert_relative_eq!(*w, c / 35.0, epsilon = 1e-15);
        }
    }

    #[test]
    fn reproduces_polynomials_of_its_order() {
        let fit = PolyFit::new(9, 3);
        let p = |x: Real| 2.0 - x + 0.5 * x * x - 0.1 * x * x * x;
        let dp = |x: Real| -1.0 + x - 0.3 * x * x;
        let d2p = |x: Real| 1.0 - 0.6 * x;
        let y: Vec<Real> = (0..9).map(|j| p(Real::from(j))).collect();
        for at in [0.0, 1.0, 4.0, 7.5, 8.0] {
            assert_relative_eq!(apply(&fit.weights(at, 0), &y), p(at), epsilon = 1e-12);
            assert_relative_eq!(apply(&fit.weights(at, 1), &y), dp(at), epsilon = 1e-12);
            assert_relative_eq!(apply(&fit.weights(at, 2), &y), d2p(at), epsilon = 1e-12);
            assert_relative_eq!(apply(&fit.weights(at, 4), &y), 0.0, epsilon = 1e-12);
        }
    }
}
