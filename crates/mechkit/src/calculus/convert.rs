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
    let angular = names_a_unit(quantity, ANGLES);
    let converted = match to {
        None => None,
        Some(u) => {
            let unit = Unit::parse(u)?;
            if angular != names_a_unit(u, ANGLES)
                && (names_a_unit(u, HERTZ) || names_a_unit(quantity, HERTZ))
            {
                // rad counts as 1, so `3000 rpm` is 314.159 per second: as rad/s, not Hz
                return Err(CalculusError::Invalid(format!(
                    "cannot convert {quantity} to {u}: one is an angular speed (an angle per time) and the other a frequency in Hz (cycles per second), which differ by 2π; convert between rad/s, rev/s, rpm and deg/s, or between Hz and 1/s (a rotation of 50 rev/s has a frequency of 50 Hz and an angular speed of 314.16 rad/s)"
                )));
            }
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
        // an angle per time is in rad/s, never Hz (cycles per second)
        si_unit: if angular && q.dim == Dimension::FREQUENCY {
            "rad/s".to_string()
        } else {
            q.dim
                .derived_symbol()
                .map_or_else(|| q.dim.to_string(), str::to_string)
        },
        dimension: q.dim,
        quantity: q.dim.quantity_name().unwrap_or("").to_string(),
        converted,
    })
}

use crate::values::{ANGLES, HERTZ, names_a_unit};

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

    /// `3000 rpm` was "314.159 Hz" (rad counts as 1, and Hz is 1/s): a rotation of 3000 rpm
    /// has a frequency of 50 Hz. Angle rates are shown in rad/s, and converting between one
    /// and Hz is refused with the 2π spelled out.
    #[test]
    fn an_angular_speed_is_never_in_hertz() {
        let c = convert("3000 rpm", None).unwrap();
        assert_eq!(c.si_unit, "rad/s");
        assert!((c.si - 100.0 * std::f64::consts::PI).abs() < 1e-9);
        let rev = convert("3000 rpm", Some("rev/s")).unwrap();
        assert!((rev.converted.unwrap().value - 50.0).abs() < 1e-12);
        for (q, to) in [("3000 rpm", "Hz"), ("50 Hz", "rpm"), ("1 kHz", "rad/s")] {
            let e = convert(q, Some(to)).unwrap_err().to_string();
            assert!(e.contains("differ by 2π"), "{q} to {to}: {e}");
        }
        assert_eq!(convert("50 Hz", None).unwrap().si_unit, "Hz");
        assert!(
            (convert("50 Hz", Some("1/s"))
                .unwrap()
                .converted
                .unwrap()
                .value
                - 50.0)
                .abs()
                < 1e-12
        );
    }
}
