//! The simulation loop: advance, keep the energy ledger, find and handle events in time order,
//! sample the requested output times, hand every sample to the observers, and stop with a
//! diagnosis when the numbers stop being numbers.
//!
//! `run.rs` holds the loop and the state it carries (`Run`), `step.rs` advancing one step (or
//! a chunk of silent steps in the fused kernel) and finishing it, `events.rs` the events
//! inside a step in time order, and `fire.rs` what one firing does to the run.

mod events;
mod fire;
mod run;
mod step;

pub(super) use run::drive;
