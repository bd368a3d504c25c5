//! The events of one step: where each event function must be sampled on the step's
//! interpolant so that no sign change is missed, and the first crossings, located by Brent's
//! method.
//!
//! For an event with an enclosure the step is cut into pieces proven sign-definite, monotone or
//! at rounding level ([`StepProof`]); the ends of every piece that is not sign-definite are
//! sample points, so every sign change of odd multiplicity of `g` along the interpolant shows
//! between two consecutive samples. An event without an enclosure, or whose proof needs more
//! than [`MAX_BOUNDS`](crate::ode::MAX_BOUNDS) enclosures, is sampled at
//! [`SAMPLES`] evenly spaced points instead. All events are evaluated at the union of the
//! points, the interpolant at the exact step end being replaced by the state the step reached.

use mechkit_expr::interval::{Interval, Jet};

use super::event::{OdeEvent, Side};
use crate::Real;
use crate::ode::{ProofOutcome, StepPolynomial, StepProof};
use crate::roots::brent_with_values;

/// Evenly spaced intervals per step at which an event without an enclosure is sampled.
pub const SAMPLES: usize = 8;

/// A crossing inside a step: `(t, index of the event)`.
pub(super) type Firing = (Real, usize);

/// Buffers reused from step to step, and the events' sides and values at the step start.
#[derive(Debug, Default)]
pub(super) struct Scanner {
    /// The interpolant of the step being scanned.
    pub poly: StepPolynomial,
    proof: StepProof,
    fractions: Vec<Real>,
    points: Vec<Real>,
    jets: Vec<Jet>,
    y: Vec<Real>,
    /// Every event function at the start of the step.
    start: Vec<Real>,
    vals: Vec<Real>,
    sides: Vec<Side>,
    /// The non-terminal crossings of the last scan, in time order.
    pub firings: Vec<Firing>,
}

impl Scanner {
    /// Buffers for `events`, starting from `(t, y)`.
    pub fn new(events: &[OdeEvent<'_>], t: Real, y: &[Real]) -> Self {
        let start: Vec<Real> = events.iter().map(|e| e.value(t, y)).collect();
        Self {
            sides: start.iter().map(|g| Side::of(*g)).collect(),
            vals: vec![0.0; events.len()],
            y: vec![0.0; y.len()],
            start,
            ..Self::default()
        }
    }

    /// The interpolated state at time `t` of the step.
    pub fn state_at(&mut self, t: Real) -> &[Real] {
        interpolate(&self.poly, t, &mut self.y);
        &self.y
    }

    /// Scans the step of [`Scanner::poly`], which ended at `(t1, y1)`: the non-terminal
    /// crossings before the first terminal one go to [`Scanner::firings`] in time order, and
    /// the terminal one, if any, is returned. Without one the sides and values move on to the
    /// step end.
    pub fn scan(&mut self, events: &[OdeEvent<'_>], t1: Real, y1: &[Real]) -> Option<Firing> {
        self.firings.clear();
        self.sample_points(events, t1);
        let t0 = self.poly.t0;
        let mut t_prev = t0;
        for j in 0..=self.points.len() {
            let t_j = self.points.get(j).copied().unwrap_or(t1);
            if t_j == t1 {
                fill(events, t1, y1, &mut self.vals);
            } else {
                interpolate(&self.poly, t_j, &mut self.y);
                fill(events, t_j, &self.y, &mut self.vals);
            }
            let first = self.firings.len();
            for (i, event) in events.iter().enumerate() {
                let (g_prev, g) = (self.start[i], self.vals[i]);
                if !event.fires(self.sides[i], g) {
                    self.sides[i] = self.sides[i].after(g);
                    continue;
                }
                let t = if g == 0.0 {
                    t_j
                } else if g_prev == 0.0 {
                    t_prev
                } else {
                    let (poly, y) = (&self.poly, &mut self.y);
                    let g_at = |t: Real| {
                        interpolate(poly, t, y);
                        event.value(t, y)
                    };
                    let tol = 4.0 * Real::EPSILON * t_j.abs().max(t_j - t_prev);
                    brent_with_values(g_at, t_prev, t_j, Some((g_prev, g)), tol).unwrap_or(t_j)
                };
                self.firings.push((t, i));
                self.sides[i] = if g == 0.0 { Side::Unknown } else { Side::of(g) };
            }
            let found = &mut self.firings[first..];
            found.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            if let Some(&terminal) = found.iter().find(|f| events[f.1].is_terminal()) {
                // the crossings of earlier intervals all come before it
                self.firings
                    .retain(|f| !events[f.1].is_terminal() && f.0 <= terminal.0);
                return Some(terminal);
            }
            std::mem::swap(&mut self.start, &mut self.vals);
            t_prev = t_j;
        }
        None
    }

    /// The sorted times strictly inside the step at which the events must be sampled.
    fn sample_points(&mut self, events: &[OdeEvent<'_>], t1: Real) {
        let Self {
            poly,
            proof,
            fractions,
            points,
            jets,
            ..
        } = self;
        fractions.clear();
        let (t0, h) = (poly.t0, poly.h);
        let n = poly.len();
        let mut uniform = false;
        for event in events {
            if !event.is_bounded() {
                uniform = true;
                continue;
            }
            let outcome = proof.cut(t0, h, &mut |s| {
                jets.clear();
                jets.extend((0..n).map(|i| poly.enclose(i, s)));
                let t = Jet::new(Interval::point(t0) + Interval::point(h) * s, Interval::ONE);
                event.enclose(t, jets)
            });
            match outcome {
                ProofOutcome::Proven => proof.sample_fractions_into(fractions),
                ProofOutcome::OutOfBounds | ProofOutcome::NotBounded => uniform = true,
            }
        }
        if uniform {
            fractions.extend((1..SAMPLES).map(|j| j as Real / SAMPLES as Real));
        }
        points.clear();
        points.extend(fractions.iter().map(|s| t0 + s * h));
        points.retain(|t| *t > t0 && *t < t1);
        points.sort_by(Real::total_cmp);
        points.dedup();
    }
}

/// Every event function at `(t, y)`.
fn fill(events: &[OdeEvent<'_>], t: Real, y: &[Real], out: &mut [Real]) {
    for (o, e) in out.iter_mut().zip(events) {
        *o = e.value(t, y);
    }
}

/// The interpolant at time `t`.
fn interpolate(poly: &StepPolynomial, t: Real, out: &mut [Real]) {
    let s = poly.fraction(t);
    for (i, o) in out.iter_mut().enumerate() {
        *o = poly.value(i, s);
    }
}
