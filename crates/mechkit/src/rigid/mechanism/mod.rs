//! Planar mechanisms: particles and rigid bodies in a plane, joined to each other and to the
//! world by joints, run as one particle system.
//!
//! **Coordinates.** Every body has its centre of mass `(x, y)` among the particle system's
//! positions; a rigid body also has an angle `θ` among the system's extra coordinates, whose
//! "mass" is its moment of inertia about the centre of mass (in a plane the equations of
//! rotation are `I θ̈ = τ`, with no gyroscopic term, so the mass matrix stays diagonal). The
//! modes of the joints that switch (a contact touching or apart, a string taut or slack, a
//! contact sticking or sliding) are frozen extra coordinates: their rate is zero and only the
//! events of the joints change them.
//!
//! **Joints** are constraints `C(q) = 0` (or `≥ 0`, unilateral) on body points. With the
//! applied forces `F` the constraint forces are `Dᵀλ`, with `λ` from
//! `J M⁻¹ Dᵀ λ = −(J M⁻¹ F + J̇ v + 2 J v/τ + C/τ²)`: the acceleration form of the constraint
//! with Baumgarte's stabilisation (time constant `τ`), so the drift of `C` decays instead of
//! growing. `D = J` except for a sliding contact, whose normal row also carries the kinetic
//! friction `−μₖ s N` along the surface (`s` the sliding direction). Each joint is a
//! [`crate::forces::Force`] ([`JointForce`]) acting after the applied forces, so the energy
//! ledger books its work by name: ideal joints do no work (up to the drift), friction does.
//!
//! **Switching** (`events`): a contact or a string lets go when its force reaches zero, and
//! engages when the gap closes (an inelastic impulse removes the approach speed, its
//! tangential part bounded by Coulomb friction: `impact`; then, as at the start, a contact
//! sticks only where static friction holds it, since no event sees a bound broken from the
//! outset); a sticking contact starts to slide when the friction it needs exceeds `μₛ N`, and a sliding one sticks
//! when its sliding speed reaches zero, if static friction can then hold it (else it slides
//! back the other way). Rolling without slipping is a disk's contact that sticks.

mod force;
mod gauss;
mod impact;
mod joint;
mod modes;
mod rows;
mod solve;

pub use super::at::AppliedAt;
pub use force::JointForce;
pub use joint::{Anchor, Curve, Friction, Joint, JointKind, distance};
pub use solve::{Mechanism, MechanismBody, REPORT_FIELDS, REPORT_LEN};
