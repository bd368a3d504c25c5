//! Why a rolling body or its motion cannot be built or simulated.

use thiserror::Error;

use crate::Real;
use crate::mass::MassError;
use crate::ode::{AdaptiveError, ConfigError};
use crate::rigid::Input;
use crate::rigid::friction::FrictionError;

/// An invalid rolling body or motion, or a simulation of it that failed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RollingError {
    /// A radius that is not positive and finite: a rolling constraint `v = ω R` needs one.
    #[error(
        "the radius is {} m; rolling needs a body with a circular contact profile of positive radius (give the radius of the sphere, cylinder or hoop)",
        crate::error::short(*radius)
    )]
    NoRadius {
        /// The value.
        radius: Real,
    },
    /// A shape without a circular profile to roll on.
    #[error(
        "a {shape} has no circular cross-section to roll on; rolling needs a sphere, spherical shell, cylinder, tube, disk or ring"
    )]
    ShapeCannotRoll {
        /// The shape's name.
        shape: &'static str,
    },
    /// A mass that is not positive and finite.
    #[error("the mass is {} kg; it must be positive and finite", crate::error::short(*value))]
    Mass {
        /// The value.
        value: Real,
    },
    /// A moment-of-inertia factor outside `0 < k` (I = k m R²; 2/5 for a solid sphere).
    #[error(
        "the inertia factor k = I/(m R²) is {}; it must be positive and finite (2/5 solid sphere, 2/3 hollow sphere, 1/2 cylinder, 1 hoop)",
        crate::error::short(*value)
    )]
    InertiaFactor {
        /// The value.
        value: Real,
    },
    /// An unknown body preset.
    #[error(
        "unknown body `{name}`; use sphere, hollow-sphere, cylinder, hoop, or a factor k = I/(m R²)"
    )]
    UnknownBody {
        /// What was asked for.
        name: String,
    },
    /// An incline angle outside −90° … 90°.
    #[error(
        "the slope is {}°; it must be between -90° and 90° (0 is a flat floor)",
        crate::error::short(*degrees)
    )]
    Angle {
        /// The angle in degrees.
        degrees: Real,
    },
    /// A negative or non-finite gravity.
    #[error("g is {} m/s²; it must be 0 or positive", crate::error::short(*value))]
    Gravity {
        /// The value.
        value: Real,
    },
    /// An initial value or time span that is not finite (or not positive).
    #[error("{what} is {}; it must be {expected}", crate::error::short(*value))]
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
    /// Invalid friction coefficients.
    #[error(transparent)]
    Friction(#[from] FrictionError),
    /// The shape's moment of inertia could not be computed.
    #[error(transparent)]
    Shape(#[from] MassError),
    /// Invalid settings of the adaptive integrator.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// The adaptive integrator could not advance.
    #[error(transparent)]
    Integrate(#[from] AdaptiveError),
}

impl RollingError {
    /// The input the error is about (`None` when the integration failed; the end time when
    /// it used up the step budget).
    pub fn input(&self) -> Option<Input> {
        Some(match self {
            RollingError::NoRadius { .. } => Input::Radius,
            RollingError::Mass { .. } => Input::Mass,
            RollingError::InertiaFactor { .. }
            | RollingError::UnknownBody { .. }
            | RollingError::ShapeCannotRoll { .. }
            | RollingError::Shape(_) => Input::Body,
            RollingError::Angle { .. } => Input::Angle,
            RollingError::Gravity { .. } => Input::Gravity,
            RollingError::Invalid { input, .. } => *input,
            RollingError::Friction(e) => return e.input(),
            RollingError::Config(_) => Input::Tolerance,
            // the end time asked for more steps than a run may take
            RollingError::Integrate(e) if e.is_step_budget() => Input::Duration,
            RollingError::Integrate(_) => return None,
        })
    }
}
