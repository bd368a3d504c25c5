//! Initial lattices: chain (1-D), square and hexagonal (2-D), simple cubic and fcc (3-D).
//!
//! Each fills a periodic box of `cells` unit cells per axis at a given number density
//! ρ = N / V. The unit cell holds `b` atoms (chain, square, simple cubic 1; hexagonal 2 in a
//! rectangular a × a√3 cell; fcc 4), so the lattice constant is a = (b / ρ)^(1/d), and
//! a = (2 / (√3 ρ))^(1/2) for the hexagonal lattice.

use crate::Real;

use super::{MdError, MdInput, SimBox};

/// A crystal lattice to start from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Lattice {
    /// Equally spaced points on a line (1-D).
    Chain,
    /// The square lattice (2-D).
    Square,
    /// The hexagonal (triangular) lattice, the densest packing of discs (2-D).
    Hexagonal,
    /// The simple cubic lattice (3-D).
    SimpleCubic,
    /// The face-centred cubic lattice, 4 atoms per cubic cell (3-D).
    Fcc,
}

impl Lattice {
    /// Its dimension.
    pub fn dim(self) -> usize {
        match self {
            Self::Chain => 1,
            Self::Square | Self::Hexagonal => 2,
            Self::SimpleCubic | Self::Fcc => 3,
        }
    }

    /// Its name as the command line spells it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Chain => "chain",
            Self::Square => "square",
            Self::Hexagonal => "hexagonal",
            Self::SimpleCubic => "sc",
            Self::Fcc => "fcc",
        }
    }

    /// The lattice named `name` (`chain`, `square`, `hexagonal`, `sc`, `fcc`).
    pub fn from_name(name: &str) -> Option<Self> {
        [
            Self::Chain,
            Self::Square,
            Self::Hexagonal,
            Self::SimpleCubic,
            Self::Fcc,
        ]
        .into_iter()
        .find(|l| l.name() == name || (name == "simple-cubic" && *l == Self::SimpleCubic))
    }

    /// The basis: positions of the atoms in the unit cell, in units of the cell's edges.
    fn basis(self) -> &'static [[Real; 3]] {
        match self {
            Self::Chain | Self::Square | Self::SimpleCubic => &[[0.0; 3]],
            Self::Hexagonal => &[[0.0, 0.0, 0.0], [0.5, 0.5, 0.0]],
            Self::Fcc => &[
                [0.0, 0.0, 0.0],
                [0.5, 0.5, 0.0],
                [0.5, 0.0, 0.5],
                [0.0, 0.5, 0.5],
            ],
        }
    }

    /// The edges of the unit cell for lattice constant `a`.
    fn cell_edges(self, a: Real) -> [Real; 3] {
        match self {
            Self::Hexagonal => [a, a * 3f64.sqrt(), 0.0],
            _ => [a; 3],
        }
    }

    /// The lattice constant (nearest-neighbour distance for chain, square, hexagonal and
    /// simple cubic; cube edge for fcc) at number density `density`.
    pub fn constant_for_density(self, density: Real) -> Real {
        let b = self.basis().len() as Real;
        match self {
            Self::Hexagonal => (2.0 / (3f64.sqrt() * density)).sqrt(),
            _ => (b / density).powf(1.0 / self.dim() as Real),
        }
    }

    /// The positions of `cells` unit cells per axis at number density `density`, and the
    /// periodic box they fill.
    ///
    /// # Example
    /// ```
    /// use mechkit::md::Lattice;
    /// let (b, x) = Lattice::Fcc.build(20, 0.8442).unwrap();
    /// assert_eq!(x.len(), 32_000);
    /// assert!((x.len() as f64 / b.volume() - 0.8442).abs() < 1e-12);
    /// ```
    pub fn build(self, cells: usize, density: Real) -> Result<(SimBox, Vec<[Real; 3]>), MdError> {
        if cells == 0 {
            return Err(MdError::NoCells { cells });
        }
        if !(density.is_finite() && density > 0.0) {
            return Err(MdError::NotPositive {
                input: MdInput::Density,
                value: density,
            });
        }
        let dim = self.dim();
        let atoms = (cells as u64)
            .checked_pow(dim as u32)
            .and_then(|n| n.checked_mul(self.basis().len() as u64))
            .unwrap_or(u64::MAX);
        if atoms > super::MAX_ATOMS as u64 {
            return Err(MdError::TooMany {
                input: MdInput::Atoms,
                value: atoms,
                max: super::MAX_ATOMS as u64,
                hint: "use fewer unit cells",
            });
        }
        let edges = self.cell_edges(self.constant_for_density(density));
        let mut lengths = [0.0; 3];
        for a in 0..dim {
            lengths[a] = edges[a] * cells as Real;
        }
        let sim_box = SimBox::periodic(dim, lengths)?;
        let n_axis = |a: usize| if a < dim { cells } else { 1 };
        let mut x = Vec::with_capacity(cells.pow(dim as u32) * self.basis().len());
        for i in 0..n_axis(0) {
            for j in 0..n_axis(1) {
                for k in 0..n_axis(2) {
                    for b in self.basis() {
                        let c = [i as Real + b[0], j as Real + b[1], k as Real + b[2]];
                        x.push([c[0] * edges[0], c[1] * edges[1], c[2] * edges[2]]);
                    }
                }
            }
        }
        Ok((sim_box, x))
    }
}
