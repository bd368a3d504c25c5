//! Physical dimensions as exact rational exponents of the SI base units.

use std::fmt;
use std::ops::{Div, Mul};

use super::ratio::Ratio;

/// Exponents of the seven SI base units, in the order m, kg, s, A, K, mol, cd.
///
/// Exponents are exact fractions ([`Ratio`]): `m^(3/2)` in a Hertz contact stiffness
/// `N/m^(3/2)`, `s^(1/2)`, `t^(3/2)` in the constant-power motion. Angles are dimensionless
/// (radians), as in SI.
///
/// Arithmetic never wraps or saturates. A numerator or denominator that would reach 2^31 is
/// an error from the checked operations ([`Dimension::checked_mul`],
/// [`Dimension::pow_rational`], …), which every path from user input uses; the operators
/// `*` and `/` and [`Dimension::powi`], meant for the fixed dimensions of the code, give
/// [`Dimension::TOO_LARGE`] instead, which equals no real dimension and prints as such.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Dimension {
    exponents: [Ratio; 7],
    too_large: bool,
}

const BASE_SYMBOLS: [&str; 7] = ["m", "kg", "s", "A", "K", "mol", "cd"];

/// A dimension whose exponents would leave the exact range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum DimensionError {
    /// An exponent's numerator or denominator would reach 2^31.
    ExponentTooLarge,
}

impl fmt::Display for DimensionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DimensionError::ExponentTooLarge => write!(
                f,
                "exponent too large: a dimension's exponents are exact fractions whose \
                 numerator and denominator stay below 2^31 = 2147483648"
            ),
        }
    }
}

impl std::error::Error for DimensionError {}

impl Dimension {
    /// The dimension with these whole-number exponents of m, kg, s, A, K, mol, cd.
    pub const fn base(e: [i8; 7]) -> Dimension {
        let mut exponents = [Ratio::ZERO; 7];
        let mut i = 0;
        while i < 7 {
            exponents[i] = Ratio::int(e[i] as i32);
            i += 1;
        }
        Dimension {
            exponents,
            too_large: false,
        }
    }

    /// The dimension with these exact exponents of m, kg, s, A, K, mol, cd.
    ///
    /// ```
    /// use mechkit_expr::units::{Dimension, Ratio};
    /// let half = Ratio::new(1, 2).unwrap();
    /// let z = Ratio::ZERO;
    /// let d = Dimension::from_exponents([half, z, z, z, z, z, z]);
    /// assert_eq!(d, Dimension::LENGTH.root(2).unwrap());
    /// assert_eq!(d.to_string(), "m^(1/2)");
    /// ```
    pub const fn from_exponents(exponents: [Ratio; 7]) -> Dimension {
        Dimension {
            exponents,
            too_large: false,
        }
    }

    /// The exponent of base unit `i` (0 = m, 1 = kg, 2 = s, …) as a reduced fraction
    /// `(numerator, denominator)`; `(0, 0)` in [`Dimension::TOO_LARGE`].
    pub fn exponent(self, i: usize) -> (i32, i32) {
        if self.too_large {
            return (0, 0);
        }
        let r = self.exponents[i];
        (r.num(), r.den())
    }

    /// The exponent of base unit `i` (0 = m, 1 = kg, 2 = s, …); `None` in
    /// [`Dimension::TOO_LARGE`].
    pub fn exponent_ratio(self, i: usize) -> Option<Ratio> {
        (!self.too_large).then_some(self.exponents[i])
    }

    /// What the unchecked operations give when an exponent would leave the exact range: equal
    /// to no real dimension, displayed as "(exponent too large)".
    pub const TOO_LARGE: Dimension = Dimension {
        exponents: [Ratio::ZERO; 7],
        too_large: true,
    };

    /// No dimension (pure numbers, angles).
    pub const NONE: Dimension = Dimension::base([0; 7]);
    /// Length (m).
    pub const LENGTH: Dimension = Dimension::base([1, 0, 0, 0, 0, 0, 0]);
    /// Mass (kg).
    pub const MASS: Dimension = Dimension::base([0, 1, 0, 0, 0, 0, 0]);
    /// Time (s).
    pub const TIME: Dimension = Dimension::base([0, 0, 1, 0, 0, 0, 0]);
    /// Electric current (A).
    pub const CURRENT: Dimension = Dimension::base([0, 0, 0, 1, 0, 0, 0]);
    /// Temperature (K).
    pub const TEMPERATURE: Dimension = Dimension::base([0, 0, 0, 0, 1, 0, 0]);
    /// Amount of substance (mol).
    pub const AMOUNT: Dimension = Dimension::base([0, 0, 0, 0, 0, 1, 0]);
    /// Luminous intensity (cd).
    pub const LUMINOSITY: Dimension = Dimension::base([0, 0, 0, 0, 0, 0, 1]);
    /// Velocity (m/s).
    pub const VELOCITY: Dimension = Dimension::base([1, 0, -1, 0, 0, 0, 0]);
    /// Acceleration (m/s²).
    pub const ACCELERATION: Dimension = Dimension::base([1, 0, -2, 0, 0, 0, 0]);
    /// Force (N).
    pub const FORCE: Dimension = Dimension::base([1, 1, -2, 0, 0, 0, 0]);
    /// Energy and work (J); also torque (N·m).
    pub const ENERGY: Dimension = Dimension::base([2, 1, -2, 0, 0, 0, 0]);
    /// Power (W).
    pub const POWER: Dimension = Dimension::base([2, 1, -3, 0, 0, 0, 0]);
    /// Momentum and impulse (kg·m/s).
    pub const MOMENTUM: Dimension = Dimension::base([1, 1, -1, 0, 0, 0, 0]);
    /// Frequency and angular velocity (1/s).
    pub const FREQUENCY: Dimension = Dimension::base([0, 0, -1, 0, 0, 0, 0]);
    /// Spring constant (N/m).
    pub const STIFFNESS: Dimension = Dimension::base([0, 1, -2, 0, 0, 0, 0]);
    /// Linear drag coefficient (N·s/m = kg/s).
    pub const LINEAR_DRAG: Dimension = Dimension::base([0, 1, -1, 0, 0, 0, 0]);
    /// Quadratic drag coefficient (N·s²/m² = kg/m).
    pub const QUADRATIC_DRAG: Dimension = Dimension::base([-1, 1, 0, 0, 0, 0, 0]);
    /// Gravitational parameter GM (m³/s²).
    pub const GRAVITATIONAL_PARAMETER: Dimension = Dimension::base([3, 0, -2, 0, 0, 0, 0]);
    /// Gravitational constant G (m³/(kg·s²)).
    pub const GRAVITATIONAL_CONSTANT: Dimension = Dimension::base([3, -1, -2, 0, 0, 0, 0]);
    /// Moment of inertia (kg·m²).
    pub const MOMENT_OF_INERTIA: Dimension = Dimension::base([2, 1, 0, 0, 0, 0, 0]);
    /// Angular momentum (kg·m²/s).
    pub const ANGULAR_MOMENTUM: Dimension = Dimension::base([2, 1, -1, 0, 0, 0, 0]);
    /// Pressure (Pa).
    pub const PRESSURE: Dimension = Dimension::base([-1, 1, -2, 0, 0, 0, 0]);

    /// Whether this is dimensionless.
    pub fn is_none(self) -> bool {
        self == Dimension::NONE
    }

    /// Whether an unchecked operation overflowed ([`Dimension::TOO_LARGE`]).
    pub fn is_too_large(self) -> bool {
        self.too_large
    }

    fn checked(self) -> Result<Dimension, DimensionError> {
        if self.too_large {
            Err(DimensionError::ExponentTooLarge)
        } else {
            Ok(self)
        }
    }

    fn map(
        self,
        rhs: Dimension,
        op: impl Fn(Ratio, Ratio) -> Option<Ratio>,
    ) -> Result<Dimension, DimensionError> {
        let (a, b) = (self.checked()?, rhs.checked()?);
        let mut out = a;
        for (e, r) in out.exponents.iter_mut().zip(b.exponents) {
            *e = op(*e, r).ok_or(DimensionError::ExponentTooLarge)?;
        }
        Ok(out)
    }

    /// `self * rhs`, or an error if an exponent leaves the exact range.
    pub fn checked_mul(self, rhs: Dimension) -> Result<Dimension, DimensionError> {
        self.map(rhs, Ratio::checked_add)
    }

    /// `self / rhs`, or an error if an exponent leaves the exact range.
    pub fn checked_div(self, rhs: Dimension) -> Result<Dimension, DimensionError> {
        self.map(rhs, |a, b| a.checked_add(b.checked_neg()?))
    }

    /// Raised to the exact power `p`, or an error if an exponent leaves the exact range.
    ///
    /// ```
    /// use mechkit_expr::units::{Dimension, Ratio};
    /// let m3 = Dimension::LENGTH.powi(3);
    /// let half = Ratio::new(1, 2).unwrap();
    /// assert_eq!(m3.pow_rational(half).unwrap().to_string(), "m^(3/2)");
    /// let huge = Ratio::int(1 << 20);
    /// assert!(Dimension::LENGTH.pow_rational(huge).unwrap().pow_rational(huge).is_err());
    /// ```
    pub fn pow_rational(self, p: Ratio) -> Result<Dimension, DimensionError> {
        let mut out = self.checked()?;
        for e in &mut out.exponents {
            *e = e.checked_mul(p).ok_or(DimensionError::ExponentTooLarge)?;
        }
        Ok(out)
    }

    /// Raised to the integer power `n`, or an error if an exponent leaves the exact range.
    pub fn checked_powi(self, n: i32) -> Result<Dimension, DimensionError> {
        self.pow_rational(Ratio::int(n))
    }

    /// Raised to an integer power; [`Dimension::TOO_LARGE`] if an exponent leaves the exact
    /// range (use [`Dimension::checked_powi`] on dimensions that come from input).
    #[must_use]
    pub fn powi(self, n: i32) -> Dimension {
        self.checked_powi(n).unwrap_or(Dimension::TOO_LARGE)
    }

    /// The `n`-th root; `None` if `n` is 0 or an exponent leaves the exact range.
    pub fn root(self, n: i32) -> Option<Dimension> {
        self.pow_ratio(1, n)
    }

    /// Raised to the rational power `num/den` (e.g. 1/2 for a square root); `None` if `den`
    /// is 0 or an exponent leaves the exact range.
    pub fn pow_ratio(self, num: i32, den: i32) -> Option<Dimension> {
        self.pow_rational(Ratio::new(i64::from(num), i64::from(den))?)
            .ok()
    }

    /// A name for the kind of quantity, where it has a common one.
    pub fn quantity_name(self) -> Option<&'static str> {
        NAMED
            .iter()
            .find(|(d, _, _)| *d == self)
            .map(|(_, q, _)| *q)
    }

    /// The derived SI unit symbol, where there is a common one (N, J, W, Pa, Hz).
    pub fn derived_symbol(self) -> Option<&'static str> {
        NAMED
            .iter()
            .find(|(d, _, _)| *d == self)
            .and_then(|(_, _, s)| *s)
    }

    /// The dimension in base units with its name, e.g. "kg*m/s^2 (force, N)".
    pub fn describe(self) -> String {
        if self.too_large {
            return self.to_string();
        }
        match (self.quantity_name(), self.derived_symbol()) {
            (Some(q), Some(s)) => format!("{self} ({q}, {s})"),
            (Some(q), None) => format!("{self} ({q})"),
            _ => self.to_string(),
        }
    }
}

const NAMED: &[(Dimension, &str, Option<&str>)] = &[
    (Dimension::NONE, "dimensionless", None),
    (Dimension::LENGTH, "length", None),
    (Dimension::MASS, "mass", None),
    (Dimension::TIME, "time", None),
    (Dimension::VELOCITY, "velocity", None),
    (Dimension::ACCELERATION, "acceleration", None),
    (Dimension::FORCE, "force", Some("N")),
    (Dimension::ENERGY, "energy", Some("J")),
    (Dimension::POWER, "power", Some("W")),
    (Dimension::MOMENTUM, "momentum", None),
    (
        Dimension::FREQUENCY,
        "frequency or angular velocity",
        Some("Hz"),
    ),
    (Dimension::STIFFNESS, "spring constant", None),
    (Dimension::LINEAR_DRAG, "linear drag coefficient", None),
    (
        Dimension::QUADRATIC_DRAG,
        "quadratic drag coefficient",
        None,
    ),
    (
        Dimension::GRAVITATIONAL_PARAMETER,
        "gravitational parameter",
        None,
    ),
    (
        Dimension::GRAVITATIONAL_CONSTANT,
        "gravitational constant",
        None,
    ),
    (Dimension::MOMENT_OF_INERTIA, "moment of inertia", None),
    (Dimension::ANGULAR_MOMENTUM, "angular momentum", None),
    (Dimension::PRESSURE, "pressure", Some("Pa")),
    (
        Dimension::base([0, 0, -2, 0, 0, 0, 0]),
        "angular acceleration",
        None,
    ),
    (Dimension::base([2, 0, 0, 0, 0, 0, 0]), "area", None),
    (Dimension::base([3, 0, 0, 0, 0, 0, 0]), "volume", None),
    (Dimension::base([-3, 1, 0, 0, 0, 0, 0]), "density", None),
];

impl Mul for Dimension {
    type Output = Dimension;
    /// The product; [`Dimension::TOO_LARGE`] if an exponent leaves the exact range (use
    /// [`Dimension::checked_mul`] on dimensions that come from input).
    fn mul(self, rhs: Dimension) -> Dimension {
        self.checked_mul(rhs).unwrap_or(Dimension::TOO_LARGE)
    }
}

impl Div for Dimension {
    type Output = Dimension;
    /// The quotient; [`Dimension::TOO_LARGE`] if an exponent leaves the exact range (use
    /// [`Dimension::checked_div`] on dimensions that come from input).
    fn div(self, rhs: Dimension) -> Dimension {
        self.checked_div(rhs).unwrap_or(Dimension::TOO_LARGE)
    }
}

impl fmt::Display for Dimension {
    /// Base units, numerator then denominator: `kg*m/s^2`, `1/s`, `1` for none; fractional
    /// powers in parentheses, `kg/(m^(1/2)*s^2)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // kg reads better first (kg*m/s^2, kg*m^2/s^2).
        const ORDER: [usize; 7] = [1, 0, 2, 3, 4, 5, 6];
        if self.too_large {
            return write!(f, "(exponent too large)");
        }
        let part = |positive: bool| -> Vec<String> {
            ORDER
                .iter()
                .filter_map(|&i| {
                    let (num, den) = self.exponent(i);
                    let num = if positive { num } else { -num };
                    (num > 0).then(|| match (num, den) {
                        (1, 1) => BASE_SYMBOLS[i].to_string(),
                        (n, 1) => format!("{}^{n}", BASE_SYMBOLS[i]),
                        (n, d) => format!("{}^({n}/{d})", BASE_SYMBOLS[i]),
                    })
                })
                .collect()
        };
        let (num, den) = (part(true), part(false));
        let num = if num.is_empty() {
            "1".to_string()
        } else {
            num.join("*")
        };
        match den.len() {
            0 => write!(f, "{num}"),
            1 => write!(f, "{num}/{}", den[0]),
            _ => write!(f, "{num}/({})", den.join("*")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display() {
        assert_eq!(Dimension::FORCE.to_string(), "kg*m/s^2");
        assert_eq!(Dimension::FREQUENCY.to_string(), "1/s");
        assert_eq!(Dimension::NONE.to_string(), "1");
        assert_eq!(
            Dimension::GRAVITATIONAL_CONSTANT.to_string(),
            "m^3/(kg*s^2)"
        );
        assert_eq!(Dimension::FORCE.describe(), "kg*m/s^2 (force, N)");
    }

    #[test]
    fn algebra() {
        assert_eq!(Dimension::MASS * Dimension::ACCELERATION, Dimension::FORCE);
        assert_eq!(Dimension::ENERGY / Dimension::TIME, Dimension::POWER);
        assert_eq!(
            (Dimension::VELOCITY * Dimension::VELOCITY).root(2),
            Some(Dimension::VELOCITY)
        );
        assert_eq!(Dimension::LENGTH.root(2).unwrap().to_string(), "m^(1/2)");
        assert_eq!(Dimension::LENGTH.root(4).unwrap().to_string(), "m^(1/4)");
        assert_eq!(
            Dimension::TIME.pow_ratio(-3, 2).unwrap().to_string(),
            "1/s^(3/2)"
        );
        assert_eq!(Dimension::TIME.pow_ratio(1, 0), None);
        // a Hertz contact stiffness times a length to the 3/2 is a force
        let hertz = Dimension::FORCE / Dimension::LENGTH.pow_ratio(3, 2).unwrap();
        assert_eq!(hertz.to_string(), "kg/(m^(1/2)*s^2)");
        assert_eq!(
            hertz * Dimension::LENGTH.pow_ratio(3, 2).unwrap(),
            Dimension::FORCE
        );
        assert_eq!(
            Dimension::LENGTH.pow_ratio(1, 3).unwrap() * Dimension::LENGTH.pow_ratio(1, 6).unwrap(),
            Dimension::LENGTH.root(2).unwrap()
        );
    }

    #[test]
    fn large_exponents_are_exact_or_refused() {
        let mut d = Dimension::LENGTH;
        for _ in 0..4 {
            d = d.checked_powi(12).unwrap();
        }
        assert_eq!(d.to_string(), "m^20736");
        assert_ne!(d, Dimension::LENGTH.powi(5000));
        // an energy never passes for a force, however large the powers
        let big = Dimension::LENGTH.powi(1 << 30);
        assert_ne!(big * Dimension::ENERGY, big * Dimension::FORCE);
        assert_eq!(big.checked_mul(big), Err(DimensionError::ExponentTooLarge));
        assert_eq!(
            Dimension::LENGTH
                .checked_powi(i32::MIN)
                .unwrap()
                .checked_div(Dimension::LENGTH),
            Err(DimensionError::ExponentTooLarge)
        );
        assert!(
            DimensionError::ExponentTooLarge
                .to_string()
                .starts_with("exponent too large")
        );
        // the unchecked operators give TOO_LARGE, which equals no real dimension
        let over = big * big;
        assert!(over.is_too_large());
        assert_ne!(over, Dimension::NONE);
        assert_eq!(over.to_string(), "(exponent too large)");
        assert_eq!(over.exponent_ratio(0), None);
        assert!((over * Dimension::LENGTH).is_too_large());
        assert!(over.checked_mul(Dimension::NONE).is_err());
        // denominators overflow too: 2^31 square roots
        let mut r = Some(Dimension::LENGTH);
        for _ in 0..31 {
            r = r.and_then(|d| d.root(2));
        }
        assert_eq!(r, None);
    }
}
