//! `mechkit.MdResult`: what `mechkit.md()` hands back: the library's `MdReport` as a dict
//! (the command's `--json`), and the series `mechkit md -o DIR` writes (`thermo.csv`,
//! `rdf.csv`, `trajectory.xyz`'s positions) with the final state as numpy arrays.

use mechkit::md::{MdStop, Thermo};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::arguments::{data_frame, float_columns, from_json};
use super::md_run::Outcome;
use crate::errors::MechkitError;

/// The result of `mechkit.md()`.
///
/// ```python
/// melt = mechkit.md(cells=4, steps=200)
/// melt.report["energy_change_per_atom"]   # `mechkit md --json` as a dict
/// melt.thermo["temperature"]              # thermo.csv's columns as numpy arrays
/// melt.rdf["g"]                           # rdf.csv's
/// ```
#[pyclass(module = "mechkit", name = "MdResult", frozen)]
pub struct MdResult {
    report: Py<PyDict>,
    thermo: Py<PyDict>,
    thermo_units: Py<PyDict>,
    rdf: Py<PyDict>,
    positions: Py<PyAny>,
    velocities: Py<PyAny>,
    frames: Option<(Py<PyAny>, Py<PyAny>)>,
    divergence: Option<String>,
    atoms: usize,
    steps: usize,
}

impl MdResult {
    pub(super) fn new(py: Python<'_>, o: Outcome) -> PyResult<Self> {
        let json = serde_json::to_string(&o.report)
            .map_err(|e| MechkitError::new_err(format!("cannot write the report: {e}")))?;
        let report = from_json(py, &json)?.cast_into::<PyDict>()?;
        let columns = Thermo::columns(o.dim);
        let mut data = vec![Vec::with_capacity(o.rows.len()); columns.len()];
        for row in &o.rows {
            for (column, x) in data.iter_mut().zip(row.values()) {
                column.push(x);
            }
        }
        let thermo = float_columns(py, columns.iter().map(|c| c.name.as_str()), data)?;
        // the step is a count
        let steps: Vec<usize> = o.rows.iter().map(|r| r.step).collect();
        thermo.set_item(Thermo::NAMES[0], PyArray1::from_vec(py, steps))?;
        let thermo_units = PyDict::new(py);
        for c in &columns {
            thermo_units.set_item(&c.name, c.unit.as_deref())?;
        }
        let (r, g): (Vec<f64>, Vec<f64>) = o.rdf.into_iter().unzip();
        let rdf = float_columns(py, ["r", "g"], vec![r, g])?;
        let atoms = o.report.atoms;
        let shaped = |values: Vec<f64>, shape: &[usize]| -> PyResult<Py<PyAny>> {
            Ok(PyArray1::from_vec(py, values)
                .reshape(shape)?
                .into_any()
                .unbind())
        };
        let frames = match o.frames.steps.len() {
            0 => None,
            n => Some((
                shaped(o.frames.positions, &[n, atoms, o.dim])?,
                PyArray1::from_vec(py, o.frames.steps).into_any().unbind(),
            )),
        };
        Ok(Self {
            report: report.unbind(),
            thermo: thermo.unbind(),
            thermo_units: thermo_units.unbind(),
            rdf: rdf.unbind(),
            positions: shaped(o.positions, &[atoms, o.dim])?,
            velocities: shaped(o.velocities, &[atoms, o.dim])?,
            frames,
            divergence: match o.report.stop {
                MdStop::Diverged(e) => Some(e.to_string()),
                _ => None,
            },
            atoms,
            steps: o.report.steps,
        })
    }
}

#[pymethods]
impl MdResult {
    /// The report: a dict equal to what `mechkit md --json` prints (`atoms`, `start`,
    /// `potential`, `steps`, `seconds`, `energy_change_per_atom`, `msd`, `thermo`: the rows
    /// with energies per atom, ...).
    #[getter]
    fn report(&self, py: Python<'_>) -> Py<PyDict> {
        self.report.clone_ref(py)
    }

    /// The thermo rows: `thermo.csv`'s columns (`step`, `t`, `kinetic`, `potential`,
    /// `total`, `temperature`, `pressure`; energies of the whole system) as numpy arrays.
    #[getter]
    fn thermo(&self, py: Python<'_>) -> Py<PyDict> {
        self.thermo.clone_ref(py)
    }

    /// The unit of each thermo column, in reduced units (`"epsilon"`, `"tau"`, ...).
    #[getter]
    fn thermo_units(&self, py: Python<'_>) -> Py<PyDict> {
        self.thermo_units.clone_ref(py)
    }

    /// The radial distribution function at the end: `rdf.csv`'s columns `r` (σ) and `g`.
    #[getter]
    fn rdf(&self, py: Python<'_>) -> Py<PyDict> {
        self.rdf.clone_ref(py)
    }

    /// The positions at the end, an `(N, d)` array (wrapped into a periodic box).
    #[getter]
    fn positions(&self, py: Python<'_>) -> Py<PyAny> {
        self.positions.clone_ref(py)
    }

    /// The velocities at the end, an `(N, d)` array.
    #[getter]
    fn velocities(&self, py: Python<'_>) -> Py<PyAny> {
        self.velocities.clone_ref(py)
    }

    /// With `xyz_every`: the positions of every frame (`trajectory.xyz`'s), an `(F, N, d)`
    /// array; None without.
    #[getter]
    fn frames(&self, py: Python<'_>) -> Option<Py<PyAny>> {
        self.frames.as_ref().map(|(f, _)| f.clone_ref(py))
    }

    /// The step of each frame; None without `xyz_every`.
    #[getter]
    fn frame_steps(&self, py: Python<'_>) -> Option<Py<PyAny>> {
        self.frames.as_ref().map(|(_, s)| s.clone_ref(py))
    }

    /// Whether the run diverged (the command line would exit with 1); `divergence` says how.
    #[getter]
    fn failed(&self) -> bool {
        self.divergence.is_some()
    }

    /// The command line's error for a diverged run, None otherwise.
    #[getter]
    fn divergence(&self) -> Option<&str> {
        self.divergence.as_deref()
    }

    /// The thermo rows as a pandas DataFrame, the units in `df.attrs["units"]`.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        data_frame(py, self.thermo.bind(py), self.thermo_units.bind(py))
    }

    fn __repr__(&self) -> String {
        format!(
            "<mechkit.MdResult {} atoms, {} steps{}>",
            self.atoms,
            self.steps,
            if self.divergence.is_some() {
                ", diverged"
            } else {
                ""
            }
        )
    }
}
