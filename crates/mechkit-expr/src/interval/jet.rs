//! [`Jet`]: an enclosure of a function's value and of its derivative over an interval of its
//! parameter (forward-mode differentiation in interval arithmetic), and its arithmetic.
//!
//! For `u(t), w(t)` on `T` with jets `(U, U′)`, `(W, W′)`:
//!
//! - `(u ± w)′ = u′ ± w′`, `(u·w)′ = u′w + uw′`, `(u/w)′ = (u′ − (u/w)·w′)/w`;
//! - `(u²)′ = 2uu′`, `(uⁿ)′ = n·uⁿ⁻¹·u′`, `(u^w)′ = u^w·(w′ ln u + w·u′/u)`.
//!
//! Each rule evaluates the textbook formula in interval arithmetic, which encloses the
//! derivative at every `t ∈ T` because every quantity in it is enclosed.

use std::ops::{Add, Div, Mul, Neg, Sub};

use super::bounds::Interval;

/// The value `v` and the derivative `d` of a function `f(t)` over an interval `T` of one
/// parameter (time, say): `f(t) ∈ v` and `f′(t) ∈ d` for every `t ∈ T`.
///
/// The derivative bound is valid for `f` as an absolutely continuous function on `T`: where `f`
/// has kinks (`abs`, `min`, `max` deciding nothing), `d` holds the one-sided derivatives, so
/// `f(t₂) − f(t₁) ∈ d·(t₂ − t₁)` still holds; where `f` may *jump* inside `T` (`sign`,
/// `floor`, a comparison or an `if` that changes over `T`), `d` is ENTIRE; where such a
/// function is constant over `T`, `d` is `[0, 0]`.
///
/// So: `v.is_positive()` proves `f > 0` on `T`, and `d.is_positive()` (with a known `v`)
/// proves `f` strictly increasing; [`Jet::is_increasing`] checks both. A jet whose value is
/// ENTIRE (unknown) always has an ENTIRE derivative.
///
/// # Example
/// ```
/// use mechkit_expr::{Interval, Jet};
/// let t = Jet::variable(Interval::new(1.0, 2.0)); // t itself: t′ = 1
/// let g = t * t - Jet::constant(0.5);             // g = t² − 0.5, g′ = 2t
/// assert!(g.v.is_positive());                     // no root on [1, 2]
/// assert!(g.is_increasing());
/// assert!(g.d.contains(2.0) && g.d.contains(4.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet {
    /// Enclosure of the values over the interval.
    pub v: Interval,
    /// Enclosure of the derivatives over the interval (ENTIRE where the function may jump).
    pub d: Interval,
}

impl Jet {
    /// ENTIRE value and derivative: unknown.
    pub const ENTIRE: Jet = Jet {
        v: Interval::ENTIRE,
        d: Interval::ENTIRE,
    };

    /// A jet; the derivative becomes ENTIRE when the value is (unknown).
    #[inline]
    pub fn new(v: Interval, d: Interval) -> Jet {
        if v.is_entire() {
            Jet::ENTIRE
        } else {
            Jet { v, d }
        }
    }

    /// The constant `c`: derivative `[0, 0]`.
    #[inline]
    pub fn constant(c: f64) -> Jet {
        Jet::new(Interval::point(c), Interval::ZERO)
    }

    /// The parameter itself over `t`: derivative `[1, 1]`.
    #[inline]
    pub fn variable(t: Interval) -> Jet {
        Jet::new(t, Interval::ONE)
    }

    /// The jet of a piecewise-constant function with values `v` (a step, a comparison):
    /// derivative 0 if `v` is one value (the function is constant over the interval), else
    /// ENTIRE (it may jump).
    #[inline]
    pub fn step(v: Interval) -> Jet {
        Jet::new(
            v,
            if v.is_point() {
                Interval::ZERO
            } else {
                Interval::ENTIRE
            },
        )
    }

    /// Proven strictly increasing over the interval: a known value and `d > 0`.
    #[inline]
    pub fn is_increasing(self) -> bool {
        !self.v.is_entire() && self.d.is_positive()
    }

    /// Proven strictly decreasing over the interval: a known value and `d < 0`.
    #[inline]
    pub fn is_decreasing(self) -> bool {
        !self.v.is_entire() && self.d.is_negative()
    }

    /// `u²`: `(u², 2uu′)`.
    #[must_use]
    #[inline]
    pub fn sqr(self) -> Jet {
        Jet::new(self.v.sqr(), Interval::point(2.0) * self.v * self.d)
    }

    /// `uⁿ` as `f64::powi` computes it: `(uⁿ, n·uⁿ⁻¹·u′)`.
    #[must_use]
    pub fn powi(self, n: i32) -> Jet {
        if n == 0 {
            return if self.v.is_entire() {
                Jet::ENTIRE
            } else {
                Jet::constant(1.0)
            };
        }
        let d = Interval::point(f64::from(n)) * self.v.powi(n - 1) * self.d;
        Jet::new(self.v.powi(n), d)
    }

    /// `u^w` as [`crate::ast::pow`] computes it. With a constant exponent the derivative is
    /// `w·u^(w−1)·u′`; otherwise `u^w·(w′ ln u + w·u′/u)` where `u > 0`, else ENTIRE.
    #[must_use]
    pub fn pow(self, w: Jet) -> Jet {
        let v = self.v.pow(w.v);
        let constant_exponent = w.d.is_false();
        let d = if constant_exponent && w.v.is_point() && w.v.lo().fract() == 0.0 {
            return self.powi_f64(w.v.lo(), v);
        } else if constant_exponent {
            w.v * self.v.pow(w.v - Interval::ONE) * self.d
        } else if self.v.is_positive() {
            v * (w.d * self.v.ln() + w.v * self.d / self.v)
        } else {
            Interval::ENTIRE
        };
        Jet::new(v, d)
    }

    /// `u^n` for an integer `n` held as `f64` (its value `v` already computed).
    fn powi_f64(self, n: f64, v: Interval) -> Jet {
        if n.abs() <= 64.0 {
            self.powi(n as i32)
        } else {
            let n = Interval::point(n);
            Jet::new(v, n * self.v.pow(n - Interval::ONE) * self.d)
        }
    }
}

impl Add for Jet {
    type Output = Jet;

    #[inline]
    fn add(self, o: Jet) -> Jet {
        Jet::new(self.v + o.v, self.d + o.d)
    }
}

impl Sub for Jet {
    type Output = Jet;

    #[inline]
    fn sub(self, o: Jet) -> Jet {
        Jet::new(self.v - o.v, self.d - o.d)
    }
}

impl Neg for Jet {
    type Output = Jet;

    #[inline]
    fn neg(self) -> Jet {
        Jet::new(-self.v, -self.d)
    }
}

impl Mul for Jet {
    type Output = Jet;

    #[inline]
    fn mul(self, o: Jet) -> Jet {
        Jet::new(self.v * o.v, self.d * o.v + self.v * o.d)
    }
}

impl Div for Jet {
    type Output = Jet;

    /// ENTIRE when the divisor may be 0.
    #[inline]
    fn div(self, o: Jet) -> Jet {
        let q = self.v / o.v;
        Jet::new(q, (self.d - q * o.d) / o.v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn i(lo: f64, hi: f64) -> Interval {
        Interval::new(lo, hi)
    }

    fn t(lo: f64, hi: f64) -> Jet {
        Jet::variable(i(lo, hi))
    }

    #[test]
    fn product_and_quotient_rules() {
        // t³ − t on [2, 3]: derivative 3t² − 1 ∈ [11, 26]
        let x = t(2.0, 3.0);
        let g = x * x * x - x;
        assert!(g.d.contains(11.0) && g.d.contains(26.0) && g.is_increasing());
        // 1/t on [1, 2]: −1/t² ∈ [−1, −1/4]
        let r = Jet::constant(1.0) / t(1.0, 2.0);
        assert!(r.d.contains(-1.0) && r.d.contains(-0.25) && r.is_decreasing());
        assert!((Jet::constant(1.0) / t(-1.0, 1.0)).d.is_entire());
    }

    #[test]
    fn squares_and_powers() {
        let x = t(-1.0, 2.0);
        assert!(x.sqr().d.contains(-2.0) && x.sqr().d.contains(4.0));
        let c = t(1.0, 2.0).powi(3);
        assert!(c.d.contains(3.0) && c.d.contains(12.0));
        assert_eq!(x.powi(0), Jet::constant(1.0));
        assert!(t(-1.0, 1.0).powi(-2).d.is_entire());
        // t^1.5: 1.5 t^0.5
        let p = t(1.0, 4.0).pow(Jet::constant(1.5));
        assert!(p.d.contains(1.5) && p.d.contains(3.0) && p.d.hi() < 3.0 + 1e-9);
        // 2^t: 2^t ln 2
        let e = Jet::constant(2.0).pow(t(0.0, 1.0));
        assert!(e.d.contains(std::f64::consts::LN_2) && e.d.contains(2.0 * std::f64::consts::LN_2));
        // t^t on (0, 1]: the base reaches 0
        assert!(t(0.0, 1.0).pow(t(0.0, 1.0)).d.is_entire());
        assert_eq!(t(0.5, 1.0).pow(Jet::constant(2.0)), t(0.5, 1.0).powi(2));
    }

    #[test]
    fn unknown_values_carry_unknown_derivatives() {
        let j = Jet::new(Interval::ENTIRE, Interval::ONE);
        assert_eq!(j, Jet::ENTIRE);
        assert!(!j.is_increasing() && !j.is_decreasing());
        assert_eq!(Jet::step(i(0.0, 1.0)).d, Interval::ENTIRE);
        assert_eq!(Jet::step(Interval::ONE).d, Interval::ZERO);
        assert_eq!(Jet::constant(f64::NAN), Jet::ENTIRE);
    }
}
