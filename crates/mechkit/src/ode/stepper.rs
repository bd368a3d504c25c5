//! The stepper trait: advance a state by one step.

use thiserror::Error;

use super::state::State;
use crate::Real;

/// What one step cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct StepInfo {
    /// Evaluations of the right-hand side (or of the acceleration) made by this step.
    pub evaluations: usize,
}

/// Why a stepper could not advance.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum IntegrateError {
    /// The step size is not a positive finite number.
    #[error(
        "step size h = {} at t = {} is not a positive finite number",
        crate::error::short(*h),
        crate::error::short(*t)
    )]
    BadStep {
        /// Time.
        t: Real,
        /// Step.
        h: Real,
    },
    /// A splitting method was given a system whose acceleration depends on the velocity.
    #[error(
        "{method} is a symplectic splitting method and needs forces that depend on position and time only; this system has velocity-dependent forces (drag, friction): use rk4 or dopri5"
    )]
    NeedsPositionForces {
        /// The method.
        method: &'static str,
    },
    /// An implicit method was asked for fixed steps.
    #[error(
        "{method} is implicit and chooses its own steps: run it without a fixed step (dt), with rtol/atol"
    )]
    AdaptiveOnly {
        /// The method.
        method: &'static str,
    },
    /// The state became NaN or infinite.
    #[error("the state became non-finite at t = {}", crate::error::short(*t))]
    NonFinite {
        /// Time at the end of the failed step.
        t: Real,
    },
}

/// Advances a state of a system `S` by one step.
///
/// The caller owns the [`State`]; steppers keep only scratch buffers (allocated on the first
/// step, reused after) and, for methods that reuse an evaluation, a cache that
/// [`Stepper::reset`] clears.
pub trait Stepper<S: ?Sized> {
    /// Short name, as in scenario files (`euler-cromer`).
    fn name(&self) -> &'static str;

    /// Global order of accuracy.
    fn order(&self) -> u32;

    /// Advances `state` by `h`.
    fn step(&mut self, sys: &S, state: &mut State, h: Real) -> Result<StepInfo, IntegrateError>;

    /// Forgets cached evaluations; call after changing the state outside the stepper.
    fn reset(&mut self) {}

    /// Hands the stepper the derivative `f(t, y)` of the state the next step starts from (for
    /// a second-order system `[v, a]`), when the caller has computed it anyway: the next step
    /// uses it instead of evaluating it again ("first same as last"). It is used once; a step
    /// from a different time ignores it.
    fn provide_derivative(&mut self, _t: Real, _dydt: &[Real]) {}

    /// Takes fixed steps of `h` until `t_end` (the last step shortened to land on it).
    /// Returns the number of steps.
    fn integrate(
        &mut self,
        sys: &S,
        state: &mut State,
        t_end: Real,
        h: Real,
    ) -> Result<usize, IntegrateError> {
        if !(h > 0.0 && h.is_finite()) {
            return Err(IntegrateError::BadStep { t: state.t, h });
        }
        let t0 = state.t;
        let span = t_end - t0;
        if span <= 0.0 {
            return Ok(0);
        }
        let n = steps_to_cover(span, h);
        for i in 0..n {
            let t_next = if i + 1 == n {
                t_end
            } else {
                t0 + (i + 1) as Real * h
            };
            let hi = t_next - state.t;
            self.step(sys, state, hi)?;
            state.t = t_next;
            if !state.is_finite() {
                return Err(IntegrateError::NonFinite { t: state.t });
            }
        }
        Ok(n)
    }
}

/// A derivative handed in by the caller for the next step (see
/// [`Stepper::provide_derivative`]).
#[derive(Debug, Clone, Default)]
pub(crate) struct Provided {
    t: Option<Real>,
    pub dydt: Vec<Real>,
}

impl Provided {
    pub fn set(&mut self, t: Real, dydt: &[Real]) {
        self.t = Some(t);
        self.dydt.clear();
        self.dydt.extend_from_slice(dydt);
    }

    /// Whether a derivative for time `t` is waiting; it is consumed either way.
    pub fn take(&mut self, t: Real) -> bool {
        self.t.take() == Some(t)
    }

    pub fn clear(&mut self) {
        self.t = None;
    }
}

/// Number of steps of size `h` that cover `span`, treating a remainder below 1e-9 h as
/// rounding (so 0.5 s in steps of 1e-5 s is 50 000 steps, not 50 001).
pub fn steps_to_cover(span: Real, h: Real) -> usize {
    let n = span / h;
    let rounded = n.round();
    if (n - rounded).abs() <= 1e-9 * rounded.max(1.0) {
        rounded.max(1.0) as usize
    } else {
        n.ceil() as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_counts() {
        assert_eq!(steps_to_cover(0.5, 1e-5), 50_000);
        assert_eq!(steps_to_cover(20.0, 1e-3), 20_000);
        assert_eq!(steps_to_cover(1.0, 0.3), 4);
        assert_eq!(steps_to_cover(1e-12, 1.0), 1);
    }
}
