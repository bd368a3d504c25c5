//! Why a constrained motion cannot be set up or integrated.

use thiserror::Error;

use crate::Real;
use crate::calculus::CalculusError;
use crate::ode::{AdaptiveError, ConfigError};
use crate::rigid::Input;

/// An invalid curve or start, or an integration that failed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ConstrainedError {
    /// The curve's formula does not parse or names lack values.
    #[error("{0}")]
    Formula(#[from] CalculusError),
    /// A value that must be positive (or finite) is not.
    #[error("{what} is {}; it must be {must_be}", crate::error::short(*value))]
    Value {
        /// Which input it is.
        input: Input,
        /// Which value (`the radius`, `g`, `t_max`, …).
        what: &'static str,
        /// The value given.
        value: Real,
        /// What it must be.
        must_be: &'static str,
    },
    /// The graph y(x) or its derivatives are undefined (or the tangent vertical) at `x`.
    #[error(
        "the curve is undefined or vertical at x = {} (y = {}, y' = {}); a graph y(x) \
         cannot carry the body there: use a circle, or start elsewhere",
        crate::error::short(*x),
        crate::error::short(*y),
        crate::error::short(*slope)
    )]
    Undefined {
        /// Where.
        x: Real,
        /// y there.
        y: Real,
        /// y' there.
        slope: Real,
    },
    /// The graph jumps, or its slope does, at `x` (reached by the run): the equations of
    /// motion on a curve need `y'` and `y''` there.
    #[error(
        "the curve is not smooth at x = {}: {}; a body on a curve needs y and its slope y' to \
         be continuous (the derivative of a step is zero, so the body would cross the jump at \
         constant speed, creating or destroying energy): write a smooth curve (round the corner \
         or the step), or end the run before x = {}",
        crate::error::short(*x),
        match what { super::Break::Jump(j) => format!("y jumps by {} m", crate::error::short(*j)), super::Break::Kink(k) => format!("its slope y' jumps by {} (a kink)", crate::error::short(*k)) },
        crate::error::short(*x)
    )]
    NotSmooth {
        /// Where.
        x: Real,
        /// What jumps.
        what: super::Break,
    },
    /// A start given as an angle on a graph, or as x on a circle.
    #[error("{0}")]
    Start(String),
    /// Invalid settings of the adaptive integrator.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// The adaptive integrator could not advance.
    #[error(transparent)]
    Integrate(#[from] AdaptiveError),
}

impl ConstrainedError {
    /// The input the error is about (`None` when the integration failed; the end time when
    /// it used up the step budget).
    pub fn input(&self) -> Option<Input> {
        Some(match self {
            ConstrainedError::Formula(_) | ConstrainedError::NotSmooth { .. } => Input::Curve,
            ConstrainedError::Value { input, .. } => *input,
            ConstrainedError::Undefined { .. } | ConstrainedError::Start(_) => Input::StartPosition,
            ConstrainedError::Config(_) => Input::Tolerance,
            // the end time asked for more steps than a run may take
            ConstrainedError::Integrate(e) if e.is_step_budget() => Input::Duration,
            ConstrainedError::Integrate(_) => return None,
        })
    }
}
