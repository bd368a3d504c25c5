//! Rotation and rigid bodies: angular kinematics and circular motion ([`kinematics`]),
//! friction and stick-slip ([`friction`]), motion constrained to a curve ([`constrained`]),
//! rotation about a fixed axis ([`fixed_axis`], the bodies of `[[rigid_body]]` scenarios),
//! planar bodies rolling and slipping ([`rolling`]), rigid impacts ([`mod@impact`]), and free
//! rigid bodies and tops in 3-D ([`free3d`]); [`rotation`] holds the answers of rotation
//! questions as values, [`Input`] names the inputs that errors are about, and [`elliptic`]
//! holds the elliptic integrals and Jacobi functions the exact solutions are written in
//! (re-exported from the crate root).
//!
//! Each model is a value type with a checked constructor and its own error type, integrated
//! by the steppers of [`crate::ode`]; regime switches (stick to slip, slipping to rolling,
//! leaving a surface, a wheel stopping) are events of the one driver
//! ([`crate::ode::run_to_event`]), located inside a step, never detected a step late.

pub mod at;
pub mod constrained;
pub mod fixed_axis;
pub mod free3d;
pub mod friction;
pub mod impact;
mod input;
pub mod kinematics;
pub mod mechanism;
pub mod rolling;
pub mod rotation;

pub use crate::elliptic;
pub use constrained::{BeadOnCurve, Curve};
pub use fixed_axis::HingedBody;
pub use free3d::{FreeBody, SpinningBody};
pub use friction::{Coulomb, Incline, SpringBlock};
pub use impact::{Particle, PivotedBody, PlanarBody, hinged_impact, impact};
pub use input::Input;
pub use kinematics::{AngularMotion, CircularMotion, UniformAngularAcceleration};
pub use rolling::{RollingBody, RollingMotion};
