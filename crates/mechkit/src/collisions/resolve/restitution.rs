//! The coefficient of restitution `e`, checked to lie in `[0, 1]`: `e = 1` keeps the kinetic
//! energy (elastic), `e = 0` leaves the bodies moving on together along the normal
//! (perfectly inelastic); in between the separation speed is `e` times the approach speed.

use super::CollisionError;
use crate::Real;

/// A coefficient of restitution, checked: `0 ≤ e ≤ 1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Restitution(Real);

impl Restitution {
    /// `e = 1`: kinetic energy is conserved.
    pub const ELASTIC: Restitution = Restitution(1.0);
    /// `e = 0`: the bodies move on together along the normal.
    pub const PERFECTLY_INELASTIC: Restitution = Restitution(0.0);

    /// `e`, checked to be in `[0, 1]`.
    pub fn new(e: Real) -> Result<Self, CollisionError> {
        if (0.0..=1.0).contains(&e) {
            Ok(Self(e))
        } else {
            Err(CollisionError::Restitution { e })
        }
    }

    /// A preset by name (`elastic`, `perfectly-inelastic` or `plastic`) or a number.
    pub fn parse(text: &str) -> Result<Self, CollisionError> {
        match text.trim().to_ascii_lowercase().as_str() {
            "elastic" => Ok(Self::ELASTIC),
            "perfectly-inelastic" | "perfectly_inelastic" | "plastic" => {
                Ok(Self::PERFECTLY_INELASTIC)
            }
            other => match other.parse::<Real>() {
                Ok(e) => Self::new(e),
                Err(_) => Err(CollisionError::RestitutionName {
                    text: text.to_string(),
                }),
            },
        }
    }

    /// The value.
    pub fn value(self) -> Real {
        self.0
    }
}
