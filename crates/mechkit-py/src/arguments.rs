//! Python arguments as the library's inputs, read by the parsers the command line uses
//! (`mechkit::values`): a value is a number (SI) or a string as the command line takes it
//! (`"2 kg"`, `"pi/6"`), a vector a string (`"3, -1 m/s"`), a number or a sequence of
//! values; errors name the Python argument (`m1: ...` where the command line says `--m1: ...`).
//! Results go back as the command's `--json`, read by Python's `json`.

use mechkit::csv::Table;
use mechkit::units::{Dimension, Quantity};
use mechkit::values::{self, ValueError};
use numpy::PyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

use crate::errors::MechkitError;

/// A `MechkitError` with the command line's message.
pub fn error(message: impl Into<String>) -> PyErr {
    MechkitError::new_err(message.into())
}

/// The library's error about a value: its message names the argument.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
pub fn value_error(e: ValueError) -> PyErr {
    error(e.message)
}

/// A value as Python gave it: a number, or text for the command line's parsers.
pub enum Scalar {
    /// A number (not a bool), in SI.
    Number(f64),
    /// A string.
    Text(String),
}

/// The type of `obj` for messages: `list`, `dict`.
pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map_or_else(|_| "?".to_string(), |n| n.to_string())
}

/// `obj` as a number or a string; anything else (a bool, a list) is a `TypeError`.
pub fn scalar(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Scalar> {
    if obj.is_instance_of::<PyString>() {
        return Ok(Scalar::Text(obj.extract()?));
    }
    if !obj.is_instance_of::<PyBool>()
        && let Ok(x) = obj.extract::<f64>()
    {
        return Ok(Scalar::Number(x));
    }
    Err(PyTypeError::new_err(format!(
        "{name} is a {}: give a number (SI) or a string with units, e.g. \"2 kg\"",
        type_name(obj)
    )))
}

/// A quantity of dimension `dim`: a number in SI (finite), or a string with units of `dim`.
pub fn quantity(obj: &Bound<'_, PyAny>, name: &str, dim: Dimension) -> PyResult<f64> {
    match scalar(obj, name)? {
        Scalar::Text(text) => values::quantity(&text, name, dim).map_err(value_error),
        Scalar::Number(x) if x.is_finite() => Ok(x),
        Scalar::Number(x) => Err(error(format!("{name}: {x} is not a finite number"))),
    }
}

/// A value that may be a formula of the `params` names (`"b/4"`), or `inf`: a number (not
/// NaN) or a string as `--x0 TEXT` reads.
pub fn value(obj: &Bound<'_, PyAny>, name: &str, params: &[(String, f64)]) -> PyResult<f64> {
    match scalar(obj, name)? {
        Scalar::Text(text) => values::value(&text, name, params).map_err(value_error),
        Scalar::Number(x) if x.is_nan() => Err(error(format!("{name}: NaN is not a number"))),
        Scalar::Number(x) => Ok(x),
    }
}

/// A vector of quantities of `dim`: a string `"3, -1 m/s"` as the command line reads it, a
/// number (one component), or a sequence of values (each a number or a string with units).
pub fn vector(obj: &Bound<'_, PyAny>, name: &str, dim: Dimension) -> PyResult<Vec<f64>> {
    if obj.is_instance_of::<PyString>() {
        let text: String = obj.extract()?;
        return values::vector(&text, name, dim).map_err(value_error);
    }
    match items(obj) {
        Some(items) => items.iter().map(|c| quantity(c, name, dim)).collect(),
        None => Ok(vec![quantity(obj, name, dim)?]),
    }
}

/// A numpy shape as Python writes it: `(400,)`, `(2, 3)`.
pub fn shape_text(shape: &[usize]) -> String {
    let dims: Vec<String> = shape.iter().map(ToString::to_string).collect();
    if let [n] = shape {
        format!("({n},)")
    } else {
        format!("({})", dims.join(", "))
    }
}

/// The items of a sequence that is not a string (a list, a tuple, a numpy array), or `None`.
pub fn items<'py>(obj: &Bound<'py, PyAny>) -> Option<Vec<Bound<'py, PyAny>>> {
    if obj.is_instance_of::<PyString>() {
        return None;
    }
    obj.extract::<Vec<Bound<'py, PyAny>>>().ok()
}

/// An interval as the text `A:B` the command line reads: a string `"-1:2"`, or a pair
/// `(a, b)` of values (numbers are written exactly: Rust prints the shortest round trip).
pub fn interval_text(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<String> {
    if obj.is_instance_of::<PyString>() {
        return obj.extract();
    }
    let ends = items(obj).filter(|ends| ends.len() == 2).ok_or_else(|| {
        PyTypeError::new_err(format!(
            "{name} is a {}: give a pair (a, b) or a string \"a:b\", e.g. {name}=(-1, 2)",
            type_name(obj)
        ))
    })?;
    let text = |end: &Bound<'_, PyAny>| -> PyResult<String> {
        Ok(match scalar(end, name)? {
            Scalar::Number(x) => x.to_string(),
            Scalar::Text(t) => t,
        })
    };
    Ok(format!("{}:{}", text(&ends[0])?, text(&ends[1])?))
}

/// The values of the other names of a formula (`**params`), as `--set` gives them: in order,
/// each a number (SI) or a string that may use the names before it; with the dimension of
/// those given with units.
#[derive(Default)]
pub struct Params {
    /// Names and SI values.
    pub values: Vec<(String, f64)>,
    /// The dimension of each value given with units.
    pub dims: Vec<(String, Dimension)>,
}

impl Params {
    /// Reads the keyword arguments.
    pub fn read(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Self> {
        let mut out = Self::default();
        let Some(kwargs) = kwargs else {
            return Ok(out);
        };
        for (key, obj) in kwargs.iter() {
            let name: String = key.extract()?;
            let x = value(&obj, &name, &out.values)?;
            if let Scalar::Text(text) = scalar(&obj, &name)?
                && let Ok(q) = Quantity::parse(text.trim())
                && !q.dim.is_none()
            {
                out.dims.push((name.clone(), q.dim));
            }
            out.values.push((name, x));
        }
        Ok(out)
    }

    /// The dimension of the value of `name`, when it was given with units.
    pub fn dim(&self, name: &str) -> Option<Dimension> {
        self.dims.iter().find(|(k, _)| k == name).map(|(_, d)| *d)
    }
}

/// The length (or other) unit `unit=` of a report, as `--in` reads it: its size in SI and its
/// text, checked to have dimension `dim` (with `plain_ok`, a bare number is a multiple of SI);
/// `text` is (default unit, what the unit must be, examples).
pub fn output_unit(
    unit: Option<&str>,
    dim: Dimension,
    text: (&str, &str, &str),
    plain_ok: bool,
) -> PyResult<(f64, String)> {
    let (default, must_be, examples) = text;
    let Some(u) = unit else {
        return Ok((1.0, default.to_string()));
    };
    let q = Quantity::parse(u)
        .or_else(|_| Quantity::parse(&format!("1 {u}")))
        .map_err(|e| error(format!("unit: {e}")))?;
    let fits = q.dim == dim || (plain_ok && q.dim.is_none());
    if !(fits && q.value > 0.0 && q.value.is_finite()) {
        return Err(error(format!(
            "unit `{u}` must be {must_be}, e.g. {examples}"
        )));
    }
    Ok((q.value, u.to_string()))
}

/// A result's JSON (as `mechkit CMD --json` prints it) as a Python dict.
pub fn from_json<'py>(py: Python<'py>, json: &str) -> PyResult<Bound<'py, PyDict>> {
    Ok(py
        .import("json")?
        .call_method1("loads", (json,))?
        .cast_into::<PyDict>()?)
}

/// A serialization that failed (a bug: the results are plain data).
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
pub fn json_error(e: serde_json::Error) -> PyErr {
    error(format!(
        "internal error: the result cannot be written as JSON: {e}"
    ))
}

/// A table's columns (what the command writes as CSV) as a dict of numpy float64 arrays.
pub fn table_arrays<'py>(py: Python<'py>, table: &Table) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (k, column) in table.columns().iter().enumerate() {
        let values: Vec<f64> = table.rows().map(|row| row[k]).collect();
        dict.set_item(&column.name, PyArray1::from_vec(py, values))?;
    }
    Ok(dict)
}
