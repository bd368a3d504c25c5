//! `mechkit.Scenario`: a checked scenario file or text, and `scenario.run(**constants)`.

use std::path::PathBuf;
use std::time::Instant;

use mechkit::scenario::{ConstantOverride, Scenario as Checked, read_source};
use mechkit::simulate::Cancel;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

use crate::errors::scenario_error;
use crate::model::Model;
use crate::plot::Replay;
use crate::run::Run;

/// A scenario, checked when it is loaded: its bodies, forces, integrator and outputs, as in
/// the command line's `mechkit run FILE`.
///
/// ```python
/// import mechkit
/// feather = mechkit.Scenario.load("examples/feather.toml")
/// run = feather.run(Dmg="2 s^2/m^2")       # a constant given another value
/// run.events[0]["t"]                       # the landing time (s)
/// ```
#[pyclass(module = "mechkit", name = "Scenario", frozen)]
pub struct Scenario {
    /// The name errors give (the file's path).
    name: String,
    /// The TOML text, built again by each run with that run's constants.
    text: String,
    title: String,
    /// The `[constants]`: name and SI value.
    constants: Vec<(String, f64)>,
}

#[pymethods]
impl Scenario {
    /// Reads and checks a scenario file (`.toml`). Raises `ScenarioError` for a file that
    /// cannot be read or is not a valid scenario.
    #[staticmethod]
    #[allow(clippy::needless_pass_by_value)] // PyO3 hands arguments over owned
    fn load(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let text = py
            .detach(|| read_source(&path))
            .map_err(|e| scenario_error(py, &e))?;
        Self::checked(py, path.display().to_string(), text)
    }

    /// Reads and checks a scenario from its TOML text; `name` stands for the file in error
    /// messages (and relative paths in the text are read from the current directory).
    #[staticmethod]
    #[pyo3(signature = (text, name = "<string>"))]
    fn from_str(py: Python<'_>, text: String, name: &str) -> PyResult<Self> {
        Self::checked(py, name.to_string(), text)
    }

    /// Runs the scenario and returns a `Run`. Keyword arguments give `[constants]` other
    /// values: a string with units (`m="2 kg"`, `th="30 deg"`, `th="pi/6"`) or a number in
    /// SI (`m=2.0`). The GIL is released while it runs; Ctrl-C (KeyboardInterrupt) stops the
    /// run after its current step and raises KeyboardInterrupt.
    #[pyo3(signature = (**constants))]
    fn run(&self, py: Python<'_>, constants: Option<&Bound<'_, PyDict>>) -> PyResult<Run> {
        let overrides = overrides(py, constants)?;
        let cancel = Cancel::new();
        let handle = cancel.clone();
        let (name, text, given) = (self.name.as_str(), self.text.as_str(), &overrides);
        let start = Instant::now();
        let result = crate::interrupt::run(py, &cancel, move || {
            let mut scenario = Checked::from_str_with(name, text, given)?;
            scenario.cancel = handle;
            scenario.run_with_trajectory()
        })?;
        let (out, trajectory) = result.map_err(|e| scenario_error(py, &e))?;
        let replay = Replay {
            name: self.name.clone(),
            text: self.text.clone(),
            overrides,
            limited: false,
        };
        Run::new(py, out, trajectory, replay, start.elapsed().as_secs_f64())
    }

    /// The scenario's model with the given constants (as `run` takes them): its
    /// accelerations and each force's value, power and potential at any states, for a loop
    /// written by hand (`mechkit.Model`).
    #[pyo3(signature = (**constants))]
    fn model<'py>(
        &self,
        py: Python<'py>,
        constants: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let overrides = overrides(py, constants)?;
        let scenario = py
            .detach(|| Checked::from_str_with(&self.name, &self.text, &overrides))
            .map_err(|e| scenario_error(py, &e))?;
        let native = Bound::new(py, Model::new(scenario))?;
        // the numpy shaping is Python's (`mechkit/_model.py`)
        py.import("mechkit._model")?
            .getattr("Model")?
            .call1((native,))
    }

    /// The name given when loading (the file's path, or `name` of `from_str`).
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    /// The scenario's title.
    #[getter]
    fn title(&self) -> &str {
        &self.title
    }

    /// The `[constants]` as a dict: name → value in SI units.
    #[getter]
    fn constants<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (name, value) in &self.constants {
            dict.set_item(name, value)?;
        }
        Ok(dict)
    }

    fn __repr__(&self) -> String {
        format!("<mechkit.Scenario {:?} ({})>", self.title, self.name)
    }
}

impl Scenario {
    /// The name errors give (the file's path) and the TOML text (`mechkit.sweep` of a
    /// scenario).
    pub fn source(&self) -> (&str, &str) {
        (&self.name, &self.text)
    }

    /// Checks `text` (with the GIL released) and keeps it for the runs.
    fn checked(py: Python<'_>, name: String, text: String) -> PyResult<Self> {
        let (title, constants) = py
            .detach(|| {
                Checked::from_str(&name, &text).map(|s| {
                    let constants = s.constants.iter().map(|(n, v, _)| (n.clone(), *v));
                    (s.title.clone(), constants.collect())
                })
            })
            .map_err(|e| scenario_error(py, &e))?;
        Ok(Self {
            name,
            text,
            title,
            constants,
        })
    }
}

/// The keyword arguments of `run` as overrides of the constants: a string is read as the
/// command line reads `--set NAME=TEXT`; a number (not a bool) is SI.
fn overrides(
    py: Python<'_>,
    constants: Option<&Bound<'_, PyDict>>,
) -> PyResult<Vec<ConstantOverride>> {
    let Some(constants) = constants else {
        return Ok(Vec::new());
    };
    let mut out = Vec::with_capacity(constants.len());
    for (key, value) in constants.iter() {
        let name: String = key.extract()?;
        if value.is_instance_of::<PyString>() {
            let text: String = value.extract()?;
            out.push(parse_override(py, &name, &text)?);
        } else if value.is_instance_of::<PyBool>() {
            return Err(not_a_value(&name, &value));
        } else {
            let Ok(number) = value.extract::<f64>() else {
                return Err(not_a_value(&name, &value));
            };
            if !number.is_finite() {
                return Err(invalid(
                    py,
                    format!("the value given for `{name}` is {number}, not a finite number"),
                ));
            }
            out.push(ConstantOverride {
                name,
                value: number,
                dim: None,
            });
        }
    }
    Ok(out)
}

/// `name="2 kg"`, read as `--set "name=2 kg"` is.
fn parse_override(py: Python<'_>, name: &str, text: &str) -> PyResult<ConstantOverride> {
    let mut parsed = ConstantOverride::parse_list(&format!("{name}={text}"))
        .map_err(|e| invalid(py, e.to_string()))?;
    match (parsed.pop(), parsed.is_empty()) {
        (Some(o), true) if o.name == name => Ok(o),
        _ => Err(invalid(
            py,
            format!("the value given for `{name}` is `{text}`, not one value"),
        )),
    }
}

fn not_a_value(name: &str, value: &Bound<'_, PyAny>) -> PyErr {
    let type_name = value
        .get_type()
        .name()
        .map_or_else(|_| "?".to_string(), |n| n.to_string());
    PyTypeError::new_err(format!(
        "the value given for `{name}` is a {type_name}: give a number (SI) or a string with \
         units, e.g. {name}=\"2 kg\""
    ))
}

/// A `ScenarioError` without a place in the file.
fn invalid(py: Python<'_>, message: String) -> PyErr {
    let e = mechkit::scenario::ScenarioError::new(mechkit::scenario::ErrorKind::Invalid, message);
    scenario_error(py, &e)
}
