//! `mechkit.md(...)`: `mechkit md` in memory. The starting state is built from the options
//! as the command builds it (a lattice at a density and temperature, or positions and
//! velocities from files or arrays), the run is `Md::run_observed`, and the result is the
//! library's `MdReport` (the command's `--json`) with the thermo rows, the radial
//! distribution, the final state and the frames (`md_result.rs`).

use std::convert::Infallible;

use mechkit::md::{
    Lattice, LennardJones, LinearSpring, Md, MdConfig, MdError, MdInput, MdObserver, MdReport,
    PairPotential, RunPlan, SimBox, SoftSphere, Thermo, maxwell_boltzmann,
};
use mechkit::simulate::Cancel;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::md_options::{Atoms, MdOptions};
use super::md_result::MdResult;
use crate::errors::MechkitError;

/// Bins of the radial distribution (`rdf.csv` of `mechkit md`).
const RDF_BINS: usize = 100;

/// The temperature of a lattice's velocities when none is given (`mechkit md`'s).
const LATTICE_TEMPERATURE: f64 = 1.44;

/// Runs `mechkit md` in memory and returns an `MdResult`. The keyword arguments are the
/// command's options under the same names (`rest_length` for `--rest-length`), with its
/// defaults; `positions` and `velocities` are a file's path (CSV or XYZ) or an `(N, d)`
/// array. The GIL is released while it runs; Ctrl-C stops the run after its current step and
/// raises KeyboardInterrupt.
#[pyfunction]
#[pyo3(signature = (**options))]
pub fn md(py: Python<'_>, options: Option<&Bound<'_, PyDict>>) -> PyResult<MdResult> {
    let options = MdOptions::from_kwargs(options)?;
    let cancel = Cancel::new();
    let handle = cancel.clone();
    let outcome = crate::interrupt::run(py, &cancel, move || run(&options, &handle))?;
    let outcome = outcome.map_err(MechkitError::new_err)?;
    MdResult::new(py, outcome)
}

/// The pair potential chosen with `potential`.
enum Potential {
    Lj(LennardJones),
    Soft(SoftSphere),
    Spring(LinearSpring),
}

/// The starting state: the box, positions, velocities, and what they came from (the
/// report's `start`).
struct Start {
    sim_box: SimBox,
    x: Vec<[f64; 3]>,
    v: Vec<[f64; 3]>,
    origin: String,
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
fn run(o: &MdOptions, cancel: &Cancel) -> Result<Outcome, String> {
    let plan = RunPlan::new(o.steps, o.thermo_every, o.xyz_every).map_err(named)?;
    let potential = match o.potential.as_str() {
        "lj" => {
            Potential::Lj(LennardJones::new(o.epsilon, o.sigma, o.cutoff, o.shift).map_err(named)?)
        }
        "soft-sphere" => Potential::Soft(SoftSphere::new(o.epsilon, o.sigma).map_err(named)?),
        "spring" => {
            Potential::Spring(LinearSpring::new(o.k, o.rest_length, o.cutoff).map_err(named)?)
        }
        other => {
            return Err(format!(
                "potential: unknown potential `{other}`; use lj, soft-sphere or spring"
            ));
        }
    };
    match potential {
        Potential::Lj(p) => run_with(o, &plan, p, cancel),
        Potential::Soft(p) => run_with(o, &plan, p, cancel),
        Potential::Spring(p) => run_with(o, &plan, p, cancel),
    }
}

fn run_with<P: PairPotential>(
    o: &MdOptions,
    plan: &RunPlan,
    potential: P,
    cancel: &Cancel,
) -> Result<Outcome, String> {
    let start = start(o, potential.cutoff())?;
    let config = MdConfig {
        dt: o.dt,
        skin: o.skin,
        mass: o.mass,
        threads: o.threads,
    };
    let cutoff = potential.cutoff();
    let dim = start.sim_box.dim();
    let mut md = Md::new(start.sim_box, potential, start.x, start.v, config).map_err(named)?;
    let mut frames = Frames {
        dim,
        positions: Vec::new(),
        steps: Vec::new(),
    };
    let Ok(run) = md.run_observed(plan, cancel, &mut frames);
    let report = md.report(&run, &start.origin, &o.potential);
    let flat = |vectors: &[[f64; 3]]| -> Vec<f64> {
        vectors.iter().flat_map(|p| p[..dim].to_vec()).collect()
    };
    Ok(Outcome {
        rdf: md.radial_distribution(RDF_BINS, cutoff + o.skin),
        positions: flat(md.positions()),
        velocities: flat(md.velocities()),
        report,
        rows: run.rows,
        dim,
        frames,
    })
}

/// The starting state, as `mechkit md` builds it from its flags: a lattice (velocities at
/// `temperature`, 1.44 by default), or `positions` in a box (`box`, or the particles' extent
/// plus the cut-off when open) with `velocities`, or drawn at `temperature`, or at rest.
fn start(o: &MdOptions, cutoff: f64) -> Result<Start, String> {
    let Some(Atoms { atoms, path }) = &o.positions else {
        let lattice = Lattice::from_name(&o.lattice).ok_or_else(|| {
            format!(
                "lattice: unknown lattice `{}`; use fcc, sc, hexagonal, square or chain",
                o.lattice
            )
        })?;
        let (sim_box, x) = lattice.build(o.cells, o.density).map_err(named)?;
        let t = o.temperature.unwrap_or(LATTICE_TEMPERATURE);
        let v = maxwell_boltzmann(t, o.mass, lattice.dim(), x.len(), o.seed).map_err(named)?;
        let origin = format!("{} lattice", lattice.name());
        return Ok(Start {
            sim_box,
            x,
            v,
            origin,
        });
    };
    let dim = atoms.dim;
    let periodic = match o.boundary.as_deref().unwrap_or("periodic") {
        "periodic" => true,
        "open" => false,
        other => {
            return Err(format!(
                "boundary: unknown boundary `{other}`; use periodic or open"
            ));
        }
    };
    let lengths: [f64; 3] = match o.box_lengths.as_deref().unwrap_or_default() {
        [] if periodic => {
            return Err(
                "box: a periodic box needs its edge lengths: give box=L (every axis) or \
                        one length per axis, e.g. box=[10, 10, 10]; or boundary=\"open\""
                    .into(),
            );
        }
        [] => atoms.extent_with_margin(cutoff),
        [l] => [*l; 3],
        ls if ls.len() == dim => std::array::from_fn(|a| ls.get(a).copied().unwrap_or(0.0)),
        ls => {
            return Err(format!(
                "box: {} for {dim}-D positions; give 1 or {dim}",
                count(ls.len(), "length", "lengths")
            ));
        }
    };
    let sim_box = SimBox::new(dim, lengths, [periodic; 3]).map_err(named)?;
    let n = atoms.vectors.len();
    let v = match (&o.velocities, o.temperature) {
        (Some(given), _) => {
            let v = &given.atoms;
            if v.vectors.len() != n || v.dim != dim {
                let source = given
                    .path
                    .as_ref()
                    .map_or_else(|| "the array".to_string(), |p| p.display().to_string());
                return Err(format!(
                    "velocities: {source} has {} for {}; give one velocity per particle, in \
                     the order of positions and with as many components",
                    count(
                        v.vectors.len(),
                        &format!("{}-D velocity", v.dim),
                        &format!("{}-D velocities", v.dim)
                    ),
                    count(
                        n,
                        &format!("{dim}-D position"),
                        &format!("{dim}-D positions")
                    ),
                ));
            }
            v.vectors.clone()
        }
        (None, Some(t)) => maxwell_boltzmann(t, o.mass, dim, n, o.seed).map_err(named)?,
        (None, None) => vec![[0.0; 3]; n],
    };
    let origin = match path {
        Some(p) => format!("{n} particles from {}", p.display()),
        None => format!("{n} particles from an array"),
    };
    Ok(Start {
        sim_box,
        x: atoms.vectors.clone(),
        v,
        origin,
    })
}

/// `n` and the noun, singular for one: `1 length`, `2 lengths`.
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// The keyword argument behind a library error (from the input the error names), then the
/// error: `density: the density is -1; it must be positive and finite`.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
fn named(e: MdError) -> String {
    let key = match (&e, e.input()) {
        (MdError::BoxTooSmall { .. }, _) => "cells or box (or cutoff, skin)",
        (MdError::NoCells { .. }, _) => "cells",
        (_, Some(input)) => keyword(input),
        (_, None) => "input",
    };
    format!("{key}: {e}")
}

/// The keyword argument of an input of `mechkit.md`.
fn keyword(input: MdInput) -> &'static str {
    match input {
        MdInput::Density => "density",
        MdInput::Temperature => "temperature",
        MdInput::TimeStep => "dt",
        MdInput::Skin => "skin",
        MdInput::Threads => "threads",
        MdInput::Cutoff => "cutoff",
        MdInput::Mass => "mass",
        MdInput::Epsilon => "epsilon",
        MdInput::Sigma => "sigma",
        MdInput::SpringConstant => "k",
        MdInput::RestLength => "rest_length",
        MdInput::BoxLength => "box",
        MdInput::ThermoEvery => "thermo_every",
        MdInput::FrameEvery => "xyz_every",
        _ => "cells (or positions)",
    }
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
