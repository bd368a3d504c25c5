//! Continuing a run in LAMMPS: the state a run starts from as a LAMMPS data file, and an input
//! script with the same potential, cut-off, time step, neighbour settings and thermo output.
//!
//! `cd DIR && lmp -in in.lammps` then takes the same velocity-Verlet steps (`fix nve` is the
//! same update: half kick, drift, forces, half kick) from the same positions and velocities,
//! and prints the thermo rows of mechkit's run: `step temp pe ke etotal press`, energies per
//! atom (`thermo_modify norm yes`), every `thermo_every` steps and at the last.
//!
//! What maps to what:
//! - **Units**: `units lj`. mechkit works in any consistent set of units with k_B = 1, and
//!   LAMMPS's `lj` style is exactly that (every conversion factor is 1, k_B = 1); ε, σ and
//!   the mass are written as they are, so the numbers mean in LAMMPS what they meant here.
//! - **Box**: a periodic axis is `p` with bounds `0 L`. An open axis is `s` (shrink-wrapped):
//!   the box follows the atoms and nothing pushes them back, as in mechkit, where an open axis
//!   has no walls (`f` would lose atoms that leave the bounds, `m` is `s` with a floor).
//!   A 2-D run is `dimension 2` with a periodic z (LAMMPS's rule) and `fix enforce2d`.
//!   LAMMPS has no 1-D: a 1-D run is 2-D with every y and vy zero and a fixed (`f`) y axis,
//!   so y stays zero (the forces along y are exactly zero), and `compute_modify thermo_temp
//!   extra/dof` removes the N extra degrees of freedom, so the temperature is 2K/(N − 1) as
//!   here. The pressure then is LAMMPS's 2-D one, not mechkit's 1-D pressure.
//! - **Potential**: a law with a native style ([`LammpsPair`]: Lennard-Jones as `lj/cut`,
//!   `pair_modify shift yes` exactly when mechkit shifts it) is written as that; any other
//!   (soft spheres, springs) as `pair_style table spline` from `pair.table`, sampled from the
//!   law itself at [`TABLE_POINTS`] points evenly spaced in r² between
//!   [`TABLE_INNER`]·r_c and r_c (LAMMPS interpolates by cubic splines in r²: the interpolation
//!   error is below 1e-12 of the energy scale for r > 0.05 r_c, and LAMMPS stops with "Pair
//!   distance < table inner cutoff" if two atoms come closer than `TABLE_INNER`·r_c).
//! - **Pressure**: LAMMPS's is (2K + W)/(dV), mechkit's (N T + W/d)/V: they differ by the
//!   factor N/(N − 1) on the kinetic part; on an open axis LAMMPS also uses the shrink-wrapped
//!   box where mechkit uses the box given.
//!
//! Numbers are written in full precision (Rust's shortest representation that reads back to
//! the same `f64`).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::Real;

use super::lammps_data::{data_file, num, pair_table};
use super::{Md, PairPotential, RunPlan};

/// The name of the data file in the export's directory.
pub const LAMMPS_DATA: &str = "data.lammps";
/// The name of the input script in the export's directory.
pub const LAMMPS_INPUT: &str = "in.lammps";
/// The name of the pair table, for a law without a native LAMMPS style.
pub const LAMMPS_TABLE: &str = "pair.table";
/// The points of a pair table (the same number is LAMMPS's internal table, so LAMMPS uses
/// the tabulated values as they are).
pub const TABLE_POINTS: usize = 20_000;
/// The inner end of a pair table, as a fraction of the cut-off.
pub const TABLE_INNER: Real = 0.01;

/// A pair law as a native LAMMPS pair style.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum LammpsPair {
    /// `pair_style lj/cut cutoff`, `pair_coeff 1 1 epsilon sigma`, `pair_modify shift`.
    LjCut {
        /// ε.
        epsilon: Real,
        /// σ.
        sigma: Real,
        /// r_c.
        cutoff: Real,
        /// Whether U(r_c) is subtracted.
        shift: bool,
    },
}

/// The files of a LAMMPS export: their names in the directory and their text.
#[derive(Debug, Clone, PartialEq)]
pub struct LammpsExport {
    /// `data.lammps`: box, mass, positions and velocities.
    pub data: String,
    /// `in.lammps`: the run's settings and `run STEPS`.
    pub input: String,
    /// `pair.table`, for a law without a native style.
    pub table: Option<String>,
}

impl LammpsExport {
    /// The files as `(name, text)`, the data file first.
    pub fn files(&self) -> Vec<(&'static str, &str)> {
        let mut files = vec![(LAMMPS_DATA, self.data.as_str())];
        if let Some(table) = &self.table {
            files.push((LAMMPS_TABLE, table.as_str()));
        }
        files.push((LAMMPS_INPUT, self.input.as_str()));
        files
    }

    /// Writes the files into `dir` (created with its parents), each atomically, never
    /// through a path that is not a regular file; the paths written.
    ///
    /// # Errors
    /// The directory cannot be created or a file cannot be written: the error names the path.
    pub fn write(&self, dir: &Path) -> std::io::Result<Vec<PathBuf>> {
        let named = |path: &Path, e: std::io::Error| {
            std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
        };
        if dir.exists() && !dir.is_dir() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::AlreadyExists,
                format!("{} is a file, not a directory", dir.display()),
            ));
        }
        std::fs::create_dir_all(dir).map_err(|e| named(dir, e))?;
        let mut written = Vec::new();
        for (name, text) in self.files() {
            let path = dir.join(name);
            crate::csv::write_atomic(&path, text.as_bytes()).map_err(|e| named(&path, e))?;
            written.push(path);
        }
        Ok(written)
    }
}

impl<P: PairPotential> Md<P> {
    /// The state now (before a run: the state the run starts from) with `plan`'s steps and
    /// thermo interval as a LAMMPS data file and input script (module docs: what maps to
    /// what).
    ///
    /// ```
    /// use mechkit::md::{Lattice, LennardJones, Md, MdConfig, RunPlan, maxwell_boltzmann};
    /// let (sim_box, x) = Lattice::Fcc.build(4, 0.8442).unwrap();
    /// let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 1).unwrap();
    /// let md = Md::new(sim_box, LennardJones::reduced(2.5).unwrap(), x, v, MdConfig::default())
    ///     .unwrap();
    /// let export = md.lammps_export(&RunPlan::new(50, 10, None).unwrap());
    /// assert!(export.data.contains("256 atoms"));
    /// assert!(export.input.contains("pair_style      lj/cut 2.5"));
    /// assert!(export.input.ends_with("run             50\n"));
    /// ```
    pub fn lammps_export(&self, plan: &RunPlan) -> LammpsExport {
        let dim = self.sim_box.dim();
        let n = self.len();
        let mut s = String::new();
        let _ = writeln!(
            s,
            "# LAMMPS input written by mechkit md ({n} atoms, {dim}-D): the run from its start;\n\
             # run it here with `lmp -in {LAMMPS_INPUT}`"
        );
        let mut line = |key: &str, value: String| {
            let _ = writeln!(s, "{key:<15} {value}");
        };
        line("units", "lj".into());
        line("dimension", dim.max(2).to_string());
        line("boundary", boundary(self).join(" "));
        line("atom_style", "atomic".into());
        line("read_data", LAMMPS_DATA.into());
        line("mass", format!("1 {}", num(self.config.mass)));
        let table = match self.potential.lammps_pair() {
            Some(LammpsPair::LjCut {
                epsilon,
                sigma,
                cutoff,
                shift,
            }) => {
                line("pair_style", format!("lj/cut {}", num(cutoff)));
                line("pair_coeff", format!("1 1 {} {}", num(epsilon), num(sigma)));
                line("pair_modify", format!("shift {}", yes(shift)));
                None
            }
            None => {
                line("pair_style", format!("table spline {TABLE_POINTS}"));
                line(
                    "pair_coeff",
                    format!(
                        "1 1 {LAMMPS_TABLE} MECHKIT {}",
                        num(self.potential.cutoff())
                    ),
                );
                Some(pair_table(&self.potential))
            }
        };
        line("neighbor", format!("{} bin", num(self.config.skin)));
        line(
            "neigh_modify",
            format!(
                "every {} delay 0 check {}",
                self.config.neigh_every,
                if self.config.neigh_check { "yes" } else { "no" }
            ),
        );
        line("timestep", num(self.config.dt));
        line("fix", "1 all nve".into());
        if dim < 3 {
            line("fix", "2 all enforce2d".into());
        }
        if dim == 1 {
            // 2-D's 2N − 2 degrees of freedom less N: mechkit's N − 1
            line("compute_modify", format!("thermo_temp extra/dof {}", n + 1));
        }
        line("thermo_style", "custom step temp pe ke etotal press".into());
        line("thermo_modify", "norm yes format float %.16g".into());
        line("thermo", plan.thermo_every.to_string());
        line("run", plan.steps.to_string());
        LammpsExport {
            data: data_file(self),
            input: s,
            table,
        }
    }
}

/// `yes` or `no`.
fn yes(b: bool) -> &'static str {
    if b { "yes" } else { "no" }
}

/// The LAMMPS boundary of each axis: `p` periodic, `s` open; a 1-D run's y is `f` and a
/// lower dimension's z `p` (module docs).
fn boundary<P: PairPotential>(md: &Md<P>) -> [&'static str; 3] {
    let dim = md.sim_box.dim();
    let periodic = md.sim_box.is_periodic();
    std::array::from_fn(|a| match a {
        a if a < dim => {
            if periodic[a] {
                "p"
            } else {
                "s"
            }
        }
        1 => "f",
        _ => "p",
    })
}

#[cfg(test)]
#[path = "lammps_tests.rs"]
mod tests;
