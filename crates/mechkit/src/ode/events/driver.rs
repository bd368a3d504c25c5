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
use crate::Real;
use thiserror::Error;

use crate::ode::{
    AdaptiveError, AdaptiveRk, IntegrateError, OdeSystem, State, StepPolynomial, Stepper,
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
    #[error("the state became non-finite at t = {t} s; a smaller step (dt) may keep it finite")]
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

/// How a run of an [`OdeSystem`] steps, and the interpolant of its last step.
trait Stepping<S: ?Sized> {
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
struct Adaptive<'r>(&'r mut AdaptiveRk);

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

/// Fixed steps on a grid from `origin`, with the derivative at each step's end kept for the
/// next step's interpolant.
struct Fixed<'r, S: ?Sized> {
    stepper: &'r mut dyn Stepper<S>,
    dt: Real,
    origin: Real,
    k: u64,
    /// The derivative at the start of the step (`None`: to evaluate) and at its end.
    f0: Option<Vec<Real>>,
    f1: Vec<Real>,
}

impl<'r, S: ?Sized> Fixed<'r, S> {
    fn new(stepper: &'r mut dyn Stepper<S>, dt: Real, state: &State) -> Self {
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
mod tests {
    use mechkit_expr::interval::Jet;

    use super::*;
    use crate::ode::{AdaptiveConfig, Direction, Tableau};

    /// `x' = v, v' = −x`.
    struct Oscillator;
    impl OdeSystem for Oscillator {
        fn dim(&self) -> usize {
            2
        }
        fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
            dydt[0] = y[1];
            dydt[1] = -y[0];
        }
    }

    /// `y = [t, c − t²]`: integrated exactly by any pair, so its steps are as long as allowed.
    struct Parabola;
    impl OdeSystem for Parabola {
        fn dim(&self) -> usize {
            2
        }
        fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
            dydt[0] = 1.0;
            dydt[1] = -2.0 * y[0];
        }
    }

    fn rk(rtol: Real) -> AdaptiveRk {
        AdaptiveRk::new(Tableau::dop853(), AdaptiveConfig::from_rtol(rtol)).unwrap()
    }

    /// Runs and collects the hits and the steps.
    fn collect<S: OdeSystem>(
        rk: &mut AdaptiveRk,
        sys: &S,
        state: &mut State,
        t_end: Real,
        events: &[OdeEvent<'_>],
    ) -> (EventEnd, Vec<(usize, Real)>, Vec<Real>) {
        let (mut hits, mut steps) = (Vec::new(), Vec::new());
        let end = run_to_event(rk, sys, state, t_end, events, &mut |p| {
            match p {
                Progress::Step(s) => steps.push(s.t),
                Progress::Event(h) => hits.push((h.event, h.t)),
            }
            ControlFlow::Continue(())
        })
        .unwrap();
        (end, hits, steps)
    }

    #[test]
    fn a_short_excursion_that_eight_samples_miss_is_found() {
        // one step of length 1 over [−0.45, 0.55]; c − t² > 0 only for |t| < 1e-3, while the
        // nearest of the eight samples is at t = 0.05
        let run = |event: OdeEvent<'_>| {
            let config = AdaptiveConfig {
                h0: Some(1.0),
                h_max: 1.0,
                ..AdaptiveConfig::from_rtol(1e-10)
            };
            let mut rk = AdaptiveRk::new(Tableau::dop853(), config).unwrap();
            let mut state = State::new(-0.45, vec![-0.45, 1e-6 - 0.45 * 0.45]);
            let (end, hits, steps) = collect(&mut rk, &Parabola, &mut state, 0.55, &[event]);
            assert_eq!(end, EventEnd::TimeLimit);
            assert_eq!(steps, vec![0.55], "one step");
            hits
        };
        assert!(
            run(OdeEvent::new(|_, y| y[1])).is_empty(),
            "sampled: missed"
        );
        let hits = run(OdeEvent::new(|_, y| y[1]).bounded_by(|_, y: &[Jet]| Some(y[1])));
        assert_eq!(hits.len(), 2, "{hits:?}");
        for ((_, t), want) in hits.iter().zip([-1e-3, 1e-3]) {
            assert!((t - want).abs() < 1e-11, "{t} vs {want}");
        }
    }

    #[test]
    fn recorded_events_come_in_time_order() {
        // x = cos t: zeros at π/2 (falling) and 3π/2 (rising), x = 0.5 at π/3 and 5π/3
        let mut rk = rk(1e-12);
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let bounded = |f: fn(Jet) -> Jet| move |_: Jet, y: &[Jet]| Some(f(y[0]));
        let events = [
            OdeEvent::new(|_, y| y[0]).bounded_by(bounded(|x| x)),
            OdeEvent::new(|_, y| y[0] - 0.5)
                .bounded_by(bounded(|x| x - Jet::constant(0.5)))
                .direction(Direction::Rising),
            OdeEvent::new(|t, _| t - 1.0),
        ];
        let (end, hits, steps) = collect(&mut rk, &Oscillator, &mut state, 6.0, &events);
        assert_eq!(end, EventEnd::TimeLimit);
        let pi = std::f64::consts::PI;
        let want = [(2, 1.0), (0, pi / 2.0), (0, 1.5 * pi), (1, 5.0 * pi / 3.0)];
        assert_eq!(hits.len(), want.len(), "{hits:?}");
        for ((e, t), (we, wt)) in hits.iter().zip(want) {
            assert_eq!(*e, we);
            assert!((t - wt).abs() < 1e-11, "{e}: {t} vs {wt}");
        }
        assert_eq!(*steps.last().unwrap(), 6.0);
        assert!(steps.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn the_redone_step_ends_exactly_at_the_event() {
        // x = cos t falls through 0.5 at π/3; the time mark at 0.5 is recorded first, the one
        // at 2 never
        let mut rk = rk(1e-13);
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let events = [
            OdeEvent::new(|t, _| t - 2.0),
            OdeEvent::new(|_, y| y[0] - 0.5)
                .bounded_by(|_, y: &[Jet]| Some(y[0] - Jet::constant(0.5)))
                .falling()
                .terminal(),
            OdeEvent::new(|t, _| t - 0.5),
        ];
        let (mut order, mut last_step) = (Vec::new(), 0.0);
        let end = run_to_event(&mut rk, &Oscillator, &mut state, 10.0, &events, &mut |p| {
            match p {
                Progress::Step(s) => {
                    order.push(("step", s.t));
                    last_step = s.t;
                }
                Progress::Event(h) => order.push(("event", h.t)),
            }
            ControlFlow::Continue(())
        })
        .unwrap();
        assert_eq!(end, EventEnd::Terminal { event: 1 });
        let exact = std::f64::consts::FRAC_PI_3;
        assert!((state.t - exact).abs() < 1e-13, "{}", state.t - exact);
        assert!((state.y[0] - 0.5).abs() < 1e-13);
        // the integrator reached the event time exactly: the last step ends there
        assert_eq!(last_step, state.t);
        assert_eq!(rk.last_step().1, state.t);
        assert!(order.iter().any(|(k, t)| *k == "event" && *t == 0.5));
        assert!(order.windows(2).all(|w| w[0].1 <= w[1].1), "{order:?}");
    }

    #[test]
    fn starting_on_zero_does_not_fire_and_no_event_ends_at_the_limit() {
        // g = x starts at 0 (leaving); the next zero is at t = π
        let mut rk = rk(1e-13);
        let mut state = State::new(0.0, vec![0.0, 1.0]);
        let events = [OdeEvent::new(|_, y| y[0]).terminal()];
        let (end, _, _) = collect(&mut rk, &Oscillator, &mut state, 10.0, &events);
        assert_eq!(end, EventEnd::Terminal { event: 0 });
        assert!((state.t - std::f64::consts::PI).abs() < 1e-12);
        // an event that never happens: the run ends at the time limit
        rk.reset();
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let events = [OdeEvent::new(|_, y| y[0] - 2.0).terminal()];
        let (end, _, _) = collect(&mut rk, &Oscillator, &mut state, 1.0, &events);
        assert_eq!(end, EventEnd::TimeLimit);
        assert_eq!(state.t, 1.0);
    }

    #[test]
    fn the_caller_can_halt_the_run() {
        let mut rk = rk(1e-10);
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let mut steps = 0;
        let end = run_to_event(&mut rk, &Oscillator, &mut state, 10.0, &[], &mut |_| {
            steps += 1;
            if steps == 3 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        })
        .unwrap();
        assert_eq!(end, EventEnd::Halted);
        assert_eq!(steps, 3);
        assert!(state.t < 10.0);
    }

    /// `x' = v, v' = −g`.
    struct Fall;
    impl OdeSystem for Fall {
        fn dim(&self) -> usize {
            2
        }
        fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
            dydt[0] = y[1];
            dydt[1] = -9.81;
        }
    }

    fn floor(e: Real) -> OdeEvent<'static> {
        OdeEvent::new(|_, y| y[0])
            .bounded_by(|_, y: &[Jet]| Some(y[0]))
            .falling()
            .action(move |_, y| y[1] *= -e)
    }

    #[test]
    fn fixed_steps_find_every_crossing_on_the_hermite_interpolant() {
        // x = cos t with rk4 at dt = 0.01: zeros at π/2 + kπ, none missed, each to the
        // interpolant's accuracy
        let mut rk4 = crate::ode::Rk4::default();
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let events = [OdeEvent::new(|_, y| y[0]).bounded_by(|_, y: &[Jet]| Some(y[0]))];
        let mut hits = Vec::new();
        let fixed = Integrator::Fixed {
            stepper: &mut rk4,
            dt: 0.01,
        };
        let end = run_events(fixed, &Oscillator, &mut state, 10.0, &events, &mut |p| {
            if let Progress::Event(h) = p {
                hits.push(h.t);
            }
            ControlFlow::Continue(())
        })
        .unwrap();
        assert_eq!(end, EventEnd::TimeLimit);
        assert_eq!(state.t, 10.0);
        let pi = std::f64::consts::PI;
        assert_eq!(hits.len(), 3, "{hits:?}");
        for (k, t) in hits.iter().enumerate() {
            assert!((t - (0.5 + k as Real) * pi).abs() < 1e-8, "{t}");
        }
        // one step of length 1 over [−0.45, 0.55]: c − t² > 0 only for |t| < 1e-3
        let mut rk4 = crate::ode::Rk4::default();
        let mut state = State::new(-0.45, vec![-0.45, 1e-6 - 0.45 * 0.45]);
        let events = [OdeEvent::new(|_, y| y[1]).bounded_by(|_, y: &[Jet]| Some(y[1]))];
        let mut hits = Vec::new();
        let fixed = Integrator::Fixed {
            stepper: &mut rk4,
            dt: 1.0,
        };
        run_events(fixed, &Parabola, &mut state, 0.55, &events, &mut |p| {
            if let Progress::Event(h) = p {
                hits.push(h.t);
            }
            ControlFlow::Continue(())
        })
        .unwrap();
        assert_eq!(hits.len(), 2, "{hits:?}");
        assert!((hits[0] + 1e-3).abs() < 1e-12 && (hits[1] - 1e-3).abs() < 1e-12);
    }

    #[test]
    fn an_action_cuts_the_step_and_the_fixed_steps_restart_there() {
        let mut rk4 = crate::ode::Rk4::default();
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let mut order = Vec::new();
        let fixed = Integrator::Fixed {
            stepper: &mut rk4,
            dt: 0.01,
        };
        let end = run_events(fixed, &Fall, &mut state, 0.5, &[floor(0.8)], &mut |p| {
            order.push(match p {
                Progress::Step(s) => ("step", s.t, s.y[1]),
                Progress::Event(h) => ("event", h.t, h.y[1]),
            });
            ControlFlow::Continue(())
        })
        .unwrap();
        assert_eq!(end, EventEnd::TimeLimit);
        let t1 = (2.0 / 9.81 as Real).sqrt();
        let at = order.iter().position(|o| o.0 == "event").unwrap();
        let (_, te, v_before) = order[at];
        assert!((te - t1).abs() < 1e-13 && v_before < 0.0);
        // the step reached the event, the new state follows at the same time, then the
        // fixed steps count from the event
        assert_eq!((order[at + 1].0, order[at + 1].1), ("step", te));
        assert_eq!((order[at + 2].0, order[at + 2].1), ("step", te));
        assert!((order[at + 2].2 + 0.8 * v_before).abs() < 1e-12);
        assert_eq!(order[at + 3].1, te + 0.01);
    }

    #[test]
    fn bounces_that_accumulate_end_the_run_as_zeno() {
        // restitution 0.5: the bounces accumulate at t∞ = t₁ (1 + e)/(1 − e) = 3 t₁
        let mut rk = rk(1e-12);
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        let mut bounces = 0;
        let end = run_events(
            Integrator::Adaptive(&mut rk),
            &Fall,
            &mut state,
            10.0,
            &[floor(0.5)],
            &mut |p| {
                if let Progress::Event(_) = p {
                    bounces += 1;
                }
                ControlFlow::Continue(())
            },
        )
        .unwrap();
        assert_eq!(end, EventEnd::Zeno { event: 0 });
        let t_inf = 3.0 * (2.0 / 9.81 as Real).sqrt();
        assert!((state.t - t_inf).abs() < 1e-12, "{} vs {t_inf}", state.t);
        assert!(bounces > 30, "{bounces}");
    }

    #[test]
    fn a_bad_fixed_step_is_refused() {
        let mut rk4 = crate::ode::Rk4::default();
        let mut state = State::new(0.0, vec![1.0, 0.0]);
        for dt in [0.0, -1.0, Real::NAN, Real::INFINITY] {
            let fixed = Integrator::Fixed {
                stepper: &mut rk4,
                dt,
            };
            let err = run_events(fixed, &Oscillator, &mut state, 1.0, &[], &mut |_| {
                ControlFlow::Continue(())
            });
            assert!(matches!(err, Err(RunError::Fixed(_))), "{dt}: {err:?}");
        }
    }
}
