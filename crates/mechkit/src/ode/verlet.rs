//! Velocity Verlet (Swope, Andersen, Berens & Wilson, J. Chem. Phys. 76, 637 (1982)):
//!
//! ```text
//! q_{n+1} = q_n + h v_n + h²/2 a_n
//! v_{n+1} = v_n + h/2 (a_n + a_{n+1})
//! ```
//!
//! Second order and symplectic for forces of position only; one evaluation per step, the end
//! acceleration being reused as the next start. With velocity-dependent forces `a_{n+1}` is
//! evaluated at the predicted velocity `v_n + h a_n`, which keeps second order, and nothing is
//! reused.

use super::state::State;
use super::stepper::{IntegrateError, Provided, StepInfo, Stepper};
use super::system::SecondOrderSystem;
use crate::Real;

/// Velocity Verlet for second-order systems.
#[derive(Debug, Clone, Default)]
pub struct VelocityVerlet {
    a0: Vec<Real>,
    a1: Vec<Real>,
    v_pred: Vec<Real>,
    /// `a0` holds the acceleration at this time (and the unchanged state since).
    cached_t: Option<Real>,
    provided: Provided,
}

impl VelocityVerlet {
    /// A new stepper.
    pub fn new() -> Self {
        Self::default()
    }
}

impl<S: SecondOrderSystem + ?Sized> Stepper<S> for VelocityVerlet {
    fn name(&self) -> &'static str {
        "verlet"
    }

    fn order(&self) -> u32 {
        2
    }

    fn reset(&mut self) {
        self.cached_t = None;
        self.provided.clear();
    }

    fn provide_derivative(&mut self, t: Real, dydt: &[Real]) {
        self.provided.set(t, dydt);
    }

    fn step(&mut self, sys: &S, state: &mut State, h: Real) -> Result<StepInfo, IntegrateError> {
        let n = sys.dof();
        self.a0.resize(n, 0.0);
        self.a1.resize(n, 0.0);
        self.v_pred.resize(n, 0.0);
        let velocity_dependent = sys.velocity_dependent();
        let t = state.t;
        let (q, v) = state.qv_mut();
        let mut evaluations = 0;
        if self.provided.take(t) {
            // exact at the true state, so good for velocity-dependent forces too
            self.a0.copy_from_slice(&self.provided.dydt[n..]);
        } else if self.cached_t != Some(t) || velocity_dependent {
            sys.accel_into(t, q, v, &mut self.a0);
            evaluations += 1;
        }
        for i in 0..n {
            q[i] += h * v[i] + 0.5 * h * h * self.a0[i];
            self.v_pred[i] = v[i] + h * self.a0[i];
        }
        sys.accel_into(t + h, q, &self.v_pred, &mut self.a1);
        evaluations += 1;
        for ((vi, a0), a1) in v.iter_mut().zip(&self.a0).zip(&self.a1) {
            *vi += 0.5 * h * (a0 + a1);
        }
        std::mem::swap(&mut self.a0, &mut self.a1);
        state.t += h;
        self.cached_t = Some(state.t);
        Ok(StepInfo { evaluations })
    }
}
