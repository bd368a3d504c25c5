//! Explicit Runge-Kutta methods driven by a [`Tableau`]: the stage computation shared by the
//! fixed-step stepper here and the adaptive one in [`super::adaptive`].

use super::state::State;
use super::stepper::{IntegrateError, Provided, StepInfo, Stepper};
use super::system::OdeSystem;
use super::tableau::Tableau;
use crate::Real;

/// Stage buffers for a tableau.
#[derive(Debug, Clone)]
pub(crate) struct Stages {
    /// `k[i]`: the stage derivatives; one more than the stages for first-same-as-last pairs,
    /// three more for DOP853's dense output.
    pub k: Vec<Vec<Real>>,
    pub tmp: Vec<Real>,
    pub provided: Provided,
}

impl Stages {
    pub fn new() -> Self {
        Self {
            k: Vec::new(),
            tmp: Vec::new(),
            provided: Provided::default(),
        }
    }

    pub fn resize(&mut self, count: usize, n: usize) {
        if self.k.len() < count {
            self.k.resize(count, Vec::new());
        }
        for k in &mut self.k {
            k.resize(n, 0.0);
        }
        self.tmp.resize(n, 0.0);
    }

    /// Computes the stages of `tab` from `(t, y)` with step `h`, and the new solution into
    /// `y_new`. Returns the evaluations made. `k[0]` must already hold `f(t, y)` when
    /// `k0_known`.
    #[allow(clippy::too_many_arguments)]
    pub fn compute<S: OdeSystem + ?Sized>(
        &mut self,
        tab: &Tableau,
        sys: &S,
        t: Real,
        y: &[Real],
        h: Real,
        y_new: &mut [Real],
        k0_known: bool,
    ) -> usize {
        let s = tab.stages();
        let mut evaluations = 0;
        if !k0_known {
            sys.rhs_into(t, y, &mut self.k[0]);
            evaluations += 1;
        }
        for i in 1..s {
            self.tmp.copy_from_slice(y);
            for (l, a) in tab.a[i].iter().enumerate() {
                if *a != 0.0 {
                    let ha = h * a;
                    for (t, k) in self.tmp.iter_mut().zip(&self.k[l]) {
                        *t += ha * k;
                    }
                }
            }
            let (_, tail) = self.k.split_at_mut(i);
            sys.rhs_into(t + tab.c[i] * h, &self.tmp, &mut tail[0]);
            evaluations += 1;
        }
        y_new.copy_from_slice(y);
        for (l, b) in tab.b.iter().enumerate() {
            if *b != 0.0 {
                let hb = h * b;
                for (yn, k) in y_new.iter_mut().zip(&self.k[l]) {
                    *yn += hb * k;
                }
            }
        }
        evaluations
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
    y_new: Vec<Real>,
}

impl ExplicitRk {
    /// A stepper for `tableau` (which must be valid).
    pub fn new(tableau: Tableau) -> Self {
        tableau.validate().unwrap_or_else(|e| panic!("{e}"));
        Self {
            tableau,
            stages: Stages::new(),
            y_new: Vec::new(),
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
        self.y_new.resize(n, 0.0);
        let known = self.stages.provided.take(state.t);
        if known {
            self.stages.k[0].copy_from_slice(&self.stages.provided.dydt);
        }
        let evaluations = self.stages.compute(
            &self.tableau,
            sys,
            state.t,
            &state.y,
            h,
            &mut self.y_new,
            known,
        );
        state.y.copy_from_slice(&self.y_new);
        state.t += h;
        Ok(StepInfo { evaluations })
    }

    fn reset(&mut self) {
        self.stages.provided.clear();
    }

    fn provide_derivative(&mut self, t: Real, dydt: &[Real]) {
        self.stages.provided.set(t, dydt);
    }
}
