//! Measured convergence orders of the quadrature rules: the least-squares slope of log(error)
//! against log(h) over doublings of the number of intervals, for ∫_0^1 eˣ dx = e − 1, must be
//! within ±0.1 of the rule's order. The ranges of n keep every error well above round-off
//! (1e-13 for the fastest rules).

use mechkit::quad::{Rule, SampleRule, integrate_rule, integrate_samples};

use crate::util::order;

const EXACT: f64 = std::f64::consts::E - 1.0;

/// n = first, 2·first, …, last.
fn doublings(first: usize, last: usize) -> Vec<usize> {
    std::iter::successors(Some(first), |n| Some(2 * n))
        .take_while(|&n| n <= last)
        .collect()
}

fn measured(ns: &[usize], error: impl Fn(usize) -> f64) -> f64 {
    let hs: Vec<f64> = ns.iter().map(|&n| 1.0 / n as f64).collect();
    let errs: Vec<f64> = ns.iter().map(|&n| error(n)).collect();
    order(&hs, &errs)
}

#[test]
fn rules_on_functions() {
    // measured: left 0.996, right 1.004, midpoint 2.000, trapezoid 2.000, Simpson 3.999,
    // Gauss-Legendre(3) 5.985 (n = 1-8: at n = 16 the error is already 5e-14)
    let cases = [
        (Rule::Left, doublings(8, 512)),
        (Rule::Right, doublings(8, 512)),
        (Rule::Midpoint, doublings(8, 512)),
        (Rule::Trapezoid, doublings(8, 512)),
        (Rule::Simpson, doublings(8, 128)),
        (Rule::GaussLegendre(3), doublings(1, 8)),
    ];
    for (rule, ns) in cases {
        let p = measured(&ns, |n| {
            (integrate_rule(f64::exp, 0.0, 1.0, rule, n).unwrap() - EXACT).abs()
        });
        assert!(
            (p - rule.order() as f64).abs() < 0.1,
            "{rule}: measured order {p:.3}"
        );
    }
}

/// The sample grids.
#[derive(Clone, Copy, Debug)]
enum Grid {
    /// `x_i = i/n`.
    Uniform,
    /// `x_i = (i/n)^1.5`: smooth, finer near 0.
    Graded,
    /// Odd samples moved left by 0.2 h: every pair of intervals is 0.8 h then 1.2 h.
    Lopsided,
    /// Interior samples moved by up to ±0.2 h (fixed-seed LCG, Knuth's MMIX constants).
    Jittered,
}

fn grid(kind: Grid, n: usize) -> Vec<f64> {
    let mut state: u64 = 0x5eed_0000 + n as u64;
    let mut uniform = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            match kind {
                Grid::Graded => t.powf(1.5),
                Grid::Lopsided if i % 2 == 1 => t - 0.2 / n as f64,
                Grid::Jittered if i > 0 && i < n => t + 0.4 * (uniform() - 0.5) / n as f64,
                Grid::Uniform | Grid::Lopsided | Grid::Jittered => t,
            }
        })
        .collect()
}

/// The orders of the sample rules (left, right, midpoint, trapezoid, Simpson) on each grid.
///
/// Left, right and trapezoid keep their orders on any grid: their interval errors
/// (`h_i² f′/2`, `h_i³ f″/12`) have one sign and add up to `O(h)` and `O(h²)`.
///
/// Simpson's pair is exact for parabolas on any spacing, but for cubics only when
/// `h₀ = h₁`: its error is `(h₁ − h₀)(h₀ + h₁)³ f‴/72 + O(h⁵)`. On a smooth grid
/// `h₁ − h₀ = O(h²)`, so the order stays 4 (graded); with lopsided pairs `h₁ − h₀ = 0.4 h`
/// and every pair errs by `O(h⁴)` with one sign: order 3. With random jitter the `O(h⁴)`
/// errors have random signs and add up like a random walk, `√n h⁴`: order 3.5.
///
/// The midpoint rule on samples takes `x_{2j+1}` as the centre of `[x_{2j}, x_{2j+2}]`, which
/// it is only up to `(h₁ − h₀)/2`; that costs `f′ (h₁ − h₀)(h₀ + h₁)/2` per pair: order 2 on
/// a smooth grid, 1 on lopsided pairs and 1.5 (random walk) with jitter.
fn sample_orders(kind: Grid) -> [f64; 5] {
    match kind {
        Grid::Uniform | Grid::Graded => [1.0, 1.0, 2.0, 2.0, 4.0],
        Grid::Lopsided => [1.0, 1.0, 1.0, 2.0, 3.0],
        Grid::Jittered => [1.0, 1.0, 1.5, 2.0, 3.5],
    }
}

#[test]
fn rules_on_samples() {
    // measured: uniform 0.996 1.004 2.000 2.000 3.999; graded 0.994 1.005 1.999 1.999 3.996;
    // lopsided 0.998 1.007 1.018 2.004 3.005; jittered 0.993 1.002 1.489 1.992 3.444
    for kind in [Grid::Uniform, Grid::Graded, Grid::Lopsided, Grid::Jittered] {
        for (rule, expected) in SampleRule::ALL.into_iter().zip(sample_orders(kind)) {
            let p = measured(&doublings(8, 512), |n| {
                let x = grid(kind, n);
                let y: Vec<f64> = x.iter().map(|x| x.exp()).collect();
                (integrate_samples(&x, &y, rule).unwrap() - EXACT).abs()
            });
            assert!(
                (p - expected).abs() < 0.1,
                "{kind:?} grid, {rule}: measured order {p:.3}"
            );
        }
    }
}
