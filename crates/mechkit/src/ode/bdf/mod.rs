//! Variable-order (1–5), variable-step backward differentiation formulas for stiff systems,
//! in the numerical differentiation form (NDF) of Shampine and Reichelt (MATLAB's `ode15s`,
//! SciPy's `BDF`).
//!
//! The back values live in a difference array `D` (modified divided differences on an equal
//! grid of the current step `h`): `D⁰ = yₙ`, `Dʲ⁺¹ = ∇Dʲ`. A step of order `k`:
//!
//! - predicts `y⁽⁰⁾ = Σ_{j≤k} Dʲ` and solves `(1 − κ) γₖ (y − y⁽⁰⁾) + Σ_{j≤k} γⱼ Dʲ = h f(t, y)`
//!   (`γⱼ = Σ_{m≤j} 1/m`, `κ` the NDF coefficients `−0.185, −1/9, −0.0823, −0.0415, 0`) by
//!   simplified Newton iterations with the factorisation of `I − c J`, `c = h / ((1 − κ) γₖ)`,
//!   kept while `h` and `k` hold; at most [`NEWTON_MAX_ITER`] iterations, converged when
//!   `θ/(1 − θ) ‖Δy‖ < κ_N`, `κ_N = max(10 ε / rtol, min(0.03, √rtol))`. A failing iteration
//!   gets a fresh Jacobian (the system's own, [`OdeSystem::jacobian_into`], or by
//!   differences), then half the step. The factorisation is dense, or banded in a reordering
//!   of the unknowns when the system's [`OdeSystem::jacobian_pattern`] makes that cheaper
//!   ([`Bdf::band`]);
//! - estimates its local error from the next difference, `(κ γₖ + 1/(k + 1)) ‖y − y⁽⁰⁾‖`;
//! - after `k + 1` steps of one size, compares the estimates of orders `k − 1`, `k`, `k + 1`
//!   (from `Dᵏ` and `Dᵏ⁺²`) and goes on with the order that allows the longest step, the step
//!   scaled by `0.9 (2 N_max + 1)/(2 N_max + N) · err^(−1/(k+1))` (at most 10 times);
//! - changes the step size by re-expressing `D` on the new grid: `D ← (R U)ᵀ D` ([`diff`]).
//!
//! The dense output of a step is the polynomial of degree `k` through the new state and the
//! `k` back values before it: it passes through both ends of the step, and is handed out in
//! monomial form ([`StepPolynomial`]) so that events are located and proven on it.

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use super::control::{AdaptiveConfig, AdaptiveError, AdaptiveStats, ConfigError, Tolerance};
use super::newton_lu::NewtonLu;
use super::radau5::ImplicitStats;
use super::state::State;
use super::system::OdeSystem;
use crate::Real;

mod dense;
mod diff;
mod newton;
#[cfg(test)]
mod tests;

pub use diff::MAX_ORDER;
use diff::{ROWS, change_spacing};

/// The most Newton iterations of one step (SciPy's BDF).
pub const NEWTON_MAX_ITER: usize = 4;

/// The NDF coefficients `κₖ` (index `k`; 0 for order 5, where NDF is BDF).
const KAPPA: [Real; MAX_ORDER + 1] = [0.0, -0.1850, -1.0 / 9.0, -0.0823, -0.0415, 0.0];

/// The integrator: variable-order (1–5) BDF/NDF.
#[derive(Debug, Clone)]
pub struct Bdf {
    config: AdaptiveConfig,
    max_order: usize,
    /// Keeps the step and the order whatever the error (the tests of the formulas' order).
    held: bool,
    newton_tol: Real,
    /// `γₖ`, `αₖ = (1 − κₖ) γₖ` and the error constants `κₖ γₖ + 1/(k + 1)`.
    gamma: [Real; MAX_ORDER + 2],
    alpha: [Real; MAX_ORDER + 2],
    error_const: [Real; MAX_ORDER + 2],
    stats: AdaptiveStats,
    implicit: ImplicitStats,
    /// The time `D⁰` belongs to; `None` to start afresh at the next step.
    t: Option<Real>,
    /// The step size to try first after a reset (else chosen from `f`).
    h_start: Option<Real>,
    /// The step the differences are on, the order, and the steps taken at both.
    h: Real,
    order: usize,
    equal_steps: usize,
    /// The differences `D⁰ … D⁷`, row-major (`ROWS × n`).
    d: Vec<Real>,
    /// The Jacobian (row-major), whether one was formed, and whether in this step.
    jac: Vec<Real>,
    jac_ready: bool,
    jac_current: bool,
    /// The factorisation of `I − c J` and its `c`.
    lu: NewtonLu<Real>,
    lu_c: Option<Real>,
    /// Work buffers.
    f: Vec<Real>,
    f0: Vec<Real>,
    y_pred: Vec<Real>,
    y_new: Vec<Real>,
    y_work: Vec<Real>,
    psi: Vec<Real>,
    corr: Vec<Real>,
    dy: Vec<Real>,
    scale: Vec<Real>,
    err: Vec<Real>,
    /// The last accepted step (dense output): start, size, and the monomial coefficients in
    /// `s = (t − t₀)/h` (`width` per component).
    last_t0: Real,
    last_h: Real,
    width: usize,
    cont: Vec<Real>,
}

impl Bdf {
    /// An integrator with `config`'s tolerances and step limits (its `controller` is not used:
    /// the method has its own), of orders up to [`MAX_ORDER`].
    pub fn new(config: AdaptiveConfig) -> Self {
        let rtol = config.rtol.as_scalar().unwrap_or_else(|| {
            let Tolerance::PerComponent(v) = &config.rtol else {
                unreachable!("a tolerance is a scalar or per component")
            };
            v.iter().copied().fold(Real::INFINITY, Real::min)
        });
        let newton_tol = (10.0 * Real::EPSILON / rtol).max(0.03_f64.min(rtol.sqrt()));
        let mut gamma = [0.0; MAX_ORDER + 2];
        let mut alpha = [0.0; MAX_ORDER + 2];
        let mut error_const = [0.0; MAX_ORDER + 2];
        for k in 1..=MAX_ORDER {
            gamma[k] = gamma[k - 1] + 1.0 / k as Real;
            alpha[k] = (1.0 - KAPPA[k]) * gamma[k];
            error_const[k] = KAPPA[k] * gamma[k] + 1.0 / (k + 1) as Real;
        }
        // order 6 only estimates the error of a step of order 5 raised
        gamma[MAX_ORDER + 1] = gamma[MAX_ORDER] + 1.0 / (MAX_ORDER + 1) as Real;
        alpha[MAX_ORDER + 1] = gamma[MAX_ORDER + 1];
        error_const[MAX_ORDER + 1] = 1.0 / (MAX_ORDER + 2) as Real;
        Self {
            config,
            max_order: MAX_ORDER,
            held: false,
            newton_tol,
            gamma,
            alpha,
            error_const,
            stats: AdaptiveStats::default(),
            implicit: ImplicitStats::default(),
            t: None,
            h_start: None,
            h: 0.0,
            order: 1,
            equal_steps: 0,
            d: Vec::new(),
            jac: Vec::new(),
            jac_ready: false,
            jac_current: false,
            lu: NewtonLu::default(),
            lu_c: None,
            f: Vec::new(),
            f0: Vec::new(),
            y_pred: Vec::new(),
            y_new: Vec::new(),
            y_work: Vec::new(),
            psi: Vec::new(),
            corr: Vec::new(),
            dy: Vec::new(),
            scale: Vec::new(),
            err: Vec::new(),
            last_t0: 0.0,
            last_h: 0.0,
            width: 1,
            cont: Vec::new(),
        }
    }

    /// The same with orders up to `max_order` only (clamped to `1..=`[`MAX_ORDER`]): order 1
    /// is backward Euler, order 2 BDF2 (A-stable).
    pub fn with_max_order(config: AdaptiveConfig, max_order: usize) -> Self {
        let mut bdf = Self::new(config);
        bdf.max_order = max_order.clamp(1, MAX_ORDER);
        bdf
    }

    /// Checks the settings for a system of `n` components.
    pub fn validate(&self, n: usize) -> Result<(), ConfigError> {
        self.config.validate(n)
    }

    /// The counters so far (every evaluation of `f` counted, those of difference Jacobians
    /// too).
    pub fn stats(&self) -> AdaptiveStats {
        self.stats
    }

    /// The implicit method's own counters (a decomposition is one LU of `I − c J`).
    pub fn implicit_stats(&self) -> ImplicitStats {
        self.implicit
    }

    /// The order the next step will take.
    pub fn order(&self) -> usize {
        self.order
    }

    /// `(kl, ku)`, the sub- and super-diagonals of the Newton matrix when it is factored as a
    /// band matrix (in a reordering of the unknowns, from the system's
    /// [`OdeSystem::jacobian_pattern`]); `None` when it is factored dense or before the first
    /// step.
    pub fn band(&self) -> Option<(usize, usize)> {
        self.lu.band()
    }

    /// The number of unknowns of the Newton systems actually factored when the system is a
    /// second-order one ([`OdeSystem::second_order_dof`]: its coordinates alone, the
    /// velocities and the quantities carried along following from them; [`Self::band`] is
    /// then that reduced matrix's band); `None` when the whole Newton matrix is factored or
    /// before the first step.
    pub fn reduced_to(&self) -> Option<usize> {
        self.lu.reduced_to()
    }

    /// The step size the next step will try.
    pub fn next_step(&self) -> Option<Real> {
        self.t.map(|_| self.h)
    }

    /// Starts afresh at order 1 from the state of the next step (after the state was changed
    /// from outside, e.g. by an event). The Jacobian is kept but no longer counts as current.
    pub fn reset(&mut self) {
        self.t = None;
        self.h_start = None;
        self.jac_current = false;
    }

    /// As [`Bdf::reset`], trying `h` first.
    pub fn reset_to_step(&mut self, h: Real) {
        self.reset();
        if h > 0.0 && h.is_finite() {
            self.h_start = Some(h);
        }
    }

    fn resize(&mut self, n: usize) {
        if self.f.len() == n {
            return;
        }
        for v in [
            &mut self.f,
            &mut self.f0,
            &mut self.y_pred,
            &mut self.y_new,
            &mut self.y_work,
            &mut self.psi,
            &mut self.corr,
            &mut self.dy,
            &mut self.scale,
            &mut self.err,
        ] {
            v.resize(n, 0.0);
        }
        self.d.resize(ROWS * n, 0.0);
        self.jac.resize(n * n, 0.0);
        self.jac_ready = false;
        self.lu.forget_plan();
        self.t = None;
    }

    /// Whether the differences continue from `state` (else the run starts afresh there).
    fn continues_from(&self, state: &State) -> bool {
        let n = state.y.len();
        self.t == Some(state.t) && self.d[..n] == state.y[..]
    }

    /// Order 1 from `state`: `D⁰ = y`, `D¹ = h f(t, y)`.
    fn start<S: OdeSystem + ?Sized>(&mut self, sys: &S, state: &State, t_bound: Real) {
        let n = state.y.len();
        let t = state.t;
        sys.rhs_into(t, &state.y, &mut self.f0);
        self.stats.evaluations += 1;
        let h = match self.h_start.take().or(self.config.h0) {
            Some(h) => h.min(self.config.h_max),
            None => self.initial_step(sys, t, &state.y, (t_bound - t).abs()),
        };
        self.d.fill(0.0);
        self.d[..n].copy_from_slice(&state.y);
        for i in 0..n {
            self.d[n + i] = h * self.f0[i];
        }
        self.h = h;
        self.order = 1;
        self.equal_steps = 0;
        self.lu_c = None;
        self.t = Some(t);
    }

    /// Changes the step to `factor` times itself, the differences following.
    fn rescale(&mut self, factor: Real) {
        let n = self.f.len();
        change_spacing(&mut self.d, n, self.order, factor);
        self.h *= factor;
        self.equal_steps = 0;
    }
}

impl Bdf {
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
        if t_bound <= t {
            // nothing to integrate: the dense output is the state
            self.last_t0 = t;
            self.last_h = 0.0;
            self.width = 1;
            self.cont.clone_from(&state.y);
            return Ok(0.0);
        }
        if !self.continues_from(state) {
            self.start(sys, state, t_bound);
        }
        if !self.jac_ready {
            self.jacobian(sys, t, &state.y);
        }
        let h_min = self
            .config
            .h_min
            .unwrap_or_else(|| 10.0 * (next_up(t.abs()) - t.abs()).max(Real::MIN_POSITIVE));
        if self.h > self.config.h_max {
            self.rescale(self.config.h_max / self.h);
        } else if self.h < h_min && self.h > 0.0 {
            self.rescale(h_min / self.h);
        }
        let (t_new, iterations, err_norm) = loop {
            let remaining = t_bound - t;
            let last = remaining.is_finite() && self.h >= remaining;
            if last && self.h > remaining {
                self.rescale(remaining / self.h);
            }
            if !(last || self.h >= h_min && self.h.is_finite()) {
                return Err(self.too_small(t, h_min));
            }
            let t_new = if last { t_bound } else { t + self.h };
            let k = self.order;
            // the prediction and the history term ψ
            for i in 0..n {
                let mut pred = 0.0;
                let mut psi = 0.0;
                for j in 0..=k {
                    let dj = self.d[j * n + i];
                    pred += dj;
                    psi += self.gamma[j] * dj;
                }
                self.y_pred[i] = pred;
                self.psi[i] = psi / self.alpha[k];
            }
            let y_pred = std::mem::take(&mut self.y_pred);
            self.set_scale(&y_pred, None);
            self.y_pred = y_pred;
            let c = self.h / self.alpha[k];
            let mut solved = None;
            loop {
                if self.lu_c != Some(c) && !self.factor(n, c) {
                    if self.jac_current {
                        break;
                    }
                    self.jacobian_at_prediction(sys, t_new);
                    continue;
                }
                solved = self.newton(sys, t_new, c);
                if solved.is_some() || self.jac_current {
                    break;
                }
                self.jacobian_at_prediction(sys, t_new);
            }
            let Some(iterations) = solved else {
                self.stats.rejected += 1;
                self.rescale(0.5);
                continue;
            };
            let (y_pred, y_new) = (
                std::mem::take(&mut self.y_pred),
                std::mem::take(&mut self.y_new),
            );
            self.set_scale(&y_new, None);
            (self.y_pred, self.y_new) = (y_pred, y_new);
            for i in 0..n {
                self.err[i] = self.error_const[k] * self.corr[i];
            }
            let err_norm = self.norm(&self.err);
            if !self.held && (!err_norm.is_finite() || err_norm > 1.0) {
                self.stats.rejected += 1;
                let factor = if err_norm.is_finite() {
                    (safety(iterations) * err_norm.powf(-1.0 / (k + 1) as Real)).max(0.2)
                } else {
                    0.2
                };
                self.rescale(factor);
                continue;
            }
            break (t_new, iterations, err_norm);
        };
        // accepted: the differences of the new state, `corr` being D^(k+1)
        self.stats.accepted += 1;
        self.equal_steps += 1;
        let k = self.order;
        for i in 0..n {
            let d = &mut self.d;
            d[(k + 2) * n + i] = self.corr[i] - d[(k + 1) * n + i];
            d[(k + 1) * n + i] = self.corr[i];
            for j in (0..=k).rev() {
                d[j * n + i] += d[(j + 1) * n + i];
            }
            d[i] = self.y_new[i];
        }
        self.set_dense(t, t_new);
        state.y.copy_from_slice(&self.y_new);
        state.t = t_new;
        self.t = Some(t_new);
        self.jac_current = false;
        if !self.held && self.equal_steps > k {
            self.choose_order(err_norm, iterations);
        }
        Ok(t_new - t)
    }

    /// A fresh Jacobian at the prediction of the step ending at `t_new`.
    fn jacobian_at_prediction<S: OdeSystem + ?Sized>(&mut self, sys: &S, t_new: Real) {
        let y = std::mem::take(&mut self.y_pred);
        self.jacobian(sys, t_new, &y);
        self.y_pred = y;
    }

    /// After `k + 1` steps of one size: the order among `k − 1`, `k`, `k + 1` that allows the
    /// longest next step, and that step.
    fn choose_order(&mut self, err_norm: Real, iterations: usize) {
        let n = self.f.len();
        let k = self.order;
        let estimate = |order: usize, row: usize| {
            let c = self.error_const[order];
            self.norm_by(n, |i| c * self.d[row * n + i])
        };
        let err_m = if k > 1 {
            estimate(k - 1, k)
        } else {
            Real::INFINITY
        };
        let err_p = if k < self.max_order {
            estimate(k + 1, k + 2)
        } else {
            Real::INFINITY
        };
        let factors = [
            err_m.powf(-1.0 / k as Real),
            err_norm.powf(-1.0 / (k + 1) as Real),
            err_p.powf(-1.0 / (k + 2) as Real),
        ];
        let mut best = 1;
        for (i, f) in factors.iter().enumerate() {
            if *f > factors[best] {
                best = i;
            }
        }
        self.order = k + best - 1;
        let factor = (safety(iterations) * factors[best]).min(10.0);
        self.rescale(factor);
    }

    fn too_small(&self, t: Real, h_min: Real) -> AdaptiveError {
        let n = self.err.len();
        let component = (0..n)
            .max_by(|&i, &j| {
                let e = |k: usize| (self.err[k] / self.scale[k]).abs();
                e(i).total_cmp(&e(j))
            })
            .unwrap_or(0);
        AdaptiveError::StepTooSmall {
            t,
            h: self.h,
            h_min,
            component,
            non_finite: self.f.iter().any(|f| !f.is_finite()),
        }
    }
}

/// The safety factor of a step that took `iterations` Newton iterations.
fn safety(iterations: usize) -> Real {
    0.9 * (2 * NEWTON_MAX_ITER + 1) as Real / (2 * NEWTON_MAX_ITER + iterations) as Real
}

fn next_up(x: Real) -> Real {
    if x.is_finite() {
        Real::from_bits(x.to_bits() + 1)
    } else {
        x
    }
}
