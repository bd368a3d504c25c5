//! `mechkit.Plot`: one plot drawn as the `mechkit` command draws it (the same SVG bytes, the
//! same PNG), for Jupyter (`_repr_svg_`, `_repr_png_`) and files (`save`); and where a run's
//! plot comes from (`Run.plot(spec)`).
//!
//! A plot's points are collected while the scenario runs (`[output] plots`), not from the
//! trajectory: a plot can show what no column holds (accelerations, powers), thinned as the
//! run goes. So `Run.plot` hands back the plots the run recorded, and for any other spec runs
//! the scenario again, the same way, recording that plot only: a run is deterministic, so the
//! points are those the first run would have recorded.

use std::path::PathBuf;
use std::sync::OnceLock;

use mechkit::figure::PlotData;
use mechkit::scenario::{ConstantOverride, Scenario as Checked, ScenarioError};
use mechkit::simulate::Cancel;
use mechkit_cli::{PNG_DPI, PlotStyle};
use numpy::PyArray1;
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};

use crate::errors::{MechkitError, scenario_error};

/// The resolution of `Plot.png()` and `_repr_png_` by default: the command line's `--dpi`.
const DPI: u32 = 192;

/// A plot, drawn on demand as `mechkit run` draws it into its output directory.
///
/// ```python
/// run = mechkit.Scenario.load("examples/feather.toml").run()
/// p = run.plot("v(t)")          # shown by Jupyter (SVG, or PNG where SVG is not shown)
/// p.svg                         # the text of what `mechkit run` writes to v_t.svg
/// p.save("v_t.png")             # by the extension: .svg or .png
/// ```
#[pyclass(module = "mechkit", name = "Plot", frozen)]
pub struct Plot {
    data: PlotData,
    title: String,
    style: PlotStyle,
    svg: OnceLock<String>,
    png: OnceLock<Vec<u8>>,
}

impl Plot {
    /// The plot `data` with its title (a run's plots: the scenario's title), in `style`.
    pub fn new(data: PlotData, title: String, style: PlotStyle) -> Self {
        Self {
            data,
            title,
            style,
            svg: OnceLock::new(),
            png: OnceLock::new(),
        }
    }

    /// The SVG text, drawn once (with the GIL released).
    fn svg_text(&self, py: Python<'_>) -> PyResult<&str> {
        if let Some(text) = self.svg.get() {
            return Ok(text);
        }
        let text = py
            .detach(|| mechkit_cli::plot_svg(&self.data, &self.title, self.style))
            .map_err(|e| MechkitError::new_err(format!("cannot draw the plot: {e:#}")))?;
        Ok(self.svg.get_or_init(|| text))
    }

    /// The PNG at `dpi`; the one at [`DPI`] is kept.
    fn png_bytes(&self, py: Python<'_>, dpi: u32) -> PyResult<Vec<u8>> {
        if !PNG_DPI.contains(&dpi) {
            return Err(PyValueError::new_err(format!(
                "dpi must be from {} to {} (96 gives the SVG's own 900x600 pixels), not {dpi}",
                PNG_DPI.start(),
                PNG_DPI.end()
            )));
        }
        if dpi == DPI
            && let Some(png) = self.png.get()
        {
            return Ok(png.clone());
        }
        let png = py
            .detach(|| mechkit_cli::plot_png(&self.data, &self.title, self.style, dpi))
            .map_err(|e| MechkitError::new_err(format!("cannot draw the plot: {e:#}")))?;
        if dpi == DPI {
            return Ok(self.png.get_or_init(|| png).clone());
        }
        Ok(png)
    }
}

#[pymethods]
impl Plot {
    /// The SVG text: the bytes `mechkit` writes to the plot's `.svg` file.
    #[getter]
    fn svg(&self, py: Python<'_>) -> PyResult<&str> {
        self.svg_text(py)
    }

    /// The PNG file's bytes at `dpi` dots per inch (24 to 1200; 96 gives 900x600 pixels,
    /// the default 192 gives 1800x1200, as `mechkit run --format png`).
    #[pyo3(signature = (dpi = DPI))]
    fn png<'py>(&self, py: Python<'py>, dpi: u32) -> PyResult<Bound<'py, PyBytes>> {
        let png = self.png_bytes(py, dpi)?;
        Ok(PyBytes::new(py, &png))
    }

    /// Writes the plot to `path`, SVG or PNG by its extension (`.svg`, `.png`, at `dpi`);
    /// the file is replaced at once, never left half-written.
    #[pyo3(signature = (path, *, dpi = DPI))]
    #[allow(clippy::needless_pass_by_value)] // PyO3 hands arguments over owned
    fn save(&self, py: Python<'_>, path: PathBuf, dpi: u32) -> PyResult<()> {
        let extension = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        let bytes = match extension.as_deref() {
            Some("svg") => self.svg_text(py)?.as_bytes().to_vec(),
            Some("png") => self.png_bytes(py, dpi)?,
            _ => {
                return Err(PyValueError::new_err(format!(
                    "cannot tell the format of {}: give a path ending in .svg or .png",
                    path.display()
                )));
            }
        };
        py.detach(|| mechkit::csv::write_atomic(&path, &bytes))
            .map_err(|e| PyOSError::new_err(format!("cannot write {}: {e}", path.display())))
    }

    /// The plot as written (`"v(x)"`).
    #[getter]
    fn spec(&self) -> &str {
        &self.data.spec
    }

    /// The title drawn over the plot.
    #[getter]
    fn title(&self) -> &str {
        &self.title
    }

    /// `"paper"` or `"slides"`.
    #[getter]
    fn style(&self) -> &'static str {
        match self.style {
            PlotStyle::Paper => "paper",
            PlotStyle::Slides => "slides",
        }
    }

    /// The file name `mechkit` gives the plot, without extension (`v_x`).
    #[getter]
    fn file_stem(&self) -> &str {
        &self.data.file_stem
    }

    /// The axis labels with their units, `(x_label, y_label)`.
    #[getter]
    fn labels(&self) -> (&str, &str) {
        (&self.data.x_label, &self.data.y_label)
    }

    /// The curves: a list of dicts with `label`, and `x` and `y` as numpy arrays.
    #[getter]
    fn series<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let list = PyList::empty(py);
        for s in &self.data.series {
            let curve = PyDict::new(py);
            curve.set_item("label", &s.label)?;
            let (x, y): (Vec<f64>, Vec<f64>) = s.points.iter().copied().unzip();
            curve.set_item("x", PyArray1::from_vec(py, x))?;
            curve.set_item("y", PyArray1::from_vec(py, y))?;
            list.append(curve)?;
        }
        Ok(list)
    }

    fn _repr_svg_(&self, py: Python<'_>) -> PyResult<&str> {
        self.svg_text(py)
    }

    fn _repr_png_<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyBytes>> {
        self.png(py, DPI)
    }

    fn __repr__(&self) -> String {
        let n = self.data.series.len().max(self.data.bars.len());
        let what = if self.data.bars.is_empty() {
            "curve"
        } else {
            "bar"
        };
        format!(
            "<mechkit.Plot {:?}: {n} {what}{}>",
            self.data.spec,
            if n == 1 { "" } else { "s" }
        )
    }
}

/// `"paper"` or `"slides"` (the command line's `--style`).
pub fn style(name: &str) -> PyResult<PlotStyle> {
    match name {
        "paper" => Ok(PlotStyle::Paper),
        "slides" => Ok(PlotStyle::Slides),
        other => Err(PyValueError::new_err(format!(
            "style must be \"paper\" or \"slides\", not {other:?}"
        ))),
    }
}

/// What a run was run from, to run it again for a plot it did not record.
#[derive(Debug, Clone)]
pub struct Replay {
    /// The name errors give (the file's path).
    pub name: String,
    /// The scenario's text.
    pub text: String,
    /// The constants given other values.
    pub overrides: Vec<ConstantOverride>,
    /// Whether the run kept its trajectory up to the output limit: then it ran with the
    /// trajectory's table, whose limit ended it, and runs again so.
    pub limited: bool,
}

/// The plot `spec` of a run: one the run recorded (its `[output] plots`, the energy bars), or
/// else the scenario run again recording `spec` (with the GIL released; Ctrl-C stops it).
pub fn of_run(
    py: Python<'_>,
    recorded: &[PlotData],
    replay: &Replay,
    spec: &str,
) -> PyResult<PlotData> {
    let wanted = spec.trim();
    if let Some(p) = recorded.iter().find(|p| p.spec.trim() == wanted) {
        return Ok(p.clone());
    }
    let cancel = Cancel::new();
    let handle = cancel.clone();
    let result = crate::interrupt::run(py, &cancel, move || -> Result<_, ScenarioError> {
        let mut scenario = Checked::from_str_with(&replay.name, &replay.text, &replay.overrides)?;
        scenario.plots = vec![scenario.plot_spec(wanted)?];
        scenario.energy_bars = false;
        scenario.cancel = handle;
        let out = if replay.limited {
            scenario.run_with_trajectory()?.0
        } else {
            scenario.run()?
        };
        Ok(out.plots.into_iter().next())
    })?;
    match result {
        Ok(Some(plot)) => Ok(plot),
        Ok(None) => Err(MechkitError::new_err(format!(
            "the run recorded no plot `{spec}`"
        ))),
        Err(e) => Err(scenario_error(py, &e)),
    }
}
