//! The step bound: every run's number of steps is bounded before its first step.
//!
//! - Fixed steps reach `t_max` in `N = ⌈(t_max − t0)/dt⌉` steps; `N` may be at most
//!   [`MAX_STEPS`] unless `max_steps` bounds the run itself (`t_max = 1e300` with
//!   `dt = 1 ms` would be 10^302 steps: a run for ever).
//! - `max_steps` may be at most [`MAX_STEPS`].
//! - A fixed step may not be longer than the run (`dt > t_max − t0`): one step of 20 s
//!   over a run of 10 s is no simulation of it (a feather would reach −4530 m/s).
//! - A fixed step must move the time: `t + dt > t` in double precision at every time the run
//!   reaches (a subnormal `dt`, or one below the spacing of the numbers near `t_max`, would
//!   leave `t` where it is).
//! - Adaptive steps choose their own size, so they cannot be counted up front: without
//!   `max_steps` they get [`DEFAULT_MAX_STEPS`] steps, with or without `t_max`, and a run that
//!   uses them up before its end stops with a warning that says how to allow more.
//!
//! [`Simulation::run`](super::Simulation::run) checks the rule before anything is computed,
//! and so does a scenario when it is read (`mechkit check` reports it at the `dt`, `t_max`
//! or `max_steps` of the file).

use thiserror::Error;

use super::run::DEFAULT_MAX_STEPS;
use super::stepping::Stepping;
use crate::Real;
use crate::ode::steps_to_cover;

/// The most steps one run may take: 10^9, about 10 minutes of the simplest fixed-step run
/// (a body under gravity takes 0.5 µs a step) and hours for a system of many bodies. A run
/// that needs more is refused before it starts, unless `max_steps` says how far to go.
pub const MAX_STEPS: u64 = 1_000_000_000;

/// Why a run's steps would not be bounded.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum StepBoundError {
    /// Fixed steps of `dt` from `t0` to `t_max` are more than [`MAX_STEPS`].
    #[error(
        "fixed steps of dt = {} s from t = {} s to t_max = {} s are {} steps, more than the {MAX_STEPS} a run may take",
        num(*dt), num(*t0), num(*t_max), count(*steps)
    )]
    TooManySteps {
        /// The step (s).
        dt: Real,
        /// The start (s).
        t0: Real,
        /// The end (s).
        t_max: Real,
        /// The steps it would take (∞ past `f64`).
        steps: Real,
    },
    /// The step does not move the time at `t`: `t + dt == t`.
    #[error(
        "the time step dt = {} s is too small to move the time at t = {} s: t + dt is t again in double precision, so the run would never advance",
        num(*dt), num(*t)
    )]
    StepBelowTimeResolution {
        /// The step (s).
        dt: Real,
        /// The time at which it stops counting (s).
        t: Real,
    },
    /// A subnormal step: below the smallest normal double, no time but 0 moves by it.
    #[error(
        "the time step dt = {} s is below 2.2e-308 s, the smallest step double precision holds in full: the time could not advance by it",
        num(*.0)
    )]
    SubnormalStep(Real),
    /// A fixed step longer than the whole run: `dt > t_max − t0`.
    #[error(
        "the time step dt = {} s is longer than the run, from t = {} s to t_max = {} s: one step would cover all of it",
        num(*dt), num(*t0), num(*t_max)
    )]
    StepLongerThanRun {
        /// The step (s).
        dt: Real,
        /// The start (s).
        t0: Real,
        /// The end (s).
        t_max: Real,
    },
    /// `max_steps` above [`MAX_STEPS`].
    #[error("max_steps = {0} is more than the {MAX_STEPS} steps a run may take")]
    MaxStepsTooLarge(u64),
    /// An output interval that asks for more than [`MAX_STEPS`] output times before `t_max`.
    #[error(
        "an output every {} s from t = {} s to t_max = {} s is {} output times, more than the {MAX_STEPS} a run may have",
        num(*interval), num(*t0), num(*t_max), short(*outputs)
    )]
    TooManyOutputs {
        /// The output interval (s).
        interval: Real,
        /// The start (s).
        t0: Real,
        /// The end (s).
        t_max: Real,
        /// The output times it asks for (∞ past `f64`).
        outputs: Real,
    },
}

impl StepBoundError {
    /// What to do about it.
    pub fn hint(&self) -> String {
        match self {
            StepBoundError::TooManySteps { t0, t_max, .. } => format!(
                "choose a larger dt (at least {} s reaches t_max within the limit), an earlier t_max, or give max_steps (at most {MAX_STEPS}) to run that many steps towards t_max",
                short(t_max / MAX_STEPS as Real - t0 / MAX_STEPS as Real)
            ),
            StepBoundError::StepBelowTimeResolution { t, .. } => format!(
                "a step must be at least {} s at t = {} s (a relative 2.2e-16 of the time); choose a larger dt",
                short(spacing(*t)),
                num(*t)
            ),
            StepBoundError::StepLongerThanRun { t0, t_max, .. } => format!(
                "choose a step much shorter than the run, e.g. dt = {} s (a thousandth of it), or a later t_max",
                short((t_max - t0) / 1000.0)
            ),
            StepBoundError::SubnormalStep(_) => {
                "choose a step the run can take, e.g. dt = \"1 ms\"".into()
            }
            StepBoundError::MaxStepsTooLarge(_) => format!(
                "give max_steps = {MAX_STEPS} or less; a longer simulation is several runs, each started from the last state of the one before"
            ),
            StepBoundError::TooManyOutputs { t0, t_max, .. } => format!(
                "choose a larger interval (at least {} s; a plot needs a few thousand points), or an earlier t_max",
                short(t_max / MAX_STEPS as Real - t0 / MAX_STEPS as Real)
            ),
        }
    }
}

/// `n` steps as a whole number (`1e303` when large).
fn count(n: Real) -> String {
    if n < 1e16 {
        format!("{n:.0}")
    } else if n.is_finite() {
        format!("{n:e}")
    } else {
        "over 1.8e308".into()
    }
}

/// A time as `0.001`, or `1e300` when very large or small.
fn num(x: Real) -> String {
    if x == 0.0 || (1e-4..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// `x` to three significant digits, rounded up so that it is enough: `16400`, `1e291`.
fn short(x: Real) -> String {
    if !(x.is_finite() && x > 0.0) {
        return num(x);
    }
    let text = format!("{x:.2e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let mut m: Real = mantissa.parse().unwrap_or(x);
    let e: i32 = exponent.parse().unwrap_or(0);
    // {:.2e} rounds to nearest: step up where that went below x
    if format!("{m}e{e}").parse::<Real>().is_ok_and(|r| r < x) {
        m = ((m * 100.0).round() + 1.0) / 100.0;
    }
    let m = format!("{m:.2}");
    let m = m.trim_end_matches('0').trim_end_matches('.');
    match format!("{m}e{e}").parse::<Real>() {
        Ok(r) if (-4..16).contains(&e) => format!("{r}"),
        _ => format!("{m}e{e}"),
    }
}

/// The gap between `t` and the next number up.
fn spacing(t: Real) -> Real {
    let t = t.abs();
    if t == 0.0 {
        return Real::from_bits(1);
    }
    Real::from_bits(t.to_bits() + 1) - t
}

/// The output times an output `interval` asks for from `t0` to `t_max`, or
/// [`StepBoundError::TooManyOutputs`] past [`MAX_STEPS`] (a run writes a row at each, however
/// few steps it takes: `interval = "1e-300 s"` asked for 10^300 rows inside the first step).
///
/// ```
/// use mechkit::simulate::check_output_bound;
/// assert_eq!(check_output_bound(0.0, 10.0, 0.01), Ok(1000));
/// assert!(check_output_bound(0.0, 1.0, 1e-300).is_err());
/// ```
pub fn check_output_bound(t0: Real, t_max: Real, interval: Real) -> Result<u64, StepBoundError> {
    let outputs = ((t_max - t0) / interval).floor().max(0.0);
    if outputs.is_nan() || outputs > MAX_STEPS as Real {
        return Err(StepBoundError::TooManyOutputs {
            interval,
            t0,
            t_max,
            outputs,
        });
    }
    Ok(outputs as u64)
}

/// The step budget of a run before its first step: `max_steps` if given, else the steps
/// fixed steps take to reach `t_max`, else [`DEFAULT_MAX_STEPS`]; or why there is none
/// (see the module's rule). `t0` is the start time.
///
/// # Example
/// ```
/// use mechkit::ode::Method;
/// use mechkit::simulate::{MAX_STEPS, Stepping, StepBoundError, check_step_bound};
/// let fixed = Stepping::Fixed { method: Method::Rk4, dt: 1e-3 };
/// assert_eq!(check_step_bound(&fixed, 0.0, Some(10.0), None), Ok(10_000));
/// assert!(matches!(
///     check_step_bound(&fixed, 0.0, Some(1e300), None),
///     Err(StepBoundError::TooManySteps { .. })
/// ));
/// // max_steps bounds the run however far t_max is
/// assert_eq!(check_step_bound(&fixed, 0.0, Some(1e300), Some(1000)), Ok(1000));
/// assert!(check_step_bound(&fixed, 0.0, None, Some(MAX_STEPS + 1)).is_err());
/// ```
pub fn check_step_bound(
    stepping: &Stepping,
    t0: Real,
    t_max: Option<Real>,
    max_steps: Option<u64>,
) -> Result<u64, StepBoundError> {
    if let Some(n) = max_steps
        && n > MAX_STEPS
    {
        return Err(StepBoundError::MaxStepsTooLarge(n));
    }
    let Some(dt) = stepping.dt() else {
        return Ok(max_steps.unwrap_or(DEFAULT_MAX_STEPS));
    };
    if dt < Real::MIN_POSITIVE {
        return Err(StepBoundError::SubnormalStep(dt));
    }
    if let Some(tm) = t_max
        && dt > tm - t0
        && tm > t0
    {
        return Err(StepBoundError::StepLongerThanRun { dt, t0, t_max: tm });
    }
    let planned = t_max.map(|tm| {
        let steps = ((tm - t0) / dt).ceil();
        (tm, steps)
    });
    if let (Some((tm, steps)), None) = (planned, max_steps)
        && (steps.is_nan() || steps > MAX_STEPS as Real)
    {
        return Err(StepBoundError::TooManySteps {
            dt,
            t0,
            t_max: tm,
            steps,
        });
    }
    let budget = match (max_steps, planned) {
        (Some(n), Some((tm, _))) => n.min(steps_to_cover(tm - t0, dt) as u64),
        (Some(n), None) => n,
        (None, Some((tm, _))) => steps_to_cover(tm - t0, dt) as u64,
        (None, None) => DEFAULT_MAX_STEPS,
    };
    // the last time reached is the latest; the spacing of the numbers only grows with them
    let last = match planned {
        Some((tm, _)) => tm.min(t0 + budget as Real * dt),
        None => t0 + budget as Real * dt,
    };
    for t in [t0, last] {
        if (t + dt).partial_cmp(&t) != Some(std::cmp::Ordering::Greater) {
            return Err(StepBoundError::StepBelowTimeResolution { dt, t });
        }
    }
    Ok(budget)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::{AdaptiveConfig, Method};

    fn fixed(dt: Real) -> Stepping {
        Stepping::Fixed {
            method: Method::Rk4,
            dt,
        }
    }

    /// Issue 26: `t_max = 1e300` with `dt = 1 ms`, `dt = 1e-320` and `max_steps = 9.2e18`
    /// ran for hours; each is refused before the first step, with the count it would take.
    #[test]
    fn issue_026_runs_that_would_never_end_are_refused_up_front() {
        let e = check_step_bound(&fixed(1e-3), 0.0, Some(1e300), None).unwrap_err();
        assert!(e.to_string().contains("1e303 steps"), "{e}");
        assert!(e.hint().contains("max_steps"), "{}", e.hint());
        assert!(e.hint().contains("at least 1.01e291 s"), "{}", e.hint());
        let e = check_step_bound(&fixed(1e-3), 0.0, Some(Real::MAX), None).unwrap_err();
        assert!(e.to_string().contains("are over 1.8e308 steps"), "{e}");
        assert!(
            e.to_string().contains("t_max = 1.7976931348623157e308 s"),
            "{e}"
        );
        for max_steps in [None, Some(10)] {
            let e = check_step_bound(&fixed(1e-320), 0.0, Some(1.0), max_steps).unwrap_err();
            assert_eq!(e, StepBoundError::SubnormalStep(1e-320));
        }
        // a step below the spacing of the times the run reaches
        let e = check_step_bound(&fixed(1e-3), 1e20, None, None).unwrap_err();
        assert!(
            matches!(e, StepBoundError::StepBelowTimeResolution { t, .. } if t == 1e20),
            "{e}"
        );
        assert!(e.hint().contains("16400 s"), "{}", e.hint());
        let e =
            check_step_bound(&fixed(1e-3), 0.0, None, Some(9_200_000_000_000_000_000)).unwrap_err();
        assert_eq!(
            e,
            StepBoundError::MaxStepsTooLarge(9_200_000_000_000_000_000)
        );
    }

    /// Issue 26: `dt = 20 s` with `t_max = 10 s` ran one step past the end without a word.
    #[test]
    fn issue_026_a_step_longer_than_the_run_is_refused() {
        let e = check_step_bound(&fixed(20.0), 0.0, Some(10.0), None).unwrap_err();
        assert_eq!(
            e,
            StepBoundError::StepLongerThanRun {
                dt: 20.0,
                t0: 0.0,
                t_max: 10.0
            }
        );
        assert!(
            e.to_string().contains("dt = 20 s is longer than the run"),
            "{e}"
        );
        assert!(e.hint().contains("dt = 0.01 s"), "{}", e.hint());
        let e = check_step_bound(&fixed(1.5), 1.0, Some(2.0), Some(5)).unwrap_err();
        assert!(matches!(e, StepBoundError::StepLongerThanRun { .. }), "{e}");
        // one step that covers the run exactly is a run
        assert_eq!(check_step_bound(&fixed(10.0), 0.0, Some(10.0), None), Ok(1));
    }

    #[test]
    fn bounded_runs_get_their_budget() {
        assert_eq!(check_step_bound(&fixed(0.1), 0.0, Some(1.0), None), Ok(10));
        assert_eq!(
            check_step_bound(&fixed(0.1), 0.0, None, None),
            Ok(DEFAULT_MAX_STEPS)
        );
        assert_eq!(
            check_step_bound(&fixed(1e-9), 0.0, Some(1.0), None),
            Ok(MAX_STEPS)
        );
        assert!(check_step_bound(&fixed(1e-9), 0.0, Some(1.000_001), None).is_err());
        assert_eq!(
            check_step_bound(&fixed(1e-3), 0.0, Some(1e300), Some(MAX_STEPS)),
            Ok(MAX_STEPS)
        );
        let adaptive = Stepping::Adaptive {
            method: Method::Dopri5,
            config: AdaptiveConfig::default(),
        };
        assert_eq!(
            check_step_bound(&adaptive, 0.0, Some(1e300), None),
            Ok(DEFAULT_MAX_STEPS)
        );
        assert_eq!(
            check_step_bound(&adaptive, 0.0, Some(1e300), Some(7)),
            Ok(7)
        );
    }
}
