//! Rational functions of `sin x`, `cos x`, `tan x` with a trigonometric denominator
//! (`1/(a + b cos x)`, `1/(1 + sin x)`) by the Weierstrass substitution `t = tan(x/2)`:
//! `sin x = 2t/(1+t²)`, `cos x = (1−t²)/(1+t²)`, `tan x = 2t/(1−t²)`, `dx = 2 dt/(1+t²)`,
//! which makes them rational functions of `t`; a rational function of `tan x` alone goes by
//! `u = tan x`, `dx = du/(1+u²)` (`1/(3 + tan x)`), and so does one where `cos x` occurs
//! only squared once `sin x` is written `tan x cos x` (`1/(1 + sin² x)`). The antiderivative
//! holds between the poles of `tan(x/2)` (of `tan x` for `u`), and is made continuous across
//! them where its `atan` terms tell the jump (`continuous`); else a definite integral across
//! a pole is left to quadrature (the closed form is checked against it).

use super::{Ctx, Sym, var};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::poly::coefficients;

/// The largest degree in `t` of the denominator given to partial fractions.
const MAX_DEGREE: usize = 8;

/// The largest power of a sum brought over one denominator.
const MAX_POWER: i128 = 8;

/// The Weierstrass substitution, for integrands where `x` occurs only in `sin x`, `cos x`,
/// `tan x` and one of them is in a denominator.
pub(super) fn weierstrass(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    if !only_trig_of(f, x) || !trig_in_denominator(f, x, false) {
        return None;
    }
    if !ctx.spend(super::size(f)) {
        return None;
    }
    let t = ctx.fresh();
    let tv = var(&t);
    if !has_call(f, x, Func::Sin) && !has_call(f, x, Func::Cos) {
        // a rational function of tan x alone: u = tan x, dx = du/(1 + u²)
        let g = rewrite(f, x, &|_| tv.clone());
        let one_plus = Sym::sum(vec![Sym::one(), Sym::pow(tv.clone(), Sym::int(2))]);
        let g = Sym::quotient(g, one_plus);
        let big_g = rational_in(&g, &t, ctx)?;
        return Some(continuous(&big_g, &t, &var(x), ctx));
    }
    if let Some(big_g) = even_in_tan(f, x, &t, ctx) {
        return Some(continuous(&big_g, &t, &var(x), ctx));
    }
    let one_plus = Sym::sum(vec![Sym::one(), Sym::pow(tv.clone(), Sym::int(2))]);
    let one_minus = Sym::difference(Sym::one(), Sym::pow(tv.clone(), Sym::int(2)));
    let two_t = Sym::product(vec![Sym::int(2), tv.clone()]);
    let g = rewrite(f, x, &|func| match func {
        Func::Sin => Sym::quotient(two_t.clone(), one_plus.clone()),
        Func::Cos => Sym::quotient(one_minus.clone(), one_plus.clone()),
        _ => Sym::quotient(two_t.clone(), one_minus.clone()),
    });
    let g = Sym::product(vec![g, Sym::int(2), Sym::pow(one_plus, Sym::int(-1))]);
    let big_g = rational_in(&g, &t, ctx)?;
    let half_x = Sym::product(vec![Sym::rational(1, 2), var(x)]);
    Some(continuous(&big_g, &t, &half_x, ctx))
}

/// `∫ f dx` by `u = tan x` for an integrand where `cos x` occurs only squared once `sin x` is
/// written `tan x cos x` (unchanged by `x → x + π`: `1/(1 + sin² x)`, `1/(2 + sin x cos x)`):
/// `cos² x = 1/(1 + u²)`, `dx = du/(1 + u²)`, a rational function of `u` of half the degree
/// `t = tan(x/2)` gives. `None` for any other integrand.
fn even_in_tan(f: &Sym, x: &str, u: &str, ctx: &mut Ctx) -> Option<Sym> {
    let w = ctx.fresh();
    let (uv, wv) = (var(u), var(&w));
    let g = rewrite(f, x, &|func| match func {
        Func::Sin => Sym::product(vec![uv.clone(), wv.clone()]),
        Func::Cos => wv.clone(),
        _ => uv.clone(),
    });
    let one_plus = Sym::sum(vec![Sym::one(), Sym::pow(uv.clone(), Sym::int(2))]);
    let g = even_powers(&g, &w, &one_plus)?;
    let g = Sym::quotient(g, one_plus);
    rational_in(&g, u, ctx)
}

/// `s` with each even power `w^2k` replaced by `c^-k`; `None` when `w` occurs otherwise.
fn even_powers(s: &Sym, w: &str, c: &Sym) -> Option<Sym> {
    if s.free_of(w) {
        return Some(s.clone());
    }
    match s {
        Sym::Pow(b, e) if matches!(&**b, Sym::Var(v) if v == w) => {
            let k = e.as_num()?.as_integer()?;
            (k % 2 == 0).then(|| Sym::pow(c.clone(), Sym::Num(Number::int(-(k / 2) as i64))))
        }
        Sym::Add(xs) => Some(Sym::sum(
            xs.iter()
                .map(|t| even_powers(t, w, c))
                .collect::<Option<_>>()?,
        )),
        Sym::Mul(xs) => Some(Sym::product(
            xs.iter()
                .map(|t| even_powers(t, w, c))
                .collect::<Option<_>>()?,
        )),
        Sym::Pow(b, e) if e.free_of(w) => Some(Sym::pow(even_powers(b, w, c)?, (**e).clone())),
        _ => None,
    }
}

/// `G(tan(y))` made continuous across the poles of `tan(y)` (`y = x` or `x/2`): each
/// `c atan(α t + β)` of `G` jumps by `−c π sign(α)` where `t = tan(y)` passes from `+∞` to
/// `−∞` (logarithms and rational terms have equal limits at both ends), so
/// `G(tan y) + J round(y/π)` with `J = Σ c π sign(α)` is continuous (the standard
/// `∫ dx/(2 + cos x)` over a period). Without a linear `atan` argument, `G(tan y)`.
fn continuous(big_g: &Sym, t: &str, y: &Sym, ctx: &Ctx) -> Sym {
    let back = big_g.substitute(t, &Sym::call(Func::Tan, vec![y.clone()]));
    let Some(jump) = jump(big_g, t, ctx) else {
        return back;
    };
    if jump.is_zero() {
        return back;
    }
    // the number of poles passed, round(y/π), written (y − atan(tan y))/π so that in floating
    // point it turns exactly where `tan y` changes sign (at an end x = π as well)
    let turns = Sym::quotient(
        Sym::difference(
            y.clone(),
            Sym::call(Func::Atan, vec![Sym::call(Func::Tan, vec![y.clone()])]),
        ),
        Sym::var("pi"),
    );
    Sym::sum(vec![back, Sym::product(vec![jump, turns])])
}

/// `lim G(+∞) − lim G(−∞)` from the `atan` terms of `G` with arguments linear in `t`; `None`
/// when an `atan` of another argument occurs.
fn jump(s: &Sym, t: &str, ctx: &Ctx) -> Option<Sym> {
    if s.free_of(t) {
        return Some(Sym::zero());
    }
    match s {
        Sym::Add(terms) => Some(Sym::sum(
            terms
                .iter()
                .map(|c| jump(c, t, ctx))
                .collect::<Option<_>>()?,
        )),
        Sym::Mul(fs) => {
            let (constant, rest): (Vec<Sym>, Vec<Sym>) =
                fs.iter().cloned().partition(|f| f.free_of(t));
            match rest.as_slice() {
                [one] => Some(Sym::product(vec![
                    Sym::product(constant),
                    jump(one, t, ctx)?,
                ])),
                _ => (!has_atan(s)).then(Sym::zero),
            }
        }
        Sym::Call(Func::Atan, args) => {
            let c = coefficients(&args[0], t).filter(|c| c.len() == 2 && c[1].free_of(t))?;
            Some(Sym::product(vec![Sym::var("pi"), sign(&c[1], ctx)]))
        }
        _ => (!has_atan(s)).then(Sym::zero),
    }
}

/// The sign of `a`: a number, or a product of numbers, square roots and symbols assumed
/// positive; else `sign(a)`.
fn sign(a: &Sym, ctx: &Ctx) -> Sym {
    let mut negative = false;
    for f in super::factors(a) {
        match &f {
            Sym::Num(n) => negative ^= n.is_negative(),
            Sym::Pow(b, e)
                if e.as_num()
                    .and_then(Number::as_rational)
                    .is_some_and(|(_, q)| q == 2)
                    || ctx.positive.contains(b) => {}
            other if ctx.positive.contains(other) => {}
            _ => return Sym::call(Func::Sign, vec![a.clone()]),
        }
    }
    Sym::int(if negative { -1 } else { 1 })
}

fn has_atan(s: &Sym) -> bool {
    match s {
        Sym::Call(Func::Atan, _) => true,
        Sym::Call(_, xs) | Sym::Add(xs) | Sym::Mul(xs) => xs.iter().any(has_atan),
        Sym::Pow(a, b) => has_atan(a) || has_atan(b),
        _ => false,
    }
}

/// `∫ g dt` for a rational function `g` of `t`, brought over one denominator first.
fn rational_in(g: &Sym, t: &str, ctx: &mut Ctx) -> Option<Sym> {
    let (num, den) = together(g, t)?;
    let degree: usize = den
        .iter()
        .map(|d| coefficients(d, t).map_or(usize::MAX, |c| c.len() - 1))
        .fold(0, usize::saturating_add);
    if degree > MAX_DEGREE {
        return None;
    }
    let mut parts = vec![Sym::product(num).expand()];
    parts.extend(den.into_iter().map(|d| Sym::pow(d, Sym::int(-1))));
    ctx.integrate_in(&Sym::product(parts), t)
}

/// Whether `s` holds `func(x)`.
fn has_call(s: &Sym, x: &str, func: Func) -> bool {
    match s {
        Sym::Call(f, args) if *f == func && args[0] == var(x) => true,
        Sym::Call(_, xs) | Sym::Add(xs) | Sym::Mul(xs) => xs.iter().any(|c| has_call(c, x, func)),
        Sym::Pow(a, b) => has_call(a, x, func) || has_call(b, x, func),
        _ => false,
    }
}

/// Whether `x` occurs in `s` only as the argument of `sin`, `cos`, `tan`.
fn only_trig_of(s: &Sym, x: &str) -> bool {
    match s {
        Sym::Var(v) => v != x,
        Sym::Num(_) => true,
        Sym::Call(Func::Sin | Func::Cos | Func::Tan, args) if args[0] == var(x) => true,
        Sym::Call(_, xs) | Sym::Add(xs) | Sym::Mul(xs) => xs.iter().all(|c| only_trig_of(c, x)),
        Sym::Pow(a, b) => only_trig_of(a, x) && b.free_of(x),
        _ => false,
    }
}

/// Whether a trigonometric function of `x` occurs in a sum raised to a negative power.
fn trig_in_denominator(s: &Sym, x: &str, below: bool) -> bool {
    match s {
        Sym::Pow(a, e) => {
            let negative = e.as_num().is_some_and(Number::is_negative);
            trig_in_denominator(a, x, below || (negative && matches!(**a, Sym::Add(_))))
        }
        Sym::Call(_, _) => below && !s.free_of(x),
        Sym::Add(xs) | Sym::Mul(xs) => xs.iter().any(|c| trig_in_denominator(c, x, below)),
        _ => false,
    }
}

/// `s` with `sin x`, `cos x`, `tan x` replaced by `by(func)`.
fn rewrite(s: &Sym, x: &str, by: &dyn Fn(Func) -> Sym) -> Sym {
    match s {
        Sym::Call(func @ (Func::Sin | Func::Cos | Func::Tan), args) if args[0] == var(x) => {
            by(*func)
        }
        _ => s.map_children(|c| rewrite(c, x, by)),
    }
}

/// A rational expression in `t` as a numerator and a denominator, each a list of expanded
/// polynomial factors, with factors common to both cancelled; `None` when `s` is not a
/// rational function of `t` (or its powers are large).
fn together(s: &Sym, t: &str) -> Option<(Vec<Sym>, Vec<Sym>)> {
    if s.free_of(t) || coefficients(s, t).is_some() {
        return Some((vec![s.clone()], Vec::new()));
    }
    match s {
        Sym::Add(terms) => {
            let mut num = Sym::int(0);
            let mut den: Vec<Sym> = Vec::new();
            for term in terms {
                let (n2, d2) = together(term, t)?;
                let for_sum = minus(&d2, &den);
                let for_term = minus(&den, &d2);
                num = Sym::sum(vec![
                    Sym::product(std::iter::once(num).chain(for_sum.clone()).collect()),
                    Sym::product(n2.into_iter().chain(for_term).collect()),
                ])
                .expand();
                den.extend(for_sum);
                if den.len() > MAX_DEGREE {
                    return None; // a denominator too large for partial fractions
                }
            }
            Some(cancel(&[num], &den))
        }
        Sym::Mul(fs) => {
            let (mut num, mut den) = (Vec::new(), Vec::new());
            for g in fs {
                let (n, d) = together(g, t)?;
                num.extend(n);
                den.extend(d);
            }
            Some(cancel(&num, &den))
        }
        Sym::Pow(b, e) => {
            let k = e.as_num()?.as_integer()?;
            if k.abs() > MAX_POWER {
                return None;
            }
            let (n, d) = together(b, t)?;
            let (n, d) = if k < 0 { (d, n) } else { (n, d) };
            let repeat = |v: &Vec<Sym>| -> Vec<Sym> {
                (0..k.unsigned_abs())
                    .flat_map(|_| v.iter().cloned())
                    .collect()
            };
            Some((repeat(&n), repeat(&d)))
        }
        _ => None,
    }
}

/// The multiset difference `a \ b`.
fn minus(a: &[Sym], b: &[Sym]) -> Vec<Sym> {
    let mut b = b.to_vec();
    a.iter()
        .filter(|s| {
            if let Some(i) = b.iter().position(|c| c == *s) {
                b.swap_remove(i);
                false
            } else {
                true
            }
        })
        .cloned()
        .collect()
}

/// Expands each factor and cancels the factors common to numerator and denominator.
fn cancel(num: &[Sym], den: &[Sym]) -> (Vec<Sym>, Vec<Sym>) {
    let num: Vec<Sym> = num.iter().map(Sym::expand).collect();
    let den: Vec<Sym> = den.iter().map(Sym::expand).collect();
    (minus(&num, &den), minus(&den, &num))
}
