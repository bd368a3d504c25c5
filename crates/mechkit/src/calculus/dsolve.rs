//! Ordinary differential equations in closed form, `mechkit dsolve`: the engine's methods
//! ([`mechkit_expr::sym::dsolve`]) with values for the other names substituted first (so that
//! the damping case is decided by them), initial conditions, and the verification by
//! substitution reported.

use mechkit_expr::sym::dsolve::{Condition, DsolveError, Ode, Verification};
use mechkit_expr::{Number, Sym};

use super::{CalculusError, Params};
use crate::Real;
use crate::inputs::{Input, InputError};

/// A differential equation solved in closed form.
///
/// Serialized as `{equation, function, variable, order, solution, method, constants, ic,
/// determined: {C1: value}, assumptions, verified, verification, parameters}`: `solution` is
/// a formula in the variable, with the given values substituted; `verification` is
/// `"symbolic"` (the residual simplified to 0) or `"numeric"` (it vanished at many points).
#[derive(Debug, Clone, PartialEq)]
pub struct OdeSolved {
    /// The equation, `lhs - rhs = 0` with primes, values substituted.
    pub equation: String,
    /// The unknown function.
    pub func: String,
    /// The independent variable.
    pub var: String,
    /// The order of the equation.
    pub order: usize,
    /// `x(t)`.
    pub solution: Sym,
    /// The method, in words.
    pub method: String,
    /// Constants left free (`C1`, `C2`).
    pub constants: Vec<String>,
    /// The initial conditions, as read (`x(0) = 1`).
    pub ic: Vec<String>,
    /// Constants fixed by the conditions, with their values.
    pub determined: Vec<(String, Sym)>,
    /// What was assumed about the other names (`k/m > 0`).
    pub assumptions: Vec<String>,
    /// How the solution was verified.
    pub verification: Verification,
    /// The values given to the other names.
    pub parameters: Vec<(String, Real)>,
}

#[cfg(feature = "serde")]
impl serde::Serialize for OdeSolved {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("OdeSolved", 13)?;
        st.serialize_field("equation", &self.equation)?;
        st.serialize_field("function", &self.func)?;
        st.serialize_field("variable", &self.var)?;
        st.serialize_field("order", &self.order)?;
        st.serialize_field("solution", &self.solution.to_string())?;
        st.serialize_field("method", &self.method)?;
        st.serialize_field("constants", &self.constants)?;
        st.serialize_field("ic", &self.ic)?;
        let determined: std::collections::BTreeMap<&str, String> = self
            .determined
            .iter()
            .map(|(k, v)| (k.as_str(), v.to_string()))
            .collect();
        st.serialize_field("determined", &determined)?;
        st.serialize_field("assumptions", &self.assumptions)?;
        st.serialize_field("verified", &true)?;
        st.serialize_field(
            "verification",
            match self.verification {
                Verification::Symbolic => "symbolic",
                Verification::Numeric { .. } => "numeric",
            },
        )?;
        st.serialize_field("parameters", &Parameters(&self.parameters))?;
        st.end()
    }
}

/// Name-value pairs as a JSON object.
#[cfg(feature = "serde")]
struct Parameters<'a>(&'a [(String, Real)]);

#[cfg(feature = "serde")]
impl serde::Serialize for Parameters<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        super::text::params(self.0, s)
    }
}

/// Solves the differential equation `text` (primes for derivatives: `x'' + w^2*x = 0`) for
/// the function `func` of `var`, with the initial conditions `ic` (`"x(0)=1, x'(0)=0"`) and
/// values for the other names.
///
/// ```
/// use mechkit::calculus::dsolve;
/// let s = dsolve("m*x'' + k*x = 0", "x", "t", Some("x(0)=1, x'(0)=0"),
///     &[("m".into(), 1.0), ("k".into(), 4.0)]).unwrap();
/// assert_eq!(s.solution.to_string(), "cos(2*t)");
/// ```
pub fn dsolve(
    text: &str,
    func: &str,
    var: &str,
    ic: Option<&str>,
    params: &Params,
) -> Result<OdeSolved, CalculusError> {
    super::check_variable(func, Input::Function)?;
    super::check_variable(var, Input::Variable)?;
    super::check_not_given(params, &[func, var])?;
    let ode = Ode::parse(text, func, var).map_err(|e| engine_error(e, text))?;
    let values: Vec<(String, Sym)> = params
        .iter()
        .map(|(k, v)| (k.clone(), Sym::Num(Number::from_f64(*v))))
        .collect();
    let given = match ic {
        Some(t) => Condition::parse_list(t, func).map_err(|e| engine_error(e, text))?,
        None => Vec::new(),
    };
    let s = ode
        .solve_with_values(&values, &given)
        .map_err(|e| engine_error(e, text))?;
    let ode = ode.with_values(&values);
    let mut conditions = given;
    for c in &mut conditions {
        for (k, v) in &values {
            c.at = c.at.substitute(k, v);
            c.value = c.value.substitute(k, v);
        }
    }
    Ok(OdeSolved {
        equation: ode.display(),
        func: func.to_string(),
        var: var.to_string(),
        order: ode.order,
        solution: s.solution,
        method: s.method,
        constants: s.constants,
        ic: conditions.iter().map(|c| format!("{func}{c}")).collect(),
        determined: s.determined,
        assumptions: s.assumptions,
        verification: s.verification,
        parameters: params.to_vec(),
    })
}

fn engine_error(e: DsolveError, text: &str) -> CalculusError {
    match e {
        DsolveError::Formula(f) => CalculusError::Formula(f),
        DsolveError::Condition(m) => InputError::new(Input::InitialConditions, m).into(),
        DsolveError::NoMethod { reason, .. } => CalculusError::NoClosedForm(format!(
            "no closed form for `{}`: {reason}\n  = hint: for a numerical solution, write it as \
             a scenario (one body whose force formula gives the acceleration from x, vx and t; \
             see docs/scenario.md) and run `mechkit run FILE`",
            text.trim()
        )),
        other => CalculusError::Invalid(other.to_string()),
    }
}
