//! What is wrong with an angular-kinematics question, and the checks of its values.

use thiserror::Error;

use super::super::Input;
use crate::Real;
use crate::calculus::CalculusError;

/// What is wrong with an angular-kinematics question.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum KinematicsError {
    /// The formula does not parse, or names lack values.
    #[error("{0}")]
    Formula(#[from] CalculusError),
    /// A value needed for the question was not given.
    #[error("{what} is needed {why}")]
    Missing {
        /// Which input.
        input: Input,
        /// The value, in words.
        what: &'static str,
        /// What needs it.
        why: &'static str,
    },
    /// A value that must be finite (and positive, where said) is not.
    #[error("{what} must be {must_be}, not {}", crate::error::short(*value))]
    Value {
        /// Which input it is.
        input: Input,
        /// Which value, in words.
        what: &'static str,
        /// The value given.
        value: Real,
        /// What it must be.
        must_be: &'static str,
    },
    /// θ = θ₀ + ∫₀ᵗ ω dt at a time asked diverges: ω has a pole between 0 and that time.
    #[error(
        "θ(t) = θ₀ + ∫₀ᵗ ω dt diverges at t = {}: ω = `{omega}` is not integrable at t = {} \
         in [0, {}]{growth}\n  = hint: ask for times before {} s, where θ is finite",
        crate::calculus::show_point(*t),
        crate::calculus::show_point(*pole),
        crate::calculus::show_point(*t),
        crate::calculus::show_point(*pole)
    )]
    Diverges {
        /// The time asked (s).
        t: Real,
        /// The pole of ω (s).
        pole: Real,
        /// ω as written.
        omega: String,
        /// How ω grows there, in words (`; near it …`), or empty.
        growth: String,
    },
}

impl KinematicsError {
    /// The input the error is about (`None` for a formula's error: it names its own place).
    pub fn input(&self) -> Option<Input> {
        match self {
            KinematicsError::Value { input, .. } | KinematicsError::Missing { input, .. } => {
                Some(*input)
            }
            KinematicsError::Formula(_) | KinematicsError::Diverges { .. } => None,
        }
    }
}

pub(in crate::rigid) fn check(
    (input, what): (Input, &'static str),
    value: Real,
    must_be: &'static str,
    ok: bool,
) -> Result<Real, KinematicsError> {
    if ok && value.is_finite() {
        Ok(value)
    } else {
        Err(KinematicsError::Value {
            input,
            what,
            value,
            must_be,
        })
    }
}

pub(in crate::rigid) fn positive(
    name: (Input, &'static str),
    value: Real,
) -> Result<Real, KinematicsError> {
    check(name, value, "positive and finite", value > 0.0)
}

pub(in crate::rigid) fn finite(
    name: (Input, &'static str),
    value: Real,
) -> Result<Real, KinematicsError> {
    check(name, value, "finite", true)
}
