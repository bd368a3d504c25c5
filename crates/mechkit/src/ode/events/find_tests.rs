//! Tests of the one event finder.

use super::*;
use crate::ode::events::Direction;

/// One event `f(t)` over the step `[0, 1]`, sampled at `interior` evenly spaced points.
struct One<F> {
    f: F,
    direction: Direction,
}

impl<F: Fn(Real) -> Real> Rules for One<F> {
    fn count(&self) -> usize {
        1
    }
    fn enabled(&self, _: usize) -> bool {
        true
    }
    fn fires(&self, _: usize, from: Side, to: Side) -> bool {
        self.direction.fires(from, to)
    }
    fn values(&mut self, _: &StepPolynomial, t: Real, out: &mut [Real]) {
        out[0] = (self.f)(t);
    }
}

impl<F: Fn(Real) -> Real> Bounds for One<F> {
    fn count(&self) -> usize {
        1
    }
    fn enabled(&self, _: usize) -> bool {
        true
    }
    fn provable(&self, _: usize) -> bool {
        false
    }
    fn enclose(&mut self, _: usize, _: &StepPolynomial, _: Interval) -> Option<Jet> {
        None
    }
}

fn finder(one: &mut dyn Bounds, interior: usize) -> Finder {
    let mut finder = Finder::default();
    finder.poly.reset(0.0, 1.0, 0, 1);
    finder.plan(one, 1.0, interior, &mut |_| {});
    finder
}

fn run(f: impl Fn(Real) -> Real, direction: Direction, interior: usize) -> Vec<Real> {
    let mut one = One { f, direction };
    let mut finder = finder(&mut one, interior);
    let start = (one.f)(0.0);
    let mut sides = vec![match Side::of(start) {
        Some(Side::Zero) => Side::StartZero,
        s => s.unwrap_or(Side::Unknown),
    }];
    let (mut t, end) = (0.0, [(one.f)(1.0)]);
    let mut found = Vec::new();
    loop {
        let g = [(one.f)(t)];
        let Some(fired) = finder.first_firing(&mut one, &mut sides, (t, &g), (1.0, &end)) else {
            return found;
        };
        found.push(fired.firing.t);
        t = fired.firing.t;
        sides = vec![Side::Zero];
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
    let mut one = One {
        f,
        direction: Direction::Falling,
    };
    let mut finder = finder(&mut one, 7);
    let (g0, g1) = ((one.f)(0.0), (one.f)(1.0));
    finder
        .first_firing(&mut one, &mut [Side::Pos], (0.0, &[g0]), (1.0, &[g1]))
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

#[test]
fn crossing_rules() {
    use Side::*;
    let r = Direction::Rising;
    assert!(r.fires(Neg, Pos) && r.fires(Neg, Zero) && r.fires(StartZero, Pos));
    assert!(!r.fires(Zero, Pos) && !r.fires(Pos, Neg) && !r.fires(StartZero, Neg));
    let f = Direction::Falling;
    assert!(f.fires(Pos, Neg) && f.fires(Pos, Zero) && f.fires(StartZero, Neg));
    assert!(!f.fires(Zero, Neg) && !f.fires(Neg, Pos));
    let b = Direction::Both;
    assert!(b.fires(Pos, Neg) && b.fires(Neg, Pos) && b.fires(StartZero, Pos));
    assert!(!b.fires(Zero, Pos) && !b.fires(Zero, Neg) && !b.fires(Pos, Pos));
    assert!(!b.fires(Unknown, Pos) && !b.fires(Pos, Unknown));
    assert_eq!(Pos.after(Real::NAN), Pos);
    assert_eq!(Zero.after(-2.0), Neg);
}
