//! Why an impact cannot be resolved.

use thiserror::Error;

use crate::Real;
use crate::rigid::Input;

/// An invalid body or contact.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ImpactError {
    /// A value that must be positive (or finite) is not.
    #[error("{what} is {}; it must be {must_be}", crate::error::short(*value))]
    Value {
        /// Which input it is.
        input: Input,
        /// Which value.
        what: &'static str,
        /// The value given.
        value: Real,
        /// What it must be.
        must_be: &'static str,
    },
    /// The moment of inertia about the axis is zero while the contact has a lever arm.
    #[error(
        "the moment of inertia of {which} about its axis is zero, so any angular impulse \
         would spin it infinitely fast: give a positive moment of inertia (a rod of mass M \
         and length L about its end has M L²/3)"
    )]
    ZeroInertia {
        /// Which body.
        which: &'static str,
    },
    /// I_O < M d²: impossible by the parallel-axis theorem.
    #[error(
        "the moment of inertia about the pivot, {} kg m², is below M d² = {} kg m² \
         (parallel-axis theorem: I_O = I_cm + M d² ≥ M d²); check the inertia, the mass and \
         the distance of the centre of mass from the pivot",
        crate::error::short(*inertia),
        crate::error::short(*minimum)
    )]
    ParallelAxis {
        /// I_O given.
        inertia: Real,
        /// M d².
        minimum: Real,
    },
    /// A zero or non-finite normal.
    #[error(
        "the contact normal ({}, {}) has no direction; give a non-zero vector",
        crate::error::short(normal[0]),
        crate::error::short(normal[1])
    )]
    Normal {
        /// The normal given.
        normal: [Real; 2],
    },
    /// A restitution outside [0, 1].
    #[error(
        "the coefficient of restitution is {}; it must be between 0 (plastic) and 1 (elastic)",
        crate::error::short(*value)
    )]
    Restitution {
        /// The value given.
        value: Real,
    },
    /// The bodies are not approaching at the contact: no impact.
    #[error(
        "the bodies are not approaching at the contact (normal relative speed {} m/s \
         along the normal from the first into the second): there is no impact; check the \
         velocities' signs or the normal",
        crate::error::short(*normal_speed)
    )]
    Separating {
        /// (v_B − v_A)·n at the contact (≥ 0).
        normal_speed: Real,
    },
    /// Both bodies immovable.
    #[error("both bodies are immovable; at least one must have a finite mass")]
    BothFixed,
}

impl ImpactError {
    /// The input the error is about; `None` for bodies that do not approach (which velocity
    /// is at fault depends on the question) and for two immovable bodies.
    pub fn input(&self) -> Option<Input> {
        Some(match self {
            ImpactError::Value { input, .. } => *input,
            ImpactError::ZeroInertia { .. } | ImpactError::ParallelAxis { .. } => Input::Inertia,
            ImpactError::Normal { .. } => Input::Normal,
            ImpactError::Restitution { .. } => Input::Restitution,
            ImpactError::Separating { .. } | ImpactError::BothFixed => return None,
        })
    }
}
