//! Python's view of mechkit's errors: `mechkit.MechkitError`, and `mechkit.ScenarioError`
//! with the place in the file (`file`, `line`, `column`), a `hint` and a `kind`; its `str` is
//! the command line's message (the line with a caret under the problem, then the hint).

use mechkit::scenario::{ErrorKind, ScenarioError as Error};
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

pyo3::create_exception!(
    mechkit,
    MechkitError,
    PyException,
    "The base class of mechkit's errors."
);

pyo3::create_exception!(
    mechkit,
    ScenarioError,
    MechkitError,
    "An error in a scenario: its text, its constants, or reading it. `str(e)` is the \
     command line's message; `e.file`, `e.line` and `e.column` (1-based) say where, when the \
     error is in the scenario's text, and are None otherwise; `e.hint` is what would fix it \
     (or None); `e.kind` names the kind of problem (\"syntax\", \"unit\", \"dimension\", ...)."
);

/// The attributes every [`ScenarioError`] has; the class holds them as None, so that one
/// raised from Python has them too.
const ATTRIBUTES: [&str; 6] = ["kind", "message", "file", "line", "column", "hint"];

/// Gives the exception classes their attributes' defaults (at the module's import).
pub fn init_classes(py: Python<'_>) -> PyResult<()> {
    let class = py.get_type::<ScenarioError>();
    for name in ATTRIBUTES {
        class.setattr(name, py.None())?;
    }
    Ok(())
}

/// The Python exception for a library error, its attributes from the error's fields.
pub fn scenario_error(py: Python<'_>, e: &Error) -> PyErr {
    let err = ScenarioError::new_err(e.to_string());
    let location = e.location.as_deref();
    let value = err.value(py);
    let set = || -> PyResult<()> {
        value.setattr("kind", kind_name(e.kind))?;
        value.setattr("message", &e.message)?;
        value.setattr("file", location.map(|l| l.file.as_str()))?;
        value.setattr("line", location.map(|l| l.line))?;
        value.setattr("column", location.map(|l| l.column))?;
        value.setattr("hint", e.hint.as_deref())?;
        Ok(())
    };
    // setting attributes on a fresh exception instance does not fail; if it did, the
    // message alone is still the error
    let _ = set();
    err
}

/// The snake_case name of a kind of error (`e.kind`).
fn kind_name(kind: ErrorKind) -> &'static str {
    match kind {
        ErrorKind::Syntax => "syntax",
        ErrorKind::UnknownKey => "unknown_key",
        ErrorKind::Missing => "missing",
        ErrorKind::WrongType => "wrong_type",
        ErrorKind::Unit => "unit",
        ErrorKind::Dimension => "dimension",
        ErrorKind::Formula => "formula",
        ErrorKind::Invalid => "invalid",
        ErrorKind::Io => "io",
        _ => "other",
    }
}
