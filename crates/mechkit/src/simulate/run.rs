//! A configured run: the system, how it steps, when it ends, its events and output times.

use super::cancel::Cancel;
use super::condition::Condition;
use super::diagnose::coordinate_name;
use super::event::Event;
use super::observe::Observer;
use super::report::{RunReport, SimulateError};
use super::stepping::Stepping;
use crate::Real;
use crate::ode::{AdaptiveConfig, IntegrateError, Method, MethodKind, SecondOrderSystem, State};
use crate::particles::{Evaluation, ParticleSystem, Sample, SampleKind};

/// Step budget of a run with neither `t_max` nor `max_steps` (and of adaptive runs without
/// `max_steps`): the models' budget, [`crate::ode::STEP_BUDGET`].
pub const DEFAULT_MAX_STEPS: u64 = crate::ode::STEP_BUDGET;

/// A configured run of a particle system.
///
/// # Example
/// ```
/// use mechkit::forces::UniformGravity;
/// use mechkit::ode::{AdaptiveConfig, Method, State};
/// use mechkit::particles::ParticleSystem;
/// use mechkit::simulate::{Direction, Event, Simulation};
/// let sys = ParticleSystem::builder(1)
///     .body("ball", 1.0)
///     .force(UniformGravity::new("gravity", vec![0], 9.81))
///     .build()
///     .unwrap();
/// let bounce = Event::new("bounce", |s, _| s.q[0])
///     .direction(Direction::Falling)
///     .set(|_, _, y| y[1] *= -0.9);
/// let report = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
///     .t_max(2.0)
///     .event(bounce)
///     .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [])
///     .unwrap();
/// // first bounce at sqrt(2 h / g)
/// assert!((report.events[0].t - (2.0f64 / 9.81).sqrt()).abs() < 1e-12);
/// ```
#[derive(Debug, Clone)]
pub struct Simulation<'a> {
    pub(crate) system: &'a ParticleSystem,
    pub(crate) stepping: Stepping,
    pub(crate) t_max: Option<Real>,
    pub(crate) max_steps: Option<u64>,
    pub(crate) events: Vec<Event>,
    pub(crate) interval: Option<Real>,
    pub(crate) times: Option<Vec<Real>>,
    pub(crate) max_outputs: Option<u64>,
    pub(crate) fuse: Option<bool>,
    pub(crate) cancel: Option<Cancel>,
}

impl<'a> Simulation<'a> {
    /// A run of `system` with fixed steps `dt` of `method`.
    pub fn new(system: &'a ParticleSystem, method: Method, dt: Real) -> Self {
        Self::with_stepping(system, Stepping::Fixed { method, dt })
    }

    /// A run with adaptive steps of a Runge-Kutta pair (`Dopri5`, `Dop853`, `BogackiShampine`,
    /// `Heun`).
    pub fn adaptive(system: &'a ParticleSystem, method: Method, config: AdaptiveConfig) -> Self {
        Self::with_stepping(system, Stepping::Adaptive { method, config })
    }

    /// A run stepping as `stepping` says.
    pub fn with_stepping(system: &'a ParticleSystem, stepping: Stepping) -> Self {
        Self {
            system,
            stepping,
            t_max: None,
            max_steps: None,
            events: Vec::new(),
            interval: None,
            times: None,
            max_outputs: None,
            fuse: None,
            cancel: None,
        }
    }

    /// Ends at time `t_max` (the last step is shortened to land on it).
    #[must_use]
    pub fn t_max(mut self, t_max: Real) -> Self {
        self.t_max = Some(t_max);
        self
    }

    /// Ends after at most `n` steps.
    #[must_use]
    pub fn max_steps(mut self, n: u64) -> Self {
        self.max_steps = Some(n);
        self
    }

    /// Ends when `condition` becomes true, at the located crossing (if it holds at the start,
    /// nothing is simulated).
    #[must_use]
    pub fn stop_when(mut self, condition: Condition) -> Self {
        self.events.push(Event::stop_condition(condition));
        self
    }

    /// Adds an event (fired in time order; simultaneous ones in the order added).
    #[must_use]
    pub fn event(mut self, event: Event) -> Self {
        self.events.push(event);
        self
    }

    /// Also passes observers the state every `interval` seconds from the start (interpolated
    /// inside the steps, [`SampleKind::Grid`]), without affecting the steps.
    #[must_use]
    pub fn output_interval(mut self, interval: Real) -> Self {
        self.interval = Some(interval);
        self
    }

    /// Ends the output times of [`Simulation::output_interval`] after `n` of them, with a
    /// warning, however many the interval asks for before `t_max` (the run itself goes on): a
    /// bound on the rows a run can produce, for a caller whose output is bounded too (a
    /// scenario's output limit). Without it the output times are bounded only by `t_max`, or
    /// by 10^6 of them when there is none.
    #[must_use]
    pub fn max_output_times(mut self, n: u64) -> Self {
        self.max_outputs = Some(n);
        self
    }

    /// Also passes observers the state at each of `times` (increasing; those at or before the
    /// start, or after `t_max`, are skipped), interpolated inside the steps: `t_eval` of
    /// `solve_ivp`. Replaces [`Simulation::output_interval`].
    #[must_use]
    pub fn output_times(mut self, times: Vec<Real>) -> Self {
        self.times = Some(times);
        self
    }

    /// Whether the steps no observer looks at may run in a compiled kernel (Euler and
    /// Euler-Cromer runs without events or output times, whose forces can all be compiled;
    /// the numbers are the general loop's, bit for bit). `true` fuses whenever possible,
    /// `false` never; by default runs of at least 20,000 steps are fused, unless the
    /// environment variable `MECHKIT_FUSE` is `0`.
    #[must_use]
    pub fn fuse(mut self, on: bool) -> Self {
        self.fuse = Some(on);
        self
    }

    /// Stops after the current step, with [`StopReason::Interrupted`](super::StopReason), once
    /// `cancel` (or a clone of it) is raised; the outputs are finished as for any other end.
    /// Without a handle the run cannot be stopped from outside.
    #[must_use]
    pub fn cancel_on(mut self, cancel: Cancel) -> Self {
        self.cancel = Some(cancel);
        self
    }

    /// How the run steps.
    pub fn stepping(&self) -> &Stepping {
        &self.stepping
    }

    /// Runs from `initial`, passing every sample to `observers`.
    pub fn run(
        &self,
        initial: State,
        observers: &mut [&mut dyn Observer],
    ) -> Result<RunReport, SimulateError> {
        self.check(&initial)?;
        super::drive::drive(self, initial, observers)
    }

    fn check(&self, initial: &State) -> Result<(), SimulateError> {
        let sys = self.system;
        let expected = 2 * sys.dof();
        match &self.stepping {
            Stepping::Fixed { method, dt } => {
                if !(*dt > 0.0 && dt.is_finite()) {
                    return Err(SimulateError::BadStep(*dt));
                }
                if method.kind() == MethodKind::Implicit {
                    return Err(IntegrateError::AdaptiveOnly {
                        method: method.name(),
                    }
                    .into());
                }
                if method.needs_position_forces() && sys.velocity_dependent() {
                    return Err(IntegrateError::NeedsPositionForces {
                        method: method.name(),
                    }
                    .into());
                }
            }
            Stepping::Adaptive { method, config } => {
                if !method.is_adaptive() {
                    return Err(crate::ode::ConfigError::NotAdaptive(method.name()).into());
                }
                let mut config = config.clone();
                config.error_components.get_or_insert(expected);
                config.validate(expected)?;
            }
        }
        if let Some(i) = self.interval
            && !(i > 0.0 && i.is_finite())
        {
            return Err(SimulateError::BadInterval(i));
        }
        if let Some(times) = &self.times
            && let Some(w) = times
                .windows(2)
                .find(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater))
        {
            return Err(SimulateError::BadOutputTimes(w[0], w[1]));
        }
        if let Some(t) = self.times.iter().flatten().find(|t| !t.is_finite()) {
            return Err(SimulateError::BadOutputTimes(*t, *t));
        }
        if initial.y.len() != expected {
            return Err(SimulateError::StateLength {
                expected,
                got: initial.y.len(),
            });
        }
        if let Some(i) = initial.y.iter().position(|x| !x.is_finite()) {
            return Err(SimulateError::NonFiniteInitial(format!(
                "{} = {}",
                coordinate_name(sys, i),
                initial.y[i]
            )));
        }
        if let Some(t_max) = self.t_max
            && t_max.partial_cmp(&initial.t) != Some(std::cmp::Ordering::Greater)
        {
            return Err(SimulateError::BadTMax {
                t_max,
                t0: initial.t,
            });
        }
        super::check_step_bound(&self.stepping, initial.t, self.t_max, self.max_steps)?;
        if let (Some(interval), Some(t_max)) = (self.interval, self.t_max) {
            super::check_output_bound(initial.t, t_max, interval)?;
        }
        Ok(())
    }
}

/// The sample of a state.
pub(crate) fn sample_of<'s>(
    step: u64,
    state: &'s State,
    eval: &'s Evaluation,
    work: &'s [Real],
    kind: SampleKind,
) -> Sample<'s> {
    let (q, v) = state.qv();
    Sample {
        step,
        t: state.t,
        q,
        v,
        eval,
        work,
        kind,
    }
}
