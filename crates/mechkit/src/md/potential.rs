//! Pair potentials with a cut-off: Lennard-Jones, soft spheres, linear springs.
//!
//! Each law gives, for a squared separation r² below its cut-off, the energy U(r) and
//! F(r)/r = −U'(r)/r, so the force on i from j is `(F/r) · (xᵢ − xⱼ)` and the pair's virial
//! is `(F/r) r²`, all without a square root for Lennard-Jones. The laws are small value
//! types behind the [`PairPotential`] trait, monomorphised in the force loop (no dynamic
//! dispatch per pair).

use crate::Real;

use super::{LammpsPair, MdError, MdInput};

/// A central pair potential, zero beyond its cut-off.
pub trait PairPotential: Sync + Send {
    /// The cut-off radius r_c.
    fn cutoff(&self) -> Real;
    /// `(U(r), F(r)/r)` for `r² < r_c²`, where F = −dU/dr (positive = repulsive).
    fn energy_force(&self, r2: Real) -> (Real, Real);
    /// The pair energy just inside the cut-off, `U(r_c⁻)`: what the energy jumps by each
    /// time a pair crosses the cut-off; 0 for a law continuous there (a shifted
    /// Lennard-Jones, a soft sphere), where `U(r_c⁻)` is below 1e-9 of the law's size inside
    /// (`|U|` at half and three quarters of `r_c`).
    fn cutoff_jump(&self) -> Real {
        let rc = self.cutoff();
        let u = |r: Real| self.energy_force(r * r).0;
        let jump = self.energy_force(rc * rc * (1.0 - 4.0 * Real::EPSILON)).0;
        let inside = u(0.5 * rc).abs().max(u(0.75 * rc).abs());
        if jump.abs() <= 1e-9 * inside {
            0.0
        } else {
            jump
        }
    }
    /// The same law as a native LAMMPS pair style, where LAMMPS has one; `None` (the
    /// default): [`Md::lammps_export`](super::Md::lammps_export) tabulates it instead.
    fn lammps_pair(&self) -> Option<LammpsPair> {
        None
    }
}

/// Lennard-Jones, U = 4ε[(σ/r)¹² − (σ/r)⁶], cut at r_c and optionally shifted so U(r_c) = 0.
///
/// In reduced (LJ) units σ = ε = m = 1 and the time unit is τ = σ √(m/ε).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LennardJones {
    epsilon: Real,
    sigma: Real,
    cutoff: Real,
    shift: Real,
    s6: Real,
}

impl LennardJones {
    /// ε, σ and the cut-off r_c; `shift` subtracts U(r_c) so the energy is continuous.
    pub fn new(epsilon: Real, sigma: Real, cutoff: Real, shift: bool) -> Result<Self, MdError> {
        for (input, value) in [
            (MdInput::Epsilon, epsilon),
            (MdInput::Sigma, sigma),
            (MdInput::Cutoff, cutoff),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(MdError::NotPositive { input, value });
            }
        }
        let s6 = sigma.powi(6);
        let mut lj = Self {
            epsilon,
            sigma,
            cutoff,
            shift: 0.0,
            s6,
        };
        if shift {
            lj.shift = lj.energy_force(cutoff * cutoff).0;
        }
        Ok(lj)
    }

    /// Reduced units (σ = ε = 1), cut-off `cutoff`, not shifted (as LAMMPS's `lj/cut`).
    pub fn reduced(cutoff: Real) -> Result<Self, MdError> {
        Self::new(1.0, 1.0, cutoff, false)
    }

    /// ε.
    pub fn epsilon(&self) -> Real {
        self.epsilon
    }

    /// σ.
    pub fn sigma(&self) -> Real {
        self.sigma
    }
}

impl PairPotential for LennardJones {
    #[inline]
    fn cutoff(&self) -> Real {
        self.cutoff
    }

    #[inline]
    fn energy_force(&self, r2: Real) -> (Real, Real) {
        let inv2 = 1.0 / r2;
        let sr6 = self.s6 * inv2 * inv2 * inv2;
        let u = 4.0 * self.epsilon * sr6 * (sr6 - 1.0) - self.shift;
        let f_over_r = 24.0 * self.epsilon * sr6 * (2.0 * sr6 - 1.0) * inv2;
        (u, f_over_r)
    }

    fn lammps_pair(&self) -> Option<LammpsPair> {
        Some(LammpsPair::LjCut {
            epsilon: self.epsilon,
            sigma: self.sigma,
            cutoff: self.cutoff,
            // U(r_c) is zero only at r_c = σ, where shifting changes nothing
            shift: self.shift != 0.0,
        })
    }
}

/// Soft (harmonic) spheres of diameter σ: U = ε/2 (1 − r/σ)² for r < σ, zero beyond.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoftSphere {
    epsilon: Real,
    sigma: Real,
}

impl SoftSphere {
    /// Stiffness ε and diameter σ.
    pub fn new(epsilon: Real, sigma: Real) -> Result<Self, MdError> {
        for (input, value) in [(MdInput::Epsilon, epsilon), (MdInput::Sigma, sigma)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(MdError::NotPositive { input, value });
            }
        }
        Ok(Self { epsilon, sigma })
    }
}

impl PairPotential for SoftSphere {
    #[inline]
    fn cutoff(&self) -> Real {
        self.sigma
    }

    #[inline]
    fn energy_force(&self, r2: Real) -> (Real, Real) {
        let r = r2.sqrt();
        let overlap = 1.0 - r / self.sigma;
        (
            0.5 * self.epsilon * overlap * overlap,
            self.epsilon * overlap / (self.sigma * r),
        )
    }
}

/// Linear springs between neighbours of a lattice: U = k/2 (r − r₀)² for r < r_c, so with
/// r_c between the first and second neighbour distances only nearest neighbours are bonded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearSpring {
    k: Real,
    rest_length: Real,
    cutoff: Real,
}

impl LinearSpring {
    /// Stiffness `k`, rest length `rest_length` and cut-off `cutoff` (> rest length).
    pub fn new(k: Real, rest_length: Real, cutoff: Real) -> Result<Self, MdError> {
        for (input, value) in [
            (MdInput::SpringConstant, k),
            (MdInput::RestLength, rest_length),
            (MdInput::Cutoff, cutoff),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(MdError::NotPositive { input, value });
            }
        }
        Ok(Self {
            k,
            rest_length,
            cutoff,
        })
    }
}

impl PairPotential for LinearSpring {
    #[inline]
    fn cutoff(&self) -> Real {
        self.cutoff
    }

    #[inline]
    fn energy_force(&self, r2: Real) -> (Real, Real) {
        let r = r2.sqrt();
        let stretch = r - self.rest_length;
        (0.5 * self.k * stretch * stretch, -self.k * stretch / r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F/r agrees with −U'(r)/r by a central difference, for every law.
    #[test]
    fn force_is_minus_the_derivative_of_the_energy() {
        let laws: [(&dyn PairPotential, Real); 3] = [
            (&LennardJones::new(1.3, 0.9, 2.5, true).unwrap(), 1.1),
            (&SoftSphere::new(2.0, 1.0).unwrap(), 0.8),
            (&LinearSpring::new(3.0, 1.0, 1.4).unwrap(), 1.2),
        ];
        for (law, r) in laws {
            let h = 1e-6;
            let du = (law.energy_force((r + h) * (r + h)).0
                - law.energy_force((r - h) * (r - h)).0)
                / (2.0 * h);
            let f_over_r = law.energy_force(r * r).1;
            assert!((f_over_r * r + du).abs() < 1e-7, "{f_over_r} vs {du}");
        }
        let lj = LennardJones::new(1.0, 1.0, 2.5, true).unwrap();
        assert!(lj.energy_force(6.25).0.abs() < 1e-15);
        let min = 2f64.powf(1.0 / 6.0);
        assert!(
            (LennardJones::reduced(2.5)
                .unwrap()
                .energy_force(min * min)
                .0
                + 1.0)
                .abs()
                < 1e-14
        );
    }
}
