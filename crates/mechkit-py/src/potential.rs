//! `mechkit.potential(U, var="x", ...)`: `mechkit potential` from Python. In one dimension the
//! library's `analyse_potential` (the force, the equilibria with their stability, the turning
//! points and forbidden regions at an energy, a released body's motion); in 2-D and 3-D
//! (`var="x,y"`) `potential_field` (`F = -∇U` and its values at points). The result is the
//! command's `--json` as a dict.

use mechkit::calculus::CalculusError;
use mechkit::energy::{
    AxisUnits, Given, PotentialQuestion, Release, analyse_potential, potential_field,
};
use mechkit::inputs::Input;
use mechkit::units::{Dimension, Quantity};
use mechkit::values::{self, split_top_level};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use crate::arguments::{
    Params, error, from_json, interval_text, items, json_error, quantity, table_arrays, value,
    value_error,
};

/// The argument an input of `potential` is given by.
fn argument(input: Input) -> &'static str {
    match input {
        Input::Range => "range",
        Input::Energy => "energy",
        Input::Mass => "mass",
        Input::StartPosition => "x0",
        Input::StartSpeed => "v0",
        Input::At => "at",
        Input::Variable => "var",
        Input::Force => "force",
        Input::Params => "params",
        _ => "U",
    }
}

/// The library's error, naming the argument at fault.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
fn calculus_error(e: CalculusError) -> PyErr {
    match e {
        CalculusError::Input(e) => error(format!("{}: {}", argument(e.input), e.message)),
        other => error(other.to_string()),
    }
}

/// `mechkit potential` as a function: the analysis of a potential `U(var)` (or of a force,
/// `force="-k*x"`, with `U = -∫F dx`) on `range` (`(a, b)` or `"a:b"`), as the command's
/// `--json` prints it (a dict): the force, `U''`, the equilibria with their stability, the
/// singular points; with `energy` the turning points and allowed/forbidden regions; with
/// `mass`, `x0` (and `v0`) the motion of a body released there; `U`, `F` (and `v`) at the
/// points `at`. `**params` give the other names (`k=2`, `U0="1 eV"`). `samples` grid
/// intervals find the equilibria. `table=True` adds `"table"`: the diagram's columns as
/// numpy arrays (`potential.csv`).
///
/// `var="x,y"` (or `"x,y,z"`): a potential field; the result is `F = -∇U` and its values at
/// the points `at` (`[(0, 1), (1, 0)]`).
///
/// Values are numbers (SI) or strings as the command line reads them (`"3 Å"`, `"pi/6"`);
/// bad input raises MechkitError naming the argument.
#[pyfunction]
#[pyo3(signature = (
    U = None, var = None, *, force = None, range = None, energy = None, mass = None,
    x0 = None, v0 = None, at = None, samples = 2000, table = false, **params
))]
#[allow(non_snake_case, clippy::too_many_arguments)] // `U` as the course writes it
pub fn potential<'py>(
    py: Python<'py>,
    U: Option<&str>,
    var: Option<&Bound<'py, PyAny>>,
    force: Option<&str>,
    range: Option<&Bound<'py, PyAny>>,
    energy: Option<&Bound<'py, PyAny>>,
    mass: Option<&Bound<'py, PyAny>>,
    x0: Option<&Bound<'py, PyAny>>,
    v0: Option<&Bound<'py, PyAny>>,
    at: Option<&Bound<'py, PyAny>>,
    samples: usize,
    table: bool,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let p = Params::read(params)?;
    let vars = variables(var)?;
    if vars.len() > 1 {
        if force.is_some() {
            return Err(error(
                "a field from force= has no single formula to take the gradient of: give U(x, y)",
            ));
        }
        return gradient(py, U, &vars, &p, at);
    }
    let var = vars.concat();
    let Some(range) = range else {
        return Err(error(
            "give the range to analyse, e.g. range=(0.8, 3) or range=\"-1:2\"",
        ));
    };
    let range_text = interval_text(range, "range")?;
    let (a, b) =
        values::increasing_interval(&range_text, "range", &p.values).map_err(value_error)?;
    let given = match (U, force) {
        (Some(u), None) => Given::Potential(u),
        (None, Some(f)) => Given::Force(f),
        (Some(_), Some(_)) => return Err(error("give either a potential U or force=F, not both")),
        (None, None) => {
            return Err(error(
                "give a potential, e.g. mechkit.potential(\"k*x^2/2\", range=(-1, 1), k=1), or a force with force=",
            ));
        }
    };
    let release = match (mass, x0, v0) {
        (None, None, None) => None,
        (Some(m), Some(x0), v0) => {
            if energy.is_some() {
                return Err(error(
                    "energy and mass/x0/v0 both set the energy: give one of them",
                ));
            }
            Some(Release {
                mass: quantity(m, "mass", Dimension::MASS)?,
                x0: value(x0, "x0", &p.values)?,
                v0: v0.map_or(Ok(0.0), |v| value(v, "v0", &p.values))?,
            })
        }
        _ => return Err(error("the motion needs mass and x0 (and v0, default 0)")),
    };
    let question = PotentialQuestion {
        given,
        var: &var,
        range: (a, b),
        params: &p.values,
        energy: energy.map(|e| value(e, "energy", &p.values)).transpose()?,
        release,
        at: match at {
            Some(at) => points_1d(at, &p.values)?,
            None => Vec::new(),
        },
        samples,
        units: axis_units(given, &var, &range_text, &p),
    };
    let (json, csv) = py
        .detach(|| {
            let analysis = analyse_potential(&question)?;
            let csv = table.then(|| analysis.table());
            Ok((serde_json::to_string(&analysis), csv))
        })
        .map_err(calculus_error)?;
    let dict = from_json(py, &json.map_err(json_error)?)?;
    if let Some(csv) = csv {
        dict.set_item("table", table_arrays(py, &csv)?)?;
    }
    Ok(dict)
}

/// `var`: `"x"`, `"x,y"` or a sequence of names.
fn variables(var: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<String>> {
    let Some(var) = var else {
        return Ok(vec!["x".to_string()]);
    };
    if var.is_instance_of::<PyString>() {
        let text: String = var.extract()?;
        return Ok(text.split(',').map(|v| v.trim().to_string()).collect());
    }
    var.extract::<Vec<String>>().map_err(|_| {
        pyo3::exceptions::PyTypeError::new_err(
            "var: give the variable's name, e.g. \"x\", or the coordinates, \"x,y\" or (\"x\", \"y\")",
        )
    })
}

/// `at` in one dimension: a value, a sequence of values, or the command line's `"1, 2"`.
fn points_1d(at: &Bound<'_, PyAny>, p: &[(String, f64)]) -> PyResult<Vec<f64>> {
    if at.is_instance_of::<PyString>() {
        let text: String = at.extract()?;
        return split_top_level(&text, ',')
            .into_iter()
            .map(|v| values::value(v, "at", p).map_err(value_error))
            .collect();
    }
    match items(at) {
        Some(items) => items.iter().map(|v| value(v, "at", p)).collect(),
        None => Ok(vec![value(at, "at", p)?]),
    }
}

/// `at` in 2-D/3-D: a sequence of points (each a sequence of values or `"x, y"`), or the
/// command line's `"0, 1; 1, 0"`.
fn points(at: &Bound<'_, PyAny>, p: &[(String, f64)]) -> PyResult<Vec<Vec<f64>>> {
    let text_point = |text: &str| -> PyResult<Vec<f64>> {
        split_top_level(text, ',')
            .into_iter()
            .map(|v| values::value(v, "at", p).map_err(value_error))
            .collect()
    };
    if at.is_instance_of::<PyString>() {
        let text: String = at.extract()?;
        return split_top_level(&text, ';')
            .into_iter()
            .map(text_point)
            .collect();
    }
    let list = items(at).ok_or_else(|| {
        pyo3::exceptions::PyTypeError::new_err(
            "at: give a list of points, e.g. at=[(0, 1), (1, 0)], or \"0, 1; 1, 0\"",
        )
    })?;
    list.iter()
        .map(|point| {
            if point.is_instance_of::<PyString>() {
                return text_point(&point.extract::<String>()?);
            }
            match items(point) {
                Some(coordinates) => coordinates.iter().map(|c| value(c, "at", p)).collect(),
                None => Ok(vec![value(point, "at", p)?]),
            }
        })
        .collect()
}

/// `F = -∇U` of a potential of 2 or 3 coordinates.
fn gradient<'py>(
    py: Python<'py>,
    u: Option<&str>,
    vars: &[String],
    p: &Params,
    at: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let Some(u) = u else {
        return Err(error("give the potential U(x, y) to take the gradient of"));
    };
    let at = match at {
        Some(at) => points(at, &p.values)?,
        None => Vec::new(),
    };
    let vars: Vec<&str> = vars.iter().map(String::as_str).collect();
    let json = py
        .detach(|| potential_field(u, &vars, &p.values, &at).map(|f| serde_json::to_string(&f)))
        .map_err(calculus_error)?;
    from_json(py, &json.map_err(json_error)?)
}

/// The units of the axes: what the range and the parameters were given in (a number has no
/// unit we know), as the command line infers them.
fn axis_units(given: Given<'_>, var: &str, range: &str, p: &Params) -> AxisUnits {
    let range_dim = split_top_level(range, ':').into_iter().find_map(|end| {
        Quantity::parse(end.trim())
            .ok()
            .map(|q| q.dim)
            .filter(|d| !d.is_none())
    });
    let dims = |name: &str| {
        if name == var { range_dim } else { p.dim(name) }
    };
    AxisUnits::infer(given, var, &dims)
}
