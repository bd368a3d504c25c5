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
//! shrinks with `d` where `f` is continuous, and stays the size of the jump where it is not;
//! so does the larger difference from `f(x)` itself (else the rounding of `x ± d` in a kink
//! away from 0, `|x − 1|` at 1, passed for a jump of 1e-16).
//!
//! A corner (a kink, a cusp) is told the same way from the one-sided slopes
//! `(f(x) − f(x − d))/d` and `(f(x + d) − f(x))/d`: their difference shrinks like `f'' d` where
//! `f` is differentiable, and stays where it is not (`|x|` at 0: −1 and 1). There is no
//! derivative there, whatever the rules say (`sign(0)` = 0).
//!
//! A vertical tangent or a cusp (`cbrt(x)`, `sqrt(|x|)` at 0) shows in the same slopes: on
//! both sides they grow without bound as the step shrinks (by more than 3 times each time the
//! step is cut 100 times; a slope that tends to a value changes by `f'' d`). There is no finite
//! derivative there.

use super::richardson::{Estimate, derivative};
use crate::Real;

/// What Ridders' estimate says about a derivative.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Verdict {
    /// The estimate confirms it.
    Agree,
    /// The two differ, or the estimate is too uncertain to confirm it.
    Disagree,
    /// The claimed value is not a number, but the estimate is sure and nothing breaks the
    /// function there: the derivative exists and is the estimate (the claimed formula has a
    /// removable singularity there: `2x³/√(x⁴)`, the rules' derivative of `√(x⁴)`, at 0).
    EstimateOnly,
    /// The function jumps at the point: no derivative exists there. Its limits from the left
    /// and from the right.
    Jump {
        /// `f(x⁻)`.
        left: Real,
        /// `f(x⁺)`.
        right: Real,
    },
    /// The function's slopes grow without bound on both sides of the point (a vertical
    /// tangent when they have one sign, a cusp when opposite): no finite derivative exists
    /// there. Its slopes over the smallest steps tried, `1e-8` of the initial step.
    Vertical {
        /// The slope from the left.
        left: Real,
        /// The slope from the right.
        right: Real,
    },
    /// The function is continuous at the point but has a corner: no derivative exists there.
    /// Its slopes just left and just right of it.
    Kink {
        /// The slope from the left.
        left: Real,
        /// The slope from the right.
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
    match kink(&f, x, h) {
        Some(Corner::Vertical(left, right)) => return (est, Verdict::Vertical { left, right }),
        Some(Corner::Kink(left, right)) => return (est, Verdict::Kink { left, right }),
        None => {}
    }
    let scale = claimed
        .abs()
        .max(est.value.abs())
        .max((f(x - h).abs() + f(x + h).abs()) / (2.0 * h));
    let close = (claimed - est.value).abs() <= (10.0 * est.error).max(1e-9 * claimed.abs());
    let sure = est.error <= 1e-4 * scale;
    let verdict = if close && sure {
        Verdict::Agree
    } else if !claimed.is_finite()
        && sure
        && est.value.is_finite()
        && one_sided(&f, x, h, est.value, 1e-4 * scale)
    {
        Verdict::EstimateOnly
    } else {
        Verdict::Disagree
    };
    (est, verdict)
}

/// Whether `f` has a value at `x` and its one-sided slopes over `1e-6 h` both lie within
/// `tolerance` of `slope` (central differences alone would pass `x sin(1/x)` at 0, even and
/// NaN at 0 itself, for a derivative of 0).
fn one_sided(f: &impl Fn(Real) -> Real, x: Real, h: Real, slope: Real, tolerance: Real) -> bool {
    let f0 = f(x);
    let (left, right, _) = slopes(f, x, f0, 1e-6 * h);
    f0.is_finite() && (left - slope).abs() <= tolerance && (right - slope).abs() <= tolerance
}

/// The slopes of `f` (valued `f0` at `x`) from the left and from the right over the step
/// `d`, divided by the steps as taken so that the rounding of `x ± d` cancels, and the
/// rounding of the values over that step.
fn slopes(f: &impl Fn(Real) -> Real, x: Real, f0: Real, d: Real) -> (Real, Real, Real) {
    let (a, b) = steps(x, d);
    let (fa, fb) = (f(a), f(b));
    let (left, right) = ((f0 - fa) / (x - a), (fb - f0) / (b - x));
    let rounding = 1e3 * Real::EPSILON * (f0.abs() + fa.abs() + fb.abs()) / (b - x).min(x - a);
    (left, right, rounding)
}

/// `x ± d`, no closer to `x` than a few units in its last place, where `x ± d` is still not
/// `x`: the steps taken to each side, as they round.
fn steps(x: Real, d: Real) -> (Real, Real) {
    let d = d.max(4.0 * Real::EPSILON * x.abs());
    (x - d, x + d)
}

/// The values on each side of `x` when `f` jumps there (the difference across `x`, and the
/// larger difference from `f(x)`, do not shrink from `1e-4 h` to `1e-8 h`, and are more than
/// rounding), else `None`.
fn jump(f: &impl Fn(Real) -> Real, x: Real, h: Real) -> Option<(Real, Real)> {
    let f0 = f(x);
    let sides = |d: Real| {
        let (a, b) = steps(x, d);
        (f(a), f(b))
    };
    let (l1, r1) = sides(1e-4 * h);
    let (l2, r2) = sides(1e-8 * h);
    let (far, near) = ((r1 - l1).abs(), (r2 - l2).abs());
    let rounding = 1e3 * Real::EPSILON * (l2.abs() + r2.abs());
    let from_centre = |l: Real, r: Real| (l - f0).abs().max((r - f0).abs());
    let stays = from_centre(l2, r2) > 0.5 * from_centre(l1, r1) || !f0.is_finite();
    (near > 0.5 * far && near > rounding && stays).then_some((l2, r2))
}

/// How a function breaks at a point, from its one-sided slopes there.
enum Corner {
    /// The slopes grow without bound on both sides.
    Vertical(Real, Real),
    /// The slopes differ by a difference that does not shrink.
    Kink(Real, Real),
}

/// The slopes on each side of `x` over `1e-8 h` when `f` has a corner there (their
/// difference does not shrink from `1e-4 h` to `1e-6 h` to `1e-8 h`, and is more than the
/// rounding of the values over the step), or when they grow without bound on both sides (more
/// than 3 times at each step), else `None`.
fn kink(f: &impl Fn(Real) -> Real, x: Real, h: Real) -> Option<Corner> {
    let f0 = f(x);
    if !f0.is_finite() {
        return None;
    }
    let (l1, r1, _) = slopes(f, x, f0, 1e-4 * h);
    let (l2, r2, _) = slopes(f, x, f0, 1e-6 * h);
    let (l3, r3, rounding) = slopes(f, x, f0, 1e-8 * h);
    if ![l1, r1, l2, r2, l3, r3].iter().all(|s| s.is_finite()) {
        return None;
    }
    let grows = |a: Real, b: Real, c: Real| b.abs() > 3.0 * a.abs() && c.abs() > 3.0 * b.abs();
    if grows(l1, l2, l3) && grows(r1, r2, r3) && l3.abs().min(r3.abs()) > rounding {
        return Some(Corner::Vertical(l3, r3));
    }
    let (g1, g2, g3) = ((r1 - l1).abs(), (r2 - l2).abs(), (r3 - l3).abs());
    (g2 > 0.5 * g1 && g3 > 0.5 * g2 && g3 > rounding).then_some(Corner::Kink(l3, r3))
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
            Verdict::Jump { .. } | Verdict::Kink { .. }
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
        // a claim that is not a number where the estimate is sure: the estimate stands
        assert_eq!(
            confirm(|x: Real| x.powi(4).sqrt(), 0.0, 0.1, Real::NAN).1,
            Verdict::EstimateOnly
        );
        // and where it is not (x sin(1/x) at 0 oscillates): nothing is confirmed
        assert_eq!(
            confirm(|x: Real| x * (1.0 / x).sin(), 0.0, 0.1, Real::NAN).1,
            Verdict::Disagree
        );
    }

    /// A corner has no derivative, at 0 and away from it (`|x − 1|` at 1 had passed for a
    /// jump of 1e-16, `|x|` at 0 for a derivative of 0, `sign(0)`); smooth functions, steep
    /// or large ones included, have none.
    #[test]
    fn a_corner_has_no_derivative_and_smooth_functions_have_no_corner() {
        for (f, x, left, right) in [
            (Real::abs as fn(Real) -> Real, 0.0, -1.0, 1.0),
            (|x: Real| (x - 1.0).abs(), 1.0, -1.0, 1.0),
            (|x: Real| (x - 1e6).abs(), 1e6, -1.0, 1.0),
            (|x: Real| x.max(0.0), 0.0, 0.0, 1.0),
            (|x: Real| 3.0 * (x - 2.0).abs() + x * x, 2.0, 1.0, 7.0),
        ] {
            match confirm(f, x, 0.1, 0.0).1 {
                Verdict::Kink { left: l, right: r } => assert!(
                    (l - left).abs() < 1e-6 && (r - right).abs() < 1e-6,
                    "at {x}: {l} {r}"
                ),
                v => panic!("at {x}: {v:?}"),
            }
        }
        // a cusp (slopes of opposite signs) and a vertical tangent (of one sign), growing as
        // the step shrinks, on both sides
        for (f, x, opposite) in [
            ((|x: Real| x.abs().sqrt()) as fn(Real) -> Real, 0.0, true),
            (Real::cbrt, 0.0, false),
            (|x: Real| (x - 3.0).cbrt() + x, 3.0, false),
            (|x: Real| -(x - 1.0).abs().powf(0.25), 1.0, true),
        ] {
            match confirm(f, x, 0.1, 0.0).1 {
                Verdict::Vertical { left, right } => {
                    assert!(
                        left.abs() > 1e3 && right.abs() > 1e3,
                        "at {x}: {left} {right}"
                    );
                    assert_eq!(left.signum() != right.signum(), opposite, "at {x}");
                }
                v => panic!("at {x}: {v:?}"),
            }
        }
        for (f, x, d) in [
            (Real::sin as fn(Real) -> Real, 1.0, 1f64.cos()),
            (|x: Real| (1000.0 * x).exp(), 0.0, 1000.0),
            (|x: Real| 1e6 + x, 2.0, 1.0),
            (|x: Real| (x - 1e6).powi(2), 1e6, 0.0),
            (|x: Real| x * x * x, 0.0, 0.0),
        ] {
            let v = confirm(f, x, 0.1, d).1;
            assert!(
                !matches!(
                    v,
                    Verdict::Kink { .. } | Verdict::Jump { .. } | Verdict::Vertical { .. }
                ),
                "at {x}: {v:?}"
            );
        }
    }
}
