//! `mechkit md`: many particles with a Lennard-Jones pair potential (reduced units).

use std::path::PathBuf;

/// `mechkit md`.
#[derive(Debug, clap::Args)]
pub struct MdArgs {
    /// Initial lattice: fcc or sc (3-D), hexagonal or square (2-D), chain (1-D).
    #[arg(long, default_value = "fcc")]
    pub lattice: String,
    /// Unit cells per axis (fcc: 4 atoms per cell; 20 cells = 32,000 atoms).
    #[arg(long, default_value_t = 20)]
    pub cells: usize,
    /// Number density ρ in σ^-d.
    #[arg(long, default_value_t = 0.8442)]
    pub density: f64,
    /// Initial temperature in ε/k_B (Maxwell-Boltzmann, zero total momentum).
    #[arg(long, default_value_t = 1.44)]
    pub temperature: f64,
    /// Seed of the initial velocities.
    #[arg(long, default_value_t = 87287)]
    pub seed: u64,
    /// Number of velocity-Verlet steps.
    #[arg(long, default_value_t = 100)]
    pub steps: usize,
    /// Time step in τ.
    #[arg(long, default_value_t = 0.005)]
    pub dt: f64,
    /// Lennard-Jones cut-off in σ.
    #[arg(long, default_value_t = 2.5)]
    pub cutoff: f64,
    /// Shift the potential so U(r_c) = 0 (LAMMPS: pair_modify shift yes).
    #[arg(long)]
    pub shift: bool,
    /// Neighbour-list skin in σ.
    #[arg(long, default_value_t = 0.3)]
    pub skin: f64,
    /// Threads for the forces (results are bit-identical for any number).
    #[arg(long, default_value_t = 1)]
    pub threads: usize,
    /// Thermo output every this many steps.
    #[arg(long, default_value_t = 50)]
    pub thermo_every: usize,
    /// Write DIR/thermo.csv, DIR/rdf.csv and (with --xyz-every) DIR/trajectory.xyz.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Extended-XYZ frame every this many steps (needs --out).
    #[arg(long, requires = "out")]
    pub xyz_every: Option<usize>,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
}
