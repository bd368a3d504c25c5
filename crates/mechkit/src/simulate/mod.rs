//! The run loop: advance a particle system with a fixed-step method, keep the energy ledger,
//! locate stop conditions between steps, hand every sample to observers, and stop with a
//! diagnosis when the numbers stop being numbers.
//!
//! A stop condition is an event function `g` of the state that is negative while the run
//! should go on; when a step ends with `g ≥ 0` the crossing is located on the cubic Hermite
//! interpolant of the step (positions from positions and velocities, velocities from
//! velocities and accelerations) by Brent's method, and the run ends there. Both the located
//! event and the last step before it are reported, so the textbook's `while` loop answer and
//! the refined answer sit side by side.

mod book;
mod cancel;
mod condition;
pub(crate) mod diagnose;
mod drive;
mod event;
mod fused;
mod halt;
mod observe;
mod pair;
mod probe;
mod prove;
mod rearm;
mod reduce;
mod report;
mod run;
mod step_bound;
mod stepping;

pub use book::ZENO_LIMIT;
pub use cancel::{Cancel, Progress};
pub use condition::Condition;
pub use event::{Direction, Event, EventAction};
pub use observe::{Observer, ObserverError, Recorder};
pub use reduce::{Reducer, Reduction};
pub use report::{Divergence, EventRecord, RunReport, SimulateError, Snapshot, StopReason};
pub use run::{DEFAULT_MAX_STEPS, Simulation};
pub use step_bound::{MAX_STEPS, StepBoundError, check_output_bound, check_step_bound};
pub use stepping::Stepping;
