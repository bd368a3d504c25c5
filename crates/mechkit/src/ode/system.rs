//! The equations a stepper solves.

use crate::Real;

/// A first-order system `y' = f(t, y)`.
pub trait OdeSystem {
    /// Length of the state vector.
    fn dim(&self) -> usize;

    /// Writes `f(t, y)` into `dydt` (same length as `y`).
    fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]);
}

/// A second-order system `q'' = a(t, q, v)` with `v = q'`: what Newton's second law gives.
pub trait SecondOrderSystem {
    /// Number of coordinates (length of `q`, and of `v`).
    fn dof(&self) -> usize;

    /// Writes the acceleration `a(t, q, v)` into `a`.
    fn accel_into(&self, t: Real, q: &[Real], v: &[Real], a: &mut [Real]);

    /// Whether the acceleration depends on `v` (drag, friction). Velocity Verlet is exact
    /// in its use of the acceleration only when it does not.
    fn velocity_dependent(&self) -> bool {
        true
    }
}

/// Every second-order system is a first-order one with `y = [q, v]` and `y' = [v, a]`.
impl<T: SecondOrderSystem + ?Sized> OdeSystem for T {
    fn dim(&self) -> usize {
        2 * self.dof()
    }

    fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]) {
        let n = self.dof();
        let (q, v) = y.split_at(n);
        let (dq, dv) = dydt.split_at_mut(n);
        dq.copy_from_slice(v);
        self.accel_into(t, q, v, dv);
    }
}
