//! Many-particle molecular dynamics: pair potentials with a cut-off in a periodic box.
//!
//! N equal particles interact through a central pair potential cut at r_c
//! ([`LennardJones`], [`SoftSphere`], [`LinearSpring`]). Pairs are found through a cell list
//! (particles sorted by cell) and a half Verlet [`NeighbourList`] with a skin, each pair once,
//! rebuilt automatically when a particle has moved more than half the skin; periodic axes use
//! the minimum image ([`SimBox`], 1-D to 3-D). [`Md`] advances the system by velocity Verlet, starting from a [`Lattice`] (chain,
//! square, hexagonal, simple cubic, fcc) and [`maxwell_boltzmann`] velocities with zero
//! momentum from a seeded generator ([`Xoshiro256`]). Observables: energies, temperature,
//! virial pressure ([`Thermo`], its CSV columns with units), g(r) (`rdf_table`) and the
//! mean-square displacement; frames as extended XYZ; initial particles may be read from a
//! small CSV or XYZ file ([`AtomsFile`]); the state a run starts from, with its settings,
//! exports to LAMMPS ([`Md::lammps_export`]). A run of many steps hands its thermo rows and frames
//! to an [`MdObserver`] as they come ([`Md::run_observed`], stopped by a `Cancel` handle) and
//! ends in an [`MdReport`]. Forces
//! run on `threads` threads over a fixed split of the box into slabs, with a result
//! bit-identical to the serial one.
//!
//! Units: whatever consistent set the caller uses, with k_B = 1 (temperatures are k_B T).
//! The LJ presets use reduced units: σ = ε = m = 1, time in τ = σ √(m/ε), temperature in
//! ε/k_B, pressure in ε/σ³.
//!
//! # Example: the LJ melt (LAMMPS `bench/in.lj`) at 500 atoms
//! ```
//! use mechkit::md::{Lattice, LennardJones, Md, MdConfig, maxwell_boltzmann};
//! let (sim_box, x) = Lattice::Fcc.build(5, 0.8442).unwrap();
//! let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 87287).unwrap();
//! let mut md = Md::new(sim_box, LennardJones::reduced(2.5).unwrap(), x, v, MdConfig::default())
//!     .unwrap();
//! let e0 = md.thermo().total;
//! md.run(50).unwrap();
//! assert!((md.thermo().total - e0).abs() < 1e-2 * e0.abs());
//! ```

mod atoms_file;
mod cell_list;
mod error;
mod forces;
mod kernel;
mod lammps;
mod lammps_data;
mod lattice;
mod list_build;
mod neighbour;
mod observe;
mod potential;
mod reorder;
mod report;
mod rng;
mod run;
mod setup;
mod setup_error;
mod sim_box;
mod start;
mod system;
mod velocities;
mod xyz;

/// The most atoms a run holds: ten million (a few GB with the neighbour list).
pub const MAX_ATOMS: usize = 10_000_000;

/// The most threads a run starts.
pub const MAX_THREADS: usize = 256;

pub use atoms_file::AtomsFile;
pub use error::{MdError, MdInput};
pub use forces::{ForceScratch, PairSums, all_pairs_forces, compute_forces, compute_forces_with};
pub use lammps::{
    LAMMPS_DATA, LAMMPS_INPUT, LAMMPS_TABLE, LammpsExport, LammpsPair, TABLE_INNER, TABLE_POINTS,
};
pub use lattice::Lattice;
pub use neighbour::NeighbourList;
pub use observe::{Thermo, ThermoPerAtom};
pub use potential::{LennardJones, LinearSpring, PairPotential, SoftSphere};
pub use report::MdReport;
pub use rng::Xoshiro256;
pub use run::{MdObserver, MdRun, MdStop, RunPlan};
pub use setup::{Atoms, LATTICE_TEMPERATURE, MdOptions, Potential, RDF_BINS, Setup, WithPotential};
pub use setup_error::{MdOption, SetupError};
pub use sim_box::SimBox;
pub use system::{Md, MdConfig};
pub use velocities::maxwell_boltzmann;
