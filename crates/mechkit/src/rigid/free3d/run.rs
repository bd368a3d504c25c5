//! The simulation: a chosen integrator over `[0, t_end]` on the one event-aware loop
//! (`model.rs`), samples on a uniform grid by the interpolant of each step, the zero crossings
//! of the intermediate axis' angular velocity as events (none missed; Brent's method on the
//! interpolant), the largest deviations of the conserved quantities at every step end, and the
//! unwrapped precession angle.

use super::body::{Attitude, SpinningBody};
use super::driver::{Clock, Driver, Window};
use super::equations::{Formulation, SpinEquations};
use super::error::Free3dError;
use super::model::SpinModel;
use super::record::Record;
use crate::Real;
use crate::mass::Vec3;
use crate::ode::events::drive::drive;
use crate::ode::events::find::{Finder, Side};
use crate::ode::{
    AdaptiveConfig, AdaptiveRk, ExplicitRk, STEP_BUDGET, State, Tableau, steps_to_cover,
};

/// How the equations are integrated.
#[derive(Debug, Clone)]
pub enum SpinIntegrator {
    /// An embedded Runge-Kutta pair with step-size control and dense output.
    Adaptive {
        /// The pair (`Tableau::dop853()`, `Tableau::dopri5()`).
        tableau: Tableau,
        /// Tolerances and step limits.
        config: AdaptiveConfig,
    },
    /// An explicit Runge-Kutta method with a fixed step (cubic Hermite between steps).
    Fixed {
        /// The method (`Tableau::rk4()`).
        tableau: Tableau,
        /// The step (s), shortened so that whole steps cover the run.
        dt: Real,
    },
    /// The splitting into exact rotations about the body axes: fixed
    /// step, symplectic, second order, `|L|` and `|q|` kept to rounding.
    Splitting {
        /// The step (s), shortened so that whole steps cover the run.
        dt: Real,
    },
}

impl SpinIntegrator {
    /// The method's name.
    pub fn name(&self) -> &'static str {
        match self {
            SpinIntegrator::Adaptive { tableau, .. } | SpinIntegrator::Fixed { tableau, .. } => {
                tableau.name
            }
            SpinIntegrator::Splitting { .. } => "splitting",
        }
    }

    /// DOP853 at relative tolerance `rtol` ([`AdaptiveConfig::from_rtol`]: absolute
    /// `rtol · 1e-3`).
    pub fn dop853(rtol: Real) -> Self {
        SpinIntegrator::Adaptive {
            tableau: Tableau::dop853(),
            config: AdaptiveConfig::from_rtol(rtol),
        }
    }
}

/// Settings of [`SpinningBody::simulate`].
#[derive(Debug, Clone)]
pub struct SpinOptions {
    /// The integrator.
    pub integrator: SpinIntegrator,
    /// The frame of `L` in the state.
    pub formulation: Formulation,
    /// Normalise the quaternion after every step.
    pub renormalise: bool,
    /// Number of intervals of the uniform output grid (samples at `t_end k / samples`).
    pub samples: usize,
}

impl Default for SpinOptions {
    /// DOP853 at `rtol = 1e-10`, `L` in the world frame, renormalised, 1000 intervals.
    fn default() -> Self {
        Self {
            integrator: SpinIntegrator::dop853(1e-10),
            formulation: Formulation::World,
            renormalise: true,
            samples: 1000,
        }
    }
}

/// The body at one output time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinSample {
    /// Time (s).
    pub t: Real,
    /// Orientation and angular momentum.
    pub attitude: Attitude,
    /// `ω` in the body frame (rad/s).
    pub omega_body: Vec3,
    /// Kinetic energy (J).
    pub kinetic: Real,
    /// Potential energy (J; 0 for a free body).
    pub potential: Real,
    /// The precession angle `φ`, unwrapped (rad).
    pub precession: Real,
}

/// A zero of the intermediate axis' angular velocity component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// Time (s).
    pub t: Real,
    /// Whether `ω` goes from negative to positive.
    pub rising: bool,
}

/// Largest deviations from the start over all step ends.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Conservation {
    /// `max ||L| − |L₀|| / |L₀|`.
    #[cfg_attr(feature = "serde", serde(rename = "angular_momentum_norm"))]
    pub l_norm: Real,
    /// `max |E − E₀| / max(|E₀|, T₀)`.
    pub energy: Real,
    /// `max |L_z − L_z0| / |L₀|` (the vertical component: conserved on a pivot).
    pub l_z: Real,
    /// `max |L₃ − L₃₀| / |L₀|` (the body's third component: conserved for a symmetric top).
    pub l_3: Real,
    /// `max ||q| − 1|` before renormalisation.
    pub quaternion_norm: Real,
}

/// A simulated rotation ([`SpinningBody::simulate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SpinRun {
    /// The samples at `t_end k / samples`, `k = 0..=samples`.
    pub samples: Vec<SpinSample>,
    /// Zeros of `ω` about the intermediate axis (free bodies only), in time order.
    pub crossings: Vec<Crossing>,
    /// The largest deviations of the conserved quantities.
    pub conservation: Conservation,
    /// The attitude at `t_end`.
    pub end: Attitude,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (adaptive).
    pub rejected: u64,
    /// Evaluations of the right-hand side.
    pub evaluations: u64,
    /// Steps in which the zeros of `ω` about the intermediate axis could not be proven (the
    /// proof needed more than [`MAX_BOUNDS`](crate::ode::MAX_BOUNDS) enclosures): `ω` was
    /// sampled at [`FALLBACK_SAMPLES`](crate::ode::events::FALLBACK_SAMPLES) points there, so
    /// a zero between two samples may be missed.
    pub unproven_steps: u64,
}

impl SpinRun {
    /// The period of `ω` about the intermediate axis from its zeros (two per period):
    /// `2 (t_last − t_first)/(n − 1)`; `None` with fewer than three zeros.
    pub fn crossing_period(&self) -> Option<Real> {
        let n = self.crossings.len();
        (n >= 3).then(|| 2.0 * (self.crossings[n - 1].t - self.crossings[0].t) / (n - 1) as Real)
    }
}

impl SpinningBody {
    /// Integrates the rotation from `start` over `[0, t_end]` with `options`: samples on a
    /// uniform grid, the zeros of `ω` about the intermediate axis (free bodies) located
    /// inside the steps, and the largest deviations of `|L|`, `E`, `L_z`, `L₃` and `|q|` at
    /// every step end.
    ///
    /// ```
    /// use mechkit::rigid::free3d::{FreeBody, SpinOptions, SpinningBody};
    /// use mechkit::mass::Vec3;
    /// use nalgebra::UnitQuaternion;
    /// let body = SpinningBody::free(FreeBody::new([1.0, 2.0, 3.0], 1.0)?);
    /// let start = body.attitude(UnitQuaternion::identity(), Vec3::new(0.01, 1.0, 0.01))?;
    /// let run = body.simulate(&start, 100.0, &SpinOptions::default())?;
    /// // the racket flips: ω₂ changes sign, and |L| and E are kept
    /// assert!(run.crossings.len() >= 4);
    /// assert!(run.conservation.energy < 1e-9);
    /// # Ok::<(), mechkit::rigid::free3d::Free3dError>(())
    /// ```
    pub fn simulate(
        &self,
        start: &Attitude,
        t_end: Real,
        options: &SpinOptions,
    ) -> Result<SpinRun, Free3dError> {
        if !(t_end > 0.0 && t_end.is_finite()) {
            return Err(Free3dError::Duration { value: t_end });
        }
        crate::sample_bound::check_samples("output intervals", options.samples)?;
        let start = self.attitude(start.q, self.omega_body(start))?;
        let eq = SpinEquations::new(self, options.formulation);
        let state = State::new(0.0, eq.formulation().to_state(&start));
        let clock = |dt: Real| -> Result<Clock, Free3dError> {
            // a subnormal step cannot move the time; past the budget the run would be endless
            if !(dt >= Real::MIN_POSITIVE && dt.is_finite()) {
                return Err(Free3dError::Step { value: dt });
            }
            let steps = (t_end / dt).ceil();
            if steps > STEP_BUDGET as Real {
                return Err(Free3dError::TooManySteps { steps, dt });
            }
            Ok(Clock {
                n: steps_to_cover(t_end, dt),
                k: 0,
                t_end,
            })
        };
        let driver = match &options.integrator {
            SpinIntegrator::Adaptive { tableau, config } => {
                config.validate(7)?;
                Driver::Adaptive(Box::new(AdaptiveRk::new(tableau.clone(), config.clone())?))
            }
            SpinIntegrator::Fixed { tableau, dt } => Driver::Fixed {
                rk: Box::new(ExplicitRk::new(tableau.clone())),
                clock: clock(*dt)?,
                window: Window::new(&eq, &state),
            },
            SpinIntegrator::Splitting { dt } => {
                if let Some((d, _)) = self.pivot()
                    && d.iter().filter(|x| **x != 0.0).count() > 1
                {
                    return Err(Free3dError::SplittingOffAxis { offset: d.into() });
                }
                Driver::Splitting {
                    clock: clock(*dt)?,
                    window: Window::new(&eq, &state),
                }
            }
        };
        let evaluations = match driver {
            Driver::Adaptive(_) => 0,
            _ => 1,
        };
        let record = Record::new(&eq, &start, t_end, options.samples);
        let watch = record.watch;
        let mut model = SpinModel {
            eq: &eq,
            driver,
            state,
            t_end,
            record,
            renormalise: options.renormalise,
            steps: 0,
            evaluations,
            watch: None,
            finder: Finder::default(),
            unproven_steps: 0,
            side: [Side::Unknown],
            g: (0.0, 0.0, 0.0),
            t0: 0.0,
            done: false,
        }
        .watching(watch);
        drive(&mut model)?;
        let SpinModel {
            driver,
            state,
            record,
            steps,
            evaluations,
            unproven_steps,
            ..
        } = model;
        let rejected = match &driver {
            Driver::Adaptive(rk) => rk.stats().rejected,
            _ => 0,
        };
        let end = eq.formulation().attitude(&state.y);
        Ok(SpinRun {
            samples: record.samples,
            crossings: record.crossings,
            conservation: record.conservation,
            end,
            steps,
            rejected,
            evaluations,
            unproven_steps,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::equations::rotation;
    use super::*;

    #[test]
    fn rotation_matches_nalgebra_for_unnormalised_quaternions() {
        let y = [0.3, -1.2, 0.7, 2.0, 0.0, 0.0, 0.0];
        let r = rotation(&y);
        let q = Formulation::World.attitude(&y).q.to_rotation_matrix();
        for (i, row) in r.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                assert!((x - q[(i, j)]).abs() < 1e-15);
            }
        }
    }
}
