//! Finding the first event firing inside a step: the event functions are evaluated at the
//! ends and at interior points of the step's interpolant (the points [`super::prove`] has
//! shown to be enough), and the first sign change in the direction of an event is located
//! by Brent's method.

use super::event::{Event, Side};
use crate::Real;
use crate::roots::brent_with_values;

/// Events firing together at one instant.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Firing {
    pub t: Real,
    /// Indices of the events, in declaration order.
    pub events: Vec<usize>,
}

/// Events fire at `firing.t`; `values` holds every event function there.
pub(crate) struct Fired {
    pub firing: Firing,
    pub values: Vec<Real>,
}

/// Buffers reused from step to step.
#[derive(Debug, Default)]
pub(crate) struct ScanBuffers {
    prev: Vec<Real>,
    vals: Vec<Real>,
}

/// Scans `(t_a, t_b]`: `sides` are the events' sides at `t_a`, `g_a`/`g_b` their values at the
/// ends (NaN where unknown), `points` the interior sample times (sorted; those outside
/// `(t_a, t_b)` are skipped), and
/// `values(t, out)` evaluates every event function at `t` on the interpolant. Disabled events
/// never fire. `sides` follows the scan: the sides at `t_b` when nothing fires (`None`), at
/// the last sample point before the firing otherwise.
#[allow(clippy::too_many_arguments)]
pub(crate) fn scan(
    events: &[Event],
    enabled: &[bool],
    sides: &mut [Side],
    (t_a, g_a): (Real, &[Real]),
    (t_b, g_b): (Real, &[Real]),
    points: &[Real],
    values: &mut dyn FnMut(Real, &mut [Real]),
    buffers: &mut ScanBuffers,
) -> Option<Fired> {
    let m = events.len();
    let cur = sides;
    let ScanBuffers { prev, vals } = buffers;
    let prev_vals = prev;
    prev_vals.clear();
    prev_vals.extend_from_slice(g_a);
    vals.clear();
    vals.resize(m, Real::NAN);
    let mut t_prev = t_a;
    let inside = points.iter().copied().filter(|t| *t > t_a && *t < t_b);
    for t_j in inside.chain(std::iter::once(t_b)) {
        if t_j == t_b {
            vals.copy_from_slice(g_b);
        } else {
            values(t_j, vals);
        }
        let mut first: Option<(Real, Vec<usize>)> = None;
        for i in (0..m).filter(|&i| enabled[i]) {
            let to = cur[i].after(vals[i]);
            if !events[i].fires(cur[i], to) {
                continue;
            }
            let te = if left_armed(cur[i], prev_vals[i]) {
                // re-armed by a state change that turned the function back (a bounce) while
                // it still sits at or past zero: its next arrival is found after its
                // excursion to the armed side, or at once when none can be resolved
                excursion_end((i, m), cur[i], (t_prev, t_j), vals[i], values)
            } else if to == Side::Zero {
                t_j
            } else if matches!(cur[i], Side::Zero | Side::StartZero) || prev_vals[i] == 0.0 {
                t_prev
            } else {
                let tol = 2.0 * Real::EPSILON * t_prev.abs().max(t_j.abs());
                let mut buf = vec![0.0; m];
                brent_with_values(
                    |t| {
                        values(t, &mut buf);
                        buf[i]
                    },
                    t_prev,
                    t_j,
                    Some((prev_vals[i], vals[i])),
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
        if let Some((te, mut list)) = first {
            // the values at the instant, and any other event that fires exactly there
            let at = if te == t_j {
                vals.clone()
            } else if te == t_prev {
                prev_vals.clone()
            } else {
                let mut v = vec![0.0; m];
                values(te, &mut v);
                v
            };
            let also: Vec<usize> = (0..m)
                .filter(|&i| enabled[i] && !list.contains(&i))
                .filter(|&i| events[i].fires(cur[i], cur[i].after(at[i])))
                .collect();
            list.extend(also);
            list.sort_unstable();
            return Some(Fired {
                firing: Firing {
                    t: te,
                    events: list,
                },
                values: at,
            });
        }
        for i in 0..m {
            cur[i] = cur[i].after(vals[i]);
        }
        prev_vals.copy_from_slice(vals);
        t_prev = t_j;
    }
    None
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

/// The end of the excursion of event `i`'s function (of `m`) to `side` that starts at `t_prev` (where
/// the function is not on `side` yet) and is over by `t_j` (value `g_j`, not on `side`): the
/// interval is halved towards `t_prev` until a point on `side` is found, and the return to
/// zero after it is located by Brent's method. When no representable time after `t_prev`
/// shows the function on `side`, the excursion is too short to resolve and the event fires
/// again at `t_prev` (the book reads it as an accumulation of occurrences: Zeno).
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
mod tests {
    use super::*;
    use crate::simulate::Direction;

    fn even(interior: usize) -> Vec<Real> {
        (1..=interior)
            .map(|j| j as Real / (interior + 1) as Real)
            .collect()
    }

    fn run(f: impl Fn(Real) -> Real, d: Direction, interior: usize) -> Vec<Real> {
        let points = even(interior);
        let events = [Event::new("g", |_, _| 0.0).direction(d)];
        let (t_a, t_b) = (0.0, 1.0);
        let mut sides = vec![events[0].initial_side(f(t_a))];
        let mut t = t_a;
        let mut found = Vec::new();
        let mut values = |t: Real, out: &mut [Real]| out[0] = f(t);
        let mut buffers = ScanBuffers::default();
        loop {
            let fired = scan(
                &events,
                &[true],
                &mut sides,
                (t, &[f(t)]),
                (t_b, &[f(t_b)]),
                &points,
                &mut values,
                &mut buffers,
            );
            match fired {
                Some(Fired { firing, .. }) => {
                    found.push(firing.t);
                    t = firing.t;
                    sides = vec![Side::Zero];
                }
                None => return found,
            }
        }
    }

    #[test]
    fn finds_every_root_of_a_cubic_in_one_step() {
        // roots at 0.2, 0.5, 0.8 (the case of SciPy issue #9228, scaled to one step)
        let f = |t: Real| (t - 0.2) * (t - 0.5) * (t - 0.8);
        let found = run(f, Direction::Both, 7);
        assert_eq!(found.len(), 3, "{found:?}");
        for (t, want) in found.iter().zip([0.2, 0.5, 0.8]) {
            assert!((t - want).abs() < 1e-15, "{t} vs {want}");
        }
        // only the sign changes the direction asks for
        assert_eq!(run(f, Direction::Rising, 7).len(), 2);
        assert_eq!(run(f, Direction::Falling, 7).len(), 1);
    }

    #[test]
    fn a_root_on_the_step_end_fires_once_there() {
        let found = run(|t| t - 1.0, Direction::Both, 3);
        assert_eq!(found, vec![1.0]);
    }

    /// Scans `(0, 1]` for a falling event armed above zero (after a bounce) from `f(0)`.
    fn armed(f: impl Fn(Real) -> Real) -> Option<Real> {
        let events = [Event::new("g", |_, _| 0.0).direction(Direction::Falling)];
        let mut sides = vec![Side::Pos];
        let mut values = |t: Real, out: &mut [Real]| out[0] = f(t);
        scan(
            &events,
            &[true],
            &mut sides,
            (0.0, &[f(0.0)]),
            (1.0, &[f(1.0)]),
            &even(7),
            &mut values,
            &mut ScanBuffers::default(),
        )
        .map(|fired| fired.firing.t)
    }

    #[test]
    fn an_armed_event_finds_an_excursion_no_sample_sees() {
        // just below zero after a bounce, up and back down by t = 2e-4, far before the first
        // sample at 1/8: the return is located
        let t = armed(|t| -1e-30 + 1e-4 * t - 0.5 * t * t).unwrap();
        assert!((t - 2e-4).abs() < 1e-16, "{t}");
        // no excursion the time grid can show: fires again at once (the book's Zeno)
        assert_eq!(armed(|t| -1e-30 - t), Some(0.0));
    }

    #[test]
    fn a_root_at_the_start_fires_when_leaving_in_the_direction() {
        assert_eq!(run(|t| t, Direction::Rising, 3), vec![0.0]);
        assert!(run(|t| t, Direction::Falling, 3).is_empty());
        assert!(run(|t| -t, Direction::Rising, 3).is_empty());
    }
}
