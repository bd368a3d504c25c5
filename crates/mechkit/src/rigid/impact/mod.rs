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
//! ΔK = −½ (1 − e²) m_eff u² exactly. A body hinged at a pivot O ([`PivotedBody`]) takes an
//! unknown impulse from the hinge, so its response is written about O: its term is
//! (r_O × n)²/I_O with no 1/m, the angular momentum about O is conserved, and the hinge impulse
//! follows from the change of the body's momentum. An immovable body ([`PlanarBody::fixed`]:
//! the ground) has 1/m = 1/I = 0.
//!
//! Checks (tests in `tests/rigid/impact.rs`): the hinged rod struck by a block (c16-B6),
//! angular momentum about the hinge conserved to 1e-12, the energy loss against the closed
//! form, zero hinge impulse at the centre of percussion, two free bodies conserving P and L,
//! a rod landing on its end.
//!
//! [`hinged_report`] and [`rod_landing`] are the answers of `mechkit rigid-collide` as values.

mod contact;
mod error;
mod free;
mod hinged;
mod report;

pub use contact::Contact;
pub(crate) use contact::{cross, spin};
pub use error::ImpactError;
pub use free::{FreeImpact, PlanarBody, impact};
pub use hinged::{HingedImpact, Particle, PivotedBody, hinged_impact, release_omega};
pub use report::{
    AngularMomentumChange, BeforeAfter, BlockNumbers, ContactNumbers, HingedBodyNumbers,
    HingedReport, KineticEnergy, LandingEnergy, LandingReport, RodMotion, RodNumbers,
    hinged_report, rod_landing,
};
