//! Explicit Runge-Kutta methods driven by a [`Tableau`]: the fixed-step stepper (the stage
//! computation, shared with [`super::adaptive`], is in [`super::stages`]).

use super::stages::Stages;
use super::state::State;
use super::stepper::{IntegrateError, StepInfo, Stepper};
use super::system::OdeSystem;
use super::tableau::Tableau;
use crate::Real;

/// `y += dy` with Kahan's compensated summation: `carry` keeps the low-order bits each addition
/// loses, so that round-off over many small steps grows like √n ε rather than n ε.
pub(crate) fn compensated_add(y: &mut [Real], dy: &[Real], carry: &mut [Real]) {
    for ((yi, di), ci) in y.iter_mut().zip(dy).zip(carry.iter_mut()) {
        let d = di + *ci;
        let sum = *yi + d;
        *ci = d - (sum - *yi);
        *yi = sum;
    }
}

/// A fixed-step explicit Runge-Kutta method from any tableau (its embedded estimate unused).
///
/// # Example
/// ```
/// use mechkit::ode::{ExplicitRk, State, Stepper, Tableau};
/// use mechkit::ode::reference::Decay;
/// let decay = Decay { lambda: 1.0 };
/// let mut s = State::new(0.0, vec![1.0]);
/// ExplicitRk::new(Tableau::dopri5()).integrate(&decay, &mut s, 1.0, 0.1).unwrap();
/// assert!((s.y[0] - (-1f64).exp()).abs() < 1e-8);
/// ```
#[derive(Debug, Clone)]
pub struct ExplicitRk {
    tableau: Tableau,
    stages: Stages,
    dy: Vec<Real>,
    /// Low-order bits lost by the additions so far (compensated summation); cleared by
    /// `reset`.
    carry: Vec<Real>,
}

impl ExplicitRk {
    /// A stepper for `tableau` (which must be valid).
    pub fn new(tableau: Tableau) -> Self {
        tableau.validate().unwrap_or_else(|e| panic!("{e}"));
        Self {
            stages: Stages::new(&tableau),
            tableau,
            dy: Vec::new(),
            carry: Vec::new(),
        }
    }

    /// The tableau.
    pub fn tableau(&self) -> &Tableau {
        &self.tableau
    }
}

impl<S: OdeSystem + ?Sized> Stepper<S> for ExplicitRk {
    fn name(&self) -> &'static str {
        self.tableau.name
    }

    fn order(&self) -> u32 {
        self.tableau.order
    }

    fn step(&mut self, sys: &S, state: &mut State, h: Real) -> Result<StepInfo, IntegrateError> {
        let n = state.y.len();
        self.stages.resize(self.tableau.stages(), n);
        self.dy.resize(n, 0.0);
        if self.carry.len() != n {
            self.carry = vec![0.0; n];
        }
        let known = self.stages.take_provided(state.t);
        let evaluations = self
            .stages
            .compute(&self.tableau, sys, state.t, &state.y, h, known);
        self.stages.slope_into(&mut self.dy);
        for d in &mut self.dy {
            *d *= h;
        }
        compensated_add(&mut state.y, &self.dy, &mut self.carry);
        state.t += h;
        Ok(StepInfo { evaluations })
    }

    fn reset(&mut self) {
        self.stages.provided.clear();
        self.carry.fill(0.0);
    }

    fn provide_derivative(&mut self, t: Real, dydt: &[Real]) {
        self.stages.provided.set(t, dydt);
    }
}
