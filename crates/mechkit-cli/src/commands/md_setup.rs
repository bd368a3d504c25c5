//! `mechkit md`'s starting state: the box, positions, velocities and pair potential from
//! the flags (a lattice, or --positions / --velocities files).

use anyhow::{Context, Result, anyhow, bail};
use mechkit::md::{
    AtomsFile, Lattice, LennardJones, LinearSpring, MdError, SimBox, SoftSphere, maxwell_boltzmann,
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

/// The flag behind a library error, to say where the input went wrong.
pub fn flag(e: &MdError) -> &'static str {
    match e {
        MdError::NotPositive { name, .. } => match *name {
            "the density" => "--density",
            "the temperature" => "--temperature",
            "the time step dt" => "--dt",
            "the skin" => "--skin",
            "the number of threads" => "--threads",
            "the cut-off" => "--cutoff",
            "the mass" => "--mass",
            "epsilon" => "--epsilon",
            "sigma" => "--sigma",
            "k" => "--k",
            "the rest length" => "--rest-length",
            "a box length" => "--box",
            _ => "input",
        },
        MdError::NoCells { .. } => "--cells",
        MdError::TooMany { what, .. } => match *what {
            "the number of threads" => "--threads",
            _ => "--cells (or --positions)",
        },
        MdError::TooFewParticles { .. } => "--cells (or --positions)",
        MdError::BoxTooSmall { .. } => "--cells or --box (or --cutoff, --skin)",
        _ => "input",
    }
}

/// The library error with the flag behind it.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
fn with_flag(e: MdError) -> anyhow::Error {
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
        [] => std::array::from_fn(|a| {
            let (lo, hi) = atoms
                .vectors
                .iter()
                .fold((f64::MAX, f64::MIN), |(lo, hi), p| {
                    (lo.min(p[a]), hi.max(p[a]))
                });
            hi - lo + 2.0 * potential.cutoff()
        }),
        [l] => [*l; 3],
        ls if ls.len() == dim => std::array::from_fn(|a| ls.get(a).copied().unwrap_or(0.0)),
        ls => bail!(
            "--box: {} lengths for {dim}-D positions; give 1 or {dim}",
            ls.len()
        ),
    };
    let sim_box = SimBox::new(dim, lengths, [periodic; 3]).map_err(with_flag)?;
    let n = atoms.vectors.len();
    let v = if let Some(vpath) = &args.velocities {
        let v = read_atoms("--velocities", vpath)?;
        if v.vectors.len() != n || v.dim != dim {
            bail!(
                "--velocities: {} has {} {}-D velocities for {n} {dim}-D positions; give one \
                 velocity per particle, in the order of --positions and with as many components",
                vpath.display(),
                v.vectors.len(),
                v.dim
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
