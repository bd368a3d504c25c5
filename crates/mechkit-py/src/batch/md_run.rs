//! `mechkit.md(...)`: `mechkit md` in memory. The starting state is built from the options
//! as the command builds it (a lattice at a density and temperature, or positions and
//! velocities from files or arrays), the run is `Md::run_observed`, and the result is the
//! library's `MdReport` (the command's `--json`) with the thermo rows, the radial
//! distribution, the final state and the frames (`md_result.rs`).

use std::convert::Infallible;
use std::path::Path;

use mechkit::md::{
    Md, MdConfig, MdObserver, MdOption, MdOptions, MdReport, PairPotential, Potential, RDF_BINS,
    RunPlan, Setup, SetupError, Thermo, WithPotential,
};
use mechkit::simulate::Cancel;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::md_options::{export_lammps, from_kwargs};
use super::md_result::MdResult;
use crate::errors::MechkitError;

/// Runs `mechkit md` in memory and returns an `MdResult`. The keyword arguments are the
/// command's options under the same names (`rest_length` for `--rest-length`), with its
/// defaults; `positions` and `velocities` are a file's path (CSV or XYZ) or an `(N, d)`
/// array. The GIL is released while it runs; Ctrl-C stops the run after its current step and
/// raises KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (**options))]
pub fn md(py: Python<'_>, options: Option<&Bound<'_, PyDict>>) -> PyResult<MdResult> {
    let export = export_lammps(options)?;
    let options = from_kwargs(options)?;
    let cancel = Cancel::new();
    let handle = cancel.clone();
    let outcome = crate::interrupt::run(py, &cancel, move || {
        run(&options, export.as_deref(), &handle)
    })?;
    let outcome = outcome.map_err(MechkitError::new_err)?;
    MdResult::new(py, outcome)
}

/// What a run hands back to Python: the report, the thermo rows of a `dim`-dimensional
/// box, the radial distribution `(r, g)`, the final state (`dim` components per atom) and the
/// frames.
pub(super) struct Outcome {
    pub report: MdReport,
    pub rows: Vec<Thermo>,
    pub dim: usize,
    pub rdf: Vec<(f64, f64)>,
    pub positions: Vec<f64>,
    pub velocities: Vec<f64>,
    pub frames: Frames,
}

/// Builds the system as `mechkit md` does and runs it; an error is the message, naming the
/// keyword argument behind it.
fn run(o: &MdOptions, export: Option<&Path>, cancel: &Cancel) -> Result<Outcome, String> {
    let plan = o.plan().map_err(named)?;
    let potential = Potential::from_options(o).map_err(named)?;
    let setup = Setup::from_options(o, potential.cutoff()).map_err(named)?;
    potential.apply(Runner {
        options: o,
        plan: &plan,
        setup,
        export,
        cancel,
    })
}

/// The run, for whichever potential.
struct Runner<'a> {
    options: &'a MdOptions,
    plan: &'a RunPlan,
    setup: Setup,
    export: Option<&'a Path>,
    cancel: &'a Cancel,
}

impl WithPotential for Runner<'_> {
    type Output = Result<Outcome, String>;

    fn call<P: PairPotential>(self, potential: P) -> Result<Outcome, String> {
        let Self {
            options: o,
            plan,
            setup: s,
            export,
            cancel,
        } = self;
        let cutoff = potential.cutoff();
        let dim = s.sim_box.dim();
        let mut md = Md::new(s.sim_box, potential, s.x, s.v, MdConfig::from(o)).map_err(named)?;
        // the state the run starts from, written before the run
        if let Some(dir) = export {
            md.lammps_export(plan).write(dir).map_err(|e| {
                format!(
                    "export_lammps: cannot write the LAMMPS files: {e}; give a directory (it \
                     is created if missing) where in.lammps and data.lammps can be written"
                )
            })?;
        }
        let mut frames = Frames {
            dim,
            positions: Vec::new(),
            steps: Vec::new(),
        };
        let Ok(run) = md.run_observed(plan, cancel, &mut frames);
        let mut report = md.report(&run, &s.origin, &o.potential);
        report.lammps_export = export.map(|d| d.display().to_string());
        let flat = |vectors: &[[f64; 3]]| -> Vec<f64> {
            vectors.iter().flat_map(|p| p[..dim].to_vec()).collect()
        };
        Ok(Outcome {
            rdf: md.radial_distribution(RDF_BINS, cutoff + o.skin),
            positions: flat(&md.positions()),
            velocities: flat(&md.velocities()),
            report,
            rows: run.rows,
            dim,
            frames,
        })
    }
}

/// The keyword argument of an option of `mechkit.md`.
fn keyword(option: MdOption) -> &'static str {
    match option {
        MdOption::Lattice => "lattice",
        MdOption::Cells => "cells",
        MdOption::Density => "density",
        MdOption::Temperature => "temperature",
        MdOption::Positions => "positions",
        MdOption::Velocities => "velocities",
        MdOption::Box => "box",
        MdOption::Boundary => "boundary",
        MdOption::Potential => "potential",
        MdOption::Epsilon => "epsilon",
        MdOption::Sigma => "sigma",
        MdOption::K => "k",
        MdOption::RestLength => "rest_length",
        MdOption::Mass => "mass",
        MdOption::Dt => "dt",
        MdOption::Cutoff => "cutoff",
        MdOption::Skin => "skin",
        MdOption::Threads => "threads",
        MdOption::Steps => "steps",
        MdOption::ThermoEvery => "thermo_every",
        MdOption::XyzEvery => "xyz_every",
        MdOption::NeighEvery => "neigh_every",
    }
}

/// The error with the keyword argument behind it: `density: the density is -1; it must be
/// positive and finite`.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
fn named(e: impl Into<SetupError>) -> String {
    e.into().message(keyword)
}

/// The frames of a run with `xyz_every`: the positions (`dim` components each) and the step
/// of each frame.
pub(super) struct Frames {
    dim: usize,
    pub positions: Vec<f64>,
    pub steps: Vec<usize>,
}

impl<P: PairPotential> MdObserver<P> for Frames {
    type Error = Infallible;

    fn frame(&mut self, md: &Md<P>) -> Result<(), Infallible> {
        let dim = self.dim;
        self.positions
            .extend(md.positions().iter().flat_map(|p| p[..dim].iter().copied()));
        self.steps.push(md.steps());
        Ok(())
    }
}
