//! Events of any [`OdeSystem`](crate::ode::OdeSystem), on the one event-aware loop every model
//! runs on: functions `g(t, y)` whose crossings of zero are found inside every step with a
//! guarantee where the function can be enclosed, located by Brent's method on the interpolant,
//! reported in time order; a terminal event is reached by integration, an event with an action
//! changes the state and the integration starts afresh ([`run_events`], [`run_to_event`]).
//!
//! `drive.rs`: the loop, generic over a `Model` (the particles' `simulate` is one, the free
//! 3-D body another); `find.rs`: the one event finder all of them use: the sample points of a
//! step (from [`StepProof`](crate::ode::StepProof)) and the first firing after a time;
//! `event.rs`: [`OdeEvent`], [`Direction`] and the crossing rules; `scan.rs`: the
//! [`OdeEvent`]s of one step through the finder; `stepping.rs`: fixed or adaptive steps and
//! their interpolants; `driver.rs`: [`run_events`], the `Model` of an `OdeSystem`.

pub(crate) mod drive;
mod driver;
mod event;
pub(crate) mod find;
mod scan;
mod stepping;

pub use driver::{EventEnd, EventHit, Integrator, Progress, RunError, run_events, run_to_event};
pub use event::{Direction, OdeEvent};
pub use find::FALLBACK_SAMPLES;
pub use scan::SAMPLES;
