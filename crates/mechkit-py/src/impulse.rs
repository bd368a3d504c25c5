//! `mechkit.impulse(file, ...)` or `mechkit.impulse(t=..., f=...)`: `mechkit impulse` from
//! Python, the impulse `J = ∫F dt` of a force measured at times (a data file as the command
//! reads it, or two arrays), the average force and `Δv = J/m`: the library's `data_work` with
//! time as the abscissa, as the command's `--json` (a dict).

use std::path::PathBuf;

use mechkit::data::{ColumnRef, Table};
use mechkit::energy::{Abscissa, DataWorkError, DataWorkQuestion, data_work};
use mechkit::inputs::Input;
use mechkit::quad::SampleRule;
use mechkit::units::Dimension;
use numpy::{PyReadonlyArray1, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyInt, PyString};

use crate::arguments::{error, from_json, json_error, quantity, shape_text, type_name};

/// What arrays are called in messages (and in the result's `file`).
const ARRAYS: &str = "<arrays>";

/// `mechkit impulse` as a function: the impulse `J = ∫F dt` of a force measured at times,
/// the average force, the peak, and with `mass` the change of velocity `Δv = J/m` (from
/// `v0`), as the command's `--json` (a dict; the running impulse is `"cumulative"`).
///
/// The samples are a data file, as the command reads it (`t` and `f` name its columns or
/// number them from 1; by default the first two), or, without a file, two 1-D arrays `t=`
/// and `f=` (s and N). `method`: trapezoid, simpson, left, right or midpoint.
#[pyfunction]
#[pyo3(signature = (file = None, *, t = None, f = None, method = "trapezoid", mass = None, v0 = None))]
pub fn impulse<'py>(
    py: Python<'py>,
    file: Option<PathBuf>,
    t: Option<&Bound<'py, PyAny>>,
    f: Option<&Bound<'py, PyAny>>,
    method: &str,
    mass: Option<&Bound<'py, PyAny>>,
    v0: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (table, x, f) = if let Some(path) = file {
        let table = py
            .detach(|| Table::read(&path))
            .map_err(|e| error(e.to_string()))?;
        (table, column(t, "1", "t")?, column(f, "2", "f")?)
    } else {
        let (Some(t), Some(f)) = (t, f) else {
            return Err(error(
                "give a data file of t and F columns (mechkit.impulse(\"baseballforce.d\")), or the samples as arrays t= and f=",
            ));
        };
        let columns = vec![samples(t, "t")?, samples(f, "f")?];
        let table =
            Table::from_columns(ARRAYS, &["t", "F"], columns).map_err(|e| error(e.to_string()))?;
        (table, ColumnRef::Index(0), ColumnRef::Index(1))
    };
    let rule = SampleRule::parse(method).ok_or_else(|| {
        error(format!(
            "method: unknown rule `{method}`; use trapezoid, simpson, left, right or midpoint"
        ))
    })?;
    let question = DataWorkQuestion {
        table: &table,
        x,
        f,
        rule,
        of: Some(Abscissa::Time),
        mass: mass
            .map(|m| quantity(m, "mass", Dimension::MASS))
            .transpose()?,
        v0: v0.map_or(Ok(0.0), |v| quantity(v, "v0", Dimension::VELOCITY))?,
    };
    let json = py
        .detach(|| data_work(&question).map(|w| serde_json::to_string(&w)))
        .map_err(|e| match e {
            DataWorkError::Column { input, error: e } => {
                let name = if input == Input::AbscissaColumn {
                    "t"
                } else {
                    "f"
                };
                error(format!("{name}: {e}"))
            }
            DataWorkError::Input(e) => {
                let name = match e.input {
                    Input::Mass => "mass",
                    Input::StartSpeed => "v0",
                    _ => "method",
                };
                error(format!("{name}: {}", e.message))
            }
            other => error(other.to_string()),
        })?;
    from_json(py, &json.map_err(json_error)?)
}

/// A column of the file: its name or its number counted from 1 (`default` when not given).
fn column(obj: Option<&Bound<'_, PyAny>>, default: &str, name: &str) -> PyResult<ColumnRef> {
    let text = match obj {
        None => default.to_string(),
        Some(c) if c.is_instance_of::<PyString>() => c.extract()?,
        Some(c) if c.is_instance_of::<PyInt>() && !c.is_instance_of::<PyBool>() => {
            c.extract::<i64>()?.to_string()
        }
        Some(c) => {
            return Err(PyTypeError::new_err(format!(
                "{name} is a {}: with a file, give the column's name or its number counted from 1",
                type_name(c)
            )));
        }
    };
    ColumnRef::parse(&text).map_err(|e| error(format!("{name}: {e}")))
}

/// Samples given as a 1-D array (or a list), as float64.
fn samples(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Vec<f64>> {
    let array = obj
        .py()
        .import("numpy")?
        .call_method1("asarray", (obj, "float64"))
        .map_err(|_| {
            PyTypeError::new_err(format!(
                "{name} is a {}: without a file, give the samples as a 1-D array of numbers",
                type_name(obj)
            ))
        })?;
    let array: PyReadonlyArray1<'_, f64> = array.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "{name} is an array of shape {}: give the samples as a 1-D array",
            shape_text(
                &array
                    .cast::<numpy::PyUntypedArray>()
                    .map(|a| a.shape().to_vec())
                    .unwrap_or_default()
            )
        ))
    })?;
    Ok(array.as_array().to_vec())
}
