//! The Newton iteration of [`Bdf`]: the Jacobian, the factorisation of `I − c h J`, the
//! simplified Newton iterations for the new state, the error scale and the first step.

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use super::{Bdf, NEWTON_MAX_ITER};
use crate::Real;
use crate::ode::OdeSystem;
use crate::ode::weights::{controlled, first_step, set_weights, trial_step, weighted_rms};

impl Bdf {
    /// Forms the Jacobian at `(t, y)` (by differences: `n + 1` evaluations).
    pub(super) fn jacobian<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: Real, y: &[Real]) {
        let n = y.len();
        self.implicit.jacobians += 1;
        self.jac_ready = true;
        self.jac_current = true;
        self.lu_c = None;
        if !self.lu.is_planned() {
            self.lu.plan(sys, n);
        }
        if sys.jacobian_into(t, y, &mut self.jac) {
            return;
        }
        self.implicit.jacobians_by_differences += 1;
        sys.rhs_into(t, y, &mut self.f0);
        self.stats.evaluations += 1;
        self.y_work.copy_from_slice(y);
        for j in 0..n {
            let yj = y[j];
            let delta = (Real::EPSILON * yj.abs().max(1e-5)).sqrt();
            self.y_work[j] = yj + delta;
            let delta = self.y_work[j] - yj;
            sys.rhs_into(t, &self.y_work, &mut self.f);
            self.stats.evaluations += 1;
            for i in 0..n {
                self.jac[i * n + j] = (self.f[i] - self.f0[i]) / delta;
            }
            self.y_work[j] = yj;
        }
    }

    /// Factors `I − c J`; `false` when it is singular.
    pub(super) fn factor(&mut self, n: usize, c: Real) -> bool {
        self.implicit.decompositions += 1;
        let ok = self.lu.factor(n, 1.0, c, &self.jac).is_ok();
        self.lu_c = ok.then_some(c);
        ok
    }

    /// Solves `y − c f(t, y) − ψ = 0` from the prediction in `y_pred`, with `scale` the
    /// weights of the prediction: the new state in `y_new`, the correction `y_new − y_pred`
    /// in `corr`. The iterations taken, or `None` when the iteration diverges, is too slow
    /// or `f` is not finite.
    pub(super) fn newton<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t_new: Real,
        c: Real,
    ) -> Option<usize> {
        let n = self.y_pred.len();
        self.y_new.copy_from_slice(&self.y_pred);
        self.corr.fill(0.0);
        let mut norm_old: Option<Real> = None;
        for k in 0..NEWTON_MAX_ITER {
            self.implicit.newton_iterations += 1;
            sys.rhs_into(t_new, &self.y_new, &mut self.f);
            self.stats.evaluations += 1;
            if self.f.iter().any(|v| !v.is_finite()) {
                return None;
            }
            for i in 0..n {
                self.dy[i] = c * self.f[i] - self.psi[i] - self.corr[i];
            }
            self.lu.solve(&mut self.dy);
            let norm = self.norm(&self.dy);
            if !norm.is_finite() {
                return None;
            }
            let rate = norm_old.map(|old| norm / old);
            if let Some(rate) = rate
                && (rate >= 1.0
                    || rate.powi((NEWTON_MAX_ITER - k) as i32) / (1.0 - rate) * norm
                        > self.newton_tol)
            {
                return None;
            }
            for i in 0..n {
                self.y_new[i] += self.dy[i];
                self.corr[i] += self.dy[i];
            }
            if norm == 0.0 || rate.is_some_and(|r| r / (1.0 - r) * norm < self.newton_tol) {
                return Some(k + 1);
            }
            norm_old = Some(norm);
        }
        None
    }

    /// The RMS norm of `v` in the weights `scale`, over the controlled components.
    pub(super) fn norm(&self, v: &[Real]) -> Real {
        self.norm_by(v.len(), |i| v[i])
    }

    /// The RMS norm of the vector `v(0), …, v(n − 1)` in the weights `scale`.
    pub(super) fn norm_by(&self, n: usize, v: impl Fn(usize) -> Real) -> Real {
        weighted_rms(&self.scale, self.controlled(n), v)
    }

    pub(super) fn controlled(&self, n: usize) -> usize {
        controlled(&self.config, n)
    }

    /// The weights `atol + rtol max(|y₀|, |y₁|)`.
    pub(super) fn set_scale(&mut self, y0: &[Real], y1: Option<&[Real]>) {
        set_weights(&self.config, y0, y1, &mut self.scale);
    }

    /// A first step for order 1 from the sizes of `y`, `f = f(t, y)` (in `self.f0`) and the
    /// change of `f` along a small explicit step (Hairer, *Solving ODEs I*, Sec. II.4).
    pub(super) fn initial_step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: Real,
        y: &[Real],
        span: Real,
    ) -> Real {
        let n = y.len();
        self.set_scale(y, None);
        let d0 = self.norm(y);
        let d1 = self.norm(&self.f0);
        let h0 = trial_step(&self.config, d0, d1, span);
        for i in 0..n {
            self.y_work[i] = y[i] + h0 * self.f0[i];
        }
        sys.rhs_into(t + h0, &self.y_work, &mut self.f);
        self.stats.evaluations += 1;
        for i in 0..n {
            self.dy[i] = self.f[i] - self.f0[i];
        }
        let d2 = self.norm(&self.dy) / h0;
        first_step(&self.config, h0, d1, d2, span, 1)
    }
}
