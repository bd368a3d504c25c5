//! How a run advances: fixed steps of any method, or adaptive steps of a Runge-Kutta pair; and
//! the interpolant of the last step that events and output times are read from.

use std::cell::RefCell;

use super::pair::Pair;
use super::run::{DEFAULT_MAX_STEPS, Simulation};
use crate::Real;
use crate::ode::{
    AdaptiveConfig, AdaptiveError, AdaptiveStats, Method, OdeSystem, State, StepPolynomial,
    Stepper, hermite,
};
use crate::particles::{Evaluation, ParticleSystem};

/// The step-size regime of a run.
#[derive(Debug, Clone, PartialEq)]
pub enum Stepping {
    /// Steps of `dt` (the last shortened to land on `t_max`).
    Fixed {
        /// The method.
        method: Method,
        /// The step (s).
        dt: Real,
    },
    /// Steps chosen by the error estimate of a Runge-Kutta pair or an implicit method.
    Adaptive {
        /// The method (one with [`crate::ode::MethodKind::Adaptive`] or [`crate::ode::MethodKind::Implicit`]).
        method: Method,
        /// Tolerances and limits.
        config: AdaptiveConfig,
    },
}

impl Stepping {
    /// The method.
    pub fn method(&self) -> Method {
        match self {
            Stepping::Fixed { method, .. } | Stepping::Adaptive { method, .. } => *method,
        }
    }

    /// The fixed step, if there is one.
    pub fn dt(&self) -> Option<Real> {
        match self {
            Stepping::Fixed { dt, .. } => Some(*dt),
            Stepping::Adaptive { .. } => None,
        }
    }

    /// Whether the steps are adaptive.
    pub fn is_adaptive(&self) -> bool {
        matches!(self, Stepping::Adaptive { .. })
    }

    /// For people: `rk4 with dt = 0.001 s`, `dopri5, adaptive (rtol 1e-08, atol 1e-10)`.
    pub fn describe(&self) -> String {
        let tol = |t: &crate::ode::Tolerance| match t {
            crate::ode::Tolerance::Scalar(x) => format!("{x:e}"),
            crate::ode::Tolerance::PerComponent(_) => "per component".into(),
        };
        match self {
            Stepping::Fixed { method, dt } => {
                format!("{method} with dt = {} s", crate::error::short(*dt))
            }
            Stepping::Adaptive { method, config } => format!(
                "{method}, adaptive (rtol {}, atol {})",
                tol(&config.rtol),
                tol(&config.atol)
            ),
        }
    }
}

/// The particle system with the work of each force appended to the state, `W_i' = F_i·v`, so
/// that an adaptive method integrates the energy ledger to its own order and tolerance. It
/// keeps the evaluation of its latest call (the accepted step's end, after a step) and the
/// first state at which a force was not finite.
pub(crate) struct WorkSystem<'a> {
    pub sys: &'a ParticleSystem,
    n: usize,
    nf: usize,
    last: RefCell<(Evaluation, Vec<Real>)>,
    pub bad: RefCell<Option<State>>,
}

impl<'a> WorkSystem<'a> {
    pub fn new(sys: &'a ParticleSystem) -> Self {
        Self {
            sys,
            n: crate::ode::SecondOrderSystem::dof(sys),
            nf: sys.forces().len(),
            last: RefCell::new((Evaluation::default(), Vec::new())),
            bad: RefCell::new(None),
        }
    }

    /// Swaps the evaluation of the latest call into `out`.
    pub fn take_last(&self, out: &mut Evaluation) {
        std::mem::swap(&mut self.last.borrow_mut().0, out);
    }
}

impl OdeSystem for WorkSystem<'_> {
    fn dim(&self) -> usize {
        2 * self.n + self.nf
    }

    fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]) {
        let n = self.n;
        let mut last = self.last.borrow_mut();
        let (eval, scratch) = &mut *last;
        self.sys.evaluate(t, &y[..n], &y[n..2 * n], eval, scratch);
        dydt[..n].copy_from_slice(&y[n..2 * n]);
        dydt[n..2 * n].copy_from_slice(&eval.a);
        dydt[2 * n..].copy_from_slice(&eval.power);
        if dydt.iter().any(|x| !x.is_finite()) {
            let mut bad = self.bad.borrow_mut();
            if bad.is_none() {
                *bad = Some(State::new(t, y[..2 * n].to_vec()));
            }
        }
    }
    /// `[[0, I, 0], [∂a/∂q, ∂a/∂v, 0], [0, 0, 0]]` from the system's compiled Jacobian, when
    /// it has one. The work rows are left zero: the works do not act back on the motion, so
    /// the simplified Newton iteration converges for them once it has for the motion.
    fn jacobian_into(&self, t: Real, y: &[Real], jac: &mut [Real]) -> bool {
        let n = self.n;
        let (q, v) = (&y[..n], &y[n..2 * n]);
        let mut da_dq = vec![0.0; n * n];
        let mut da_dv = vec![0.0; n * n];
        if !crate::ode::SecondOrderSystem::accel_jacobian_into(
            self.sys, t, q, v, &mut da_dq, &mut da_dv,
        ) {
            return false;
        }
        let m = self.dim();
        jac.fill(0.0);
        for i in 0..n {
            jac[i * m + n + i] = 1.0;
            let row = (n + i) * m;
            jac[row..row + n].copy_from_slice(&da_dq[i * n..(i + 1) * n]);
            jac[row + n..row + 2 * n].copy_from_slice(&da_dv[i * n..(i + 1) * n]);
        }
        true
    }

    /// `[[0, I, 0], [A, A, 0], [0, 0, 0]]` from the compiled Jacobian's structural zeros (the
    /// work rows zero, as in [`OdeSystem::jacobian_into`] above).
    fn jacobian_pattern(&self) -> Option<crate::ode::JacobianPattern> {
        crate::ode::SecondOrderSystem::accel_pattern(self.sys).map(|p| p.second_order(self.nf))
    }

    /// `[q, v]` and the works, which no derivative depends on.
    fn second_order_dof(&self) -> Option<usize> {
        Some(self.n)
    }
}

/// What advances the state: a fixed-step stepper, or the adaptive integrator with its
/// augmented state.
pub(crate) enum Engine {
    Fixed {
        stepper: Box<dyn Stepper<ParticleSystem>>,
        dt: Real,
    },
    Adaptive {
        rk: Box<Pair>,
        /// `[q, v, W]` at the current time.
        y: Vec<Real>,
        buf: Vec<Real>,
    },
}

/// The two ends of the last step, for fixed-step interpolation (cubic Hermite).
#[derive(Debug, Clone, Default)]
pub(crate) struct StepEnds {
    pub t0: Real,
    pub y0: Vec<Real>,
    pub a0: Vec<Real>,
    pub t1: Real,
    pub y1: Vec<Real>,
    pub a1: Vec<Real>,
}

impl Engine {
    pub fn new(stepping: &Stepping) -> Result<Engine, crate::ode::ConfigError> {
        Ok(match stepping {
            Stepping::Fixed { method, dt } => Engine::Fixed {
                stepper: method.stepper(),
                dt: *dt,
            },
            Stepping::Adaptive { method, config } => {
                let pair = Pair::new(*method, config)?;
                Engine::Adaptive {
                    rk: Box::new(pair),
                    y: Vec::new(),
                    buf: Vec::new(),
                }
            }
        })
    }

    /// Starts (or restarts after a state change) from `state` with the work so far. An adaptive
    /// run chooses its first step afresh: the motion after a bounce may last much shorter than
    /// the steps before it, and a step spanning all of it would hide its next crossing.
    pub fn restart(&mut self, state: &State, work: &[Real]) {
        match self {
            Engine::Fixed { stepper, .. } => stepper.reset(),
            Engine::Adaptive { rk, y, .. } => {
                rk.reset();
                y.clear();
                y.extend_from_slice(&state.y);
                y.extend_from_slice(work);
            }
        }
    }

    pub fn adaptive_stats(&self) -> Option<AdaptiveStats> {
        match self {
            Engine::Adaptive { rk, .. } => Some(rk.stats()),
            Engine::Fixed { .. } => None,
        }
    }

    /// When the explicit pair's stiffness test fired (see [`AdaptiveRk::stiff_from`]).
    pub fn stiff_from(&self) -> Option<Real> {
        match self {
            Engine::Adaptive { rk, .. } => match &**rk {
                Pair::Explicit(rk) => rk.stiff_from(),
                _ => None,
            },
            Engine::Fixed { .. } => None,
        }
    }

    /// Where `method = "auto"` switched to its implicit method.
    pub fn switched_at(&self) -> Option<Real> {
        match self {
            Engine::Adaptive { rk, .. } => match &**rk {
                Pair::Auto(auto) => auto.switched_at,
                _ => None,
            },
            Engine::Fixed { .. } => None,
        }
    }

    /// One adaptive step towards `t_bound`; the state and the work follow.
    pub fn adaptive_step(
        &mut self,
        ws: &WorkSystem<'_>,
        state: &mut State,
        work: &mut [Real],
        t_bound: Real,
    ) -> Result<(), AdaptiveError> {
        let Engine::Adaptive { rk, y, .. } = self else {
            unreachable!("adaptive_step on a fixed-step engine")
        };
        let mut aug = State::new(state.t, std::mem::take(y));
        let result = rk.step(ws, &mut aug, t_bound);
        *y = aug.y;
        let n2 = state.y.len();
        state.y.copy_from_slice(&y[..n2]);
        work.copy_from_slice(&y[n2..]);
        state.t = aug.t;
        result.map(|_| ())
    }

    /// The state (and, for adaptive runs, the work) at `t` inside the last step. Returns
    /// whether `work` was filled.
    pub fn interpolate(
        &mut self,
        ws: &WorkSystem<'_>,
        ends: &StepEnds,
        t: Real,
        y: &mut [Real],
        work: &mut Vec<Real>,
    ) -> bool {
        match self {
            Engine::Fixed { .. } => {
                let h = ends.t1 - ends.t0;
                let s = if h == 0.0 { 1.0 } else { (t - ends.t0) / h };
                let n = y.len() / 2;
                for i in 0..n {
                    y[i] = hermite(ends.y0[i], ends.y0[n + i], ends.y1[i], ends.y1[n + i], h, s);
                    y[n + i] =
                        hermite(ends.y0[n + i], ends.a0[i], ends.y1[n + i], ends.a1[i], h, s);
                }
                false
            }
            Engine::Adaptive { rk, y: aug, buf } => {
                buf.resize(aug.len(), 0.0);
                if t == ends.t1 {
                    buf.copy_from_slice(aug);
                } else {
                    rk.dense_into(ws, t, buf);
                }
                let n2 = y.len();
                y.copy_from_slice(&buf[..n2]);
                work.clear();
                work.extend_from_slice(&buf[n2..]);
                true
            }
        }
    }
}

impl Engine {
    /// The interpolant of the last step as a polynomial per component (`[q, v]`, then the
    /// work of each force in adaptive runs), the same interpolant [`Engine::interpolate`]
    /// reads, for enclosures of the motion inside the step.
    pub fn step_polynomial(
        &mut self,
        ws: &WorkSystem<'_>,
        ends: &StepEnds,
        out: &mut StepPolynomial,
    ) {
        match self {
            Engine::Fixed { .. } => {
                let n = ends.y0.len() / 2;
                out.reset(ends.t0, ends.t1 - ends.t0, 2 * n, 4);
                for i in 0..n {
                    out.set_hermite(
                        i,
                        (ends.y0[i], ends.y0[n + i]),
                        (ends.y1[i], ends.y1[n + i]),
                    );
                    out.set_hermite(
                        n + i,
                        (ends.y0[n + i], ends.a0[i]),
                        (ends.y1[n + i], ends.a1[i]),
                    );
                }
            }
            Engine::Adaptive { rk, .. } => rk.dense_polynomial_into(ws, out),
        }
    }
}

/// The largest number of steps: `max_steps`; with `t_max`, unbounded for fixed steps (their
/// count to `t_max` was bounded before the run, see [`super::check_step_bound`]) and
/// [`DEFAULT_MAX_STEPS`] for adaptive ones; else the default budget (with a warning).
pub(crate) fn step_budget(
    sim: &Simulation<'_>,
    stepping: &Stepping,
    t0: Real,
    warnings: &mut Vec<String>,
) -> u64 {
    match (sim.max_steps, sim.t_max) {
        (Some(n), _) => n,
        (None, Some(_)) if stepping.dt().is_some() => u64::MAX,
        (None, Some(_)) => DEFAULT_MAX_STEPS,
        (None, None) => {
            warnings.push(format!(
                "no t_max was given: the run is bounded by {DEFAULT_MAX_STEPS} steps{}; set t_max to choose the end",
                stepping
                    .dt()
                    .map(|dt| {
                        format!(
                            " (t = {} s with dt = {} s)",
                            crate::error::short(t0 + DEFAULT_MAX_STEPS as Real * dt),
                            crate::error::short(dt)
                        )
                    })
                    .unwrap_or_default()
            ));
            DEFAULT_MAX_STEPS
        }
    }
}

/// The end of fixed step number `k + 1` of a grid started at `origin` (landing on `t_max`).
pub(crate) fn fixed_next(
    origin: Real,
    k: u64,
    dt: Real,
    planned: Option<u64>,
    t_max: Option<Real>,
) -> Real {
    match (planned, t_max) {
        (Some(n), Some(tm)) if k + 1 >= n => tm,
        _ => origin + (k + 1) as Real * dt,
    }
}

#[cfg(test)]
#[path = "stepping_tests.rs"]
mod tests;
