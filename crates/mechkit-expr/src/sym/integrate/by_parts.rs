//! Integration by parts, `∫ u dv = u v - ∫ v du`: a logarithm or an inverse function times
//! an integrable factor (`x*atan(x)`, `ln(x)^2`, `x^2*ln(x)`), a polynomial times an
//! integrable transcendental factor (`x^2*exp(-x)`, `x*exp(x)*sin(x)`), and the cyclic case
//! `exp(a x) sin(b x)` in closed form.

use super::{Ctx, Sym, factors, integrate};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::poly::coefficients;

/// Whether `g` is a factor to differentiate: `ln(u)^n`, `atan(u)`, `asin(u)`, `acos(u)`.
fn to_differentiate(g: &Sym, x: &str) -> bool {
    let call = match g {
        Sym::Pow(b, e)
            if e.as_num()
                .and_then(Number::as_integer)
                .is_some_and(|n| n > 0) =>
        {
            b
        }
        other => other,
    };
    matches!(call, Sym::Call(Func::Ln | Func::Atan | Func::Asin | Func::Acos, args) if !args[0].free_of(x))
}

/// Whether `s` holds a call (a transcendental function) that depends on `x`.
fn has_call(s: &Sym, x: &str) -> bool {
    match s {
        Sym::Call(_, _) => !s.free_of(x),
        Sym::Add(xs) | Sym::Mul(xs) => xs.iter().any(|c| has_call(c, x)),
        Sym::Pow(a, b) => has_call(a, x) || has_call(b, x),
        _ => false,
    }
}

/// Integration by parts.
pub(super) fn by_parts(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let mut fs = factors(f);
    // a logarithm or inverse function: differentiate it, integrate the rest
    if let Some(i) = fs.iter().position(|g| to_differentiate(g, x)) {
        let g = fs.remove(i);
        let rest = fs;
        let q = integrate(&Sym::product(rest), ctx)?;
        let rest = Sym::product(vec![q.clone(), g.diff(x)]);
        return Some(Sym::difference(
            Sym::product(vec![q, g]),
            integrate(&rest, ctx)?,
        ));
    }
    // a polynomial times a transcendental factor: differentiate the polynomial
    let (poly, other): (Vec<Sym>, Vec<Sym>) = fs
        .iter()
        .cloned()
        .partition(|s| coefficients(s, x).is_some());
    if poly.is_empty() || other.is_empty() {
        return None;
    }
    let other = Sym::product(other);
    if !has_call(&other, x) {
        return None;
    }
    let p = Sym::product(poly);
    let big_g = integrate(&other, ctx)?;
    let rest = Sym::product(vec![p.diff(x), big_g.clone()]).expand();
    Some(Sym::difference(
        Sym::product(vec![p, big_g]),
        integrate(&rest, ctx)?,
    ))
}

/// `∫ exp(a x + a0) sin(b x + b0) dx = exp(…)(a sin(…) - b cos(…))/(a² + b²)` and
/// `∫ exp(…) cos(…) dx = exp(…)(a cos(…) + b sin(…))/(a² + b²)` (the cyclic case of
/// integration by parts, solved once for all), with symbolic `a`, `b`.
pub(super) fn cyclic(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let Sym::Mul(fs) = f else { return None };
    if fs.len() != 2 {
        return None;
    }
    let linear =
        |s: &Sym| coefficients(s, x).filter(|c| c.len() == 2 && c.iter().all(|k| k.free_of(x)));
    let (mut exp_arg, mut trig) = (None, None);
    for g in fs {
        match g {
            Sym::Call(Func::Exp, args) => exp_arg = Some(args[0].clone()),
            Sym::Call(func @ (Func::Sin | Func::Cos), args) => {
                trig = Some((*func, args[0].clone()));
            }
            _ => return None,
        }
    }
    let (ea, (func, ta)) = (exp_arg?, trig?);
    let (a, b) = (linear(&ea)?[1].clone(), linear(&ta)?[1].clone());
    let e = Sym::call(Func::Exp, vec![ea]);
    let (s, c) = (
        Sym::call(Func::Sin, vec![ta.clone()]),
        Sym::call(Func::Cos, vec![ta]),
    );
    let combo = match func {
        Func::Sin => Sym::difference(
            Sym::product(vec![a.clone(), s]),
            Sym::product(vec![b.clone(), c]),
        ),
        _ => Sym::sum(vec![
            Sym::product(vec![a.clone(), c]),
            Sym::product(vec![b.clone(), s]),
        ]),
    };
    let norm = Sym::sum(vec![
        Sym::pow(a.clone(), Sym::int(2)),
        Sym::pow(b.clone(), Sym::int(2)),
    ]);
    if norm.as_num().is_none() {
        let statement = format!("{norm} ≠ 0");
        if !ctx.assumptions.contains(&statement) {
            ctx.assumptions.push(statement);
        }
    }
    Some(Sym::product(vec![e, combo, Sym::pow(norm, Sym::int(-1))]))
}

/// The product rule backwards: `∫ exp(c x + d) g dx = exp(c x + d) h` when `g = c h + h'`,
/// for `h` one term of `g` over `c` (`exp(x) (1/x + ln x) → exp(x) ln x`, whose terms have no
/// antiderivatives of their own); checked by differentiation.
pub(super) fn product_rule_backwards(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let mut fs = factors(f);
    let i = fs.iter().position(|g| {
        matches!(g, Sym::Call(Func::Exp, a)
            if coefficients(&a[0], x).is_some_and(|c| c.len() == 2 && c[1].free_of(x)))
    })?;
    let e = fs.remove(i);
    let Sym::Call(_, a) = &e else { return None };
    let c = coefficients(&a[0], x)?.pop()?;
    let g = Sym::product(fs).expand();
    let terms = match &g {
        Sym::Add(ts) if ts.len() <= 8 => ts.clone(),
        Sym::Add(_) => return None,
        other => vec![other.clone()],
    };
    if !ctx.spend(super::size(f) * terms.len()) {
        return None;
    }
    terms.iter().find_map(|t| {
        let big_f = Sym::product(vec![e.clone(), Sym::quotient(t.clone(), c.clone())]);
        super::verify(f, &big_f, x, &ctx.positive).then_some(big_f)
    })
}
