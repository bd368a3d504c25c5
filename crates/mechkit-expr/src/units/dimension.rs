//! Physical dimensions as integer exponents of the SI base units.

use std::fmt;
use std::ops::{Div, Mul};

/// Exponents of the seven SI base units, in the order m, kg, s, A, K, mol, cd.
///
/// Exponents may be halves and thirds (`t^(3/2)` in the constant-power motion, `sqrt(2*P/m)`),
/// so they are stored in sixths. Angles are dimensionless (radians), as in SI.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Dimension([i16; 7]);

/// Exponents are stored as multiples of 1/`DEN`.
const DEN: i16 = 6;

const BASE_SYMBOLS: [&str; 7] = ["m", "kg", "s", "A", "K", "mol", "cd"];

impl Dimension {
    /// The dimension with these whole-number exponents of m, kg, s, A, K, mol, cd.
    pub const fn base(e: [i8; 7]) -> Dimension {
        let mut out = [0i16; 7];
        let mut i = 0;
        while i < 7 {
            out[i] = e[i] as i16 * DEN;
            i += 1;
        }
        Dimension(out)
    }

    /// The exponent of base unit `i` (0 = m, 1 = kg, 2 = s, …) as a reduced fraction.
    pub fn exponent(self, i: usize) -> (i32, i32) {
        let num = i32::from(self.0[i]);
        let g = gcd(num.unsigned_abs(), DEN as u32).max(1) as i32;
        (num / g, i32::from(DEN) / g)
    }

    /// No dimension (pure numbers, angles).
    pub const NONE: Dimension = Dimension([0; 7]);
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

    /// Raised to an integer power.
    #[must_use]
    pub fn powi(self, n: i32) -> Dimension {
        let mut out = self.0;
        for e in &mut out {
            *e = (i32::from(*e) * n).clamp(-30_000, 30_000) as i16;
        }
        Dimension(out)
    }

    /// The `n`-th root, if the exponents stay multiples of 1/6.
    pub fn root(self, n: i32) -> Option<Dimension> {
        self.pow_ratio(1, n)
    }

    /// Raised to the rational power `num/den` (e.g. 1/2 for a square root), if the exponents
    /// stay multiples of 1/6.
    pub fn pow_ratio(self, num: i32, den: i32) -> Option<Dimension> {
        assert!(den > 0, "denominator must be positive");
        let mut out = self.0;
        for e in &mut out {
            let v = i32::from(*e) * num;
            if v % den != 0 || (v / den).abs() > 30_000 {
                return None;
            }
            *e = (v / den) as i16;
        }
        Some(Dimension(out))
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
    fn mul(self, rhs: Dimension) -> Dimension {
        let mut out = self.0;
        for (e, r) in out.iter_mut().zip(rhs.0) {
            *e = e.saturating_add(r).clamp(-30_000, 30_000);
        }
        Dimension(out)
    }
}

impl Div for Dimension {
    type Output = Dimension;
    fn div(self, rhs: Dimension) -> Dimension {
        self * rhs.powi(-1)
    }
}

impl fmt::Display for Dimension {
    /// Base units, numerator then denominator: `kg*m/s^2`, `1/s`, `1` for none.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // kg reads better first (kg*m/s^2, kg*m^2/s^2).
        const ORDER: [usize; 7] = [1, 0, 2, 3, 4, 5, 6];
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

fn gcd(mut a: u32, mut b: u32) -> u32 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
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
        assert_eq!(Dimension::LENGTH.root(4), None);
        assert_eq!(
            Dimension::TIME.pow_ratio(-3, 2).unwrap().to_string(),
            "1/s^(3/2)"
        );
    }
}
