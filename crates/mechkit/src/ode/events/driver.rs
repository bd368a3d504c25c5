//! Any [`OdeSystem`] integrated by an adaptive pair or a fixed-step method until a terminal
//! event or the end time, with every crossing of every event found inside the steps and
//! events that may change the state: a [`Model`] of the one event-aware loop
//! ([`super::drive`]).
//!
//! After every step the step's interpolant is taken as a polynomial (the pair's dense output,
//! [`AdaptiveRk::dense_polynomial_into`], or the cubic Hermite interpolant of a fixed step);
//! the events are sampled on it where their proofs
//! (or, without an enclosure, [`SAMPLES`](super::SAMPLES) evenly spaced points) say they must be,
//! and each sign change is located by Brent's method on the interpolant: the one event finder
//! that the particles' loop uses too (`find.rs`).
//! The first crossings are handled in time order: a non-terminal event is reported and the
//! integration goes on; a terminal one ends it, after the step is redone from its start to end
//! exactly at the located time, so that the state there is one the integrator reached, not an
//! interpolated one.

use std::ops::ControlFlow;

use super::drive::{AfterFiring, Model, drive};
use super::event::OdeEvent;
use super::find::Fired;
use super::scan::StepEvents;
use super::stepping::{Adaptive, Backward, Fixed, Implicit, Stepping};
use crate::Real;
use thiserror::Error;

use crate::ode::{
    AdaptiveError, AdaptiveRk, Bdf, IntegrateError, OdeSystem, Radau5, State, Stepper,
};

/// A crossing of a non-terminal event.
#[derive(Debug, Clone, PartialEq)]
pub struct EventHit {
    /// Index of the event in the slice given to [`run_to_event`].
    pub event: usize,
    /// Time of the crossing (s).
    pub t: Real,
    /// The state there, on the step's interpolant.
    pub y: Vec<Real>,
}

/// What [`run_to_event`] reports as it goes, in time order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Progress<'a> {
    /// An accepted step ended at this state (the final one of a terminal event included).
    Step(&'a State),
    /// A non-terminal event fired.
    Event(&'a EventHit),
}

/// How [`run_to_event`] ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventEnd {
    /// A terminal event fired; the state is at its time, reached by integration.
    Terminal {
        /// Index of the event (the first in the slice when several fire at once).
        event: usize,
    },
    /// The end time was reached first.
    TimeLimit,
    /// The caller's `on_progress` asked to stop (returned [`ControlFlow::Break`]); the state is
    /// the last one reported.
    Halted,
    /// An event with an action fired again within 64 units in the last place of the time of
    /// its own last state change: its occurrences accumulate at that instant (Zeno behaviour,
    /// a ball bouncing infinitely often before it comes to rest). The state is the one after
    /// that change.
    Zeno {
        /// Index of the event.
        event: usize,
    },
}

/// How [`run_events`] steps: an adaptive pair with its dense output, or a fixed-step method
/// with the cubic Hermite interpolant between the ends of each step (whose derivatives cost
/// one evaluation more per step).
pub enum Integrator<'r, S: ?Sized> {
    /// Adaptive steps; they go on from the pair's step-size history.
    Adaptive(&'r mut AdaptiveRk),
    /// Adaptive steps of the implicit Radau IIA(5), for stiff systems.
    Implicit(&'r mut Radau5),
    /// Adaptive steps of the variable-order BDF/NDF, for stiff systems.
    Bdf(&'r mut Bdf),
    /// Fixed steps of `dt` from the start (and from every state change), the last one
    /// shortened to land on the end time.
    Fixed {
        /// The method (`Rk4`, `ExplicitRk`, …).
        stepper: &'r mut dyn Stepper<S>,
        /// The step (s).
        dt: Real,
    },
}

/// Why [`run_events`] failed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum RunError {
    /// An adaptive step failed.
    #[error(transparent)]
    Adaptive(#[from] AdaptiveError),
    /// A fixed step failed.
    #[error(transparent)]
    Fixed(#[from] IntegrateError),
    /// The state became non-finite.
    #[error(
        "the state became non-finite at t = {} s; a smaller step (dt) may keep it finite",
        crate::error::short(*t)
    )]
    NonFinite {
        /// Time of the step's end (s).
        t: Real,
    },
}

/// Integrates `sys` from `state` with the adaptive pair `rk` until a terminal event among
/// `events` fires or until `t_end`: [`run_events`] with [`Integrator::Adaptive`].
///
/// `rk` goes on from its step-size history: [`AdaptiveRk::reset`] it first when the system or
/// the state changed since its last step.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use std::ops::ControlFlow;
/// use mechkit::interval::Jet;
/// use mechkit::ode::{
///     AdaptiveConfig, AdaptiveRk, EventEnd, OdeEvent, OdeSystem, Progress, State, Tableau,
///     run_to_event,
/// };
/// // a ball thrown up at 10 m/s, y = [x, v]
/// struct Throw;
/// impl OdeSystem for Throw {
///     fn dim(&self) -> usize { 2 }
///     fn rhs_into(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
///         dydt[0] = y[1];
///         dydt[1] = -9.81;
///     }
/// }
/// let events = [
///     // the apex, recorded
///     OdeEvent::new(|_, y| y[1]).bounded_by(|_, y: &[Jet]| Some(y[1])).falling(),
///     // the landing ends the run
///     OdeEvent::new(|_, y| y[0]).bounded_by(|_, y: &[Jet]| Some(y[0])).falling().terminal(),
/// ];
/// let mut rk = AdaptiveRk::new(Tableau::dopri5(), AdaptiveConfig::from_rtol(1e-10))?;
/// let mut state = State::new(0.0, vec![0.0, 10.0]);
/// let mut apex = None;
/// let end = run_to_event(&mut rk, &Throw, &mut state, 10.0, &events, &mut |p| {
///     if let Progress::Event(hit) = p {
///         apex = Some((hit.t, hit.y[0]));
///     }
///     ControlFlow::Continue(())
/// })?;
/// assert_eq!(end, EventEnd::Terminal { event: 1 });
/// assert_relative_eq!(state.t, 20.0 / 9.81, max_relative = 1e-12);
/// let (t, x) = apex.unwrap();
/// assert_relative_eq!(t, 10.0 / 9.81, max_relative = 1e-12);
/// assert_relative_eq!(x, 100.0 / (2.0 * 9.81), max_relative = 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn run_to_event<S: OdeSystem + ?Sized>(
    rk: &mut AdaptiveRk,
    sys: &S,
    state: &mut State,
    t_end: Real,
    events: &[OdeEvent<'_>],
    on_progress: &mut dyn FnMut(Progress<'_>) -> ControlFlow<()>,
) -> Result<EventEnd, AdaptiveError> {
    let mut stepping = Adaptive(rk);
    run_with(&mut stepping, sys, state, t_end, events, on_progress)
}

/// Integrates `sys` from `state` with `integrator` until a terminal event among `events` fires
/// or until `t_end`, calling `on_progress` after every step and at every crossing of a
/// non-terminal event, in time order; `on_progress` stops the run by returning
/// [`ControlFlow::Break`] ([`EventEnd::Halted`]).
///
/// - **Crossings**: [`OdeEvent`]'s rules; the functions' sides start from their values at the
///   start (a zero there is not a crossing). Every sign change of an event with an enclosure
///   along the step's interpolant is found, however short.
/// - **A terminal event** ends the run after the step is redone from its start to end exactly at
///   the located time, so the state there is one the integrator reached.
/// - **An event with an action** ([`OdeEvent::action`]) cuts the step the same way; the
///   crossing is reported with the state before the change, the actions of the events firing
///   together are applied in their order, the new state is reported as a step at the same
///   time, and the integration starts afresh from it (the adaptive pair's history reset, the
///   fixed steps counted from there). Each event's side is then taken from the new state.
///
/// # Example
/// ```
/// use std::ops::ControlFlow;
/// use mechkit::interval::Jet;
/// use mechkit::ode::{EventEnd, Integrator, OdeEvent, OdeSystem, Rk4, State, run_events};
/// // a ball bouncing on the floor with restitution 0.8, y = [x, v], rk4 with dt = 1 ms
/// struct Fall;
/// impl OdeSystem for Fall {
///     fn dim(&self) -> usize { 2 }
///     fn rhs_into(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
///         dydt[0] = y[1];
///         dydt[1] = -9.81;
///     }
/// }
/// let bounce = OdeEvent::new(|_, y| y[0])
///     .bounded_by(|_, y: &[Jet]| Some(y[0]))
///     .falling()
///     .action(|_, y| y[1] *= -0.8);
/// let mut state = State::new(0.0, vec![1.0, 0.0]);
/// let mut bounces = Vec::new();
/// let mut rk4 = Rk4::default();
/// let fixed = Integrator::Fixed { stepper: &mut rk4, dt: 1e-3 };
/// let end = run_events(fixed, &Fall, &mut state, 1.5, &[bounce], &mut |p| {
///     if let mechkit::ode::Progress::Event(hit) = p {
///         bounces.push(hit.t);
///     }
///     ControlFlow::Continue(())
/// })?;
/// assert_eq!(end, EventEnd::TimeLimit);
/// // the first bounce at √(2/g), the second 2·0.8·√(2/g) later
/// let t1 = (2.0 / 9.81f64).sqrt();
/// assert_eq!(bounces.len(), 2);
/// assert!((bounces[0] - t1).abs() < 1e-12);
/// assert!((bounces[1] - t1 * (1.0 + 1.6)).abs() < 1e-12);
/// # Ok::<(), mechkit::ode::RunError>(())
/// ```
pub fn run_events<S: OdeSystem + ?Sized>(
    integrator: Integrator<'_, S>,
    sys: &S,
    state: &mut State,
    t_end: Real,
    events: &[OdeEvent<'_>],
    on_progress: &mut dyn FnMut(Progress<'_>) -> ControlFlow<()>,
) -> Result<EventEnd, RunError> {
    match integrator {
        Integrator::Adaptive(rk) => Ok(run_with(
            &mut Adaptive(rk),
            sys,
            state,
            t_end,
            events,
            on_progress,
        )?),
        Integrator::Implicit(radau) => Ok(run_with(
            &mut Implicit(radau),
            sys,
            state,
            t_end,
            events,
            on_progress,
        )?),
        Integrator::Bdf(bdf) => Ok(run_with(
            &mut Backward(bdf),
            sys,
            state,
            t_end,
            events,
            on_progress,
        )?),
        Integrator::Fixed { stepper, dt } => {
            if !(dt > 0.0 && dt.is_finite()) {
                return Err(IntegrateError::BadStep { t: state.t, h: dt }.into());
            }
            let mut fixed = Fixed::new(stepper, dt, state);
            run_with(&mut fixed, sys, state, t_end, events, on_progress)
        }
    }
}

/// The run of either kind of stepping.
fn run_with<S: OdeSystem + ?Sized, G: Stepping<S>>(
    stepping: &mut G,
    sys: &S,
    state: &mut State,
    t_end: Real,
    events: &[OdeEvent<'_>],
    on_progress: &mut dyn FnMut(Progress<'_>) -> ControlFlow<()>,
) -> Result<EventEnd, G::Error> {
    let mut run = OdeRun {
        step: StepEvents::new(events, state),
        stepping,
        sys,
        before: state.clone(),
        state,
        t_end,
        hits: Vec::new(),
        on_progress,
        last_change: None,
        end: None,
    };
    drive(&mut run)?;
    Ok(run.end.unwrap_or(EventEnd::TimeLimit))
}

/// A run of an [`OdeSystem`] with [`OdeEvent`]s on the one event-aware loop.
struct OdeRun<'r, 'e, 'a, S: ?Sized, G> {
    stepping: &'r mut G,
    sys: &'r S,
    state: &'r mut State,
    t_end: Real,
    step: StepEvents<'e, 'a>,
    /// The state at the start of the step.
    before: State,
    /// The non-terminal crossings of the step so far.
    hits: Vec<EventHit>,
    on_progress: &'r mut dyn FnMut(Progress<'_>) -> ControlFlow<()>,
    /// The time of the last state change.
    last_change: Option<Real>,
    end: Option<EventEnd>,
}

impl<S: OdeSystem + ?Sized, G: Stepping<S>> OdeRun<'_, '_, '_, S, G> {
    /// Redoes the step from its start to end exactly at `t_star`, reporting its steps and the
    /// hits in time order (the state at `t_star` last, as a step); returns whether
    /// `on_progress` let the run go on.
    fn redo_to(&mut self, t_star: Real) -> Result<bool, G::Error> {
        self.state.clone_from(&self.before);
        self.stepping.restart(self.state);
        let mut reported = 0;
        while self.state.t < t_star {
            self.stepping.step(self.sys, self.state, t_star)?;
            if self.state.t < t_star {
                let (n, flow) = report(&self.hits[reported..], self.state.t, self.on_progress);
                reported += n;
                if flow.is_break() || (self.on_progress)(Progress::Step(self.state)).is_break() {
                    return Ok(false);
                }
            }
        }
        let (_, flow) = report(&self.hits[reported..], Real::INFINITY, self.on_progress);
        Ok(flow.is_continue() && (self.on_progress)(Progress::Step(self.state)).is_continue())
    }

    /// Applies the actions of the `fired` events at the state the run has reached (in a step
    /// of length `h`), reports the new state, and starts afresh from it; an action firing
    /// again at once is Zeno.
    fn change_state(&mut self, fired: &[usize], h: Real) {
        let t = self.state.t;
        let acting = fired.iter().copied().filter(|&i| self.step.acts(i));
        if let (Some(first), Some(last)) = (acting.clone().next(), self.last_change)
            && t <= last + 64.0 * ulp(last.abs().max(t.abs()))
        {
            self.end = Some(EventEnd::Zeno { event: first });
            return;
        }
        let g_pre = self.step.values_at(self.state);
        for i in acting {
            self.step.act(i, t, &mut self.state.y);
        }
        self.last_change = Some(t);
        self.stepping.changed(self.state, h);
        // a moment along the new state's flow: which way the change turned each function
        let mut ahead = self.state.clone();
        let mut f = vec![0.0; ahead.y.len()];
        self.sys.rhs_into(t, &self.state.y, &mut f);
        let delta = Real::EPSILON.sqrt() * t.abs().max(h.abs()).max(Real::MIN_POSITIVE);
        ahead.t += delta;
        for (y, f) in ahead.y.iter_mut().zip(&f) {
            *y += delta * f;
        }
        self.step.changed(fired, &g_pre, self.state, &ahead);
        if (self.on_progress)(Progress::Step(self.state)).is_break() {
            self.end = Some(EventEnd::Halted);
        }
    }
}

/// The spacing of floating-point numbers at `x`.
fn ulp(x: Real) -> Real {
    (x.next_up() - x).max(Real::MIN_POSITIVE)
}

impl<S: OdeSystem + ?Sized, G: Stepping<S>> Model for OdeRun<'_, '_, '_, S, G> {
    type Error = G::Error;

    fn ended(&self) -> bool {
        self.end.is_some()
    }

    fn stops_before_step(&mut self) -> bool {
        if self.state.t >= self.t_end {
            self.end = Some(EventEnd::TimeLimit);
        }
        self.ended()
    }

    fn advance(&mut self) -> Result<bool, G::Error> {
        self.before.clone_from(self.state);
        self.stepping.step(self.sys, self.state, self.t_end)?;
        self.hits.clear();
        Ok(false)
    }

    fn any_enabled(&self) -> bool {
        !self.step.is_empty()
    }

    fn plan(&mut self) {
        self.stepping.polynomial(
            self.sys,
            &self.before,
            self.state,
            &mut self.step.finder.poly,
        );
        self.step.plan(self.state);
    }

    fn begin_scan(&mut self) -> Real {
        self.step.begin_scan()
    }

    fn scan_from(&mut self, t_scan: Real) -> Option<Fired> {
        self.step.scan_from(t_scan, self.state.t)
    }

    fn end_scan(&mut self) {}

    fn fire(&mut self, fired: Fired) -> Result<AfterFiring, G::Error> {
        let t = fired.firing.t;
        let y = self.step.state_at(t, self.state);
        let mut terminal = None;
        for &event in &fired.firing.events {
            if self.step.is_terminal(event) {
                terminal = terminal.or(Some(event));
            } else {
                self.hits.push(EventHit {
                    event,
                    t,
                    y: y.clone(),
                });
            }
        }
        let acts = fired.firing.events.iter().any(|&i| self.step.acts(i));
        if terminal.is_none() && !acts {
            return Ok(self.step.recorded(fired, self.state.t));
        }
        let h = self.state.t - self.before.t;
        let go_on = self.redo_to(t)?;
        self.end = match terminal {
            _ if !go_on => Some(EventEnd::Halted),
            Some(event) => Some(EventEnd::Terminal { event }),
            None => {
                self.change_state(&fired.firing.events, h);
                self.end
            }
        };
        Ok(AfterFiring::Cut)
    }

    fn finish_step(&mut self, _event_at_end: bool) -> Result<(), G::Error> {
        self.step.end_step();
        let (_, flow) = report(&self.hits, Real::INFINITY, self.on_progress);
        if flow.is_break() || (self.on_progress)(Progress::Step(self.state)).is_break() {
            self.end = Some(EventEnd::Halted);
        }
        Ok(())
    }
}

/// Reports the leading `hits` at or before `t` (until `on_progress` says stop); returns how
/// many were reported.
fn report(
    hits: &[EventHit],
    t: Real,
    on_progress: &mut dyn FnMut(Progress<'_>) -> ControlFlow<()>,
) -> (usize, ControlFlow<()>) {
    for (n, hit) in hits.iter().enumerate() {
        if hit.t > t {
            return (n, ControlFlow::Continue(()));
        }
        if on_progress(Progress::Event(hit)).is_break() {
            return (n + 1, ControlFlow::Break(()));
        }
    }
    (hits.len(), ControlFlow::Continue(()))
}

#[cfg(test)]
#[path = "driver_tests.rs"]
mod tests;
