//! The real roots of a quartic `a x^4 + b x^3 + c x^2 + d x + e` with numeric coefficients, in
//! closed form (Ferrari's method, 1540, as in Cardano's *Ars Magna*, 1545).
//!
//! Divided by `a` and with `x = u - b/(4a)` it is depressed to `u^4 + p u^2 + q u + r`. When
//! `q = 0` it is a biquadratic: `y = u²` solves `y² + p y + r = 0`, and each `y ≥ 0` gives
//! `u = ±sqrt(y)`. Otherwise, for a root `m > 0` of the resolvent cubic
//! `8m³ + 8p m² + (2p² - 8r) m - q² = 0` (it has one: it is `-q² < 0` at 0),
//! `u^4 + p u^2 + q u + r = (u² + p/2 + m)² - (s u - q/(2s))²` with `s = sqrt(2m)`, a difference
//! of squares, so the roots are those of the two quadratics
//! `u² + s u + p/2 + m - q/(2s)` and `u² - s u + p/2 + m + q/(2s)`.

use super::Sym;
use super::closed_form::{numeric_value, real_quadratic};
use super::cubic::{add, div, negligible};
use super::poly::NumPoly;
use crate::number::Number;

/// The distinct real roots of `a x^4 + b x^3 + c x^2 + d x + e` (`a ≠ 0`), unsorted; `None`
/// when the resolvent cubic has no closed-form root that is positive.
pub(super) fn quartic_roots(
    a: Number,
    b: Number,
    c: Number,
    d: Number,
    e: Number,
) -> Option<Vec<Sym>> {
    let n = Number::int;
    let (b, c, d, e) = (div(b, a), div(c, a), div(d, a), div(e, a));
    let (b2, b3) = (b.times(b), b.times(b).times(b));
    let p = add(&[c, div(n(-3).times(b2), n(8))]);
    let q = add(&[d, div(b.times(c), n(-2)), div(b3, n(8))]);
    let r = add(&[
        e,
        div(b.times(d), n(-4)),
        div(b2.times(c), n(16)),
        div(n(-3).times(b2).times(b2), n(256)),
    ]);
    let shift = Sym::Num(div(b, n(-4)));
    let scale = 1.0 + p.to_f64().abs() + r.to_f64().abs().sqrt();
    let u: Vec<Sym> = if negligible(q, scale.powf(1.5)) {
        biquadratic(p, r)?
    } else {
        ferrari(p, q, r)?
    };
    Some(
        u.into_iter()
            .map(|u| Sym::sum(vec![u, shift.clone()]))
            .collect(),
    )
}

/// The real roots of `u^4 + p u^2 + r` (`None` when a value overflows).
fn biquadratic(p: Number, r: Number) -> Option<Vec<Sym>> {
    let mut out = Vec::new();
    for y in real_quadratic(&Sym::one(), &Sym::Num(p), &Sym::Num(r))? {
        let v = numeric_value(&y)?;
        let tiny = 1e-14 * (p.to_f64().abs() + r.to_f64().abs().sqrt());
        if v.abs() <= tiny && y.as_num().is_none_or(Number::is_zero) {
            out.push(Sym::zero());
        } else if v > 0.0 {
            let root = Sym::sqrt(y);
            out.push(Sym::negate(root.clone()));
            out.push(root);
        }
    }
    Some(out)
}

/// The real roots of `u^4 + p u^2 + q u + r` (`q ≠ 0`) through the resolvent cubic.
fn ferrari(p: Number, q: Number, r: Number) -> Option<Vec<Sym>> {
    let n = Number::int;
    let resolvent = NumPoly::new(vec![
        q.times(q).negated(),
        add(&[n(2).times(p).times(p), n(-8).times(r)]),
        n(8).times(p),
        n(8),
    ]);
    // the largest root of the resolvent is positive
    let m = resolvent
        .closed_form_roots()?
        .into_iter()
        .filter_map(|m| numeric_value(&m).map(|v| (m, v)))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .filter(|(_, v)| *v > 0.0)?
        .0;
    let s = Sym::sqrt(Sym::product(vec![Sym::int(2), m.clone()]));
    let half_p_m = Sym::sum(vec![Sym::Num(div(p, n(2))), m]);
    let q_2s = Sym::quotient(Sym::Num(div(q, n(2))), s.clone());
    let mut out = real_quadratic(
        &Sym::one(),
        &s,
        &Sym::difference(half_p_m.clone(), q_2s.clone()),
    )?;
    out.extend(real_quadratic(
        &Sym::one(),
        &Sym::negate(s),
        &Sym::sum(vec![half_p_m, q_2s]),
    )?);
    Some(out)
}
