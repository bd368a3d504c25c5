//! Force laws. Each is a small named value type that adds its contribution to a force buffer
//! (`dim` components per body) and, when conservative, reports its potential energy so the
//! energy ledger can be exact.
//!
//! | type | force on a body | potential |
//! |---|---|---|
//! | [`ConstantForce`] | `F` | `-F·x` |
//! | [`UniformGravity`] | `-m g ê_up` (last axis is up) | `m g x_up` |
//! | [`NewtonianGravity`] | `-G M m r̂/r²` (fixed centre) or between every pair | `-G M m/r` |
//! | [`Spring`] | `-k (r - L) r̂` (to an anchor or between two bodies) | `k (r - L)²/2` |
//! | [`LinearDrag`] | `-b (v - w)` | — |
//! | [`QuadraticDrag`] | `-D |v - w| (v - w)` | — |
//! | [`ExpressionForce`] | a formula per component | — |
//! | [`PairForce`] | `-dU/dr` along the line of centres, for each pair (derived symbolically) | `U(r)` per pair |
//! | [`ContactForce`] | `F_e(δ) n̂` while overlapping by `δ > 0`: `k δ` or `k δ^(3/2)` (sphere pairs, walls) | `k δ²/2` or `(2/5) k δ^(5/2)` |
//! | [`ContactDamper`] | its damping: `c δ̇` or `α F_e δ̇` along `n̂`, total clamped at `≥ 0` | — |
//!
//! `w` is the wind: still air, a constant vector, or a formula of position and time ([`Wind`]).

mod constant;
mod contact;
mod contact_builder;
mod contact_damper;
mod contact_emit;
mod contact_law;
mod drag;
mod emit;
mod expression;
mod force;
mod gravity;
mod pair;
mod set;
mod spring;
mod thrust;
mod wind;

pub mod terminal;

pub use constant::ConstantForce;
pub use contact::ContactForce;
pub use contact_builder::{ContactError, ContactForceBuilder, ContactPair, ContactWall};
pub use contact_damper::ContactDamper;
pub use contact_law::{
    ContactDamping, ContactLaw, hertz_contact_time, hertz_max_overlap, linear_contact_time,
    linear_damping_ratio, linear_restitution, linear_restitution_clamped,
};
pub use drag::{LinearDrag, QuadraticDrag};
pub use emit::ForceEmitter;
pub use expression::ExpressionForce;
pub use force::{Force, Target};
pub use gravity::{Attractor, NewtonianGravity, UniformGravity};
pub use pair::{PairError, PairForce, RadialPotential};
pub use set::ForceSet;
pub use spring::{Spring, SpringEnds};
pub use thrust::{Exhaust, Thrust};
pub use wind::Wind;
