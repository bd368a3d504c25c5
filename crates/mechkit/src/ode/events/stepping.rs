//! How [`run_events`](super::run_events) steps: adaptive steps of a pair with its dense
//! output, or fixed steps with the cubic Hermite interpolant between each step's ends.

use super::driver::RunError;
use crate::Real;
use crate::ode::{
    AdaptiveError, AdaptiveRk, Bdf, OdeSystem, Radau5, State, StepPolynomial, Stepper,
};

/// How a run of an [`OdeSystem`] steps, and the interpolant of its last step.
pub(super) trait Stepping<S: ?Sized> {
    type Error;
    /// One step from `state`, not past `t_bound`.
    fn step(&mut self, sys: &S, state: &mut State, t_bound: Real) -> Result<(), Self::Error>;
    /// The interpolant of the step from `before` to `after` (the last one taken).
    fn polynomial(&mut self, sys: &S, before: &State, after: &State, out: &mut StepPolynomial);
    /// Starts afresh from `state`, to redo a step.
    fn restart(&mut self, state: &State);
    /// Starts afresh from `state` after a state change, `h` the length of the step in which
    /// the change fired.
    fn changed(&mut self, state: &State, _h: Real) {
        self.restart(state);
    }
}

/// Adaptive steps.
pub(super) struct Adaptive<'r>(pub &'r mut AdaptiveRk);

impl<S: OdeSystem + ?Sized> Stepping<S> for Adaptive<'_> {
    type Error = AdaptiveError;

    fn step(&mut self, sys: &S, state: &mut State, t_bound: Real) -> Result<(), AdaptiveError> {
        self.0.step(sys, state, t_bound).map(|_| ())
    }

    fn polynomial(&mut self, sys: &S, _: &State, _: &State, out: &mut StepPolynomial) {
        self.0.dense_polynomial_into(sys, out);
    }

    fn restart(&mut self, _: &State) {
        self.0.reset();
    }

    /// The step in which the change fired is tried first: a first step chosen afresh from a
    /// state near rest (a ball bouncing ever lower) can fall below the smallest step.
    fn changed(&mut self, _: &State, h: Real) {
        self.0.reset_to_step(h);
    }
}

/// Adaptive steps of the implicit Radau IIA(5).
pub(super) struct Implicit<'r>(pub &'r mut Radau5);

impl<S: OdeSystem + ?Sized> Stepping<S> for Implicit<'_> {
    type Error = AdaptiveError;

    fn step(&mut self, sys: &S, state: &mut State, t_bound: Real) -> Result<(), AdaptiveError> {
        self.0.step(sys, state, t_bound).map(|_| ())
    }

    fn polynomial(&mut self, _: &S, _: &State, _: &State, out: &mut StepPolynomial) {
        self.0.dense_polynomial_into(out);
    }

    fn restart(&mut self, _: &State) {
        self.0.reset();
    }

    fn changed(&mut self, _: &State, h: Real) {
        self.0.reset_to_step(h);
    }
}

/// Adaptive steps of the variable-order BDF/NDF.
pub(super) struct Backward<'r>(pub &'r mut Bdf);

impl<S: OdeSystem + ?Sized> Stepping<S> for Backward<'_> {
    type Error = AdaptiveError;

    fn step(&mut self, sys: &S, state: &mut State, t_bound: Real) -> Result<(), AdaptiveError> {
        self.0.step(sys, state, t_bound).map(|_| ())
    }

    fn polynomial(&mut self, _: &S, _: &State, _: &State, out: &mut StepPolynomial) {
        self.0.dense_polynomial_into(out);
    }

    fn restart(&mut self, _: &State) {
        self.0.reset();
    }

    fn changed(&mut self, _: &State, h: Real) {
        self.0.reset_to_step(h);
    }
}

/// Fixed steps on a grid from `origin`, with the derivative at each step's end kept for the
/// next step's interpolant.
pub(super) struct Fixed<'r, S: ?Sized> {
    stepper: &'r mut dyn Stepper<S>,
    dt: Real,
    origin: Real,
    k: u64,
    /// The derivative at the start of the step (`None`: to evaluate) and at its end.
    f0: Option<Vec<Real>>,
    f1: Vec<Real>,
}

impl<'r, S: ?Sized> Fixed<'r, S> {
    pub fn new(stepper: &'r mut dyn Stepper<S>, dt: Real, state: &State) -> Self {
        stepper.reset();
        Self {
            stepper,
            dt,
            origin: state.t,
            k: 0,
            f0: None,
            f1: vec![0.0; state.y.len()],
        }
    }
}

impl<S: OdeSystem + ?Sized> Stepping<S> for Fixed<'_, S> {
    type Error = RunError;

    fn step(&mut self, sys: &S, state: &mut State, t_bound: Real) -> Result<(), RunError> {
        let grid = self.origin + (self.k + 1) as Real * self.dt;
        let t_next = if grid >= t_bound || t_bound - grid < 1e-9 * self.dt {
            t_bound
        } else {
            grid
        };
        // the derivative at the start, from the last step's end when it is still valid
        if let Some(f0) = &mut self.f0 {
            std::mem::swap(f0, &mut self.f1);
        }
        self.stepper.step(sys, state, t_next - state.t)?;
        state.t = t_next;
        self.k += 1;
        if !state.is_finite() {
            return Err(RunError::NonFinite { t: t_next });
        }
        Ok(())
    }

    fn polynomial(&mut self, sys: &S, before: &State, after: &State, out: &mut StepPolynomial) {
        let f0 = self.f0.get_or_insert_with(|| {
            let mut f = vec![0.0; before.y.len()];
            sys.rhs_into(before.t, &before.y, &mut f);
            f
        });
        sys.rhs_into(after.t, &after.y, &mut self.f1);
        out.reset(before.t, after.t - before.t, before.y.len(), 4);
        let ends = before
            .y
            .iter()
            .zip(f0.iter())
            .zip(after.y.iter().zip(&self.f1));
        for (i, ((y0, d0), (y1, d1))) in ends.enumerate() {
            out.set_hermite(i, (*y0, *d0), (*y1, *d1));
        }
    }

    fn restart(&mut self, state: &State) {
        self.stepper.reset();
        self.origin = state.t;
        self.k = 0;
        self.f0 = None;
    }
}
