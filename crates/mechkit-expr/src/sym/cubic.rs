//! The real roots of a cubic `a x^3 + b x^2 + c x + d` with numeric coefficients, in closed
//! form.
//!
//! With `x = t - b/(3a)` the cubic is depressed to `t^3 + p t + q` with
//! `p = (3ac - b²)/(3a²)` and `q = (2b³ - 9abc + 27a²d)/(27a³)`, and `D = (q/2)² + (p/3)³`
//! decides:
//!
//! - `D < 0` (three distinct real roots, the casus irreducibilis): Viète's trigonometric form
//!   `t_k = 2 sqrt(-p/3) cos(acos((3q/(2p)) sqrt(-3/p))/3 - 2πk/3)`, `k = 0, 1, 2`;
//! - `D > 0` (one real root): Cardano's, written `t = w - p/(3w)` with
//!   `w = cbrt(-q/2 - sign(q) sqrt(D))`, so that no two nearly equal numbers are subtracted;
//! - `D = 0`: `t = 0` (a triple root) when `p = 0`, else `3q/p` and the double root `-3q/(2p)`.
//!
//! (Cardano, *Ars Magna*, 1545; Viète, *De aequationum recognitione*, 1615; e.g. Press et al.,
//! *Numerical Recipes*, 3rd ed., §5.6.)

use super::Sym;
use crate::ast::Func;
use crate::number::Number;

/// `a / b` for `b` not zero (a float NaN otherwise, which verification rejects).
pub(super) fn div(a: Number, b: Number) -> Number {
    a.checked_div(b).unwrap_or(Number::Float(f64::NAN))
}

/// `Σ terms` of numbers.
pub(super) fn add(terms: &[Number]) -> Number {
    terms.iter().fold(Number::ZERO, |s, t| s.plus(*t))
}

/// Whether `v` is zero: exactly for an exact number, to within `1e-12` of `scale` for a float
/// (which carries rounding from the coefficients).
pub(super) fn negligible(v: Number, scale: f64) -> bool {
    if v.is_exact() {
        v.is_zero()
    } else {
        v.to_f64().abs() <= 1e-12 * scale.abs()
    }
}

/// The distinct real roots of `a x^3 + b x^2 + c x + d` (`a ≠ 0`), unsorted.
pub(super) fn cubic_roots(a: Number, b: Number, c: Number, d: Number) -> Vec<Sym> {
    let n = Number::int;
    let a2 = a.times(a);
    let p = div(
        add(&[n(3).times(a).times(c), b.times(b).negated()]),
        n(3).times(a2),
    );
    let q = div(
        add(&[
            n(2).times(b).times(b).times(b),
            n(-9).times(a).times(b).times(c),
            n(27).times(a2).times(d),
        ]),
        n(27).times(a2).times(a),
    );
    let shift = Sym::Num(div(b, n(3).times(a)).negated());
    let half_q = div(q, n(2));
    let third_p = div(p, n(3));
    let q2 = half_q.times(half_q);
    let p3 = third_p.times(third_p).times(third_p);
    let disc = q2.plus(p3);
    let scale = q2.to_f64().abs() + p3.to_f64().abs();
    let t: Vec<Sym> = if negligible(disc, scale) {
        if negligible(p, scale.cbrt()) {
            vec![Sym::zero()]
        } else {
            vec![
                Sym::Num(div(n(3).times(q), p)),
                Sym::Num(div(n(-3).times(q), n(2).times(p))),
            ]
        }
    } else if disc.is_negative() {
        // p < 0 here
        let r = Sym::product(vec![Sym::int(2), Sym::sqrt(Sym::Num(third_p.negated()))]);
        let arg = Sym::product(vec![
            Sym::Num(div(n(3).times(q), n(2).times(p))),
            Sym::sqrt(Sym::Num(div(n(-3), p))),
        ]);
        let theta = Sym::call(Func::Acos, vec![arg]);
        (0..3)
            .map(|k| {
                let angle = Sym::difference(
                    Sym::quotient(theta.clone(), Sym::int(3)),
                    Sym::product(vec![Sym::rational(2 * k, 3), Sym::var("pi")]),
                );
                Sym::product(vec![r.clone(), Sym::call(Func::Cos, vec![angle])])
            })
            .collect()
    } else {
        let sign = if q.is_negative() { -1 } else { 1 };
        let w = Sym::call(
            Func::Cbrt,
            vec![Sym::sum(vec![
                Sym::Num(half_q.negated()),
                Sym::product(vec![Sym::int(-sign), Sym::sqrt(Sym::Num(disc))]),
            ])],
        );
        vec![Sym::difference(
            w.clone(),
            Sym::quotient(Sym::Num(third_p), w),
        )]
    };
    t.into_iter()
        .map(|t| Sym::sum(vec![t, shift.clone()]))
        .collect()
}
