//! A body runs on a curve only where the curve is smooth: its equation of motion uses `y'` and
//! `y''`, so where `y` jumps (`floor(x)`) or its slope does (`abs(x)`: a kink) the symbolic
//! derivatives say nothing of the jump (the derivative of `floor` is 0), and the body would go
//! down a step at constant speed, creating or destroying energy. Over each step of the run the
//! graph's `y` and `y'` are enclosed by interval arithmetic ([`Jet`]: its derivative bound is
//! ENTIRE where a step function may change); where one may jump, the interval is bisected down
//! to the point, and a jump of `y` or `y'` that is more than rounding there stops the run.

use super::curve::Curve;
use crate::Real;
use crate::interval::{Interval, Jet};

/// What is not smooth at a point of a graph.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Break {
    /// `y` jumps, by this much (m).
    Jump(Real),
    /// `y'` jumps (a kink), by this much.
    Kink(Real),
}

/// Bisections down to a break: 2⁻⁶⁰ of the step's width.
const DEPTH: u32 = 60;

/// The first break in `[lo, hi]`: halves where `may_jump` cannot rule one out, down to
/// `depth` halvings, where `jump` measures it.
fn search(
    lo: Real,
    hi: Real,
    depth: u32,
    may_jump: &dyn Fn(Real, Real) -> bool,
    jump: &dyn Fn(Real, Real) -> Option<Break>,
) -> Option<(Real, Break)> {
    if !may_jump(lo, hi) {
        return None;
    }
    let mid = lo.midpoint(hi);
    if depth == 0 || mid <= lo || mid >= hi {
        return jump(lo, hi).map(|j| (mid, j));
    }
    search(lo, mid, depth - 1, may_jump, jump)
        .or_else(|| search(mid, hi, depth - 1, may_jump, jump))
}

impl Curve {
    /// The first point between `a` and `b` where a graph's `y` or `y'` jumps, with the jump;
    /// `None` for a circle, a graph whose formulas do not compile, or a smooth stretch.
    pub(super) fn break_between(&self, a: Real, b: Real) -> Option<(Real, Break)> {
        let programs = self.programs()?;
        let (lo, hi) = (a.min(b), a.max(b));
        if !(lo.is_finite() && hi.is_finite()) || lo == hi {
            return None;
        }
        let may_jump = |lo: Real, hi: Real| {
            let x = [Jet::variable(Interval::new(lo, hi))];
            programs[0].eval_jet(&x).d.is_entire() || programs[1].eval_jet(&x).d.is_entire()
        };
        let jump = |lo: Real, hi: Real| {
            let f = |k: usize, x: Real| programs[k].eval(&[x]);
            let (y0, y1) = (f(0, lo), f(0, hi));
            // one-sided slopes, a few ulps outside the bracket: at the kink itself the slope
            // formula gives neither side's (`sign(0) = 0`, or 0/0 for `x/abs(x)`); further out
            // while it is not a number
            let slope = |x: Real, dir: Real| {
                let mut delta = 4.0 * Real::EPSILON * x.abs().max(Real::MIN_POSITIVE);
                let mut d = f(1, x + dir * delta);
                for _ in 0..8 {
                    if d.is_finite() {
                        break;
                    }
                    delta *= 16.0;
                    d = f(1, x + dir * delta);
                }
                d
            };
            let (d0, d1) = (slope(lo, -1.0), slope(hi, 1.0));
            // more than the slope can carry over the tiny interval, and more than rounding
            let carried = d0.abs().max(d1.abs()) * (hi - lo);
            let tol = |v: Real, w: Real| 1e-9 * (1.0 + v.abs().max(w.abs()));
            if !(y0.is_finite() && y1.is_finite()) {
                return None;
            }
            if (y1 - y0).abs() > carried + tol(y0, y1) {
                Some(Break::Jump(y1 - y0))
            } else if d0.is_finite() && d1.is_finite() && (d1 - d0).abs() > tol(d0, d1).max(1e-6) {
                Some(Break::Kink(d1 - d0))
            } else {
                None
            }
        };
        search(lo, hi, DEPTH, &may_jump, &jump)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn graph(text: &str) -> Curve {
        Curve::graph(text, &[]).unwrap()
    }

    #[test]
    fn steps_and_kinks_are_found_and_smooth_joins_are_not() {
        let (x, j) = graph("-floor(x)").break_between(0.5, 1.7).unwrap();
        assert!(
            (x - 1.0).abs() < 1e-9 && j == Break::Jump(-1.0),
            "{x} {j:?}"
        );
        let (x, j) = graph("abs(x - 0.25)").break_between(-1.0, 1.0).unwrap();
        assert!(
            (x - 0.25).abs() < 1e-9 && matches!(j, Break::Kink(k) if (k - 2.0).abs() < 1e-6),
            "{x} {j:?}"
        );
        // smooth, or joined with a continuous slope: nothing
        assert_eq!(graph("x^2/2 - sin(x)").break_between(-3.0, 3.0), None);
        assert_eq!(
            graph("if(x < 1, x^2, 2*x - 1)").break_between(0.0, 2.0),
            None
        );
        assert_eq!(graph("-floor(x)").break_between(0.2, 0.7), None);
        assert_eq!(Curve::circle(1.0).unwrap().break_between(0.0, 3.0), None);
    }
}
