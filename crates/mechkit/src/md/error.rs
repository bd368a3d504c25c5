//! Why a many-particle system cannot be built or run.

use thiserror::Error;

use crate::Real;

/// The input of a many-particle system or run that an [`MdError`] is about, so that a front
/// can name its own field for it (a flag, a form field).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum MdInput {
    /// The number density of a lattice.
    Density,
    /// The initial temperature.
    Temperature,
    /// The time step.
    TimeStep,
    /// The neighbour-list skin.
    Skin,
    /// The number of threads.
    Threads,
    /// The cut-off of the pair potential.
    Cutoff,
    /// The mass of a particle.
    Mass,
    /// ε of Lennard-Jones or soft spheres.
    Epsilon,
    /// σ of Lennard-Jones or soft spheres.
    Sigma,
    /// The stiffness k of springs.
    SpringConstant,
    /// The rest length of springs.
    RestLength,
    /// An edge length of the box.
    BoxLength,
    /// The number of atoms (unit cells of a lattice, or particles of a file).
    Atoms,
    /// The number of steps of a run.
    Steps,
    /// The steps between thermo rows.
    ThermoEvery,
    /// The steps between frames.
    FrameEvery,
    /// The steps between neighbour-list checks.
    NeighEvery,
}

impl MdInput {
    /// The input as messages name it (`the density`, `the time step dt`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Density => "the density",
            Self::Temperature => "the temperature",
            Self::TimeStep => "the time step dt",
            Self::Skin => "the skin",
            Self::NeighEvery => "the steps between neighbour-list checks",
            Self::Threads => "the number of threads",
            Self::Cutoff => "the cut-off",
            Self::Mass => "the mass",
            Self::Epsilon => "epsilon",
            Self::Sigma => "sigma",
            Self::SpringConstant => "k",
            Self::RestLength => "the rest length",
            Self::BoxLength => "a box length",
            Self::Atoms => "the number of atoms",
            Self::Steps => "the number of steps",
            Self::ThermoEvery => "the number of steps between thermo rows",
            Self::FrameEvery => "the number of steps between frames",
        }
    }
}

impl std::fmt::Display for MdInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// An invalid box, lattice, potential or run setting of [`crate::md`].
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum MdError {
    /// A parameter that must be positive and finite is not.
    #[error("{input} is {}; it must be positive and finite", crate::error::short(*value))]
    NotPositive {
        /// Which parameter.
        input: MdInput,
        /// The value given.
        value: Real,
    },
    /// A parameter below the smallest normal double (2.2e-308): dividing by it overflows.
    #[error(
        "{input} is {value:e}, below 2.2e-308, the smallest number double precision holds in full: the accelerations would overflow"
    )]
    Subnormal {
        /// Which parameter.
        input: MdInput,
        /// The value given.
        value: Real,
    },
    /// The fastest particle at the start moves farther than the box in one step (a
    /// temperature or a time step far too large).
    #[error(
        "the fastest atom moves {} in one step of dt = {} at the start (its speed is {}), more than the box's shortest edge {}: a step would carry it across the whole box",
        short(*.distance), short(*.dt), short(*.speed), short(*.edge)
    )]
    StepTooLong {
        /// The time step.
        dt: Real,
        /// The largest speed at the start.
        speed: Real,
        /// `speed · dt`.
        distance: Real,
        /// The shortest edge of the box.
        edge: Real,
    },
    /// Two particles at the same place: the pair force between them is infinite.
    #[error(
        "atoms {first} and {second} (counted from 1) are at the same place, ({}, {}, {}): the force between them is infinite",
        crate::error::short(.at[0]), crate::error::short(.at[1]), crate::error::short(.at[2])
    )]
    Coincident {
        /// The first atom (1-based, in the order given).
        first: usize,
        /// The second.
        second: usize,
        /// Where they are.
        at: [Real; 3],
    },
    /// A thermo quantity stopped being finite during a run.
    #[error(
        "the run diverged at step {step}: the {quantity} is {value}; use a smaller time step, a lower temperature or start from a lattice"
    )]
    NotFinite {
        /// The step at which it was noticed.
        step: usize,
        /// Which quantity (`temperature`, `pressure`, …).
        quantity: &'static str,
        /// Its value.
        value: Real,
    },
    /// A dimension other than 1, 2 or 3.
    #[error("the dimension is {dim}; it must be 1, 2 or 3")]
    Dimension {
        /// The dimension given.
        dim: usize,
    },
    /// A lattice that does not exist in the requested dimension.
    #[error("the {lattice} lattice is {needs}-dimensional, but the box is {dim}-dimensional")]
    LatticeDimension {
        /// The lattice's name.
        lattice: &'static str,
        /// Its dimension.
        needs: usize,
        /// The box's dimension.
        dim: usize,
    },
    /// A count above what this code runs (atoms, threads).
    #[error("{input} would be {value}, more than {max}; {hint}")]
    TooMany {
        /// What is counted (atoms, threads).
        input: MdInput,
        /// The count asked for (saturated at `u64::MAX`).
        value: u64,
        /// The limit.
        max: u64,
        /// How to stay within it.
        hint: &'static str,
    },
    /// A lattice with no unit cells.
    #[error("the lattice needs at least one unit cell along each axis (got {cells})")]
    NoCells {
        /// The number of cells given.
        cells: usize,
    },
    /// A periodic box too small for the minimum-image convention at this cut-off.
    #[error(
        "the periodic box is {} long on the {} axis, shorter than twice the cut-off plus skin ({}); use more unit cells or a shorter cut-off",
        crate::error::short(round6(*.length)),
        ["x", "y", "z"].get(*.axis).copied().unwrap_or("last"),
        crate::error::short(round6(*.needed))
    )]
    BoxTooSmall {
        /// The axis (0 = x).
        axis: usize,
        /// The box length on that axis.
        length: Real,
        /// The smallest length allowed, 2 (r_c + skin).
        needed: Real,
    },
    /// Positions, velocities and masses of different lengths.
    #[error("{what} has {got} entries, but there are {expected} particles")]
    Length {
        /// What has the wrong length.
        what: &'static str,
        /// Its length.
        got: usize,
        /// The number of particles.
        expected: usize,
    },
    /// Fewer than two particles where a temperature is needed.
    #[error("a temperature needs at least two particles (got {n})")]
    TooFewParticles {
        /// The number of particles.
        n: usize,
    },
    /// The run produced a non-finite energy (too large a time step, overlapping particles).
    #[error(
        "the run diverged at step {step}: the total energy is {energy}; use a smaller time step or start from a lattice"
    )]
    Diverged {
        /// The step at which it was noticed.
        step: usize,
        /// The energy found.
        energy: Real,
    },
    /// A particle file that cannot be read.
    #[error("line {line}: {message}")]
    Parse {
        /// The 1-based line number.
        line: usize,
        /// What is wrong there.
        message: String,
    },
}

impl MdError {
    /// The input the error is about, when it is about one.
    pub fn input(&self) -> Option<MdInput> {
        match self {
            Self::NotPositive { input, .. }
            | Self::Subnormal { input, .. }
            | Self::TooMany { input, .. } => Some(*input),
            Self::StepTooLong { .. } => Some(MdInput::TimeStep),
            Self::Coincident { .. } | Self::NoCells { .. } | Self::TooFewParticles { .. } => {
                Some(MdInput::Atoms)
            }
            Self::BoxTooSmall { .. } => Some(MdInput::BoxLength),
            _ => None,
        }
    }
}

/// A number for a message: 6 significant digits, in exponent form outside 1e-4..1e6
/// (`2.4978e48`, not 49 digits).
fn short(x: Real) -> String {
    let r = round6(x);
    if r == 0.0 || !r.is_finite() || (1e-4..1e6).contains(&r.abs()) {
        format!("{r}")
    } else {
        format!("{r:e}")
    }
}

/// A length for a message: 6 significant digits (`2.17674`, not `2.176743828161131`).
fn round6(x: Real) -> Real {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(5 - x.abs().log10().floor() as i32);
    (x * scale).round() / scale
}
