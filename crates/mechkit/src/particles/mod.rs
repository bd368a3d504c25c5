//! Systems of point particles in 1, 2 or 3 dimensions: bodies, their state, the forces on them,
//! and the names by which formulas refer to them.
//!
//! Positions and velocities are flat arrays, body after body: `q = [x₀, y₀, x₁, y₁, …]`, and
//! the state vector of the system is `[q, v]` ([`crate::ode::State`]).

mod body_refs;
mod enclosure;
mod kinematics;
mod names;
mod sample;
pub mod spin;
mod state_expr;
mod system;
mod vars;

pub use body_refs::{PointRef, SpinField, SpinRef};
pub use enclosure::StateJets;
pub use kinematics::{Kinematics, dot, norm};
pub use names::{NO_PLANAR, NameContext, PlanarNames, RigidName};
pub use sample::{Evaluation, Sample, SampleKind};
pub use state_expr::StateExpr;
pub use system::{
    Body, CompiledJacobian, Extra, ParticleSystem, ParticleSystemBuilder, SystemError,
};
pub use vars::{BodyRef, Coordinates, StateVar, VarLevel};
