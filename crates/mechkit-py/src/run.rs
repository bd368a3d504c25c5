//! `mechkit.Run`: what a run produced, as Python values: the summary (`summary.json` as a
//! dict), the trajectory (`trajectory.csv`'s columns as numpy arrays, moved from Rust without
//! a copy), the columns' units, and its plots (`run.plot(spec)`, `plot.rs`).

use std::time::Instant;

use mechkit::figure::PlotData;
use mechkit::scenario::{ENERGY_BARS, RunOutput, Trajectory};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::plot::{Plot, Replay};

/// The result of `Scenario.run()`.
///
/// ```python
/// run = mechkit.Scenario.load("examples/feather.toml").run()
/// run.trajectory["feather.x"][-1]   # a numpy float64 array per column
/// run.summary["energy"]["change"]   # summary.json as a dict
/// run.to_pandas()                   # a DataFrame of the trajectory
/// run.plot("v(x)")                   # a plot, as `mechkit run` draws it
/// ```
#[pyclass(module = "mechkit", name = "Run", frozen)]
pub struct Run {
    summary: Py<PyDict>,
    trajectory: Py<PyDict>,
    units: Py<PyDict>,
    failed: bool,
    rows: usize,
    /// The scenario's title, over its plots.
    title: String,
    /// The plots the run recorded (`[output] plots`) and its energy bars.
    plots: Vec<PlotData>,
    /// How to run it again for another plot.
    replay: Replay,
    /// Seconds spent: the run in the library, its summary and its trajectory made Python
    /// values.
    timings: Timings,
}

/// Where a run's time went, in seconds (`Run.timings`).
#[derive(Clone, Copy)]
struct Timings {
    run: f64,
    summary: f64,
    trajectory: f64,
}

impl Run {
    /// The Python view of a run's outputs; the trajectory's columns become numpy arrays that
    /// own the Rust vectors' memory. `replay` is what the run was run from, `run_seconds` the
    /// time the run took.
    pub fn new(
        py: Python<'_>,
        out: RunOutput,
        trajectory: Trajectory,
        mut replay: Replay,
        run_seconds: f64,
    ) -> PyResult<Self> {
        let start = Instant::now();
        let json = py.import("json")?;
        let summary = json
            .call_method1("loads", (out.summary.to_json(),))?
            .cast_into::<PyDict>()?;
        let summary_seconds = start.elapsed().as_secs_f64();
        let start = Instant::now();
        let rows = trajectory.len();
        let (columns, data) = trajectory.into_data();
        let arrays = PyDict::new(py);
        let units = PyDict::new(py);
        for (column, values) in columns.into_iter().zip(data) {
            arrays.set_item(&column.name, PyArray1::from_vec(py, values))?;
            units.set_item(&column.name, column.unit)?;
        }
        let timings = Timings {
            run: run_seconds,
            summary: summary_seconds,
            trajectory: start.elapsed().as_secs_f64(),
        };
        replay.limited = out.summary.stop_reason == "output_limit";
        let mut plots = out.plots;
        if !plots.iter().any(|p| p.spec == ENERGY_BARS) {
            plots.push(out.summary.energy_bars());
        }
        Ok(Self {
            summary: summary.unbind(),
            trajectory: arrays.unbind(),
            units: units.unbind(),
            failed: out.report.stop_reason.is_failure(),
            rows,
            title: out.summary.title,
            plots,
            replay,
            timings,
        })
    }
}

#[pymethods]
impl Run {
    /// The run's summary: a dict equal to what `mechkit run` writes to `summary.json` (its
    /// `files` aside: nothing was written).
    #[getter]
    fn summary(&self, py: Python<'_>) -> Py<PyDict> {
        self.summary.clone_ref(py)
    }

    /// The trajectory: a dict from the column names of `trajectory.csv` (`t`,
    /// `feather.x`, `work.gravity`, ...) to numpy float64 arrays, in the CSV's order.
    #[getter]
    fn trajectory(&self, py: Python<'_>) -> Py<PyDict> {
        self.trajectory.clone_ref(py)
    }

    /// The unit of each trajectory column (`"m/s"`; `"1"` for a pure number), None when
    /// unknown.
    #[getter]
    fn units(&self, py: Python<'_>) -> Py<PyDict> {
        self.units.clone_ref(py)
    }

    /// The located events (the summary's `events`): each a dict with `name`, `t`, `state`,
    /// `last_step`, ...
    #[getter]
    fn events<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        Ok(self
            .summary
            .bind(py)
            .as_any()
            .get_item("events")?
            .cast_into()?)
    }

    /// The `[observe]` results (the summary's `observables`): name → value (SI).
    #[getter]
    fn observables<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        Ok(self
            .summary
            .bind(py)
            .as_any()
            .get_item("observables")?
            .cast_into()?)
    }

    /// Whether the computation failed (diverged, step size underflow, an endless event): the
    /// command line would exit with 1. The summary's `divergence` says why.
    #[getter]
    fn failed(&self) -> bool {
        self.failed
    }

    /// The trajectory as a pandas DataFrame, one column per trajectory column; the units are
    /// in `df.attrs["units"]`. Needs pandas (`pip install mechkit[pandas]`).
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let pandas = py.import("pandas")?;
        let frame = pandas.call_method1("DataFrame", (self.trajectory.bind(py),))?;
        frame
            .getattr("attrs")?
            .set_item("units", self.units.bind(py).copy()?)?;
        Ok(frame)
    }

    /// The plot `spec` (`"v(x)"`, `"energy(t)"`, `"energy-bars"`, any plot `[output] plots`
    /// accepts) drawn as `mechkit run` draws it, in `style` `"paper"` or `"slides"`. A plot
    /// the scenario lists comes from this run; another runs the scenario again, recording
    /// it (the same run: the same points; the GIL is released and Ctrl-C stops it). A spec
    /// that is not a plot of the scenario raises ScenarioError.
    #[pyo3(signature = (spec, *, style = "paper"))]
    fn plot(&self, py: Python<'_>, spec: &str, style: &str) -> PyResult<Plot> {
        let style = crate::plot::style(style)?;
        let data = crate::plot::of_run(py, &self.plots, &self.replay, spec)?;
        Ok(Plot::new(data, self.title.clone(), style))
    }

    /// The run's animation: the bodies drawn to scale in their shapes, frame by frame, as
    /// `mechkit animate` draws them. Jupyter shows it inline (the HTML player); `.save(path)`
    /// writes a GIF, an HTML file or an MP4.
    #[pyo3(signature = (fps = mechkit::animation::DEFAULT_FPS, speed = None, trails = true, energy_bars = true, width = 640, height = 480))]
    #[allow(clippy::too_many_arguments)]
    fn animate(
        &self,
        py: Python<'_>,
        fps: f64,
        speed: Option<f64>,
        trails: bool,
        energy_bars: bool,
        width: u32,
        height: u32,
    ) -> PyResult<crate::animation::Animation> {
        crate::animation::of_run(
            py,
            &self.replay,
            self.trajectory.bind(py),
            mechkit::animation::AnimationOptions {
                fps,
                speed,
                trails,
                energy_bars,
            },
            mechkit_cli::animate::Canvas { width, height },
        )
    }

    /// Where the time went, in seconds: `run` (the simulation, in Rust), `summary` (the
    /// summary made a dict) and `trajectory` (the columns handed to numpy: moved, not
    /// copied, so this does not grow with the rows).
    #[getter]
    fn timings<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let t = self.timings;
        let d = PyDict::new(py);
        d.set_item("run", t.run)?;
        d.set_item("summary", t.summary)?;
        d.set_item("trajectory", t.trajectory)?;
        Ok(d)
    }

    fn __len__(&self) -> usize {
        self.rows
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let summary = self.summary.bind(py);
        let field = |k: &str| {
            summary
                .get_item(k)
                .ok()
                .flatten()
                .map_or_else(|| "?".to_string(), |v| v.to_string())
        };
        format!(
            "<mechkit.Run {} rows, t_end = {} s, stop_reason = {}>",
            self.rows,
            field("t_end"),
            field("stop_reason")
        )
    }
}
