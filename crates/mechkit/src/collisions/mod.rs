//! Momentum, impulse and collisions: one collision of two bodies resolved by an impulse with a
//! coefficient of restitution and Coulomb friction ([`Collision`]), and the event-driven
//! collisions of spheres and walls in a simulation ([`Impacts`]).

mod impacts;
mod resolve;

pub use impacts::{Impacts, Overlap, Wall};
pub use resolve::{Collision, CollisionError, Outcome, Resolution, Restitution};
