//! Observables: energies, temperature, virial pressure, radial distribution function and
//! mean-square displacement.
//!
//! K = ½ m Σ v², T = 2K / (d (N − 1)) (k_B = 1: the degrees of freedom left with the total
//! momentum fixed), P = (N T + W / d) / V with the virial W = Σ_pairs r_ij · F_ij.

use crate::Real;
use crate::csv::{Column, Table};

use super::{Md, PairPotential};

/// One row of the thermodynamic time series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thermo {
    /// Steps taken.
    pub step: usize,
    /// Time.
    pub t: Real,
    /// Kinetic energy K.
    pub kinetic: Real,
    /// Potential energy U.
    pub potential: Real,
    /// Total energy E = K + U.
    pub total: Real,
    /// Temperature 2K / (d (N − 1)).
    pub temperature: Real,
    /// Virial pressure.
    pub pressure: Real,
}

impl Thermo {
    /// The CSV column names of [`Thermo::values`].
    pub const NAMES: [&'static str; 7] = [
        "step",
        "t",
        "kinetic",
        "potential",
        "total",
        "temperature",
        "pressure",
    ];

    /// The CSV columns of [`Thermo::values`] with their units, in reduced units (ε, σ, τ,
    /// k_B = 1) for a box of `dim` dimensions: step `1`, t `tau`, energies `epsilon`,
    /// temperature `epsilon/k_B`, pressure `epsilon/sigma^dim` (a force per length, area or
    /// volume).
    ///
    /// ```
    /// use mechkit::md::Thermo;
    /// let units: Vec<_> = Thermo::columns(3).into_iter().map(|c| c.unit.unwrap()).collect();
    /// assert_eq!(units, ["1", "tau", "epsilon", "epsilon", "epsilon", "epsilon/k_B", "epsilon/sigma^3"]);
    /// assert_eq!(Thermo::columns(1)[6].unit.as_deref(), Some("epsilon/sigma"));
    /// ```
    pub fn columns(dim: usize) -> Vec<Column> {
        let pressure = match dim {
            1 => "epsilon/sigma".to_string(),
            d => format!("epsilon/sigma^{d}"),
        };
        let units = [
            "1",
            "tau",
            "epsilon",
            "epsilon",
            "epsilon",
            "epsilon/k_B",
            pressure.as_str(),
        ];
        Self::NAMES
            .iter()
            .zip(units)
            .map(|(name, unit)| Column::new(*name, unit))
            .collect()
    }

    /// The row as numbers, in the order of [`Thermo::columns`].
    pub fn values(&self) -> [Real; 7] {
        [
            self.step as Real,
            self.t,
            self.kinetic,
            self.potential,
            self.total,
            self.temperature,
            self.pressure,
        ]
    }

    /// The row with its energies per atom, for `n` atoms (as LAMMPS prints them).
    pub fn per_atom(&self, n: usize) -> ThermoPerAtom {
        let n = n.max(1) as Real;
        ThermoPerAtom {
            step: self.step,
            t: self.t,
            temperature: self.temperature,
            potential_per_atom: self.potential / n,
            total_per_atom: self.total / n,
            kinetic_per_atom: self.kinetic / n,
            pressure: self.pressure,
        }
    }
}

/// A thermo row with its energies per atom: what `mechkit md` prints and reports.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ThermoPerAtom {
    /// Steps taken.
    pub step: usize,
    /// Time (τ).
    pub t: Real,
    /// Temperature (ε/k_B).
    pub temperature: Real,
    /// Potential energy per atom U/N (ε).
    pub potential_per_atom: Real,
    /// Total energy per atom E/N (ε).
    pub total_per_atom: Real,
    /// Kinetic energy per atom K/N (ε).
    pub kinetic_per_atom: Real,
    /// Virial pressure (ε/σ^d).
    pub pressure: Real,
}

impl<P: PairPotential> Md<P> {
    /// Kinetic energy ½ m Σ v².
    pub fn kinetic_energy(&self) -> Real {
        0.5 * self.config.mass
            * self
                .v
                .iter()
                .map(|v| v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
                .sum::<Real>()
    }

    /// Energies, temperature and pressure now.
    pub fn thermo(&self) -> Thermo {
        let sums = self.pair_sums();
        let d = self.sim_box.dim() as Real;
        let n = self.len() as Real;
        let kinetic = self.kinetic_energy();
        let temperature = 2.0 * kinetic / (d * (n - 1.0).max(1.0));
        let pressure = (n * temperature + sums.virial / d) / self.sim_box.volume();
        Thermo {
            step: self.steps,
            t: self.steps as Real * self.config.dt,
            kinetic,
            potential: sums.potential,
            total: kinetic + sums.potential,
            temperature,
            pressure,
        }
    }

    /// Mean-square displacement ⟨|x(t) − x(0)|²⟩ of the unwrapped positions.
    pub fn mean_square_displacement(&self) -> Real {
        let l = self.sim_box.lengths();
        let sum: Real = self
            .x
            .iter()
            .zip(&self.image)
            .zip(&self.id)
            .map(|((x, n), &i)| {
                let x0 = self.x0[i as usize];
                (0..3)
                    .map(|a| (x[a] + Real::from(n[a]) * l[a] - x0[a]).powi(2))
                    .sum::<Real>()
            })
            .sum();
        sum / self.len().max(1) as Real
    }

    /// The radial distribution function g(r) on `bins` equal bins of [0, r_max], r_max at
    /// most the neighbour-list range (`r_c + skin`): `(bin centre, g)` pairs, normalised by
    /// the ideal-gas count N ρ V_shell (V_shell the shell's length, area or volume).
    pub fn radial_distribution(&self, bins: usize, r_max: Real) -> Vec<(Real, Real)> {
        let r_max = r_max.min(self.list.range());
        let bins = bins.max(1);
        let width = r_max / bins as Real;
        let mut hist = vec![0usize; bins];
        // Each pair once: it counts for both partners.
        for (i, j) in self.list.sorted_pairs() {
            let d = self.sim_box.separation(&self.x[i], &self.x[j]);
            let r = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            if r < r_max {
                hist[((r / width) as usize).min(bins - 1)] += 2;
            }
        }
        let n = self.len() as Real;
        let rho = n / self.sim_box.volume();
        let dim = self.sim_box.dim();
        let ball = |r: Real| match dim {
            1 => 2.0 * r,
            2 => std::f64::consts::PI * r * r,
            _ => 4.0 / 3.0 * std::f64::consts::PI * r * r * r,
        };
        hist.iter()
            .enumerate()
            .map(|(k, &c)| {
                let (lo, hi) = (k as Real * width, (k + 1) as Real * width);
                (
                    0.5 * (lo + hi),
                    c as Real / (n * rho * (ball(hi) - ball(lo))),
                )
            })
            .collect()
    }

    /// [`Md::radial_distribution`] as a table: columns `r` (σ) and `g` (1), what `rdf.csv`
    /// holds.
    pub fn rdf_table(&self, bins: usize, r_max: Real) -> Table {
        let mut table = Table::new([Column::new("r", "sigma"), Column::new("g", "1")]);
        for (r, g) in self.radial_distribution(bins, r_max) {
            table.push(&[r, g]);
        }
        table
    }
}
