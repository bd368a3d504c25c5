//! The classical fourth-order Runge-Kutta method (Kutta 1901):
//!
//! ```text
//! k1 = f(t, y)            k2 = f(t + h/2, y + h/2 k1)
//! k3 = f(t + h/2, y + h/2 k2)   k4 = f(t + h, y + h k3)
//! y_{n+1} = y_n + h/6 (k1 + 2 k2 + 2 k3 + k4)
//! ```

use super::state::State;
use super::stepper::{IntegrateError, Provided, StepInfo, Stepper};
use super::system::OdeSystem;
use crate::Real;

/// Classical RK4.
#[derive(Debug, Clone, Default)]
pub struct Rk4 {
    k: [Vec<Real>; 4],
    tmp: Vec<Real>,
    provided: Provided,
}

impl Rk4 {
    /// A new stepper.
    pub fn new() -> Self {
        Self::default()
    }
}

impl<S: OdeSystem + ?Sized> Stepper<S> for Rk4 {
    fn name(&self) -> &'static str {
        "rk4"
    }

    fn order(&self) -> u32 {
        4
    }

    fn step(&mut self, sys: &S, state: &mut State, h: Real) -> Result<StepInfo, IntegrateError> {
        let n = state.y.len();
        for k in &mut self.k {
            k.resize(n, 0.0);
        }
        self.tmp.resize(n, 0.0);
        let t = state.t;
        let [k1, k2, k3, k4] = &mut self.k;
        let y = &state.y;
        let mut evaluations = 3;
        if self.provided.take(t) {
            k1.copy_from_slice(&self.provided.dydt);
        } else {
            sys.rhs_into(t, y, k1);
            evaluations += 1;
        }
        for i in 0..n {
            self.tmp[i] = y[i] + 0.5 * h * k1[i];
        }
        sys.rhs_into(t + 0.5 * h, &self.tmp, k2);
        for i in 0..n {
            self.tmp[i] = y[i] + 0.5 * h * k2[i];
        }
        sys.rhs_into(t + 0.5 * h, &self.tmp, k3);
        for i in 0..n {
            self.tmp[i] = y[i] + h * k3[i];
        }
        sys.rhs_into(t + h, &self.tmp, k4);
        for i in 0..n {
            state.y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
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
