//! Rotation and rigid bodies: angular kinematics and circular motion, friction and contact,
//! motion constrained to a curve, rotation about a fixed axis, planar bodies rolling and
//! slipping, rigid impacts, and free rigid bodies in 3-D.
//!
//! Each model is a value type with a checked constructor and its own error type, integrated
//! by the steppers of [`crate::ode`]; regime switches (stick to slip, slipping to rolling,
//! leaving a surface) are located inside a step, never detected a step late.

pub mod constrained;
pub mod elliptic;
pub mod fixed_axis;
pub mod free3d;
pub mod friction;
pub mod impact;
pub mod kinematics;
pub mod rolling;
