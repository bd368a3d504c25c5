//! Python values given to the batch commands' keyword arguments, read with messages that name
//! the argument: whole numbers, numbers, strings, and a dict of numpy arrays for results.

use numpy::PyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

use crate::errors::MechkitError;

/// The Python type's name of `value`, for messages.
pub fn type_name(value: &Bound<'_, PyAny>) -> String {
    value
        .get_type()
        .name()
        .map_or_else(|_| "?".to_string(), |n| n.to_string())
}

/// A whole number ≥ 0 given to `key` (a count, a seed); a negative one is refused with the
/// command line's words, anything but an integer is a TypeError.
pub fn whole(key: &str, value: &Bound<'_, PyAny>) -> PyResult<u64> {
    if !value.is_instance_of::<PyBool>() {
        if let Ok(n) = value.extract::<u64>() {
            return Ok(n);
        }
        if let Ok(n) = value.extract::<i64>() {
            return Err(MechkitError::new_err(format!(
                "{key}: `{n}` is not a whole number ≥ 0 (a count, e.g. 20)"
            )));
        }
    }
    Err(PyTypeError::new_err(format!(
        "{key} is a {}: give a whole number ≥ 0 (an int)",
        type_name(value)
    )))
}

/// A count given to `key`.
pub fn count(key: &str, value: &Bound<'_, PyAny>) -> PyResult<usize> {
    let n = whole(key, value)?;
    usize::try_from(n).map_err(|_| MechkitError::new_err(format!("{key}: `{n}` is too large")))
}

/// A number given to `key` (an int or a float, not a bool); the library checks its range.
pub fn number(key: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    if !value.is_instance_of::<PyBool>()
        && let Ok(x) = value.extract::<f64>()
    {
        return Ok(x);
    }
    Err(PyTypeError::new_err(format!(
        "{key} is a {}: give a number",
        type_name(value)
    )))
}

/// A string given to `key`.
pub fn text(key: &str, value: &Bound<'_, PyAny>) -> PyResult<String> {
    if value.is_instance_of::<PyString>() {
        return value.extract();
    }
    Err(PyTypeError::new_err(format!(
        "{key} is a {}: give a string",
        type_name(value)
    )))
}

/// A bool given to `key`.
pub fn flag(key: &str, value: &Bound<'_, PyAny>) -> PyResult<bool> {
    if value.is_instance_of::<PyBool>() {
        return value.extract();
    }
    Err(PyTypeError::new_err(format!(
        "{key} is a {}: give True or False",
        type_name(value)
    )))
}

/// `{name: numpy float64 array}` of `columns` and their values, in order.
pub fn float_columns(
    py: Python<'_>,
    names: impl IntoIterator<Item = impl AsRef<str>>,
    data: Vec<Vec<f64>>,
) -> PyResult<Bound<'_, PyDict>> {
    let dict = PyDict::new(py);
    for (name, values) in names.into_iter().zip(data) {
        dict.set_item(name.as_ref(), PyArray1::from_vec(py, values))?;
    }
    Ok(dict)
}

/// `json.loads(text)`: a library result serialized by serde, as Python values.
pub fn from_json<'py>(py: Python<'py>, text: &str) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?.call_method1("loads", (text,))
}

/// A pandas DataFrame of `columns`, the units in `df.attrs["units"]`.
pub fn data_frame<'py>(
    py: Python<'py>,
    columns: &Bound<'py, PyDict>,
    units: &Bound<'py, PyDict>,
) -> PyResult<Bound<'py, PyAny>> {
    let frame = py.import("pandas")?.call_method1("DataFrame", (columns,))?;
    frame.getattr("attrs")?.set_item("units", units.copy()?)?;
    Ok(frame)
}
