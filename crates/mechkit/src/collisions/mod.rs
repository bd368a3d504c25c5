//! Momentum, impulse and collisions: one collision of two bodies resolved by an impulse with a
//! coefficient of restitution and Coulomb friction ([`Collision`]).

mod resolve;

pub use resolve::{Collision, CollisionError, Outcome, Resolution, Restitution};
