//! Events of any [`OdeSystem`](crate::ode::OdeSystem) run by an
//! [`AdaptiveRk`](crate::ode::AdaptiveRk): functions `g(t, y)` whose crossings of zero are found
//! inside every step with a guarantee where the function can be enclosed, located by Brent's
//! method on the interpolant, reported in time order, and, for a terminal event, reached by
//! integration ([`run_to_event`]).
//!
//! `find.rs`: the one event finder, which the particles' loop (`simulate`) uses too: the
//! sample points of a step (from [`StepProof`](crate::ode::StepProof)) and the first firing
//! after a time; `event.rs`: [`OdeEvent`], [`Direction`] and the crossing rules; `scan.rs`:
//! the [`OdeEvent`]s of one step through the finder; `driver.rs`: the loop.

pub(crate) mod drive;
mod driver;
mod event;
pub(crate) mod find;
mod scan;

pub use driver::{EventEnd, EventHit, Integrator, Progress, RunError, run_events, run_to_event};
pub use event::{Direction, OdeEvent};
pub use find::FALLBACK_SAMPLES;
pub use scan::SAMPLES;
