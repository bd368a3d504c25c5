//! Where an integrand is unbounded on `[a, b]`, and whether the integral converges there: a
//! definite integral across a pole (`1/x^2` on [−1, 1]) diverges, and neither the closed form
//! (−2) nor a quadrature's number is its value; one across an integrable singularity
//! (`1/sqrt(x)` on [0, 1] = 2, `ln(x)` on [0, 1] = −1) is an improper integral that converges.
//!
//! The points are found by interval arithmetic ([`mechkit_expr::Program::eval_interval`]):
//! `[a, b]` is bisected, a piece on which the enclosure of the integrand is bounded is proved
//! free of singularities, and a piece that stays unbounded down to a width of
//! 1e-10 (b − a) holds a candidate, located where `|f|` peaks in it. At a candidate `c` the
//! growth of `|f|` is measured on each side that lies in `[a, b]`: `|f(c ± h)| ~ h^−p` with
//! `h` = 1e-3, 1e-5 and 1e-7 of `b − a`. The integral diverges at `c` when `p ≥ 0.99` at both scales (`1/x`: p = 1,
//! `1/x^2`: p = 2, `tan(x)` at π/2: p = 1); it converges for `p` well below 1 (`1/sqrt(x)`:
//! 0.5, `ln(x)`: about 0).

use mechkit_expr::{Interval, MapScope, Program, Sym};

use crate::Real;
use crate::quad::{QuadResult, Tolerance, tanh_sinh};

/// The most interval evaluations one analysis makes (the bisection of a formula whose
/// enclosure is loose everywhere gives up there, finding nothing).
const MAX_EVALUATIONS: usize = 4000;

/// The most candidate points followed.
const MAX_CANDIDATES: usize = 16;

/// A point of `[a, b]` near which the integrand is unbounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Singularity {
    /// Where (to about the spacing of the numbers there).
    pub at: Real,
    /// The measured order of growth `p` in `|f| ~ |x − at|^−p` (the larger of the two sides).
    pub order: Real,
}

impl Singularity {
    /// Whether the integral converges across it (`p < 0.99`).
    pub fn integrable(&self) -> bool {
        self.order < 0.99
    }
}

/// The points of `[a, b]` (either order) where `f`, a formula of `x` with `params` for its
/// other names, is unbounded; empty when the formula does not compile (a name without a
/// value) or none is found.
pub fn singularities(
    f: &Sym,
    x: &str,
    params: &[(String, Real)],
    a: Real,
    b: Real,
) -> Vec<Singularity> {
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    if !(lo.is_finite() && hi.is_finite()) || lo == hi {
        return Vec::new();
    }
    let mut scope = MapScope::new().slot(x, 0);
    for (k, v) in params {
        if k != x {
            scope = scope.constant(k, *v);
        }
    }
    let Ok(program) = Program::compile(&f.to_expr(), &scope) else {
        return Vec::new();
    };
    let at = |v: Real| program.eval(&[v]);
    let width = hi - lo;
    let tiny = width * 1e-10;
    let mut pending = vec![(lo, hi)];
    let mut candidates: Vec<(Real, Real)> = Vec::new();
    let mut evaluations = 0;
    while let Some((l, h)) = pending.pop() {
        evaluations += 1;
        if evaluations > MAX_EVALUATIONS || candidates.len() >= MAX_CANDIDATES {
            break;
        }
        let e = program.eval_interval(&[Interval::new(l, h)]);
        if e.lo().is_finite() && e.hi().is_finite() {
            continue;
        }
        let mid = 0.5 * (l + h);
        // undefined here (sqrt of a negative): a question of the domain, not a singularity
        if at(mid).is_nan() && h - l > tiny {
            continue;
        }
        if h - l <= tiny || mid <= l || mid >= h {
            match candidates.last_mut() {
                Some(last) if l - last.1 <= tiny => last.1 = h,
                _ => candidates.push((l, h)),
            }
            continue;
        }
        // the right half first on the stack's bottom: pieces come out left to right
        pending.push((mid, h));
        pending.push((l, mid));
    }
    candidates
        .into_iter()
        .filter_map(|(l, h)| {
            let c = peak(&|v| at(v).abs(), l.max(lo), h.min(hi));
            let c = if c - lo <= tiny {
                lo
            } else if hi - c <= tiny {
                hi
            } else {
                c
            };
            let side = |dir: Real| -> Option<Real> {
                let value = |k: i32| at(c + dir * width * 10f64.powi(-k)).abs();
                let (f3, f5, f7) = (value(3), value(5), value(7));
                if !f3.is_finite() || f3 == 0.0 {
                    // values that overflow already away from the point (exp(x^2) at 30) are
                    // no pole: their integral is not representable, which the quadrature says
                    return None;
                }
                if !(f5.is_finite() && f7.is_finite()) {
                    // an infinite value this close is a pole that double precision reached
                    return (f5.is_infinite() || f7.is_infinite()).then_some(Real::INFINITY);
                }
                let p1 = (f5 / f3).log10() / 2.0;
                let p2 = (f7 / f5).log10() / 2.0;
                Some(p1.min(p2))
            };
            let orders: Vec<Real> = [-1.0, 1.0]
                .into_iter()
                .filter(|&d| (d < 0.0 && c > lo) || (d > 0.0 && c < hi))
                .filter_map(side)
                .collect();
            let order = orders.into_iter().fold(Real::NEG_INFINITY, Real::max);
            (order > 0.0).then_some(Singularity { at: c, order })
        })
        .collect()
}

/// The definite integral of `f` over `[a, b]` (either order) checked for poles: the points
/// inside where `f` has an integrable singularity (breakpoints for a quadrature, in the
/// direction from `a` to `b`), or the first point where the integral diverges. Every caller
/// that integrates a formula over an interval (`integrate`, θ = ∫ω dt of `rotation`) goes
/// through it, so neither a closed form's `F(b) − F(a)` nor a quadrature is taken across a
/// pole.
pub fn integrable(
    f: &Sym,
    x: &str,
    params: &[(String, Real)],
    a: Real,
    b: Real,
) -> Result<Vec<Real>, Singularity> {
    let mut breaks = Vec::new();
    for s in singularities(f, x, params, a, b) {
        if !s.integrable() {
            return Err(s);
        }
        if s.at != a && s.at != b {
            breaks.push(s.at);
        }
    }
    if a > b {
        breaks.reverse();
    }
    Ok(breaks)
}

/// The growth of `f` near a pole as a message says it: `; near it the integrand grows like
/// 1/|x - 1|^2` (empty when the order is not finite).
pub fn pole_growth(x: &str, s: Singularity) -> String {
    if !s.order.is_finite() {
        return String::new();
    }
    let at = show_point(s.at);
    let distance = if s.at == 0.0 {
        format!("|{x}|")
    } else {
        format!("|{x} - {at}|")
    };
    format!(
        "; near it the integrand grows like 1/{distance}^{}",
        show_point((s.order * 100.0).round() / 100.0)
    )
}

/// Where `g` (≥ 0, largest at one point of `[l, h]` and smaller away from it, as `|f|` near
/// a pole) is largest: ternary search down to the spacing of the numbers.
fn peak(g: &dyn Fn(Real) -> Real, mut l: Real, mut h: Real) -> Real {
    for _ in 0..200 {
        let (a, b) = (l + (h - l) / 3.0, h - (h - l) / 3.0);
        if !(l < a && a < b && b < h) {
            break;
        }
        let (ga, gb) = (g(a), g(b));
        // an infinite or undefined value is the point itself, or on its side
        if ga.is_nan() || ga >= gb {
            h = b;
        } else {
            l = a;
        }
    }
    let m = 0.5 * (l + h);
    if l <= 0.0 && 0.0 <= h { 0.0 } else { m }
}

/// A point as a message shows it: 10 significant digits, without trailing zeros
/// (`1.570796327`, `0`, `-1`).
pub fn show_point(x: Real) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let text = format!("{x:.9e}");
    let Ok(rounded) = text.parse::<Real>() else {
        return text;
    };
    if (1e-4..1e15).contains(&rounded.abs()) {
        format!("{rounded}")
    } else {
        format!("{rounded:e}")
    }
}

/// `∫ f` over `[a, b]` by the tanh-sinh rule, with `f(a + s)` and `f(b - s)` expanded in `s`
/// so that the nodes next to an end keep their distance to it (`1 - x^2` at `x = 1 - s` is
/// `2 s - s^2`, not `1 - 0.9999…^2`). `None` when it does not converge either.
pub(super) fn endpoint_singular(
    f: &Sym,
    x: &str,
    env: &dyn Fn(&str) -> Option<Real>,
    a: Real,
    b: Real,
) -> Option<QuadResult> {
    let (lo, hi) = (a.min(b), a.max(b));
    if !(lo.is_finite() && hi.is_finite()) || lo == hi {
        return None;
    }
    let s = "__s";
    let around = |end: Real, sign: i64| {
        let at = Sym::sum(vec![
            Sym::Num(mechkit_expr::Number::from_f64(end)),
            Sym::product(vec![Sym::int(sign), Sym::var(s)]),
        ]);
        f.substitute(x, &at).expand()
    };
    let (near_lo, near_hi) = (around(lo, 1), around(hi, -1));
    let value = |g: &Sym, d: Real| {
        g.eval(&|n| if n == s { Some(d) } else { env(n) })
            .unwrap_or(Real::NAN)
    };
    let r = tanh_sinh(
        |d| value(&near_lo, d),
        |d| value(&near_hi, d),
        lo,
        hi,
        Tolerance::default(),
    )
    .ok()?;
    Some(if a > b {
        QuadResult {
            value: -r.value,
            ..r
        }
    } else {
        r
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use mechkit_expr::parse;

    fn found(text: &str, a: Real, b: Real) -> Vec<Singularity> {
        let f = Sym::from_expr(&parse(text).unwrap().expr);
        singularities(&f, "x", &[("c".into(), 1.0)], a, b)
    }

    /// (integrand, a, b, the points and whether each is integrable)
    type Case = (&'static str, Real, Real, &'static [(Real, bool)]);

    #[test]
    fn issue_026_poles_are_found_and_told_from_integrable_singularities() {
        let cases: &[Case] = &[
            ("1/x", -1.0, 1.0, &[(0.0, false)]),
            ("1/x^2", -1.0, 1.0, &[(0.0, false)]),
            ("1/x", 0.0, 1.0, &[(0.0, false)]),
            ("1/(x-c)", 0.0, 2.0, &[(1.0, false)]),
            ("tan(x)", 0.0, 2.0, &[(std::f64::consts::FRAC_PI_2, false)]),
            ("1/sqrt(x)", 0.0, 1.0, &[(0.0, true)]),
            ("ln(x)", 0.0, 1.0, &[(0.0, true)]),
            ("1/sqrt(1-x^2)", -1.0, 1.0, &[(-1.0, true), (1.0, true)]),
            ("1/sqrt(abs(x))", -1.0, 1.0, &[(0.0, true)]),
            ("x^2", -1.0, 1.0, &[]),
            ("1/(1+x^2)", -10.0, 10.0, &[]),
            ("sin(x)/x", 0.5, 3.0, &[]),
            ("1/x", 1.0, 2.0, &[]),
        ];
        for (text, a, b, want) in cases {
            let got = found(text, *a, *b);
            assert_eq!(got.len(), want.len(), "{text} on [{a}, {b}]: {got:?}");
            for (s, (at, integrable)) in got.iter().zip(*want) {
                assert!((s.at - at).abs() < 1e-9, "{text}: {s:?}");
                assert_eq!(s.integrable(), *integrable, "{text}: {s:?}");
            }
        }
        // the order of growth is measured
        let s = found("1/x^2", 0.0, 1.0)[0];
        assert!((s.order - 2.0).abs() < 1e-6, "{s:?}");
        let s = found("1/sqrt(x)", 0.0, 1.0)[0];
        assert!((s.order - 0.5).abs() < 1e-6, "{s:?}");
    }

    #[test]
    fn points_are_shown_short() {
        assert_eq!(show_point(0.0), "0");
        assert_eq!(show_point(std::f64::consts::FRAC_PI_2), "1.570796327");
        assert_eq!(show_point(-1.0), "-1");
        assert_eq!(show_point(1e20), "1e20");
    }

    /// Issue 27: an integrable singularity at an end is no failure of the quadrature: where
    /// Gauss-Kronrod cannot reach the tolerance (or samples the end), tanh-sinh takes over.
    #[test]
    fn integrable_end_singularities_have_a_quadrature() {
        use std::f64::consts::PI;
        for (text, a, b, exact) in [
            ("1/sqrt(1 - x^2)", -1.0, 1.0, PI),
            ("1/sqrt(1 - x^2)", 1.0, -1.0, -PI),
            ("x^2/sqrt(1 - x^2)", 0.0, 1.0, PI / 4.0),
            ("1/sqrt(4 - x^2)", 0.0, 2.0, PI / 2.0),
            ("1/sqrt(x)", 0.0, 1.0, 2.0),
            ("ln(x)", 0.0, 1.0, -1.0),
        ] {
            let d = super::super::integral::integral(text, "x", Some((a, b)), &[])
                .unwrap()
                .definite
                .unwrap();
            let q = d
                .quadrature
                .as_ref()
                .unwrap_or_else(|e| panic!("{text}: {e}"));
            assert!((q.value - exact).abs() < 1e-9, "{text}: {q:?}");
            assert_ne!(d.agree, Some(false), "{text}: {d:?}");
        }
    }
}
