//! What a run did: why it stopped, the located event, the divergence diagnosis, the ledger.

use std::fmt;

use thiserror::Error;

use super::observe::ObserverError;
use super::stepping::Stepping;
use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::{AdaptiveStats, Method, State};

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
    /// The adaptive step size fell below its minimum.
    StepTooSmall,
    /// An event fired again and again at practically the same time (Zeno behaviour).
    Zeno,
    /// A stop was asked for from outside: the run's [`Cancel`](super::Cancel) was raised (by
    /// Ctrl-C, another thread).
    Interrupted,
    /// An observer could take no more: an output file reached its size limit
    /// ([`Observer::halt`](super::Observer::halt)).
    OutputLimit,
    /// An observer could not write its output (a full disk): the run stopped there.
    OutputError,
}

impl StopReason {
    /// Name as in summaries: `t_max`, `event`, `max_steps`, `diverged`, `step_too_small`,
    /// `zeno`, `interrupted`, `output_limit`, `output_error`.
    pub fn name(self) -> &'static str {
        match self {
            StopReason::TMax => "t_max",
            StopReason::Event => "event",
            StopReason::MaxSteps => "max_steps",
            StopReason::Diverged => "diverged",
            StopReason::StepTooSmall => "step_too_small",
            StopReason::Zeno => "zeno",
            StopReason::Interrupted => "interrupted",
            StopReason::OutputLimit => "output_limit",
            StopReason::OutputError => "output_error",
        }
    }

    /// Whether the computation failed (the CLI exits with 1).
    pub fn is_failure(self) -> bool {
        matches!(
            self,
            StopReason::Diverged | StopReason::StepTooSmall | StopReason::Zeno
        )
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

/// A located event.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRecord {
    /// What fired (the event's name, or the stop condition as written).
    pub name: String,
    /// Which occurrence of this event it is (1 for the first).
    pub occurrence: u32,
    /// Time of the crossing, located on the step's interpolant.
    pub t: Real,
    /// The interpolated state at the crossing.
    pub state: Snapshot,
    /// The last step before the crossing (what a `while` loop on the condition ends with).
    pub last_step: Snapshot,
    /// The step that crossed (the first for which the condition held).
    pub crossing_step: Snapshot,
    /// The state after the event's state change, if it has one.
    pub after: Option<Snapshot>,
    /// Whether the event ended the run.
    pub terminal: bool,
}

/// Where and how a run failed: it stopped being finite, the adaptive step size underflowed, or
/// an event fired endlessly.
#[derive(Debug, Clone, PartialEq)]
pub struct Divergence {
    /// Time of the last finite state.
    pub t: Real,
    /// Step index of the last finite state.
    pub step: u64,
    /// The quantity that went bad (`feather.vx`, `force air on feather`, the event's name).
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
    /// Step size: the fixed step, or for adaptive runs the mean accepted step.
    pub dt: Real,
    /// How the run stepped.
    pub stepping: Stepping,
    /// Accepted and rejected steps and evaluations of an adaptive run (the stepper's own).
    pub adaptive: Option<AdaptiveStats>,
    /// Smallest and largest step taken.
    pub step_range: (Real, Real),
    /// Steps taken (accepted steps, for adaptive runs).
    pub steps: u64,
    /// Force evaluations (by the stepper and for the ledger).
    pub evaluations: u64,
    /// Steps run in the compiled kernel (see [`Simulation::fuse`](super::Simulation::fuse));
    /// included in `steps`.
    pub fused_steps: u64,
    /// Why it stopped.
    pub stop_reason: StopReason,
    /// The initial state.
    pub initial: State,
    /// The final state (at the event, if one fired; the last finite state, if it diverged).
    pub final_state: State,
    /// The event that ended the run.
    pub event: Option<EventRecord>,
    /// Every event occurrence, in time order (the terminal one included).
    pub events: Vec<EventRecord>,
    /// What went wrong, if the run failed.
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
    #[error("the time step must be positive and finite, not {} s", crate::error::short(*.0))]
    BadStep(Real),
    /// `t_max` is before the start.
    #[error("t_max = {} s is not after the start time {} s", crate::error::short(*t_max), crate::error::short(*t0))]
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
    /// Invalid adaptive settings.
    #[error(transparent)]
    Config(#[from] crate::ode::ConfigError),
    /// An output interval that is not positive.
    #[error("the output interval must be positive and finite, not {} s", crate::error::short(*.0))]
    BadInterval(Real),
    /// Output times that are not increasing (or not finite).
    #[error(
        "the output times must be finite and increasing: {} s is followed by {} s",
        crate::error::short(*.0),
        crate::error::short(*.1)
    )]
    BadOutputTimes(Real, Real),
    /// The run's steps would not be bounded (see [`super::check_step_bound`]).
    #[error("{0}")]
    StepBound(#[from] super::StepBoundError),
    /// An observer failed (an output could not be written).
    #[error("output failed: {0}")]
    Observer(#[from] ObserverError),
}
