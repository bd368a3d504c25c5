//! Quantities written with units, `"9.8 m/s^2"`, `"60 km/h"`, `"30 1/m"`, `"4.0 s^2/m^2"`,
//! converted to SI.

use std::fmt;

use super::dimension::Dimension;
use super::parse::parse_unit_at;
use crate::span::{Span, caret_lines};
use crate::suggest::did_you_mean;

/// A value in SI units with its dimension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quantity {
    /// The value in SI units.
    pub value: f64,
    /// Its dimension.
    pub dim: Dimension,
}

impl Quantity {
    /// A quantity of `value` SI units of dimension `dim`.
    pub fn new(value: f64, dim: Dimension) -> Self {
        Self { value, dim }
    }

    /// A pure number.
    pub fn number(value: f64) -> Self {
        Self::new(value, Dimension::NONE)
    }

    /// Parses `"<number> <unit>"`; a bare number is dimensionless.
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::units::{Dimension, Quantity};
    /// let v = Quantity::parse("60 km/h").unwrap();
    /// assert!((v.value - 16.666_666_666_666_668).abs() < 1e-12);
    /// assert_eq!(v.dim, Dimension::VELOCITY);
    /// assert_eq!(Quantity::parse("30 1/m").unwrap().dim, Dimension::LENGTH.powi(-1));
    /// ```
    pub fn parse(text: &str) -> Result<Quantity, UnitError> {
        let (number, rest_start) = leading_number(text).ok_or_else(|| UnitError {
            kind: UnitErrorKind::NoNumber,
            span: Span::new(0, text.len()),
            source: text.to_string(),
        })?;
        let rest = &text[rest_start..];
        let too_large = |message: String, span: Span| UnitError {
            kind: UnitErrorKind::NumberTooLarge(message),
            span,
            source: text.to_string(),
        };
        if number.is_infinite() {
            let start = text.len() - text.trim_start().len();
            let digits = text[start..rest_start].trim_end();
            return Err(too_large(
                format!("`{digits}` is too large for a double-precision number"),
                Span::new(start, start + digits.len()),
            ));
        }
        if rest.trim().is_empty() {
            return Ok(Quantity::number(number));
        }
        let unit = parse_unit_at(text, rest_start)?;
        let value = number * unit.factor;
        if value.is_infinite() {
            let shown = text.trim();
            let start = text.len() - text.trim_start().len();
            return Err(too_large(
                format!("`{shown}` in SI units is too large for a double-precision number"),
                Span::new(start, start + shown.len()),
            ));
        }
        Ok(Quantity::new(value, unit.dim))
    }

    /// Where the unit of `"<number> <unit>"` starts: the byte index after the leading number
    /// and the spaces that follow it; `None` if the text does not start with a number.
    ///
    /// ```
    /// use mechkit_expr::units::Quantity;
    /// assert_eq!(Quantity::unit_start("2.5e3 m/s"), Some(6));
    /// assert_eq!(Quantity::unit_start(" 3"), Some(2));
    /// assert_eq!(Quantity::unit_start("m"), None);
    /// ```
    pub fn unit_start(text: &str) -> Option<usize> {
        let (_, end) = leading_number(text)?;
        Some(end + (text[end..].len() - text[end..].trim_start().len()))
    }

    /// This quantity expressed in `unit` (e.g. metres per second in km/h); `None` if the
    /// dimensions differ.
    pub fn value_in(&self, unit: &Unit) -> Option<f64> {
        (self.dim == unit.dim).then(|| self.value / unit.factor)
    }
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.dim.is_none() {
            write!(f, "{}", crate::short_number(self.value))
        } else {
            write!(f, "{} {}", crate::short_number(self.value), self.dim)
        }
    }
}

/// A unit expression such as `km/h` or `N*m^2`: its size in SI and its dimension.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// Size of one of these in SI units.
    pub factor: f64,
    /// Dimension.
    pub dim: Dimension,
}

impl Unit {
    /// Parses a unit expression: names joined by `*`, `·`, spaces or `/`, powers `^n` (also
    /// `^-1`, `^(-1)`, `²`, `³`) and rational powers (`^1.5`, `^(3/2)`, `^(-1/2)`),
    /// parentheses, and `1` as in `1/s`.
    ///
    /// ```
    /// use mechkit_expr::units::{Dimension, Unit};
    /// let hertz = Unit::parse("N/m^1.5").unwrap();
    /// assert_eq!(hertz, Unit::parse("N/m^(3/2)").unwrap());
    /// assert_eq!(hertz.dim.to_string(), "kg/(m^(1/2)*s^2)");
    /// assert_eq!(hertz.dim * Dimension::LENGTH.pow_ratio(3, 2).unwrap(), Dimension::FORCE);
    /// ```
    pub fn parse(text: &str) -> Result<Unit, UnitError> {
        parse_unit_at(text, 0)
    }
}

/// What went wrong reading a quantity or unit.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum UnitErrorKind {
    /// The text does not start with a number.
    NoNumber,
    /// A unit name that is not in the table.
    UnknownUnit {
        /// The name.
        name: String,
        /// Known units with similar names.
        suggestions: Vec<String>,
    },
    /// Malformed unit expression; says what was expected.
    Syntax(String),
    /// A power that is not a short decimal or fraction, or out of range (`m^0.333333`,
    /// `m^99`, `m^3/2` for `m^(3/2)`).
    Power {
        /// What is wrong with it.
        message: String,
        /// What would fix it.
        hint: String,
    },
    /// A unit whose exponents or size leave the exact or floating-point range
    /// (`(((km^12)^12)^12)^12`); says which.
    TooLarge(String),
    /// A number too large for a double (`1e309 m`), or one whose value in SI units is
    /// (`1e308 km`); says which.
    NumberTooLarge(String),
}

/// An error reading a quantity or unit, pointing into the text.
#[derive(Debug, Clone, PartialEq)]
pub struct UnitError {
    /// What went wrong.
    pub kind: UnitErrorKind,
    /// Where, as bytes of `source`.
    pub span: Span,
    /// The text.
    pub source: String,
}

impl UnitError {
    /// The problem in one line.
    pub fn message(&self) -> String {
        match &self.kind {
            UnitErrorKind::NoNumber => format!("`{}` does not start with a number", self.source),
            UnitErrorKind::UnknownUnit { name, .. } => format!("unknown unit `{name}`"),
            UnitErrorKind::Syntax(expected) => format!("expected {expected} in the unit"),
            UnitErrorKind::Power { message, .. }
            | UnitErrorKind::TooLarge(message)
            | UnitErrorKind::NumberTooLarge(message) => message.clone(),
        }
    }

    /// What would fix it.
    pub fn hint(&self) -> Option<String> {
        match &self.kind {
            UnitErrorKind::UnknownUnit { suggestions, .. } => did_you_mean(suggestions)
                .or_else(|| Some("units: m, kg, g, s, N, J, W, km/h, rpm, deg, eV, u, Å, AU, … (see docs/scenario.md)".into())),
            UnitErrorKind::NoNumber => Some("write a number followed by its unit, e.g. \"9.8 m/s^2\"".into()),
            UnitErrorKind::Syntax(_) => Some("units combine with `*`, `/` and `^`, e.g. \"kg*m/s^2\", \"30 1/m\" or \"1e5 N/m^(3/2)\"".into()),
            UnitErrorKind::Power { hint, .. } => Some(hint.clone()),
            UnitErrorKind::TooLarge(_) => Some("write the unit with smaller powers".into()),
            UnitErrorKind::NumberTooLarge(_) => Some(
                "a double-precision number is at most about 1.8e308: write the value in \
                 larger units or scale the problem"
                    .into(),
            ),
        }
    }

    /// The text with a caret line under the problem.
    pub fn snippet(&self) -> String {
        caret_lines(&self.source, self.span)
    }
}

impl fmt::Display for UnitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}\n  {}",
            self.message(),
            self.snippet().replace('\n', "\n  ")
        )?;
        if let Some(h) = self.hint() {
            write!(f, "\n  hint: {h}")?;
        }
        Ok(())
    }
}

impl std::error::Error for UnitError {}

/// Parses a leading real number; returns it and the byte index after it.
fn leading_number(text: &str) -> Option<(f64, usize)> {
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() && b[i].is_ascii_whitespace() {
        i += 1;
    }
    let start = i;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let digits_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    if i < b.len() && b[i] == b'.' {
        i += 1;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
    }
    if i == digits_start || (i == digits_start + 1 && b[digits_start] == b'.') {
        return None;
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if j < b.len() && b[j].is_ascii_digit() {
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            i = j;
        }
    }
    let value = text[start..i].parse().ok()?;
    Some((value, i))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn q(s: &str) -> Quantity {
        Quantity::parse(s).unwrap_or_else(|e| panic!("{e}"))
    }

    /// Issue 26: `1e309 m` was `inf m`; a number or a value in SI that overflows a double is
    /// an error at the number (or at the whole quantity).
    #[test]
    fn issue_026_a_number_too_large_for_a_double_is_refused() {
        let e = Quantity::parse("  1e309 m").unwrap_err();
        assert!(matches!(e.kind, UnitErrorKind::NumberTooLarge(_)), "{e}");
        assert_eq!((e.span.start, e.span.end), (2, 7));
        assert!(e.hint().unwrap().contains("1.8e308"));
        let e = Quantity::parse("1e308 km").unwrap_err();
        assert!(
            e.message().contains("`1e308 km` in SI units is too large"),
            "{e}"
        );
        assert!(Quantity::parse("-1e309").is_err());
        assert_eq!(q("1e308 m").value, 1e308);
        assert_eq!(q("1e308 mm").value, 1e305);
    }

    #[test]
    fn course_quantities() {
        assert_eq!(q("9.8 m/s^2"), Quantity::new(9.8, Dimension::ACCELERATION));
        assert_relative_eq!(q("60 km/h").value, 60.0 / 3.6);
        assert_relative_eq!(q("1 g").value, 1e-3);
        assert_eq!(q("2.4 m"), Quantity::new(2.4, Dimension::LENGTH));
        assert_eq!(
            q("4.0 s^2/m^2").dim,
            Dimension::base([-2, 0, 2, 0, 0, 0, 0])
        );
        assert_eq!(q("30 1/m").dim, Dimension::LENGTH.powi(-1));
        assert_eq!(q("30 m^-1"), q("30 1/m"));
        assert_eq!(q("1 N*m^2").dim, Dimension::base([3, 1, -2, 0, 0, 0, 0]));
        assert_relative_eq!(q("1e-8 s").value, 1e-8);
        assert_relative_eq!(q("3000 rpm").value, 100.0 * std::f64::consts::PI);
        assert_relative_eq!(q("90 deg").value, std::f64::consts::FRAC_PI_2);
        assert_relative_eq!(q("2 rev").value, 4.0 * std::f64::consts::PI);
        assert_relative_eq!(q("1.5 h").value, 5400.0);
        assert_relative_eq!(q("16 u").value, 16.0 * 1.660_539_066_60e-27);
        assert_relative_eq!(q("1 eV").value, 1.602_176_634e-19);
        assert_relative_eq!(q("74 pm").value, 74e-12, max_relative = 1e-15);
        assert_relative_eq!(q("1.2 Å").value, 1.2e-10);
        assert_relative_eq!(q("1 AU").value, 1.495_978_707e11);
        assert_eq!(q("-3.5"), Quantity::number(-3.5));
        assert_eq!(q("5 N m").dim, Dimension::ENERGY);
        assert_eq!(q("5 m²").dim, Dimension::base([2, 0, 0, 0, 0, 0, 0]));
        assert_eq!(
            q("1 J/(kg*K)").dim,
            Dimension::base([2, 0, -2, 0, -1, 0, 0])
        );
        assert_eq!(q("1 kg m s⁻¹").dim, Dimension::MOMENTUM);
    }

    #[test]
    fn unknown_unit_suggests_near_names() {
        let e = Quantity::parse("3 mps").unwrap_err();
        assert_eq!(e.message(), "unknown unit `mps`");
        assert!(e.hint().unwrap().starts_with("did you mean `m/s`"), "{e}");
        assert_eq!(e.span, Span::new(2, 5));

        let e = Quantity::parse("3 kgg").unwrap_err();
        assert!(e.hint().unwrap().contains("`kg`"), "{e}");

        let e = Quantity::parse("2 Nm").unwrap_err();
        assert!(e.hint().unwrap().contains("`N*m`"), "{e}");
    }

    #[test]
    fn syntax_errors() {
        assert!(matches!(
            Quantity::parse("m/s").unwrap_err().kind,
            UnitErrorKind::NoNumber
        ));
        assert!(Quantity::parse("3 m/").is_err());
        assert!(Quantity::parse("3 m^x").is_err());
        assert!(Quantity::parse("3 m^99").is_err());
        assert!(Quantity::parse("3 (m").is_err());
        assert!(Quantity::parse("3 m $").is_err());
    }

    #[test]
    fn rational_powers() {
        let hertz = q("1e5 N/m^1.5");
        assert_eq!(hertz, q("1e5 N/m^(3/2)"));
        assert_eq!(hertz.dim.to_string(), "kg/(m^(1/2)*s^2)");
        let m32 = Dimension::LENGTH.pow_ratio(3, 2).unwrap();
        assert_eq!(hertz.dim * m32, Dimension::FORCE);
        assert_eq!(q("1 m^(3/2)").dim, m32);
        assert_eq!(q("1 m^-1.5"), q("1 m^(-3/2)"));
        assert_eq!(q("1 m^-1.5").dim, m32.powi(-1));
        assert_eq!(q("1 m**1.5").dim, m32);
        assert_eq!(q("1 m^( 3 / 2 )").dim, m32);
        assert_eq!(q("1 s^0.5").dim.to_string(), "s^(1/2)");
        assert_eq!(q("1 kg^(1/2)").dim.to_string(), "kg^(1/2)");
        assert_eq!(q("1 m^0.25").dim.to_string(), "m^(1/4)");
        assert_eq!(q("1 m^(6/4)").dim, m32);
        // exact: two halves make a whole, no rounding
        assert_eq!(q("1 m^0.5*m^0.5").dim, Dimension::LENGTH);
        assert_eq!(q("1 m^(1/3)*m^(1/3)*m^(1/3)").dim, Dimension::LENGTH);
        // sizes follow: 1 km^1.5 is 1000^1.5 m^1.5
        assert_relative_eq!(q("1 km^1.5").value, 1000f64.powf(1.5));
        assert_relative_eq!(q("2 N/cm^(3/2)").value, 2.0 / 0.01f64.powf(1.5));
    }

    #[test]
    fn nested_powers_are_exact() {
        let d = q("1 (((m^12)^12)^12)^12").dim;
        assert_eq!(d.to_string(), "m^20736");
        assert_eq!(d, Dimension::LENGTH.checked_powi(20_736).unwrap());
        // an energy never passes as a force
        assert_ne!(
            q("1 J*(((m^12)^12)^12)^12").dim,
            q("1 N*(((m^12)^12)^12)^12").dim
        );
        // sizes that leave floating point are refused, not infinite
        let e = Quantity::parse("1 (((km^12)^12)^12)^12").unwrap_err();
        assert!(matches!(e.kind, UnitErrorKind::TooLarge(_)), "{e}");
        assert!(
            e.message().contains("too large to hold in floating point"),
            "{e}"
        );
    }

    #[test]
    fn bad_powers_say_why() {
        let e = Quantity::parse("3 m^0.333333").unwrap_err();
        assert!(matches!(e.kind, UnitErrorKind::Power { .. }), "{e}");
        assert!(e.message().contains("q at most 1000"), "{e}");
        assert!(e.hint().unwrap().contains("m^(1/3)"), "{e}");
        assert_eq!(e.span, Span::new(4, 12));

        let e = Quantity::parse("1e5 N/m^3/2").unwrap_err();
        assert!(e.message().contains("needs parentheses"), "{e}");
        assert_eq!(e.hint().unwrap(), "write `^(3/2)`");
        assert_eq!(e.span, Span::new(8, 11));

        let e = Quantity::parse("3 m^99").unwrap_err();
        assert!(e.message().contains("out of range"), "{e}");
        let e = Quantity::parse("3 m^(25/2)").unwrap_err();
        assert!(e.message().contains("out of range"), "{e}");
        for (bad, says) in [
            ("3 m^x", "expected a number after `^`, found `x`"),
            ("3 m^", "found the end"),
            ("3 m^(1/0)", "not a fraction of whole numbers"),
            ("3 m^(1.5/2)", "not a fraction of whole numbers"),
            ("3 m^(3/-2)", "not a fraction of whole numbers"),
            ("3 m^1.2.3", "not a short decimal"),
            ("3 m^1.", "not a short decimal"),
            ("3 m^(1/2000)", "q at most 1000"),
        ] {
            let e = Quantity::parse(bad).unwrap_err();
            assert!(e.message().contains(says), "{bad}: {e}");
        }
        assert!(matches!(
            Quantity::parse("3 m^(3/2").unwrap_err().kind,
            UnitErrorKind::Syntax(_)
        ));
    }

    #[test]
    fn value_in_other_unit() {
        let v = q("10 m/s");
        assert_relative_eq!(v.value_in(&Unit::parse("km/h").unwrap()).unwrap(), 36.0);
        assert!(v.value_in(&Unit::parse("kg").unwrap()).is_none());
    }
}
