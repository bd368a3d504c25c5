//! Why a run stops before its next step: its [`Cancel`](super::Cancel) raised (Ctrl-C), an
//! observer that can take no more, `t_max`, or the step budget (with what to say about it).

use super::event::Event;
use super::observe::Observer;
use super::report::StopReason;
use super::run::{DEFAULT_MAX_STEPS, Simulation};
use crate::Real;

/// The reason to stop before taking step `steps + 1` at time `t`, if there is one; the message
/// that explains it goes to `warnings`.
pub(crate) fn stop_before_step(
    sim: &Simulation<'_>,
    observers: &[&mut dyn Observer],
    events: &[Event],
    t: Real,
    steps: u64,
    limit: u64,
    warnings: &mut Vec<String>,
) -> Option<StopReason> {
    if sim.cancel.as_ref().is_some_and(super::Cancel::is_cancelled) {
        warnings.push(format!(
            "interrupted at t = {} s after {steps} steps; the outputs hold everything up to there",
            time(t)
        ));
        return Some(StopReason::Interrupted);
    }
    if let Some((reason, why)) = observers.iter().find_map(|o| o.halt()) {
        warnings.push(why);
        return Some(reason);
    }
    if sim.t_max.is_some_and(|tm| t >= tm) {
        return Some(StopReason::TMax);
    }
    if steps >= limit {
        let has_condition = events.iter().any(Event::is_stop_condition);
        warnings.extend(step_limit_warning(sim, has_condition, t));
        return Some(StopReason::MaxSteps);
    }
    None
}

/// What to say when a run used up its step budget at time `t` before anything else ended it:
/// why it had not ended, and how to let it go on. Nothing when the budget was the only end
/// asked for.
pub(crate) fn step_limit_warning(
    sim: &Simulation<'_>,
    has_stop_condition: bool,
    t: Real,
) -> Option<String> {
    let why = if has_stop_condition {
        "the stop condition never became true"
    } else {
        "nothing else ends this run"
    };
    match (sim.max_steps, sim.t_max) {
        (None, Some(tm)) => Some(format!(
            "stopped after the default budget of {DEFAULT_MAX_STEPS} adaptive steps at t = {} s, before t_max = {} s; give [stop] max_steps (at most {}) to allow more",
            time(t),
            time(tm),
            super::MAX_STEPS
        )),
        (None, None) => Some(format!(
            "stopped after the default budget of {DEFAULT_MAX_STEPS} steps at t = {} s: {why}; set [stop] t_max",
            time(t)
        )),
        (Some(n), Some(tm)) => Some(format!(
            "stopped at the step limit of {n} steps at t = {} s, before t_max = {} s; raise [stop] max_steps to go on",
            time(t),
            time(tm)
        )),
        (Some(n), None) if has_stop_condition => Some(format!(
            "stopped at the step limit of {n} steps at t = {} s: {why}; raise [stop] max_steps to go on",
            time(t)
        )),
        (Some(_), None) => None,
    }
}

/// A time for a message: `2.5`, `1e300`, `3e-7` (`crate::error::short`).
fn time(t: Real) -> String {
    crate::error::short(t)
}
