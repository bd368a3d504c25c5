//! Settings of adaptive steps: tolerances, limits, the step-size controller; their errors and
//! counters.

use thiserror::Error;

use super::tableau::{DenseKind, Tableau};
use crate::Real;

/// A tolerance: the same for every component, or one per component.
#[derive(Debug, Clone, PartialEq)]
pub enum Tolerance {
    /// One value for all components.
    Scalar(Real),
    /// One value per component.
    PerComponent(Vec<Real>),
}

impl Tolerance {
    pub(super) fn at(&self, i: usize) -> Real {
        match self {
            Tolerance::Scalar(v) => *v,
            Tolerance::PerComponent(v) => v[i],
        }
    }

    /// The value, when it is the same for every component.
    pub fn as_scalar(&self) -> Option<Real> {
        match self {
            Tolerance::Scalar(v) => Some(*v),
            Tolerance::PerComponent(_) => None,
        }
    }

    fn values(&self) -> Vec<Real> {
        match self {
            Tolerance::Scalar(v) => vec![*v],
            Tolerance::PerComponent(v) => v.clone(),
        }
    }
}

/// The step-size controller: `h_new = h · clamp(safety · err^(−α) · err_prev^β, min_factor,
/// max_factor)` with `α = 1/(q+1) − 0.75 β` for an error estimator of order `q`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Controller {
    /// Safety factor (below 1).
    pub safety: Real,
    /// Weight of the previous error (0: the classical I controller).
    pub beta: Real,
    /// Smallest ratio of successive steps.
    pub min_factor: Real,
    /// Largest ratio of successive steps.
    pub max_factor: Real,
    /// Also apply Gustafsson's predictive limit `safety · (h/h_prev) · (err_prev/err²)^(1/(q+1))`
    /// (as in Hairer's `radau5`), which shortens steps early when the error is growing and so
    /// avoids rejections.
    pub predictive: bool,
}

impl Controller {
    /// The default for a tableau. Chosen by the work-precision study in
    /// `benches/work_precision.rs` (Kepler e = 0.5 and 0.9, Arenstorf): Gustafsson's
    /// predictive limit on top of the classical controller saves 10-30 % of the evaluations at
    /// equal error, because the few rejections per orbit disappear. DOP853 uses the I
    /// controller (β = 0, as in Hairer's `dop853`), the others a light PI term (β = 0.02).
    pub fn for_tableau(tableau: &Tableau) -> Controller {
        let beta = if matches!(tableau.dense, DenseKind::Dop853) {
            0.0
        } else {
            0.02
        };
        Controller {
            safety: 0.9,
            beta,
            min_factor: 0.2,
            max_factor: 10.0,
            predictive: true,
        }
    }
}

/// Settings of an adaptive run.
#[derive(Debug, Clone, PartialEq)]
pub struct AdaptiveConfig {
    /// Relative tolerance.
    pub rtol: Tolerance,
    /// Absolute tolerance.
    pub atol: Tolerance,
    /// Smallest step allowed (`None`: ten units in the last place of `t`).
    pub h_min: Option<Real>,
    /// Largest step allowed.
    pub h_max: Real,
    /// First step (`None`: chosen automatically).
    pub h0: Option<Real>,
    /// How many leading components the error control looks at (`None`: all); the rest (a
    /// work integral, say) ride along.
    pub error_components: Option<usize>,
    /// The step-size controller (`None`: the method's usual one, [`Controller::for_tableau`]).
    pub controller: Option<Controller>,
    /// The most steps the integrator accepts before it refuses to go on
    /// ([`AdaptiveError::StepBudget`]); `None`: no bound (a scenario's run has its own,
    /// `simulate::check_step_bound`). [`AdaptiveConfig::from_rtol`], the models' rule, sets
    /// [`STEP_BUDGET`].
    pub max_steps: Option<u64>,
}

impl Default for AdaptiveConfig {
    /// `rtol = 1e-6`, `atol = 1e-9`, no step limits.
    fn default() -> Self {
        Self {
            rtol: Tolerance::Scalar(1e-6),
            atol: Tolerance::Scalar(1e-9),
            h_min: None,
            h_max: Real::INFINITY,
            h0: None,
            error_components: None,
            controller: None,
            max_steps: None,
        }
    }
}

/// The absolute tolerance per unit of relative tolerance in [`AdaptiveConfig::from_rtol`]:
/// `atol = rtol · 10⁻³`, so a component controls its error relative to its size down to a
/// thousandth of its unit (1 mm in metres, 1 ms in seconds) and absolutely below that.
pub const ATOL_PER_RTOL: Real = 1e-3;

/// The steps a model's run may take ([`AdaptiveConfig::from_rtol`]; a scenario's adaptive run
/// gets as many unless `max_steps` says more, `simulate::DEFAULT_MAX_STEPS`). Past it the run
/// stops with [`AdaptiveError::StepBudget`], which names the time it reached: a bound on the
/// work of any end time, since adaptive steps cannot be counted before the run. A million
/// steps of the heaviest model (`mechkit spin`, DOP853) take a few seconds in a release build.
pub const STEP_BUDGET: u64 = 1_000_000;

/// The smallest relative tolerance an adaptive run accepts: a few units in the last place of a
/// double (2.2e-16). Below it no step can meet the tolerance, the step size falls towards the
/// resolution of `t`, and a run takes minutes to fail; [`AdaptiveConfig::validate`] refuses
/// it, for every model and every front (a scenario's `rtol`, each command's `--rtol`).
pub const MIN_RTOL: Real = 1e-14;

/// Steps per span in [`AdaptiveConfig::sampled_over`]: `h_max = span / 1000`, so that the
/// steps (what a model records and plots) follow the motion, even where the method could cross
/// it in a few steps (a parabola in one).
pub const STEPS_PER_SPAN: Real = 1000.0;

impl AdaptiveConfig {
    /// The default settings at relative tolerance `rtol`, with `atol = rtol ·`
    /// [`ATOL_PER_RTOL`] and at most [`STEP_BUDGET`] steps: the one rule of the models'
    /// commands (`mechkit rocket`, `friction`, `roll`, `bead`, `spin`), so that none runs for
    /// ever, whatever its end time (`spin --t-max 1e300`).
    ///
    /// # Example
    /// ```
    /// use mechkit::ode::{AdaptiveConfig, Tolerance};
    /// let config = AdaptiveConfig::from_rtol(1e-8).sampled_over(10.0);
    /// assert_eq!(config.rtol, Tolerance::Scalar(1e-8));
    /// assert_eq!(config.atol, Tolerance::Scalar(1e-8 * 1e-3));
    /// assert_eq!(config.h_max, 10.0 / 1000.0);
    /// assert_eq!(config.max_steps, Some(mechkit::ode::STEP_BUDGET));
    /// ```
    pub fn from_rtol(rtol: Real) -> Self {
        Self {
            rtol: Tolerance::Scalar(rtol),
            atol: Tolerance::Scalar(rtol * ATOL_PER_RTOL),
            max_steps: Some(STEP_BUDGET),
            ..Self::default()
        }
    }

    /// The same settings with steps of at most `span /` [`STEPS_PER_SPAN`] (`span`: the
    /// duration of the motion recorded, s).
    #[must_use]
    pub fn sampled_over(self, span: Real) -> Self {
        Self {
            h_max: span / STEPS_PER_SPAN,
            ..self
        }
    }
}

/// Invalid adaptive settings.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ConfigError {
    /// `rtol` not positive.
    #[error("rtol must be positive and finite, not {}", crate::error::short(*.0))]
    Rtol(Real),
    /// `rtol` below [`MIN_RTOL`]: double precision cannot deliver it, and the steps shrink
    /// towards the resolution of `t` (`rtol = 1e-300` took minutes to fail).
    #[error(
        "rtol = {} is below what double precision can deliver; use {} or more",
        crate::error::short(*.0),
        crate::error::short(MIN_RTOL)
    )]
    RtolBelowPrecision(Real),
    /// `atol` negative.
    #[error("atol must be zero or positive and finite, not {}", crate::error::short(*.0))]
    Atol(Real),
    /// Per-component tolerance of the wrong length.
    #[error("{what} has {got} components, the system has {want}")]
    Length {
        /// Which tolerance.
        what: &'static str,
        /// Given.
        got: usize,
        /// Needed.
        want: usize,
    },
    /// A step limit that is not positive.
    #[error("{what} must be positive, not {}", crate::error::short(*value))]
    Step {
        /// Which limit.
        what: &'static str,
        /// Its value.
        value: Real,
    },
    /// Two step limits in the wrong order: `h_min > h_max`, or a first step `h0` below
    /// `h_min` (every step would be refused).
    #[error(
        "{small} = {} must not exceed {large} = {}",
        crate::error::short(*small_value),
        crate::error::short(*large_value)
    )]
    StepOrder {
        /// The limit that must be the smaller (`h_min`, or `h0`).
        small: &'static str,
        /// Its value.
        small_value: Real,
        /// The limit that must be the larger (`h_max`, or `h_min`'s partner).
        large: &'static str,
        /// Its value.
        large_value: Real,
    },
    /// The method has no error estimator.
    #[error("the method {0} has no error estimator; use a fixed step")]
    NotAdaptive(&'static str),
}

impl AdaptiveConfig {
    /// Checks the tolerances and limits for a system of `n` components.
    pub fn validate(&self, n: usize) -> Result<(), ConfigError> {
        for r in self.rtol.values() {
            if !(r > 0.0 && r.is_finite()) {
                return Err(ConfigError::Rtol(r));
            }
            if r < MIN_RTOL {
                return Err(ConfigError::RtolBelowPrecision(r));
            }
        }
        for a in self.atol.values() {
            if !(a >= 0.0 && a.is_finite()) {
                return Err(ConfigError::Atol(a));
            }
        }
        for (what, t) in [("rtol", &self.rtol), ("atol", &self.atol)] {
            if let Tolerance::PerComponent(v) = t {
                let want = self.error_components.unwrap_or(n);
                if v.len() != want {
                    return Err(ConfigError::Length {
                        what,
                        got: v.len(),
                        want,
                    });
                }
            }
        }
        for (what, v) in [
            ("h_min", self.h_min),
            ("h0", self.h0),
            ("h_max", Some(self.h_max)),
        ] {
            if let Some(v) = v
                && (v.is_nan() || v <= 0.0)
            {
                return Err(ConfigError::Step { what, value: v });
            }
        }
        if let Some(h_min) = self.h_min {
            // h_min > h_max: every step is clipped below the smallest one allowed; h0 < h_min:
            // the first step is refused. Either fails at the first step, so refuse it here.
            let pairs = [
                ("h_min", h_min, "h_max", self.h_max),
                ("h_min", h_min, "h0", self.h0.unwrap_or(Real::INFINITY)),
            ];
            for (small, small_value, large, large_value) in pairs {
                if small_value > large_value {
                    return Err(ConfigError::StepOrder {
                        small,
                        small_value,
                        large,
                        large_value,
                    });
                }
            }
        }
        Ok(())
    }
}

/// Counters of an adaptive run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct AdaptiveStats {
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
}

/// Why an adaptive step could not be taken.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum AdaptiveError {
    /// The step size fell below its minimum.
    #[error(
        "the step size fell to {} at t = {} (minimum {}); the error is dominated by component {component}{}",
        crate::error::short(*h),
        crate::error::short(*t),
        crate::error::short(*h_min),
        if *non_finite { " whose derivative is not finite" } else { "" }
    )]
    StepTooSmall {
        /// Time.
        t: Real,
        /// The step that was refused.
        h: Real,
        /// The minimum.
        h_min: Real,
        /// Index of the component with the largest scaled error.
        component: usize,
        /// Whether a stage produced non-finite values.
        non_finite: bool,
    },
    /// The run took [`AdaptiveConfig::max_steps`] steps before its end.
    #[error(
        "the run took its budget of {steps} steps and reached only t = {} s of {} s; choose an earlier end time, or a larger rtol",
        crate::error::short(*t),
        crate::error::short(*t_end)
    )]
    StepBudget {
        /// The budget.
        steps: u64,
        /// The time reached.
        t: Real,
        /// The end the run was asked to reach.
        t_end: Real,
    },
}

impl AdaptiveError {
    /// Whether the run stopped at its step budget (the end time asked too much of it), rather
    /// than failing to take a step.
    pub fn is_step_budget(&self) -> bool {
        matches!(self, AdaptiveError::StepBudget { .. })
    }
}

#[cfg(test)]
mod tests {
    use super::{AdaptiveConfig, ConfigError, MIN_RTOL, STEP_BUDGET};

    /// `mechkit rocket --rtol 1e-307` ran 115 s (`spin`, `bead`, `roll` at 1e-100 past 370 s)
    /// before failing: the steps shrank towards the resolution of t. Only a scenario refused
    /// it; now the one validation of every adaptive run does.
    #[test]
    fn a_tolerance_below_double_precision_is_refused() {
        for rtol in [1e-307, 1e-100, 1e-15] {
            let e = AdaptiveConfig::from_rtol(rtol).validate(2).unwrap_err();
            assert_eq!(e, ConfigError::RtolBelowPrecision(rtol));
            assert!(e.to_string().contains("use 1e-14 or more"), "{e}");
        }
        assert_eq!(AdaptiveConfig::from_rtol(MIN_RTOL).validate(2), Ok(()));
        assert_eq!(AdaptiveConfig::from_rtol(1e-6).max_steps, Some(STEP_BUDGET));
        assert_eq!(AdaptiveConfig::default().max_steps, None);
    }

    /// Issue 26: `h_min > h_max` (or a first step below `h_min`) failed at the first step of
    /// the run; it is refused by `validate`, before any step.
    #[test]
    fn issue_026_step_limits_in_the_wrong_order_are_refused() {
        let config = AdaptiveConfig {
            h_min: Some(1.0),
            h_max: 1e-3,
            ..AdaptiveConfig::default()
        };
        assert!(matches!(
            config.validate(2),
            Err(ConfigError::StepOrder {
                small: "h_min",
                large: "h_max",
                ..
            })
        ));
        let config = AdaptiveConfig {
            h_min: Some(1e-3),
            h0: Some(1e-6),
            ..AdaptiveConfig::default()
        };
        let e = config.validate(2).unwrap_err();
        assert_eq!(e.to_string(), "h_min = 0.001 must not exceed h0 = 1e-6");
        let config = AdaptiveConfig {
            h_min: Some(1e-3),
            h0: Some(1e-3),
            h_max: 1e-3,
            ..AdaptiveConfig::default()
        };
        assert_eq!(config.validate(2), Ok(()));
    }
}
