//! Explicit Runge-Kutta methods driven by a [`Tableau`]: the stage computation shared by the
//! fixed-step stepper here and the adaptive one in [`super::adaptive`].

use super::state::State;
use super::stepper::{IntegrateError, Provided, StepInfo, Stepper};
use super::system::OdeSystem;
use super::tableau::Tableau;
use crate::Real;

/// The non-zero entries of a row of coefficients: `(stage, coefficient)`.
pub(crate) type Sparse = Vec<(usize, Real)>;

/// The non-zero entries of `row`.
pub(crate) fn sparse(row: &[Real]) -> Sparse {
    row.iter()
        .copied()
        .enumerate()
        .filter(|(_, c)| *c != 0.0)
        .collect()
}

/// Stage buffers for a tableau, stored flat (`k[l]` is `k[l n .. (l + 1) n]`), with the
/// tableau's rows as lists of non-zero coefficients.
#[derive(Debug, Clone)]
pub(crate) struct Stages {
    n: usize,
    k: Vec<Real>,
    tmp: Vec<Real>,
    acc: Vec<Real>,
    rows: Vec<Sparse>,
    weights: Sparse,
    pub provided: Provided,
}

impl Stages {
    /// Buffers for `tab`'s stages plus `extra` more (the derivative at the new point, DOP853's
    /// dense-output stages).
    pub fn new(tab: &Tableau) -> Self {
        Self {
            n: 0,
            k: Vec::new(),
            tmp: Vec::new(),
            acc: Vec::new(),
            rows: tab.a.iter().map(|r| sparse(r)).collect(),
            weights: sparse(&tab.b),
            provided: Provided::default(),
        }
    }

    /// Room for `count` stage vectors of length `n`.
    pub fn resize(&mut self, count: usize, n: usize) {
        if self.n != n || self.k.len() < count * n {
            self.n = n;
            self.k.resize(count * n, 0.0);
            self.tmp.resize(n, 0.0);
            self.acc.resize(n, 0.0);
        }
    }

    /// Stage `l`.
    pub fn k(&self, l: usize) -> &[Real] {
        &self.k[l * self.n..(l + 1) * self.n]
    }

    /// Stage `l`, to write.
    pub fn k_mut(&mut self, l: usize) -> &mut [Real] {
        &mut self.k[l * self.n..(l + 1) * self.n]
    }

    /// Component `i` of stage `l`.
    #[inline]
    pub fn at(&self, l: usize, i: usize) -> Real {
        self.k[l * self.n + i]
    }

    /// Copies stage `from` into stage `to`.
    pub fn copy_stage(&mut self, from: usize, to: usize) {
        let n = self.n;
        self.k.copy_within(from * n..(from + 1) * n, to * n);
    }

    /// `out = Σ_{(l, c) in row} c k_l`.
    #[inline]
    fn combine(k: &[Real], n: usize, row: &[(usize, Real)], out: &mut [Real]) {
        let Some(((l0, c0), rest)) = row.split_first() else {
            out.fill(0.0);
            return;
        };
        for (o, kv) in out.iter_mut().zip(&k[l0 * n..(l0 + 1) * n]) {
            *o = c0 * kv;
        }
        for (l, c) in rest {
            for (o, kv) in out.iter_mut().zip(&k[l * n..(l + 1) * n]) {
                *o += c * kv;
            }
        }
    }

    /// `out = Σ_{(l, c) in row} c k_l` for the stages held.
    pub fn combine_into(&self, row: &[(usize, Real)], out: &mut [Real]) {
        Self::combine(&self.k, self.n, row, out);
    }

    /// Evaluates stage `into` at `t` from `y + h Σ_{(l, c) in row} c k_l`. The small terms are
    /// summed before they are added to `y`, which keeps round-off at the level of `y`'s last
    /// bit.
    #[inline]
    pub fn stage_from<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        row: &[(usize, Real)],
        t: Real,
        y: &[Real],
        h: Real,
        into: usize,
    ) {
        let n = self.n;
        Self::combine(&self.k, n, row, &mut self.acc);
        for ((tm, y), a) in self.tmp.iter_mut().zip(y).zip(&self.acc) {
            *tm = y + h * a;
        }
        let (tmp, k) = (&self.tmp, &mut self.k);
        sys.rhs_into(t, tmp, &mut k[into * n..(into + 1) * n]);
    }

    /// Evaluates `f(t, y)` into stage `l`.
    pub fn eval_into<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: Real, y: &[Real], l: usize) {
        let n = self.n;
        sys.rhs_into(t, y, &mut self.k[l * n..(l + 1) * n]);
    }

    /// Computes the stages of `tab` from `(t, y)` with step `h`, and `Σ b_i k_i` (the
    /// increment of the solution divided by `h`) into `slope`. Returns the evaluations made.
    /// Stage 0 must already hold `f(t, y)` when `k0_known`.
    #[allow(clippy::too_many_arguments)]
    pub fn compute<S: OdeSystem + ?Sized>(
        &mut self,
        tab: &Tableau,
        sys: &S,
        t: Real,
        y: &[Real],
        h: Real,
        slope: &mut [Real],
        k0_known: bool,
    ) -> usize {
        let s = tab.stages();
        let mut evaluations = 0;
        if !k0_known {
            self.eval_into(sys, t, y, 0);
            evaluations += 1;
        }
        let rows = std::mem::take(&mut self.rows);
        for (i, row) in rows[1..s].iter().enumerate() {
            self.stage_from(sys, row, t + tab.c[i + 1] * h, y, h, i + 1);
            evaluations += 1;
        }
        self.rows = rows;
        Self::combine(&self.k, self.n, &self.weights, slope);
        evaluations
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
        let known = self.stages.provided.take(state.t);
        if known {
            let Stages { k, provided, .. } = &mut self.stages;
            k[..n].copy_from_slice(&provided.dydt);
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
