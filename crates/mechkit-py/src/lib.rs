//! `mechkit._native`: the Rust side of the `mechkit` Python package (PyO3). The package's
//! `python/mechkit/__init__.py` re-exports it; Python users read its docstrings and the type
//! stubs, `python/mechkit/__init__.pyi`.
//!
//! - `Scenario.load(path)`, `Scenario.from_str(text)`, `scenario.run(**constants)` → `Run`
//!   (`scenario.rs`, `run.rs`), the run on a worker thread that Ctrl-C stops
//!   (`interrupt.rs`);
//! - `MechkitError`, `ScenarioError` (`errors.rs`);
//! - `cli(args)`: the `mechkit` command line, run in-process for the console script;
//! - calculus and data: `integrate`, `diff`, `solve`, `units` (`calculus.rs`), `trapz`,
//!   `cumtrapz`, `simpson`, `derive` (`data.rs`);
//! - batch: `md(...)` → `MdResult`, `sweep(scenario, ...)` → `SweepResult` (`batch.rs`), and
//!   `run.plot(spec)` → `Plot`, drawn as the command line draws it (`plot.rs`);
//! - mechanics: `potential`, `collide`, `impulse`, `com`, `inertia` (`potential.rs`,
//!   `collisions.rs`, `impulse.rs`, `mass.rs` with `image.rs`), the one-question commands as
//!   functions returning the command's `--json` as a dict, their arguments read by
//!   `arguments.rs`.

mod animation;
mod batch;
mod calculus;
mod data;
mod errors;
mod interrupt;
mod model;
mod plot;
mod run;
mod scenario;
// mechanics: potential, collide, impulse, com, inertia
mod arguments;
mod collisions;
mod image;
mod impulse;
mod mass;
mod potential;

use std::ffi::OsString;

use pyo3::prelude::*;

/// Runs the `mechkit` command line with `args` (without the program's name) in this process
/// and returns its exit status, as the `mechkit` binary would (0 ok, 1 the computation
/// failed, 2 bad input, 101 a bug, 130 Ctrl-C). It prints to the process's stdout and stderr.
/// The `mechkit` console script calls it; Ctrl-C during `run`, `sweep` and `md` is caught by
/// the command itself (its handler calls Python's after its own).
#[pyfunction]
fn cli(py: Python<'_>, args: Vec<OsString>) -> i32 {
    let argv: Vec<OsString> = std::iter::once(OsString::from("mechkit"))
        .chain(args)
        .collect();
    py.detach(move || {
        // a panic has been reported by the command's panic hook; its status is Rust's
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            mechkit_cli::main_with_args(argv)
        }))
        .unwrap_or(101)
    })
}

/// mechkit's scenarios, runs and command line, from Python.
#[pymodule(name = "_native")]
mod native {
    use pyo3::prelude::*;

    #[pymodule_export]
    use super::animation::Animation;
    #[pymodule_export]
    use super::cli;
    #[pymodule_export]
    use super::errors::{MechkitError, ScenarioError};
    #[pymodule_export]
    use super::model::Model;
    #[pymodule_export]
    use super::run::Run;
    #[pymodule_export]
    use super::scenario::Scenario;
    // mechanics: potential, collide, impulse, com, inertia
    #[pymodule_export]
    use super::collisions::collide;
    #[pymodule_export]
    use super::impulse::impulse;
    #[pymodule_export]
    use super::mass::{com, inertia};
    #[pymodule_export]
    use super::potential::potential;

    // calculus and data (integrate, diff, solve, units; trapz, cumtrapz, simpson, derive)
    #[pymodule_export]
    use super::calculus::{diff, dsolve, integrate, solve, units};
    #[pymodule_export]
    use super::data::{cumtrapz, derive, simpson, trapz};
    // batch: md, sweep and plots (batch.rs, plot.rs)
    #[pymodule_export]
    use super::batch::{MdResult, SweepResult, md, sweep, sweep_merge, sweep_part, sweep_plan};
    #[pymodule_export]
    use super::plot::Plot;

    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        m.add("__version__", env!("CARGO_PKG_VERSION"))?;
        super::errors::init_classes(m.py())
    }
}
