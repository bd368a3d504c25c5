//! Exact rational exponents: `3/2` in `m^(3/2)`, `1/2` in `sqrt(x)`.
//!
//! A [`Ratio`] is a fraction `num/den` in lowest terms with `den ≥ 1`, numerator and
//! denominator inside the `i32` range. Arithmetic is exact and checked: a result that leaves
//! the range is `None`, never a wrapped or saturated number.

use std::fmt;

/// The largest denominator a power written by hand may have (`m^(1/1000)`, `x^0.001`): a
/// decimal such as `0.333333` is not taken for 1/3, and a float such as `pi` is not taken
/// for a fraction.
pub const MAX_WRITTEN_DENOMINATOR: i64 = 1000;

/// An exact fraction in lowest terms, `den ≥ 1`.
///
/// # Example
/// ```
/// use mechkit_expr::units::Ratio;
/// let r = Ratio::new(6, 4).unwrap();
/// assert_eq!((r.num(), r.den()), (3, 2));
/// assert_eq!(r.to_string(), "3/2");
/// assert_eq!(Ratio::parse_decimal("-0.25"), Ratio::new(-1, 4));
/// assert_eq!(Ratio::from_f64(1.0 / 3.0, 1000), Ratio::new(1, 3));
/// assert_eq!(Ratio::from_f64(std::f64::consts::PI, 1000), None);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Ratio {
    num: i32,
    den: i32,
}

impl Default for Ratio {
    fn default() -> Self {
        Ratio::ZERO
    }
}

impl Ratio {
    /// 0.
    pub const ZERO: Ratio = Ratio { num: 0, den: 1 };
    /// 1.
    pub const ONE: Ratio = Ratio { num: 1, den: 1 };

    /// The whole number `n`.
    pub const fn int(n: i32) -> Ratio {
        Ratio { num: n, den: 1 }
    }

    /// `num/den` in lowest terms; `None` if `den` is 0 or the reduced fraction does not fit
    /// in `i32`.
    pub fn new(num: i64, den: i64) -> Option<Ratio> {
        Ratio::reduce(i128::from(num), i128::from(den))
    }

    fn reduce(num: i128, den: i128) -> Option<Ratio> {
        if den == 0 {
            return None;
        }
        let g = gcd(num.unsigned_abs(), den.unsigned_abs()).max(1) as i128;
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            (n, d) = (-n, -d);
        }
        Some(Ratio {
            num: i32::try_from(n).ok()?,
            den: i32::try_from(d).ok()?,
        })
    }

    /// The numerator (carries the sign).
    pub const fn num(self) -> i32 {
        self.num
    }

    /// The denominator, at least 1.
    pub const fn den(self) -> i32 {
        self.den
    }

    /// Whether this is 0.
    pub const fn is_zero(self) -> bool {
        self.num == 0
    }

    /// Whether the denominator is 1.
    pub const fn is_integer(self) -> bool {
        self.den == 1
    }

    /// The nearest float.
    pub fn to_f64(self) -> f64 {
        f64::from(self.num) / f64::from(self.den)
    }

    /// `self + rhs`, or `None` if it leaves the range.
    pub fn checked_add(self, rhs: Ratio) -> Option<Ratio> {
        let (a, b) = (i128::from(self.num), i128::from(self.den));
        let (c, d) = (i128::from(rhs.num), i128::from(rhs.den));
        Ratio::reduce(a * d + c * b, b * d)
    }

    /// `self * rhs`, or `None` if it leaves the range.
    pub fn checked_mul(self, rhs: Ratio) -> Option<Ratio> {
        Ratio::reduce(
            i128::from(self.num) * i128::from(rhs.num),
            i128::from(self.den) * i128::from(rhs.den),
        )
    }

    /// `-self`; `None` only for a numerator of `i32::MIN`.
    pub fn checked_neg(self) -> Option<Ratio> {
        Some(Ratio {
            num: self.num.checked_neg()?,
            den: self.den,
        })
    }

    /// The value of a short decimal written `[+-]digits[.digits]` (`1.5`, `-0.25`, `.5`,
    /// `12`), exactly; `None` if the text is not such a number, has more than 9 decimals, or
    /// does not fit.
    pub fn parse_decimal(text: &str) -> Option<Ratio> {
        let (negative, body) = match text.as_bytes().first()? {
            b'-' => (true, &text[1..]),
            b'+' => (false, &text[1..]),
            _ => (false, text),
        };
        let (whole, frac) = body.split_once('.').unwrap_or((body, ""));
        if whole.is_empty() && frac.is_empty()
            || !whole.bytes().all(|b| b.is_ascii_digit())
            || !frac.bytes().all(|b| b.is_ascii_digit())
            || body.ends_with('.')
            || frac.len() > 9
        {
            return None;
        }
        let digits = format!("{whole}{frac}");
        let digits = digits.trim_start_matches('0');
        if digits.len() > 18 {
            return None;
        }
        let n: i64 = if digits.is_empty() {
            0
        } else {
            digits.parse().ok()?
        };
        let den = 10_i64.pow(frac.len() as u32);
        Ratio::new(if negative { -n } else { n }, den)
    }

    /// The fraction with the smallest denominator up to `max_den` within rounding (a relative
    /// 1e-12) of `x`: `1.5` is 3/2, `0.1` is 1/10, `1.0/3.0` is 1/3; `None` for `pi`, for a
    /// non-finite `x`, or for one outside the `i32` range.
    pub fn from_f64(x: f64, max_den: i64) -> Option<Ratio> {
        if !x.is_finite() || x.abs() > f64::from(i32::MAX) {
            return None;
        }
        let tolerance = 1e-12 * x.abs().max(1.0);
        (1..=max_den.max(1)).find_map(|den| {
            let num = (x * den as f64).round();
            ((x - num / den as f64).abs() <= tolerance)
                .then(|| Ratio::new(num as i64, den))
                .flatten()
        })
    }
}

impl fmt::Display for Ratio {
    /// `3`, `-1`, `3/2`, `-1/2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(n: i64, d: i64) -> Ratio {
        Ratio::new(n, d).unwrap()
    }

    #[test]
    fn lowest_terms_and_sign() {
        assert_eq!(r(6, 4), r(3, 2));
        assert_eq!(r(3, -6), r(-1, 2));
        assert_eq!(r(0, -5), Ratio::ZERO);
        assert_eq!(Ratio::new(1, 0), None);
        assert_eq!(Ratio::new(i64::from(i32::MAX) + 1, 1), None);
        assert_eq!(r(-3, 2).to_string(), "-3/2");
        assert_eq!(r(4, 2).to_string(), "2");
    }

    #[test]
    fn checked_arithmetic_never_wraps() {
        assert_eq!(r(1, 2).checked_add(r(1, 3)), Some(r(5, 6)));
        assert_eq!(r(3, 2).checked_mul(r(2, 3)), Some(Ratio::ONE));
        let big = Ratio::int(i32::MAX);
        assert_eq!(big.checked_add(Ratio::ONE), None);
        assert_eq!(big.checked_mul(Ratio::int(2)), None);
        assert_eq!(r(1, 65_536).checked_mul(r(1, 65_536)), None);
        assert_eq!(Ratio::int(i32::MIN).checked_neg(), None);
    }

    #[test]
    fn decimals_are_exact() {
        assert_eq!(Ratio::parse_decimal("1.5"), Some(r(3, 2)));
        assert_eq!(Ratio::parse_decimal("0.25"), Some(r(1, 4)));
        assert_eq!(Ratio::parse_decimal("-.5"), Some(r(-1, 2)));
        assert_eq!(Ratio::parse_decimal("+2"), Some(Ratio::int(2)));
        assert_eq!(
            Ratio::parse_decimal("0.333333"),
            Some(r(333_333, 1_000_000))
        );
        for bad in ["", ".", "1.", "-", "1.2.3", "1e3", "0.1234567891", "x"] {
            assert_eq!(Ratio::parse_decimal(bad), None, "{bad}");
        }
    }

    #[test]
    fn floats_become_fractions_only_when_they_are_ones() {
        assert_eq!(Ratio::from_f64(1.5, 1000), Some(r(3, 2)));
        assert_eq!(Ratio::from_f64(-0.1, 1000), Some(r(-1, 10)));
        assert_eq!(Ratio::from_f64(2.0 / 3.0, 1000), Some(r(2, 3)));
        assert_eq!(Ratio::from_f64(20_736.0, 1000), Some(Ratio::int(20_736)));
        assert_eq!(Ratio::from_f64(0.333_333, 1000), None);
        assert_eq!(Ratio::from_f64(std::f64::consts::E, 1000), None);
        assert_eq!(Ratio::from_f64(f64::NAN, 1000), None);
        assert_eq!(Ratio::from_f64(1e12, 1000), None);
    }
}
