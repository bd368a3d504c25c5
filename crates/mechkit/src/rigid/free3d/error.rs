//! Why a spinning body cannot be built or simulated.

use thiserror::Error;

use crate::Real;
use crate::ode::{AdaptiveError, ConfigError};
use crate::rigid::Input;

/// An invalid body, initial state or setting, or a simulation that failed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Free3dError {
    /// A principal moment that is not positive and finite.
    #[error(
        "the principal moment I{index} = {} kg·m² must be positive and finite (a body of any extent has three positive principal moments)",
        crate::error::short(*value)
    )]
    Moment {
        /// 1, 2 or 3.
        index: usize,
        /// The value.
        value: Real,
    },
    /// Principal moments that no mass distribution has: one exceeds the sum of the others.
    #[error(
        "the principal moments I1 = {}, I2 = {}, I3 = {} kg·m² violate the triangle inequality: I{largest} exceeds the sum of the other two, which no distribution of positive mass allows (each moment is at most the sum of the others; equality is a flat body)",
        crate::error::short(moments[0]), crate::error::short(moments[1]), crate::error::short(moments[2])
    )]
    Triangle {
        /// `[I1, I2, I3]`.
        moments: [Real; 3],
        /// Which moment (1, 2 or 3) is too large.
        largest: usize,
    },
    /// A mass that is not positive and finite.
    #[error("the mass is {} kg; it must be positive, finite and at least 2.2e-308 kg (its reciprocal must be finite)", crate::error::short(*value))]
    Mass {
        /// The value.
        value: Real,
    },
    /// A negative or non-finite gravity.
    #[error("g is {} m/s²; it must be 0 or positive (pointing down, along −z)", crate::error::short(*value))]
    Gravity {
        /// The value.
        value: Real,
    },
    /// A vector input with a component that is not finite.
    #[error(
        "{what} has a component that is not finite: ({}, {}, {})",
        crate::error::short(value[0]),
        crate::error::short(value[1]),
        crate::error::short(value[2])
    )]
    NonFinite {
        /// Which input it is.
        input: Input,
        /// Which input (`the pivot offset`, `the angular velocity`, `the orientation`).
        what: &'static str,
        /// The value.
        value: [Real; 3],
    },
    /// An orientation quaternion of zero or non-finite norm.
    #[error(
        "the orientation quaternion has norm {}; it must be a non-zero finite quaternion",
        crate::error::short(*norm)
    )]
    Quaternion {
        /// Its norm.
        norm: Real,
    },
    /// A duration that is not positive and finite.
    #[error("the duration t_end = {} s must be positive and finite", crate::error::short(*value))]
    Duration {
        /// The value.
        value: Real,
    },
    /// A fixed step that is not positive, finite and normal (a subnormal step cannot move the
    /// time).
    #[error(
        "the step dt = {} s must be positive, finite and at least 2.2e-308 s",
        crate::error::short(*value)
    )]
    Step {
        /// The value.
        value: Real,
    },
    /// More fixed steps for the duration than a run may take ([`crate::ode::STEP_BUDGET`]).
    #[error(
        "{} fixed steps of {} s would be needed, more than the {} a run may take; use a larger step, an earlier end, or the adaptive method",
        crate::error::short(*steps),
        crate::error::short(*dt),
        crate::ode::STEP_BUDGET
    )]
    TooManySteps {
        /// The number of steps.
        steps: Real,
        /// The step.
        dt: Real,
    },
    /// The splitting method needs the inertia about the rotation point to be diagonal in the
    /// body frame.
    #[error(
        "the splitting method needs the pivot on a principal axis through the centre of mass (the offset ({}, {}, {}) m has more than one non-zero component); use an adaptive method",
        crate::error::short(offset[0]), crate::error::short(offset[1]), crate::error::short(offset[2])
    )]
    SplittingOffAxis {
        /// The pivot offset.
        offset: [Real; 3],
    },
    /// Invalid settings of the adaptive integrator.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// More output samples than a result may hold.
    #[error(transparent)]
    Samples(#[from] crate::sample_bound::SampleBoundError),
    /// The adaptive integrator could not advance.
    #[error(transparent)]
    Integrate(#[from] AdaptiveError),
}

impl Free3dError {
    /// The input the error is about (`None` when the integration failed; the end time when
    /// it used up the step budget).
    pub fn input(&self) -> Option<Input> {
        Some(match self {
            Free3dError::Moment { .. } | Free3dError::Triangle { .. } => Input::Inertia,
            Free3dError::Mass { .. } => Input::Mass,
            Free3dError::Gravity { .. } => Input::Gravity,
            Free3dError::NonFinite { input, .. } => *input,
            Free3dError::Quaternion { .. } => Input::Orientation,
            Free3dError::Duration { .. } => Input::Duration,
            Free3dError::Step { .. } | Free3dError::TooManySteps { .. } => Input::Step,
            Free3dError::SplittingOffAxis { .. } => Input::Method,
            Free3dError::Config(_) => Input::Tolerance,
            Free3dError::Samples(_) => Input::Samples,
            // the end time asked for more steps than a run may take
            Free3dError::Integrate(e) if e.is_step_budget() => Input::Duration,
            Free3dError::Integrate(_) => return None,
        })
    }
}
