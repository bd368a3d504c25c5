//! Interval arithmetic: `+ − × ÷`, squares and powers, each result rounded outwards.
//!
//! With `X = [a, b]`, `Y = [c, d]`:
//!
//! - `X + Y = [a + c, b + d]`, `X − Y = [a − d, b − c]`;
//! - `X · Y = [min, max]` of the four products `ac, ad, bc, bd`;
//! - `X / Y = X · [1/d, 1/c]` when `0 ∉ Y`, else ENTIRE;
//! - `X² = [0, max(a², b²)]` when `a < 0 < b` (tighter than `X · X`);
//! - `Xⁿ` by monotonicity on each side of 0.
//!
//! Each end is computed in round-to-nearest and then moved one float outwards, which holds
//! both the exact result and the rounded one. A NaN end (`0·∞`, `∞ − ∞`, `∞/∞`) gives ENTIRE.

use std::ops::{Add, Div, Mul, Neg, Sub};

use super::bounds::{Interval, LIB_ULPS, POWI_ULPS};

impl Add for Interval {
    type Output = Interval;

    #[inline]
    fn add(self, o: Interval) -> Interval {
        Interval::outward(self.lo() + o.lo(), self.hi() + o.hi())
    }
}

impl Sub for Interval {
    type Output = Interval;

    #[inline]
    fn sub(self, o: Interval) -> Interval {
        Interval::outward(self.lo() - o.hi(), self.hi() - o.lo())
    }
}

impl Neg for Interval {
    type Output = Interval;

    /// Exact: `[−hi, −lo]`.
    #[inline]
    fn neg(self) -> Interval {
        Interval::raw(-self.hi(), -self.lo())
    }
}

/// The hull of four values, NaN if any is NaN.
#[inline]
fn hull4(p: [f64; 4]) -> (f64, f64) {
    if p.iter().any(|x| x.is_nan()) {
        return (f64::NAN, f64::NAN);
    }
    let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    (lo, hi)
}

/// The hull of `f` at the four corners of `x × y`, widened by `ulps`.
#[inline]
pub(super) fn corners(
    x: Interval,
    y: Interval,
    f: impl Fn(f64, f64) -> f64,
    ulps: u32,
) -> Interval {
    let (lo, hi) = hull4([
        f(x.lo(), y.lo()),
        f(x.lo(), y.hi()),
        f(x.hi(), y.lo()),
        f(x.hi(), y.hi()),
    ]);
    Interval::widened(lo, hi, ulps)
}

impl Mul for Interval {
    type Output = Interval;

    #[inline]
    fn mul(self, o: Interval) -> Interval {
        if self.is_entire() || o.is_entire() {
            return Interval::ENTIRE;
        }
        corners(self, o, |a, b| a * b, 1)
    }
}

impl Div for Interval {
    type Output = Interval;

    /// ENTIRE when the divisor contains 0.
    #[inline]
    fn div(self, o: Interval) -> Interval {
        if self.is_entire() || o.contains_zero() {
            return Interval::ENTIRE;
        }
        corners(self, o, |a, b| a / b, 1)
    }
}

impl Interval {
    /// `x²`, tight: `[0, max(lo², hi²)]` when the interval straddles 0.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let s = Interval::new(-1.0, 2.0).sqr();
    /// assert_eq!(s.lo(), 0.0);
    /// assert!(s.contains(4.0) && s.hi() < 4.0 + 1e-14);
    /// ```
    #[must_use]
    #[inline]
    pub fn sqr(self) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        let (a, b) = (self.lo() * self.lo(), self.hi() * self.hi());
        let (lo, hi) = if self.lo() >= 0.0 {
            (a, b)
        } else if self.hi() <= 0.0 {
            (b, a)
        } else {
            (0.0, a.max(b))
        };
        let w = Interval::outward(lo, hi);
        Interval::raw(w.lo().max(0.0), w.hi())
    }

    /// `xⁿ` as `f64::powi` computes it: tight for even powers (`[0, …]` across 0), ENTIRE for
    /// a negative power of an interval containing 0.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let x = Interval::new(-2.0, 1.0);
    /// assert!(x.powi(4).lo() == 0.0 && x.powi(4).contains(16.0));
    /// assert!(x.powi(3).contains(-8.0) && x.powi(3).contains(1.0));
    /// assert!(x.powi(-2).is_entire());
    /// ```
    #[must_use]
    pub fn powi(self, n: i32) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        if n == 0 {
            return Interval::ONE;
        }
        let (a, b) = (self.lo().powi(n), self.hi().powi(n));
        let straddles = self.lo() < 0.0 && self.hi() > 0.0;
        if n < 0 && self.contains_zero() {
            Interval::ENTIRE
        } else if n % 2 == 0 && straddles {
            Interval::widened(0.0, a.max(b), POWI_ULPS).clamp_nonnegative()
        } else if n % 2 == 0 {
            Interval::widened_hull(a, b, POWI_ULPS).clamp_nonnegative()
        } else {
            // odd powers are increasing on the whole line, negative odd on each side of 0
            Interval::widened_hull(a, b, POWI_ULPS)
        }
    }

    /// `x^y` as [`crate::ast::pow`] computes it: `powi` for a point exponent that is an
    /// integer of magnitude at most 64, else `powf`, which is real only for `x >= 0` (ENTIRE
    /// where the base may be negative, or 0 under an exponent that may be `<= 0`).
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let x = Interval::new(1.0, 4.0);
    /// let p = x.pow(Interval::point(1.5));
    /// assert!(p.contains(1.0) && p.contains(8.0) && p.hi() < 8.0 + 1e-12);
    /// assert!(Interval::new(-1.0, 4.0).pow(Interval::point(1.5)).is_entire());
    /// ```
    #[must_use]
    pub fn pow(self, y: Interval) -> Interval {
        if self.is_entire() || y.is_entire() {
            return Interval::ENTIRE;
        }
        if y.is_point() && y.lo().fract() == 0.0 && y.lo().abs() <= 64.0 {
            return self.powi(y.lo() as i32);
        }
        if self.lo() > 0.0 || (self.lo() >= 0.0 && y.lo() > 0.0) {
            // x^y = exp(y ln x) is monotone in x for fixed y and in y for fixed x, so its
            // extremes over the box are at corners (the critical value 1 at x = 1, y = 0 lies
            // between corners too). Integers inside `y` are computed by powi: its error too.
            corners(self, y, f64::powf, POWI_ULPS.max(LIB_ULPS)).clamp_nonnegative()
        } else {
            Interval::ENTIRE
        }
    }

    /// The interval with its lower end raised to 0 where widening took it below (for
    /// functions whose computed and exact values are never negative).
    pub(super) fn clamp_nonnegative(self) -> Interval {
        if self.is_entire() {
            self
        } else {
            Interval::raw(self.lo().max(0.0), self.hi())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn i(lo: f64, hi: f64) -> Interval {
        Interval::new(lo, hi)
    }

    #[test]
    fn sums_are_rounded_outwards() {
        let s = Interval::point(0.1) + Interval::point(0.2);
        let computed = 0.1 + 0.2; // 0.30000000000000004, above the exact 0.3000…0166
        assert!(s.lo() < computed && computed < s.hi());
        assert!(s.lo() <= 0.3 && s.width() > 0.0);
        let d = Interval::point(1.0) - Interval::point(1e-20);
        assert!(d.lo() < 1.0 && d.contains(1.0));
    }

    #[test]
    fn products_and_quotients_over_signs() {
        let p = i(-1.0, 2.0) * i(-3.0, 4.0);
        assert!(p.contains(-6.0) && p.contains(8.0));
        assert!(p.lo() > -6.0 - 1e-14 && p.hi() < 8.0 + 1e-14);
        let q = i(1.0, 2.0) / i(-4.0, -2.0);
        assert!(q.contains(-1.0) && q.contains(-0.25) && q.is_negative());
        assert!((i(1.0, 2.0) / i(-1.0, 1.0)).is_entire());
        assert!((i(1.0, 2.0) / i(0.0, 1.0)).is_entire());
        assert_eq!(-i(1.0, 2.0), i(-2.0, -1.0));
    }

    #[test]
    fn nan_producing_ends_give_entire() {
        let unbounded = i(0.0, f64::INFINITY);
        assert!((unbounded - unbounded).is_entire()); // ∞ − ∞
        assert!((unbounded * Interval::ZERO).is_entire()); // 0·∞
        assert!((unbounded / i(1.0, f64::INFINITY)).is_entire()); // ∞/∞
        assert!((Interval::ENTIRE * Interval::ZERO).is_entire());
        assert!(Interval::ENTIRE.sqr().is_entire());
        assert!(Interval::ENTIRE.powi(2).is_entire());
        assert!(
            Interval::point(f64::NAN)
                .pow(Interval::point(0.5))
                .is_entire()
        );
    }

    #[test]
    fn squares_are_tight() {
        let s = i(-1.0, 2.0).sqr();
        assert_eq!(s.lo(), 0.0);
        assert!(s.hi() >= 4.0 && s.hi() <= 4.0 + 1e-15);
        let s = i(-3.0, -2.0).sqr();
        assert!(s.contains(4.0) && s.contains(9.0) && s.lo() > 3.99);
        assert!(i(1e-200, 1e-200).sqr().is_nonnegative());
    }

    #[test]
    fn powers() {
        let x = i(-2.0, 1.0);
        assert_eq!(x.powi(0), Interval::ONE);
        assert!(x.powi(2).lo() == 0.0 && x.powi(2).contains(4.0));
        assert!(x.powi(5).contains(-32.0) && x.powi(5).contains(1.0));
        let y = i(0.5, 2.0);
        assert!(y.powi(-3).contains(8.0) && y.powi(-3).contains(0.125));
        assert!(i(-2.0, -0.5).powi(-2).contains(4.0) && i(-2.0, -0.5).powi(-2).contains(0.25));
        assert!(i(-2.0, -0.5).powi(-3).is_negative());
        // pow dispatches like ast::pow
        assert_eq!(x.pow(Interval::point(3.0)), x.powi(3));
        let r = y.pow(i(-1.0, 0.5));
        for (a, b) in [(0.5, -1.0), (2.0, -1.0), (0.5, 0.5), (2.0, 0.5), (1.0, 0.0)] {
            assert!(r.contains(f64::powf(a, b)), "{a}^{b} in {r}");
        }
        assert!(i(0.0, 1.0).pow(Interval::point(0.5)).contains(0.0));
        assert!(i(0.0, 1.0).pow(Interval::point(-0.5)).is_entire());
        assert!(i(-1.0, 1.0).pow(i(2.0, 3.0)).is_entire());
    }
}
