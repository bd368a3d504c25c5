//! `mechkit.sweep(scenario, ...)`: `mechkit sweep` in memory. The swept constants are read
//! as the command reads `--set` (`Parameter::parse`), the runs are `run_sweep` on a thread
//! pool of `threads` workers, and the result is the library's `SweepTable`: `sweep.csv`'s
//! columns as numpy arrays, one summary per run, and the overlay of the runs' plots.

use std::path::PathBuf;

use mechkit::md::MAX_THREADS;
use mechkit::scenario::sweep::{
    Parameter, Sampling, Shard, SweepError, SweepGrid, SweepOptions, SweepTable, run_sweep,
};
use mechkit::scenario::{Scenario as Checked, read_source};
use mechkit::simulate::Cancel;
use numpy::PyArray1;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyString};

use super::arguments::{count, data_frame, from_json, type_name, whole};
use crate::errors::{MechkitError, scenario_error};
use crate::plot::Plot;
use crate::scenario::Scenario;

/// Curves labelled in the overlay's legend at most (as `mechkit sweep` draws it).
const LEGEND: usize = 10;

/// Runs `mechkit sweep` in memory and returns a `SweepResult`.
///
/// `scenario` is a `mechkit.Scenario` or a scenario file's path. The swept constants are
/// `set`, a string or a list of strings as `--set` takes them (`"v0=0:5:51"`, `"k=1,2,4"`,
/// `"v0=0 km/h:18 km/h:51"`), and keyword arguments: `v0="0:5:51"`, `k=[1, 2, 4]`, `m=2.0`
/// (numbers in SI); the last varies fastest. `random=N` draws N points instead of the grid
/// (seeded by `seed`), `shard="K/N"` runs one slice of it, `threads` workers run it (all
/// cores by default; the table does not depend on it). `plot` is the plot every run records
/// for the overlay: None for the scenario's first plot (as the command), a spec, or False.
/// The GIL is released while it runs; Ctrl-C stops the runs in flight and raises
/// KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (scenario, set = None, *, random = None, seed = None, shard = None,
    threads = None, plot = None, **params))]
#[allow(clippy::too_many_arguments)] // the command's options, as Python keyword arguments
pub fn sweep(
    py: Python<'_>,
    scenario: &Bound<'_, PyAny>,
    set: Option<&Bound<'_, PyAny>>,
    random: Option<&Bound<'_, PyAny>>,
    seed: Option<&Bound<'_, PyAny>>,
    shard: Option<&str>,
    threads: Option<&Bound<'_, PyAny>>,
    plot: Option<&Bound<'_, PyAny>>,
    params: Option<&Bound<'_, PyDict>>,
) -> PyResult<SweepResult> {
    let (name, text) = source(py, scenario)?;
    let sets = sets(set, params)?;
    let sweep_error = |e: SweepError| MechkitError::new_err(e.to_string());
    let params = sets
        .iter()
        .map(|s| Parameter::parse(s))
        .collect::<Result<Vec<_>, _>>()
        .map_err(sweep_error)?;
    let sampling = match random {
        Some(n) => Sampling::Random {
            n: count("random", n)?,
            seed: seed.map_or(Ok(1), |s| whole("seed", s))?,
        },
        None if seed.is_some() => {
            return Err(MechkitError::new_err(
                "seed goes with random: it seeds the random sample (random=N)",
            ));
        }
        None => Sampling::Grid,
    };
    let grid = SweepGrid::new(params, sampling);
    grid.check().map_err(sweep_error)?;
    let shard = shard.map(Shard::parse).transpose().map_err(sweep_error)?;
    let threads = workers(threads)?;
    let options = SweepOptions {
        shard,
        plot: plot_option(plot)?,
        cancel: Cancel::new(),
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| MechkitError::new_err(format!("cannot start the worker threads: {e}")))?;
    let (name_ref, text_ref, grid_ref, options_ref) = (&name, &text, &grid, &options);
    let result = crate::interrupt::run(py, &options.cancel, move || {
        pool.install(|| run_sweep(name_ref, text_ref, grid_ref, options_ref, &|| {}))
    })?;
    let table = result.map_err(|e| match e {
        SweepError::Scenario { source } => scenario_error(py, &source),
        e => sweep_error(e),
    })?;
    let base = py
        .detach(|| Checked::from_str(&name, &text))
        .map_err(|e| scenario_error(py, &e))?;
    let texts: Vec<&str> = grid.params.iter().map(|p| p.text.as_str()).collect();
    let title = format!("{} runs, {}", table.rows.len(), texts.join("; "));
    SweepResult::new(py, table, &base, title)
}

/// The scenario's name (for errors and the manifest) and text: a `mechkit.Scenario`'s, or a
/// file's as `mechkit sweep FILE` reads it.
fn source(py: Python<'_>, scenario: &Bound<'_, PyAny>) -> PyResult<(String, String)> {
    if let Ok(s) = scenario.cast::<Scenario>() {
        let (name, text) = s.get().source();
        return Ok((name.to_string(), text.to_string()));
    }
    if scenario.is_instance_of::<PyString>() || scenario.hasattr("__fspath__")? {
        let path: PathBuf = scenario.extract()?;
        let text = py
            .detach(|| read_source(&path))
            .map_err(|e| scenario_error(py, &e))?;
        return Ok((path.display().to_string(), text));
    }
    Err(PyTypeError::new_err(format!(
        "scenario is a {}: give a mechkit.Scenario or a scenario file's path",
        type_name(scenario)
    )))
}

/// The swept constants as `--set` texts: `set` (a string or a list of strings), then the
/// keyword arguments (`v0="0:5:51"`, `k=[1, 2, 4]`, `m=2.0`).
fn sets(
    set: Option<&Bound<'_, PyAny>>,
    params: Option<&Bound<'_, PyDict>>,
) -> PyResult<Vec<String>> {
    let mut out: Vec<String> = match set {
        None => Vec::new(),
        Some(s) if s.is_instance_of::<PyString>() => vec![s.extract()?],
        Some(s) => s.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "set is a {}: give a string as --set takes it (\"v0=0:5:51\") or a list of them",
                type_name(s)
            ))
        })?,
    };
    if let Some(params) = params {
        for (key, value) in params.iter() {
            let name: String = key.extract()?;
            out.push(format!("{name}={}", values(&name, &value)?));
        }
    }
    Ok(out)
}

/// The values of a keyword argument as `--set` writes them after the `=`: a string as it is,
/// a number or a list of numbers (SI) printed to round-trip.
fn values(name: &str, value: &Bound<'_, PyAny>) -> PyResult<String> {
    if value.is_instance_of::<PyString>() {
        return value.extract();
    }
    let wrong = || {
        PyTypeError::new_err(format!(
            "{name} is a {}: give a number (SI), a list of numbers, or a string as --set \
             takes it after the `=` (\"0:5:51\", \"0 km/h:18 km/h:51\")",
            type_name(value)
        ))
    };
    if value.is_instance_of::<PyBool>() {
        return Err(wrong());
    }
    if let Ok(x) = value.extract::<f64>() {
        return Ok(x.to_string());
    }
    let list: Vec<f64> = value.extract().map_err(|_| wrong())?;
    Ok(list
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(","))
}

/// The worker threads: `threads`, or every core; as `mechkit sweep --threads` checks it.
fn workers(threads: Option<&Bound<'_, PyAny>>) -> PyResult<usize> {
    match threads.map(|t| count("threads", t)).transpose()? {
        Some(0) => Err(MechkitError::new_err(
            "threads must be at least 1\n  = hint: leave it out to use every core",
        )),
        Some(n) if n > MAX_THREADS => Err(MechkitError::new_err(format!(
            "threads={n} is more than {MAX_THREADS}\n  = hint: leave it out to use every core; \
             more threads than cores only slow a sweep down"
        ))),
        Some(n) => Ok(n),
        None => Ok(std::thread::available_parallelism().map_or(1, std::num::NonZero::get)),
    }
}

/// `plot`: None for the scenario's first plot, a spec, or False for none.
fn plot_option(plot: Option<&Bound<'_, PyAny>>) -> PyResult<Option<String>> {
    let Some(plot) = plot else {
        return Ok(Some(String::new()));
    };
    if plot.is_instance_of::<PyString>() {
        return Ok(Some(plot.extract()?));
    }
    if plot.is_instance_of::<PyBool>() && !plot.extract::<bool>()? {
        return Ok(None);
    }
    Err(PyTypeError::new_err(format!(
        "plot is {}: give a plot such as \"v(x)\", None for the scenario's first plot, or \
         False for none",
        plot.repr()
            .map_or_else(|_| "?".to_string(), |r| r.to_string())
    )))
}

/// The result of `mechkit.sweep()`.
///
/// ```python
/// s = mechkit.sweep("examples/sweep/throw.toml", v0="0:5:51")
/// s.table["x_max"]          # sweep.csv's columns as numpy arrays
/// s.rows[3]["stop_reason"]  # one run's summary
/// s.plot()                  # the runs' plots in one figure, as `mechkit sweep -o DIR` draws it
/// ```
#[pyclass(module = "mechkit", name = "SweepResult", frozen)]
pub struct SweepResult {
    table: SweepTable,
    columns: Py<PyDict>,
    units: Py<PyDict>,
    rows: Py<PyList>,
    title: String,
}

impl SweepResult {
    fn new(py: Python<'_>, table: SweepTable, base: &Checked, title: String) -> PyResult<Self> {
        let columns = PyDict::new(py);
        let header = table.header();
        let mut names = header.iter();
        let mut column = |values: Bound<'_, PyAny>| -> PyResult<()> {
            let name = names.next().expect("one value per column of the header");
            columns.set_item(name, values)
        };
        let rows = &table.rows;
        let floats = |f: &dyn Fn(&mechkit::scenario::sweep::SweepRow) -> f64| {
            PyArray1::from_vec(py, rows.iter().map(f).collect()).into_any()
        };
        column(PyArray1::from_vec(py, rows.iter().map(|r| r.index).collect()).into_any())?;
        for i in 0..table.params.len() {
            column(floats(&|r| r.values[i]))?;
        }
        let reasons: Vec<&str> = rows.iter().map(|r| r.stop_reason.as_str()).collect();
        column(py.import("numpy")?.call_method1("array", (reasons,))?)?;
        column(floats(&|r| r.t_end))?;
        column(PyArray1::from_vec(py, rows.iter().map(|r| r.steps).collect()).into_any())?;
        for i in 0..table.observables.len() {
            column(floats(&|r| r.observables[i]))?;
        }
        column(floats(&|r| r.kinetic_end))?;
        column(floats(&|r| r.potential_end.unwrap_or(f64::NAN)))?;
        column(floats(&|r| r.energy_end))?;
        column(floats(&|r| r.work_energy_residual))?;
        let units = PyDict::new(py);
        for c in table.columns(base) {
            units.set_item(&c.name, c.unit.as_deref())?;
        }
        let json = serde_json::to_string(&table.rows)
            .map_err(|e| MechkitError::new_err(format!("cannot write the rows: {e}")))?;
        let summaries = from_json(py, &json)?.cast_into::<PyList>()?;
        Ok(Self {
            table,
            columns: columns.unbind(),
            units: units.unbind(),
            rows: summaries.unbind(),
            title,
        })
    }
}

#[pymethods]
impl SweepResult {
    /// `sweep.csv`'s columns as numpy arrays, in its order: `index`, the swept constants,
    /// `stop_reason` (strings), `t_end`, `steps`, the observables, `K_end`, `U_end` (NaN
    /// where no force has a potential), `E_end`, `work_energy_residual`.
    #[getter]
    fn table(&self, py: Python<'_>) -> Py<PyDict> {
        self.columns.clone_ref(py)
    }

    /// The unit of each column (`sweep.units.json`); None for text or an unknown unit.
    #[getter]
    fn units(&self, py: Python<'_>) -> Py<PyDict> {
        self.units.clone_ref(py)
    }

    /// One summary per run, in run order: dicts with `index`, `values` (of the swept
    /// constants, in the order of `params`), `stop_reason`, `t_end`, `steps`, `observables`
    /// (in the order of `observables`), `kinetic_end`, `potential_end`, `energy_end`,
    /// `work_energy_residual`.
    #[getter]
    fn rows(&self, py: Python<'_>) -> Py<PyList> {
        self.rows.clone_ref(py)
    }

    /// The swept constants' names.
    #[getter]
    fn params(&self) -> Vec<String> {
        self.table.params.clone()
    }

    /// The observables' names (`[observe]`).
    #[getter]
    fn observables(&self) -> Vec<String> {
        self.table.observables.clone()
    }

    /// How many runs the whole sweep has (a shard holds fewer rows).
    #[getter]
    fn runs(&self) -> usize {
        self.table.runs
    }

    /// `sweep.manifest.json` as a dict: the sweep's identity, its runs, its shard.
    #[getter]
    fn manifest<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        from_json(py, &self.table.manifest_json())
    }

    /// The text of `sweep.csv` (`sweep.partK.csv` for a shard), byte for byte.
    fn to_csv(&self) -> String {
        self.table.to_csv()
    }

    /// The table as a pandas DataFrame, the units in `df.attrs["units"]`.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        data_frame(py, self.columns.bind(py), self.units.bind(py))
    }

    /// The runs' plots in one figure, as `mechkit sweep -o DIR` draws it, in `style`
    /// `"paper"` or `"slides"`. Raises MechkitError when the sweep recorded no plot
    /// (`plot=False`, or a scenario without plots).
    #[pyo3(signature = (*, style = "paper"))]
    fn plot(&self, style: &str) -> PyResult<Plot> {
        let style = crate::plot::style(style)?;
        let overlay = self.table.overlay(LEGEND).ok_or_else(|| {
            MechkitError::new_err(
                "the sweep recorded no plot: give plot=\"v(x)\" (or leave it out for the \
                 scenario's first plot)",
            )
        })?;
        Ok(Plot::new(overlay, self.title.clone(), style))
    }

    fn __len__(&self) -> usize {
        self.table.rows.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "<mechkit.SweepResult {} of {} runs: {}>",
            self.table.rows.len(),
            self.table.runs,
            self.table.params.join(", ")
        )
    }
}
