//! Numbers for symbolic work: exact rationals where the input was exact (`1/2`, `0.1` read as
//! 1/10), floating point where it was not or where a rational would overflow.

use std::cmp::Ordering;
use std::fmt;

/// An exact rational `num/den` (`den > 0`, lowest terms) or a float.
#[derive(Debug, Clone, Copy)]
pub enum Number {
    /// Exact rational.
    Rational(i128, i128),
    /// Floating point.
    Float(f64),
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// Beyond this, rationals become floats: numerator and denominator stay exactly representable
/// as `f64` (so an exact number prints and reads back exactly), and every intermediate product
/// stays inside `i128`.
const LIMIT: i128 = 1 << 53;

impl Number {
    /// Zero.
    pub const ZERO: Number = Number::Rational(0, 1);
    /// One.
    pub const ONE: Number = Number::Rational(1, 1);
    /// Minus one.
    pub const MINUS_ONE: Number = Number::Rational(-1, 1);

    /// The rational `num/den` in lowest terms (a float if it is too large).
    pub fn rational(num: i128, den: i128) -> Number {
        assert!(den != 0, "zero denominator");
        let g = gcd(num, den).max(1);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = -n;
            d = -d;
        }
        if n.abs() > LIMIT || d > LIMIT {
            Number::Float(n as f64 / d as f64)
        } else {
            Number::Rational(n, d)
        }
    }

    /// An integer.
    pub fn int(n: i64) -> Number {
        Number::rational(i128::from(n), 1)
    }

    /// A float, read as the exact decimal it prints as when that decimal is short enough
    /// (`0.1` → 1/10, `1e-9` → 1/10⁹, `6.674e-11` → 6674/10¹⁴); otherwise kept as a float.
    pub fn from_f64(x: f64) -> Number {
        if !x.is_finite() {
            return Number::Float(x);
        }
        if x.fract() == 0.0 && x.abs() <= LIMIT as f64 {
            return Number::rational(x as i128, 1);
        }
        let text = format!("{x:e}"); // shortest round-trip digits, e.g. "6.674e-11"
        let (mantissa, exp) = text.split_once('e').expect("exponent form");
        let exp: i32 = exp.parse().expect("integer exponent");
        let negative = mantissa.starts_with('-');
        let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
        let frac_len = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
        // more significant digits than a person types: a computed value, keep it a float
        if digits.trim_start_matches('0').len() > 15 {
            return Number::Float(x);
        }
        let Ok(mut n) = digits.parse::<i128>() else {
            return Number::Float(x);
        };
        if negative {
            n = -n;
        }
        let scale = exp - frac_len;
        if scale.abs() > 30 {
            return Number::Float(x);
        }
        let p = 10i128.pow(scale.unsigned_abs());
        let r = if scale >= 0 {
            n.checked_mul(p).map(|v| Number::rational(v, 1))
        } else {
            Some(Number::rational(n, p))
        };
        match r {
            Some(r @ Number::Rational(..)) => r,
            _ => Number::Float(x),
        }
    }

    /// The value as a float.
    pub fn to_f64(self) -> f64 {
        match self {
            Number::Rational(n, d) => n as f64 / d as f64,
            Number::Float(x) => x,
        }
    }

    /// Whether it is exactly zero.
    pub fn is_zero(self) -> bool {
        match self {
            Number::Rational(n, _) => n == 0,
            Number::Float(x) => x == 0.0,
        }
    }

    /// Whether it is exactly one.
    pub fn is_one(self) -> bool {
        match self {
            Number::Rational(n, d) => n == 1 && d == 1,
            Number::Float(x) => x == 1.0,
        }
    }

    /// Whether it is negative.
    pub fn is_negative(self) -> bool {
        self.to_f64() < 0.0
    }

    /// The integer, when it is an exact integer.
    pub fn as_integer(self) -> Option<i128> {
        match self {
            Number::Rational(n, 1) => Some(n),
            _ => None,
        }
    }

    /// Numerator and denominator, when exact.
    pub fn as_rational(self) -> Option<(i128, i128)> {
        match self {
            Number::Rational(n, d) => Some((n, d)),
            Number::Float(_) => None,
        }
    }

    /// Whether it is exact.
    pub fn is_exact(self) -> bool {
        matches!(self, Number::Rational(..))
    }

    /// `-self`.
    #[must_use]
    pub fn negated(self) -> Number {
        match self {
            Number::Rational(n, d) => Number::Rational(-n, d),
            Number::Float(x) => Number::Float(-x),
        }
    }

    /// `|self|`.
    #[must_use]
    pub fn abs(self) -> Number {
        if self.is_negative() {
            self.negated()
        } else {
            self
        }
    }

    /// `self + other`.
    #[must_use]
    pub fn plus(self, other: Number) -> Number {
        match (self, other) {
            (Number::Rational(a, b), Number::Rational(c, d)) => {
                Number::rational(a * d + c * b, b * d)
            }
            _ => Number::Float(self.to_f64() + other.to_f64()),
        }
    }

    /// `self * other`.
    #[must_use]
    pub fn times(self, other: Number) -> Number {
        match (self, other) {
            (Number::Rational(a, b), Number::Rational(c, d)) => Number::rational(a * c, b * d),
            _ => Number::Float(self.to_f64() * other.to_f64()),
        }
    }

    /// `1/self`; `None` for zero.
    pub fn recip(self) -> Option<Number> {
        match self {
            Number::Rational(0, _) => None,
            Number::Rational(n, d) => Some(Number::rational(d, n)),
            Number::Float(x) => Some(Number::Float(1.0 / x)),
        }
    }

    /// `self / other`; `None` when dividing by zero.
    pub fn checked_div(self, other: Number) -> Option<Number> {
        other.recip().map(|r| self.times(r))
    }

    /// `self^n` for an integer `n` (exact for rationals unless it overflows; `n` beyond the
    /// `i32` range is not saturated, which would change the sign of a negative base); `None` for
    /// `0^-n`.
    pub fn powi(self, n: i128) -> Option<Number> {
        if n < 0 {
            return self.recip()?.powi(-n);
        }
        match self {
            Number::Rational(a, b) => {
                let n32 = u32::try_from(n).ok()?;
                match (a.checked_pow(n32), b.checked_pow(n32)) {
                    (Some(p), Some(q)) if p.abs() <= LIMIT && q <= LIMIT => {
                        Some(Number::rational(p, q))
                    }
                    _ => Some(Number::Float(float_powi(a as f64 / b as f64, n))),
                }
            }
            Number::Float(x) => Some(Number::Float(float_powi(x, n))),
        }
    }

    /// The exact `k`-th root of a rational, when there is one (`4` → 2, `8/27` with k = 3 →
    /// 2/3).
    pub fn exact_root(self, k: u32) -> Option<Number> {
        let Number::Rational(n, d) = self else {
            return None;
        };
        if n < 0 && k.is_multiple_of(2) {
            return None;
        }
        let root = |v: i128| -> Option<i128> {
            let r = (v.unsigned_abs() as f64).powf(1.0 / f64::from(k)).round() as i128;
            (r - 1..=r + 1)
                .find(|c| *c >= 0 && c.checked_pow(k) == Some(v.abs()))
                .map(|c| c * v.signum())
        };
        Some(Number::rational(root(n)?, root(d)?))
    }

    /// A positive rational as `a^k · r` with `a` the largest factor made of primes below 1000
    /// (`396/25`, k = 2 → `(6/5, 11)`): what comes out of a `k`-th root. `None` when nothing
    /// comes out, or for a negative number or a float.
    pub fn split_power(self, k: u32) -> Option<(Number, Number)> {
        let Number::Rational(n, d) = self else {
            return None;
        };
        if n <= 0 || k < 2 {
            return None;
        }
        let take = |mut v: i128| -> (i128, i128) {
            let mut out = 1i128;
            let mut p = 2i128;
            while p < 1000 && p.checked_pow(k).is_some_and(|pk| pk <= v) {
                let pk = p.pow(k);
                while v % pk == 0 {
                    v /= pk;
                    out *= p;
                }
                p += 1;
            }
            (out, v)
        };
        let ((on, n1), (od, d1)) = (take(n), take(d));
        (on != 1 || od != 1).then(|| (Number::rational(on, od), Number::rational(n1, d1)))
    }

    /// Total order (NaN last).
    pub fn total_cmp(&self, other: &Number) -> Ordering {
        match (self, other) {
            (Number::Rational(a, b), Number::Rational(c, d)) => (a * d).cmp(&(c * b)),
            _ => self.to_f64().total_cmp(&other.to_f64()),
        }
    }
}

impl PartialEq for Number {
    fn eq(&self, other: &Number) -> bool {
        match (self, other) {
            (Number::Rational(a, b), Number::Rational(c, d)) => a == c && b == d,
            (Number::Float(x), Number::Float(y)) => x.to_bits() == y.to_bits(),
            _ => false,
        }
    }
}

impl Eq for Number {}

impl std::hash::Hash for Number {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        match self {
            Number::Rational(n, d) => {
                0u8.hash(state);
                n.hash(state);
                d.hash(state);
            }
            Number::Float(x) => {
                1u8.hash(state);
                x.to_bits().hash(state);
            }
        }
    }
}

impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Number::Rational(n, 1) => write!(f, "{n}"),
            Number::Rational(n, d) => write!(f, "{n}/{d}"),
            Number::Float(x) => write!(f, "{}", crate::ast::format_number(*x)),
        }
    }
}

/// `x^n` for a whole `n ≥ 0` of any size: repeated multiplication within the `i32` range,
/// else `powf` (whose integer powers keep the sign of a negative base), never a saturated `n`.
fn float_powi(x: f64, n: i128) -> f64 {
    match i32::try_from(n) {
        Ok(k) => x.powi(k),
        Err(_) => x.powf(n as f64),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 26: an exponent beyond the `i32` range was cast (`as i32`): 3e9 wrapped to a
    /// negative power, and a saturated one changed the sign of a negative base.
    #[test]
    fn issue_026_powers_beyond_i32_are_not_wrapped_or_saturated() {
        let big = 3_000_000_000_i128;
        assert_eq!(Number::Float(-1.0).powi(big), Some(Number::Float(1.0)));
        assert_eq!(Number::Float(-1.0).powi(big + 1), Some(Number::Float(-1.0)));
        assert_eq!(
            Number::rational(-3, 2).powi(big),
            Some(Number::Float(f64::INFINITY))
        );
        assert_eq!(Number::rational(3, 2).powi(-big), Some(Number::Float(0.0)));
        assert_eq!(Number::Float(0.5).powi(big), Some(Number::Float(0.0)));
    }

    #[test]
    fn decimals_are_exact() {
        assert_eq!(Number::from_f64(0.5), Number::rational(1, 2));
        assert_eq!(Number::from_f64(0.1), Number::rational(1, 10));
        assert_eq!(Number::from_f64(1e-9), Number::rational(1, 1_000_000_000));
        assert_eq!(
            Number::from_f64(6.674e-11),
            Number::rational(6674, 100_000_000_000_000)
        );
        assert_eq!(Number::from_f64(-2.5), Number::rational(-5, 2));
        assert_eq!(Number::from_f64(1500.0), Number::int(1500));
        assert!(matches!(
            Number::from_f64(std::f64::consts::PI),
            Number::Float(_)
        ));
        assert!(matches!(Number::from_f64(0.1 + 0.2), Number::Float(_)));
        assert!(matches!(Number::from_f64(1e300), Number::Float(_)));
    }

    #[test]
    fn arithmetic() {
        let h = Number::rational(1, 2);
        assert_eq!(h.plus(Number::rational(1, 3)), Number::rational(5, 6));
        assert_eq!(h.times(Number::int(4)), Number::int(2));
        assert_eq!(
            Number::rational(2, 3).powi(-2),
            Some(Number::rational(9, 4))
        );
        assert_eq!(Number::ZERO.recip(), None);
        assert_eq!(Number::int(8).exact_root(3), Some(Number::int(2)));
        assert_eq!(
            Number::rational(4, 9).exact_root(2),
            Some(Number::rational(2, 3))
        );
        assert_eq!(Number::int(2).exact_root(2), None);
        assert_eq!(Number::int(-8).exact_root(3), Some(Number::int(-2)));
        assert_eq!(Number::int(10).powi(40).map(Number::is_exact), Some(false));
    }
}
