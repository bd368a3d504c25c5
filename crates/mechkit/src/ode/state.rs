//! The state a stepper advances: time and a flat vector.

use crate::Real;

/// Time `t` and state vector `y`. For a second-order system `y = [q, v]`: all positions, then
/// all velocities, each half of length [`crate::ode::SecondOrderSystem::dof`].
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// Time.
    pub t: Real,
    /// State vector.
    pub y: Vec<Real>,
}

impl State {
    /// A state at time `t`.
    pub fn new(t: Real, y: Vec<Real>) -> Self {
        Self { t, y }
    }

    /// A second-order state from positions and velocities of equal length.
    pub fn from_qv(t: Real, q: &[Real], v: &[Real]) -> Self {
        assert_eq!(
            q.len(),
            v.len(),
            "positions and velocities differ in length"
        );
        let mut y = Vec::with_capacity(2 * q.len());
        y.extend_from_slice(q);
        y.extend_from_slice(v);
        Self { t, y }
    }

    /// Positions and velocities of a second-order state.
    pub fn qv(&self) -> (&[Real], &[Real]) {
        self.y.split_at(self.y.len() / 2)
    }

    /// Mutable positions and velocities of a second-order state.
    pub fn qv_mut(&mut self) -> (&mut [Real], &mut [Real]) {
        let n = self.y.len() / 2;
        self.y.split_at_mut(n)
    }

    /// Whether every component is finite.
    pub fn is_finite(&self) -> bool {
        self.t.is_finite() && self.y.iter().all(|x| x.is_finite())
    }
}
