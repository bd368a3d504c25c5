//! Rotation about a fixed axis: a rigid body hinged to the world ([`HingedBody`]), the torques
//! acting on it ([`torques`]), the physical pendulum's periods ([`pendulum`]), and the system
//! that the simulation runs.
//!
//! The coordinate is the angle `θ` of the body about the axis, counter-clockwise seen from
//! the tip of the axis, zero in the configuration the body was described in. Newton's second
//! law for rotation, `I α = Σ τ`, with `I` the moment of inertia about the axis (plus `m r²`
//! of every weight hanging from a drum on the axle), is a one-coordinate mechanical system:
//! the simulation runs it as a [`ParticleSystem`] in [`Coordinates::Angle`], so every
//! integrator, event, stop condition and the energy ledger (the work `∫τ ω dt` of each
//! torque, `K = ½ I ω²`) apply unchanged, and the momentum side of the ledger is the angular
//! momentum `I ω` with the angular impulses `∫τ dt` of the torques.

mod hinge;
pub mod pendulum;
pub mod torques;

pub use hinge::{FixedAxisError, HingedBody};

use crate::forces::Force;
use crate::particles::{Coordinates, ParticleSystem, SystemError};

/// The system of hinged bodies under torques: one angle per body.
///
/// # Example
/// A uniform rod of 1 m and 2 kg hinged at its end, hanging down, in gravity:
/// ```
/// use mechkit::mass::{MassProperties, Mat3, Vec3};
/// use mechkit::rigid::fixed_axis::{HingedBody, system};
/// let rod = MassProperties::new(2.0, Vec3::new(0.0, -0.5, 0.0),
///     Mat3::from_diagonal(&Vec3::new(2.0 / 12.0, 0.0, 2.0 / 12.0)));
/// let body = HingedBody::new("rod", &rod, Vec3::zeros(), Vec3::z()).unwrap();
/// assert!((body.moment() - 2.0 / 3.0).abs() < 1e-15);
/// let gravity = body.gravity("gravity", 0, Vec3::new(0.0, -9.81, 0.0));
/// let sys = system(&[body], vec![Box::new(gravity)]).unwrap();
/// assert_eq!(sys.masses(), &[2.0 / 3.0]);
/// ```
pub fn system(
    bodies: &[HingedBody],
    torques: Vec<Box<dyn Force>>,
) -> Result<ParticleSystem, SystemError> {
    let mut builder = ParticleSystem::builder(1).coordinates(Coordinates::Angle);
    for b in bodies {
        builder = builder.body(b.name(), b.effective_moment());
    }
    for t in torques {
        builder = builder.boxed_force(t);
    }
    builder.build()
}
