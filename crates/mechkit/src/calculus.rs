//! The one-question calculus of the command line, as library calls: the derivative of a
//! formula (and its value checked against Ridders' extrapolation), its antiderivative and
//! definite integral (closed form next to adaptive quadrature, and whether they agree; the
//! fixed rules of a course side by side), the solutions of an equation (symbolic, else numeric
//! on an interval) or of a linear system, and unit conversion.
//!
//! Each question has a result type whose serde shape is what `mechkit diff | integrate | solve
//! | units | dsolve --json` prints: [`Differentiation`], [`Integration`], [`Solved`],
//! [`Conversion`], [`OdeSolved`].
//!
//! ```
//! use mechkit::calculus::{Solved, solve_equations};
//! // a linear system with a value for `a`: solved symbolically, then evaluated
//! let s = solve_equations("a*x + y = 3; x - y = 1", &["x", "y"], None, &[("a".into(), 2.0)])
//!     .unwrap();
//! let Solved::System(system) = s else { panic!() };
//! let x = system.numeric.unwrap()[0].1;
//! assert!((x - 4.0 / 3.0).abs() < 1e-15);
//! ```

use mechkit_expr::ExprError;
use mechkit_expr::units::UnitError;
use thiserror::Error;

use crate::Real;
use crate::inputs::{Input, InputError};

mod convert;
mod derivative;
mod dsolve;
mod equation;
mod integral;
mod singular;
mod solve;

pub use convert::{Conversion, Converted, convert};
pub use derivative::{
    Derivative, DerivativeCheck, Differentiation, derivative, derivative_at, differentiate,
};
pub use dsolve::{OdeSolved, dsolve};
pub use integral::{
    Definite, Integral, Integration, RuleEstimate, integral, integration, rule_estimates,
};
pub use singular::{Singularity, integrable, pole_growth, show_point};
pub use solve::{Solution, Solved, SystemSolution, solve, solve_equations, solve_system};

/// A formula, a unit or a value that could not be read.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum CalculusError {
    /// The formula does not parse.
    #[error("{0}")]
    Formula(#[from] ExprError),
    /// A unit or quantity does not parse.
    #[error("{0}")]
    Unit(#[from] UnitError),
    /// Something else is wrong with the question (what, and how to fix it).
    #[error("{0}")]
    Invalid(String),
    /// A value of a named input does not fit the question.
    #[error("{0}")]
    Input(#[from] InputError),
    /// The question is well posed but has no closed-form answer here (what was tried, and
    /// where a numerical answer is).
    #[error("{0}")]
    NoClosedForm(String),
    /// The answer is beyond the range of doubles (an overflow): `what` (the unknown, a
    /// quantity) would be `value`, an infinity or NaN.
    #[error("the result {what} is {value}, not a finite number: {why}")]
    NotFinite {
        /// The quantity, by name (`x`).
        what: String,
        /// Its value: an infinity or NaN.
        value: Real,
        /// Where it came from, and what would help.
        why: String,
    },
}

/// Refuses a value given (`--set`) to the variable of a question, or to the unknown function
/// of an equation: `diff "x^2" --at 1 --set x=2` has no meaning, and ignoring either would
/// answer another question than the one asked.
///
/// ```
/// let p = [("x".to_string(), 2.0)];
/// let e = mechkit::calculus::check_not_given(&p, &["x"]).unwrap_err();
/// assert!(e.to_string().starts_with("`x` is the variable"));
/// assert!(mechkit::calculus::check_not_given(&p, &["t"]).is_ok());
/// ```
pub fn check_not_given(params: &Params, variables: &[&str]) -> Result<(), CalculusError> {
    match params.iter().find(|(n, _)| variables.contains(&n.as_str())) {
        Some((name, _)) => Err(InputError::new(
            Input::Params,
            format!(
                "`{name}` is the variable of the question (or the function of the equation): \
                 it cannot be given a value; drop `{name}` from --set"
            ),
        )
        .into()),
        None => Ok(()),
    }
}

/// Checks that `name`, given as the variable of a question (`--var`, `--for`), is a name of
/// the formula language (`x`, `theta_1`, `ball.x`), not a formula (`x+y`), a number or a
/// built-in constant (`pi`): differentiating with respect to `x+y` has no meaning, and
/// treating it as a name would print nonsense.
///
/// ```
/// use mechkit::inputs::Input;
/// assert!(mechkit::calculus::check_variable("theta_1", Input::Variable).is_ok());
/// let e = mechkit::calculus::check_variable("x+y", Input::Variable).unwrap_err();
/// assert!(e.to_string().starts_with("`x+y` is not a name"));
/// ```
pub fn check_variable(name: &str, input: Input) -> Result<(), CalculusError> {
    let bad = |why: &str| {
        Err(InputError::new(
            input,
            format!(
                "`{name}` is not a name{why}: the variable must be one name of the formula, \
                 such as x, t or theta_1"
            ),
        )
        .into())
    };
    match mechkit_expr::parse(name).map(|p| p.expr) {
        Ok(mechkit_expr::Expr::Var(v)) if v == name => {
            if mechkit_expr::builtin_constant(&v).is_some() {
                bad(" but a built-in constant")
            } else {
                Ok(())
            }
        }
        Ok(mechkit_expr::Expr::Var(_)) => bad(" (spaces around it)"),
        Ok(mechkit_expr::Expr::Num(_)) => bad(" but a number"),
        _ => bad(""),
    }
}

/// Values given for the names of a formula (`--set a=1,b=2`), SI.
pub type Params = [(String, Real)];

fn lookup(params: &Params) -> impl Fn(&str) -> Option<Real> + '_ {
    move |n| params.iter().find(|(k, _)| k == n).map(|(_, v)| *v)
}

/// Reads `a=1,b=2 m,th=pi/6` into names and SI values ([`crate::values::params`]).
pub fn parse_params(text: &str) -> Result<Vec<(String, Real)>, CalculusError> {
    crate::values::params(text).map_err(|e| {
        CalculusError::Invalid(
            e.message
                .strip_prefix("--set ")
                .or_else(|| e.message.strip_prefix("--set: "))
                .unwrap_or(&e.message)
                .to_string(),
        )
    })
}

/// Serde helpers: formulas as their text, name-value lists as JSON objects.
#[cfg(feature = "serde")]
pub(crate) mod text {
    use std::fmt::Display;

    use serde::Serializer;
    use serde::ser::SerializeMap;

    use crate::Real;

    /// A value by its `Display` text (a `Sym` as `k*x^2/2`).
    pub fn display<T: Display, S: Serializer>(v: &T, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(v)
    }

    /// An optional value by its text, or null.
    #[allow(clippy::ref_option)] // serde's `serialize_with` passes `&Option<T>`
    pub fn display_opt<T: Display, S: Serializer>(v: &Option<T>, s: S) -> Result<S::Ok, S::Error> {
        match v {
            Some(v) => s.collect_str(v),
            None => s.serialize_none(),
        }
    }

    /// Values by their texts, as a list.
    pub fn display_list<T: Display, S: Serializer>(v: &[T], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(v.iter().map(ToString::to_string))
    }

    /// `[(name, value)]` as `{"name": value}`, in order.
    pub fn params<S: Serializer>(p: &[(String, Real)], s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(p.len()))?;
        for (k, v) in p {
            // a value given as `inf` is an input echoed as null (JSON has no infinity), not
            // an answer: the finiteness rule passes it
            map.serialize_entry(k, &v.is_finite().then_some(*v))?;
        }
        map.end()
    }
}
