//! The Newton iteration of [`Radau5`]: the Jacobian, the two factorisations, and the
//! simplified Newton iterations for the stage values in the transformed coordinates.

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use nalgebra::Complex;

use super::{NEWTON_MAX_ITER, Radau5};
use crate::Real;
use crate::ode::OdeSystem;
use crate::ode::radau_tableau::RadauTableau;

/// `sⁱ`-weighted value of the collocation polynomial `Σₖ qₖ sᵏ` (without `y₀`).
pub(super) fn cont_at(cont: &[Real], n: usize, i: usize, s: Real) -> Real {
    s * (cont[i] + s * (cont[n + i] + s * cont[2 * n + i]))
}

impl Radau5 {
    /// Forms the Jacobian at `(t, y)`, whose derivative is `self.f0`.
    pub(super) fn jacobian<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: Real, y: &[Real]) {
        let n = y.len();
        self.implicit.jacobians += 1;
        self.jac_ready = true;
        self.jac_current = true;
        self.lu_h = None;
        if !self.lu_real.is_planned() {
            self.lu_real.plan(sys, n);
            self.lu_complex.plan(sys, n);
        }
        if sys.jacobian_into(t, y, &mut self.jac) {
            return;
        }
        self.implicit.jacobians_by_differences += 1;
        self.y_stage.copy_from_slice(y);
        for j in 0..n {
            let yj = y[j];
            let delta = (Real::EPSILON * yj.abs().max(1e-5)).sqrt();
            self.y_stage[j] = yj + delta;
            let delta = self.y_stage[j] - yj;
            sys.rhs_into(t, &self.y_stage, &mut self.f[0]);
            self.stats.evaluations += 1;
            for i in 0..n {
                self.jac[i * n + j] = (self.f[0][i] - self.f0[i]) / delta;
            }
            self.y_stage[j] = yj;
        }
    }

    /// Factors `(γ/h − J)` and `((α + iβ)/h − J)`; `false` when either is singular.
    pub(super) fn factor(&mut self, n: usize, h: Real) -> bool {
        self.implicit.decompositions += 1;
        let (g, a, b) = (self.rt.gamma / h, self.rt.alpha / h, self.rt.beta / h);
        let real = self.lu_real.factor(n, g, 1.0, &self.jac);
        let complex = self
            .lu_complex
            .factor(n, Complex::new(a, b), 1.0, &self.jac);
        let ok = real.is_ok() && complex.is_ok();
        self.lu_h = ok.then_some(h);
        ok
    }

    /// The simplified Newton iteration for the stages of a step of `h` from `(t, y)`; the
    /// iterations and the last contraction rate, or `None` when it diverges or is too slow.
    pub(super) fn newton<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: Real,
        y: &[Real],
        h: Real,
    ) -> Option<(usize, Real)> {
        let n = y.len();
        let rt = self.rt.clone();
        // starting values: the last polynomial extrapolated, else zero
        if self.cont_valid && self.last_h > 0.0 {
            let ratio = h / self.last_h;
            for i in 0..n {
                let at_end = cont_at(&self.cont, n, i, 1.0);
                for k in 0..3 {
                    self.z[k][i] = cont_at(&self.cont, n, i, 1.0 + rt.c[k] * ratio) - at_end;
                }
            }
        } else {
            for z in &mut self.z {
                z.fill(0.0);
            }
        }
        for i in 0..n {
            let w = RadauTableau::apply(&rt.ti, [self.z[0][i], self.z[1][i], self.z[2][i]]);
            for k in 0..3 {
                self.w[k][i] = w[k];
            }
        }
        let mut eta = self.eta.max(Real::EPSILON).powf(0.8);
        let mut norm_old: Option<Real> = None;
        let mut rate = 1.0;
        for k in 0..NEWTON_MAX_ITER {
            self.implicit.newton_iterations += 1;
            for s in 0..3 {
                for i in 0..n {
                    self.y_stage[i] = y[i] + self.z[s][i];
                }
                let ys = std::mem::take(&mut self.y_stage);
                self.eval(sys, t + rt.c[s] * h, &ys, s);
                self.y_stage = ys;
                if self.f[s].iter().any(|v| !v.is_finite()) {
                    return None;
                }
            }
            // residuals in W coordinates, then the two solves
            let (g, a, b) = (rt.gamma / h, rt.alpha / h, rt.beta / h);
            let mut dw0 = std::mem::take(&mut self.dw0);
            for i in 0..n {
                let f = RadauTableau::apply(&rt.ti, [self.f[0][i], self.f[1][i], self.f[2][i]]);
                let (w0, w1, w2) = (self.w[0][i], self.w[1][i], self.w[2][i]);
                dw0[i] = f[0] - g * w0;
                self.cbuf[i] = Complex::new(f[1] - a * w1 + b * w2, f[2] - b * w1 - a * w2);
            }
            self.lu_real.solve(&mut dw0);
            let mut cb = std::mem::take(&mut self.cbuf);
            self.lu_complex.solve(&mut cb);
            let mut sum = 0.0;
            let nc = self.controlled(n);
            for i in 0..n {
                let (d0, d1, d2) = (dw0[i], cb[i].re, cb[i].im);
                if i < nc && self.scale[i] > 0.0 {
                    let s = self.scale[i];
                    sum += (d0 / s).powi(2) + (d1 / s).powi(2) + (d2 / s).powi(2);
                }
                self.w[0][i] += d0;
                self.w[1][i] += d1;
                self.w[2][i] += d2;
            }
            self.cbuf = cb;
            self.dw0 = dw0;
            let norm = (sum / (3 * nc.max(1)) as Real).sqrt();
            if !norm.is_finite() {
                return None;
            }
            if let Some(old) = norm_old {
                rate = norm / old;
                if rate >= 0.99 {
                    return None;
                }
                if rate.powi((NEWTON_MAX_ITER - 1 - k) as i32) / (1.0 - rate) * norm
                    > self.newton_tol
                {
                    return None;
                }
                eta = rate / (1.0 - rate);
            }
            for i in 0..n {
                let z = RadauTableau::apply(&rt.t, [self.w[0][i], self.w[1][i], self.w[2][i]]);
                for s in 0..3 {
                    self.z[s][i] = z[s];
                }
            }
            // One pass converges on the contraction rate remembered from the last step only
            // when its correction is within the error tolerance: that rate says nothing of a
            // right-hand side whose Jacobian jumped inside the step (a stiff contact starting),
            // and a larger correction has to be checked by `f` at the stages it leads to.
            let trusted = norm_old.is_some() || norm <= 1.0;
            if norm == 0.0 || trusted && eta * norm <= self.newton_tol {
                self.eta = eta;
                return Some((k + 1, if norm_old.is_some() { rate } else { 0.0 }));
            }
            norm_old = Some(norm);
        }
        None
    }
}
