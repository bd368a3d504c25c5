//! The [`OdeEvent`]s of one step of [`run_events`](super::run_events), through the one event
//! finder ([`Finder`]): how an event is evaluated on the step's interpolant and enclosed over
//! a range of it, the first firing after a time, and the events' sides after a recorded firing
//! or a state change.

use mechkit_expr::interval::{Interval, Jet};

use super::drive::AfterFiring;
use super::event::OdeEvent;
use super::find::{Bounds, Finder, Fired, Rules, Side, sides_after_change};
use crate::Real;
use crate::ode::{State, StepPolynomial};

/// Evenly spaced intervals per step at which an event without an enclosure is sampled.
pub const SAMPLES: usize = 8;

/// The events of a run, their sides and values at the start of the current step, and the
/// finder's buffers.
pub(super) struct StepEvents<'e, 'a> {
    events: &'e [OdeEvent<'a>],
    pub finder: Finder,
    sides: Vec<Side>,
    /// Every event function at the start of the step.
    start: Vec<Real>,
    /// … and at its end.
    end: Vec<Real>,
    /// … and where the scan of the step has reached.
    scan: Vec<Real>,
    /// Scratch: the jets of the state components, a state on the interpolant.
    jets: Vec<Jet>,
    y: Vec<Real>,
}

impl<'e, 'a> StepEvents<'e, 'a> {
    /// The events, starting from `state`.
    pub fn new(events: &'e [OdeEvent<'a>], state: &State) -> Self {
        let start: Vec<Real> = events.iter().map(|e| e.value(state.t, &state.y)).collect();
        Self {
            events,
            finder: Finder::default(),
            sides: start.iter().map(|g| OdeEvent::initial_side(*g)).collect(),
            end: vec![0.0; events.len()],
            scan: Vec::new(),
            start,
            jets: Vec::new(),
            y: vec![0.0; state.y.len()],
        }
    }

    /// Whether there are no events.
    pub fn is_empty(&self) -> bool {
        self.events.is_empty()
    }

    /// Whether event `i` changes the state where it fires.
    pub fn acts(&self, i: usize) -> bool {
        self.events[i].has_action()
    }

    /// Applies event `i`'s action to the state `y` at time `t`.
    pub fn act(&self, i: usize, t: Real, y: &mut [Real]) {
        self.events[i].apply(t, y);
    }

    /// Every event function at `state`.
    pub fn values_at(&self, state: &State) -> Vec<Real> {
        self.events
            .iter()
            .map(|e| e.value(state.t, &state.y))
            .collect()
    }

    /// After a state change by the `fired` events at the event (where the functions were
    /// `g_pre`), to `state` (and `ahead` a moment along its flow): the events' sides
    /// ([`sides_after_change`]: an event the change turned back is armed on the side it came
    /// from) and values start afresh there.
    pub fn changed(&mut self, fired: &[usize], g_pre: &[Real], state: &State, ahead: &State) {
        let g_post = self.values_at(state);
        let g_ahead = self.values_at(ahead);
        let before = self.sides.clone();
        let events = self.events;
        let origin = |i: usize| events[i].crossing_direction().origin(before[i]);
        sides_after_change(
            fired,
            &origin,
            &before,
            (g_pre, &g_post, &g_ahead),
            &mut self.sides,
        );
        self.start = g_post;
    }

    /// Whether event `i` ends the integration.
    pub fn is_terminal(&self, i: usize) -> bool {
        self.events[i].is_terminal()
    }

    /// The event functions at the end of the step that ended at `state` (the finder's
    /// interpolant filled), and the points at which they are sampled inside it.
    pub fn plan(&mut self, state: &State) {
        for (g, e) in self.end.iter_mut().zip(self.events) {
            *g = e.value(state.t, &state.y);
        }
        let mut values = Values {
            events: self.events,
            jets: &mut self.jets,
            y: &mut self.y,
        };
        self.finder
            .plan(&mut values, state.t, SAMPLES - 1, &mut |_| {});
    }

    /// Starts the scan from the step's start; returns its time.
    pub fn begin_scan(&mut self) -> Real {
        self.scan.clone_from(&self.start);
        self.finder.poly.t0()
    }

    /// The first firing after `t_scan` in the step that ends at `t1`.
    pub fn scan_from(&mut self, t_scan: Real, t1: Real) -> Option<Fired> {
        let mut values = Values {
            events: self.events,
            jets: &mut self.jets,
            y: &mut self.y,
        };
        self.finder.first_firing(
            &mut values,
            &mut self.sides,
            (t_scan, &self.scan),
            (t1, &self.end),
        )
    }

    /// The state at time `t` of the step that ended at `state`.
    pub fn state_at(&self, t: Real, state: &State) -> Vec<Real> {
        if t == state.t {
            return state.y.clone();
        }
        let mut y = vec![0.0; state.y.len()];
        interpolate(&self.finder.poly, t, &mut y);
        y
    }

    /// A firing recorded (no terminal event in it) in the step that ends at `t1`: the fired
    /// events are at zero, the others on the side of their values there, and the scan goes on
    /// from its time.
    pub fn recorded(&mut self, fired: Fired, t1: Real) -> AfterFiring {
        let t = fired.firing.t;
        for (i, (side, g)) in self.sides.iter_mut().zip(&fired.values).enumerate() {
            *side = if fired.firing.events.contains(&i) {
                Side::Zero
            } else {
                side.after(*g)
            };
        }
        if t == t1 {
            return AfterFiring::AtStepEnd;
        }
        self.scan = fired.values;
        AfterFiring::ScanFrom(t)
    }

    /// The step's end becomes the start of the next.
    pub fn end_step(&mut self) {
        std::mem::swap(&mut self.start, &mut self.end);
    }
}

/// The events on the step's interpolant, for the finder.
struct Values<'v, 'e, 'a> {
    events: &'e [OdeEvent<'a>],
    jets: &'v mut Vec<Jet>,
    y: &'v mut Vec<Real>,
}

impl Bounds for Values<'_, '_, '_> {
    fn count(&self) -> usize {
        self.events.len()
    }

    fn enabled(&self, _: usize) -> bool {
        true
    }

    fn provable(&self, i: usize) -> bool {
        self.events[i].is_bounded()
    }

    fn enclose(&mut self, i: usize, poly: &StepPolynomial, s: Interval) -> Option<Jet> {
        self.jets.clear();
        self.jets
            .extend((0..poly.len()).map(|k| poly.enclose(k, s)));
        let (t0, h) = (Interval::point(poly.t0()), Interval::point(poly.h()));
        let t = Jet::new(t0 + h * s, Interval::ONE);
        self.events[i].enclose(t, self.jets)
    }
}

impl Rules for Values<'_, '_, '_> {
    fn count(&self) -> usize {
        self.events.len()
    }

    fn enabled(&self, _: usize) -> bool {
        true
    }

    fn fires(&self, i: usize, from: Side, to: Side) -> bool {
        self.events[i].crossing_direction().fires(from, to)
    }

    fn values(&mut self, poly: &StepPolynomial, t: Real, out: &mut [Real]) {
        interpolate(poly, t, self.y);
        for (o, e) in out.iter_mut().zip(self.events) {
            *o = e.value(t, self.y);
        }
    }
}

/// The interpolant at time `t`.
fn interpolate(poly: &StepPolynomial, t: Real, out: &mut [Real]) {
    let s = poly.fraction(t);
    for (i, o) in out.iter_mut().enumerate() {
        *o = poly.value(i, s);
    }
}
