//! Why a friction model cannot be built or run.

use thiserror::Error;

use crate::Real;
use crate::ode::{AdaptiveError, ConfigError};
use crate::rigid::Input;

/// An invalid friction model, or a simulation of it that failed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum FrictionError {
    /// A friction coefficient that is negative or not finite.
    #[error(
        "the {which} friction coefficient is {}; it must be zero or positive (a ratio of forces, typically 0.05 to 1.5)",
        crate::error::short(*value)
    )]
    Coefficient {
        /// `static` or `dynamic`.
        which: &'static str,
        /// The value.
        value: Real,
    },
    /// A parameter that must be positive and finite (a mass, a spring constant).
    #[error("{what} is {}; it must be positive and finite", crate::error::short(*value))]
    NotPositive {
        /// Which input it is.
        input: Input,
        /// What it is, with its unit (`the mass m (kg)`).
        what: &'static str,
        /// The value.
        value: Real,
    },
    /// A parameter that must be finite (a speed, a position) or not negative (gravity).
    #[error("{what} is {}; {expected}", crate::error::short(*value))]
    Invalid {
        /// Which input it is.
        input: Input,
        /// What it is.
        what: &'static str,
        /// The value.
        value: Real,
        /// What would be valid.
        expected: &'static str,
    },
    /// An incline angle outside −90° … 90°.
    #[error(
        "the incline angle is {}°; it must be between -90° and 90° (0 is a flat floor)",
        crate::error::short(*degrees)
    )]
    Angle {
        /// The angle in degrees.
        degrees: Real,
    },
    /// The loads pull the block off the surface: no contact, no friction.
    #[error(
        "the normal force is {} N: the loads pull the block off the surface (m g cos α + the extra normal load must be at least 0)",
        crate::error::short(*normal)
    )]
    NoContact {
        /// `N = m g cos α + extra`.
        normal: Real,
    },
    /// The switches between regimes accumulate (Zeno) or are too many for the time span.
    #[error(
        "more than {max} stick/slip phases before t = {} s; shorten the time span or raise the limit",
        crate::error::short(*t)
    )]
    TooManyPhases {
        /// The limit.
        max: usize,
        /// Where it was reached.
        t: Real,
    },
    /// Invalid settings of the adaptive integrator.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// The adaptive integrator could not advance.
    #[error(transparent)]
    Integrate(#[from] AdaptiveError),
}

impl FrictionError {
    /// The input the error is about (`None` when the integration failed; the end time when
    /// it used up the step budget).
    pub fn input(&self) -> Option<Input> {
        Some(match self {
            FrictionError::Coefficient {
                which: "static", ..
            } => Input::StaticFriction,
            FrictionError::Coefficient { .. } => Input::DynamicFriction,
            FrictionError::NotPositive { input, .. } | FrictionError::Invalid { input, .. } => {
                *input
            }
            FrictionError::Angle { .. } => Input::Angle,
            FrictionError::NoContact { .. } => Input::NormalLoad,
            FrictionError::TooManyPhases { .. } => Input::Duration,
            FrictionError::Config(_) => Input::Tolerance,
            // the end time asked for more steps than a run may take
            FrictionError::Integrate(e) if e.is_step_budget() => Input::Duration,
            FrictionError::Integrate(_) => return None,
        })
    }
}

/// Checks that `value` is positive and finite.
pub(crate) fn positive(
    (input, what): (Input, &'static str),
    value: Real,
) -> Result<(), FrictionError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(FrictionError::NotPositive { input, what, value })
    }
}

/// Checks that `value` is finite.
pub(crate) fn finite(
    (input, what): (Input, &'static str),
    value: Real,
) -> Result<(), FrictionError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(FrictionError::Invalid {
            input,
            what,
            value,
            expected: "it must be a finite number",
        })
    }
}

/// Checks that `g` is finite and not negative.
pub(crate) fn gravity(g: Real) -> Result<(), FrictionError> {
    if g.is_finite() && g >= 0.0 {
        Ok(())
    } else {
        Err(FrictionError::Invalid {
            input: Input::Gravity,
            what: "g (m/s²)",
            value: g,
            expected: "it must be 0 or positive (pointing down into the surface)",
        })
    }
}
