//! `mechkit md`: many particles with a pair potential (Lennard-Jones, soft spheres or
//! springs), from a lattice or from a file of positions.

use std::path::PathBuf;

/// `mechkit md`.
#[derive(Debug, clap::Args)]
pub struct MdArgs {
    /// Initial lattice: fcc or sc (3-D), hexagonal or square (2-D), chain (1-D).
    #[arg(long, default_value = "fcc")]
    pub lattice: String,
    /// Unit cells per axis (fcc: 4 atoms per cell; 20 cells = 32,000 atoms).
    #[arg(value_parser = super::whole_count, long, default_value_t = 20, allow_hyphen_values = true)]
    pub cells: usize,
    /// Number density ρ in σ^-d.
    #[arg(long, default_value_t = 0.8442, allow_hyphen_values = true)]
    pub density: f64,
    /// Initial temperature in ε/k_B (Maxwell-Boltzmann, zero total momentum); default 1.44
    /// on a lattice; with --positions the particles start at rest unless it is given.
    #[arg(long, conflicts_with = "velocities", allow_hyphen_values = true)]
    pub temperature: Option<f64>,
    /// Initial positions instead of a lattice: CSV (x[,y[,z]] per line, the column count is
    /// the dimension) or XYZ (by the .xyz extension).
    #[arg(long, value_name = "FILE")]
    pub positions: Option<PathBuf>,
    /// Initial velocities, one per particle of --positions, in the same format.
    #[arg(long, value_name = "FILE", requires = "positions")]
    pub velocities: Option<PathBuf>,
    /// Box edge lengths with --positions: one value for every axis or one per axis (needed
    /// when periodic; an open box defaults to the particles' extent plus the cut-off).
    #[arg(
        long,
        value_name = "L[,L,L]",
        requires = "positions",
        value_delimiter = ',',
        allow_hyphen_values = true
    )]
    pub r#box: Vec<f64>,
    /// Boundaries of a --positions box: periodic (minimum image) or open.
    #[arg(long, default_value = "periodic", requires = "positions")]
    pub boundary: String,
    /// Pair potential: lj (4ε[(σ/r)^12 − (σ/r)^6] cut at --cutoff), soft-sphere
    /// (ε/2 (1 − r/σ)^2 for r < σ) or spring (k/2 (r − r0)^2 for r < --cutoff).
    #[arg(long, default_value = "lj")]
    pub potential: String,
    /// ε of lj and soft-sphere.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub epsilon: f64,
    /// σ of lj and soft-sphere (the soft spheres' diameter and cut-off).
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub sigma: f64,
    /// Stiffness k of spring.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub k: f64,
    /// Rest length r0 of spring.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub rest_length: f64,
    /// Mass of every particle.
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub mass: f64,
    /// Seed of the initial velocities.
    #[arg(value_parser = super::whole_u64, long, default_value_t = 87287, allow_hyphen_values = true)]
    pub seed: u64,
    /// Number of velocity-Verlet steps.
    #[arg(value_parser = super::whole_count, long, default_value_t = 100, allow_hyphen_values = true)]
    pub steps: usize,
    /// Time step in τ.
    #[arg(long, default_value_t = 0.005, allow_hyphen_values = true)]
    pub dt: f64,
    /// Cut-off of lj and spring (spring: between the first and second neighbour distances
    /// to bond nearest neighbours only).
    #[arg(long, default_value_t = 2.5, allow_hyphen_values = true)]
    pub cutoff: f64,
    /// Shift the potential so U(r_c) = 0 (LAMMPS: pair_modify shift yes).
    #[arg(long)]
    pub shift: bool,
    /// Neighbour-list skin in σ.
    #[arg(long, default_value_t = 0.3, allow_hyphen_values = true)]
    pub skin: f64,
    /// Check the neighbour list every this many steps (LAMMPS: neigh_modify every N); 1,
    /// the default, never misses a pair; larger saves builds and reports any that came late
    /// ("dangerous builds").
    #[arg(value_parser = super::whole_count, long, default_value_t = 1, allow_hyphen_values = true)]
    pub neigh_every: usize,
    /// At a check, rebuild only if an atom moved more than half the skin (yes, the default)
    /// or always (no) (LAMMPS: neigh_modify check yes|no).
    #[arg(long, value_name = "yes|no", default_value = "yes", action = clap::ArgAction::Set,
        value_parser = yes_no)]
    pub neigh_check: bool,
    /// Threads for the forces (results are bit-identical for any number).
    #[arg(value_parser = super::whole_count, long, default_value_t = 1, allow_hyphen_values = true)]
    pub threads: usize,
    /// Thermo output every this many steps.
    #[arg(value_parser = super::whole_count, long, default_value_t = 50, allow_hyphen_values = true)]
    pub thermo_every: usize,
    /// Write DIR/thermo.csv, DIR/rdf.csv (each with its units sidecar NAME.units.json, in
    /// reduced units) and (with --xyz-every) DIR/trajectory.xyz; without it nothing is written.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Extended-XYZ frame every this many steps (needs --out).
    #[arg(value_parser = super::whole_count, long, requires = "out", allow_hyphen_values = true)]
    pub xyz_every: Option<usize>,
    /// Write DIR/in.lammps and DIR/data.lammps (and DIR/pair.table for soft-sphere and
    /// spring): the state the run starts from with its potential, time step, neighbour and
    /// thermo settings, to continue it in LAMMPS (`cd DIR && lmp -in in.lammps`); the run
    /// itself still happens.
    #[arg(long, value_name = "DIR")]
    pub export_lammps: Option<PathBuf>,
    /// Largest file to write, e.g. `10GB` (default 1 GB); the run stops cleanly with a
    /// message when thermo.csv or trajectory.xyz would pass it.
    #[arg(long, value_name = "SIZE", allow_hyphen_values = true)]
    pub max_output: Option<String>,
    /// `--json` and `-q/--quiet` (no report, no progress bar).
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `yes` or `no` (LAMMPS's words), as a flag's value.
fn yes_no(s: &str) -> Result<bool, String> {
    match s {
        "yes" => Ok(true),
        "no" => Ok(false),
        _ => Err("give yes or no (as LAMMPS's neigh_modify check)".into()),
    }
}
