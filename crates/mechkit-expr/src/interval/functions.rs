//! The built-in functions ([`Func`]) over intervals: exponentials, logarithms, roots,
//! hyperbolic functions, `abs` and the steps (the trigonometric ones are in `trig.rs`), and
//! the dispatch by [`Func`].
//!
//! A monotone function maps `[a, b]` to `[f(a), f(b)]` (increasing) or `[f(b), f(a)]`; the ends
//! come from the maths library, which is not correctly rounded, so they are widened by
//! [`LIB_ULPS`] floats. `cosh` and `abs` are smallest at 0; the steps `sign`, `heaviside`,
//! `floor`, `ceil` are non-decreasing and exact.
//!
//! Outside a function's domain (`sqrt`, `ln` of negatives), where the point function gives
//! NaN, the result is ENTIRE, the unknown value.

use super::bounds::{Interval, LIB_ULPS};
use crate::ast::{self, Func};

/// `f` monotone on `x` (either way): `f` at the ends, ordered and widened. (Ordering them
/// here, not by the direction, keeps the ends in order where the library's rounding makes `f`
/// step backwards between two neighbouring floats.)
pub(super) fn monotone(x: Interval, f: fn(f64) -> f64) -> Interval {
    Interval::widened_hull(f(x.lo()), f(x.hi()), LIB_ULPS)
}

/// A step function, non-decreasing and exact: `[f(lo), f(hi)]`.
fn steps(x: Interval, f: fn(f64) -> f64) -> Interval {
    if x.is_entire() {
        return Interval::ENTIRE;
    }
    Interval::new(f(x.lo()), f(x.hi()))
}

impl Interval {
    /// `eˣ`.
    #[must_use]
    pub fn exp(self) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        monotone(self, f64::exp).clamp_nonnegative()
    }

    /// `ln x`; ENTIRE unless `x >= 0` (`ln 0 = −∞`).
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// assert!(Interval::new(1.0, 2.0).ln().contains(std::f64::consts::LN_2));
    /// assert!(Interval::new(-1.0, 2.0).ln().is_entire());
    /// ```
    #[must_use]
    pub fn ln(self) -> Interval {
        if self.lo() >= 0.0 {
            monotone(self, f64::ln)
        } else {
            Interval::ENTIRE
        }
    }

    /// `log₁₀ x`; ENTIRE unless `x >= 0`.
    #[must_use]
    pub fn log10(self) -> Interval {
        if self.lo() >= 0.0 {
            monotone(self, f64::log10)
        } else {
            Interval::ENTIRE
        }
    }

    /// `√x`; ENTIRE unless `x >= 0` (`−0` counts as 0).
    #[must_use]
    pub fn sqrt(self) -> Interval {
        if self.lo() >= 0.0 {
            // correctly rounded: one float each side
            Interval::outward(self.lo().sqrt(), self.hi().sqrt()).clamp_nonnegative()
        } else {
            Interval::ENTIRE
        }
    }

    /// `∛x`.
    #[must_use]
    pub fn cbrt(self) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        monotone(self, f64::cbrt)
    }

    /// `sinh x`.
    #[must_use]
    pub fn sinh(self) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        monotone(self, f64::sinh)
    }

    /// `cosh x`, smallest (1) at 0.
    #[must_use]
    pub fn cosh(self) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        if self.lo() >= 0.0 || self.hi() <= 0.0 {
            monotone(self, f64::cosh)
        } else {
            let top = self.lo().cosh().max(self.hi().cosh());
            Interval::widened(1.0, top, LIB_ULPS)
        }
    }

    /// `tanh x`.
    #[must_use]
    pub fn tanh(self) -> Interval {
        if self.is_entire() {
            return Interval::ENTIRE;
        }
        let t = monotone(self, f64::tanh);
        Interval::raw(t.lo().max(-1.0), t.hi().min(1.0))
    }

    /// `|x|`, exact: `[0, max(−lo, hi)]` across 0.
    #[must_use]
    pub fn abs(self) -> Interval {
        if self.is_entire() {
            Interval::ENTIRE
        } else if self.lo() >= 0.0 {
            Interval::raw(self.lo().abs(), self.hi())
        } else if self.hi() <= 0.0 {
            -self
        } else {
            Interval::raw(0.0, self.hi().max(-self.lo()))
        }
    }

    /// `sign x` ([`ast::sign`]): −1, 0 or 1, exact.
    #[must_use]
    pub fn sign(self) -> Interval {
        steps(self, ast::sign)
    }

    /// `heaviside x` ([`ast::heaviside`]): 0, ½ or 1, exact.
    #[must_use]
    pub fn heaviside(self) -> Interval {
        steps(self, ast::heaviside)
    }

    /// `⌊x⌋`, exact.
    #[must_use]
    pub fn floor(self) -> Interval {
        steps(self, f64::floor)
    }

    /// `⌈x⌉`, exact.
    #[must_use]
    pub fn ceil(self) -> Interval {
        steps(self, f64::ceil)
    }

    /// `f(x)` for a one-argument built-in, as [`Func::apply1`] computes it pointwise.
    ///
    /// # Panics
    /// For `atan2`, `min`, `max` and `if`.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::{Func, Interval};
    /// let x = Interval::new(0.0, 1.0);
    /// assert_eq!(x.apply1(Func::Exp), x.exp());
    /// ```
    #[must_use]
    pub fn apply1(self, f: Func) -> Interval {
        match f {
            Func::Sin => self.sin(),
            Func::Cos => self.cos(),
            Func::Tan => self.tan(),
            Func::Asin => self.asin(),
            Func::Acos => self.acos(),
            Func::Atan => self.atan(),
            Func::Sinh => self.sinh(),
            Func::Cosh => self.cosh(),
            Func::Tanh => self.tanh(),
            Func::Exp => self.exp(),
            Func::Log | Func::Ln => self.ln(),
            Func::Log10 => self.log10(),
            Func::Sqrt => self.sqrt(),
            Func::Cbrt => self.cbrt(),
            Func::Abs => self.abs(),
            Func::Sign => self.sign(),
            Func::Floor => self.floor(),
            Func::Ceil => self.ceil(),
            Func::Heaviside => self.heaviside(),
            Func::Atan2 | Func::Min | Func::Max | Func::If => {
                panic!("{} does not take one argument", f.name())
            }
        }
    }

    /// `f(self, b)` for `atan2`, `min` and `max`, as [`Func::apply2`] computes it.
    ///
    /// # Panics
    /// For the other functions.
    #[must_use]
    pub fn apply2(self, f: Func, b: Interval) -> Interval {
        match f {
            Func::Atan2 => self.atan2(b),
            Func::Min => self.min(b),
            Func::Max => self.max(b),
            _ => panic!("{} does not take two arguments", f.name()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn i(lo: f64, hi: f64) -> Interval {
        Interval::new(lo, hi)
    }

    #[test]
    fn domains() {
        assert!(i(-1.0, 1.0).sqrt().is_entire());
        assert_eq!(i(-0.0, 4.0).sqrt().lo(), 0.0);
        assert!(i(0.0, 4.0).sqrt().contains(2.0));
        assert!(i(0.0, 1.0).ln().contains(f64::NEG_INFINITY));
        assert!(i(-1e-300, 1.0).ln().is_entire());
        assert!(i(-1e-300, 1.0).log10().is_entire());
        for f in Func::ALL.iter().filter(|f| f.arity().accepts(1)) {
            if *f != Func::If {
                assert!(Interval::ENTIRE.apply1(*f).is_entire(), "{}", f.name());
            }
        }
    }

    #[test]
    fn steps_and_absolute_value_are_exact() {
        assert_eq!(i(-2.0, 3.0).abs(), i(0.0, 3.0));
        assert_eq!(i(-2.0, -1.0).abs(), i(1.0, 2.0));
        assert_eq!(i(-2.0, 3.0).sign(), i(-1.0, 1.0));
        assert_eq!(i(0.0, 3.0).heaviside(), i(0.5, 1.0));
        assert_eq!(i(-0.5, 2.5).floor(), i(-1.0, 2.0));
        assert_eq!(i(-0.5, 2.5).ceil(), i(-0.0, 3.0));
        assert_eq!(i(0.2, 0.7).floor(), Interval::ZERO);
    }

    #[test]
    fn hyperbolic() {
        let c = i(-1.0, 2.0).cosh();
        assert!(c.contains(1.0) && c.contains(2f64.cosh()) && c.lo() > 0.99);
        assert!(i(-30.0, 30.0).tanh().hi() <= 1.0);
    }

    /// Every one-argument function at random points of random intervals.
    fn unary() -> Vec<Func> {
        Func::ALL
            .iter()
            .copied()
            .filter(|f| f.arity() == ast::Arity::Exactly(1))
            .collect()
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        #[test]
        fn point_values_lie_in_the_enclosure(
            k in 0usize..19, c in -8.0f64..8.0, e in -14i32..2, u in 0.0f64..1.0,
            t in 0.0f64..=1.0, big in prop::sample::select(vec![0, 0, 0, 0, 0, 0, 6, 12]),
        ) {
            let f = unary()[k];
            let scale = 10f64.powi(big);
            let lo = c * scale;
            let hi = lo + u * 10f64.powi(e) * scale;
            let x = (lo + (hi - lo) * t).clamp(lo, hi);
            let r = Interval::new(lo, hi).apply1(f);
            let y = f.apply1(x);
            prop_assert!(r.contains(y), "{}({x}) = {y} not in {r} from [{lo}, {hi}]", f.name());
        }

        #[test]
        fn atan2_min_max_hold_their_points(
            a in -3.0f64..3.0, b in -3.0f64..3.0, wa in 0.0f64..2.0, wb in 0.0f64..2.0,
            s in 0.0f64..=1.0, t in 0.0f64..=1.0, k in 0usize..3,
        ) {
            let f = [Func::Atan2, Func::Min, Func::Max][k];
            let (y, x) = (Interval::new(a, a + wa), Interval::new(b, b + wb));
            let (py, px) = ((a + wa * s).min(a + wa), (b + wb * t).min(b + wb));
            let r = y.apply2(f, x);
            prop_assert!(r.contains(f.apply2(py, px)), "{} {r}", f.name());
        }
    }
}
