//! Variable mass: a rocket flying straight up (or in free space) while it ejects mass.
//!
//! A rocket of mass `m` ejects `ṁ` kilograms per second at the exhaust speed `u` relative to
//! itself. Momentum bookkeeping over `dt` (rocket and the ejected `ṁ dt` together) gives the
//! rocket equation
//!
//! `m dv/dt = u ṁ − m g − D v|v|`,
//!
//! with `u ṁ` the thrust, `g` a uniform gravity (0 in free space) and `D` the coefficient of an
//! optional quadratic drag. Note that `d(mv)/dt` is *not* the external force for a variable
//! mass: `d(mv)/dt = −ṁ (v − u) + F_ext`, the first term being the momentum the exhaust carries
//! away.
//!
//! The burn lasts `T = (m0 − m1)/ṁ`, with `m(t) = m0 − ṁ t`. Without drag:
//!
//! - free space (Tsiolkovsky): `Δv = u ln(m0/m1)`;
//! - uniform gravity, from rest: `v(t) = u ln(m0/m(t)) − g t` and, integrating once more,
//!   `x(t) = u t − (u m(t)/ṁ) ln(m0/m(t)) − g t²/2`;
//! - after burnout a ballistic coast to the apex at `t1 + v1/g`, height `x1 + v1²/(2g)`.
//!
//! [`Rocket`] holds the parameters and these closed forms; [`Rocket::simulate`] integrates the
//! state `(x, v, m)` with Dormand-Prince 5(4) through burnout (located exactly) and optionally
//! the coast to the apex (an event of the one driver, [`crate::ode::run_to_event`]), and is the only answer when there is drag ([`RocketRun`]). The model
//! has no launch pad: a rocket whose thrust is below its weight sinks at first.
//!
//! [`Rocket::report`] is the answer of `mechkit rocket` as a value ([`RocketReport`], with its
//! table and plots); errors name their [`Input`].

mod error;
mod report;
mod run;
mod vehicle;

pub use error::{Input, RocketError};
pub use report::{Apex, Burnout, RocketReport};
pub use run::RocketRun;
pub use vehicle::Rocket;
