//! Adaptive explicit Runge-Kutta: embedded error estimates, a PI step-size controller with
//! Gustafsson's predictive limit, an automatic first step, and dense output inside each
//! accepted step.
//!
//! The error of a step is the root-mean-square of `err_i / (atol_i + rtol_i max(|y_i|,
//! |y_new,i|))` over the controlled components (DOP853: Hairer's combined 5th/3rd-order
//! estimate); a step is accepted when it is at most 1. The next step is
//! `h · clamp(0.9 · err^(-α) · err_prev^β, 0.2, 10)` with α = 1/(q+1) − 0.75 β, limited further
//! by the predictive factor when the error is growing; see [`Controller`]. The first step follows
//! Hairer, Nørsett & Wanner, *Solving ODEs I*, Sec. II.4.

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use super::blocks::copy_small;
use super::control::{
    AdaptiveConfig, AdaptiveError, AdaptiveStats, ConfigError, Controller, Tolerance,
};
use super::fixed::{Dop853, Dopri5, FixedTableau, Kernel};
use super::stages::{Sparse, Stages, sparse};
use super::state::State;
use super::stiffness::StiffnessTest;
use super::system::OdeSystem;
use super::tableau::{DenseKind, Tableau};
use crate::Real;

/// An adaptive Runge-Kutta integrator for a tableau with an error estimator.
#[derive(Debug, Clone)]
pub struct AdaptiveRk {
    pub(super) tableau: Tableau,
    config: AdaptiveConfig,
    pub(super) stages: Stages,
    /// The stage loops: unrolled with constant coefficients for DP5 and DOP853.
    pub(super) kernel: Kernel,
    /// Non-zero error weights (and DOP853's third-order ones).
    err_w: Sparse,
    err_w3: Sparse,
    /// Whether the error estimate uses `f(t + h, y_new)` (first-same-as-last pairs).
    fsal_in_error: bool,
    y_new: Vec<Real>,
    err_buf: Vec<Real>,
    err_buf3: Vec<Real>,
    h: Option<Real>,
    /// ln of the previous accepted error (PI term) and of the one before the step (predictive).
    ln_err_prev: Real,
    ln_err_acc: Real,
    /// No step accepted since the start or a reset (the predictive limit needs one).
    fresh: bool,
    controller: Controller,
    pub(super) stats: AdaptiveStats,
    /// The last accepted step: start time, size, start and end states (for dense output).
    pub(super) last_t0: Real,
    pub(super) last_h: Real,
    pub(super) last_y0: Vec<Real>,
    pub(super) last_y1: Vec<Real>,
    pub(super) dense_ready: bool,
    pub(super) dense: Vec<Real>,
    /// Stage 0 holds `f(t, y)` of the current state at this time.
    k0_at: Option<Real>,
    /// Hairer's stiffness test, for pairs with a second stage at the step's end.
    stiffness: Option<StiffnessTest>,
}

impl AdaptiveRk {
    /// An integrator for `tableau` (which needs an error estimator).
    pub fn new(tableau: Tableau, config: AdaptiveConfig) -> Result<Self, ConfigError> {
        if !tableau.is_adaptive() {
            return Err(ConfigError::NotAdaptive(tableau.name));
        }
        tableau.validate().unwrap_or_else(|e| panic!("{e}"));
        let controller = config
            .controller
            .unwrap_or_else(|| Controller::for_tableau(&tableau));
        let s = tableau.stages();
        let err_w = sparse(&tableau.e);
        Ok(Self {
            stiffness: StiffnessTest::for_tableau(&tableau),
            stages: Stages::new(&tableau),
            kernel: Kernel::for_tableau(&tableau),
            fsal_in_error: err_w.iter().any(|(l, _)| *l == s),
            err_w,
            err_w3: sparse(&tableau.e3),
            tableau,
            config,
            y_new: Vec::new(),
            err_buf: Vec::new(),
            err_buf3: Vec::new(),
            h: None,
            ln_err_prev: LN_1E_4,
            ln_err_acc: LN_1E_2,
            fresh: true,
            controller,
            stats: AdaptiveStats::default(),
            last_t0: 0.0,
            last_h: 0.0,
            last_y0: Vec::new(),
            last_y1: Vec::new(),
            dense_ready: false,
            dense: Vec::new(),
            k0_at: None,
        })
    }

    /// The tableau.
    pub fn tableau(&self) -> &Tableau {
        &self.tableau
    }

    /// The counters so far.
    pub fn stats(&self) -> AdaptiveStats {
        self.stats
    }

    /// When Hairer's stiffness test first fired: from that time stability, not accuracy,
    /// limited the steps for many steps in a row (an implicit method would take far fewer).
    pub fn stiff_from(&self) -> Option<Real> {
        self.stiffness.as_ref().and_then(|t| t.from)
    }

    /// The step size the next step will try.
    pub fn next_step(&self) -> Option<Real> {
        self.h
    }

    /// Forgets the step size history and cached derivatives (after the state was changed
    /// from outside, e.g. by an event).
    pub fn reset(&mut self) {
        self.h = None;
        self.ln_err_prev = LN_1E_4;
        self.ln_err_acc = LN_1E_2;
        self.k0_at = None;
        self.fresh = true;
    }

    /// Forgets the history as [`AdaptiveRk::reset`] does, but tries `h` first instead of
    /// choosing a first step afresh (after a state change, the last step taken: a first-step
    /// guess from a state near rest can fall below the smallest step).
    pub fn reset_to_step(&mut self, h: Real) {
        self.reset();
        if h > 0.0 && h.is_finite() {
            self.h = Some(h);
        }
    }

    /// Hands the integrator `f(t, y)` of the state the next step starts from.
    pub fn provide_derivative(&mut self, t: Real, dydt: &[Real]) {
        self.stages.resize(self.stage_count(), dydt.len());
        self.stages.k_mut(0).copy_from_slice(dydt);
        self.k0_at = Some(t);
    }

    fn stage_count(&self) -> usize {
        let extra = match self.tableau.dense {
            DenseKind::Dop853 => 3,
            _ => 0,
        };
        self.tableau.stages() + 1 + extra
    }

    #[inline]
    fn scale(&self, i: usize, a: Real, b: Real) -> Real {
        match (&self.config.atol, &self.config.rtol) {
            (Tolerance::Scalar(atol), Tolerance::Scalar(rtol)) => {
                atol + rtol * a.abs().max(b.abs())
            }
            (atol, rtol) => atol.at(i) + rtol.at(i) * a.abs().max(b.abs()),
        }
    }

    fn controlled(&self, n: usize) -> usize {
        self.config.error_components.unwrap_or(n).min(n)
    }

    /// Hairer's first step: from the sizes of `y` and `f`, then refined with one more
    /// evaluation.
    fn initial_step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: Real,
        y: &[Real],
        t_bound: Real,
    ) -> Real {
        let f0 = self.stages.k(0).to_vec();
        let n = self.controlled(y.len());
        let rms = |v: &dyn Fn(usize) -> Real| {
            ((0..n).map(|i| v(i) * v(i)).sum::<Real>() / n as Real).sqrt()
        };
        // a component with no tolerance at all (atol = 0 and y = 0) says nothing of the scale
        let ratio = |v: Real, sc: Real| if sc > 0.0 { v / sc } else { 0.0 };
        let d0 = rms(&|i| ratio(y[i], self.scale(i, y[i], y[i])));
        let d1 = rms(&|i| ratio(f0[i], self.scale(i, y[i], y[i])));
        let span = (t_bound - t).abs();
        let mut h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        h0 = h0.min(self.config.h_max).min(span);
        let y1: Vec<Real> = y.iter().zip(&f0).map(|(y, f)| y + h0 * f).collect();
        let mut f1 = vec![0.0; y.len()];
        sys.rhs_into(t + h0, &y1, &mut f1);
        self.stats.evaluations += 1;
        let d2 = rms(&|i| ratio(f1[i] - f0[i], self.scale(i, y[i], y[i]))) / h0;
        let q = Real::from(self.tableau.error_order.unwrap_or(1));
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(1.0 / (q + 1.0))
        };
        let h = (100.0 * h0).min(h1).min(self.config.h_max).min(span);
        if h > 0.0 && h.is_finite() {
            h
        } else {
            Real::min(1e-6, self.config.h_max).min(span)
        }
    }

    /// Takes one accepted step from `state` towards `t_bound` (never past it), retrying
    /// rejected attempts with smaller steps. Returns the accepted step size, or
    /// [`AdaptiveError::StepBudget`] once [`AdaptiveConfig::max_steps`] steps were accepted.
    pub fn step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        state: &mut State,
        t_bound: Real,
    ) -> Result<Real, AdaptiveError> {
        if let Some(steps) = self.config.max_steps
            && self.stats.accepted >= steps
        {
            return Err(AdaptiveError::StepBudget {
                steps,
                t: state.t,
                t_end: t_bound,
            });
        }
        let n = state.y.len();
        self.stages.resize(self.stage_count(), n);
        if self.y_new.len() != n {
            self.y_new.resize(n, 0.0);
            self.err_buf.resize(n, 0.0);
            self.err_buf3.resize(n, 0.0);
        }
        let t = state.t;
        let s = self.tableau.stages();
        if self.stats.accepted > 0
            && self.k0_at == Some(self.last_t0)
            && t == self.last_t0 + self.last_h
        {
            // the derivative at the end of the last step starts this one
            self.stages.copy_stage(s, 0);
            self.k0_at = Some(t);
        }
        if self.k0_at != Some(t) {
            self.stages.eval_into(sys, t, &state.y, 0);
            self.stats.evaluations += 1;
            self.k0_at = Some(t);
        }
        if self.h.is_none() {
            let h = match self.config.h0 {
                Some(h0) => h0.min(self.config.h_max),
                None => self.initial_step(sys, t, &state.y, t_bound),
            };
            self.h = Some(h);
        }
        let h_min = self
            .config
            .h_min
            .unwrap_or_else(|| 10.0 * (next_up(t.abs()) - t.abs()).max(Real::MIN_POSITIVE));
        let mut h = self.h.expect("set above").min(self.config.h_max);
        let mut rejected_before = false;
        let q = Real::from(self.tableau.error_order.expect("adaptive"));
        let Controller {
            safety,
            beta,
            min_factor,
            max_factor,
            predictive,
        } = self.controller;
        let alpha = 1.0 / (q + 1.0) - 0.75 * beta;
        loop {
            let remaining = t_bound - t;
            // with no end (t_bound = ∞) no step is the last one, however large
            let last = remaining.is_finite() && h >= remaining;
            if last {
                h = remaining;
            }
            // a step size that is not a finite number (0/0 in a norm) is a failure too, never
            // a step: NaN compares false with everything, and ∞ would be retried for ever
            if !(last || h >= h_min && h.is_finite()) {
                let component = self.dominant_component(&state.y);
                return Err(AdaptiveError::StepTooSmall {
                    t,
                    h,
                    h_min,
                    component,
                    non_finite: (0..=s).any(|l| self.stages.k(l).iter().any(|v| !v.is_finite())),
                });
            }
            let evals = match self.kernel {
                Kernel::Dopri5 => {
                    let evals = self.stages.compute_fixed::<Dopri5, S>(sys, t, &state.y, h);
                    self.stages.advance_fixed(Dopri5::B, h, &mut self.y_new);
                    evals
                }
                Kernel::Dop853 => {
                    let evals = self.stages.compute_fixed::<Dop853, S>(sys, t, &state.y, h);
                    self.stages.advance_fixed(Dop853::B, h, &mut self.y_new);
                    evals
                }
                Kernel::General => {
                    let evals = self
                        .stages
                        .compute(&self.tableau, sys, t, &state.y, h, true);
                    self.stages.solution_into(h, &mut self.y_new);
                    evals
                }
            };
            self.stats.evaluations += evals as u64;
            let t_new = if last { t_bound } else { t + h };
            // f at the new point starts the next step; first-same-as-last pairs need it for
            // the error estimate too, the others only once the step is accepted
            if self.fsal_in_error {
                self.stages.eval_into(sys, t_new, &self.y_new, s);
                self.stats.evaluations += 1;
            }
            let err = self.error_norm(h, &state.y);
            if err <= 1.0 {
                if !self.fsal_in_error {
                    self.stages.eval_into(sys, t_new, &self.y_new, s);
                    self.stats.evaluations += 1;
                }
                if let Some(test) = &mut self.stiffness {
                    test.check(
                        &mut self.stages,
                        s,
                        h,
                        &self.y_new,
                        &mut self.err_buf,
                        t_new,
                    );
                }
                self.stats.accepted += 1;
                // h_new = h · safety · err^(-α) · err_prev^β, in logarithms (one ln, one exp)
                let ln_err = err.max(1e-10).ln();
                let mut fac = (safety * (-alpha * ln_err + beta * self.ln_err_prev).exp())
                    .clamp(min_factor, max_factor);
                if predictive && !self.fresh && self.last_h > 0.0 {
                    // Gustafsson: safety · (h/h_prev) · (err_prev/err²)^(1/(q+1))
                    let pred = safety
                        * (h / self.last_h)
                        * ((self.ln_err_acc - 2.0 * ln_err) / (q + 1.0)).exp();
                    fac = fac.min(pred.max(min_factor));
                }
                self.ln_err_acc = ln_err.max(LN_1E_2);
                self.fresh = false;
                let mut h_next = h * fac;
                if rejected_before {
                    h_next = h_next.min(h);
                }
                self.ln_err_prev = ln_err.max(LN_1E_4);
                self.h = Some(h_next.min(self.config.h_max));
                self.last_t0 = t;
                self.last_h = t_new - t;
                self.last_y0.resize(n, 0.0);
                copy_small(&mut self.last_y0, &state.y);
                copy_small(&mut state.y, &self.y_new);
                // y_new is recomputed by the next step: its buffer can hold the step's end
                std::mem::swap(&mut self.last_y1, &mut self.y_new);
                if self.y_new.len() != n {
                    self.y_new.resize(n, 0.0);
                }
                self.dense_ready = false;
                state.t = t_new;
                return Ok(self.last_h);
            }
            self.stats.rejected += 1;
            rejected_before = true;
            let fac = if err.is_finite() {
                (safety * err.powf(-alpha)).clamp(min_factor, 1.0)
            } else {
                min_factor
            };
            h *= fac;
        }
    }

    fn error_norm(&mut self, h: Real, y: &[Real]) -> Real {
        let n = self.controlled(y.len());
        let combined = matches!(self.tableau.dense, DenseKind::Dop853);
        match self.kernel {
            Kernel::Dopri5 => self.stages.combine_fixed(Dopri5::E, &mut self.err_buf),
            Kernel::Dop853 => {
                self.stages.combine_fixed(Dop853::E, &mut self.err_buf);
                self.stages.combine_fixed(Dop853::E3, &mut self.err_buf3);
            }
            Kernel::General => {
                self.stages.combine_into(&self.err_w, &mut self.err_buf);
                if combined {
                    self.stages.combine_into(&self.err_w3, &mut self.err_buf3);
                }
            }
        }
        let (err, err3) = (&self.err_buf, combined.then_some(&self.err_buf3[..]));
        let (e5, e3) = match (&self.config.atol, &self.config.rtol) {
            (Tolerance::Scalar(atol), Tolerance::Scalar(rtol)) => {
                let (atol, rtol) = (*atol, *rtol);
                squared_sums(n, err, err3, y, &self.y_new, |_, a, b| {
                    atol + rtol * a.abs().max(b.abs())
                })
            }
            (atol, rtol) => squared_sums(n, err, err3, y, &self.y_new, |i, a, b| {
                atol.at(i) + rtol.at(i) * a.abs().max(b.abs())
            }),
        };
        let v = if combined {
            let den = e5 + 0.01 * e3;
            if den == 0.0 {
                return 0.0;
            }
            h.abs() * e5 / (den * n as Real).sqrt()
        } else {
            h.abs() * (e5 / n as Real).sqrt()
        };
        if v.is_nan() { Real::INFINITY } else { v }
    }

    /// The component with the largest scaled error in the last attempt (`err_buf` holds its
    /// estimate).
    fn dominant_component(&self, y: &[Real]) -> usize {
        let n = self.controlled(y.len()).min(self.err_buf.len());
        let e = |i: usize| {
            let v = self.err_buf[i] / self.scale(i, y[i], self.y_new[i]);
            if v.is_nan() { Real::INFINITY } else { v.abs() }
        };
        (0..n).max_by(|&a, &b| e(a).total_cmp(&e(b))).unwrap_or(0)
    }

    /// The start and end time of the last accepted step.
    pub fn last_step(&self) -> (Real, Real) {
        (self.last_t0, self.last_t0 + self.last_h)
    }
}

/// `(Σ (e_i / sc_i)², Σ (e3_i / sc_i)²)` over the first `n` components, with `sc_i =
/// scale(i, y_i, y_new,i)` (the second sum zero without `e3`).
#[inline]
fn squared_sums(
    n: usize,
    e: &[Real],
    e3: Option<&[Real]>,
    y: &[Real],
    y_new: &[Real],
    scale: impl Fn(usize, Real, Real) -> Real,
) -> (Real, Real) {
    let (e, y, y_new) = (&e[..n], &y[..n], &y_new[..n]);
    let (mut s5, mut s3) = (0.0, 0.0);
    if let Some(e3) = e3 {
        let e3 = &e3[..n];
        for i in 0..n {
            let sc = scale(i, y[i], y_new[i]);
            let (a, b) = (scaled(e[i], sc), scaled(e3[i], sc));
            s5 += a * a;
            s3 += b * b;
        }
    } else {
        for i in 0..n {
            let v = scaled(e[i], scale(i, y[i], y_new[i]));
            s5 += v * v;
        }
    }
    (s5, s3)
}

/// An error over its scale; with no tolerance at all (atol = 0 and y = 0), no error is 0, not
/// 0/0, and any error is too large.
#[inline]
fn scaled(e: Real, sc: Real) -> Real {
    if sc > 0.0 {
        e / sc
    } else if e == 0.0 {
        0.0
    } else {
        Real::INFINITY
    }
}

/// ln 1e-2 and ln 1e-4: the floors of the remembered errors.
const LN_1E_2: Real = -4.605_170_185_988_091;
const LN_1E_4: Real = -9.210_340_371_976_182;

fn next_up(x: Real) -> Real {
    if x.is_nan() || x == Real::INFINITY {
        return x;
    }
    Real::from_bits(x.to_bits() + 1)
}
