//! The integrators behind [`super::SpinningBody::simulate`] behind one interface: a step, the
//! interpolant inside the last step (dense output, or cubic Hermite for fixed steps), and the
//! derivative after the quaternion was renormalised.

use super::body::Attitude;
use super::equations::SpinEquations;
use super::error::Free3dError;
use super::splitting::split_step;
use crate::Real;
use crate::ode::{AdaptiveRk, ExplicitRk, OdeSystem, State, StepPolynomial, Stepper, hermite};

/// The integrator in use and what it needs to interpolate inside its last step.
pub(super) enum Driver {
    Adaptive(Box<AdaptiveRk>),
    Fixed {
        rk: Box<ExplicitRk>,
        clock: Clock,
        window: Window,
    },
    Splitting {
        clock: Clock,
        window: Window,
    },
}

/// `n` equal steps over `[0, t_end]`, the `k`-th ending exactly at `t_end k/n`.
pub(super) struct Clock {
    pub(super) n: usize,
    pub(super) k: usize,
    pub(super) t_end: Real,
}

impl Clock {
    fn next(&mut self) -> Real {
        self.k += 1;
        if self.k >= self.n {
            self.t_end
        } else {
            self.t_end * self.k as Real / self.n as Real
        }
    }
}

/// Values and derivatives at both ends of the last fixed step (cubic Hermite between them).
#[derive(Default)]
pub(super) struct Window {
    t0: Real,
    h: Real,
    y0: Vec<Real>,
    f0: Vec<Real>,
    y1: Vec<Real>,
    f1: Vec<Real>,
}

impl Driver {
    pub(super) fn interpolate(&mut self, eq: &SpinEquations, t: Real, out: &mut [Real]) {
        match self {
            Driver::Adaptive(rk) => rk.dense_into(eq, t, out),
            Driver::Fixed { window, .. } | Driver::Splitting { window, .. } => {
                let w = window;
                let s = if w.h == 0.0 { 1.0 } else { (t - w.t0) / w.h };
                for (i, o) in out.iter_mut().enumerate() {
                    *o = hermite(w.y0[i], w.f0[i], w.y1[i], w.f1[i], w.h, s);
                }
            }
        }
    }

    /// The interpolant of the last step as a polynomial per component (the same one
    /// [`Driver::interpolate`] reads), for enclosures of the motion inside the step.
    pub(super) fn step_polynomial(&mut self, eq: &SpinEquations, out: &mut StepPolynomial) {
        match self {
            Driver::Adaptive(rk) => rk.dense_polynomial_into(eq, out),
            Driver::Fixed { window, .. } | Driver::Splitting { window, .. } => {
                let w = window;
                out.reset(w.t0, w.h, w.y0.len(), 4);
                for i in 0..w.y0.len() {
                    out.set_hermite(i, (w.y0[i], w.f0[i]), (w.y1[i], w.f1[i]));
                }
            }
        }
    }

    /// One step from `state` towards `t_end`; returns the evaluations it made.
    pub(super) fn step(
        &mut self,
        eq: &SpinEquations,
        state: &mut State,
        t_end: Real,
    ) -> Result<u64, Free3dError> {
        match self {
            Driver::Adaptive(rk) => {
                let before = rk.stats().evaluations;
                rk.step(eq, state, t_end)?;
                Ok(rk.stats().evaluations - before)
            }
            Driver::Fixed { rk, clock, window } => {
                let t_next = clock.next();
                window.begin(state, t_next - state.t);
                Stepper::<SpinEquations>::provide_derivative(rk.as_mut(), state.t, &window.f0);
                let info = rk
                    .step(eq, state, t_next - state.t)
                    .expect("a positive finite step was checked");
                state.t = t_next;
                window.end(eq, state);
                Ok(info.evaluations as u64 + 1)
            }
            Driver::Splitting { clock, window } => {
                let t_next = clock.next();
                let h = t_next - state.t;
                window.begin(state, h);
                let a = eq.formulation().attitude(&state.y);
                let (mut q, mut lb) = (a.q, a.l_body());
                split_step(eq.body(), &mut q, &mut lb, h);
                let next = Attitude { q, l: q * lb };
                state.y = eq.formulation().to_state(&next);
                state.t = t_next;
                window.end(eq, state);
                Ok(1)
            }
        }
    }

    /// After the state's quaternion was scaled by `c` (renormalisation): the derivative at
    /// the new state. `dq/dt` is homogeneous of degree 1 in `q` and `dL/dt` of degree 0, so
    /// the fixed-step windows scale theirs; the adaptive pair is handed a fresh evaluation.
    pub(super) fn rescaled(&mut self, eq: &SpinEquations, state: &State, c: Real) -> u64 {
        match self {
            Driver::Adaptive(rk) => {
                let mut f = vec![0.0; 7];
                eq.rhs_into(state.t, &state.y, &mut f);
                rk.provide_derivative(state.t, &f);
                1
            }
            Driver::Fixed { window, .. } | Driver::Splitting { window, .. } => {
                window.y1.clone_from(&state.y);
                for f in &mut window.f1[..4] {
                    *f *= c;
                }
                0
            }
        }
    }
}

impl Window {
    /// A window whose end is the start state (the first step begins there).
    pub(super) fn new(eq: &SpinEquations, state: &State) -> Self {
        let mut w = Window {
            t0: state.t,
            y1: state.y.clone(),
            f1: vec![0.0; state.y.len()],
            ..Window::default()
        };
        eq.rhs_into(state.t, &state.y, &mut w.f1);
        w
    }

    fn begin(&mut self, state: &State, h: Real) {
        std::mem::swap(&mut self.y0, &mut self.y1);
        std::mem::swap(&mut self.f0, &mut self.f1);
        self.t0 = state.t;
        self.h = h;
    }

    fn end(&mut self, eq: &SpinEquations, state: &State) {
        self.y1.clone_from(&state.y);
        self.f1.resize(state.y.len(), 0.0);
        eq.rhs_into(state.t, &state.y, &mut self.f1);
    }
}
