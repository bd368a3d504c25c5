//! `mechkit.Model`: a scenario's equations of motion at given states, for the loops students
//! write themselves (`scenario.model(**constants)`).

use mechkit::scenario::Scenario as Checked;
use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::scenario_error;

/// A scenario's model: its accelerations, and each force's value, power and potential, at
/// any states, computed by the same forces, units and formulas as `run()`.
///
/// ```python
/// model = mechkit.Scenario.load("examples/feather.toml").model()
/// x, v = model.initial                      # numpy arrays of model.coordinates
/// dt = 1e-3
/// for k in range(1000):                     # the course's Euler-Cromer loop
///     v = v + model.accel(k*dt, x, v)*dt
///     x = x + v*dt
/// ```
#[pyclass(module = "mechkit", name = "Model", frozen)]
pub struct Model {
    scenario: Checked,
}

impl Model {
    pub fn new(scenario: Checked) -> Self {
        Self { scenario }
    }
}

#[pymethods]
impl Model {
    /// The names of the state's coordinates (`feather.x`; a rigid body's angle, a body's
    /// orientation `top.q0`…, a joint's mode), in the order of `q` and `v`.
    #[getter]
    fn coordinates(&self) -> Vec<String> {
        self.scenario.coordinate_names()
    }

    /// The forces' names, in the order of the results.
    #[getter]
    fn forces(&self) -> Vec<String> {
        self.scenario
            .system
            .forces()
            .iter()
            .map(|f| f.name().to_string())
            .collect()
    }

    /// The initial state `(q, v)`, two numpy arrays.
    #[getter]
    fn initial<'py>(
        &self,
        py: Python<'py>,
    ) -> (Bound<'py, PyArray1<f64>>, Bound<'py, PyArray1<f64>>) {
        let (q, v) = self.scenario.initial.qv();
        (
            PyArray1::from_vec(py, q.to_vec()),
            PyArray1::from_vec(py, v.to_vec()),
        )
    }

    /// Evaluates the model at `n` states: `t` (n,), `q` and `v` (n*dof,) flattened row by
    /// row. Returns the accelerations (n*dof,), the forces (n*forces*dof,), their powers and
    /// potentials (n*forces,); `mechkit.Model.evaluate` shapes them.
    #[allow(clippy::needless_pass_by_value)] // PyO3 hands arguments over owned
    fn _evaluate<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
        q: PyReadonlyArray1<'py, f64>,
        v: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (t, q, v) = (t.as_slice()?, q.as_slice()?, v.as_slice()?);
        let out = py
            .detach(|| self.scenario.evaluate_model(t, q, v))
            .map_err(|e| scenario_error(py, &e))?;
        let dict = PyDict::new(py);
        dict.set_item("accel", PyArray1::from_vec(py, out.accel))?;
        dict.set_item("force", PyArray1::from_vec(py, out.force))?;
        dict.set_item("power", PyArray1::from_vec(py, out.power))?;
        dict.set_item("potential", PyArray1::from_vec(py, out.potential))?;
        Ok(dict)
    }

    fn __repr__(&self) -> String {
        format!(
            "<mechkit.Model of {:?}: {} coordinates, forces {}>",
            self.scenario.title,
            self.scenario.dof(),
            self.forces().join(", ")
        )
    }
}
