//! The difference array of [`super::Bdf`]: the interpolating polynomial through the back
//! values kept as modified divided differences on an equal grid, re-expressed on a grid of
//! another spacing by the product `R·U` (Shampine and Reichelt, *The MATLAB ODE Suite*, 1997),
//! and turned into the monomial coefficients of a step's dense output.

use crate::Real;

/// The highest order.
pub const MAX_ORDER: usize = 5;

/// Rows of the difference array: `D⁰ … D^(k+2)` for the highest order `k`.
pub(super) const ROWS: usize = MAX_ORDER + 3;

/// `R(k, ρ)`: `R[i][j] = Π_{m=1..i} (m − 1 − ρ j)/m` (row 0 all ones), `(k+1) × (k+1)`.
fn r_matrix(order: usize, factor: Real) -> [[Real; MAX_ORDER + 1]; MAX_ORDER + 1] {
    let mut r = [[0.0; MAX_ORDER + 1]; MAX_ORDER + 1];
    r[0][..=order].fill(1.0);
    for i in 1..=order {
        for j in 0..=order {
            let m = if j == 0 {
                0.0
            } else {
                (i as Real - 1.0 - factor * j as Real) / i as Real
            };
            r[i][j] = r[i - 1][j] * m;
        }
    }
    r
}

/// Re-expresses the differences `D⁰ … D^k` (rows of `n` values in `d`) of the polynomial on
/// the grid of spacing `h` as those on the grid of spacing `factor · h`: `D ← (R U)ᵀ D`.
pub(super) fn change_spacing(d: &mut [Real], n: usize, order: usize, factor: Real) {
    if factor == 1.0 {
        return;
    }
    let r = r_matrix(order, factor);
    let u = r_matrix(order, 1.0);
    let mut ru = [[0.0; MAX_ORDER + 1]; MAX_ORDER + 1];
    for i in 0..=order {
        for j in 0..=order {
            ru[i][j] = (0..=order).map(|m| r[i][m] * u[m][j]).sum();
        }
    }
    let mut col = [0.0; MAX_ORDER + 1];
    for c in 0..n {
        for (j, out) in col.iter_mut().enumerate().take(order + 1) {
            *out = (0..=order).map(|i| ru[i][j] * d[i * n + c]).sum();
        }
        for (j, v) in col.iter().enumerate().take(order + 1) {
            d[j * n + c] = *v;
        }
    }
}

/// The monomial coefficients in `s` of the Newton basis of the step ending at the newest
/// back value: `φ₀ = 1`, `φⱼ(s) = Π_{m<j} (s − 1 + m)/(m + 1)` with `s = (t − t_{n−1})/h`,
/// so that `P(s) = Σⱼ Dʲ φⱼ(s)` interpolates the back values at `s = 1, 0, −1, …`.
pub(super) fn newton_basis(order: usize) -> [[Real; MAX_ORDER + 1]; MAX_ORDER + 1] {
    let mut phi = [[0.0; MAX_ORDER + 1]; MAX_ORDER + 1];
    phi[0][0] = 1.0;
    for j in 1..=order {
        // φⱼ = φⱼ₋₁ · (s + (j − 2))/j
        let shift = (j as Real - 2.0) / j as Real;
        let scale = 1.0 / j as Real;
        for p in 0..=j {
            let from_s = if p > 0 {
                phi[j - 1][p - 1] * scale
            } else {
                0.0
            };
            phi[j][p] = from_s + phi[j - 1][p] * shift;
        }
    }
    phi
}
