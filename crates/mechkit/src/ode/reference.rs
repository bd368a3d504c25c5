//! Reference problems with exact solutions, for verifying steppers: each returns the system
//! and its exact solution.

use super::system::SecondOrderSystem;
use crate::Real;

/// Harmonic oscillator `x'' = -ω² x` from `x = 1`, `v = 0`: exact `x = cos ωt`,
/// `v = -ω sin ωt`, energy `(v² + ω² x²)/2` conserved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oscillator {
    /// Angular frequency ω (1/s).
    pub omega: Real,
}

impl Oscillator {
    /// Exact position and velocity at time `t`.
    pub fn exact(&self, t: Real) -> (Real, Real) {
        let w = self.omega;
        ((w * t).cos(), -w * (w * t).sin())
    }

    /// Energy per unit mass of a state.
    pub fn energy(&self, x: Real, v: Real) -> Real {
        0.5 * (v * v + self.omega * self.omega * x * x)
    }
}

impl SecondOrderSystem for Oscillator {
    fn dof(&self) -> usize {
        1
    }

    fn accel_into(&self, _t: Real, q: &[Real], _v: &[Real], a: &mut [Real]) {
        a[0] = -self.omega * self.omega * q[0];
    }

    fn velocity_dependent(&self) -> bool {
        false
    }
}

/// Exponential decay `y' = -λ y` from `y = 1`: exact `y = e^{-λt}` (a first-order system).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Decay {
    /// Rate λ (1/s).
    pub lambda: Real,
}

impl Decay {
    /// Exact solution at `t`.
    pub fn exact(&self, t: Real) -> Real {
        (-self.lambda * t).exp()
    }
}

impl super::system::OdeSystem for Decay {
    fn dim(&self) -> usize {
        1
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = -self.lambda * y[0];
    }
}
