//! Globally adaptive Gauss-Kronrod G7/K15 quadrature (Piessens, de Doncker-Kapenga, Überhuber
//! and Kahaner, *QUADPACK*, 1983): the interval with the largest error estimate is bisected
//! until the total estimate is within tolerance. The error of a panel is `|K15 − G7|`.
//!
//! An infinite limit is mapped to a finite one: `∫_a^∞ f(x) dx = ∫_0^1 f(a + t/(1−t))/(1−t)² dt`
//! (and its mirror image), both infinite limits by splitting at 0. Integrable endpoint
//! singularities are handled because the nodes never touch the endpoints.

// The node and weight tables keep the digits as published in QUADPACK.
#![allow(clippy::excessive_precision)]

use std::collections::BinaryHeap;

use thiserror::Error;

use crate::Real;

/// Kronrod nodes on [-1, 1] (positive half, descending; the last is the centre).
const XK: [Real; 8] = [
    0.991_455_371_120_812_639_206_854_697_526_329,
    0.949_107_912_342_758_524_526_189_684_047_851,
    0.864_864_423_359_769_072_789_712_788_640_926,
    0.741_531_185_599_394_439_863_864_773_280_788,
    0.586_087_235_467_691_130_294_144_845_693_013,
    0.405_845_151_377_397_166_906_606_412_076_961,
    0.207_784_955_007_898_467_600_689_403_773_245,
    0.0,
];
/// Kronrod weights.
const WK: [Real; 8] = [
    0.022_935_322_010_529_224_963_732_008_058_970,
    0.063_092_092_629_978_553_290_700_663_189_204,
    0.104_790_010_322_250_183_839_876_322_541_518,
    0.140_653_259_715_525_918_745_189_590_510_238,
    0.169_004_726_639_267_902_826_583_426_598_550,
    0.190_350_578_064_785_409_913_256_402_421_014,
    0.204_432_940_075_298_892_414_161_999_234_649,
    0.209_482_141_084_727_828_012_999_174_891_714,
];
/// Gauss weights for the Kronrod nodes 1, 3, 5 and 7 (the 7-point Gauss rule).
const WG: [Real; 4] = [
    0.129_484_966_168_869_693_270_611_432_679_082,
    0.279_705_391_489_276_667_901_467_771_423_780,
    0.381_830_050_505_118_944_950_369_775_488_975,
    0.417_959_183_673_469_387_755_102_040_816_327,
];

/// Requested accuracy: stop when the error estimate is below `max(abs, rel·|value|)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    /// Absolute tolerance.
    pub abs: Real,
    /// Relative tolerance.
    pub rel: Real,
}

impl Default for Tolerance {
    /// `abs = 1e-10`, `rel = 1e-10`.
    fn default() -> Self {
        Self {
            abs: 1e-10,
            rel: 1e-10,
        }
    }
}

/// A computed integral.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadResult {
    /// The value.
    pub value: Real,
    /// Estimated absolute error.
    pub error: Real,
    /// Function evaluations used.
    pub evaluations: usize,
}

/// Why an integral could not be computed to the requested tolerance.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum QuadError {
    /// The integrand is not finite somewhere the rule samples it.
    #[error(
        "the integrand is {value} at x = {}: the integral may not exist there (a singularity); \
         check the interval, or integrate up to a point near it",
        super::short(*.x)
    )]
    NotFinite {
        /// Where.
        x: Real,
        /// What it was.
        value: Real,
    },
    /// The integrand is NaN over a stretch of the interval, not at an isolated point: the
    /// interval leaves the integrand's domain (`sqrt(x)` from −1).
    #[error(
        "the integrand is not a number (NaN) for x from {} to {}: there the interval leaves its domain (a square root or a logarithm of a negative number, say); integrate over the part where it is defined",
        super::short(*.from),
        super::short(*.to)
    )]
    Undefined {
        /// Where the stretch begins.
        from: Real,
        /// Where it ends.
        to: Real,
    },
    /// The subdivision limit was reached; the best estimate is given.
    #[error(
        "the tolerance was not reached after {panels} panels: {} ± {}",
        super::short(*value),
        super::short(*error)
    )]
    NotConverged {
        /// Best value.
        value: Real,
        /// Its error estimate.
        error: Real,
        /// Panels used.
        panels: usize,
    },
    /// A limit is NaN.
    #[error("the limits of integration must be numbers")]
    BadLimits,
    /// Towards an infinite limit the integrand does not decay fast enough for the samples
    /// to stay finite: `∫_1^∞ 1/x dx` grows without bound.
    #[error(
        "the integrand does not decay fast enough towards x = {} for the integral to converge (like 1/x, it may diverge there); integrate up to a finite limit",
        super::short(*.end)
    )]
    NoDecay {
        /// The infinite limit (`inf` or `-inf`).
        end: Real,
    },
}

/// An error of the integral over `t ∈ [0, 1]` told in `x = map(t)`: a sample that is not
/// finite where `x` is infinite is the integrand's failure to decay towards the limit, not a
/// singularity at the `t` it was found (`∫_1^∞ 1/x dx` said "NaN at x = 1").
fn mapped(e: QuadError, map: impl Fn(Real) -> Real) -> QuadError {
    match e {
        QuadError::NotFinite { x: t, value } => {
            let x = map(t);
            if x.is_finite() {
                QuadError::NotFinite { x, value }
            } else {
                QuadError::NoDecay {
                    end: if x.is_nan() { Real::INFINITY } else { x },
                }
            }
        }
        other => other,
    }
}

struct Panel {
    a: Real,
    b: Real,
    value: Real,
    error: Real,
}

impl PartialEq for Panel {
    fn eq(&self, o: &Self) -> bool {
        self.error == o.error
    }
}
impl Eq for Panel {}
impl PartialOrd for Panel {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Panel {
    fn cmp(&self, o: &Self) -> std::cmp::Ordering {
        self.error.total_cmp(&o.error)
    }
}

fn kronrod(f: &mut dyn FnMut(Real) -> Real, a: Real, b: Real) -> Result<(Real, Real), QuadError> {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let mut k = 0.0;
    let mut g = 0.0;
    for (i, (&x, &w)) in XK.iter().zip(&WK).enumerate() {
        let pts: &[Real] = if x == 0.0 {
            &[c]
        } else {
            &[c - h * x, c + h * x]
        };
        for &p in pts {
            let v = f(p);
            if !v.is_finite() {
                return Err(QuadError::NotFinite { x: p, value: v });
            }
            k += w * v;
            if i % 2 == 1 {
                g += WG[i / 2] * v;
            }
        }
    }
    Ok((k * h, (k - g).abs() * h))
}

/// `∫_a^b f(x) dx` to tolerance `tol` (limits may be infinite, and `b < a` gives the negated
/// integral).
///
/// # Example
/// ```
/// use mechkit::quad::{integrate, Tolerance};
/// let r = integrate(|x| 1.0 / (1.0 + x * x), 0.0, 1.0, Tolerance::default()).unwrap();
/// assert!((r.value - std::f64::consts::FRAC_PI_4).abs() < 1e-14);
/// let r = integrate(|x| (-x * x).exp(), f64::NEG_INFINITY, f64::INFINITY, Tolerance::default()).unwrap();
/// assert!((r.value - std::f64::consts::PI.sqrt()).abs() < 1e-10);
/// ```
pub fn integrate(
    mut f: impl FnMut(Real) -> Real,
    a: Real,
    b: Real,
    tol: Tolerance,
) -> Result<QuadResult, QuadError> {
    integrate_dyn(&mut f, a, b, tol)
}

fn integrate_dyn(
    f: &mut dyn FnMut(Real) -> Real,
    a: Real,
    b: Real,
    tol: Tolerance,
) -> Result<QuadResult, QuadError> {
    if a.is_nan() || b.is_nan() {
        return Err(QuadError::BadLimits);
    }
    if a == b {
        return Ok(QuadResult {
            value: 0.0,
            error: 0.0,
            evaluations: 0,
        });
    }
    if b < a {
        return integrate_dyn(f, b, a, tol).map(|r| QuadResult {
            value: -r.value,
            ..r
        });
    }
    match (a.is_finite(), b.is_finite()) {
        (true, true) => match adaptive(f, a, b, tol) {
            Err(QuadError::NotFinite { x, value }) if value.is_nan() => {
                Err(undefined_span(f, (a, b), x).unwrap_or(QuadError::NotFinite { x, value }))
            }
            other => other,
        },
        (true, false) => adaptive(
            &mut |t: Real| {
                let s = 1.0 - t;
                f(a + t / s) / (s * s)
            },
            0.0,
            1.0,
            tol,
        )
        .map_err(|e| mapped(e, |t| a + t / (1.0 - t))),
        (false, true) => adaptive(
            &mut |t: Real| {
                let s = 1.0 - t;
                f(b - t / s) / (s * s)
            },
            0.0,
            1.0,
            tol,
        )
        .map_err(|e| mapped(e, |t| b - t / (1.0 - t))),
        (false, false) => {
            let left = integrate_dyn(f, Real::NEG_INFINITY, 0.0, tol)?;
            let right = integrate_dyn(f, 0.0, Real::INFINITY, tol)?;
            Ok(QuadResult {
                value: left.value + right.value,
                error: left.error + right.error,
                evaluations: left.evaluations + right.evaluations,
            })
        }
    }
}

/// The stretch of `[a, b]` about `x`, where `f` is NaN, over which `f` is NaN, when it is
/// more than a point: on each side, the first of 64 even steps from `x` to the interval's end
/// where `f` is not NaN, and the edge by bisection between it and the step before (the end
/// given where `f` is a number; the interval's end when every step is NaN). The stretch is
/// confirmed by 16 samples inside it, all NaN. `None` for an isolated NaN (`0/0` at a point)
/// or a stretch the samples do not confirm.
fn undefined_span(
    f: &mut dyn FnMut(Real) -> Real,
    (a, b): (Real, Real),
    x: Real,
) -> Option<QuadError> {
    const STEPS: u32 = 64;
    let mut edge = |end: Real| {
        let mut nan = x;
        for k in 1..=STEPS {
            let p = if k == STEPS {
                end
            } else {
                x + (end - x) * Real::from(k) / Real::from(STEPS)
            };
            if f(p).is_nan() {
                nan = p;
                continue;
            }
            let mut number = p;
            for _ in 0..1100 {
                let m = 0.5 * (nan + number);
                if m == nan || m == number {
                    break;
                }
                if f(m).is_nan() {
                    nan = m;
                } else {
                    number = m;
                }
            }
            return number;
        }
        end
    };
    let (from, to) = (edge(a), edge(b));
    if to - from <= 1e-9 * (b - a) || (to - from).is_nan() {
        return None;
    }
    let all_nan = (1..=16).all(|k| f(from + (to - from) * Real::from(k) / 17.0).is_nan());
    all_nan.then_some(QuadError::Undefined { from, to })
}

/// Most panels before giving up.
const MAX_PANELS: usize = 2000;

fn adaptive(
    f: &mut dyn FnMut(Real) -> Real,
    a: Real,
    b: Real,
    tol: Tolerance,
) -> Result<QuadResult, QuadError> {
    let (value, error) = kronrod(f, a, b)?;
    let mut heap = BinaryHeap::new();
    heap.push(Panel { a, b, value, error });
    let (mut total, mut total_err) = (value, error);
    let mut evaluations = 15;
    while total_err > tol.abs.max(tol.rel * total.abs()) {
        if heap.len() >= MAX_PANELS {
            return Err(QuadError::NotConverged {
                value: total,
                error: total_err,
                panels: heap.len(),
            });
        }
        let p = heap.pop().expect("at least one panel");
        let m = 0.5 * (p.a + p.b);
        if m <= p.a || m >= p.b {
            // cannot split further in floating point
            return Err(QuadError::NotConverged {
                value: total,
                error: total_err,
                panels: heap.len() + 1,
            });
        }
        let (v1, e1) = kronrod(f, p.a, m)?;
        let (v2, e2) = kronrod(f, m, p.b)?;
        evaluations += 30;
        total += v1 + v2 - p.value;
        total_err += e1 + e2 - p.error;
        heap.push(Panel {
            a: p.a,
            b: m,
            value: v1,
            error: e1,
        });
        heap.push(Panel {
            a: m,
            b: p.b,
            value: v2,
            error: e2,
        });
    }
    // recompute the sums from the panels (the running sums drift by rounding)
    let (value, error) = heap
        .iter()
        .fold((0.0, 0.0), |(v, e), p| (v + p.value, e + p.error));
    Ok(QuadResult {
        value,
        error,
        evaluations,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An interval that leaves the integrand's domain is named by the stretch where it is
    /// NaN, not by the first quadrature node there (`sqrt(x)` from −1 said "NaN at
    /// x = −0.991"); an isolated NaN keeps the point.
    #[test]
    fn a_stretch_outside_the_domain_is_named() {
        type Case = (fn(Real) -> Real, Real, Real, (Real, Real));
        let tol = Tolerance::default();
        let cases: [Case; 4] = [
            (Real::sqrt, -1.0, 1.0, (-1.0, 0.0)),
            (Real::sqrt, 1.0, -1.0, (-1.0, 0.0)),
            (|x| (1.0 - x * x).sqrt(), -2.0, 2.0, (-2.0, -1.0)),
            (Real::ln, -2.0, 3.0, (-2.0, 0.0)),
        ];
        for (f, a, b, (from, to)) in cases {
            match integrate(f, a, b, tol) {
                Err(QuadError::Undefined { from: l, to: r }) => {
                    assert!(
                        (l - from).abs() < 1e-12 && (r - to).abs() < 1e-12,
                        "{l} {r}"
                    );
                }
                other => panic!("{a}..{b}: {other:?}"),
            }
        }
        let isolated = |x: Real| if x == 0.5 { Real::NAN } else { x };
        // 0.5 is the midpoint of [0, 1], a node of the rule
        assert!(matches!(
            integrate(isolated, 0.0, 1.0, tol),
            Err(QuadError::NotFinite { x, .. }) if x == 0.5
        ));
    }

    /// `∫_1^∞ 1/x dx` diverges; its quadrature said "the integrand is NaN at x = 1", the
    /// variable of the mapped interval, not the user's.
    #[test]
    fn an_integrand_that_does_not_decay_is_blamed_at_the_infinite_limit() {
        let t = Tolerance::default();
        let e = integrate(|x| 1.0 / x, 1.0, f64::INFINITY, t).unwrap_err();
        assert_eq!(e, QuadError::NoDecay { end: f64::INFINITY }, "{e}");
        assert!(e.to_string().contains("towards x = inf"), "{e}");
        let e = integrate(|x| 1.0 / x, f64::NEG_INFINITY, -1.0, t).unwrap_err();
        assert_eq!(
            e,
            QuadError::NoDecay {
                end: f64::NEG_INFINITY
            },
            "{e}"
        );
    }

    #[test]
    fn smooth_and_singular_integrands() {
        let t = Tolerance::default();
        let r = integrate(f64::sin, 0.0, std::f64::consts::PI, t).unwrap();
        assert!((r.value - 2.0).abs() < 1e-13);
        // integrable endpoint singularity: ∫0^1 1/sqrt(x) = 2
        let r = integrate(
            |x: f64| 1.0 / x.sqrt(),
            0.0,
            1.0,
            Tolerance {
                abs: 1e-9,
                rel: 1e-9,
            },
        )
        .unwrap();
        assert!((r.value - 2.0).abs() < 1e-8, "{r:?}");
        // reversed limits
        let r = integrate(|x| x, 1.0, 0.0, t).unwrap();
        assert!((r.value + 0.5).abs() < 1e-15);
        // ∫1^∞ 1/x² = 1
        let r = integrate(|x| 1.0 / (x * x), 1.0, f64::INFINITY, t).unwrap();
        assert!((r.value - 1.0).abs() < 1e-10);
        assert!(matches!(
            integrate(|x| 1.0 / x, -1.0, 1.0, t),
            Err(QuadError::NotFinite { .. })
        ));
    }
}
