//! Ordinary differential equations: systems, states and the steppers that advance them.
//!
//! A first-order system is `y' = f(t, y)` ([`OdeSystem`]); a mechanical system is second order,
//! `q'' = a(t, q, q')` ([`SecondOrderSystem`]), with the state laid out as `y = [q, v]`.
//! Every second-order system is also a first-order one, so general methods (Euler, RK4) run
//! on both, while Euler-Cromer and velocity Verlet use the split into positions and
//! velocities.
//!
//! Fixed-step methods, with `h` the step and `a_n = a(t_n, q_n, v_n)`:
//!
//! | method | update | global order |
//! |---|---|---|
//! | [`Euler`] | `y_{n+1} = y_n + h f(t_n, y_n)` | 1 |
//! | [`EulerCromer`] | `v_{n+1} = v_n + h a_n`, then `q_{n+1} = q_n + h v_{n+1}` | 1 (symplectic) |
//! | [`VelocityVerlet`] | `q_{n+1} = q_n + h v_n + h²/2 a_n`, `v_{n+1} = v_n + h/2 (a_n + a_{n+1})` | 2 (symplectic) |
//! | [`Rk4`] | classical fourth-order Runge-Kutta | 4 |
//!
//! Adaptive pairs ([`AdaptiveRk`], settings [`AdaptiveConfig`]; the models use
//! [`AdaptiveConfig::from_rtol`] and [`AdaptiveConfig::sampled_over`]) run any system with
//! events through [`run_to_event`] ([`events`]): crossings of `g(t, y) = 0` found inside every
//! step, with a guarantee where `g` has an enclosure, in time order.

mod adaptive;
mod band_plan;
mod banded;
mod bdf;
mod blocks;
mod control;
mod dense;
mod dop853;
mod euler;
mod euler_cromer;
pub mod events;
mod explicit_rk;
mod fixed;
mod hermite;
mod linalg;
mod method;
mod newton_lu;
mod pattern;
mod polynomial;
mod proof;
mod radau5;
mod radau_tableau;
mod reduction;
pub mod reference;
mod rk4;
mod series;
mod stages;
mod state;
mod stepper;
mod stiffness;
mod symplectic;
mod system;
mod tableau;
pub mod testset;
mod verlet;
mod weights;

pub use adaptive::AdaptiveRk;
pub use bdf::{Bdf, MAX_ORDER as BDF_MAX_ORDER};
pub use control::{
    ATOL_PER_RTOL, AdaptiveConfig, AdaptiveError, AdaptiveStats, ConfigError, Controller, MIN_RTOL,
    STEP_BUDGET, STEPS_PER_SPAN, Tolerance,
};
pub use euler::Euler;
pub use euler_cromer::EulerCromer;
pub use events::{
    Direction, EventEnd, EventHit, Integrator, OdeEvent, Progress, RunError, run_events,
    run_to_event,
};
pub use explicit_rk::ExplicitRk;
pub use hermite::{hermite, hermite_derivative};
pub use method::{Method, MethodInfo, MethodKind};
pub use pattern::JacobianPattern;
pub use polynomial::{MAX_COEFFICIENTS, MAX_TERMS, StepPolynomial};
pub use proof::{MAX_BOUNDS, Piece, ProofOutcome, StepProof};
pub use radau5::{ImplicitStats, NEWTON_MAX_ITER, Radau5};
pub use rk4::Rk4;
pub use series::Series;
pub use state::State;
pub use stepper::{IntegrateError, StepInfo, Stepper, steps_to_cover};
pub use symplectic::{Composition, Symplectic};
pub use system::{OdeSystem, SecondOrderSystem};
pub use tableau::{DenseKind, Tableau, TableauError};
pub use verlet::VelocityVerlet;
