//! Radau IIA of order 5 (Hairer's RADAU5): an implicit, L-stable Runge-Kutta method for stiff
//! systems, with its collocation polynomial as dense output.
//!
//! Each step solves the three stage equations by simplified Newton iterations with one
//! Jacobian `J ≈ ∂f/∂y` and two LU factorisations, `(γ/h − J)` real and `((α + iβ)/h − J)`
//! complex ([`super::radau_tableau`]). The Jacobian is the system's own
//! ([`OdeSystem::jacobian_into`]: exact, e.g. from the symbolic engine) or one by finite
//! differences (one evaluation per component); it is kept from step to step while the Newton
//! iterations converge fast, and the factorisations while the step size stays within 20 %
//! of the one they were made for. The factorisations are dense, or banded in a reordering of
//! the unknowns when the system's [`OdeSystem::jacobian_pattern`] makes that cheaper (a chain
//! of springs: [`Radau5::band`]).
//!
//! - Newton: at most [`NEWTON_MAX_ITER`] iterations from the previous step's collocation
//!   polynomial extrapolated; converged when `η ‖ΔW‖ ≤ κ`, `η = θ/(1 − θ)` with `θ` the
//!   contraction rate (Hairer's test, so a fast contraction remembered from the last step
//!   can end the iteration after one pass, but only when that pass moved the stages by less
//!   than the error tolerance), `κ = max(10 ε / rtol, min(0.03, √rtol))`. Hairer's RADAU5
//!   ends after one pass whatever its size: at the start of a stiff contact (a ball landing
//!   on a Hertz floor) the remembered rate of free flight accepted stages `f` was never
//!   evaluated at, deep in the floor, and the ball bounced higher than it fell (issue 28).
//!   A diverging or too slow iteration gets a fresh Jacobian, then half the step.
//! - Error: `(γ/h − J)⁻¹ (f₀ + Σ dᵢ Zᵢ / h)`, filtered once more through `f` after a
//!   rejection or on the first step (Hairer's stiff-aware estimate); the norm is the RMS of
//!   `err / (atol + rtol max(|y₀|, |y₁|))`, as for the explicit pairs.
//! - Step size: `h · clamp(fac · err^(-1/4), 0.2, 10)` with Gustafsson's predictive factor
//!   after accepted steps, and `fac = 0.9 (2 N_max + 1) / (2 N_max + N)` smaller for steps that
//!   needed `N` Newton iterations.

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use nalgebra::Complex;

use super::control::{AdaptiveConfig, AdaptiveError, AdaptiveStats, ConfigError, Tolerance};
use super::newton_lu::NewtonLu;
use super::polynomial::StepPolynomial;
use super::radau_tableau::RadauTableau;
use super::state::State;
use super::system::OdeSystem;
use crate::Real;

mod newton;
mod scale;
#[cfg(test)]
mod tests;

use newton::cont_at;

/// The most Newton iterations of one step.
pub const NEWTON_MAX_ITER: usize = 6;

/// Systems of at least this many components keep the step size when it would grow by less
/// than 20 %, to reuse the factorisations (Hairer's rule): there a factorisation, `O(n³)`,
/// costs more than the steps saved. Below it the step grows as the controller says: on van
/// der Pol (2 components) the rule costs 10 steps in 600.
const HOLD_FROM: usize = 16;

/// Counters of an implicit run beyond those of [`AdaptiveStats`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ImplicitStats {
    /// Jacobians formed (exact or by differences).
    pub jacobians: u64,
    /// Of which by finite differences.
    pub jacobians_by_differences: u64,
    /// LU factorisations (pairs: one real, one complex).
    pub decompositions: u64,
    /// Newton iterations.
    pub newton_iterations: u64,
}

/// The Radau IIA(5) integrator.
#[derive(Debug, Clone)]
pub struct Radau5 {
    config: AdaptiveConfig,
    rt: RadauTableau,
    newton_tol: Real,
    stats: AdaptiveStats,
    implicit: ImplicitStats,
    /// The next step to try.
    h: Option<Real>,
    /// The last accepted step and its error (Gustafsson's controller).
    h_acc: Option<Real>,
    err_acc: Option<Real>,
    /// `f(t, y)` at the state the next step starts from, and that time.
    f0: Vec<Real>,
    f0_at: Option<Real>,
    /// The Jacobian (row-major) and whether it was formed at the current state.
    jac: Vec<Real>,
    jac_ready: bool,
    jac_current: bool,
    /// The factorisations and the step they were made for.
    lu_real: NewtonLu<Real>,
    lu_complex: NewtonLu<Complex<Real>>,
    lu_h: Option<Real>,
    /// `η` of the last Newton iteration (Hairer's `FACCON`).
    eta: Real,
    /// Stage increments `Zᵢ` and work buffers.
    z: [Vec<Real>; 3],
    w: [Vec<Real>; 3],
    f: [Vec<Real>; 3],
    y_stage: Vec<Real>,
    /// The error estimate's right-hand side, and the real Newton correction.
    rhs: Vec<Real>,
    dw0: Vec<Real>,
    scale: Vec<Real>,
    err: Vec<Real>,
    cbuf: Vec<Complex<Real>>,
    /// The last accepted step (dense output): start, size, start state, `q₁..q₃` per component.
    pub(super) last_t0: Real,
    pub(super) last_h: Real,
    last_y0: Vec<Real>,
    cont: Vec<Real>,
    /// Whether `cont` extrapolates to the state the next step starts from.
    cont_valid: bool,
}

impl Radau5 {
    /// An integrator with `config`'s tolerances and step limits (its `controller` is not used:
    /// the implicit method has its own).
    pub fn new(config: AdaptiveConfig) -> Self {
        let rtol = config.rtol.as_scalar().unwrap_or_else(|| {
            let Tolerance::PerComponent(v) = &config.rtol else {
                unreachable!("a tolerance is a scalar or per component")
            };
            v.iter().copied().fold(Real::INFINITY, Real::min)
        });
        let newton_tol = (10.0 * Real::EPSILON / rtol).max(0.03_f64.min(rtol.sqrt()));
        Self {
            config,
            rt: RadauTableau::new(),
            newton_tol,
            stats: AdaptiveStats::default(),
            implicit: ImplicitStats::default(),
            h: None,
            h_acc: None,
            err_acc: None,
            f0: Vec::new(),
            f0_at: None,
            jac: Vec::new(),
            jac_ready: false,
            jac_current: false,
            lu_real: NewtonLu::default(),
            lu_complex: NewtonLu::default(),
            lu_h: None,
            eta: 1.0,
            z: Default::default(),
            w: Default::default(),
            f: Default::default(),
            y_stage: Vec::new(),
            rhs: Vec::new(),
            dw0: Vec::new(),
            scale: Vec::new(),
            err: Vec::new(),
            cbuf: Vec::new(),
            last_t0: 0.0,
            last_h: 0.0,
            last_y0: Vec::new(),
            cont: Vec::new(),
            cont_valid: false,
        }
    }

    /// Checks the settings for a system of `n` components.
    pub fn validate(&self, n: usize) -> Result<(), ConfigError> {
        self.config.validate(n)
    }

    /// The counters so far (every evaluation of `f` counted, those of difference Jacobians too).
    pub fn stats(&self) -> AdaptiveStats {
        self.stats
    }

    /// The implicit method's own counters.
    pub fn implicit_stats(&self) -> ImplicitStats {
        self.implicit
    }

    /// `(kl, ku)`, the sub- and super-diagonals of the Newton matrices when they are factored
    /// as band matrices (in a reordering of the unknowns, from the system's
    /// [`OdeSystem::jacobian_pattern`]); `None` when they are factored dense or before the
    /// first step.
    pub fn band(&self) -> Option<(usize, usize)> {
        self.lu_real.band()
    }

    /// The number of unknowns of the Newton systems actually factored when the system is a
    /// second-order one ([`OdeSystem::second_order_dof`]: its coordinates alone, the
    /// velocities and the quantities carried along following from them; [`Self::band`] is
    /// then that reduced matrix's band); `None` when the whole Newton matrices are factored or
    /// before the first step.
    pub fn reduced_to(&self) -> Option<usize> {
        self.lu_real.reduced_to()
    }

    /// The step size the next step will try.
    pub fn next_step(&self) -> Option<Real> {
        self.h
    }

    /// Forgets the step-size history, the cached derivative and the extrapolation (after the
    /// state was changed from outside, e.g. by an event). The Jacobian is kept but no longer
    /// counts as current.
    pub fn reset(&mut self) {
        self.h = None;
        self.h_acc = None;
        self.err_acc = None;
        self.f0_at = None;
        self.cont_valid = false;
        self.jac_current = false;
        self.eta = 1.0;
    }

    /// As [`Radau5::reset`], trying `h` first.
    pub fn reset_to_step(&mut self, h: Real) {
        self.reset();
        if h > 0.0 && h.is_finite() {
            self.h = Some(h);
        }
    }

    fn resize(&mut self, n: usize) {
        if self.f0.len() == n {
            return;
        }
        for v in self
            .z
            .iter_mut()
            .chain(self.w.iter_mut())
            .chain(self.f.iter_mut())
        {
            v.resize(n, 0.0);
        }
        for v in [
            &mut self.f0,
            &mut self.y_stage,
            &mut self.rhs,
            &mut self.dw0,
            &mut self.scale,
            &mut self.err,
            &mut self.last_y0,
        ] {
            v.resize(n, 0.0);
        }
        self.jac.resize(n * n, 0.0);
        self.cont.resize(3 * n, 0.0);
        self.cbuf.resize(n, Complex::new(0.0, 0.0));
        self.jac_ready = false;
        self.lu_real.forget_plan();
        self.lu_complex.forget_plan();
        self.cont_valid = false;
        self.f0_at = None;
    }

    pub(super) fn eval<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: Real, y: &[Real], out: usize) {
        sys.rhs_into(t, y, &mut self.f[out]);
        self.stats.evaluations += 1;
    }
}

impl Radau5 {
    /// Takes one accepted step from `state` towards `t_bound` (never past it), retrying
    /// rejected attempts with smaller steps. Returns the accepted step size.
    ///
    /// # Errors
    /// [`AdaptiveError::StepTooSmall`] when the step falls below its minimum (the Newton
    /// iteration keeps failing, the error cannot be met, or `f` is not finite).
    pub fn step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        state: &mut State,
        t_bound: Real,
    ) -> Result<Real, AdaptiveError> {
        let n = state.y.len();
        self.resize(n);
        let t = state.t;
        if self.f0_at != Some(t) {
            let y = state.y.clone();
            self.eval(sys, t, &y, 0);
            self.f0.copy_from_slice(&self.f[0]);
            self.f0_at = Some(t);
        }
        if self.h.is_none() {
            let h = match self.config.h0 {
                Some(h0) => h0.min(self.config.h_max),
                None => self.initial_step(sys, t, &state.y, (t_bound - t).abs()),
            };
            self.h = Some(h);
        }
        if !self.jac_ready {
            self.jacobian(sys, t, &state.y);
        }
        let h_min = self
            .config
            .h_min
            .unwrap_or_else(|| 10.0 * (next_up(t.abs()) - t.abs()).max(Real::MIN_POSITIVE));
        let mut h = self.h.expect("set above").min(self.config.h_max);
        let mut rejected = false;
        let mut first = self.stats.accepted == 0;
        loop {
            let remaining = t_bound - t;
            let last = remaining.is_finite() && h >= remaining;
            if last {
                h = remaining;
            }
            if !(last || h >= h_min && h.is_finite()) {
                return Err(self.too_small(t, h, h_min, &state.y));
            }
            if self.lu_h != Some(h) && !self.factor(n, h) {
                // singular: a fresh Jacobian, else a smaller step
                if self.jac_current {
                    h *= 0.5;
                } else {
                    self.jacobian(sys, t, &state.y);
                }
                continue;
            }
            let t_new = if last { t_bound } else { t + h };
            self.set_scale(&state.y, None);
            let Some((iterations, rate)) = self.newton(sys, t, &state.y, h) else {
                if self.jac_current {
                    h *= 0.5;
                    self.cont_valid = false;
                } else {
                    self.jacobian(sys, t, &state.y);
                }
                rejected = true;
                continue;
            };
            // the new state and its error
            for i in 0..n {
                self.y_stage[i] = state.y[i] + self.z[2][i];
            }
            // `y_stage` holds the new state until the step is accepted or retried
            let y_new = std::mem::take(&mut self.y_stage);
            self.set_scale(&state.y, Some(&y_new));
            self.y_stage = y_new;
            let d = self.rt.d;
            for i in 0..n {
                self.err[i] = self.f0[i]
                    + (d[0] * self.z[0][i] + d[1] * self.z[1][i] + d[2] * self.z[2][i]) / h;
            }
            let mut e = std::mem::take(&mut self.err);
            self.rhs.copy_from_slice(&e);
            self.lu_real.solve(&mut e);
            let mut err = self.norm(&e);
            if err > 1.0 && (first || rejected) {
                // the estimate through f once more: bounded for stiff components
                let probe: Vec<Real> = (0..n).map(|i| state.y[i] + e[i]).collect();
                self.eval(sys, t, &probe, 0);
                for i in 0..n {
                    e[i] = self.f[0][i] - self.f0[i] + self.rhs[i];
                }
                self.lu_real.solve(&mut e);
                err = self.norm(&e);
            }
            self.err = e;
            let safety = 0.9 * (2 * NEWTON_MAX_ITER + 1) as Real
                / (2 * NEWTON_MAX_ITER + iterations) as Real;
            if !err.is_finite() || err > 1.0 {
                self.stats.rejected += 1;
                rejected = true;
                first = false;
                let factor = if err.is_finite() {
                    (safety * err.powf(-0.25)).max(0.2)
                } else {
                    0.2
                };
                h *= factor;
                self.cont_valid = false;
                continue;
            }
            // accepted
            self.stats.accepted += 1;
            let multiplier = match (self.h_acc, self.err_acc) {
                (Some(h_old), Some(e_old)) if err > 0.0 => h / h_old * (e_old / err).powf(0.25),
                _ => 1.0,
            };
            let mut factor = if err > 0.0 {
                multiplier.min(1.0) * err.powf(-0.25)
            } else {
                10.0
            };
            factor = (safety * factor).min(10.0);
            if rejected {
                factor = factor.min(1.0);
            }
            self.h_acc = Some(h);
            self.err_acc = Some(err.max(1e-10));
            let recompute_jac = iterations > 2 && rate > 1e-3;
            let h_next = if n >= HOLD_FROM && !recompute_jac && (1.0..=1.2).contains(&factor) {
                h
            } else {
                h * factor
            };
            // the collocation polynomial of the step
            let v = self.rt.v_inv;
            for i in 0..n {
                let q = RadauTableau::apply(&v, [self.z[0][i], self.z[1][i], self.z[2][i]]);
                self.cont[i] = q[0];
                self.cont[n + i] = q[1];
                self.cont[2 * n + i] = q[2];
            }
            self.cont_valid = true;
            self.last_t0 = t;
            self.last_h = t_new - t;
            self.last_y0.copy_from_slice(&state.y);
            state.y.copy_from_slice(&self.y_stage);
            state.t = t_new;
            self.eval(sys, t_new, &state.y, 0);
            self.f0.copy_from_slice(&self.f[0]);
            self.f0_at = Some(t_new);
            self.jac_current = false;
            if recompute_jac {
                self.jacobian(sys, t_new, &state.y);
            }
            self.h = Some(h_next.min(self.config.h_max));
            return Ok(t_new - t);
        }
    }

    fn too_small(&self, t: Real, h: Real, h_min: Real, y: &[Real]) -> AdaptiveError {
        let component = (0..y.len())
            .max_by(|&i, &j| {
                let e = |k: usize| (self.err[k] / self.scale[k]).abs();
                e(i).total_cmp(&e(j))
            })
            .unwrap_or(0);
        AdaptiveError::StepTooSmall {
            t,
            h,
            h_min,
            component,
            non_finite: self.f.iter().any(|f| f.iter().any(|v| !v.is_finite())),
        }
    }

    /// The state at `t` inside the last accepted step, from its collocation polynomial.
    pub fn dense_into(&self, t: Real, out: &mut [Real]) {
        let n = out.len();
        let s = if self.last_h == 0.0 {
            1.0
        } else {
            (t - self.last_t0) / self.last_h
        };
        for i in 0..n {
            out[i] = self.last_y0[i] + cont_at(&self.cont, n, i, s);
        }
    }

    /// The last accepted step's collocation polynomial, for proofs about the motion inside it.
    pub fn dense_polynomial_into(&self, out: &mut StepPolynomial) {
        let n = self.last_y0.len();
        out.reset(self.last_t0, self.last_h, n, 4);
        for i in 0..n {
            let c = out.coefficients_mut(i);
            c[0] = self.last_y0[i];
            c[1] = self.cont[i];
            c[2] = self.cont[n + i];
            c[3] = self.cont[2 * n + i];
        }
    }
}

fn next_up(x: Real) -> Real {
    if x.is_finite() {
        Real::from_bits(x.to_bits() + 1)
    } else {
        x
    }
}
