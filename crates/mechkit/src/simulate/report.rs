//! What a run did: why it stopped, the located event, the divergence diagnosis, the ledger.

use std::fmt;

use thiserror::Error;

use super::observe::ObserverError;
use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::{Method, State};

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum StopReason {
    /// It reached `t_max`.
    TMax,
    /// The stop condition became true.
    Event,
    /// It used up its step budget.
    MaxSteps,
    /// The state or a force stopped being finite.
    Diverged,
}

impl StopReason {
    /// Name as in summaries: `t_max`, `event`, `max_steps`, `diverged`.
    pub fn name(self) -> &'static str {
        match self {
            StopReason::TMax => "t_max",
            StopReason::Event => "event",
            StopReason::MaxSteps => "max_steps",
            StopReason::Diverged => "diverged",
        }
    }
}

impl fmt::Display for StopReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Time, positions and velocities at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Time.
    pub t: Real,
    /// Positions.
    pub q: Vec<Real>,
    /// Velocities.
    pub v: Vec<Real>,
}

impl Snapshot {
    pub(crate) fn of(t: Real, y: &[Real]) -> Self {
        let (q, v) = y.split_at(y.len() / 2);
        Self {
            t,
            q: q.to_vec(),
            v: v.to_vec(),
        }
    }
}

/// A located stop event.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRecord {
    /// What fired (the condition's description).
    pub name: String,
    /// Time of the crossing, located on the step's interpolant.
    pub t: Real,
    /// The interpolated state at the crossing.
    pub state: Snapshot,
    /// The last step before the crossing (what a `while` loop on the condition ends with).
    pub last_step: Snapshot,
    /// The step that crossed (the first for which the condition held).
    pub crossing_step: Snapshot,
}

/// Where and how a run stopped being finite.
#[derive(Debug, Clone, PartialEq)]
pub struct Divergence {
    /// Time of the last finite state.
    pub t: Real,
    /// Step index of the last finite state.
    pub step: u64,
    /// The quantity that went bad (`feather.vx`, `force air on feather`).
    pub quantity: String,
    /// Its value (NaN or ±inf).
    pub value: Real,
    /// A full explanation with a hint.
    pub message: String,
}

/// What a run did.
#[derive(Debug, Clone)]
pub struct RunReport {
    /// Method used.
    pub method: Method,
    /// Step size.
    pub dt: Real,
    /// Steps taken.
    pub steps: u64,
    /// Force evaluations (by the stepper and for the ledger).
    pub evaluations: u64,
    /// Why it stopped.
    pub stop_reason: StopReason,
    /// The initial state.
    pub initial: State,
    /// The final state (at the event, if one fired; the last finite state, if it diverged).
    pub final_state: State,
    /// The located stop event.
    pub event: Option<EventRecord>,
    /// What went wrong, if it diverged.
    pub divergence: Option<Divergence>,
    /// Energies and work.
    pub ledger: EnergyLedger,
    /// Things the user should know (defaults applied, suspicious setups).
    pub warnings: Vec<String>,
}

/// A run could not be done at all.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SimulateError {
    /// The step is not positive.
    #[error("the time step must be positive and finite, not {0} s")]
    BadStep(Real),
    /// `t_max` is before the start.
    #[error("t_max = {t_max} s is not after the start time {t0} s")]
    BadTMax {
        /// End time asked for.
        t_max: Real,
        /// Start time.
        t0: Real,
    },
    /// The state does not fit the system.
    #[error("the state has {got} components, the system needs {expected}")]
    StateLength {
        /// Needed.
        expected: usize,
        /// Given.
        got: usize,
    },
    /// The initial state has a non-finite value.
    #[error("the initial state is not finite: {0}")]
    NonFiniteInitial(String),
    /// The stepper refused the step.
    #[error(transparent)]
    Integrate(#[from] crate::ode::IntegrateError),
    /// An observer failed (an output could not be written).
    #[error("output failed: {0}")]
    Observer(#[from] ObserverError),
}
