//! A quantity with units in SI, its dimension, and its value in another unit.

use mechkit_expr::units::{Dimension, Quantity, Unit};

use super::CalculusError;
use crate::Real;

/// The value in a requested unit.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Converted {
    /// The value in `unit`.
    pub value: Real,
    /// The unit, as given.
    pub unit: String,
}

/// A quantity in SI and, when asked, in another unit: the answer of `mechkit units`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Conversion {
    /// The quantity as given.
    pub input: String,
    /// The value in SI units.
    pub si: Real,
    /// The SI unit: the derived unit's symbol (`N`, `J`) or the base units (`m/s`).
    pub si_unit: String,
    /// Its dimension (`m/s`; the text in JSON).
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::display"))]
    pub dimension: Dimension,
    /// What the dimension measures (`velocity`), or empty when it has no name.
    pub quantity: String,
    /// The value in the requested unit.
    pub converted: Option<Converted>,
}

impl Conversion {
    /// Whether the requested unit is the SI unit itself (the conversion says nothing new).
    pub fn converted_to_si(&self) -> bool {
        self.converted
            .as_ref()
            .is_some_and(|c| c.value == self.si && c.unit.replace(' ', "") == self.si_unit)
    }
}

/// Converts `quantity` (`"60 km/h"`) to SI, and to `to` if given.
///
/// ```
/// let c = mechkit::calculus::convert("60 km/h", Some("m/s")).unwrap();
/// assert!((c.si - 16.666_666_666_666_668).abs() < 1e-12);
/// assert_eq!((c.si_unit.as_str(), c.quantity.as_str()), ("m/s", "velocity"));
/// assert!(c.converted_to_si());
/// ```
pub fn convert(quantity: &str, to: Option<&str>) -> Result<Conversion, CalculusError> {
    let q = Quantity::parse(quantity)?;
    let converted = match to {
        None => None,
        Some(u) => {
            let unit = Unit::parse(u)?;
            let v = q.value_in(&unit).ok_or_else(|| {
                CalculusError::Invalid(format!(
                    "cannot convert {} to {u}: the dimensions differ ({} vs {}); give --to a unit \
                     of {}, or leave it out to see the value in SI units",
                    quantity,
                    q.dim.describe(),
                    unit.dim.describe(),
                    q.dim.describe()
                ))
            })?;
            Some(Converted {
                value: v,
                unit: u.to_string(),
            })
        }
    };
    Ok(Conversion {
        input: quantity.to_string(),
        si: q.value,
        si_unit: q
            .dim
            .derived_symbol()
            .map_or_else(|| q.dim.to_string(), str::to_string),
        dimension: q.dim,
        quantity: q.dim.quantity_name().unwrap_or("").to_string(),
        converted,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units() {
        let c = convert("60 km/h", Some("m/s")).unwrap();
        assert!((c.si - 16.666_666_666_666_668).abs() < 1e-12);
        assert!((c.converted.as_ref().unwrap().value - c.si).abs() < 1e-12);
        assert!(c.converted_to_si());
        let au = convert("1 AU", Some("km")).unwrap();
        assert!(!au.converted_to_si());
        let e = convert("60 km/h", Some("kg")).unwrap_err().to_string();
        assert!(e.contains("dimensions differ"), "{e}");
    }
}
