//! The simulation loop.

use std::fmt;

use thiserror::Error;

use super::condition::Condition;
use super::observe::{Observer, ObserverError};
use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::steps_to_cover;
use crate::ode::{
    Euler, EulerCromer, Method, Rk4, SecondOrderSystem, State, Stepper, VelocityVerlet, hermite,
};
use crate::particles::{Evaluation, ParticleSystem, Sample};
use crate::roots::brent_with_values;

/// Step budget of a run with neither `t_max` nor `max_steps`.
pub const DEFAULT_MAX_STEPS: u64 = 1_000_000;

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum StopReason {
    /// It reached `t_max`.
    TMax,
    /// The stop condition became true.
    Event,
    /// It used up its step budget.
    MaxSteps,
    /// The state or a force stopped being finite.
    Diverged,
}

impl StopReason {
    /// Name as in summaries: `t_max`, `event`, `max_steps`, `diverged`.
    pub fn name(self) -> &'static str {
        match self {
            StopReason::TMax => "t_max",
            StopReason::Event => "event",
            StopReason::MaxSteps => "max_steps",
            StopReason::Diverged => "diverged",
        }
    }
}

impl fmt::Display for StopReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Time, positions and velocities at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Time.
    pub t: Real,
    /// Positions.
    pub q: Vec<Real>,
    /// Velocities.
    pub v: Vec<Real>,
}

impl Snapshot {
    fn of(t: Real, y: &[Real]) -> Self {
        let (q, v) = y.split_at(y.len() / 2);
        Self {
            t,
            q: q.to_vec(),
            v: v.to_vec(),
        }
    }
}

/// A located stop event.
#[derive(Debug, Clone, PartialEq)]
pub struct EventRecord {
    /// What fired (the condition's description).
    pub name: String,
    /// Time of the crossing, located on the step's interpolant.
    pub t: Real,
    /// The interpolated state at the crossing.
    pub state: Snapshot,
    /// The last step before the crossing (what a `while` loop on the condition ends with).
    pub last_step: Snapshot,
    /// The step that crossed (the first for which the condition held).
    pub crossing_step: Snapshot,
}

/// Where and how a run stopped being finite.
#[derive(Debug, Clone, PartialEq)]
pub struct Divergence {
    /// Time of the last finite state.
    pub t: Real,
    /// Step index of the last finite state.
    pub step: u64,
    /// The quantity that went bad (`feather.vx`, `force air on feather`).
    pub quantity: String,
    /// Its value (NaN or ±inf).
    pub value: Real,
    /// A full explanation with a hint.
    pub message: String,
}

/// What a run did.
#[derive(Debug, Clone)]
pub struct RunReport {
    /// Method used.
    pub method: Method,
    /// Step size.
    pub dt: Real,
    /// Steps taken.
    pub steps: u64,
    /// Force evaluations (by the stepper and for the ledger).
    pub evaluations: u64,
    /// Why it stopped.
    pub stop_reason: StopReason,
    /// The initial state.
    pub initial: State,
    /// The final state (at the event, if one fired; the last finite state, if it diverged).
    pub final_state: State,
    /// The located stop event.
    pub event: Option<EventRecord>,
    /// What went wrong, if it diverged.
    pub divergence: Option<Divergence>,
    /// Energies and work.
    pub ledger: EnergyLedger,
    /// Things the user should know (defaults applied, suspicious setups).
    pub warnings: Vec<String>,
}

/// A run could not be done at all.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SimulateError {
    /// The step is not positive.
    #[error("the time step must be positive and finite, not {0} s")]
    BadStep(Real),
    /// `t_max` is before the start.
    #[error("t_max = {t_max} s is not after the start time {t0} s")]
    BadTMax {
        /// End time asked for.
        t_max: Real,
        /// Start time.
        t0: Real,
    },
    /// The state does not fit the system.
    #[error("the state has {got} components, the system needs {expected}")]
    StateLength {
        /// Needed.
        expected: usize,
        /// Given.
        got: usize,
    },
    /// The initial state has a non-finite value.
    #[error("the initial state is not finite: {0}")]
    NonFiniteInitial(String),
    /// The stepper refused the step.
    #[error(transparent)]
    Integrate(#[from] crate::ode::IntegrateError),
    /// An observer failed (an output could not be written).
    #[error("output failed: {0}")]
    Observer(#[from] ObserverError),
}

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
        if let Some(d) = diagnose_evaluation(sys, &state, &prev_eval, 0) {
            divergence = Some(d);
            stop_reason = Some(StopReason::Diverged);
        } else if let Some(c) = &self.stop {
            let g0 = c.value(&sample0, sys);
            if c.holds_for(g0) {
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
        let mut g_prev = self
            .stop
            .as_ref()
            .map_or(Real::NAN, |c| c.value(&sample0, sys));
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

        let last = Sample {
            located: event
                .as_ref()
                .is_some_and(|e| e.t != initial.t || steps > 0),
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

fn sample_of<'s>(
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

/// Finds the crossing of `c` inside the step from `lo` to `hi` on the cubic Hermite
/// interpolant; leaves the interpolated state in `out` and returns its time and the force
/// evaluations used.
#[allow(clippy::too_many_arguments)]
fn locate(
    c: &Condition,
    sys: &ParticleSystem,
    ledger: &EnergyLedger,
    lo: (Real, &[Real], &Evaluation, Real),
    hi: (Real, &[Real], &Evaluation, Real),
    eval_buf: &mut Evaluation,
    out: &mut State,
    scratch: &mut Vec<Real>,
) -> (Real, u64) {
    let (t0, y0, e0, g0) = lo;
    let (t1, y1, e1, g1) = hi;
    let h = t1 - t0;
    let n = y0.len() / 2;
    let mut work = Vec::new();
    let mut evaluations = 0;
    let interpolate = |s: Real, out: &mut State| {
        for i in 0..n {
            out.y[i] = hermite(y0[i], y0[n + i], y1[i], y1[n + i], h, s);
            out.y[n + i] = hermite(y0[n + i], e0.a[i], y1[n + i], e1.a[i], h, s);
        }
        out.t = t0 + s * h;
    };
    let tol = (4.0 * Real::EPSILON * t1.abs().max(h) / h).max(1e-15);
    let g_prev = if g0.is_nan() { -1.0 } else { g0 };
    let s = brent_with_values(
        |s| {
            interpolate(s, out);
            if c.needs_forces() {
                let (q, v) = out.qv();
                sys.evaluate(out.t, q, v, eval_buf, scratch);
                ledger.preview_into(out.t, &eval_buf.power, &mut work);
                evaluations += 1;
            } else {
                work.clear();
                work.extend_from_slice(ledger.work());
            }
            c.value(&sample_of(0, out, eval_buf, &work), sys)
        },
        0.0,
        1.0,
        Some((g_prev.min(0.0), g1)),
        tol,
    )
    .unwrap_or(1.0);
    interpolate(s, out);
    (out.t, evaluations)
}

/// Name of state component `i`: `feather.x`, `ball.vy`.
fn coordinate_name(sys: &ParticleSystem, i: usize) -> String {
    let dim = sys.dim();
    let n = sys.dof();
    let (velocity, j) = if i >= n { (true, i - n) } else { (false, i) };
    let body = &sys.bodies()[j / dim].name;
    let axis = ["x", "y", "z"][j % dim];
    if velocity {
        format!("{body}.v{axis}")
    } else {
        format!("{body}.{axis}")
    }
}

fn diagnose_state(
    sys: &ParticleSystem,
    prev_y: &[Real],
    bad: &State,
    t_prev: Real,
    step: u64,
) -> Divergence {
    let i = bad
        .y
        .iter()
        .position(|x| !x.is_finite())
        .expect("called for a non-finite state");
    let quantity = coordinate_name(sys, i);
    let value = bad.y[i];
    let message = format!(
        "the step from t = {t_prev} s to t = {} s made {quantity} = {value}, although every force was finite at t = {t_prev} s (where {quantity} = {}): a stage of the step left the region where the forces are defined, or the step is too large for how fast the forces change; try a smaller dt",
        bad.t, prev_y[i]
    );
    Divergence {
        t: t_prev,
        step,
        quantity,
        value,
        message,
    }
}

/// Checks an evaluation for non-finite values and names the force responsible.
fn diagnose_evaluation(
    sys: &ParticleSystem,
    state: &State,
    eval: &Evaluation,
    step: u64,
) -> Option<Divergence> {
    let finite = eval.a.iter().all(|x| x.is_finite())
        && eval.power.iter().all(|x| x.is_finite())
        && eval.kinetic.is_finite()
        && eval.potential_total.is_none_or(Real::is_finite);
    if finite {
        return None;
    }
    let (q, v) = state.qv();
    let k = sys.kinematics(state.t, q, v);
    let dim = sys.dim();
    let mut f = vec![0.0; q.len()];
    for force in sys.forces().iter() {
        f.fill(0.0);
        force.add_forces(&k, &mut f);
        if let Some(i) = f.iter().position(|x| !x.is_finite()) {
            let body = &sys.bodies()[i / dim].name;
            let axis = ["x", "y", "z"][i % dim];
            let pos: Vec<String> = k.position(i / dim).iter().map(|x| format!("{x}")).collect();
            let vel: Vec<String> = k.velocity(i / dim).iter().map(|x| format!("{x}")).collect();
            // A force on one body may depend on the others (a pair force, `other.x` in a
            // formula): show where they all are.
            let others: Vec<String> = sys
                .bodies()
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != i / dim)
                .take(6)
                .map(|(j, b)| {
                    let p: Vec<String> = k.position(j).iter().map(|x| format!("{x}")).collect();
                    format!("{} at [{}]", b.name, p.join(", "))
                })
                .collect();
            let others = if others.is_empty() {
                String::new()
            } else {
                format!("; the other bodies: {}", others.join(", "))
            };
            return Some(Divergence {
                t: state.t,
                step,
                quantity: format!("force `{}` on {body} ({axis} component)", force.name()),
                value: f[i],
                message: format!(
                    "at t = {} s the force `{}` on {body} is {} ({axis} component), with {body} at position [{}] and velocity [{}]{others}: a division by zero or a value outside a function's domain (sqrt, log of a negative number)",
                    state.t,
                    force.name(),
                    f[i],
                    pos.join(", "),
                    vel.join(", ")
                ),
            });
        }
        if let Some(u) = force.potential(&k).filter(|u| !u.is_finite()) {
            return Some(Divergence {
                t: state.t,
                step,
                quantity: format!("potential energy of `{}`", force.name()),
                value: u,
                message: format!(
                    "at t = {} s the potential energy of `{}` is {u}: the bodies it acts on have reached a singular point (r = 0?)",
                    state.t,
                    force.name()
                ),
            });
        }
    }
    let value = eval.kinetic;
    Some(Divergence {
        t: state.t,
        step,
        quantity: "kinetic energy".into(),
        value,
        message: format!("at t = {} s the kinetic energy is {value}", state.t),
    })
}
