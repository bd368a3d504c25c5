//! The Rust side of `mechkit.sweep(..., client=...)` (`python/mechkit/_sweep.py`): a sweep
//! split into shards that run in other processes (Dask workers) and merged back.
//!
//! - `_sweep_plan(scenario, set, random=, seed=, plot=, **params)`, on the client, checks the
//!   arguments as `mechkit.sweep` does and gives what a worker needs as plain values: the
//!   scenario's name and TEXT (a path may not exist on a worker), the `--set` texts, the
//!   sampling, the plot, and the number of runs;
//! - `_sweep_part(name, text, set, random, seed, plot, shard)`, on a worker, runs one shard
//!   (`shard="K/N"`) on one thread and gives its table as bytes (`SweepTable::to_bytes`:
//!   every number to the bit, the recorded plots);
//! - `_sweep_merge(name, text, set, random, seed, plot, parts)`, on the client, joins the
//!   parts with the library's `merge_tables` (the checks of `mechkit sweep-merge`) into the
//!   `SweepResult` that `mechkit.sweep` without a client returns.

use mechkit::scenario::sweep::{Sampling, Shard, SweepTable, merge_tables};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyDict};

use super::sweep_result::SweepResult;
use super::sweep_run::{Request, sweep_error};

/// Checks a sweep's arguments and returns them as plain values for `_sweep_part` and
/// `_sweep_merge`: a dict of `name`, `text`, `set` (a list of `--set` texts), `random`,
/// `seed`, `plot` (a spec, `""` for the scenario's first plot, or False) and `runs`.
#[pyfunction]
#[pyo3(name = "_sweep_plan", signature = (scenario, set = None, *, random = None,
    seed = None, plot = None, **params))]
pub fn sweep_plan<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, PyAny>,
    set: Option<&Bound<'py, PyAny>>,
    random: Option<&Bound<'py, PyAny>>,
    seed: Option<&Bound<'py, PyAny>>,
    plot: Option<&Bound<'py, PyAny>>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let request = Request::read(py, scenario, set, random, seed, plot, params)?;
    // the scenario itself is checked here, not on every worker
    request.base(py)?;
    let (random, seed) = match request.grid.sampling {
        Sampling::Random { n, seed } => (Some(n), Some(seed)),
        Sampling::Grid => (None, None),
    };
    let plan = PyDict::new(py);
    plan.set_item("name", &request.name)?;
    plan.set_item("text", &request.text)?;
    plan.set_item("set", &request.sets)?;
    plan.set_item("random", random)?;
    plan.set_item("seed", seed)?;
    match &request.plot {
        Some(spec) => plan.set_item("plot", spec)?,
        None => plan.set_item("plot", PyBool::new(py, false))?,
    }
    plan.set_item("runs", request.grid.len())?;
    Ok(plan)
}

/// Runs the shard `shard` ("K/N") of the sweep of `_sweep_plan` on one thread and returns its
/// table as bytes.
#[pyfunction]
#[pyo3(name = "_sweep_part", signature = (name, text, set, random, seed, plot, shard))]
#[allow(clippy::too_many_arguments)] // the plan's values, as `_sweep_plan` gives them
pub fn sweep_part<'py>(
    py: Python<'py>,
    name: String,
    text: String,
    set: Vec<String>,
    random: Option<usize>,
    seed: Option<u64>,
    plot: Option<&Bound<'py, PyAny>>,
    shard: &str,
) -> PyResult<Bound<'py, PyBytes>> {
    let request = Request::new(name, text, set, random, seed, plot_of(plot)?)?;
    let shard = Shard::parse(shard).map_err(sweep_error)?;
    let table = request.run(py, Some(shard), 1)?;
    let bytes = py.detach(|| table.to_bytes());
    Ok(PyBytes::new(py, &bytes))
}

/// Merges the parts (`_sweep_part`'s bytes) of the sweep of `_sweep_plan` into its
/// `SweepResult`, as `mechkit sweep-merge` merges the parts' files.
#[pyfunction]
#[pyo3(name = "_sweep_merge", signature = (name, text, set, random, seed, plot, parts))]
#[allow(clippy::too_many_arguments)] // the plan's values, as `_sweep_plan` gives them
pub fn sweep_merge(
    py: Python<'_>,
    name: String,
    text: String,
    set: Vec<String>,
    random: Option<usize>,
    seed: Option<u64>,
    plot: Option<&Bound<'_, PyAny>>,
    parts: Vec<Vec<u8>>,
) -> PyResult<SweepResult> {
    let request = Request::new(name, text, set, random, seed, plot_of(plot)?)?;
    let table = py
        .detach(|| {
            let tables = parts
                .into_iter()
                .map(|p| SweepTable::from_bytes(&p))
                .collect::<Result<Vec<_>, _>>()?;
            merge_tables(tables)
        })
        .map_err(sweep_error)?;
    request.result(py, table)
}

/// The plan's `plot`: a spec (`""` for the scenario's first plot), or False for none.
fn plot_of(plot: Option<&Bound<'_, PyAny>>) -> PyResult<Option<String>> {
    match plot {
        Some(p) if p.is_instance_of::<PyBool>() => Ok(None),
        Some(p) => Ok(Some(p.extract()?)),
        None => Ok(Some(String::new())),
    }
}
