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

    /// Computes the stages of `tab` from `(t, y)` with step `h`, and the increment
    /// `h Σ b_i k_i` of the solution into `dy`. Returns the evaluations made. `k[0]` must
    /// already hold `f(t, y)` when `k0_known`. The small terms are summed before they are added
    /// to `y`, which keeps round-off at the level of `y`'s last bit.
    #[allow(clippy::too_many_arguments)]
    pub fn compute<S: OdeSystem + ?Sized>(
        &mut self,
        tab: &Tableau,
        sys: &S,
        t: Real,
        y: &[Real],
        h: Real,
        dy: &mut [Real],
        k0_known: bool,
    ) -> usize {
        let s = tab.stages();
        let mut evaluations = 0;
        if !k0_known {
            sys.rhs_into(t, y, &mut self.k[0]);
            evaluations += 1;
        }
        for i in 1..s {
            weighted_sum(&self.k, &tab.a[i], h, &mut self.tmp);
            for (t, y) in self.tmp.iter_mut().zip(y) {
                *t += y;
            }
            let (_, tail) = self.k.split_at_mut(i);
            sys.rhs_into(t + tab.c[i] * h, &self.tmp, &mut tail[0]);
            evaluations += 1;
        }
        weighted_sum(&self.k, &tab.b, h, dy);
        evaluations
    }
}

/// `out = h Σ_l w_l k_l`.
fn weighted_sum(k: &[Vec<Real>], w: &[Real], h: Real, out: &mut [Real]) {
    out.fill(0.0);
    for (l, wl) in w.iter().enumerate() {
        if *wl != 0.0 {
            for (o, kl) in out.iter_mut().zip(&k[l]) {
                *o += wl * kl;
            }
        }
    }
    for o in out.iter_mut() {
        *o *= h;
    }
}

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
            tableau,
            stages: Stages::new(),
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
            &mut self.dy,
            known,
        );
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
