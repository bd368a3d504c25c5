//! `MdReport`: what a run of many particles reports (the `--json` of `mechkit md`): the
//! system, the run's speed, the energy drift, the mean-square displacement and the thermo rows
//! per atom.

use crate::Real;

use super::{Md, MdRun, MdStop, PairPotential, ThermoPerAtom};

/// The result of a run of [`Md`]: its size and start, the run's cost, the energy change per
/// atom from the first row to the last, the mean-square displacement and the thermo rows.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MdReport {
    /// The number of atoms.
    pub atoms: usize,
    /// What the particles started from (`fcc lattice`, `2 particles from pair.csv`).
    pub start: String,
    /// The pair potential's name (`lj`, `soft-sphere`, `spring`).
    pub potential: String,
    /// Steps taken.
    pub steps: usize,
    /// Threads of the force loop.
    pub threads: usize,
    /// Wall-clock seconds of the steps.
    pub seconds: Real,
    /// Atoms times steps per second.
    pub atom_steps_per_second: Real,
    /// Neighbour-list builds.
    pub list_builds: usize,
    /// Builds that came after an atom had moved more than half the skin
    /// ([`Md::dangerous_builds`]): pairs may have been missed when not 0.
    pub dangerous_builds: usize,
    /// (E_last − E_first)/N (ε): the energy drift of velocity Verlet.
    pub energy_change_per_atom: Real,
    /// The pair energy just inside the cut-off, `U(r_c⁻)` (ε): what the energy jumps by each
    /// time a pair crosses the cut-off, which no time step removes (0 when the law is
    /// continuous there, as a shifted one is).
    pub cutoff_jump: Real,
    /// The mean-square displacement ⟨|x(t) − x(0)|²⟩ (σ²).
    pub msd: Real,
    /// The thermo rows, energies per atom.
    pub thermo: Vec<ThermoPerAtom>,
    /// The directory of the LAMMPS export of the run's start ([`Md::lammps_export`]), when
    /// one was written (in the JSON only then).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub lammps_export: Option<String>,
    /// Why the run ended (not in the JSON: a front reports it as an error or an exit code).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub stop: MdStop,
}

impl<P: PairPotential> Md<P> {
    /// The report of `run`, which brought the system to its state now; `start` and
    /// `potential` name the starting state and the pair law for the report.
    pub fn report(&self, run: &MdRun, start: &str, potential: &str) -> MdReport {
        let n = self.len();
        let atom_steps = n as Real * self.steps() as Real;
        let energy_change = match (run.rows.first(), run.rows.last()) {
            (Some(first), Some(last)) => (last.total - first.total) / n.max(1) as Real,
            _ => 0.0,
        };
        MdReport {
            atoms: n,
            start: start.to_string(),
            potential: potential.to_string(),
            steps: self.steps(),
            threads: self.config().threads,
            seconds: run.seconds,
            atom_steps_per_second: atom_steps / run.seconds.max(1e-12),
            list_builds: self.rebuilds(),
            dangerous_builds: self.dangerous_builds(),
            energy_change_per_atom: energy_change,
            cutoff_jump: self.potential.cutoff_jump(),
            msd: self.mean_square_displacement(),
            thermo: run.rows.iter().map(|r| r.per_atom(n)).collect(),
            lammps_export: None,
            stop: run.stop.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::md::{Lattice, LennardJones, Md, MdConfig, RunPlan, maxwell_boltzmann};
    use crate::simulate::Cancel;

    #[test]
    fn the_report_has_per_atom_rows_and_the_energy_drift() {
        let (sim_box, x) = Lattice::Fcc.build(4, 0.8442).unwrap();
        let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 3).unwrap();
        let mut md = Md::new(
            sim_box,
            LennardJones::reduced(2.5).unwrap(),
            x,
            v,
            MdConfig::default(),
        )
        .unwrap();
        let run = md
            .run_observed(&RunPlan::new(10, 5, None).unwrap(), &Cancel::new(), &mut ())
            .unwrap();
        let r = md.report(&run, "fcc lattice", "lj");
        assert_eq!((r.atoms, r.steps, r.thermo.len()), (256, 10, 3));
        let (first, last) = (run.rows[0], run.rows[2]);
        assert_eq!(r.energy_change_per_atom, (last.total - first.total) / 256.0);
        assert_eq!(r.thermo[2].potential_per_atom, last.potential / 256.0);
        assert_eq!(r.thermo[0].temperature, first.temperature);
        assert!((r.thermo[0].temperature - 1.44).abs() < 1e-12);
        assert!(r.msd > 0.0 && r.atom_steps_per_second > 0.0);
        // U(2.5) of the unshifted law: 4 (2.5^-12 − 2.5^-6)
        let u = 4.0 * (2.5f64.powi(-12) - 2.5f64.powi(-6));
        assert!((r.cutoff_jump - u).abs() < 1e-12, "{}", r.cutoff_jump);
    }
}
