//! Rigid-body impacts in the plane: an impulse at a contact point with a coefficient of
//! restitution, frictionless, with the angular impulse it carries.
//!
//! At the contact point P with unit normal n (from body A into body B) the normal relative
//! velocity is u = (v_B(P) − v_A(P))·n with v(P) = v_cm + ω × (P − x_cm). An impulse J n on B
//! (−J n on A) changes u by J/m_eff, with
//!
//! 1/m_eff = 1/m_A + 1/m_B + (r_A × n)²/I_A + (r_B × n)²/I_B,
//!
//! r the arm from each centre of mass to P and I the moment of inertia about it; Newton's law
//! of restitution u' = −e u gives J = −(1 + e) m_eff u, and the kinetic energy changes by
//! ΔK = −½ (1 − e²) m_eff u² exactly. A body hinged at a pivot O ([`HingedBody`]) takes an
//! unknown impulse from the hinge, so its response is written about O: its term is
//! (r_O × n)²/I_O with no 1/m, the angular momentum about O is conserved, and the hinge impulse
//! follows from the change of the body's momentum. An immovable body ([`PlanarBody::fixed`]:
//! the ground) has 1/m = 1/I = 0.
//!
//! Checks (tests in `tests/rigid/impact.rs`): the hinged rod struck by a block (c16-B6),
//! angular momentum about the hinge conserved to 1e-12, the energy loss against the closed
//! form, zero hinge impulse at the centre of percussion, two free bodies conserving P and L,
//! a rod landing on its end.

mod error;
mod free;
mod hinged;

pub use error::ImpactError;
pub use free::{FreeImpact, PlanarBody, impact};
pub use hinged::{HingedBody, HingedImpact, Particle, hinged_impact, release_omega};

use crate::Real;

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
