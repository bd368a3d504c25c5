//! Rotation and rigid bodies: exact solutions, conservation laws, regime switches located
//! to closed-form times.

mod constrained;
mod fixed_axis;
mod free3d;
mod friction;
mod impact;
mod kinematics;
mod rolling;
