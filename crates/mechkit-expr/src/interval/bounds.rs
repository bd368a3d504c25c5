//! [`Interval`]: the type, its constructors and the questions a proof asks of it, and the
//! outward rounding every operation ends with.

use std::fmt;

/// A closed interval `[lo, hi]` of `f64` that is a guaranteed enclosure: the result of an
/// operation contains every value the operation can take on its operands' intervals, both the
/// exact real value and the one `f64` arithmetic (and the platform's maths library) computes.
///
/// [`Interval::ENTIRE`], `[−∞, +∞]`, is also the *unknown* value: the only interval that may
/// stand for NaN. Every operation that could meet NaN (`0·∞`, `∞ − ∞`, `sqrt` of a negative,
/// `sin(∞)`, a NaN constant) returns it, and every operation on it returns it again (or, for
/// comparisons and logic, the undecided `[0, 1]`), so no proof can rest on a NaN: ENTIRE is
/// neither [positive](Interval::is_positive) nor [negative](Interval::is_negative), and it
/// [contains zero](Interval::contains_zero).
///
/// The fields are private so that an interval is always valid: `lo <= hi`, no NaN.
///
/// # Example
/// ```
/// use mechkit_expr::Interval;
/// let x = Interval::new(1.0, 2.0);
/// let y = x * x - Interval::point(0.5);
/// assert!(y.is_positive()); // x² − 0.5 > 0 for every x in [1, 2]
/// assert!(y.contains(0.5) && y.contains(3.5));
/// assert!(!Interval::point(f64::NAN).is_positive());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    lo: f64,
    hi: f64,
}

/// Maximum error, in ulps, that the enclosures allow the maths library (`sin`, `exp`, `ln`,
/// `atan2`, `cosh`…): glibc, musl and Apple's libm stay within 2. An enclosure from two
/// computed end values is widened by twice that, so that it holds both the exact values and
/// those computed at points between the ends.
pub(super) const LIB_ULPS: u32 = 4;

/// The same for `powi`, repeated multiplication (up to 14 roundings for `|n| <= 64`).
pub(super) const POWI_ULPS: u32 = 20;

/// `x` moved `n` floats towards −∞ (−∞ stays; NaN stays NaN).
#[inline]
pub(super) fn down(x: f64, n: u32) -> f64 {
    (0..n).fold(x, |x, _| x.next_down())
}

/// `x` moved `n` floats towards +∞.
#[inline]
pub(super) fn up(x: f64, n: u32) -> f64 {
    (0..n).fold(x, |x, _| x.next_up())
}

impl Interval {
    /// `[−∞, +∞]`: any value, or unknown (NaN possible). Proves nothing.
    pub const ENTIRE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// `[0, 1]`: a comparison or a logical operation that is not decided over the box.
    pub const UNDECIDED: Interval = Interval { lo: 0.0, hi: 1.0 };

    /// `[0, 0]`.
    pub const ZERO: Interval = Interval { lo: 0.0, hi: 0.0 };

    /// `[1, 1]`.
    pub const ONE: Interval = Interval { lo: 1.0, hi: 1.0 };

    /// `[lo, hi]`. Either end NaN gives [`Interval::ENTIRE`] (unknown).
    ///
    /// # Panics
    /// When `lo > hi`.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let x = Interval::new(-1.0, 2.0);
    /// assert_eq!((x.lo(), x.hi()), (-1.0, 2.0));
    /// assert_eq!(Interval::new(f64::NAN, 1.0), Interval::ENTIRE);
    /// ```
    #[inline]
    pub fn new(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            return Interval::ENTIRE;
        }
        assert!(lo <= hi, "interval [{lo}, {hi}] has lo > hi");
        Interval { lo, hi }
    }

    /// The single value `x` (NaN gives [`Interval::ENTIRE`]).
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// assert!(Interval::point(0.3).is_point());
    /// ```
    #[inline]
    pub fn point(x: f64) -> Interval {
        Interval::new(x, x)
    }

    /// `[lo, hi]` widened by one float at each end: the enclosure of a correctly rounded
    /// operation whose round-to-nearest results at the extreme operands are `lo` and `hi`.
    /// NaN gives ENTIRE.
    #[inline]
    pub(super) fn outward(lo: f64, hi: f64) -> Interval {
        Interval::widened(lo, hi, 1)
    }

    /// `[lo, hi]` widened by `ulps` floats at each end; NaN gives ENTIRE.
    #[inline]
    pub(super) fn widened(lo: f64, hi: f64, ulps: u32) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            return Interval::ENTIRE;
        }
        debug_assert!(lo <= hi, "[{lo}, {hi}]");
        Interval {
            lo: down(lo, ulps),
            hi: up(hi, ulps),
        }
    }

    /// The hull of `a` and `b` widened by `ulps` floats at each end; NaN gives ENTIRE.
    #[inline]
    pub(super) fn widened_hull(a: f64, b: f64, ulps: u32) -> Interval {
        if a.is_nan() || b.is_nan() {
            return Interval::ENTIRE;
        }
        Interval::widened(a.min(b), a.max(b), ulps)
    }

    /// `[lo, hi]` without checks, for ends known to be ordered and not NaN.
    pub(super) const fn raw(lo: f64, hi: f64) -> Interval {
        Interval { lo, hi }
    }

    /// The lower end.
    #[inline]
    pub fn lo(self) -> f64 {
        self.lo
    }

    /// The upper end.
    #[inline]
    pub fn hi(self) -> f64 {
        self.hi
    }

    /// Whether this is [`Interval::ENTIRE`], the unknown value.
    #[inline]
    pub fn is_entire(self) -> bool {
        self.lo == f64::NEG_INFINITY && self.hi == f64::INFINITY
    }

    /// Whether the interval holds one value.
    #[inline]
    pub fn is_point(self) -> bool {
        self.lo == self.hi
    }

    /// Whether `x` lies in the interval. NaN lies only in ENTIRE.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// assert!(Interval::new(0.0, 1.0).contains(1.0));
    /// assert!(!Interval::new(0.0, 1.0).contains(f64::NAN));
    /// assert!(Interval::ENTIRE.contains(f64::NAN));
    /// ```
    #[inline]
    pub fn contains(self, x: f64) -> bool {
        if x.is_nan() {
            self.is_entire()
        } else {
            self.lo <= x && x <= self.hi
        }
    }

    /// Whether 0 lies in the interval (always true of ENTIRE).
    #[inline]
    pub fn contains_zero(self) -> bool {
        self.lo <= 0.0 && 0.0 <= self.hi
    }

    /// Proven positive: every value is `> 0` (`lo > 0`).
    #[inline]
    pub fn is_positive(self) -> bool {
        self.lo > 0.0
    }

    /// Proven negative: every value is `< 0` (`hi < 0`).
    #[inline]
    pub fn is_negative(self) -> bool {
        self.hi < 0.0
    }

    /// Proven non-negative: every value is `>= 0`.
    #[inline]
    pub fn is_nonnegative(self) -> bool {
        self.lo >= 0.0
    }

    /// Proven non-positive: every value is `<= 0`.
    #[inline]
    pub fn is_nonpositive(self) -> bool {
        self.hi <= 0.0
    }

    /// `hi − lo`, rounded up (+∞ for an unbounded interval).
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// assert!(Interval::new(0.1, 0.3).width() >= 0.2);
    /// ```
    #[inline]
    pub fn width(self) -> f64 {
        if self.is_point() {
            0.0
        } else {
            (self.hi - self.lo).next_up()
        }
    }

    /// A point of the interval near its middle: 0 for ENTIRE, the finite end's nearest
    /// `f64::MIN`/`MAX` side for a half-unbounded one.
    #[inline]
    pub fn mid(self) -> f64 {
        match (self.lo.is_finite(), self.hi.is_finite()) {
            (true, true) => (0.5 * self.lo + 0.5 * self.hi).clamp(self.lo, self.hi),
            (false, false) if self.lo < self.hi => 0.0,
            (false, true) if self.lo < self.hi => f64::MIN.min(self.hi),
            (true, false) => f64::MAX.max(self.lo),
            _ => self.lo, // a point at ±∞
        }
    }

    /// The smallest interval holding both.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Interval;
    /// let h = Interval::point(-1.0).hull(Interval::new(2.0, 3.0));
    /// assert_eq!(h, Interval::new(-1.0, 3.0));
    /// ```
    #[must_use]
    #[inline]
    pub fn hull(self, other: Interval) -> Interval {
        Interval {
            lo: self.lo.min(other.lo),
            hi: self.hi.max(other.hi),
        }
    }
}

impl From<f64> for Interval {
    /// [`Interval::point`].
    fn from(x: f64) -> Interval {
        Interval::point(x)
    }
}

impl fmt::Display for Interval {
    /// `[lo, hi]`, each end in shortest round-trip digits, in exponent form outside
    /// `1e-4 ≤ |x| < 1e16` ([`crate::short_number`]).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "[{}, {}]",
            crate::short_number(self.lo),
            crate::short_number(self.hi)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nan_is_entire_and_proves_nothing() {
        for i in [
            Interval::point(f64::NAN),
            Interval::new(f64::NAN, 1.0),
            Interval::new(0.0, f64::NAN),
        ] {
            assert!(i.is_entire());
            assert!(!i.is_positive() && !i.is_negative());
            assert!(!i.is_nonnegative() && !i.is_nonpositive());
            assert!(i.contains_zero() && i.contains(f64::NAN));
        }
        assert_eq!(Interval::widened(f64::NAN, 1.0, 3), Interval::ENTIRE);
    }

    #[test]
    #[should_panic(expected = "lo > hi")]
    fn reversed_ends_panic() {
        let _ = Interval::new(2.0, 1.0);
    }

    #[test]
    fn queries() {
        let x = Interval::new(-1.0, 3.0);
        assert!(x.contains_zero() && x.contains(3.0) && !x.contains(3.5));
        assert!(!x.is_point() && Interval::point(2.0).is_point());
        assert_eq!(x.mid(), 1.0);
        assert!(x.width() >= 4.0 && x.width() <= 4.0 + 1e-15);
        assert_eq!(Interval::point(5e-324).mid(), 5e-324);
        assert_eq!(Interval::ENTIRE.mid(), 0.0);
        assert_eq!(Interval::new(1.0, f64::INFINITY).mid(), f64::MAX);
        assert_eq!(Interval::new(f64::NEG_INFINITY, 1.0).mid(), f64::MIN);
        assert_eq!(Interval::ENTIRE.width(), f64::INFINITY);
        assert!(Interval::new(1e-300, 1.0).is_positive());
        assert!(Interval::new(-2.0, -1e-300).is_negative());
        assert!(Interval::new(0.0, 1.0).is_nonnegative());
        assert!(!Interval::new(0.0, 1.0).is_positive());
        assert!(Interval::new(-0.0, 1.0).contains_zero());
        assert_eq!(Interval::from(2.5), Interval::point(2.5));
        assert_eq!(x.to_string(), "[-1, 3]");
    }

    #[test]
    fn widening_moves_by_whole_floats() {
        let w = Interval::widened(1.0, 1.0, 2);
        assert_eq!(w.lo(), 1.0 - 2.0 * f64::EPSILON / 2.0);
        assert_eq!(w.hi(), 1.0 + 2.0 * f64::EPSILON);
        assert_eq!(Interval::outward(0.0, 0.0).hi(), 5e-324);
        let inf = Interval::outward(f64::INFINITY, f64::INFINITY);
        assert_eq!((inf.lo(), inf.hi()), (f64::MAX, f64::INFINITY));
        assert_eq!(down(f64::NEG_INFINITY, 3), f64::NEG_INFINITY);
    }
}
