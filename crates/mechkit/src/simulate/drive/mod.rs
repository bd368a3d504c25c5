//! The simulation loop: advance, keep the energy ledger, find and handle events in time order,
//! sample the requested output times, hand every sample to the observers, and stop with a
//! diagnosis when the numbers stop being numbers.
//!
//! The loop itself is the one event-aware loop of every model
//! ([`crate::ode::events::drive`]); this is the particles' side of it. `run.rs` holds the state
//! a run carries (`Run`), how it starts and how it reports; `step.rs` advancing one step (or a
//! chunk of silent steps in the fused kernel) and finishing it; `events.rs` the particles'
//! [`Model`](crate::ode::events::drive::Model) and the events inside a step, through the one
//! event finder; `fire.rs` what one firing does to the run.

mod events;
mod fire;
mod run;
mod step;

pub(super) use run::drive;
