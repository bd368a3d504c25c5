//! What a force sees: time, positions, velocities and masses of every body.

use crate::Real;

/// A read-only view of the system's state for force evaluation.
#[derive(Debug, Clone, Copy)]
pub struct Kinematics<'a> {
    /// Time.
    pub t: Real,
    /// Spatial dimensions (1, 2 or 3).
    pub dim: usize,
    /// Positions, `dim` per body.
    pub x: &'a [Real],
    /// Velocities, `dim` per body.
    pub v: &'a [Real],
    /// Masses, one per body.
    pub mass: &'a [Real],
}

impl Kinematics<'_> {
    /// Number of bodies.
    pub fn n_bodies(&self) -> usize {
        self.mass.len()
    }

    /// Position of body `i`.
    #[inline]
    pub fn position(&self, i: usize) -> &[Real] {
        &self.x[i * self.dim..(i + 1) * self.dim]
    }

    /// Velocity of body `i`.
    #[inline]
    pub fn velocity(&self, i: usize) -> &[Real] {
        &self.v[i * self.dim..(i + 1) * self.dim]
    }
}

/// Euclidean norm.
#[inline]
pub fn norm(v: &[Real]) -> Real {
    v.iter().map(|x| x * x).sum::<Real>().sqrt()
}

/// Dot product.
#[inline]
pub fn dot(a: &[Real], b: &[Real]) -> Real {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
