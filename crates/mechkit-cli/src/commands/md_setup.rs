//! `mechkit md`'s starting state: the box, positions, velocities and pair potential from
//! the flags (a lattice, or --positions / --velocities files).

use anyhow::{Context, Result, anyhow, bail};
use mechkit::md::{
    AtomsFile, Lattice, LennardJones, LinearSpring, MdError, MdInput, SimBox, SoftSphere,
    maxwell_boltzmann,
};

use crate::args::MdArgs;

/// The pair potential chosen with --potential.
pub enum Potential {
    /// Lennard-Jones.
    Lj(LennardJones),
    /// Soft spheres.
    Soft(SoftSphere),
    /// Linear springs.
    Spring(LinearSpring),
}

impl Potential {
    /// The cut-off.
    fn cutoff(&self) -> f64 {
        use mechkit::md::PairPotential;
        match self {
            Self::Lj(p) => p.cutoff(),
            Self::Soft(p) => p.cutoff(),
            Self::Spring(p) => p.cutoff(),
        }
    }
}

/// Everything `Md::new` needs, and what the particles started from.
pub struct Setup {
    /// The box.
    pub sim_box: SimBox,
    /// Positions.
    pub x: Vec<[f64; 3]>,
    /// Velocities.
    pub v: Vec<[f64; 3]>,
    /// "fcc lattice", "file lj_pair.csv", … for the report.
    pub origin: String,
}

/// The flag of an input of `mechkit md`.
fn input_flag(input: MdInput) -> &'static str {
    match input {
        MdInput::Density => "--density",
        MdInput::Temperature => "--temperature",
        MdInput::TimeStep => "--dt",
        MdInput::Skin => "--skin",
        MdInput::Threads => "--threads",
        MdInput::Cutoff => "--cutoff",
        MdInput::Mass => "--mass",
        MdInput::Epsilon => "--epsilon",
        MdInput::Sigma => "--sigma",
        MdInput::SpringConstant => "--k",
        MdInput::RestLength => "--rest-length",
        MdInput::BoxLength => "--box",
        MdInput::ThermoEvery => "--thermo-every",
        MdInput::FrameEvery => "--xyz-every",
        _ => "--cells (or --positions)",
    }
}

/// The flag behind a library error, to say where the input went wrong: from the input the
/// error names ([`MdError::input`]).
pub fn flag(e: &MdError) -> &'static str {
    match (e, e.input()) {
        (MdError::BoxTooSmall { .. }, _) => "--cells or --box (or --cutoff, --skin)",
        (MdError::NoCells { .. }, _) => "--cells",
        (_, Some(input)) => input_flag(input),
        (_, None) => "input",
    }
}

/// The library error with the flag behind it.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
pub fn with_flag(e: MdError) -> anyhow::Error {
    anyhow!("{}: {e}", flag(&e))
}

fn potential(args: &MdArgs) -> Result<Potential> {
    Ok(match args.potential.as_str() {
        "lj" => Potential::Lj(
            LennardJones::new(args.epsilon, args.sigma, args.cutoff, args.shift)
                .map_err(with_flag)?,
        ),
        "soft-sphere" => {
            Potential::Soft(SoftSphere::new(args.epsilon, args.sigma).map_err(with_flag)?)
        }
        "spring" => Potential::Spring(
            LinearSpring::new(args.k, args.rest_length, args.cutoff).map_err(with_flag)?,
        ),
        other => bail!("--potential: unknown potential `{other}`; use lj, soft-sphere or spring"),
    })
}

/// Reads a --positions or --velocities file.
fn read_atoms(flag: &str, path: &std::path::Path) -> Result<AtomsFile> {
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("{flag}: cannot read {}", path.display()))?;
    AtomsFile::parse(&path.to_string_lossy(), &text).map_err(|e| match e {
        // `file:line:` as compilers and the data files print it
        MdError::Parse { line, message } => {
            anyhow!("{flag}: {}:{line}: {message}", path.display())
        }
        e => anyhow!("{flag}: {}: {e}", path.display()),
    })
}

/// `n` and the noun, singular for one: `1 length`, `2 lengths`.
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// The starting state and the potential from the flags.
pub fn setup(args: &MdArgs) -> Result<(Setup, Potential)> {
    let potential = potential(args)?;
    let Some(path) = &args.positions else {
        let lattice = Lattice::from_name(&args.lattice).ok_or_else(|| {
            anyhow!(
                "--lattice: unknown lattice `{}`; use fcc, sc, hexagonal, square or chain",
                args.lattice
            )
        })?;
        let (sim_box, x) = lattice.build(args.cells, args.density).map_err(with_flag)?;
        let t = args.temperature.unwrap_or(1.44);
        let v = maxwell_boltzmann(t, args.mass, lattice.dim(), x.len(), args.seed)
            .map_err(with_flag)?;
        let origin = format!("{} lattice", lattice.name());
        return Ok((
            Setup {
                sim_box,
                x,
                v,
                origin,
            },
            potential,
        ));
    };
    let atoms = read_atoms("--positions", path)?;
    let dim = atoms.dim;
    let periodic = match args.boundary.as_str() {
        "periodic" => true,
        "open" => false,
        other => bail!("--boundary: unknown boundary `{other}`; use periodic or open"),
    };
    let lengths: [f64; 3] = match args.r#box.as_slice() {
        [] if periodic => bail!(
            "--box: a periodic box needs its edge lengths: give --box L (every axis) or one \
             length per axis, e.g. --box 10,10,10; or --boundary open"
        ),
        [] => atoms.extent_with_margin(potential.cutoff()),
        [l] => [*l; 3],
        ls if ls.len() == dim => std::array::from_fn(|a| ls.get(a).copied().unwrap_or(0.0)),
        ls => bail!(
            "--box: {} for {dim}-D positions; give 1 or {dim}",
            count(ls.len(), "length", "lengths")
        ),
    };
    let sim_box = SimBox::new(dim, lengths, [periodic; 3]).map_err(with_flag)?;
    let n = atoms.vectors.len();
    let v = if let Some(vpath) = &args.velocities {
        let v = read_atoms("--velocities", vpath)?;
        if v.vectors.len() != n || v.dim != dim {
            bail!(
                "--velocities: {} has {} for {}; give one velocity per particle, in the order \
                 of --positions and with as many components",
                vpath.display(),
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
            );
        }
        v.vectors
    } else if let Some(t) = args.temperature {
        maxwell_boltzmann(t, args.mass, dim, n, args.seed).map_err(with_flag)?
    } else {
        vec![[0.0; 3]; n]
    };
    let origin = format!("{n} particles from {}", path.display());
    Ok((
        Setup {
            sim_box,
            x: atoms.vectors,
            v,
            origin,
        },
        potential,
    ))
}
