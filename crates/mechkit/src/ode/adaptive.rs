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

use thiserror::Error;

use super::explicit_rk::Stages;
use super::state::State;
use super::system::OdeSystem;
use super::tableau::{DenseKind, Tableau};
use crate::Real;

/// A tolerance: the same for every component, or one per component.
#[derive(Debug, Clone, PartialEq)]
pub enum Tolerance {
    /// One value for all components.
    Scalar(Real),
    /// One value per component.
    PerComponent(Vec<Real>),
}

impl Tolerance {
    fn at(&self, i: usize) -> Real {
        match self {
            Tolerance::Scalar(v) => *v,
            Tolerance::PerComponent(v) => v[i],
        }
    }

    fn values(&self) -> Vec<Real> {
        match self {
            Tolerance::Scalar(v) => vec![*v],
            Tolerance::PerComponent(v) => v.clone(),
        }
    }
}

/// The step-size controller: `h_new = h · clamp(safety · err^(−α) · err_prev^β, min_factor,
/// max_factor)` with `α = 1/(q+1) − 0.75 β` for an error estimator of order `q`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Controller {
    /// Safety factor (below 1).
    pub safety: Real,
    /// Weight of the previous error (0: the classical I controller).
    pub beta: Real,
    /// Smallest ratio of successive steps.
    pub min_factor: Real,
    /// Largest ratio of successive steps.
    pub max_factor: Real,
    /// Also apply Gustafsson's predictive limit `safety · (h/h_prev) · (err_prev/err²)^(1/(q+1))`
    /// (as in Hairer's `radau5`), which shortens steps early when the error is growing and so
    /// avoids rejections.
    pub predictive: bool,
}

impl Controller {
    /// The default for a tableau. Chosen by the work-precision study in
    /// `benches/work_precision.rs` (Kepler e = 0.5 and 0.9, Arenstorf): Gustafsson's
    /// predictive limit on top of the classical controller saves 10-30 % of the evaluations at
    /// equal error, because the few rejections per orbit disappear. DOP853 uses the I
    /// controller (β = 0, as in Hairer's `dop853`), the others a light PI term (β = 0.02).
    pub fn for_tableau(tableau: &Tableau) -> Controller {
        let beta = if matches!(tableau.dense, DenseKind::Dop853) {
            0.0
        } else {
            0.02
        };
        Controller {
            safety: 0.9,
            beta,
            min_factor: 0.2,
            max_factor: 10.0,
            predictive: true,
        }
    }
}

/// Settings of an adaptive run.
#[derive(Debug, Clone, PartialEq)]
pub struct AdaptiveConfig {
    /// Relative tolerance.
    pub rtol: Tolerance,
    /// Absolute tolerance.
    pub atol: Tolerance,
    /// Smallest step allowed (`None`: ten units in the last place of `t`).
    pub h_min: Option<Real>,
    /// Largest step allowed.
    pub h_max: Real,
    /// First step (`None`: chosen automatically).
    pub h0: Option<Real>,
    /// How many leading components the error control looks at (`None`: all); the rest (a
    /// work integral, say) ride along.
    pub error_components: Option<usize>,
    /// The step-size controller (`None`: the method's usual one, [`Controller::for_tableau`]).
    pub controller: Option<Controller>,
}

impl Default for AdaptiveConfig {
    /// `rtol = 1e-6`, `atol = 1e-9`, no step limits.
    fn default() -> Self {
        Self {
            rtol: Tolerance::Scalar(1e-6),
            atol: Tolerance::Scalar(1e-9),
            h_min: None,
            h_max: Real::INFINITY,
            h0: None,
            error_components: None,
            controller: None,
        }
    }
}

/// Invalid adaptive settings.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ConfigError {
    /// `rtol` not positive.
    #[error("rtol must be positive and finite, not {0}")]
    Rtol(Real),
    /// `atol` negative.
    #[error("atol must be zero or positive and finite, not {0}")]
    Atol(Real),
    /// Per-component tolerance of the wrong length.
    #[error("{what} has {got} components, the system has {want}")]
    Length {
        /// Which tolerance.
        what: &'static str,
        /// Given.
        got: usize,
        /// Needed.
        want: usize,
    },
    /// A step limit that is not positive.
    #[error("{what} must be positive, not {value}")]
    Step {
        /// Which limit.
        what: &'static str,
        /// Its value.
        value: Real,
    },
    /// The method has no error estimator.
    #[error("the method {0} has no error estimator; use a fixed step")]
    NotAdaptive(&'static str),
}

impl AdaptiveConfig {
    /// Checks the tolerances and limits for a system of `n` components.
    pub fn validate(&self, n: usize) -> Result<(), ConfigError> {
        for r in self.rtol.values() {
            if !(r > 0.0 && r.is_finite()) {
                return Err(ConfigError::Rtol(r));
            }
        }
        for a in self.atol.values() {
            if !(a >= 0.0 && a.is_finite()) {
                return Err(ConfigError::Atol(a));
            }
        }
        for (what, t) in [("rtol", &self.rtol), ("atol", &self.atol)] {
            if let Tolerance::PerComponent(v) = t {
                let want = self.error_components.unwrap_or(n);
                if v.len() != want {
                    return Err(ConfigError::Length {
                        what,
                        got: v.len(),
                        want,
                    });
                }
            }
        }
        for (what, v) in [
            ("h_min", self.h_min),
            ("h0", self.h0),
            ("h_max", Some(self.h_max)),
        ] {
            if let Some(v) = v
                && (v.is_nan() || v <= 0.0)
            {
                return Err(ConfigError::Step { what, value: v });
            }
        }
        Ok(())
    }
}

/// Counters of an adaptive run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct AdaptiveStats {
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
}

/// Why an adaptive step could not be taken.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum AdaptiveError {
    /// The step size fell below its minimum.
    #[error(
        "the step size fell to {h:e} at t = {t} (minimum {h_min:e}); the error is dominated by component {component}{}",
        if *non_finite { " whose derivative is not finite" } else { "" }
    )]
    StepTooSmall {
        /// Time.
        t: Real,
        /// The step that was refused.
        h: Real,
        /// The minimum.
        h_min: Real,
        /// Index of the component with the largest scaled error.
        component: usize,
        /// Whether a stage produced non-finite values.
        non_finite: bool,
    },
}

/// An adaptive Runge-Kutta integrator for a tableau with an error estimator.
#[derive(Debug, Clone)]
pub struct AdaptiveRk {
    tableau: Tableau,
    config: AdaptiveConfig,
    stages: Stages,
    y_new: Vec<Real>,
    h: Option<Real>,
    err_prev: Real,
    err_acc: Real,
    /// No step accepted since the start or a restart (the predictive limit needs one).
    fresh: bool,
    controller: Controller,
    stats: AdaptiveStats,
    /// The last accepted step: start time, size, start state (for dense output).
    last_t0: Real,
    last_h: Real,
    last_y0: Vec<Real>,
    last_y1: Vec<Real>,
    dense_ready: bool,
    dense: Vec<Vec<Real>>,
    /// `k[0]` holds `f(t, y)` of the current state at this time.
    k0_at: Option<Real>,
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
        Ok(Self {
            tableau,
            config,
            stages: Stages::new(),
            y_new: Vec::new(),
            h: None,
            err_prev: 1e-4,
            err_acc: 1e-2,
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

    /// The step size the next step will try.
    pub fn next_step(&self) -> Option<Real> {
        self.h
    }

    /// Forgets the step size history and cached derivatives (after the state was changed
    /// from outside, e.g. by an event).
    pub fn reset(&mut self) {
        self.h = None;
        self.err_prev = 1e-4;
        self.err_acc = 1e-2;
        self.k0_at = None;
        self.fresh = true;
    }

    /// Hands the integrator `f(t, y)` of the state the next step starts from.
    pub fn provide_derivative(&mut self, t: Real, dydt: &[Real]) {
        if self.stages.k.is_empty() {
            self.stages.k.push(Vec::new());
        }
        self.stages.k[0].clear();
        self.stages.k[0].extend_from_slice(dydt);
        self.k0_at = Some(t);
    }

    fn scale(&self, i: usize, a: Real, b: Real) -> Real {
        self.config.atol.at(i) + self.config.rtol.at(i) * a.abs().max(b.abs())
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
        f0: &[Real],
        t_bound: Real,
    ) -> Real {
        let n = self.controlled(y.len());
        let rms = |v: &dyn Fn(usize) -> Real| {
            ((0..n).map(|i| v(i) * v(i)).sum::<Real>() / n as Real).sqrt()
        };
        let d0 = rms(&|i| y[i] / self.scale(i, y[i], y[i]));
        let d1 = rms(&|i| f0[i] / self.scale(i, y[i], y[i]));
        let span = (t_bound - t).abs();
        let mut h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        h0 = h0.min(self.config.h_max).min(span);
        let mut y1 = vec![0.0; y.len()];
        for i in 0..y.len() {
            y1[i] = y[i] + h0 * f0[i];
        }
        let mut f1 = vec![0.0; y.len()];
        sys.rhs_into(t + h0, &y1, &mut f1);
        self.stats.evaluations += 1;
        let d2 = rms(&|i| (f1[i] - f0[i]) / self.scale(i, y[i], y[i])) / h0;
        let q = Real::from(self.tableau.error_order.unwrap_or(1));
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(1.0 / (q + 1.0))
        };
        (100.0 * h0).min(h1).min(self.config.h_max).min(span)
    }

    /// Takes one accepted step from `state` towards `t_bound` (never past it), retrying
    /// rejected attempts with smaller steps. Returns the accepted step size.
    pub fn step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        state: &mut State,
        t_bound: Real,
    ) -> Result<Real, AdaptiveError> {
        let n = state.y.len();
        let extra = match self.tableau.dense {
            DenseKind::Dop853 => 3,
            _ => 0,
        };
        self.stages.resize(self.tableau.stages() + 1 + extra, n);
        self.y_new.resize(n, 0.0);
        let t = state.t;
        if self.stats.accepted > 0
            && self.k0_at == Some(self.last_t0)
            && t == self.last_t0 + self.last_h
        {
            self.roll_fsal();
        }
        if self.k0_at != Some(t) {
            sys.rhs_into(t, &state.y, &mut self.stages.k[0]);
            self.stats.evaluations += 1;
            self.k0_at = Some(t);
        }
        if self.h.is_none() {
            let f0 = self.stages.k[0].clone();
            let h = match self.config.h0 {
                Some(h0) => h0.min(self.config.h_max),
                None => self.initial_step(sys, t, &state.y, &f0, t_bound),
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
        let expo = 1.0 / (q + 1.0) - 0.75 * beta;
        let s = self.tableau.stages();
        loop {
            let remaining = t_bound - t;
            let last = h >= remaining;
            if last {
                h = remaining;
            }
            if h < h_min && !last {
                let component = self.dominant_component(&state.y);
                return Err(AdaptiveError::StepTooSmall {
                    t,
                    h,
                    h_min,
                    component,
                    non_finite: self
                        .stages
                        .k
                        .iter()
                        .any(|k| k.iter().any(|v| !v.is_finite())),
                });
            }
            let evals =
                self.stages
                    .compute(&self.tableau, sys, t, &state.y, h, &mut self.y_new, true);
            self.stats.evaluations += evals as u64;
            for (yn, y) in self.y_new.iter_mut().zip(&state.y) {
                *yn += y;
            }
            // f at the new point: the error of first-same-as-last pairs needs it, and it
            // starts the next step
            let t_new = if last { t_bound } else { t + h };
            {
                let (_, tail) = self.stages.k.split_at_mut(s);
                sys.rhs_into(t_new, &self.y_new, &mut tail[0]);
            }
            self.stats.evaluations += 1;
            let err = self.error_norm(h, &state.y);
            if err <= 1.0 {
                self.stats.accepted += 1;
                let fac = err.max(1e-10).powf(-expo) * self.err_prev.powf(beta);
                let mut fac = (safety * fac).clamp(min_factor, max_factor);
                if predictive && !self.fresh && self.last_h > 0.0 {
                    let e = err.max(1e-10);
                    let pred =
                        safety * (h / self.last_h) * (self.err_acc / (e * e)).powf(1.0 / (q + 1.0));
                    fac = fac.min(pred.max(min_factor));
                }
                self.err_acc = err.max(1e-2);
                self.fresh = false;
                let mut h_next = h * fac;
                if rejected_before {
                    h_next = h_next.min(h);
                }
                self.err_prev = err.max(1e-4);
                self.h = Some(h_next.min(self.config.h_max));
                self.last_t0 = t;
                self.last_h = t_new - t;
                self.last_y0.clone_from(&state.y);
                self.last_y1.clone_from(&self.y_new);
                self.dense_ready = false;
                state.y.copy_from_slice(&self.y_new);
                state.t = t_new;
                return Ok(self.last_h);
            }
            self.stats.rejected += 1;
            rejected_before = true;
            let fac = if err.is_finite() {
                (safety * err.powf(-expo)).clamp(min_factor, 1.0)
            } else {
                min_factor
            };
            h *= fac;
        }
    }

    /// After an accepted step, `k[s]` (the derivative at the new point) becomes `k[0]` of the
    /// next; done lazily so that dense output can still use the last step's stages.
    fn roll_fsal(&mut self) {
        let s = self.tableau.stages();
        let (head, tail) = self.stages.k.split_at_mut(s);
        head[0].copy_from_slice(&tail[0]);
        self.k0_at = Some(self.last_t0 + self.last_h);
    }

    fn error_norm(&self, h: Real, y: &[Real]) -> Real {
        let n = self.controlled(y.len());
        let k = &self.stages.k;
        let weighted =
            |w: &[Real], i: usize| -> Real { w.iter().enumerate().map(|(l, e)| e * k[l][i]).sum() };
        if matches!(self.tableau.dense, DenseKind::Dop853) {
            let (mut e5, mut e3) = (0.0, 0.0);
            for i in 0..n {
                let sc = self.scale(i, y[i], self.y_new[i]);
                let a = weighted(&self.tableau.e, i) / sc;
                let b = weighted(&self.tableau.e3, i) / sc;
                e5 += a * a;
                e3 += b * b;
            }
            let den = e5 + 0.01 * e3;
            if den == 0.0 {
                return 0.0;
            }
            let v = h.abs() * e5 / (den * n as Real).sqrt();
            if v.is_nan() { Real::INFINITY } else { v }
        } else {
            let mut sum = 0.0;
            for i in 0..n {
                let e = h * weighted(&self.tableau.e, i) / self.scale(i, y[i], self.y_new[i]);
                sum += e * e;
            }
            let v = (sum / n as Real).sqrt();
            if v.is_nan() { Real::INFINITY } else { v }
        }
    }

    fn dominant_component(&self, y: &[Real]) -> usize {
        let n = self.controlled(y.len());
        let k = &self.stages.k;
        (0..n)
            .max_by(|&a, &b| {
                let e = |i: usize| {
                    let v: Real = self
                        .tableau
                        .e
                        .iter()
                        .enumerate()
                        .map(|(l, w)| w * k[l][i])
                        .sum::<Real>()
                        / self.scale(i, y[i], self.y_new[i]);
                    if v.is_nan() { Real::INFINITY } else { v.abs() }
                };
                e(a).total_cmp(&e(b))
            })
            .unwrap_or(0)
    }

    /// The start and end time of the last accepted step.
    pub fn last_step(&self) -> (Real, Real) {
        (self.last_t0, self.last_t0 + self.last_h)
    }

    /// The state at time `t` inside the last accepted step, by the method's dense output.
    pub fn dense_into<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: Real, out: &mut [Real]) {
        let h = self.last_h;
        let theta = if h == 0.0 {
            1.0
        } else {
            (t - self.last_t0) / h
        };
        let n = out.len();
        let s = self.tableau.stages();
        match &self.tableau.dense {
            DenseKind::Polynomial(p) => {
                // y0 + h Σ_i k_i Σ_j p_ij θ^(j+1)
                let powers: Vec<Real> = (1..=p[0].len()).map(|j| theta.powi(j as i32)).collect();
                let w: Vec<Real> = p
                    .iter()
                    .map(|row| row.iter().zip(&powers).map(|(c, x)| c * x).sum())
                    .collect();
                for i in 0..n {
                    let mut acc = 0.0;
                    for (l, wl) in w.iter().enumerate() {
                        acc += wl * self.stages.k[l][i];
                    }
                    out[i] = self.last_y0[i] + h * acc;
                }
            }
            DenseKind::Hermite => {
                let (k0, k1) = (&self.stages.k[0], &self.stages.k[s]);
                for i in 0..n {
                    out[i] = super::hermite::hermite(
                        self.last_y0[i],
                        k0[i],
                        self.last_y1[i],
                        k1[i],
                        h,
                        theta,
                    );
                }
            }
            DenseKind::Dop853 => {
                if !self.dense_ready {
                    self.prepare_dop853(sys);
                }
                // y0 + θ(F0 + (1-θ)(F1 + θ(F2 + (1-θ)(F3 + θ(F4 + (1-θ)(F5 + θ F6))))))
                let f = &self.dense;
                for i in 0..n {
                    let mut acc = 0.0;
                    for (m, fm) in f.iter().enumerate().rev() {
                        acc += fm[i];
                        acc *= if m % 2 == 0 { theta } else { 1.0 - theta };
                    }
                    out[i] = self.last_y0[i] + acc;
                }
            }
        }
    }

    /// DOP853's three extra stages and interpolation coefficients for the last step.
    fn prepare_dop853<S: OdeSystem + ?Sized>(&mut self, sys: &S) {
        let d = &super::dop853::DOP853;
        let n = self.last_y0.len();
        let h = self.last_h;
        let t0 = self.last_t0;
        for s in 13..16 {
            let mut y = self.last_y0.clone();
            for (l, a) in d.a[s][..s].iter().enumerate() {
                if *a != 0.0 {
                    for i in 0..n {
                        y[i] += h * a * self.stages.k[l][i];
                    }
                }
            }
            let (_, tail) = self.stages.k.split_at_mut(s);
            sys.rhs_into(t0 + d.c[s] * h, &y, &mut tail[0]);
            self.stats.evaluations += 1;
        }
        let k = &self.stages.k;
        let mut f = vec![vec![0.0; n]; 7];
        for i in 0..n {
            let dy = self.last_y1[i] - self.last_y0[i];
            f[0][i] = dy;
            f[1][i] = h * k[0][i] - dy;
            f[2][i] = 2.0 * dy - h * (k[12][i] + k[0][i]);
            for (m, row) in d.d.iter().enumerate() {
                f[3 + m][i] = h * row
                    .iter()
                    .enumerate()
                    .map(|(l, c)| c * k[l][i])
                    .sum::<Real>();
            }
        }
        self.dense = f;
        self.dense_ready = true;
    }
}

fn next_up(x: Real) -> Real {
    if x.is_nan() || x == Real::INFINITY {
        return x;
    }
    Real::from_bits(x.to_bits() + 1)
}
