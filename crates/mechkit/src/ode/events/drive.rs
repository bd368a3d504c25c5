//! The one event-aware loop. Every model with events runs on it: the particles (`simulate`,
//! which also carries the hinged rigid bodies) and, through [`run_to_event`](super::run_to_event),
//! any [`OdeSystem`](crate::ode::OdeSystem) (the rocket, stick-slip, rolling, the bead).
//!
//! The loop owns the order of things; a [`Model`] owns what they mean. Each turn: the stops
//! checked before a step, a chunk of unwatched steps in a faster kernel where the model has
//! one, one step, then the step's events in time order (the sample points proven by the one
//! event finder, [`super::find`], the first firing after the last one, what it does: cut the
//! step there, or record it and scan on), and the step's end when no firing cut it.

use crate::Real;

use super::find::Fired;

/// Where the scan of a step goes after a firing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum AfterFiring {
    /// The step is cut at the firing (the state changed there, or the run ends there).
    Cut,
    /// The firing was recorded at the step's end: nothing is left to scan.
    AtStepEnd,
    /// The firing was recorded inside the step: the scan goes on from its time.
    ScanFrom(Real),
}

/// A run on the loop: its state, its stepping, its events and its outputs.
pub(crate) trait Model {
    type Error;

    /// Whether the run has ended.
    fn ended(&self) -> bool;

    /// Whether the run stops before its next step (a time or step limit, a cancel, an
    /// observer's request); the model records why.
    fn stops_before_step(&mut self) -> bool;

    /// Runs the next steps no event or output needs in a faster kernel, if the model has one;
    /// returns whether it did.
    fn fast_forward(&mut self) -> bool {
        false
    }

    /// Takes one step and evaluates its end (the event functions there included); returns
    /// whether the run ended (a step that failed, with a diagnosis).
    fn advance(&mut self) -> Result<bool, Self::Error>;

    /// Whether any event can still fire.
    fn any_enabled(&self) -> bool;

    /// The step's interpolant, and the points at which the events must be sampled in it
    /// ([`super::find::Finder::plan`]).
    fn plan(&mut self);

    /// Starts the scan of the step from its start; returns the step's start time.
    fn begin_scan(&mut self) -> Real;

    /// The first firing in the step after `t_scan` ([`super::find::Finder::first_firing`]).
    fn scan_from(&mut self, t_scan: Real) -> Option<Fired>;

    /// Nothing fires in the rest of the step: the events' sides move to its end.
    fn end_scan(&mut self);

    /// Handles one firing.
    fn fire(&mut self, fired: Fired) -> Result<AfterFiring, Self::Error>;

    /// Finishes a step no firing cut short (`event_at_end`: a firing was recorded at its end).
    fn finish_step(&mut self, event_at_end: bool) -> Result<(), Self::Error>;
}

/// Runs `model` until it ends.
pub(crate) fn drive<M: Model + ?Sized>(model: &mut M) -> Result<(), M::Error> {
    while !model.ended() {
        if model.stops_before_step() {
            break;
        }
        if model.fast_forward() {
            continue;
        }
        if model.advance()? {
            break;
        }
        if let Some(event_at_end) = events_in_step(model)? {
            model.finish_step(event_at_end)?;
        }
    }
    Ok(())
}

/// Finds and handles the events of the step just taken, in time order; returns `None` when a
/// firing cut the step, else whether a firing was recorded at its end.
fn events_in_step<M: Model + ?Sized>(model: &mut M) -> Result<Option<bool>, M::Error> {
    if model.any_enabled() {
        model.plan();
    }
    let mut t_scan = model.begin_scan();
    while model.any_enabled() {
        let Some(fired) = model.scan_from(t_scan) else {
            model.end_scan();
            break;
        };
        match model.fire(fired)? {
            AfterFiring::Cut => return Ok(None),
            AfterFiring::AtStepEnd => return Ok(Some(true)),
            AfterFiring::ScanFrom(t) => t_scan = t,
        }
    }
    Ok(Some(false))
}
