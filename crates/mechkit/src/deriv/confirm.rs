//! Whether Ridders' estimate confirms a derivative found otherwise (symbolically), and where
//! a function jumps, so that it has no derivative at all.
//!
//! The two agree when they differ by no more than ten times the estimate's error (or 1e-9
//! relative) and that error is small: at most 1e-4 of the derivative's scale (the larger of
//! the two values and `(|f(x − h)| + |f(x + h)|)/2h`, how fast `f` could change over the
//! initial step). An estimate whose error is comparable to its value confirms nothing: at a
//! jump of `floor(x)` the differences grow without bound as the step shrinks, and the
//! extrapolation returns `9 ± 4`.
//!
//! A jump is told from a steep function by the difference across `x`: `|f(x + d) − f(x − d)|`
//! shrinks with `d` where `f` is continuous, and stays the size of the jump where it is not.

use super::richardson::{Estimate, derivative};
use crate::Real;

/// What Ridders' estimate says about a derivative.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Verdict {
    /// The estimate confirms it.
    Agree,
    /// The two differ, or the estimate is too uncertain to confirm it.
    Disagree,
    /// The function jumps at the point: no derivative exists there. Its limits from the left
    /// and from the right.
    Jump {
        /// `f(x⁻)`.
        left: Real,
        /// `f(x⁺)`.
        right: Real,
    },
}

/// `claimed`, a value of `f'(x)` found otherwise, against Ridders' estimate from the initial
/// step `h` (positive and finite): the estimate and the verdict.
///
/// ```
/// use mechkit::deriv::{Verdict, confirm};
/// let (_, v) = confirm(f64::sin, 0.3, 0.1, 0.3f64.cos());
/// assert_eq!(v, Verdict::Agree);
/// let (_, v) = confirm(f64::floor, 1.0, 0.1, 0.0);
/// assert_eq!(v, Verdict::Jump { left: 0.0, right: 1.0 });
/// ```
pub fn confirm(f: impl Fn(Real) -> Real, x: Real, h: Real, claimed: Real) -> (Estimate, Verdict) {
    let est = derivative(&f, x, h);
    if let Some((left, right)) = jump(&f, x, h) {
        return (est, Verdict::Jump { left, right });
    }
    let scale = claimed
        .abs()
        .max(est.value.abs())
        .max((f(x - h).abs() + f(x + h).abs()) / (2.0 * h));
    let close = (claimed - est.value).abs() <= (10.0 * est.error).max(1e-9 * claimed.abs());
    let sure = est.error <= 1e-4 * scale;
    let verdict = if close && sure {
        Verdict::Agree
    } else {
        Verdict::Disagree
    };
    (est, verdict)
}

/// The values on each side of `x` when `f` jumps there (the difference across `x` does not
/// shrink from `1e-4 h` to `1e-8 h`, and is more than rounding), else `None`.
fn jump(f: &impl Fn(Real) -> Real, x: Real, h: Real) -> Option<(Real, Real)> {
    // no closer than a few units in the last place of `x`, where `x ± d` is still not `x`
    let sides = |d: Real| {
        let d = d.max(4.0 * Real::EPSILON * x.abs());
        (f(x - d), f(x + d))
    };
    let (l1, r1) = sides(1e-4 * h);
    let (l2, r2) = sides(1e-8 * h);
    let (far, near) = ((r1 - l1).abs(), (r2 - l2).abs());
    let rounding = 1e3 * Real::EPSILON * (l2.abs() + r2.abs());
    (near > 0.5 * far && near > rounding).then_some((l2, r2))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Review C-08: at a jump the derivative does not exist, and an estimate whose error is
    /// not small against its value confirms nothing.
    #[test]
    fn a_jump_has_no_derivative_and_an_uncertain_estimate_confirms_nothing() {
        let (_, v) = confirm(Real::signum, 0.0, 0.1, 0.0);
        assert_eq!(
            v,
            Verdict::Jump {
                left: -1.0,
                right: 1.0
            }
        );
        let step = |x: Real| if x > 1.0 { 1.0 } else { -1.0 };
        assert!(matches!(
            confirm(step, 1.0, 0.1, 0.0).1,
            Verdict::Jump { .. }
        ));
        // continuous, even with an infinite slope or a kink: no jump
        assert!(!matches!(
            confirm(Real::cbrt, 0.0, 0.1, 0.0).1,
            Verdict::Jump { .. }
        ));
        assert!(!matches!(
            confirm(Real::abs, 0.0, 0.1, 0.0).1,
            Verdict::Jump { .. }
        ));
        // smooth functions agree, a zero derivative included
        for (f, x, d) in [
            (Real::exp as fn(Real) -> Real, 1.0, 1f64.exp()),
            (|x: Real| x * x * x - 3.0 * x, 1.0, 0.0),
            (|x: Real| x * x * x, 0.0, 0.0),
            (|x: Real| 1e6 + x, 2.0, 1.0),
        ] {
            assert_eq!(confirm(f, x, 0.1, d).1, Verdict::Agree, "at {x}");
        }
        assert_eq!(confirm(Real::exp, 1.0, 0.1, 2.0).1, Verdict::Disagree);
    }
}
