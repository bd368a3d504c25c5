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
//!
//! `w` is the wind: still air, a constant vector, or a formula of position and time ([`Wind`]).

mod constant;
mod drag;
mod expression;
mod force;
mod gravity;
mod set;
mod spring;
mod wind;

pub use constant::ConstantForce;
pub use drag::{LinearDrag, QuadraticDrag};
pub use expression::ExpressionForce;
pub use force::{Force, Target};
pub use gravity::{Attractor, NewtonianGravity, UniformGravity};
pub use set::ForceSet;
pub use spring::{Spring, SpringEnds};
pub use wind::Wind;
