//! The one event finder: inside one step, where the event functions must be sampled so that no
//! sign change along the step's interpolant is missed, and the first firing after a given
//! time, located by Brent's method. Both loops that run events use it: the particles'
//! (`simulate`) and the one of any [`OdeSystem`](crate::ode::OdeSystem)
//! ([`run_to_event`](super::run_to_event)); what differs between them (how an event function
//! is evaluated inside the step, enclosed over a range of it, and which changes of side fire
//! it) is behind [`Bounds`] and [`Rules`].
//!
//! **The sample points** ([`Finder::plan`]). For an event whose function `g` can be enclosed
//! over a range of the step, the step is cut into pieces proven sign-definite, monotone or at
//! rounding level ([`StepProof`]); the ends of every piece that is not sign-definite become
//! sample points. So every sign change of odd multiplicity of `g` along the interpolant shows
//! as a sign change between two consecutive samples, however short the excursion, and however
//! many per step. A zero of even multiplicity (a touch) is no sign change: it does not fire.
//! An event that cannot be enclosed is sampled at evenly spaced points (as many as its caller
//! says), as is a step whose proof needs more than [`MAX_BOUNDS`](crate::ode::MAX_BOUNDS)
//! enclosures ([`FALLBACK_SAMPLES`], reported to the caller to warn).
//!
//! **The first firing** ([`Finder::first_firing`]). The functions are evaluated at the points
//! in time order and the step's end; between two consecutive samples each event's side moves
//! on ([`Side::after`]), and a change of side that fires the event ([`Rules::fires`]) is
//! located by Brent's method on the interpolant. An event re-armed by a state change that
//! turned its function back (a bounce) while it still sits at or past zero is found after its
//! excursion to the armed side, however short.

use mechkit_expr::interval::{Interval, Jet};

use crate::Real;
use crate::ode::{ProofOutcome, StepPolynomial, StepProof};
use crate::roots::brent_with_values;

/// Evenly spaced interior samples of an event whose proof ran out of enclosures in a step.
pub const FALLBACK_SAMPLES: usize = 64;

/// Most interior samples an event that cannot be enclosed may ask for in one step.
const MAX_INTERIOR: usize = 100_000;

/// Where an event function is relative to zero.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Side {
    /// Negative.
    Neg,
    /// At zero, already counted (or left alone): leaving it does not fire.
    Zero,
    /// Positive.
    Pos,
    /// Exactly zero at the start of a run whose rules count leaving it in the event's
    /// direction (the particles' events), or after a state change that left it at zero with
    /// no rate: leaving it in that direction fires, at the start of the step it stayed at
    /// zero from (values that stay at zero keep this side).
    StartZero,
    /// Not known yet (NaN so far).
    Unknown,
}

impl Side {
    /// The side of a value (`None` for NaN).
    pub(crate) fn of(g: Real) -> Option<Side> {
        if g < 0.0 {
            Some(Side::Neg)
        } else if g > 0.0 {
            Some(Side::Pos)
        } else if g == 0.0 {
            Some(Side::Zero)
        } else {
            None
        }
    }

    /// The side after a value `g`, from the side before (NaN keeps the old side; a function
    /// still at zero since the start is still as at the start: leaving zero later the way
    /// the event fires fires it, as leaving it at once would).
    pub(crate) fn after(self, g: Real) -> Side {
        match Side::of(g) {
            Some(Side::Zero) if self == Side::StartZero => Side::StartZero,
            Some(s) => s,
            None => self,
        }
    }
}

/// The sides of the events right after a state change: `fired` fired, `before` are the
/// sides just before the firing, `g_pre` the values at the event before the change, `g_post`
/// after it and `g_ahead` a moment later along the flow; `origin(i)` is the side fired event
/// `i` comes from (positive for a falling event, negative for a rising one). A fired event
/// whose function the change turned back towards its origin, while leaving it where it was
/// (at the located zero, to rounding: a bounce changes the velocity, not the height) or on that
/// side, is armed on that side: its next arrival at zero fires, however short the excursion
/// ([`Finder::first_firing`] finds it, or fires at once when none can be resolved). Any other
/// fired event is at zero (leaving it does not fire: a kick along, or a jump elsewhere), and
/// the others keep their sides.
pub(crate) fn sides_after_change(
    fired: &[usize],
    origin: &dyn Fn(usize) -> Side,
    before: &[Side],
    (g_pre, g_post, g_ahead): (&[Real], &[Real], &[Real]),
    out: &mut [Side],
) {
    for (i, side) in out.iter_mut().enumerate() {
        *side = if fired.contains(&i) {
            let origin = origin(i);
            let rate = g_ahead[i] - g_post[i];
            let (turned_back, on_origin) = match origin {
                Side::Pos => (rate > 0.0, g_post[i] > 0.0),
                Side::Neg => (rate < 0.0, g_post[i] < 0.0),
                _ => (false, false),
            };
            let in_place = g_post[i] == g_pre[i] || g_post[i] == 0.0;
            if turned_back && (in_place || on_origin) {
                origin
            } else {
                Side::Zero
            }
        } else if g_post[i] == 0.0 {
            Side::Zero
        } else {
            before[i].after(g_post[i])
        };
    }
}

/// How the events of a step are bounded, for [`Finder::plan`].
pub(crate) trait Bounds {
    /// Number of events.
    fn count(&self) -> usize;
    /// Whether event `i` can still fire (a disabled one is not sampled).
    fn enabled(&self, i: usize) -> bool;
    /// Whether event `i` has an enclosure at all (if not, it is sampled evenly).
    fn provable(&self, i: usize) -> bool;
    /// An enclosure of event `i`'s function and of its time derivative over the fractions `s`
    /// of the step whose interpolant is `poly` (`None`: it cannot be bounded there).
    fn enclose(&mut self, i: usize, poly: &StepPolynomial, s: Interval) -> Option<Jet>;
    /// A level within which changes of sign of event `i`'s enclosed function are not counted
    /// (both samples of a change within it: see [`Rules::significant`]): a piece of the step
    /// enclosed within it need not be cut further (0, the default: no such level).
    fn noise(&self, _i: usize) -> Real {
        0.0
    }
    /// Evenly spaced interior samples event `i` asks for in this step, at least (a contact
    /// between fast bodies asks for more).
    fn samples_asked(&self, _i: usize) -> usize {
        0
    }
}

/// How the events of a step are evaluated and when they fire, for [`Finder::first_firing`].
pub(crate) trait Rules {
    /// Number of events.
    fn count(&self) -> usize;
    /// Whether event `i` can still fire.
    fn enabled(&self, i: usize) -> bool;
    /// Whether event `i` going from side `from` to side `to` fires it.
    fn fires(&self, i: usize, from: Side, to: Side) -> bool;
    /// Every event function at time `t` inside the step whose interpolant is `poly`.
    fn values(&mut self, poly: &StepPolynomial, t: Real, out: &mut [Real]);
    /// Whether a change of side of event `i` between consecutive samples `g_prev` and `g` is
    /// more than noise (a model that watches a quantity jittering at rounding level about
    /// zero says no when both are); every change is, unless said otherwise.
    fn significant(&self, _i: usize, _g_prev: Real, _g: Real) -> bool {
        true
    }
}

/// Events firing together at one instant.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Firing {
    pub t: Real,
    /// Indices of the events, in declaration order.
    pub events: Vec<usize>,
}

/// Events fire at `firing.t`; `values` holds every event function there.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Fired {
    pub firing: Firing,
    pub values: Vec<Real>,
}

/// The step's interpolant, its sample points, and the buffers of the proofs and of the scan,
/// reused from step to step.
#[derive(Debug, Default)]
pub(crate) struct Finder {
    /// The interpolant of the step being scanned (the caller fills it).
    pub poly: StepPolynomial,
    proof: StepProof,
    fractions: Vec<Real>,
    /// The sorted times strictly inside the step at which the events are sampled.
    pub points: Vec<Real>,
    prev: Vec<Real>,
    vals: Vec<Real>,
}

impl Finder {
    /// Sets [`Finder::points`] for the step of [`Finder::poly`], which ended at `t1`: the
    /// ends of the pieces that are not sign-definite for the events that can be enclosed, and
    /// evenly spaced samples for the others (`default_interior`, or as many as they ask for).
    /// `ran_out(i)` is told of each event whose proof needed more than
    /// [`MAX_BOUNDS`](crate::ode::MAX_BOUNDS) enclosures, sampled at [`FALLBACK_SAMPLES`]
    /// points instead.
    pub fn plan<B: Bounds + ?Sized>(
        &mut self,
        bounds: &mut B,
        t1: Real,
        default_interior: usize,
        ran_out: &mut dyn FnMut(usize),
    ) {
        self.fractions.clear();
        let (t0, h) = (self.poly.t0(), self.poly.h());
        let mut uniform = 0;
        for i in 0..bounds.count() {
            if !bounds.enabled(i) {
                continue;
            }
            let asked = bounds.samples_asked(i).min(MAX_INTERIOR);
            let outcome = if bounds.provable(i) {
                let poly = &self.poly;
                let noise = bounds.noise(i);
                self.proof
                    .cut(t0, h, noise, &mut |s| bounds.enclose(i, poly, s))
            } else {
                ProofOutcome::NotBounded
            };
            match outcome {
                ProofOutcome::Proven => self.proof.sample_fractions_into(&mut self.fractions),
                ProofOutcome::OutOfBounds => {
                    ran_out(i);
                    uniform = uniform.max(FALLBACK_SAMPLES).max(asked);
                }
                ProofOutcome::NotBounded => uniform = uniform.max(default_interior).max(asked),
            }
        }
        for j in 1..=uniform {
            self.fractions.push(j as Real / (uniform + 1) as Real);
        }
        self.points.clear();
        self.points
            .extend(self.fractions.iter().map(|s| t0 + s * h));
        self.points.retain(|t| *t > t0 && *t < t1);
        self.points.sort_by(Real::total_cmp);
        self.points.dedup();
    }

    /// The first firing in `(t_a, t_b]`, the step's end being `t_b`: `sides` are the events'
    /// sides at `t_a`, `g_a`/`g_b` their values at `t_a` and at the end (NaN where unknown);
    /// the functions are sampled at [`Finder::points`] after `t_a`. `sides` follows the scan:
    /// the sides at `t_b` when nothing fires (`None`), at the last sample point before the
    /// firing otherwise.
    pub fn first_firing<R: Rules + ?Sized>(
        &mut self,
        rules: &mut R,
        sides: &mut [Side],
        (t_a, g_a): (Real, &[Real]),
        (t_b, g_b): (Real, &[Real]),
    ) -> Option<Fired> {
        let m = rules.count();
        let Finder {
            poly,
            points,
            prev,
            vals,
            ..
        } = self;
        prev.clear();
        prev.extend_from_slice(g_a);
        vals.clear();
        vals.resize(m, Real::NAN);
        let mut t_prev = t_a;
        let inside = points.iter().copied().filter(|t| *t > t_a && *t < t_b);
        for t_j in inside.chain(std::iter::once(t_b)) {
            if t_j == t_b {
                vals.copy_from_slice(g_b);
            } else {
                rules.values(poly, t_j, vals);
            }
            let mut first: Option<(Real, Vec<usize>)> = None;
            for i in 0..m {
                if !rules.enabled(i) {
                    continue;
                }
                let to = sides[i].after(vals[i]);
                if !rules.fires(i, sides[i], to) || !rules.significant(i, prev[i], vals[i]) {
                    continue;
                }
                let te = if left_armed(sides[i], prev[i]) {
                    // re-armed by a state change that turned the function back (a bounce)
                    // while it still sits at or past zero: its next arrival is found after its
                    // excursion to the armed side, or at once when none can be resolved
                    excursion_end((i, m), sides[i], (t_prev, t_j), vals[i], &mut |t, out| {
                        rules.values(poly, t, out);
                    })
                } else if to == Side::Zero {
                    t_j
                } else if sides[i] == Side::StartZero {
                    // at zero since the step began (the run's start, or a change that left
                    // it there with no rate): it left zero when it could first have, as
                    // nothing inside the zero band tells when it did
                    t_a
                } else if sides[i] == Side::Zero || prev[i] == 0.0 {
                    t_prev
                } else {
                    let tol = 2.0 * Real::EPSILON * t_prev.abs().max(t_j.abs());
                    let mut buf = vec![0.0; m];
                    brent_with_values(
                        |t| {
                            rules.values(poly, t, &mut buf);
                            buf[i]
                        },
                        t_prev,
                        t_j,
                        Some((prev[i], vals[i])),
                        tol,
                    )
                    .unwrap_or(t_j)
                };
                match &mut first {
                    Some((t, list)) if te == *t => list.push(i),
                    Some((t, _)) if te > *t => {}
                    _ => first = Some((te, vec![i])),
                }
            }
            if let Some((te, list)) = first {
                return Some(firing_at(
                    rules,
                    poly,
                    sides,
                    (te, list),
                    (t_prev, prev),
                    (t_j, vals),
                ));
            }
            for i in 0..m {
                sides[i] = sides[i].after(vals[i]);
            }
            prev.copy_from_slice(vals);
            t_prev = t_j;
        }
        None
    }
}

/// The firing at `te` of the events in `list`, found between the samples at `t_prev` and
/// `t_j`: the values there, and any other event that fires exactly there.
fn firing_at<R: Rules + ?Sized>(
    rules: &mut R,
    poly: &StepPolynomial,
    sides: &[Side],
    (te, mut list): (Real, Vec<usize>),
    (t_prev, prev): (Real, &[Real]),
    (t_j, vals): (Real, &[Real]),
) -> Fired {
    let m = rules.count();
    let at = if te == t_j {
        vals.to_vec()
    } else if te == t_prev {
        prev.to_vec()
    } else {
        let mut v = vec![0.0; m];
        rules.values(poly, te, &mut v);
        v
    };
    let also: Vec<usize> = (0..m)
        .filter(|&i| rules.enabled(i) && !list.contains(&i))
        .filter(|&i| rules.fires(i, sides[i], sides[i].after(at[i])))
        .collect();
    list.extend(also);
    list.sort_unstable();
    Fired {
        firing: Firing {
            t: te,
            events: list,
        },
        values: at,
    }
}

/// Whether an event armed on side `side` (by a state change that turned its function back)
/// starts a sample interval at a value `g` that is not on that side yet.
fn left_armed(side: Side, g: Real) -> bool {
    match side {
        Side::Pos => g <= 0.0,
        Side::Neg => g >= 0.0,
        Side::Zero | Side::StartZero | Side::Unknown => false,
    }
}

/// Most halvings of a sample interval in the search for an excursion.
const MAX_HALVINGS: usize = 200;

/// The end of the excursion of event `i`'s function (of `m`) to `side` that starts at `t_prev`
/// (where the function is not on `side` yet) and is over by `t_j` (value `g_j`, not on
/// `side`): the interval is halved towards `t_prev` until a point on `side` is found, and the
/// return to zero after it is located by Brent's method. When no representable time after
/// `t_prev` shows the function on `side`, the excursion is too short to resolve and the event
/// fires again at `t_prev` (the particles' book reads it as an accumulation of occurrences:
/// Zeno).
fn excursion_end(
    (i, m): (usize, usize),
    side: Side,
    (t_prev, t_j): (Real, Real),
    g_j: Real,
    values: &mut dyn FnMut(Real, &mut [Real]),
) -> Real {
    let mut buf = vec![Real::NAN; m];
    let mut value_at = |t: Real, buf: &mut Vec<Real>| {
        values(t, buf);
        buf[i]
    };
    let on_side = |g: Real| match side {
        Side::Pos => g > 0.0,
        _ => g < 0.0,
    };
    let (mut hi, mut g_hi) = (t_j, g_j);
    let mut off = (t_j - t_prev) / 2.0;
    for _ in 0..MAX_HALVINGS {
        let s = t_prev + off;
        if s <= t_prev || s >= hi {
            break;
        }
        let g = value_at(s, &mut buf);
        if on_side(g) {
            let tol = 2.0 * Real::EPSILON * s.abs().max(hi.abs());
            return brent_with_values(|t| value_at(t, &mut buf), s, hi, Some((g, g_hi)), tol)
                .unwrap_or(hi);
        }
        (hi, g_hi) = (s, g);
        off /= 2.0;
    }
    t_prev
}

#[cfg(test)]
#[path = "find_tests.rs"]
mod tests;
