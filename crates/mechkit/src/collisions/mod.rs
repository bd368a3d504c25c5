//! Momentum, impulse and collisions: one collision of two bodies resolved by an impulse with a
//! coefficient of restitution and Coulomb friction ([`Collision`]; as a front states it,
//! [`CollisionSetup`], with its [`CollisionReport`]), and the event-driven
//! collisions of spheres and walls in a simulation ([`Impacts`]).

mod impacts;
mod report;
mod resolve;

pub use impacts::{Impacts, Overlap, Wall};
pub use report::{
    CmFrame, Collided, CollisionInput, CollisionReport, CollisionSetup, Contact, NoCollision, Rise,
    VelocityPair,
};
pub use resolve::{Collision, CollisionError, Outcome, Resolution, Restitution};
