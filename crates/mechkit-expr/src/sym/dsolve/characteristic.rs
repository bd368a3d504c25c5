//! The homogeneous solutions of a linear equation of order 3 or more with numeric constant
//! coefficients, from the roots of its characteristic polynomial `Σ a_k r^k`: the rational
//! roots (with their multiplicity) divided out first, then what is left in closed form: a
//! quadratic (two real roots or `α ± iβ`), a biquadratic `a r⁴ + c r² + e` (through
//! `y = r²`, or `(r² + s r + m)(r² - s r + m)` with `m = sqrt(e/a)`, `s = sqrt(2m - c/a)`
//! when `y` is complex), or the square of a quadratic. A root `r` of multiplicity `m` gives
//! `t^j e^{rt}`, a pair `α ± iβ` gives `t^j e^{αt} cos βt` and `t^j e^{αt} sin βt`,
//! `j < m`. Anything else (an irreducible cubic, a general quartic) is left to say so.

use crate::ast::Func;
use crate::number::Number;
use crate::sym::Sym;
use crate::sym::poly::NumPoly;

/// A root: real, or the pair `α ± iβ`, with its multiplicity.
enum Root {
    Real(Sym, usize),
    Pair(Sym, Sym, usize),
}

/// The basis of solutions in `t`, or `None` when the coefficients are not all numbers or
/// the roots have no closed form here.
pub(super) fn higher_basis(a: &[Sym], t: &str) -> Option<Vec<Sym>> {
    let p = NumPoly::from_syms(a)?;
    let roots = roots(&p)?;
    let tv = Sym::var(t);
    let power = |j: usize| Sym::pow(tv.clone(), Sym::int(j as i64));
    let exp = |r: &Sym| Sym::call(Func::Exp, vec![Sym::product(vec![r.clone(), tv.clone()])]);
    let mut out = Vec::new();
    for root in roots {
        match root {
            Root::Real(r, m) => out.extend((0..m).map(|j| Sym::product(vec![power(j), exp(&r)]))),
            Root::Pair(alpha, beta, m) => {
                let bt = Sym::product(vec![beta, tv.clone()]);
                for j in 0..m {
                    for f in [Func::Cos, Func::Sin] {
                        out.push(Sym::product(vec![
                            power(j),
                            exp(&alpha),
                            Sym::call(f, vec![bt.clone()]),
                        ]));
                    }
                }
            }
        }
    }
    (out.len() + 1 == a.len()).then_some(out)
}

fn num(n: Number) -> Sym {
    Sym::Num(n)
}

fn div(a: Number, b: Number) -> Option<Number> {
    a.checked_div(b)
}

/// Every root of `p` with its multiplicity.
fn roots(p: &NumPoly) -> Option<Vec<Root>> {
    let mut out = Vec::new();
    let mut rest = p.clone();
    if rest.is_exact() {
        for r in p.rational_roots() {
            let factor = NumPoly::new(vec![r.negated(), Number::ONE]);
            let mut m = 0;
            while let Some((q, rem)) = rest.div_rem(&factor) {
                if !rem.is_zero() {
                    break;
                }
                rest = q;
                m += 1;
            }
            out.push(Root::Real(num(r), m));
        }
    }
    match rest.degree()? {
        0 => {}
        1 => out.push(Root::Real(num(div(rest.0[0], rest.0[1])?.negated()), 1)),
        2 => out.extend(quadratic(rest.0[2], rest.0[1], rest.0[0], 1)?),
        4 => out.extend(quartic(&rest)?),
        _ => return None,
    }
    Some(out)
}

/// The roots of `a r² + b r + c`, each of multiplicity `m`.
fn quadratic(a: Number, b: Number, c: Number, m: usize) -> Option<Vec<Root>> {
    let two_a = Number::int(2).times(a);
    let disc = b.times(b).plus(Number::int(-4).times(a).times(c));
    let alpha = div(b.negated(), two_a)?;
    let d = disc.to_f64();
    if !d.is_finite() {
        return None;
    }
    Some(if d > 0.0 {
        let half = Sym::quotient(Sym::sqrt(num(disc)), num(two_a));
        vec![
            Root::Real(Sym::sum(vec![num(alpha), half.clone()]), m),
            Root::Real(Sym::difference(num(alpha), half), m),
        ]
    } else if d == 0.0 {
        vec![Root::Real(num(alpha), 2 * m)]
    } else {
        let beta = Sym::quotient(Sym::sqrt(num(disc.negated())), num(two_a));
        let beta = if a.is_negative() {
            Sym::negate(beta)
        } else {
            beta
        };
        vec![Root::Pair(num(alpha), beta, m)]
    })
}

/// A quartic without rational roots: the square of a quadratic, or a biquadratic.
fn quartic(p: &NumPoly) -> Option<Vec<Root>> {
    let c = &p.0;
    if let Some(sf) = p.square_free()
        && sf.degree() == Some(2)
    {
        return quadratic(sf.0[2], sf.0[1], sf.0[0], 2);
    }
    if !(c[1].is_zero() && c[3].is_zero()) {
        return None;
    }
    let (a, c2, e) = (c[4], c[2], c[0]);
    let disc = c2.times(c2).plus(Number::int(-4).times(a).times(e));
    if disc.to_f64() >= 0.0 {
        // y = r² real: y > 0 gives ±sqrt(y), y < 0 gives ±i sqrt(-y)
        let two_a = num(Number::int(2).times(a));
        let mut out = Vec::new();
        for sign in [1, -1] {
            let y = Sym::quotient(
                Sym::sum(vec![
                    num(c2.negated()),
                    Sym::product(vec![Sym::int(sign), Sym::sqrt(num(disc))]),
                ]),
                two_a.clone(),
            );
            let yv = y.eval(&|_| None).ok()?;
            if yv > 0.0 {
                out.push(Root::Real(Sym::sqrt(y.clone()), 1));
                out.push(Root::Real(Sym::negate(Sym::sqrt(y)), 1));
            } else if yv < 0.0 {
                out.push(Root::Pair(Sym::zero(), Sym::sqrt(Sym::negate(y)), 1));
            } else {
                return None;
            }
        }
        return Some(out);
    }
    // complex y: r⁴ + (c/a) r² + e/a = (r² + s r + m)(r² - s r + m)
    let m = Sym::sqrt(num(div(e, a)?));
    let ca = num(div(c2, a)?);
    let s = Sym::sqrt(Sym::difference(
        Sym::product(vec![Sym::int(2), m.clone()]),
        ca.clone(),
    ));
    let beta = Sym::sqrt(Sym::sum(vec![
        Sym::quotient(m, Sym::int(2)),
        Sym::quotient(ca, Sym::int(4)),
    ]));
    let half_s = Sym::quotient(s, Sym::int(2));
    Some(vec![
        Root::Pair(Sym::negate(half_s.clone()), beta.clone(), 1),
        Root::Pair(half_s, beta, 1),
    ])
}
