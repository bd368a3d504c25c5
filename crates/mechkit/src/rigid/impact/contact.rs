//! The contact of an impact, and the planar vector products.

use super::error::ImpactError;
use crate::Real;
use crate::rigid::Input;

/// A contact: the point, the unit normal from the first body into the second, and the
/// coefficient of restitution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// The contact point (m).
    pub point: [Real; 2],
    /// The normal, from the first body into the second (normalised when checked).
    pub normal: [Real; 2],
    /// Coefficient of restitution, 0 (plastic) to 1 (elastic).
    pub restitution: Real,
}

impl Contact {
    /// The contact with a unit normal, checked.
    pub(crate) fn checked(&self) -> Result<Contact, ImpactError> {
        let n = self.normal[0].hypot(self.normal[1]);
        if !(n > 0.0 && n.is_finite()) {
            return Err(ImpactError::Normal {
                normal: self.normal,
            });
        }
        let e = self.restitution;
        if !(0.0..=1.0).contains(&e) {
            return Err(ImpactError::Restitution { value: e });
        }
        if !self.point.iter().all(|v| v.is_finite()) {
            return Err(ImpactError::Value {
                input: Input::ContactPoint,
                what: "the contact point",
                value: self.point[0] + self.point[1],
                must_be: "finite",
            });
        }
        Ok(Contact {
            normal: [self.normal[0] / n, self.normal[1] / n],
            ..*self
        })
    }
}

/// The z component of the planar cross product a × b.
pub(crate) fn cross(a: [Real; 2], b: [Real; 2]) -> Real {
    a[0] * b[1] - a[1] * b[0]
}

/// ω ẑ × r.
pub(crate) fn spin(omega: Real, r: [Real; 2]) -> [Real; 2] {
    [-omega * r[1], omega * r[0]]
}
