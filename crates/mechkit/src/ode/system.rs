//! The equations a stepper solves.

use super::pattern::JacobianPattern;
use crate::Real;

/// A first-order system `y' = f(t, y)`.
pub trait OdeSystem {
    /// Length of the state vector.
    fn dim(&self) -> usize;

    /// Writes `f(t, y)` into `dydt` (same length as `y`).
    fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]);

    /// Writes the Jacobian `∂f/∂y` at `(t, y)` into `jac` (row-major, `dim × dim`: row `i`
    /// holds `∂fᵢ/∂yⱼ`) and returns `true`; or returns `false`, the default, when the system
    /// does not know it: the implicit methods then take it by finite differences.
    fn jacobian_into(&self, _t: Real, _y: &[Real], _jac: &mut [Real]) -> bool {
        false
    }

    /// The entries of `∂f/∂y` that may be non-zero, for every `t` and `y` (the others are
    /// structurally zero); `None`, the default, when unknown: the implicit methods then factor
    /// their Newton matrices dense. With a pattern they factor them as band matrices in a
    /// reordering of the unknowns when that is cheaper (a chain of springs). A wrong pattern
    /// makes the Newton iterations converge slowly or not at all, never the solution wrong.
    fn jacobian_pattern(&self) -> Option<JacobianPattern> {
        None
    }

    /// `Some(dof)` when the state is `[q, v, e]` with `dof` coordinates `q`, their velocities
    /// `v`, `q' = v` exactly, and no derivative depending on the components `e` after them
    /// (quantities carried along, like the works of forces); `None`, the default, when it is
    /// not so structured. The implicit methods then solve their Newton systems in `q` alone
    /// (`dof` unknowns instead of `2 dof + e`). A wrong answer makes the Newton iterations
    /// converge slowly or not at all, never the solution wrong.
    fn second_order_dof(&self) -> Option<usize> {
        None
    }
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

    /// Writes `∂a/∂q` into `da_dq` and `∂a/∂v` into `da_dv` (row-major, `dof × dof`) and
    /// returns `true`; or `false`, the default, when the system does not know them.
    fn accel_jacobian_into(
        &self,
        _t: Real,
        _q: &[Real],
        _v: &[Real],
        _da_dq: &mut [Real],
        _da_dv: &mut [Real],
    ) -> bool {
        false
    }

    /// Which coordinates each acceleration depends on: `(i, j)` marked when `aᵢ` may depend
    /// on `qⱼ` or `vⱼ` (size `dof`); `None`, the default, when unknown. It gives the first-order
    /// form its [`OdeSystem::jacobian_pattern`] ([`JacobianPattern::second_order`]).
    fn accel_pattern(&self) -> Option<JacobianPattern> {
        None
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

    /// `[[0, I], [∂a/∂q, ∂a/∂v]]` from [`SecondOrderSystem::accel_jacobian_into`].
    fn jacobian_into(&self, t: Real, y: &[Real], jac: &mut [Real]) -> bool {
        let n = self.dof();
        let (q, v) = y.split_at(n);
        let mut da_dq = vec![0.0; n * n];
        let mut da_dv = vec![0.0; n * n];
        if !self.accel_jacobian_into(t, q, v, &mut da_dq, &mut da_dv) {
            return false;
        }
        let m = 2 * n;
        jac.fill(0.0);
        for i in 0..n {
            jac[i * m + n + i] = 1.0;
            let row = (n + i) * m;
            jac[row..row + n].copy_from_slice(&da_dq[i * n..(i + 1) * n]);
            jac[row + n..row + m].copy_from_slice(&da_dv[i * n..(i + 1) * n]);
        }
        true
    }

    /// [`JacobianPattern::second_order`] of [`SecondOrderSystem::accel_pattern`].
    fn jacobian_pattern(&self) -> Option<JacobianPattern> {
        self.accel_pattern().map(|p| p.second_order(0))
    }

    fn second_order_dof(&self) -> Option<usize> {
        Some(self.dof())
    }
}
