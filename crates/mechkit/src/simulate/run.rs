//! The simulation loop.

use super::condition::Condition;
use super::diagnose::{coordinate_name, diagnose_evaluation, diagnose_state};
use super::locate::locate;
use super::observe::Observer;
use super::report::{EventRecord, RunReport, SimulateError, Snapshot, StopReason};
use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::steps_to_cover;
use crate::ode::{
    Euler, EulerCromer, Method, Rk4, SecondOrderSystem, State, Stepper, VelocityVerlet,
};
use crate::particles::{Evaluation, ParticleSystem, Sample};

/// Step budget of a run with neither `t_max` nor `max_steps`.
pub const DEFAULT_MAX_STEPS: u64 = 1_000_000;

/// A configured run of a particle system.
#[derive(Debug, Clone)]
pub struct Simulation<'a> {
    system: &'a ParticleSystem,
    method: Method,
    dt: Real,
    t_max: Option<Real>,
    max_steps: Option<u64>,
    stop: Option<Condition>,
}

impl<'a> Simulation<'a> {
    /// A run of `system` with `method` and step `dt`.
    pub fn new(system: &'a ParticleSystem, method: Method, dt: Real) -> Self {
        Self {
            system,
            method,
            dt,
            t_max: None,
            max_steps: None,
            stop: None,
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

    /// Ends when `condition` becomes true, at the located crossing.
    #[must_use]
    pub fn stop_when(mut self, condition: Condition) -> Self {
        self.stop = Some(condition);
        self
    }

    /// Runs from `initial`, passing every sample to `observers`.
    pub fn run(
        &self,
        initial: State,
        observers: &mut [&mut dyn Observer],
    ) -> Result<RunReport, SimulateError> {
        if !(self.dt > 0.0 && self.dt.is_finite()) {
            return Err(SimulateError::BadStep(self.dt));
        }
        let expected = 2 * self.system.dof();
        if initial.y.len() != expected {
            return Err(SimulateError::StateLength {
                expected,
                got: initial.y.len(),
            });
        }
        if let Some(i) = initial.y.iter().position(|x| !x.is_finite()) {
            return Err(SimulateError::NonFiniteInitial(format!(
                "{} = {}",
                coordinate_name(self.system, i),
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
        match self.method {
            Method::Euler => self.run_with(Euler::new(), initial, observers),
            Method::EulerCromer => self.run_with(EulerCromer::new(), initial, observers),
            Method::VelocityVerlet => self.run_with(VelocityVerlet::new(), initial, observers),
            Method::Rk4 => self.run_with(Rk4::new(), initial, observers),
        }
    }

    #[allow(clippy::too_many_lines)]
    fn run_with<St: Stepper<ParticleSystem>>(
        &self,
        mut stepper: St,
        mut state: State,
        observers: &mut [&mut dyn Observer],
    ) -> Result<RunReport, SimulateError> {
        let sys = self.system;
        let t0 = state.t;
        let initial = state.clone();
        let mut warnings = Vec::new();
        let planned = self.t_max.map(|tm| steps_to_cover(tm - t0, self.dt) as u64);
        let limit = match (self.max_steps, planned) {
            (Some(m), _) => m,
            (None, Some(_)) => u64::MAX,
            (None, None) => {
                warnings.push(format!(
                    "no t_max was given: the run is bounded by {DEFAULT_MAX_STEPS} steps (t = {} s with dt = {} s); set t_max to choose the end",
                    t0 + DEFAULT_MAX_STEPS as Real * self.dt,
                    self.dt
                ));
                DEFAULT_MAX_STEPS
            }
        };
        let names: Vec<String> = sys.forces().iter().map(|f| f.name().to_string()).collect();
        let mut scratch = Vec::new();
        let mut prev_eval = Evaluation::default();
        let mut new_eval = Evaluation::default();
        let mut work_buf = Vec::new();
        {
            let (q, v) = state.qv();
            sys.evaluate(t0, q, v, &mut prev_eval, &mut scratch);
        }
        let mut ledger = EnergyLedger::start(names, t0, &prev_eval);
        let mut evaluations: u64 = 1;
        let mut steps: u64 = 0;
        let mut event = None;
        let mut divergence = None;
        let mut stop_reason = None;

        let sample0 = sample_of(0, &state, &prev_eval, ledger.work());
        for o in observers.iter_mut() {
            o.observe(&sample0)?;
        }
        // the event function before the first step: negative while the run should go on
        let mut g_prev = self
            .stop
            .as_ref()
            .map_or(Real::NAN, |c| c.value(&sample0, sys));
        if let Some(d) = diagnose_evaluation(sys, &state, &prev_eval, 0) {
            divergence = Some(d);
            stop_reason = Some(StopReason::Diverged);
        } else if let Some(c) = &self.stop
            && c.holds_for(g_prev)
        {
            warnings.push(format!(
                    "the stop condition `{}` already holds at the start (t = {t0} s); nothing was simulated",
                    c.description()
                ));
            let snap = Snapshot::of(t0, &state.y);
            event = Some(EventRecord {
                name: c.description().to_string(),
                t: t0,
                state: snap.clone(),
                last_step: snap.clone(),
                crossing_step: snap,
            });
            stop_reason = Some(StopReason::Event);
        }

        // The ledger evaluates the forces at every step's end; the stepper's next step starts
        // there, so it gets that evaluation instead of repeating it.
        let n = state.y.len() / 2;
        let mut dydt = vec![0.0; 2 * n];
        let mut hand_over = |stepper: &mut St, t: Real, y: &[Real], a: &[Real]| {
            dydt[..n].copy_from_slice(&y[n..]);
            dydt[n..].copy_from_slice(a);
            stepper.provide_derivative(t, &dydt);
        };
        hand_over(&mut stepper, t0, &state.y, &prev_eval.a);
        let mut prev_y = state.y.clone();
        while stop_reason.is_none() {
            if planned == Some(steps) {
                stop_reason = Some(StopReason::TMax);
                break;
            }
            if steps >= limit {
                stop_reason = Some(StopReason::MaxSteps);
                if self.max_steps.is_none() {
                    let why = if self.stop.is_some() {
                        "the stop condition never became true"
                    } else {
                        "nothing else ends this run"
                    };
                    warnings.push(format!(
                        "stopped after the default budget of {DEFAULT_MAX_STEPS} steps at t = {} s: {why}; set [stop] t_max",
                        state.t
                    ));
                }
                break;
            }
            let t_prev = state.t;
            let t_next = match planned {
                Some(n) if steps + 1 == n => self.t_max.expect("planned implies t_max"),
                _ => t0 + (steps + 1) as Real * self.dt,
            };
            let info = stepper.step(sys, &mut state, t_next - t_prev)?;
            evaluations += info.evaluations as u64;
            state.t = t_next;
            steps += 1;
            if !state.is_finite() {
                divergence = Some(diagnose_state(sys, &prev_y, &state, t_prev, steps - 1));
                state.y.copy_from_slice(&prev_y);
                state.t = t_prev;
                stop_reason = Some(StopReason::Diverged);
                break;
            }
            {
                let (q, v) = state.qv();
                sys.evaluate(t_next, q, v, &mut new_eval, &mut scratch);
            }
            evaluations += 1;

            if let Some(c) = &self.stop {
                ledger.preview_into(t_next, &new_eval.power, &mut work_buf);
                let g = c.value(&sample_of(steps, &state, &new_eval, &work_buf), sys);
                if c.holds_for(g) {
                    let crossing_step = Snapshot::of(t_next, &state.y);
                    let y1 = state.y.clone();
                    let (te, evals) = locate(
                        c,
                        sys,
                        &ledger,
                        (t_prev, &prev_y, &prev_eval, g_prev),
                        (t_next, &y1, &new_eval, g),
                        &mut new_eval.clone(),
                        &mut state,
                        &mut scratch,
                    );
                    evaluations += evals;
                    {
                        let (q, v) = state.qv();
                        sys.evaluate(te, q, v, &mut new_eval, &mut scratch);
                    }
                    ledger.advance(te, &new_eval);
                    let s = Sample {
                        located: true,
                        ..sample_of(steps, &state, &new_eval, ledger.work())
                    };
                    for o in observers.iter_mut() {
                        o.observe(&s)?;
                    }
                    event = Some(EventRecord {
                        name: c.description().to_string(),
                        t: te,
                        state: Snapshot::of(te, &state.y),
                        last_step: Snapshot::of(t_prev, &prev_y),
                        crossing_step,
                    });
                    std::mem::swap(&mut prev_eval, &mut new_eval);
                    stop_reason = Some(StopReason::Event);
                    break;
                }
                g_prev = g;
            }

            ledger.advance(t_next, &new_eval);
            let s = sample_of(steps, &state, &new_eval, ledger.work());
            for o in observers.iter_mut() {
                o.observe(&s)?;
            }
            std::mem::swap(&mut prev_eval, &mut new_eval);
            prev_y.copy_from_slice(&state.y);
            hand_over(&mut stepper, t_next, &state.y, &prev_eval.a);
            if let Some(d) = diagnose_evaluation(sys, &state, &prev_eval, steps) {
                divergence = Some(d);
                stop_reason = Some(StopReason::Diverged);
            }
        }

        // The final sample is a located event unless the condition held from the start.
        let last = Sample {
            located: event.is_some() && steps > 0,
            ..sample_of(steps, &state, &prev_eval, ledger.work())
        };
        for o in observers.iter_mut() {
            o.finish(&last)?;
        }
        Ok(RunReport {
            method: self.method,
            dt: self.dt,
            steps,
            evaluations,
            stop_reason: stop_reason.expect("the loop sets a reason"),
            initial,
            final_state: state,
            event,
            divergence,
            ledger,
            warnings,
        })
    }
}

/// The sample of a state (a step, not a located event).
pub(crate) fn sample_of<'s>(
    step: u64,
    state: &'s State,
    eval: &'s Evaluation,
    work: &'s [Real],
) -> Sample<'s> {
    let (q, v) = state.qv();
    Sample {
        step,
        t: state.t,
        q,
        v,
        eval,
        work,
        located: false,
    }
}
