//! Sampled data: `mechkit.trapz`, `cumtrapz` and `simpson`, the sample rules of `mechkit work`
//! ([`SampleRule`]) on numpy arrays, and `mechkit.derive`, `mechkit derive` on a data file or
//! on arrays (`mechkit::deriv::derive_motion`).
//!
//! Arrays are 1-D float64 (lists and other dtypes are converted); their values must be
//! finite and the abscissa strictly increasing, which the library leaves to whoever reads
//! the data: here, this front.

use std::path::PathBuf;

use mechkit::data::{ColumnRef, Table};
use mechkit::deriv::{
    Derivation, DeriveError, DeriveQuestion, DerivedMotion, Difference, SavitzkyGolay,
    derive_motion,
};
use mechkit::inputs::Input;
use mechkit::quad::{SampleRule, cumulative, integrate_samples};
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};

use crate::calculus::{error, to_dict};

/// `value` as a contiguous 1-D float64 array (numpy converts lists and other dtypes); `name`
/// names it in errors.
fn array<'py>(
    py: Python<'py>,
    value: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<PyReadonlyArray1<'py, f64>> {
    let numpy = py.import("numpy")?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", "float64")?;
    let a = numpy.call_method("asarray", (value,), Some(&kwargs))?;
    let ndim: usize = a.getattr("ndim")?.extract()?;
    if ndim != 1 {
        let shape = a.getattr("shape")?;
        return Err(error(format!(
            "{name} must be a 1-D array, not one of shape {shape}"
        )));
    }
    let a = numpy.call_method1("ascontiguousarray", (a,))?;
    a.cast_into::<PyArray1<f64>>()?
        .try_readonly()
        .map_err(|e| error(format!("{name}: {e}")))
}

fn slice<'a>(a: &'a PyReadonlyArray1<'_, f64>) -> PyResult<&'a [f64]> {
    a.as_slice().map_err(|e| error(e.to_string()))
}

/// Every value finite.
fn finite(values: &[f64], name: &str) -> PyResult<()> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(i) => Err(error(format!(
            "{name}[{i}] is {}: the samples must be finite numbers",
            values[i]
        ))),
        None => Ok(()),
    }
}

/// Each value larger than the one before.
fn increasing(values: &[f64], name: &str) -> PyResult<()> {
    match (1..values.len()).find(|&i| values[i] <= values[i - 1]) {
        Some(i) => Err(error(format!(
            "{name} must increase strictly, but {name}[{i}] = {} follows {name}[{}] = {}; sort \
             the samples by {name} and remove or average repeated values",
            mechkit::expr::short_number(values[i]),
            i - 1,
            mechkit::expr::short_number(values[i - 1])
        ))),
        None => Ok(()),
    }
}

/// Runs `rule` on the samples `y` at `x`, or `dx` apart from 0 when `x` is None, with the
/// GIL released.
fn with_samples<T: Send>(
    py: Python<'_>,
    (y, x, dx): (&Bound<'_, PyAny>, Option<&Bound<'_, PyAny>>, f64),
    rule: impl FnOnce(&[f64], &[f64]) -> Result<T, mechkit::quad::SamplesError> + Send,
) -> PyResult<T> {
    let y = array(py, y, "y")?;
    let ys = slice(&y)?;
    finite(ys, "y")?;
    let given = x.map(|x| array(py, x, "x")).transpose()?;
    let grid: Vec<f64>;
    let xs = if let Some(x) = &given {
        let xs = slice(x)?;
        finite(xs, "x")?;
        increasing(xs, "x")?;
        xs
    } else {
        if !(dx.is_finite() && dx > 0.0) {
            return Err(error(format!(
                "dx must be a positive finite number, not {}",
                mechkit::expr::short_number(dx)
            )));
        }
        grid = (0..ys.len()).map(|i| i as f64 * dx).collect();
        &grid
    };
    py.detach(|| rule(xs, ys)).map_err(|e| error(e.to_string()))
}

/// `∫ y dx` by the trapezoid rule (`mechkit work --method trapezoid`), as NumPy's
/// `trapezoid(y, x)` and `trapezoid(y, dx=dx)`.
#[pyfunction]
#[pyo3(signature = (y, x = None, dx = 1.0))]
pub fn trapz(
    py: Python<'_>,
    y: &Bound<'_, PyAny>,
    x: Option<&Bound<'_, PyAny>>,
    dx: f64,
) -> PyResult<f64> {
    with_samples(py, (y, x, dx), |x, y| {
        integrate_samples(x, y, SampleRule::Trapezoid)
    })
}

/// The running trapezoid integral at every sample, as SciPy's `cumulative_trapezoid(y, x,
/// initial=0)`, plus `initial`; with `initial=None`, without the first sample (SciPy's
/// default, one value fewer than `y`).
#[pyfunction]
#[pyo3(signature = (y, x = None, dx = 1.0, initial = Some(0.0)))]
pub fn cumtrapz<'py>(
    py: Python<'py>,
    y: &Bound<'py, PyAny>,
    x: Option<&Bound<'py, PyAny>>,
    dx: f64,
    initial: Option<f64>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let mut out = with_samples(py, (y, x, dx), |x, y| {
        cumulative(x, y, SampleRule::Trapezoid)
    })?;
    match initial {
        None => {
            out.remove(0);
        }
        Some(c) if c != 0.0 => out.iter_mut().for_each(|v| *v += c),
        Some(_) => {}
    }
    Ok(PyArray1::from_vec(py, out))
}

/// `∫ y dx` by composite Simpson (`mechkit work --method simpson`), as SciPy's `simpson`
/// (≥ 1.11): with an odd number of intervals the last one is integrated on the parabola
/// through the last three samples; two samples give the trapezoid.
#[pyfunction]
#[pyo3(signature = (y, x = None, dx = 1.0))]
pub fn simpson(
    py: Python<'_>,
    y: &Bound<'_, PyAny>,
    x: Option<&Bound<'_, PyAny>>,
    dx: f64,
) -> PyResult<f64> {
    with_samples(py, (y, x, dx), |x, y| {
        integrate_samples(x, y, SampleRule::Simpson)
    })
}

/// `mechkit derive FILE [--t T] [--x X,...] [--method M | --smooth W:O]`: velocity and
/// acceleration of positions sampled in time, from a data file (`path_or_t` a path; `t` and
/// `x` choose its columns, by name or number from 1) or from arrays (`path_or_t` the times;
/// `x` the positions, or a dict of name → positions; `t` the time's name). Returns the
/// command's JSON as a dict, with the series as numpy arrays: `t`, and each column's `x`,
/// `v`, `a`.
#[pyfunction]
#[pyo3(signature = (path_or_t, x = None, *, t = None, method = None, smooth = None))]
pub fn derive<'py>(
    py: Python<'py>,
    path_or_t: &Bound<'py, PyAny>,
    x: Option<&Bound<'py, PyAny>>,
    t: Option<&Bound<'py, PyAny>>,
    method: Option<&str>,
    smooth: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let how = derivation(method, smooth)?;
    let is_path = path_or_t.is_instance_of::<PyString>() || path_or_t.hasattr("__fspath__")?;
    let (table, t_column, x_columns) = if is_path {
        let path: PathBuf = path_or_t.extract()?;
        let table = py
            .detach(|| Table::read(&path))
            .map_err(|e| error(e.to_string()))?;
        let t_column = column_ref(&t.map_or(Ok("1".to_string()), column_text)?, "t")?;
        let x_columns = x
            .map(|x| -> PyResult<Vec<ColumnRef>> {
                column_texts(x)?
                    .into_iter()
                    .map(|c| column_ref(&c, "x"))
                    .collect()
            })
            .transpose()?;
        (table, t_column, x_columns)
    } else {
        (arrays(py, path_or_t, x, t)?, ColumnRef::Index(0), None)
    };
    let question = DeriveQuestion {
        table: &table,
        t: t_column,
        x: x_columns,
        how,
    };
    let d = py.detach(|| derive_motion(&question)).map_err(|e| {
        error(match e {
            DeriveError::Column { input, error } => {
                let name = if input == Input::AbscissaColumn {
                    "t"
                } else {
                    "x"
                };
                format!("{name}: {error}")
            }
            other => other.to_string(),
        })
    })?;
    motion_dict(py, d)
}

/// `--method` or `--smooth`: finite differences (central unless named), or a Savitzky-Golay
/// filter given as a window, `(window, order)` (or a list) or the command line's `"WINDOW[:ORDER]"`
/// (order 2 unless given).
fn derivation(method: Option<&str>, smooth: Option<&Bound<'_, PyAny>>) -> PyResult<Derivation> {
    let Some(smooth) = smooth else {
        let name = method.unwrap_or("central");
        let scheme = Difference::parse(name).ok_or_else(|| {
            error(format!(
                "method: unknown difference `{name}`; use central, forward or backward"
            ))
        })?;
        return Ok(Derivation::Differences(scheme));
    };
    if method.is_some() {
        return Err(error(
            "give either method (finite differences) or smooth (Savitzky-Golay), not both",
        ));
    }
    let whole = |v: &Bound<'_, PyAny>| v.extract::<usize>().ok();
    let (spec, window, order) = if smooth.is_instance_of::<PyString>() {
        let spec: String = smooth.extract()?;
        let (w, o) = spec.split_once(':').unwrap_or((&spec, "2"));
        let (w, o) = (w.trim().parse().ok(), o.trim().parse().ok());
        (spec, w, o)
    } else if let Ok([w, o]) = smooth.extract::<[Bound<'_, PyAny>; 2]>() {
        (format!("({w}, {o})"), whole(&w), whole(&o))
    } else {
        (smooth.to_string(), whole(smooth), Some(2))
    };
    let (Some(window), Some(order)) = (window, order) else {
        return Err(error(format!(
            "smooth {spec}: the window and the polynomial order must be whole numbers (give \
             WINDOW, (WINDOW, ORDER) or \"WINDOW:ORDER\", e.g. 21 or (21, 2))"
        )));
    };
    let filter =
        SavitzkyGolay::new(window, order).map_err(|e| error(format!("smooth {spec}: {e}")))?;
    Ok(Derivation::SavitzkyGolay(filter))
}

/// A column of a file as the command line takes it: a name, or a number from 1.
fn column_text(v: &Bound<'_, PyAny>) -> PyResult<String> {
    if v.is_instance_of::<PyString>() {
        return v.extract();
    }
    v.extract::<i64>().map(|n| n.to_string()).map_err(|_| {
        PyTypeError::new_err(
            "with a file, t and x name its columns: a name or a number from 1 (x: a list of them)",
        )
    })
}

/// `--x`: one column, a comma-separated list, or a list.
fn column_texts(v: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
    if v.is_instance_of::<PyList>() || v.is_instance_of::<pyo3::types::PyTuple>() {
        return v
            .try_iter()?
            .map(|c| column_text(&c?))
            .collect::<PyResult<_>>();
    }
    let text = column_text(v)?;
    Ok(text.split(',').map(str::to_string).collect())
}

fn column_ref(text: &str, name: &str) -> PyResult<ColumnRef> {
    ColumnRef::parse(text).map_err(|e| error(format!("{name}: {e}")))
}

/// The table of arrays: the times (named by `t`, `"t"` unless given) and the positions (`x`,
/// or a dict name → array). A name may give a unit in brackets (`"y [cm]"`), as a file's
/// header does.
fn arrays(
    py: Python<'_>,
    times: &Bound<'_, PyAny>,
    x: Option<&Bound<'_, PyAny>>,
    t: Option<&Bound<'_, PyAny>>,
) -> PyResult<Table> {
    let t_name: String = match t {
        None => "t".to_string(),
        Some(t) => t.extract().map_err(|_| {
            PyTypeError::new_err("with arrays, t is the time's name (a string, e.g. \"t [ms]\")")
        })?,
    };
    let Some(x) = x else {
        return Err(error(
            "x: give the positions, an array or a dict of names and arrays",
        ));
    };
    let mut named: Vec<(String, Bound<'_, PyAny>)> = Vec::new();
    match x.cast::<PyDict>() {
        Ok(dict) => {
            for (k, v) in dict.iter() {
                named.push((k.extract()?, v));
            }
        }
        Err(_) => named.push(("x".to_string(), x.clone())),
    }
    let t_values = array(py, times, "t")?;
    let ts = slice(&t_values)?;
    finite(ts, "t")?;
    increasing(ts, "t")?;
    if ts.len() < 2 {
        return Err(error(format!(
            "at least 2 samples are needed, not {}",
            ts.len()
        )));
    }
    let mut names = vec![t_name];
    let mut columns = vec![ts.to_vec()];
    for (name, values) in named {
        let values = array(py, &values, &name)?;
        let xs = slice(&values)?;
        finite(xs, &name)?;
        if xs.len() != ts.len() {
            return Err(error(format!(
                "{name} has {} samples but t has {}",
                xs.len(),
                ts.len()
            )));
        }
        names.push(name);
        columns.push(xs.to_vec());
    }
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    Table::from_columns("<arrays>", &names, columns).map_err(|e| error(e.to_string()))
}

/// The command's JSON as a dict, with the series moved into numpy arrays: `t`, and each
/// column's `x`, `v` and `a`.
fn motion_dict(py: Python<'_>, d: DerivedMotion) -> PyResult<Bound<'_, PyDict>> {
    let dict = to_dict(py, serde_json::to_string(&d))?;
    let columns = dict.as_any().get_item("columns")?;
    for (i, c) in d.columns.into_iter().enumerate() {
        let column = columns.get_item(i)?;
        column.set_item("x", PyArray1::from_vec(py, c.x))?;
        column.set_item("v", PyArray1::from_vec(py, c.v))?;
        column.set_item("a", PyArray1::from_vec(py, c.a))?;
    }
    dict.set_item("t", PyArray1::from_vec(py, d.t))?;
    Ok(dict)
}
