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
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

use super::arguments::{count, type_name, whole};
use super::sweep_result::SweepResult;
use crate::errors::{MechkitError, scenario_error};
use crate::scenario::Scenario;

/// Runs `mechkit sweep` in memory and returns a `SweepResult`.
///
/// `scenario` is a `mechkit.Scenario` or a scenario file's path. The swept constants are
/// `set`, a string or a list of strings as `--set` takes them (`"v0=0:5:51"`, `"k=1,2,4"`,
/// `"v0=0 km/h:18 km/h:51"`) or a dict of them by name (`{"v0": "0:5:51", "k": [1, 2, 4]}`),
/// and keyword arguments: `v0="0:5:51"`, `k=[1, 2, 4]`, `m=2.0` (numbers in SI); the last
/// varies fastest. `random=N` draws N points instead of the grid
/// (seeded by `seed`), `shard="K/N"` runs one slice of it, `threads` workers run it (all
/// cores by default; the table does not depend on it). `plot` is the plot every run records
/// for the overlay: None for the scenario's first plot (as the command), a spec, or False.
/// The GIL is released while it runs; Ctrl-C stops the runs in flight and raises
/// KeyboardInterrupt. (`mechkit.sweep(..., client=...)`, in `_sweep.py`, runs it on a Dask
/// cluster through `sweep_parts.rs`.)
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
    let request = Request::read(py, scenario, set, random, seed, plot, params)?;
    let shard = shard.map(Shard::parse).transpose().map_err(sweep_error)?;
    let threads = workers(threads)?;
    let table = request.run(py, shard, threads)?;
    request.result(py, table)
}

/// A sweep asked for, checked: the scenario's name and text, the grid, the plot to record.
pub struct Request {
    /// The scenario's name (for errors and the manifest).
    pub name: String,
    /// The scenario's text.
    pub text: String,
    /// The swept constants as `--set` texts.
    pub sets: Vec<String>,
    /// The points.
    pub grid: SweepGrid,
    /// The plot each run records (`Some("")`: the scenario's first), as `SweepOptions::plot`.
    pub plot: Option<String>,
}

impl Request {
    /// Reads `mechkit.sweep`'s arguments (but `shard` and `threads`) and checks them.
    pub fn read(
        py: Python<'_>,
        scenario: &Bound<'_, PyAny>,
        set: Option<&Bound<'_, PyAny>>,
        random: Option<&Bound<'_, PyAny>>,
        seed: Option<&Bound<'_, PyAny>>,
        plot: Option<&Bound<'_, PyAny>>,
        params: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let (name, text) = source(py, scenario)?;
        let sets = sets(set, params)?;
        let random = random.map(|n| count("random", n)).transpose()?;
        let seed = seed.map(|s| whole("seed", s)).transpose()?;
        Self::new(name, text, sets, random, seed, plot_option(plot)?)
    }

    /// A request of plain values: `random` points seeded by `seed`, or the grid.
    pub fn new(
        name: String,
        text: String,
        sets: Vec<String>,
        random: Option<usize>,
        seed: Option<u64>,
        plot: Option<String>,
    ) -> PyResult<Self> {
        let params = sets
            .iter()
            .map(|s| Parameter::parse(s))
            .collect::<Result<Vec<_>, _>>()
            .map_err(sweep_error)?;
        let sampling = match random {
            Some(n) => Sampling::Random {
                n,
                seed: seed.unwrap_or(1),
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
        Ok(Self {
            name,
            text,
            sets,
            grid,
            plot,
        })
    }

    /// Runs the sweep (its `shard`, if given) on `threads` threads, the GIL released; Ctrl-C
    /// stops it.
    pub fn run(
        &self,
        py: Python<'_>,
        shard: Option<Shard>,
        threads: usize,
    ) -> PyResult<SweepTable> {
        let options = SweepOptions {
            shard,
            plot: self.plot.clone(),
            cancel: Cancel::new(),
        };
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| MechkitError::new_err(format!("cannot start the worker threads: {e}")))?;
        let options_ref = &options;
        let result = crate::interrupt::run(py, &options.cancel, move || {
            pool.install(|| run_sweep(&self.name, &self.text, &self.grid, options_ref, &|| {}))
        })?;
        result.map_err(|e| match e {
            SweepError::Scenario { source } => scenario_error(py, &source),
            e => sweep_error(e),
        })
    }

    /// The scenario, checked, with the values of its file.
    pub fn base(&self, py: Python<'_>) -> PyResult<Checked> {
        py.detach(|| Checked::from_str(&self.name, &self.text))
            .map_err(|e| scenario_error(py, &e))
    }

    /// The `SweepResult` of `table`, the rows of this sweep.
    pub fn result(&self, py: Python<'_>, table: SweepTable) -> PyResult<SweepResult> {
        let base = self.base(py)?;
        let texts: Vec<&str> = self.grid.params.iter().map(|p| p.text.as_str()).collect();
        let title = format!("{} runs, {}", table.rows.len(), texts.join("; "));
        SweepResult::new(py, table, &base, title)
    }
}

/// A sweep's error as Python's `MechkitError`.
#[allow(clippy::needless_pass_by_value)] // for `.map_err(sweep_error)`
pub fn sweep_error(e: SweepError) -> PyErr {
    MechkitError::new_err(e.to_string())
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
        Some(s) if s.is_instance_of::<PyDict>() => {
            let mut out = Vec::new();
            for (key, value) in s.cast::<PyDict>()?.iter() {
                let name: String = key.extract().map_err(|_| {
                    PyTypeError::new_err(format!(
                        "set has a key {}: name the constants by strings",
                        key.repr()
                            .map_or_else(|_| "?".to_string(), |r| r.to_string())
                    ))
                })?;
                out.push(format!("{name}={}", values(&name, &value)?));
            }
            out
        }
        Some(s) => s.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "set is a {}: give a string as --set takes it (\"v0=0:5:51\"), a list of them, \
                 or a dict of them by name ({{\"v0\": \"0:5:51\"}})",
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
