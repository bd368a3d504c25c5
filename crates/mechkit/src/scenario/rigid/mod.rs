//! `[[rigid_body]]` and `[[torque]]`: rigid bodies hinged to the world, each turning about a
//! fixed axis, and the torques on them. A scenario with rigid bodies is run in angle
//! coordinates ([`crate::particles::Coordinates::Angle`]): formulas use `theta`, `omega`,
//! `alpha`, `I` instead of `x`, `v`, `a`, `m`.

pub(crate) mod bodies;
mod build;
mod torques;

pub(crate) use build::{RIGID_RESERVED, build_rigid};
