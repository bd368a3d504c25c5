//! A run of `mechkit md` from its options: the pair potential by name, and the starting
//! state (a lattice at a density and temperature, or given positions in a box with given or
//! drawn velocities). The command line fills [`MdOptions`] from its flags and the Python
//! package from its keyword arguments; both build the run here, and name an input that went
//! wrong by their own spelling of the option ([`SetupError::message`]).

use std::path::{Path, PathBuf};

use super::setup_error::{MdOption, SetupError};
use super::{
    AtomsFile, Lattice, LennardJones, LinearSpring, MdError, PairPotential, RunPlan, SimBox,
    SoftSphere, maxwell_boltzmann,
};
use crate::Real;

/// Bins of the radial distribution a run reports (`rdf.csv`).
pub const RDF_BINS: usize = 100;

/// The temperature a lattice's velocities are drawn at when none is given (LAMMPS's melt).
pub const LATTICE_TEMPERATURE: Real = 1.44;

/// The options of a run, as `mechkit md` takes them; the defaults are the Lennard-Jones melt
/// (fcc, 20 cells, ρ = 0.8442, T = 1.44, dt = 0.005, 100 steps).
#[derive(Debug, Clone, PartialEq)]
pub struct MdOptions {
    /// `fcc`, `sc`, `hexagonal`, `square` or `chain`, when no positions are given.
    pub lattice: String,
    /// Unit cells per axis of the lattice.
    pub cells: usize,
    /// Number density of the lattice.
    pub density: Real,
    /// The temperature the velocities are drawn at (a lattice's default
    /// [`LATTICE_TEMPERATURE`]; given positions start at rest without it).
    pub temperature: Option<Real>,
    /// Positions instead of a lattice.
    pub positions: Option<Atoms>,
    /// Velocities for the positions.
    pub velocities: Option<Atoms>,
    /// The box's edge lengths for the positions: one for every axis, or one per axis; none
    /// for an open boundary (the particles' extent plus the cut-off).
    pub box_lengths: Vec<Real>,
    /// `periodic` (the default) or `open`.
    pub boundary: Option<String>,
    /// `lj`, `soft-sphere` or `spring`.
    pub potential: String,
    /// ε of Lennard-Jones and soft spheres.
    pub epsilon: Real,
    /// σ of Lennard-Jones and soft spheres.
    pub sigma: Real,
    /// The springs' stiffness.
    pub k: Real,
    /// The springs' rest length.
    pub rest_length: Real,
    /// The particles' mass.
    pub mass: Real,
    /// The seed of the drawn velocities.
    pub seed: u64,
    /// Steps to run.
    pub steps: usize,
    /// The time step.
    pub dt: Real,
    /// The cut-off of Lennard-Jones and springs.
    pub cutoff: Real,
    /// Shift Lennard-Jones to zero at the cut-off.
    pub shift: bool,
    /// The neighbour list's skin.
    pub skin: Real,
    /// Steps between neighbour-list checks (LAMMPS's `neigh_modify every`).
    pub neigh_every: usize,
    /// Whether a due check rebuilds only when a particle moved more than half the skin
    /// (`check yes`) or always (`check no`).
    pub neigh_check: bool,
    /// Threads of the force loop.
    pub threads: usize,
    /// Steps between thermo rows.
    pub thermo_every: usize,
    /// Steps between frames, when frames are wanted.
    pub xyz_every: Option<usize>,
}

impl Default for MdOptions {
    fn default() -> Self {
        Self {
            lattice: "fcc".into(),
            cells: 20,
            density: 0.8442,
            temperature: None,
            positions: None,
            velocities: None,
            box_lengths: Vec::new(),
            boundary: None,
            potential: "lj".into(),
            epsilon: 1.0,
            sigma: 1.0,
            k: 1.0,
            rest_length: 1.0,
            mass: 1.0,
            seed: 87287,
            steps: 100,
            dt: 0.005,
            cutoff: 2.5,
            shift: false,
            skin: 0.3,
            neigh_every: 1,
            neigh_check: true,
            threads: 1,
            thermo_every: 50,
            xyz_every: None,
        }
    }
}

/// Positions or velocities and where they came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Atoms {
    /// The vectors and their dimension.
    pub atoms: AtomsFile,
    /// The file they were read from, or None for an array.
    pub path: Option<PathBuf>,
}

impl Atoms {
    /// Reads a CSV or XYZ file ([`AtomsFile::parse`]); an error says `path:line: what`.
    ///
    /// # Errors
    /// The file cannot be read or is not a list of vectors.
    pub fn read(path: &Path) -> Result<Self, String> {
        let text = crate::csv::read_bounded_text(path, crate::csv::MAX_DATA_BYTES)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        let atoms = AtomsFile::parse(&path.to_string_lossy(), &text).map_err(|e| match e {
            // `file:line:` as compilers and the data files print it
            MdError::Parse { line, message } => format!("{}:{line}: {message}", path.display()),
            e => format!("{}: {e}", path.display()),
        })?;
        Ok(Self {
            atoms,
            path: Some(path.to_path_buf()),
        })
    }
}

/// The pair potential of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Potential {
    /// Lennard-Jones.
    Lj(LennardJones),
    /// Soft spheres.
    Soft(SoftSphere),
    /// Linear springs.
    Spring(LinearSpring),
}

/// What a caller does with the potential, whichever it is: [`Potential::apply`] calls it
/// with the concrete type, so the force loop is compiled for each.
pub trait WithPotential {
    /// What it gives.
    type Output;
    /// Does it with `potential`.
    fn call<P: PairPotential>(self, potential: P) -> Self::Output;
}

impl Potential {
    /// The potential the options name, with its parameters.
    ///
    /// # Errors
    /// An unknown name, or parameters the potential refuses.
    pub fn from_options(o: &MdOptions) -> Result<Self, SetupError> {
        Ok(match o.potential.as_str() {
            "lj" => Self::Lj(LennardJones::new(o.epsilon, o.sigma, o.cutoff, o.shift)?),
            "soft-sphere" => Self::Soft(SoftSphere::new(o.epsilon, o.sigma)?),
            "spring" => Self::Spring(LinearSpring::new(o.k, o.rest_length, o.cutoff)?),
            other => {
                return Err(SetupError::Unknown {
                    option: MdOption::Potential,
                    name: other.into(),
                });
            }
        })
    }

    /// The cut-off.
    #[must_use]
    pub fn cutoff(&self) -> Real {
        match self {
            Self::Lj(p) => p.cutoff(),
            Self::Soft(p) => p.cutoff(),
            Self::Spring(p) => p.cutoff(),
        }
    }

    /// Calls `f` with the potential as its own type.
    pub fn apply<F: WithPotential>(self, f: F) -> F::Output {
        match self {
            Self::Lj(p) => f.call(p),
            Self::Soft(p) => f.call(p),
            Self::Spring(p) => f.call(p),
        }
    }
}

/// Everything `Md::new` needs besides the potential, and what the particles started from.
#[derive(Debug, Clone, PartialEq)]
pub struct Setup {
    /// The box.
    pub sim_box: SimBox,
    /// Positions.
    pub x: Vec<[Real; 3]>,
    /// Velocities.
    pub v: Vec<[Real; 3]>,
    /// `fcc lattice`, `4 particles from pair.csv`, … for the report.
    pub origin: String,
}

impl Setup {
    /// The starting state: a lattice (velocities drawn at `temperature`, by default
    /// [`LATTICE_TEMPERATURE`]), or the positions in a box (the lengths given, or the
    /// particles' extent plus `cutoff` when open) with the velocities given, drawn at
    /// `temperature`, or at rest.
    ///
    /// # Errors
    /// An unknown lattice or boundary, a box or velocities that do not fit the positions, or
    /// an input the library refuses.
    pub fn from_options(o: &MdOptions, cutoff: Real) -> Result<Self, SetupError> {
        let Some(Atoms { atoms, path }) = &o.positions else {
            let lattice = Lattice::from_name(&o.lattice).ok_or_else(|| SetupError::Unknown {
                option: MdOption::Lattice,
                name: o.lattice.clone(),
            })?;
            let (sim_box, x) = lattice.build(o.cells, o.density)?;
            let t = o.temperature.unwrap_or(LATTICE_TEMPERATURE);
            let v = maxwell_boltzmann(t, o.mass, lattice.dim(), x.len(), o.seed)?;
            let origin = format!("{} lattice", lattice.name());
            return Ok(Self {
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
                return Err(SetupError::Unknown {
                    option: MdOption::Boundary,
                    name: other.into(),
                });
            }
        };
        let lengths: [Real; 3] = match o.box_lengths.as_slice() {
            [] if periodic => return Err(SetupError::PeriodicBoxNeedsLengths),
            [] => atoms.extent_with_margin(cutoff),
            [l] => [*l; 3],
            ls if ls.len() == dim => std::array::from_fn(|a| ls.get(a).copied().unwrap_or(0.0)),
            ls => {
                return Err(SetupError::BoxLengths {
                    given: ls.len(),
                    dim,
                });
            }
        };
        let sim_box = SimBox::new(dim, lengths, [periodic; 3])?;
        if let Some((i, j)) = super::start::coincident_pair(&atoms.vectors) {
            return Err(coincident(path.as_deref(), (i, j), atoms.vectors[i]));
        }
        let n = atoms.vectors.len();
        let v = match (&o.velocities, o.temperature) {
            (Some(given), _) => {
                let v = &given.atoms;
                if v.vectors.len() != n || v.dim != dim {
                    return Err(SetupError::Velocities {
                        path: given.path.clone(),
                        given: (v.vectors.len(), v.dim),
                        wanted: (n, dim),
                    });
                }
                v.vectors.clone()
            }
            (None, Some(t)) => maxwell_boltzmann(t, o.mass, dim, n, o.seed)?,
            (None, None) => vec![[0.0; 3]; n],
        };
        let origin = match path {
            Some(p) => format!("{n} particles from {}", p.display()),
            None => format!("{n} particles from an array"),
        };
        Ok(Self {
            sim_box,
            x: atoms.vectors.clone(),
            v,
            origin,
        })
    }
}

/// The error for particles `i` and `j` (0-based) at the same place `at`: each named by its
/// line of the file `path`, or its number in an array.
fn coincident(path: Option<&Path>, (i, j): (usize, usize), at: [Real; 3]) -> SetupError {
    let text = path.and_then(|p| crate::csv::read_bounded_text(p, crate::csv::MAX_DATA_BYTES).ok());
    let place = |k: usize| match (path, &text) {
        (Some(p), Some(text)) => match AtomsFile::line_of(&p.to_string_lossy(), text, k) {
            Some(line) => format!("{}:{line}", p.display()),
            None => format!("particle {} of {}", k + 1, p.display()),
        },
        _ => format!("particle {}", k + 1),
    };
    SetupError::Coincident {
        places: (place(i), place(j)),
        at,
    }
}

impl MdOptions {
    /// The steps, thermo rows and frames of the run.
    ///
    /// # Errors
    /// A count the plan refuses (no steps between rows or frames).
    pub fn plan(&self) -> Result<RunPlan, SetupError> {
        Ok(RunPlan::new(self.steps, self.thermo_every, self.xyz_every)?)
    }
}

impl From<&MdOptions> for super::MdConfig {
    fn from(o: &MdOptions) -> Self {
        Self {
            dt: o.dt,
            skin: o.skin,
            mass: o.mass,
            threads: o.threads,
            neigh_every: o.neigh_every,
            neigh_check: o.neigh_check,
        }
    }
}
