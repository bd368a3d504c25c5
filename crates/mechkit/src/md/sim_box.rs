//! The simulation box: orthorhombic, periodic or open along each axis.
//!
//! Positions are stored as `[x, y, z]` whatever the dimension; in 1-D and 2-D the unused
//! components stay zero and their axes are open, so one code path serves every dimension.

use crate::Real;

use super::{MdError, MdInput};

/// An orthorhombic box `[0, L₀) × [0, L₁) × [0, L₂)`, periodic per axis (minimum image).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimBox {
    dim: usize,
    lengths: [Real; 3],
    periodic: [bool; 3],
}

impl SimBox {
    /// A box of dimension `dim` (1, 2 or 3) with the given edge lengths (those beyond `dim`
    /// are ignored), periodic along the axes marked `true`.
    pub fn new(dim: usize, lengths: [Real; 3], periodic: [bool; 3]) -> Result<Self, MdError> {
        if !(1..=3).contains(&dim) {
            return Err(MdError::Dimension { dim });
        }
        let mut l = [0.0; 3];
        let mut p = [false; 3];
        for a in 0..dim {
            if !(lengths[a].is_finite() && lengths[a] > 0.0) {
                return Err(MdError::NotPositive {
                    input: MdInput::BoxLength,
                    value: lengths[a],
                });
            }
            l[a] = lengths[a];
            p[a] = periodic[a];
        }
        Ok(Self {
            dim,
            lengths: l,
            periodic: p,
        })
    }

    /// A box periodic along all `dim` axes.
    pub fn periodic(dim: usize, lengths: [Real; 3]) -> Result<Self, MdError> {
        Self::new(dim, lengths, [true; 3])
    }

    /// The dimension.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The edge lengths (zero beyond the dimension).
    pub fn lengths(&self) -> [Real; 3] {
        self.lengths
    }

    /// Which axes are periodic.
    pub fn is_periodic(&self) -> [bool; 3] {
        self.periodic
    }

    /// The volume (area in 2-D, length in 1-D).
    pub fn volume(&self) -> Real {
        self.lengths[..self.dim].iter().product()
    }

    /// The separation `a − b` by the minimum-image convention on periodic axes.
    #[inline]
    pub fn separation(&self, a: &[Real; 3], b: &[Real; 3]) -> [Real; 3] {
        let mut d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        for (k, dk) in d.iter_mut().enumerate() {
            if self.periodic[k] {
                let l = self.lengths[k];
                *dk -= l * (*dk / l).round();
            }
        }
        d
    }

    /// Maps a position into the box along periodic axes.
    #[inline]
    pub fn wrap(&self, x: &mut [Real; 3]) {
        for (k, xk) in x.iter_mut().enumerate() {
            if self.periodic[k] {
                let l = self.lengths[k];
                *xk -= l * (*xk / l).floor();
                if *xk >= l {
                    *xk -= l;
                }
            }
        }
    }

    /// Checks that the minimum image is the only image within `range` on every periodic axis.
    pub fn check_range(&self, range: Real) -> Result<(), MdError> {
        for a in 0..self.dim {
            if self.periodic[a] && self.lengths[a] < 2.0 * range {
                return Err(MdError::BoxTooSmall {
                    axis: a,
                    length: self.lengths[a],
                    needed: 2.0 * range,
                });
            }
        }
        Ok(())
    }
}
