//! The options of `mechkit md` by meaning, and why a run could not be set up: each front names
//! an input that went wrong by its own spelling of the option.

use std::path::PathBuf;

use super::{MdError, MdInput};
use crate::Real;

/// An option of [`MdOptions`](super::MdOptions), for a front to name in its own spelling (`--rest-length`,
/// `rest_length`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(missing_docs)] // each is the field of the same name
pub enum MdOption {
    Lattice,
    Cells,
    Density,
    Temperature,
    Positions,
    Velocities,
    Box,
    Boundary,
    Potential,
    Epsilon,
    Sigma,
    K,
    RestLength,
    Mass,
    Dt,
    Cutoff,
    Skin,
    Threads,
    Steps,
    ThermoEvery,
    XyzEvery,
    NeighEvery,
}

impl MdOption {
    /// The option behind a library input; None for the number of atoms (cells, or the
    /// positions).
    fn of(input: MdInput) -> Option<Self> {
        Some(match input {
            MdInput::Density => Self::Density,
            MdInput::Temperature => Self::Temperature,
            MdInput::TimeStep => Self::Dt,
            MdInput::Skin => Self::Skin,
            MdInput::Threads => Self::Threads,
            MdInput::Cutoff => Self::Cutoff,
            MdInput::Mass => Self::Mass,
            MdInput::Epsilon => Self::Epsilon,
            MdInput::Sigma => Self::Sigma,
            MdInput::SpringConstant => Self::K,
            MdInput::RestLength => Self::RestLength,
            MdInput::BoxLength => Self::Box,
            MdInput::Steps => Self::Steps,
            MdInput::ThermoEvery => Self::ThermoEvery,
            MdInput::FrameEvery => Self::XyzEvery,
            MdInput::NeighEvery => Self::NeighEvery,
            _ => return None,
        })
    }
}

/// Why a run could not be set up.
#[derive(Debug, Clone, PartialEq)]
pub enum SetupError {
    /// The library refused an input.
    Md(MdError),
    /// A name no potential, lattice or boundary has.
    Unknown {
        /// The option.
        option: MdOption,
        /// The name given.
        name: String,
    },
    /// A periodic box without its lengths.
    PeriodicBoxNeedsLengths,
    /// As many box lengths as neither 1 nor the dimension.
    BoxLengths {
        /// Lengths given.
        given: usize,
        /// The positions' dimension.
        dim: usize,
    },
    /// Two particles of the positions at the same place (an infinite force).
    Coincident {
        /// Where each is given: `file:line`, or `particle N` of an array.
        places: (String, String),
        /// Where they are.
        at: [Real; 3],
    },
    /// Velocities that do not match the positions.
    Velocities {
        /// The velocities' file, or None for an array.
        path: Option<PathBuf>,
        /// Their count and dimension.
        given: (usize, usize),
        /// The positions' count and dimension.
        wanted: (usize, usize),
    },
}

impl From<MdError> for SetupError {
    fn from(e: MdError) -> Self {
        Self::Md(e)
    }
}

/// `n` and the noun, singular for one: `1 length`, `2 lengths`.
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

impl SetupError {
    /// The option at fault, named by `name`, then what is wrong: `--density: the density is
    /// -1; it must be positive and finite`, or with Python's names `density: …`.
    pub fn message(&self, name: impl Fn(MdOption) -> &'static str) -> String {
        match self {
            Self::Md(e @ MdError::BoxTooSmall { .. }) => format!(
                "{} or {} (or {}, {}): {e}",
                name(MdOption::Cells),
                name(MdOption::Box),
                name(MdOption::Cutoff),
                name(MdOption::Skin)
            ),
            Self::Md(e @ MdError::NoCells { .. }) => format!("{}: {e}", name(MdOption::Cells)),
            Self::Md(e) => match e.input().map(MdOption::of) {
                Some(Some(option)) => format!("{}: {e}", name(option)),
                Some(None) => format!(
                    "{} (or {}): {e}",
                    name(MdOption::Cells),
                    name(MdOption::Positions)
                ),
                None => format!("input: {e}"),
            },
            Self::Unknown {
                option,
                name: given,
            } => {
                let (what, choices) = match option {
                    MdOption::Potential => ("potential", "lj, soft-sphere or spring"),
                    MdOption::Lattice => ("lattice", "fcc, sc, hexagonal, square or chain"),
                    _ => ("boundary", "periodic or open"),
                };
                format!("{}: unknown {what} `{given}`; use {choices}", name(*option))
            }
            Self::PeriodicBoxNeedsLengths => format!(
                "{box}: a periodic box needs its edge lengths: give {box} one length for every \
                 axis, or one per axis; or set {boundary} to open",
                box = name(MdOption::Box),
                boundary = name(MdOption::Boundary)
            ),
            Self::BoxLengths { given, dim } => format!(
                "{}: {} for {dim}-D positions; give 1 or {dim}",
                name(MdOption::Box),
                count(*given, "length", "lengths")
            ),
            Self::Coincident { places, at } => format!(
                "{}: {} and {} are at the same place, ({}, {}, {}): the force between two \
                 particles at one point is infinite\n  = hint: move one of them, or remove it",
                name(MdOption::Positions),
                places.0,
                places.1,
                crate::error::short(at[0]),
                crate::error::short(at[1]),
                crate::error::short(at[2])
            ),
            Self::Velocities {
                path,
                given,
                wanted,
            } => format!(
                "{}: {} has {} for {}; give one velocity per particle, in the order of {} and \
                 with as many components",
                name(MdOption::Velocities),
                path.as_ref()
                    .map_or_else(|| "the array".to_string(), |p| p.display().to_string()),
                count(
                    given.0,
                    &format!("{}-D velocity", given.1),
                    &format!("{}-D velocities", given.1)
                ),
                count(
                    wanted.0,
                    &format!("{}-D position", wanted.1),
                    &format!("{}-D positions", wanted.1)
                ),
                name(MdOption::Positions)
            ),
        }
    }
}
