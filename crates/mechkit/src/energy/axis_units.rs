//! The units of an energy diagram's axes: known where the user gave units (a range in
//! metres, a parameter in electronvolts) and the formula's dimension follows from them;
//! unknown for a formula of bare numbers, whose axes are then labelled by name alone.

use mechkit_expr::units::Dimension;
use mechkit_expr::{Dim, Formula};

use super::analysis::Given;
use crate::data::quotient_unit;

/// The units of the diagram's axes, where they are known (a formula of values given without
/// units has none): the variable's (`m`) and the potential's (`J`).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AxisUnits {
    /// The unit of the variable.
    pub x: Option<String>,
    /// The unit of the potential.
    pub potential: Option<String>,
}

impl AxisUnits {
    /// The units that follow from the dimensions of the names: `dims(name)` is the dimension
    /// of a name's value when it was given with units (`None` for a bare number, or not
    /// given), `dims(var)` that of the variable (a range given in metres). `U` has a unit when
    /// its formula (or `F` times the variable, for a force) comes out as an energy.
    ///
    /// ```
    /// use mechkit::energy::{AxisUnits, Given};
    /// use mechkit::units::Dimension;
    /// let lj = Given::Potential("U0*((a/r)^12 - (a/r)^6)");
    /// let none = AxisUnits::infer(lj, "r", &|_| None);
    /// assert_eq!(none, AxisUnits::default());
    /// let dims = |n: &str| match n {
    ///     "U0" => Some(Dimension::ENERGY),
    ///     "a" | "r" => Some(Dimension::LENGTH),
    ///     _ => None,
    /// };
    /// let known = AxisUnits::infer(lj, "r", &dims);
    /// assert_eq!((known.x.as_deref(), known.potential.as_deref()), (Some("m"), Some("J")));
    /// ```
    pub fn infer(given: Given<'_>, var: &str, dims: &dyn Fn(&str) -> Option<Dimension>) -> Self {
        let unit = |d: Dimension| {
            d.derived_symbol()
                .map_or_else(|| d.to_string(), str::to_string)
        };
        let x_dim = dims(var).filter(|d| !d.is_none());
        let (text, times_x) = match given {
            Given::Potential(t) => (t, false),
            Given::Force(t) => (t, true),
        };
        let name_dim = |n: &str| {
            dims(n)
                .filter(|d| !d.is_none())
                .map_or(Dim::Unknown, Dim::Known)
        };
        let formula_dim = Formula::parse(text)
            .ok()
            .and_then(|f| f.dimension(&name_dim).ok())
            .and_then(Dim::known);
        let u_dim = match (formula_dim, times_x) {
            (Some(d), false) => Some(d),
            (Some(f), true) => x_dim.map(|x| f * x),
            (None, _) => None,
        };
        Self {
            x: x_dim.map(unit),
            potential: u_dim.filter(|d| !d.is_none()).map(unit),
        }
    }

    /// `name [unit]`, or `name` when the unit is not known.
    pub(crate) fn label(name: &str, unit: Option<&str>) -> String {
        unit.map_or_else(|| name.to_string(), |u| format!("{name} [{u}]"))
    }

    /// The force's unit (`U` over `x`), when both are known.
    pub fn force(&self) -> Option<String> {
        Some(quotient_unit(
            self.potential.as_deref()?,
            self.x.as_deref()?,
            1,
        ))
    }

    /// The speed's unit: m/s when `U` is in joules (the mass is in kilograms).
    pub fn speed(&self) -> Option<String> {
        (self.potential.as_deref() == Some("J")).then(|| "m/s".to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_follow_the_names() {
        let dims = |n: &str| match n {
            "k" => Some(Dimension::STIFFNESS),
            "x" => Some(Dimension::LENGTH),
            _ => None,
        };
        let spring = AxisUnits::infer(Given::Force("-k*x"), "x", &dims);
        assert_eq!(spring.potential.as_deref(), Some("J"));
        assert_eq!(spring.force().as_deref(), Some("N"));
        assert_eq!(spring.speed().as_deref(), Some("m/s"));
        let bare = AxisUnits::infer(Given::Force("-k*x"), "x", &|_| None);
        assert_eq!(bare, AxisUnits::default());
        assert!(bare.force().is_none() && bare.speed().is_none());
    }
}
