//! Forward Euler: `y_{n+1} = y_n + h f(t_n, y_n)`. First order; the method of the course's
//! first loops (Euler 1768).

use super::state::State;
use super::stepper::{IntegrateError, Provided, StepInfo, Stepper};
use super::system::OdeSystem;
use crate::Real;

/// Forward (explicit) Euler.
#[derive(Debug, Clone, Default)]
pub struct Euler {
    dydt: Vec<Real>,
    provided: Provided,
}

impl Euler {
    /// A new stepper.
    pub fn new() -> Self {
        Self::default()
    }
}

impl<S: OdeSystem + ?Sized> Stepper<S> for Euler {
    fn name(&self) -> &'static str {
        "euler"
    }

    fn order(&self) -> u32 {
        1
    }

    fn step(&mut self, sys: &S, state: &mut State, h: Real) -> Result<StepInfo, IntegrateError> {
        let (dydt, evaluations) = if self.provided.take(state.t) {
            (&self.provided.dydt, 0)
        } else {
            self.dydt.resize(state.y.len(), 0.0);
            sys.rhs_into(state.t, &state.y, &mut self.dydt);
            (&self.dydt, 1)
        };
        for (y, d) in state.y.iter_mut().zip(dydt) {
            *y += h * d;
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
