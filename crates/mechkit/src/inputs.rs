//! The inputs of the one-question calculations (`calculus`, the work-energy tools, data
//! files), named so that an error can say which input caused it without a front searching the
//! message: the command line maps an [`Input`] to its flag (`Input::Mass` → `--mass`), a
//! Python front to its keyword argument.
//!
//! ```
//! use mechkit::inputs::{Input, InputError};
//!
//! let e = InputError::new(Input::Mass, "the mass must be positive, not -2");
//! assert_eq!(e.input, Input::Mass);
//! assert_eq!(e.to_string(), "the mass must be positive, not -2");
//! ```

use thiserror::Error;

/// What a one-question calculation is given.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Input {
    /// The formula asked about (an integrand, a potential, an equation).
    Formula,
    /// A force formula given instead of a potential.
    Force,
    /// The variable (or variables) of the formula.
    Variable,
    /// Values of the other names of a formula.
    Params,
    /// A point to evaluate at.
    Point,
    /// The initial step of a numerical derivative.
    Step,
    /// The limits of a definite integral.
    Limits,
    /// The numbers of intervals of fixed quadrature rules.
    Intervals,
    /// The unknowns of an equation or a system.
    Unknowns,
    /// The interval searched for roots.
    SearchInterval,
    /// A quantity to convert.
    Quantity,
    /// The unit to convert to.
    TargetUnit,
    /// The range analysed and plotted.
    Range,
    /// A total energy.
    Energy,
    /// A mass.
    Mass,
    /// A start position.
    StartPosition,
    /// A start speed.
    StartSpeed,
    /// Points (or times) to report values at.
    At,
    /// A force field, one formula per component.
    Field,
    /// A curve `r(s)`.
    Path,
    /// The parameter of a curve and its range.
    PathParameter,
    /// The corners of a path of straight segments.
    Through,
    /// A power.
    Power,
    /// A duration.
    Time,
    /// A work done.
    Work,
    /// A speed to reach.
    TargetSpeed,
    /// The abscissa column of a data file (`x`, or `t`).
    AbscissaColumn,
    /// The column integrated or differentiated (a force, positions).
    ValueColumn,
    /// A quadrature rule or a difference scheme.
    Method,
    /// Smoothing of noisy data.
    Smoothing,
    /// The number of samples of a grid ([`crate::sample_bound`]).
    Samples,
    /// The unknown function of a differential equation.
    Function,
    /// Initial conditions of a differential equation.
    InitialConditions,
}

/// A value that does not answer the question, with the input it came from and what would fix
/// it (the message does not name a flag: a front adds its own name for the input).
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{message}")]
pub struct InputError {
    /// Which input.
    pub input: Input,
    /// What is wrong and what would fix it.
    pub message: String,
}

impl InputError {
    /// An error about `input`.
    pub fn new(input: Input, message: impl Into<String>) -> Self {
        Self {
            input,
            message: message.into(),
        }
    }
}

/// `"1 component"`, `"2 components"`: a count with its noun in the right number (`noun` is
/// the singular; the plural adds `s`).
///
/// ```
/// assert_eq!(mechkit::inputs::count(1, "component"), "1 component");
/// assert_eq!(mechkit::inputs::count(3, "equation"), "3 equations");
/// ```
pub fn count(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}
