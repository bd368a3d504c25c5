//! Why a rocket cannot be built or flown.

use thiserror::Error;

use crate::Real;
use crate::ode::{AdaptiveError, ConfigError};

/// The inputs of a rocket, named so that an error says which one it is about (a front maps
/// them to its flags or keywords).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Input {
    /// The mass at ignition `m0`.
    IgnitionMass,
    /// The mass at burnout `m1`.
    BurnoutMass,
    /// The mass rate `ṁ`.
    MassRate,
    /// The exhaust speed `u`.
    ExhaustSpeed,
    /// Gravity `g`.
    Gravity,
    /// The drag coefficient `D`.
    Drag,
    /// The integrator's settings.
    Tolerance,
}

/// An invalid rocket, or a simulation of it that failed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RocketError {
    /// A mass that is not positive and finite.
    #[error("{which} is {} kg; masses must be positive and finite", crate::error::short(*value))]
    Mass {
        /// Which input: [`Input::IgnitionMass`] or [`Input::BurnoutMass`].
        input: Input,
        /// Which mass (`the mass at ignition m0`, `the burnout mass m1`).
        which: &'static str,
        /// The value.
        value: Real,
    },
    /// The burnout mass is not below the mass at ignition.
    #[error(
        "the burnout mass m1 = {} kg must be below the mass at ignition m0 = {} kg (the difference is the propellant)",
        crate::error::short(*m1),
        crate::error::short(*m0)
    )]
    Burnout {
        /// Mass at ignition.
        m0: Real,
        /// Mass at burnout.
        m1: Real,
    },
    /// A mass rate that is not positive and finite.
    #[error(
        "the mass rate is {} kg/s; it must be positive (the mass ejected per second)",
        crate::error::short(*value)
    )]
    MassRate {
        /// The value.
        value: Real,
    },
    /// A burn that lasts longer than any time a double holds: `(m0 − m1)/ṁ` overflows.
    #[error(
        "the burn lasts (m0 − m1)/ṁ = {} kg / {} kg/s, longer than any time a double holds; the mass rate must be larger",
        crate::error::short(*propellant),
        crate::error::short(*mass_rate)
    )]
    BurnTime {
        /// The propellant, `m0 − m1` (kg).
        propellant: Real,
        /// The mass rate (kg/s).
        mass_rate: Real,
    },
    /// An exhaust speed that is not positive and finite.
    #[error(
        "the exhaust speed is {} m/s; it must be positive (the speed of the exhaust relative to the rocket)",
        crate::error::short(*value)
    )]
    ExhaustSpeed {
        /// The value.
        value: Real,
    },
    /// A negative or non-finite gravity.
    #[error(
        "g is {} m/s²; it must be 0 (free space) or positive (pointing down)",
        crate::error::short(*value)
    )]
    Gravity {
        /// The value.
        value: Real,
    },
    /// A negative or non-finite drag coefficient.
    #[error(
        "the drag coefficient D is {} kg/m; it must be zero or positive (F = −D v|v|)",
        crate::error::short(*value)
    )]
    Drag {
        /// The value.
        value: Real,
    },
    /// Invalid settings of the adaptive integrator.
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// The adaptive integrator could not advance.
    #[error(transparent)]
    Integrate(#[from] AdaptiveError),
}

impl RocketError {
    /// The input the error is about (`None` when the integration failed).
    ///
    /// ```
    /// use mechkit::rocket::{Input, Rocket};
    /// let e = Rocket::new(1000.0, 2000.0, 10.0, 2000.0).unwrap_err();
    /// assert_eq!(e.input(), Some(Input::BurnoutMass));
    /// ```
    pub fn input(&self) -> Option<Input> {
        Some(match self {
            RocketError::Mass { input, .. } => *input,
            RocketError::Burnout { .. } => Input::BurnoutMass,
            RocketError::MassRate { .. } | RocketError::BurnTime { .. } => Input::MassRate,
            RocketError::ExhaustSpeed { .. } => Input::ExhaustSpeed,
            RocketError::Gravity { .. } => Input::Gravity,
            RocketError::Drag { .. } => Input::Drag,
            RocketError::Config(_) => Input::Tolerance,
            RocketError::Integrate(_) => return None,
        })
    }
}
