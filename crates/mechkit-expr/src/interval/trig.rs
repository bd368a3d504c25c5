//! The trigonometric functions over intervals, split at their turning points:
//!
//! - `sin`, `cos`: the hull of the ends, raised to 1 when a maximum `π/2 + 2kπ` (`2kπ` for
//!   `cos`) may lie inside, lowered to −1 for a minimum. The test runs in `f64` with a margin
//!   far above its rounding error, so it never misses an extremum (it may see one that lies
//!   just outside, which loosens the bound by a second-order amount);
//! - `tan`: increasing between poles, ENTIRE when a pole `π/2 + kπ` may lie inside;
//! - `asin`, `acos`, `atan`: monotone, ENTIRE outside `[−1, 1]` for the first two;
//! - `atan2(y, x)`: the hull of the four corners where the box avoids the branch cut
//!   (`x > 0`, or `y` of one sign), else `[−π, π]`.
//!
//! Infinite arguments of `sin`, `cos`, `tan` give ENTIRE (the point functions give NaN).

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use super::bounds::{Interval, LIB_ULPS};
use super::functions::monotone;
use super::ops::corners;

/// `f64::consts::PI` rounded up: above the exact π and every `atan2` result.
const PI_UP: f64 = PI.next_up();

/// Arguments beyond this magnitude are too coarse (float spacing ~0.1) for the turning-point
/// tests: `sin`, `cos` give `[−1, 1]`, `tan` ENTIRE.
const TRIG_LIMIT: f64 = 1e15;

/// Whether `[lo, hi]` may contain a point `phase + k·period` (k an integer), erring towards
/// yes: `(x − phase)/period` is computed with a relative error below 1e-15, far inside the
/// margin.
fn may_contain(lo: f64, hi: f64, phase: f64, period: f64) -> bool {
    let a = (lo - phase) / period;
    let b = (hi - phase) / period;
    let margin = 1e-9 + 1e-13 * a.abs().max(b.abs());
    (b + margin).floor() >= (a - margin).ceil()
}

/// `sin` or `cos` (`max_at`: the phase of its maxima; minima half a turn later).
fn periodic(x: Interval, f: fn(f64) -> f64, max_at: f64) -> Interval {
    if !x.lo().is_finite() || !x.hi().is_finite() {
        return Interval::ENTIRE; // sin(±∞) is NaN
    }
    let unit = Interval::raw(-1.0, 1.0);
    if x.hi() - x.lo() >= 6.0 || x.lo().abs().max(x.hi().abs()) > TRIG_LIMIT {
        return unit;
    }
    let ends = Interval::widened_hull(f(x.lo()), f(x.hi()), LIB_ULPS);
    let hi = if may_contain(x.lo(), x.hi(), max_at, TAU) {
        1.0
    } else {
        ends.hi().min(1.0)
    };
    let lo = if may_contain(x.lo(), x.hi(), max_at + PI, TAU) {
        -1.0
    } else {
        ends.lo().max(-1.0)
    };
    Interval::raw(lo, hi)
}

/// Whether `atan2(y, x)` is continuous on the box: it avoids the branch cut `x <= 0, y = 0`
/// (and the origin).
pub(super) fn atan2_continuous(y: Interval, x: Interval) -> bool {
    x.lo() > 0.0 || y.lo() > 0.0 || y.hi() < 0.0
}

impl Interval {
    /// `sin x`: `[−1, 1]`-clipped, with 1 (−1) where a maximum (minimum) may lie inside.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let s = Interval::new(0.0, std::f64::consts::PI).sin();
    /// assert_eq!(s.hi(), 1.0);
    /// assert!(s.lo() <= 0.0 && s.lo() > -1e-15);
    /// ```
    #[must_use]
    pub fn sin(self) -> Interval {
        periodic(self, f64::sin, FRAC_PI_2)
    }

    /// `cos x`; see [`Interval::sin`].
    #[must_use]
    pub fn cos(self) -> Interval {
        periodic(self, f64::cos, 0.0)
    }

    /// `tan x`; ENTIRE where a pole `π/2 + kπ` may lie inside.
    #[must_use]
    pub fn tan(self) -> Interval {
        let x = self;
        if !x.lo().is_finite()
            || !x.hi().is_finite()
            || x.hi() - x.lo() >= 3.0
            || x.lo().abs().max(x.hi().abs()) > TRIG_LIMIT
            || may_contain(x.lo(), x.hi(), FRAC_PI_2, PI)
        {
            return Interval::ENTIRE;
        }
        monotone(x, f64::tan)
    }

    /// `asin x`; ENTIRE unless `−1 <= x <= 1`.
    #[must_use]
    pub fn asin(self) -> Interval {
        if self.lo() >= -1.0 && self.hi() <= 1.0 {
            monotone(self, f64::asin)
        } else {
            Interval::ENTIRE
        }
    }

    /// `acos x`; ENTIRE unless `−1 <= x <= 1`.
    #[must_use]
    pub fn acos(self) -> Interval {
        if self.lo() >= -1.0 && self.hi() <= 1.0 {
            monotone(self, f64::acos).clamp_nonnegative()
        } else {
            Interval::ENTIRE
        }
    }

    /// `atan x`.
    #[must_use]
    pub fn atan(self) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        monotone(self, f64::atan)
    }

    /// `atan2(self, x)`, the angle of the point `(x, self)` as `f64::atan2` gives it: the hull
    /// of the corners when the box avoids the branch cut (`x > 0`, or `y` of one sign: one
    /// partial derivative keeps its sign over the box, so the extremes lie at corners), else
    /// `[−π, π]` (widened).
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let y = Interval::new(0.5, 1.0);
    /// let a = y.atan2(Interval::new(-1.0, 1.0)); // upper half plane
    /// assert!(a.contains(std::f64::consts::FRAC_PI_4) && a.is_positive());
    /// let cut = Interval::new(-0.1, 0.1).atan2(Interval::new(-1.0, -0.5));
    /// assert!(cut.contains(std::f64::consts::PI) && cut.contains(-std::f64::consts::PI));
    /// ```
    #[must_use]
    pub fn atan2(self, x: Interval) -> Interval {
        if self.is_entire() || x.is_entire() {
            return Interval::ENTIRE;
        }
        let turn = Interval::raw(-PI_UP, PI_UP);
        if !atan2_continuous(self, x) {
            return turn;
        }
        let c = corners(self, x, f64::atan2, LIB_ULPS);
        Interval::raw(c.lo().max(-PI_UP), c.hi().min(PI_UP))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn i(lo: f64, hi: f64) -> Interval {
        Interval::new(lo, hi)
    }

    #[test]
    fn sine_and_cosine_find_their_extrema() {
        let s = i(0.0, PI).sin();
        assert_eq!(s.hi(), 1.0);
        assert!(s.lo() <= 0.0 && s.lo() > -1e-15);
        let s = i(1.0, 1.5).sin(); // increasing stretch
        assert!(s.contains(1f64.sin()) && s.contains(1.5f64.sin()) && s.hi() < 1.0);
        let c = i(-0.1, 0.2).cos();
        assert_eq!(c.hi(), 1.0);
        assert!(c.contains(0.2f64.cos()) && c.lo() > 0.98);
        let c = i(3.0, 3.3).cos();
        assert_eq!(c.lo(), -1.0);
        assert_eq!(i(0.0, 7.0).sin(), i(-1.0, 1.0));
        assert_eq!(i(1e16, 1e16 + 2.0).cos(), i(-1.0, 1.0));
        // an extremum a hair inside an end is not missed
        let s = i(FRAC_PI_2, 2.0).sin();
        assert_eq!(s.hi(), 1.0);
        let s = i(0.0, FRAC_PI_2).sin();
        assert_eq!(s.hi(), 1.0);
        // far from 0, the period is still tracked: sin has a maximum at π/2 + 2·10⁶π
        let m = FRAC_PI_2 + 2e6 * PI;
        assert_eq!(i(m - 1e-3, m + 1e-3).sin().hi(), 1.0);
        assert!(i(f64::INFINITY, f64::INFINITY).sin().is_entire());
    }

    #[test]
    fn tangent_poles_give_entire() {
        assert!(i(1.5, 1.6).tan().is_entire());
        assert!(i(-1.0, 1.0).tan().contains(1f64.tan()));
        assert!(i(-1.0, 1.0).tan().hi() < 1.6);
        assert!(i(0.0, 3.5).tan().is_entire());
    }

    #[test]
    fn inverse_functions() {
        assert!(i(-1.0, 1.0).asin().contains(-FRAC_PI_2));
        assert!(i(-1.0, 1.0 + 1e-15).asin().is_entire());
        assert!(i(0.5, 1.0).acos().is_nonnegative() && i(0.5, 1.0).acos().lo() == 0.0);
        assert!(i(-2.0, 0.5).acos().is_entire());
        assert!(i(0.0, f64::INFINITY).atan().contains(FRAC_PI_2));
    }

    #[test]
    fn atan2_by_quadrants() {
        let a = i(-1.0, 1.0).atan2(i(0.5, 2.0)); // right half plane
        assert!(a.contains((-1f64).atan2(0.5)) && a.contains(1f64.atan2(0.5)));
        assert!(a.hi() < 1.2);
        let a = i(-1.0, -0.5).atan2(i(-2.0, -1.0)); // third quadrant
        assert!(a.is_negative() && a.contains((-1f64).atan2(-1.0)));
        let a = i(-1.0, 1.0).atan2(i(-1.0, 1.0)); // around the origin
        assert!(a.contains(PI) && a.contains(-PI) && a.hi() < 3.2);
        // y ∈ [0, 1] holds −0, and atan2(−0, −1) = −π
        assert!(i(0.0, 1.0).atan2(i(-2.0, -1.0)).contains(-PI));
    }
}
