//! `mechkit.SweepResult`: a sweep's table (`sweep.csv`'s columns as numpy arrays, one summary
//! per run) and the overlay of its runs' plots.

use mechkit::scenario::Scenario as Checked;
use mechkit::scenario::sweep::SweepTable;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use super::arguments::{data_frame, from_json};
use crate::errors::MechkitError;
use crate::plot::Plot;

/// Curves labelled in the overlay's legend at most (as `mechkit sweep` draws it).
const LEGEND: usize = 10;

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
    pub fn new(py: Python<'_>, table: SweepTable, base: &Checked, title: String) -> PyResult<Self> {
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
