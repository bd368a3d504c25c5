//! The events of one step of [`run_to_event`](super::run_to_event), through the one event
//! finder ([`Finder`]): how an [`OdeEvent`] is evaluated on the step's interpolant and
//! enclosed over a range of it, and the crossings of the step in time order, up to the first
//! terminal one.

use mechkit_expr::interval::{Interval, Jet};

use super::driver::EventHit;
use super::event::OdeEvent;
use super::find::{Bounds, Finder, Rules, Side};
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
            start,
            jets: Vec::new(),
            y: vec![0.0; state.y.len()],
        }
    }

    /// Scans the step of the finder's interpolant, which ended at `state`: the crossings of
    /// non-terminal events before the first terminal one (and at its time) go to `hits` in
    /// time order, and the terminal one, `(t, event)`, is returned. Without one, the sides and
    /// values move on to the step's end.
    pub fn scan(&mut self, state: &State, hits: &mut Vec<EventHit>) -> Option<(Real, usize)> {
        hits.clear();
        let (t1, y1) = (state.t, &state.y[..]);
        for (g, e) in self.end.iter_mut().zip(self.events) {
            *g = e.value(t1, y1);
        }
        let mut values = Values {
            events: self.events,
            jets: &mut self.jets,
            y: &mut self.y,
        };
        self.finder.plan(&mut values, t1, SAMPLES - 1, &mut |_| {});
        let (mut t_scan, mut g_scan) = (self.finder.poly.t0(), self.start.clone());
        let mut terminal = None;
        while let Some(fired) = self.finder.first_firing(
            &mut values,
            &mut self.sides,
            (t_scan, &g_scan),
            (t1, &self.end),
        ) {
            let t = fired.firing.t;
            let y = if t == t1 {
                y1.to_vec()
            } else {
                let mut y = vec![0.0; y1.len()];
                interpolate(&self.finder.poly, t, &mut y);
                y
            };
            for &i in &fired.firing.events {
                if self.events[i].is_terminal() {
                    terminal = terminal.or(Some((t, i)));
                } else {
                    hits.push(EventHit {
                        event: i,
                        t,
                        y: y.clone(),
                    });
                }
            }
            if terminal.is_some() {
                return terminal;
            }
            for (i, (side, g)) in self.sides.iter_mut().zip(&fired.values).enumerate() {
                *side = if fired.firing.events.contains(&i) {
                    Side::Zero
                } else {
                    side.after(*g)
                };
            }
            if t == t1 {
                break;
            }
            (t_scan, g_scan) = (t, fired.values);
        }
        std::mem::swap(&mut self.start, &mut self.end);
        None
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
