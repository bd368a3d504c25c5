//! Measured convergence orders of the finite differences on x(t) = sin t, t ∈ [0, 2], with the
//! number of intervals doubling from 20 to 320. The error is the largest over all samples, ends
//! included. Three grids: uniform; smoothly graded (t = 2(s + s²/2)/1.5 with s uniform, steps
//! growing by a factor 2 along the interval); and jittered (each uniform point moved by up to
//! ±30 % of a step, pseudo-randomly, so neighbouring steps differ by O(h)).
//!
//! Forward and backward differences are first order and central ones second order on every
//! grid; the three-point second derivative is second order on uniform and graded grids but
//! only first order on the jittered one, as its error term (h₂ − h₁) x'''/3 predicts.

use mechkit::Real;
use mechkit::deriv::{Difference, differentiate, second_derivative};

use crate::util::order;

#[derive(Clone, Copy, Debug)]
enum Grid {
    Uniform,
    Graded,
    Jittered,
}

const NS: [usize; 5] = [20, 40, 80, 160, 320];

fn grid(kind: Grid, n: usize) -> Vec<Real> {
    let s = |i: usize| i as Real / n as Real;
    // A small linear congruential generator: the same jitter on every run.
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d ^ n as u64;
    let mut jitter = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 11) as Real / (1u64 << 53) as Real) * 2.0 - 1.0
    };
    (0..=n)
        .map(|i| match kind {
            Grid::Uniform => 2.0 * s(i),
            Grid::Graded => 2.0 * (s(i) + 0.5 * s(i) * s(i)) / 1.5,
            Grid::Jittered if i == 0 || i == n => 2.0 * s(i),
            Grid::Jittered => 2.0 * (s(i) + 0.3 * jitter() / n as Real),
        })
        .collect()
}

/// The measured order of a derivative approximation: `approx(t, x)` against `exact(t)`.
fn measured(
    kind: Grid,
    approx: impl Fn(&[Real], &[Real]) -> Vec<Real>,
    exact: impl Fn(Real) -> Real,
) -> Real {
    let mut hs = Vec::new();
    let mut errors = Vec::new();
    for n in NS {
        let t = grid(kind, n);
        let x: Vec<Real> = t.iter().map(|t| t.sin()).collect();
        let d = approx(&t, &x);
        let error = t
            .iter()
            .zip(&d)
            .map(|(t, d)| (d - exact(*t)).abs())
            .fold(0.0, Real::max);
        hs.push(2.0 / n as Real);
        errors.push(error);
    }
    order(&hs, &errors)
}

fn first(kind: Grid, scheme: Difference) -> Real {
    measured(kind, |t, x| differentiate(t, x, scheme).unwrap(), Real::cos)
}

fn second(kind: Grid) -> Real {
    measured(kind, |t, x| second_derivative(t, x).unwrap(), |t| -t.sin())
}

#[test]
fn first_derivative_orders() {
    for kind in [Grid::Uniform, Grid::Graded, Grid::Jittered] {
        for scheme in Difference::ALL {
            let p = first(kind, scheme);
            println!("{kind:?} {}: {p:.3}", scheme.name());
            assert!(
                (p - scheme.order() as Real).abs() < 0.1,
                "{kind:?} {}: {p}",
                scheme.name()
            );
        }
    }
}

#[test]
fn second_derivative_orders() {
    for (kind, expected) in [
        (Grid::Uniform, 2.0),
        (Grid::Graded, 2.0),
        (Grid::Jittered, 1.0),
    ] {
        let p = second(kind);
        println!("{kind:?} second derivative: {p:.3}");
        assert!((p - expected).abs() < 0.2, "{kind:?}: {p}");
    }
}
