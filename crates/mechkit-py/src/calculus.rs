//! `mechkit.integrate`, `diff`, `solve`, `dsolve` and `units`: the one-question calculus of
//! `mechkit integrate | diff | solve | dsolve | units`, each one call of `mechkit::calculus` whose result comes
//! back as the dict the command's `--json` prints.
//!
//! A value is a Python number (SI; `inf` where the command line takes `inf`) or a string read
//! as the command line reads it (`"2 m"`, `"pi/6"`, `"b/4"` with `b` given). The other names
//! of a formula take their values from the keyword arguments, or from `set=`: a dict, or the
//! command line's `--set` text (`"a=1,b=2 m"`), for a name that is also an argument (`a`,
//! `b`). Errors are `MechkitError`s worded as the command line's, with the argument's name
//! where the command line names its flag.

use mechkit::calculus::{self, CalculusError, Definite};
use mechkit::inputs::Input;
use mechkit::quad::Rule;
use mechkit::values;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

use crate::errors::MechkitError;

/// Names and SI values of a formula's other names.
type Params = Vec<(String, f64)>;

/// A `MechkitError` with the command line's message.
pub fn error(message: impl Into<String>) -> PyErr {
    MechkitError::new_err(message.into())
}

/// A library result, serialized by `serde_json` as the command line's `--json` prints it, as
/// a dict (Python's `json.loads`).
pub fn to_dict(py: Python<'_>, json: serde_json::Result<String>) -> PyResult<Bound<'_, PyDict>> {
    let json = json.map_err(|e| error(format!("internal error, the result as JSON: {e}")))?;
    Ok(py
        .import("json")?
        .call_method1("loads", (json,))?
        .cast_into::<PyDict>()?)
}

/// The Python name of an input the library names (the command line's flag's counterpart).
fn keyword(input: Input) -> &'static str {
    match input {
        Input::Step => "step",
        Input::Point => "at",
        Input::Intervals => "n",
        Input::Limits => "a/b",
        Input::SearchInterval => "interval",
        Input::Unknowns => "unknowns",
        Input::TargetUnit => "to",
        Input::Params => "params",
        Input::Variable => "var",
        Input::Function => "func",
        Input::InitialConditions => "ic",
        _ => "the formula",
    }
}

/// A library error as the command line words it: a formula's error says which argument held
/// the formula (`what`), an input's names its argument.
fn check<T>(r: Result<T, CalculusError>, what: &str) -> PyResult<T> {
    r.map_err(|e| {
        error(match e {
            CalculusError::Formula(e) => format!("in the {what}: {e}"),
            CalculusError::Input(e) => format!("{}: {}", keyword(e.input), e.message),
            other => other.to_string(),
        })
    })
}

fn not_a_value(what: &str, v: &Bound<'_, PyAny>) -> PyErr {
    let type_name = v
        .get_type()
        .name()
        .map_or_else(|_| "?".to_string(), |n| n.to_string());
    PyTypeError::new_err(format!(
        "{what} is a {type_name}: give a number (SI) or a string with units, e.g. \"2 m\""
    ))
}

/// A number (SI) or a text read as the command line reads a value ([`values::value`]: a
/// quantity, a formula of `params`, `inf`); `what` names it in errors. NaN is refused.
pub fn value(v: &Bound<'_, PyAny>, what: &str, params: &[(String, f64)]) -> PyResult<f64> {
    if v.is_instance_of::<PyString>() {
        let text: String = v.extract()?;
        return values::value(&text, what, params).map_err(|e| error(e.message));
    }
    if v.is_instance_of::<PyBool>() {
        return Err(not_a_value(what, v));
    }
    let x: f64 = v.extract().map_err(|_| not_a_value(what, v))?;
    if x.is_nan() {
        return Err(error(format!("{what}: nan is not a number")));
    }
    Ok(x)
}

/// The values of a formula's other names: those of `set` (a dict, or the command line's
/// `"a=1,b=2 m"`), then the keyword arguments; a string may use the names before it.
pub fn params(
    set: Option<&Bound<'_, PyAny>>,
    kwargs: Option<&Bound<'_, PyDict>>,
) -> PyResult<Params> {
    let mut out = Vec::new();
    match set {
        None => {}
        Some(s) if s.is_instance_of::<PyString>() => {
            let text: String = s.extract()?;
            // the message names `--set`; here the argument is `set`
            out = values::params(&text).map_err(|e| {
                error(
                    e.message
                        .strip_prefix("--")
                        .unwrap_or(&e.message)
                        .to_string(),
                )
            })?;
        }
        Some(s) => {
            let dict = s.cast::<PyDict>().map_err(|_| {
                PyTypeError::new_err(
                    "set must be a dict of names and values, or a string such as \"a=1,b=2 m\"",
                )
            })?;
            add_params(&mut out, dict)?;
        }
    }
    if let Some(kwargs) = kwargs {
        add_params(&mut out, kwargs)?;
    }
    Ok(out)
}

fn add_params(out: &mut Params, dict: &Bound<'_, PyDict>) -> PyResult<()> {
    for (key, v) in dict.iter() {
        let name: String = key.extract()?;
        let x = value(&v, &name, out)?;
        match out.iter_mut().find(|(k, _)| *k == name) {
            Some(slot) => slot.1 = x,
            None => out.push((name, x)),
        }
    }
    Ok(())
}

/// A string, split at commas (as the command line's comma-separated lists), or a sequence
/// of strings; `what` names it in errors.
fn names(v: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<String>> {
    let list: Vec<String> = if v.is_instance_of::<PyString>() {
        let text: String = v.extract()?;
        text.split(',').map(str::to_string).collect()
    } else {
        v.extract().map_err(|_| {
            PyTypeError::new_err(format!("{what} must be a string or a list of strings"))
        })?
    };
    Ok(list
        .iter()
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .collect())
}

/// `mechkit integrate EXPR --var VAR [--from A --to B] [--method M --n N] --set ...`: the
/// antiderivative (when the rule table has one) and, with limits, the definite integral by
/// the closed form and by adaptive quadrature; with `method`, fixed rules against the exact
/// value. Returns the command's JSON as a dict, plus `value`.
#[pyfunction]
#[pyo3(signature = (expr, var = "x", a = None, b = None, *, method = None, n = None, set = None, **params))]
#[allow(clippy::too_many_arguments)] // the command's flags, one argument each
pub fn integrate<'py>(
    py: Python<'py>,
    expr: &str,
    var: &str,
    a: Option<&Bound<'py, PyAny>>,
    b: Option<&Bound<'py, PyAny>>,
    method: Option<&Bound<'py, PyAny>>,
    n: Option<&Bound<'py, PyAny>>,
    set: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let p = self::params(set, params)?;
    let limits = match (a, b) {
        (Some(a), Some(b)) => Some((value(a, "a", &p)?, value(b, "b", &p)?)),
        (None, None) => None,
        _ => return Err(error("give both a and b for a definite integral")),
    };
    let (rules, ns) = rules(method, n, limits.is_some())?;
    let result = py.detach(|| calculus::integration(expr, var, limits, &p, &rules, &ns));
    let i = check(result, "integrand")?;
    let dict = to_dict(py, serde_json::to_string(&i))?;
    dict.set_item("value", i.definite.as_ref().and_then(Definite::value))?;
    Ok(dict)
}

/// `--method` and `--n`: the rules to compare and their numbers of intervals (10 unless
/// given).
fn rules(
    method: Option<&Bound<'_, PyAny>>,
    n: Option<&Bound<'_, PyAny>>,
    limits: bool,
) -> PyResult<(Vec<Rule>, Vec<usize>)> {
    let Some(method) = method else {
        if n.is_some() {
            return Err(error(
                "n: give method too (the rules to compare), e.g. method=\"trapezoid\"",
            ));
        }
        return Ok((Vec::new(), Vec::new()));
    };
    if !limits {
        return Err(error(
            "method: the rules estimate a definite integral: give the limits a and b",
        ));
    }
    let rules =
        Rule::parse_list(&names(method, "method")?).map_err(|e| error(format!("method: {e}")))?;
    let counts: Vec<i64> = match n {
        None => vec![10],
        Some(n) => n
            .extract::<i64>()
            .map(|one| vec![one])
            .or_else(|_| n.extract::<Vec<i64>>())
            .map_err(|_| PyTypeError::new_err("n must be a whole number or a list of them"))?,
    };
    if let Some(bad) = counts.iter().find(|&&k| k < 1) {
        return Err(error(format!(
            "n {bad}: the number of intervals must be at least 1"
        )));
    }
    Ok((rules, counts.into_iter().map(|k| k as usize).collect()))
}

/// `mechkit diff EXPR --var VAR [--at X [--step H]] --set ...`: the derivative, and with `at`
/// its value there, symbolically and by Ridders' extrapolation of central differences from
/// the initial step `step` (0.1 unless given). Returns the command's JSON as a dict.
#[pyfunction]
#[pyo3(signature = (expr, var = "x", at = None, step = None, *, set = None, **params))]
pub fn diff<'py>(
    py: Python<'py>,
    expr: &str,
    var: &str,
    at: Option<&Bound<'py, PyAny>>,
    step: Option<&Bound<'py, PyAny>>,
    set: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let p = self::params(set, params)?;
    let at = match (at, step) {
        (Some(at), step) => {
            let h = step.map_or(Ok(0.1), |h| value(h, "step", &p))?;
            Some((value(at, "at", &p)?, h))
        }
        (None, Some(_)) => {
            return Err(error(
                "step: give at too, the point where the derivative is evaluated",
            ));
        }
        (None, None) => None,
    };
    let result = py.detach(|| calculus::differentiate(expr, var, at, &p));
    let d = check(result, "formula")?;
    to_dict(py, serde_json::to_string(&d))
}

/// `mechkit solve EQUATION --for UNKNOWNS [--in A:B] --set ...`: one equation symbolically
/// (linear or quadratic), else numerically on `interval`; several linear equations (a list,
/// or `;`-separated) for several unknowns. Returns the command's JSON as a dict.
#[pyfunction]
#[pyo3(signature = (equation, unknowns = None, interval = None, *, set = None, **params))]
pub fn solve<'py>(
    py: Python<'py>,
    equation: &Bound<'py, PyAny>,
    unknowns: Option<&Bound<'py, PyAny>>,
    interval: Option<&Bound<'py, PyAny>>,
    set: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let p = self::params(set, params)?;
    let equation: String = if equation.is_instance_of::<PyString>() {
        equation.extract()?
    } else {
        let list: Vec<String> = equation
            .extract()
            .map_err(|_| PyTypeError::new_err("equation must be a string or a list of strings"))?;
        list.join("; ")
    };
    let unknowns = match unknowns {
        Some(u) => names(u, "unknowns")?,
        None => vec!["x".to_string()],
    };
    let range = interval
        .map(|i| {
            let text = interval_text(i)?;
            values::increasing_interval(&text, "interval", &p).map_err(|e| error(e.message))
        })
        .transpose()?;
    let what = if unknowns.len() > 1 || equation.contains(';') {
        "equations"
    } else {
        "equation"
    };
    let result = py.detach(|| {
        let unknowns: Vec<&str> = unknowns.iter().map(String::as_str).collect();
        calculus::solve_equations(&equation, &unknowns, range, &p)
    });
    let s = check(result, what)?;
    to_dict(py, serde_json::to_string(&s))
}

/// `mechkit dsolve EQUATION --func F --var T [--ic IC] --set ...`: an ordinary differential
/// equation (primes for the derivatives) in closed form, verified by substitution. Returns the
/// command's JSON as a dict; an equation without a closed form raises `MechkitError`.
#[pyfunction]
#[pyo3(signature = (equation, func = "x", var = "t", ic = None, *, set = None, **params))]
#[allow(clippy::too_many_arguments)] // the command's flags, one keyword each
pub fn dsolve<'py>(
    py: Python<'py>,
    equation: &str,
    func: &str,
    var: &str,
    ic: Option<&str>,
    set: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let p = self::params(set, params)?;
    let result = py.detach(|| calculus::dsolve(equation, func, var, ic, &p));
    let s = check(result, "equation")?;
    to_dict(py, serde_json::to_string(&s))
}

/// An interval as the command line's `A:B`: the text itself, or two ends (numbers or texts).
fn interval_text(v: &Bound<'_, PyAny>) -> PyResult<String> {
    if v.is_instance_of::<PyString>() {
        return v.extract();
    }
    let ends: Vec<Bound<'_, PyAny>> = v.extract().map_err(|_| {
        PyTypeError::new_err("interval must be a string \"A:B\" or two ends (a, b)")
    })?;
    let [a, b] = ends.as_slice() else {
        return Err(error(format!(
            "interval takes two ends (a, b), not {}",
            ends.len()
        )));
    };
    let end = |e: &Bound<'_, PyAny>| -> PyResult<String> {
        if e.is_instance_of::<PyString>() {
            return e.extract();
        }
        if e.is_instance_of::<PyBool>() {
            return Err(not_a_value("interval", e));
        }
        let x: f64 = e.extract().map_err(|_| not_a_value("interval", e))?;
        Ok(x.to_string())
    };
    Ok(format!("{}:{}", end(a)?, end(b)?))
}

/// `mechkit units QUANTITY [--to UNIT]`: the quantity in SI, its dimension, and its value in
/// `to`. Returns the command's JSON as a dict.
#[pyfunction]
#[pyo3(signature = (value, to = None))]
pub fn units<'py>(py: Python<'py>, value: &str, to: Option<&str>) -> PyResult<Bound<'py, PyDict>> {
    let c = check(calculus::convert(value, to), "quantity")?;
    to_dict(py, serde_json::to_string(&c))
}
