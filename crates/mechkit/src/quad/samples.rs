//! Quadrature of sampled data `(x_i, y_i)`: the trapezoid rule (NumPy's `trapezoid`), its
//! running sum (SciPy's `cumulative_trapezoid(initial=0)`) and Simpson's rule on non-uniform
//! samples (SciPy's `simpson` and `cumulative_simpson`).
//!
//! With spacings `h_i = x_{i+1} − x_i`:
//!
//! - trapezoid: `Σ h_i (y_i + y_{i+1}) / 2`;
//! - Simpson, per pair of intervals `(h₀, h₁)` through `y₀, y₁, y₂` (the parabola through
//!   the three points, integrated):
//!   `(h₀+h₁)/6 · [(2 − h₁/h₀) y₀ + (h₀+h₁)²/(h₀h₁) y₁ + (2 − h₀/h₁) y₂]`,
//!   which is `h/3 (y₀ + 4y₁ + y₂)` for equal spacings. With an odd number of intervals the last
//!   one is the parabola through the last three points integrated over that interval
//!   (Cartwright, "Simpson's rule cumulative integration with MS Excel and irregularly-spaced
//!   data", *J. Math. Sci. Math. Educ.* 12(2), 2017, eq. 8), as in SciPy ≥ 1.11.
//!
//! The spacings are signed: `x` may decrease (a path walked backwards gives the negated
//! integral); repeated `x` values make Simpson's coefficients divide by zero. Checking the
//! data (finite, ordered) is the reader's job. Sums are blocked and pairwise (see
//! `summation.rs`): the rounding error grows like `log n`, not `n`.

use super::summation::{LANES, pairwise, prefix_into, sum_columns};
use crate::Real;

fn check_lengths(x: &[Real], y: &[Real]) {
    assert!(
        x.len() == y.len(),
        "x and y have different lengths ({} and {})",
        x.len(),
        y.len()
    );
}

/// `∫ y dx` by the trapezoid rule on samples at any spacing; 0 for fewer than two samples.
///
/// Panics if `x` and `y` have different lengths.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::quad::trapz;
/// assert_relative_eq!(trapz(&[0.0, 1.0, 3.0], &[0.0, 1.0, 3.0]), 4.5);
/// assert_relative_eq!(trapz(&[3.0, 1.0, 0.0], &[3.0, 1.0, 0.0]), -4.5); // walked backwards
/// ```
pub fn trapz(x: &[Real], y: &[Real]) -> Real {
    check_lengths(x, y);
    let n = x.len();
    if n < 2 {
        return 0.0;
    }
    let cols = [&x[..n - 1], &x[1..], &y[..n - 1], &y[1..]];
    0.5 * sum_columns(cols, |[x0, x1, y0, y1]| (x1 - x0) * (y0 + y1))
}

/// `∫ y dx` by the trapezoid rule on samples `h` apart: `h (Σ y_i − (y_0 + y_{n−1})/2)`;
/// 0 for fewer than two samples.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::quad::trapz_uniform;
/// assert_relative_eq!(trapz_uniform(0.5, &[0.0, 0.5, 1.0]), 0.5);
/// ```
pub fn trapz_uniform(h: Real, y: &[Real]) -> Real {
    let n = y.len();
    if n < 2 {
        return 0.0;
    }
    h * (sum_columns([y], |[v]| v) - 0.5 * (y[0] + y[n - 1]))
}

/// The running trapezoid integral `∫_{x_0}^{x_i} y dx` at every sample (so it starts at 0 and
/// has the length of `x`), like SciPy's `cumulative_trapezoid(y, x, initial=0)`.
///
/// # Example
/// ```
/// use mechkit::quad::cumtrapz;
/// assert_eq!(cumtrapz(&[0.0, 1.0, 2.0], &[1.0, 1.0, 3.0]), [0.0, 1.0, 3.0]);
/// ```
pub fn cumtrapz(x: &[Real], y: &[Real]) -> Vec<Real> {
    let mut out = vec![0.0; x.len()];
    cumtrapz_into(x, y, &mut out);
    out
}

/// [`cumtrapz`] into a buffer of the length of `x`.
///
/// The sum runs from left to right (its rounding error grows like `n ε`, so the last element
/// agrees with [`trapz`] to about `n ε Σ|h_i y_i|`).
///
/// Panics if `x`, `y` and `out` do not have the same length.
pub fn cumtrapz_into(x: &[Real], y: &[Real], out: &mut [Real]) {
    check_lengths(x, y);
    assert_eq!(out.len(), x.len(), "the output must have the length of x");
    let n = x.len();
    if n < 2 {
        out.fill(0.0);
        return;
    }
    let cols = [&x[..n - 1], &x[1..], &y[..n - 1], &y[1..]];
    prefix_into(cols, |[x0, x1, y0, y1]| 0.5 * (x1 - x0) * (y0 + y1), out);
}

/// `∫ y dx` by composite Simpson on samples at any spacing, as SciPy's `simpson(y, x=x)`
/// (≥ 1.11): parabolas through pairs of intervals, and with an odd number of intervals the
/// last one from the parabola through the last three samples. Two samples give the
/// trapezoid, fewer give 0. Samples in reverse order give the negated integral when the number
/// of intervals is even; when it is odd the pairs start from the other end, so the value
/// differs by the rule's error (SciPy's does the same).
///
/// Panics if `x` and `y` have different lengths.
///
/// # Example
/// Exact for cubics on an even number of equal intervals, and for parabolas on any grid:
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::quad::simpson;
/// let x = [0.0, 0.5, 1.0, 1.5, 2.0];
/// let y = x.map(|x: f64| x * x * x);
/// assert_relative_eq!(simpson(&x, &y), 4.0, epsilon = 1e-15);
/// let x = [0.0, 0.2, 0.7, 1.0, 1.6, 2.0];
/// let y = x.map(|x: f64| x * x);
/// assert_relative_eq!(simpson(&x, &y), 8.0 / 3.0, epsilon = 1e-14);
/// ```
pub fn simpson(x: &[Real], y: &[Real]) -> Real {
    check_lengths(x, y);
    let n = x.len();
    if n < 2 {
        return 0.0;
    }
    if n == 2 {
        return 0.5 * (x[1] - x[0]) * (y[0] + y[1]);
    }
    let pairs = (n - 1) / 2;
    let mut total = pairwise(pairs, &|r| {
        let (lo, hi) = (2 * r.start, 2 * r.end + 1);
        simpson_pairs(&x[lo..hi], &y[lo..hi])
    });
    if (n - 1) % 2 == 1 {
        total += last_half(&x[n - 3..], &y[n - 3..]);
    }
    total
}

/// Simpson over consecutive pairs of intervals: `x` and `y` have `2p + 1` samples. Groups of
/// [`LANES`] pairs go to separate accumulators, so that LLVM can vectorise the divisions.
fn simpson_pairs(x: &[Real], y: &[Real]) -> Real {
    let pairs = (x.len() - 1) / 2;
    let full = pairs / LANES * LANES;
    let mut acc = [0.0; LANES];
    for j in (0..full).step_by(LANES) {
        // fixed-length windows: the indices below need no bounds checks
        let xs = &x[2 * j..=2 * (j + LANES)];
        let ys = &y[2 * j..=2 * (j + LANES)];
        for (k, a) in acc.iter_mut().enumerate() {
            *a += simpson_pair(&xs[2 * k..2 * k + 3], &ys[2 * k..2 * k + 3]);
        }
    }
    let tail: Real = (full..pairs)
        .map(|j| simpson_pair(&x[2 * j..2 * j + 3], &y[2 * j..2 * j + 3]))
        .sum();
    acc.iter().sum::<Real>() + tail
}

/// `∫_{x₀}^{x₂}` of the parabola through three samples.
#[inline]
fn simpson_pair(x: &[Real], y: &[Real]) -> Real {
    let (h0, h1) = (x[1] - x[0], x[2] - x[1]);
    let hs = h0 + h1;
    // the module's formula with h₀h₁ taken out of the bracket: one division, nine products
    let scale = hs * (1.0 / 6.0) / (h0 * h1);
    scale * (h1 * (h0 + h0 - h1) * y[0] + hs * hs * y[1] + h0 * (h1 + h1 - h0) * y[2])
}

/// `∫_{x₀}^{x₁}` of the parabola through `(x₀, y₀), (x₁, y₁), (x₂, y₂)` (Cartwright 2017,
/// eq. 8; SciPy's `_cumulative_simpson_unequal_intervals`).
fn first_half(x: &[Real], y: &[Real]) -> Real {
    let (h0, h1) = (x[1] - x[0], x[2] - x[1]);
    half_panel(h0, h1, y[0], y[1], y[2])
}

/// `∫_{x₁}^{x₂}` of the parabola through three samples: [`first_half`] mirrored.
fn last_half(x: &[Real], y: &[Real]) -> Real {
    let (h0, h1) = (x[1] - x[0], x[2] - x[1]);
    half_panel(h1, h0, y[2], y[1], y[0])
}

/// The first interval (width `h0`) of the parabola through `f1, f2, f3` spaced `h0, h1`.
fn half_panel(h0: Real, h1: Real, f1: Real, f2: Real, f3: Real) -> Real {
    let hs = h0 + h1;
    let a = h0 / hs;
    let b = h0 * h0 / (hs * h1);
    h0 / 6.0 * ((3.0 - a) * f1 + (3.0 + b + a) * f2 - b * f3)
}

/// Cumulative Simpson into `out` (length of `x`, at least 2 samples), as SciPy's
/// `cumulative_simpson(y, x=x, initial=0)`: each interval is integrated on the parabola through
/// its pair (the first half of the pair for even intervals, the second half for odd ones and
/// for a last unpaired interval), then summed left to right. At even indices this is
/// [`simpson`] on the samples so far; two samples give the trapezoid.
pub(super) fn cumulative_simpson_into(x: &[Real], y: &[Real], out: &mut [Real]) {
    let n = x.len();
    debug_assert!(n >= 2 && y.len() == n && out.len() == n);
    out[0] = 0.0;
    if n == 2 {
        out[1] = 0.5 * (x[1] - x[0]) * (y[0] + y[1]);
        return;
    }
    let mut total = 0.0;
    for j in 0..n - 1 {
        total += if j % 2 == 0 && j + 2 < n {
            first_half(&x[j..j + 3], &y[j..j + 3])
        } else {
            last_half(&x[j - 1..j + 2], &y[j - 1..j + 2])
        };
        out[j + 1] = total;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_samples_and_fewer() {
        let (x, y) = ([1.0, 3.0], [2.0, 4.0]);
        assert_eq!(trapz(&x, &y), 6.0);
        assert_eq!(simpson(&x, &y), 6.0);
        assert_eq!(trapz_uniform(2.0, &y), 6.0);
        assert_eq!(cumtrapz(&x, &y), [0.0, 6.0]);
        assert_eq!(trapz(&[1.0], &[2.0]), 0.0);
        assert_eq!(simpson(&[], &[]), 0.0);
        assert!(cumtrapz(&[], &[]).is_empty());
        assert_eq!(cumtrapz(&[1.0], &[5.0]), [0.0]);
    }

    #[test]
    fn decreasing_x_negates() {
        // 10 intervals: Simpson pairs the same intervals in both directions
        let x: Vec<Real> = (0..11).map(|i| (Real::from(i) * 0.3).powf(1.5)).collect();
        let y: Vec<Real> = x.iter().map(|x| x.sin()).collect();
        let (xr, yr): (Vec<Real>, Vec<Real>) = (
            x.iter().rev().copied().collect(),
            y.iter().rev().copied().collect(),
        );
        assert!((trapz(&xr, &yr) + trapz(&x, &y)).abs() < 1e-15);
        assert!((simpson(&xr, &yr) + simpson(&x, &y)).abs() < 1e-14);
        let c = cumtrapz(&xr, &yr);
        assert!((c[10] - trapz(&xr, &yr)).abs() < 1e-15);
    }

    #[test]
    #[should_panic(expected = "different lengths (3 and 2)")]
    fn lengths_must_match() {
        let _ = trapz(&[0.0, 1.0, 2.0], &[0.0, 1.0]);
    }

    #[test]
    fn uniform_and_general_trapezoid_agree() {
        let h = 1e-3;
        let x: Vec<Real> = (0..=1000).map(|i| Real::from(i) * h).collect();
        let y: Vec<Real> = x.iter().map(|x| x.exp()).collect();
        let (a, b) = (trapz(&x, &y), trapz_uniform(h, &y));
        assert!((a - b).abs() < 1e-13, "{a} {b}");
        // error h²/12 (e − 1)
        let exact = 1f64.exp() - 1.0;
        assert!((a - exact - h * h / 12.0 * exact).abs() < 1e-10, "{a}");
    }

    #[test]
    fn simpson_odd_intervals_integrate_parabolas_exactly() {
        let x = [0.0, 0.3, 0.35, 1.0, 1.2, 2.0, 2.25, 3.0];
        let y = x.map(|x| 1.0 - 2.0 * x + 3.0 * x * x);
        let exact = 3.0 - 9.0 + 27.0;
        assert!(
            (simpson(&x, &y) - exact).abs() < 1e-13,
            "{}",
            simpson(&x, &y)
        );
        let mut c = [0.0; 8];
        cumulative_simpson_into(&x, &y, &mut c);
        for (xi, ci) in x.iter().zip(c) {
            assert!(
                (ci - (xi - xi * xi + xi * xi * xi)).abs() < 1e-13,
                "at {xi}: {ci}"
            );
        }
    }
}
