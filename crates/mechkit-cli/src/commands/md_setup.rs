//! `mechkit md`'s flags as the library's [`MdOptions`] (the --positions and --velocities
//! files read), and the flag behind a setup error.

use anyhow::{Result, anyhow};
use mechkit::md::{Atoms, MdOption, MdOptions, SetupError};

use crate::args::MdArgs;

/// The flag of an option.
fn flag(option: MdOption) -> &'static str {
    match option {
        MdOption::Lattice => "--lattice",
        MdOption::Cells => "--cells",
        MdOption::Density => "--density",
        MdOption::Temperature => "--temperature",
        MdOption::Positions => "--positions",
        MdOption::Velocities => "--velocities",
        MdOption::Box => "--box",
        MdOption::Boundary => "--boundary",
        MdOption::Potential => "--potential",
        MdOption::Epsilon => "--epsilon",
        MdOption::Sigma => "--sigma",
        MdOption::K => "--k",
        MdOption::RestLength => "--rest-length",
        MdOption::Mass => "--mass",
        MdOption::Dt => "--dt",
        MdOption::Cutoff => "--cutoff",
        MdOption::Skin => "--skin",
        MdOption::Threads => "--threads",
        MdOption::Steps => "--steps",
        MdOption::ThermoEvery => "--thermo-every",
        MdOption::XyzEvery => "--xyz-every",
        MdOption::NeighEvery => "--neigh-every",
    }
}

/// The setup error with the flag behind it.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
pub fn with_flag(e: impl Into<SetupError>) -> anyhow::Error {
    anyhow!(e.into().message(flag))
}

/// Reads a --positions or --velocities file.
fn read(option: MdOption, path: &std::path::Path) -> Result<Atoms> {
    Atoms::read(path).map_err(|e| anyhow!("{}: {e}", flag(option)))
}

/// The options the flags give.
pub fn options(args: &MdArgs) -> Result<MdOptions> {
    Ok(MdOptions {
        lattice: args.lattice.clone(),
        cells: args.cells,
        density: args.density,
        temperature: args.temperature,
        positions: match &args.positions {
            Some(p) => Some(read(MdOption::Positions, p)?),
            None => None,
        },
        velocities: match &args.velocities {
            Some(p) => Some(read(MdOption::Velocities, p)?),
            None => None,
        },
        box_lengths: args.r#box.clone(),
        boundary: Some(args.boundary.clone()),
        potential: args.potential.clone(),
        epsilon: args.epsilon,
        sigma: args.sigma,
        k: args.k,
        rest_length: args.rest_length,
        mass: args.mass,
        seed: args.seed,
        steps: args.steps,
        dt: args.dt,
        cutoff: args.cutoff,
        shift: args.shift,
        skin: args.skin,
        neigh_every: args.neigh_every,
        neigh_check: args.neigh_check,
        threads: args.threads,
        thermo_every: args.thermo_every,
        xyz_every: args.xyz_every,
    })
}
