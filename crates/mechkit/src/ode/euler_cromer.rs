//! Euler-Cromer (semi-implicit Euler), exactly as the course teaches it: first the velocity
//! with the acceleration at the start of the step, then the position with the *new* velocity:
//!
//! ```text
//! v_{n+1} = v_n + h a(t_n, q_n, v_n)
//! q_{n+1} = q_n + h v_{n+1}
//! ```
//!
//! First order, but symplectic: for an oscillator the energy error stays bounded instead of
//! growing as with forward Euler (Cromer, Am. J. Phys. 49, 455 (1981)).

use super::state::State;
use super::stepper::{IntegrateError, Provided, StepInfo, Stepper};
use super::system::SecondOrderSystem;
use crate::Real;

/// Euler-Cromer for second-order systems.
#[derive(Debug, Clone, Default)]
pub struct EulerCromer {
    a: Vec<Real>,
    provided: Provided,
}

impl EulerCromer {
    /// A new stepper.
    pub fn new() -> Self {
        Self::default()
    }
}

impl<S: SecondOrderSystem + ?Sized> Stepper<S> for EulerCromer {
    fn name(&self) -> &'static str {
        "euler-cromer"
    }

    fn order(&self) -> u32 {
        1
    }

    fn step(&mut self, sys: &S, state: &mut State, h: Real) -> Result<StepInfo, IntegrateError> {
        let n = sys.dof();
        let t = state.t;
        let (q, v) = state.qv_mut();
        let (a, evaluations) = if self.provided.take(t) {
            (&self.provided.dydt[n..], 0)
        } else {
            self.a.resize(n, 0.0);
            sys.accel_into(t, q, v, &mut self.a);
            (&self.a[..], 1)
        };
        for i in 0..n {
            v[i] += h * a[i];
            q[i] += h * v[i];
        }
        state.t += h;
        Ok(StepInfo { evaluations })
    }

    fn reset(&mut self) {
        self.provided.clear();
    }

    fn provide_derivative(&mut self, t: Real, dydt: &[Real]) {
        self.provided.set(t, dydt);
    }
}
