//! Free rigid bodies in 3-D: orientation as a unit quaternion, angular momentum, Euler's
//! equations; the tennis-racket flip; the heavy symmetric top.
//!
//! The body frame is the principal frame, so the inertia about the centre of mass is
//! `diag(I₁, I₂, I₃)` ([`FreeBody`]). A [`SpinningBody`] is free (torque-free, rotating about
//! its centre of mass) or held at a pivot in uniform gravity (then `J`, the inertia about the
//! pivot, follows from the parallel-axis theorem). Its state is an [`Attitude`]: the rotation
//! `q` from body to world and the angular momentum `L` about the rotation point. The equations
//! ([`SpinEquations`]):
//!
//! - `ω_body = J⁻¹ Rᵀ(q) L`, `dq/dt = ½ q ⊗ (0, ω_body)`;
//! - `dL/dt = τ = (R d) × (0, 0, −m g)` in the world frame ([`Formulation::World`]): a free
//!   body's `L` is then constant by construction, to the last bit; or Euler's equations
//!   `dL_body/dt = L_body × ω + Rᵀτ` in the body frame ([`Formulation::Body`]), whose `|L|` is
//!   kept only as well as the integrator keeps it;
//! - kinetic energy `T = ½ ω·Jω`, potential `U = m g z_cm` with the pivot at the origin.
//!
//! [`SpinningBody::simulate`] integrates them with an adaptive pair (DOP853 by default), a
//! fixed-step Runge-Kutta method, or a splitting into exact rotations about the body axes
//! ([`SpinIntegrator`]), renormalising `q` after each step (its direction alone enters every
//! observable, so this changes no observable: tested). Zeros of ω about the intermediate axis
//! are located inside the steps; [`SpinRun::crossing_period`] turns them into the period of
//! the flip, compared with the exact elliptic-function solution [`Poinsot`] (`T = 4K(m)/λ`,
//! `K` by the arithmetic-geometric mean, [`complete_k`]). For the symmetric top,
//! [`SpinningBody::steady_precession`] solves for steady precession. [`SpinningBody::report`]
//! is the answer of `mechkit spin` as a value ([`SpinReport`], with its table and plots).

mod body;
mod driver;
mod equations;
mod error;
mod model;
mod poinsot;
mod record;
mod report;
mod run;
mod splitting;
mod top;

pub use crate::elliptic::{
    agm, carlson_rf, complete_k, complete_k_complement, incomplete_f, incomplete_f_complement,
    jacobi, jacobi_complement,
};
pub use body::{Attitude, FreeBody, Orientation, SpinningBody};
pub use equations::{Formulation, SpinEquations};
pub use error::Free3dError;
pub use poinsot::Poinsot;
pub use report::{
    AngularMomentum, Flip, FlipPeriod, IntegratorInfo, Nutation, PrecessionRate, SpinEnergy,
    SpinReport, StepSetting, Top, VERTICAL_SIN,
};
pub use run::{Conservation, Crossing, SpinIntegrator, SpinOptions, SpinRun, SpinSample};
