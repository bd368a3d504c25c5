//! An [`OdeSystem`] integrated by an [`AdaptiveRk`] until a terminal event or the end time,
//! with every crossing of every event found inside the steps: a [`Model`] of the one
//! event-aware loop ([`super::drive`]).
//!
//! After every accepted step the step's interpolant is taken as a polynomial
//! ([`AdaptiveRk::dense_polynomial_into`]); the events are sampled on it where their proofs
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
use crate::ode::{AdaptiveError, AdaptiveRk, OdeSystem, State};

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
}

/// Integrates `sys` from `state` with `rk` until a terminal event among `events` fires or
/// until `t_end`, calling `on_progress` after every accepted step and at every crossing of a
/// non-terminal event, in time order; `on_progress` stops the run by returning
/// [`ControlFlow::Break`] ([`EventEnd::Halted`]). The crossing rules are [`OdeEvent`]'s; the event
/// functions' sides start from their values at the start (a zero there is not a crossing).
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
    let mut run = OdeRun {
        step: StepEvents::new(events, state),
        rk,
        sys,
        before: state.clone(),
        state,
        t_end,
        hits: Vec::new(),
        on_progress,
        end: None,
    };
    drive(&mut run)?;
    Ok(run.end.unwrap_or(EventEnd::TimeLimit))
}

/// A run of an [`OdeSystem`] with [`OdeEvent`]s on the one event-aware loop.
struct OdeRun<'r, 'e, 'a, S: ?Sized> {
    rk: &'r mut AdaptiveRk,
    sys: &'r S,
    state: &'r mut State,
    t_end: Real,
    step: StepEvents<'e, 'a>,
    /// The state at the start of the step.
    before: State,
    /// The non-terminal crossings of the step so far.
    hits: Vec<EventHit>,
    on_progress: &'r mut dyn FnMut(Progress<'_>) -> ControlFlow<()>,
    end: Option<EventEnd>,
}

impl<S: OdeSystem + ?Sized> Model for OdeRun<'_, '_, '_, S> {
    type Error = AdaptiveError;

    fn ended(&self) -> bool {
        self.end.is_some()
    }

    fn stops_before_step(&mut self) -> bool {
        if self.state.t >= self.t_end {
            self.end = Some(EventEnd::TimeLimit);
        }
        self.ended()
    }

    fn advance(&mut self) -> Result<bool, AdaptiveError> {
        self.before.clone_from(self.state);
        self.rk.step(self.sys, self.state, self.t_end)?;
        self.hits.clear();
        Ok(false)
    }

    fn any_enabled(&self) -> bool {
        !self.step.is_empty()
    }

    fn plan(&mut self) {
        self.rk
            .dense_polynomial_into(self.sys, &mut self.step.finder.poly);
        self.step.plan(self.state);
    }

    fn begin_scan(&mut self) -> Real {
        self.step.begin_scan()
    }

    fn scan_from(&mut self, t_scan: Real) -> Option<Fired> {
        self.step.scan_from(t_scan, self.state.t)
    }

    fn end_scan(&mut self) {}

    fn fire(&mut self, fired: Fired) -> Result<AfterFiring, AdaptiveError> {
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
        if let Some(event) = terminal {
            let flow = redo(
                self.rk,
                self.sys,
                self.state,
                &self.before,
                t,
                &self.hits,
                self.on_progress,
            )?;
            self.end = Some(match flow {
                ControlFlow::Continue(()) => EventEnd::Terminal { event },
                ControlFlow::Break(()) => EventEnd::Halted,
            });
            return Ok(AfterFiring::Cut);
        }
        Ok(self.step.recorded(fired, self.state.t))
    }

    fn finish_step(&mut self, _event_at_end: bool) -> Result<(), AdaptiveError> {
        self.step.end_step();
        let (_, flow) = report(&self.hits, Real::INFINITY, self.on_progress);
        if flow.is_break() || (self.on_progress)(Progress::Step(self.state)).is_break() {
            self.end = Some(EventEnd::Halted);
        }
        Ok(())
    }
}

/// Redoes the step from `before` to end exactly at `t_star`, reporting its steps and the
/// `hits` in time order (the last state reported even when no step was needed); stops early
/// when `on_progress` says so.
fn redo<S: OdeSystem + ?Sized>(
    rk: &mut AdaptiveRk,
    sys: &S,
    state: &mut State,
    before: &State,
    t_star: Real,
    hits: &[EventHit],
    on_progress: &mut dyn FnMut(Progress<'_>) -> ControlFlow<()>,
) -> Result<ControlFlow<()>, AdaptiveError> {
    state.clone_from(before);
    rk.reset();
    let mut reported = 0;
    while state.t < t_star {
        rk.step(sys, state, t_star)?;
        if state.t < t_star {
            let (n, flow) = report(&hits[reported..], state.t, on_progress);
            reported += n;
            if flow.is_break() || on_progress(Progress::Step(state)).is_break() {
                return Ok(ControlFlow::Break(()));
            }
        }
    }
    let (_, flow) = report(&hits[reported..], Real::INFINITY, on_progress);
    if flow.is_break() {
        return Ok(flow);
    }
    Ok(on_progress(Progress::Step(state)))
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
}
