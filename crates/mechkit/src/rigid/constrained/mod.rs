//! Motion constrained to a curve: a bead or a particle on a circle or on a graph y(x) in a
//! vertical plane under uniform gravity, without friction.
//!
//! The curve is a parametrised path r(q) (q = x for a graph, q = φ, the angle from the top,
//! for a circle of radius R about the origin: r = (R sin φ, R cos φ)). With r' = dr/dq,
//! Newton's law along the tangent gives the equation of motion
//!
//! q̈ = −(g y'(q) + (r'·r'') q̇²) / |r'|²,
//!
//! and along the unit normal n (the tangent turned counter-clockwise: up for a graph,
//! outward for a circle) the normal force
//!
//! N·n = m ((r''·n) q̇² + g n_y),
//!
//! i.e. m(v²κ + g cos β) with the curvature κ and the slope angle β. A body resting on one side
//! of the curve ([`Side::Outer`]: on top of a graph, outside a circle; [`Side::Inner`]: below,
//! inside) can only be pushed: when N reaches zero it leaves the curve. The motion is integrated
//! with Dormand-Prince 5(4) by the one event driver ([`crate::ode::run_to_event`]): leaving is a
//! terminal event, N enclosed by interval arithmetic on the curve's r′ and r″ (so a dip below
//! zero narrower than a step is found), the step redone to end there; the body then flies
//! freely, integrated too, until it meets the curve again (the landing, an enclosed event on its
//! gap from the curve) or `t_max`. The turning points are events where q̇ changes sign. A
//! threaded bead ([`Side::Bead`]) never leaves; the curve pulls or pushes as needed.
//!
//! Checks (tests in `tests/rigid/constrained.rs`): sliding off a frictionless cylinder from the
//! top leaves at cos θ = 2/3 + v₀²/(3gR); the loop-the-loop needs h = 5R/2; a bead on a circle
//! is a pendulum with the exact period; energy is conserved while on the curve.
//!
//! [`BeadOnCurve::report`] is the answer of `mechkit bead` as a value ([`BeadReport`]): with
//! the table and the plot, and at an equilibrium start its stability and, at an unstable top,
//! where the slightest push would make the body leave ([`Equilibrium`]).

mod curve;
mod error;
mod flight;
mod report;
mod run;
mod smooth;

pub use curve::{Curve, Side};
pub use error::ConstrainedError;
pub use report::{BeadFiles, BeadReport, DepartureReport, Equilibrium, LeavingPoint};
pub use run::{BeadOnCurve, BeadRun, BeadSample, Departure, Landing, Start, StopReason};
pub use smooth::Break;
