//! Tanh-sinh (double exponential) quadrature (Takahasi and Mori, 1974): `x = c + h tanh(π/2
//! sinh t)` crowds the nodes towards both ends double-exponentially, so an integrable
//! singularity at an end (`1/sqrt(1 - x^2)` on [-1, 1], `ln(x)` on [0, 1]) converges as fast
//! as a smooth integrand. The integrand is given as two functions of the distance `s > 0` to
//! each end, `f(a + s)` and `f(b - s)`, so that nodes closer to an end than the rounding of
//! `x` are still distinct (a symbolic integrand can be expanded around the end: `1 - x^2` at
//! `x = 1 - s` is `2 s - s^2`).

use super::{QuadError, QuadResult, Tolerance};
use crate::Real;

/// Halvings of the step, from 1/2 (each doubles the nodes).
const LEVELS: usize = 9;

/// `∫_a^b f dx` by tanh-sinh quadrature on a finite interval `a < b`, with `near_a(s) = f(a +
/// s)` and `near_b(s) = f(b - s)` for `0 < s ≤ (b - a)/2`. Converged when two successive step
/// halvings agree to the tolerance; the error estimate is their difference.
///
/// ```
/// use mechkit::quad::{tanh_sinh, Tolerance};
/// // 1/sqrt(1 - x^2) on [-1, 1] = pi, written around each end: 1 - (±1 ∓ s)^2 = 2 s - s^2
/// let g = |s: f64| 1.0 / (2.0 * s - s * s).sqrt();
/// let r = tanh_sinh(g, g, -1.0, 1.0, Tolerance::default()).unwrap();
/// assert!((r.value - std::f64::consts::PI).abs() < 1e-12);
/// ```
pub fn tanh_sinh(
    mut near_a: impl FnMut(Real) -> Real,
    mut near_b: impl FnMut(Real) -> Real,
    a: Real,
    b: Real,
    tol: Tolerance,
) -> Result<QuadResult, QuadError> {
    if !(a.is_finite() && b.is_finite() && a < b) {
        return Err(QuadError::BadLimits);
    }
    let half = 0.5 * (b - a);
    let mut evaluations = 0;
    // the sum over the nodes k h for all k, kept between levels (odd k added each level)
    let mut sum = 0.0;
    let mut previous = Real::NAN;
    let mut difference = Real::INFINITY;
    let mut h = 1.0;
    for level in 0..=LEVELS {
        let (start, stride) = if level == 0 { (0, 1) } else { (1, 2) };
        if level > 0 {
            h *= 0.5;
        }
        let mut k = start;
        loop {
            let t = Real::from(k) * h;
            let u = std::f64::consts::FRAC_PI_2 * t.sinh();
            // distance to the nearer end: half (1 - tanh|u|) = 2 half/(e^(2|u|) + 1)
            let s = 2.0 * half / ((2.0 * u).exp() + 1.0);
            let w = half * std::f64::consts::FRAC_PI_2 * t.cosh() / u.cosh().powi(2);
            if s <= 0.0 || w <= Real::MIN_POSITIVE {
                break;
            }
            let (left, right) = if k == 0 {
                (near_a(half), 0.0)
            } else {
                (near_a(s), near_b(s))
            };
            evaluations += if k == 0 { 1 } else { 2 };
            for (v, x) in [(left, a + s), (right, b - s)] {
                if !v.is_finite() {
                    return Err(QuadError::NotFinite { x, value: v });
                }
            }
            sum += w * (left + right);
            k += stride;
        }
        let value = sum * h;
        let error = (value - previous).abs();
        if level >= 3 && error <= tol.abs.max(tol.rel * value.abs()) {
            return Ok(QuadResult {
                value,
                error,
                evaluations,
            });
        }
        previous = value;
        difference = error;
    }
    Err(QuadError::NotConverged {
        value: previous,
        error: if difference.is_finite() {
            difference
        } else {
            previous.abs()
        },
        panels: evaluations,
    })
}
