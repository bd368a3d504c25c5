//! Integrands rewritten into forms the other rules know: `log10 u = ln u / ln 10`,
//! `sqrt(1 + sinh² u) = cosh u`, `exp(a) exp(b) = exp(a + b)`, `ln(p/q) = ln|p| − ln|q|`, `sqrt(p/q) = sqrt(p)/sqrt(q)`,
//! `1/(√a + √b) = (√a − √b)/(a − b)`, hyperbolic functions beside trigonometric ones (or of
//! another argument) as exponentials, and `|a x + b|` by its sign on either side of the root.

use super::{Ctx, Sym, integrate};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::poly::coefficients;

/// `s` with every node `g` for which `by(g)` is `Some` replaced, children first.
fn rewrite(s: &Sym, by: &dyn Fn(&Sym) -> Option<Sym>) -> Sym {
    let s = s.map_children(|c| rewrite(c, by));
    by(&s).unwrap_or(s)
}

/// The integrand rewritten by `by`, when that changes it.
fn changed(f: &Sym, by: &dyn Fn(&Sym) -> Option<Sym>) -> Option<Sym> {
    let g = rewrite(f, by);
    (g != *f).then_some(g)
}

fn half() -> Sym {
    Sym::rational(1, 2)
}

/// The rewrites that hold wherever the integrand is defined, tried before the table:
/// `log10 u = ln u / ln 10`, `(1 + sinh² u)^(k/2) = cosh^k u` and `exp(a) exp(b) = exp(a + b)`.
pub(super) fn identities(f: &Sym) -> Option<Sym> {
    changed(f, &|s| match s {
        Sym::Mul(fs) => {
            let (exps, rest): (Vec<Sym>, Vec<Sym>) = fs
                .iter()
                .cloned()
                .partition(|g| matches!(g, Sym::Call(Func::Exp, _)));
            (exps.len() > 1).then(|| {
                let sum = exps
                    .iter()
                    .filter_map(|g| match g {
                        Sym::Call(_, a) => Some(a[0].clone()),
                        _ => None,
                    })
                    .collect();
                let mut out = rest;
                out.push(Sym::call(Func::Exp, vec![Sym::sum(sum)]));
                Sym::product(out)
            })
        }
        Sym::Call(Func::Log10, args) => Some(Sym::quotient(
            Sym::call(Func::Ln, args.clone()),
            Sym::call(Func::Ln, vec![Sym::int(10)]),
        )),
        Sym::Pow(b, e) => {
            let Sym::Add(terms) = &**b else { return None };
            let [a, b] = &terms[..] else { return None };
            let (one, sq) = if a.is_one() { (a, b) } else { (b, a) };
            if !one.is_one() {
                return None;
            }
            let Sym::Pow(sh, two) = sq else { return None };
            let Sym::Call(Func::Sinh, args) = &**sh else {
                return None;
            };
            let k = e.as_num()?.times(Number::int(2));
            (two.as_num() == Some(Number::int(2)) && k.as_integer().is_some())
                .then(|| Sym::pow(Sym::call(Func::Cosh, args.clone()), Sym::Num(k)))
        }
        _ => None,
    })
}

/// A rational expression in `x` as `p/q`, both polynomials: a sum over the product of its
/// terms' denominators (`1 + 1/x = (x + 1)/x`), or a product with negative powers.
fn quotient(u: &Sym, x: &str) -> Option<(Sym, Sym)> {
    let mut den: Vec<Sym> = Vec::new();
    let terms = match u {
        Sym::Add(ts) => ts.clone(),
        other => vec![other.clone()],
    };
    for t in &terms {
        for fac in super::factors(t) {
            if let Sym::Pow(b, e) = &fac
                && !b.free_of(x)
                && e.as_num().is_some_and(Number::is_negative)
            {
                let inv = Sym::pow((**b).clone(), Sym::Num(e.as_num()?.negated()));
                if !den.contains(&inv) {
                    den.push(inv);
                }
            }
        }
    }
    if den.is_empty() {
        return None;
    }
    let q = Sym::product(den).expand();
    let p = Sym::product(vec![u.clone(), q.clone()]).expand();
    (coefficients(&p, x).is_some() && coefficients(&q, x).is_some()).then_some((p, q))
}

/// `ln(p/q) = ln|p| − ln|q|` for a rational argument that is not a polynomial
/// (`ln(1 + 1/x)`), `(p/q)^k` for an integer `k` (`1/(x (1 + 1/x²)) = x/(x² + 1)`), and `sqrt(p/q) = sqrt(±p)/sqrt(±q)` with the sign that makes both
/// positive where the quotient is (`sqrt(x/(1 - x)) = sqrt(x)/sqrt(1 - x)`).
pub(super) fn quotients(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let g = changed(f, &|s| match s {
        Sym::Call(Func::Ln, args) => {
            let (p, q) = quotient(&args[0], &x)?;
            Some(Sym::difference(super::ln_abs(p), super::ln_abs(q)))
        }
        Sym::Pow(b, e) if e.as_num().and_then(Number::as_integer).is_some() && !b.free_of(&x) => {
            let (p, q) = quotient(b, &x)?;
            Some(Sym::product(vec![
                Sym::pow(p, (**e).clone()),
                Sym::pow(q, Sym::negate((**e).clone())),
            ]))
        }
        Sym::Pow(b, e) if e.as_num() == Some(Number::rational(1, 2)) && !b.free_of(&x) => {
            let (p, q) = quotient(b, &x)?;
            let sign = positive_sign(&p, &q, &x)?;
            let (p, q) = (
                Sym::product(vec![Sym::int(sign), p]),
                Sym::product(vec![Sym::int(sign), q]),
            );
            Some(Sym::quotient(Sym::sqrt(p), Sym::sqrt(q)))
        }
        _ => None,
    })?;
    integrate(&g, ctx)
}

/// `1` or `−1`: the sign `s` with `s p > 0` and `s q > 0` at the first of some sample points
/// where `p/q > 0` (with the other names set to 1); `None` when there is none.
fn positive_sign(p: &Sym, q: &Sym, x: &str) -> Option<i64> {
    (0..64).find_map(|i| {
        let xv = -8.0 + 0.25 * f64::from(i) + 0.0123;
        let env = |n: &str| Some(if n == x { xv } else { 1.0 });
        let (pv, qv) = (p.eval(&env).ok()?, q.eval(&env).ok()?);
        (pv * qv > 0.0 && pv.is_finite() && qv.is_finite()).then_some(if qv > 0.0 { 1 } else { -1 })
    })
}

/// `1/(c √a + d √b) = (c √a − d √b)/(c² a − d² b)` when `c² a − d² b` is free of `x`
/// (`1/(sqrt(x + 1) + sqrt(x)) = sqrt(x + 1) − sqrt(x)`).
pub(super) fn rationalize(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let root = |t: &Sym| -> Option<(Sym, Sym)> {
        let mut fs = super::factors(t);
        let i = fs.iter().position(
            |g| matches!(g, Sym::Pow(_, e) if e.as_num() == Some(Number::rational(1, 2))),
        )?;
        let Sym::Pow(a, _) = fs.remove(i) else {
            return None;
        };
        let c = Sym::product(fs);
        c.free_of(&x).then_some((c, *a))
    };
    let g = changed(f, &|s| {
        let Sym::Pow(b, e) = s else { return None };
        if e.as_num() != Some(Number::int(-1)) {
            return None;
        }
        let Sym::Add(terms) = &**b else { return None };
        let [t1, t2] = &terms[..] else { return None };
        let ((c, a), (d, bb)) = (root(t1)?, root(t2)?);
        let square =
            |k: &Sym, v: &Sym| Sym::product(vec![Sym::pow(k.clone(), Sym::int(2)), v.clone()]);
        let den = Sym::difference(square(&c, &a), square(&d, &bb)).expand();
        (den.free_of(&x) && !den.is_zero())
            .then(|| Sym::quotient(Sym::difference(t1.clone(), t2.clone()), den))
    })?;
    integrate(&g.expand(), ctx)
}

/// Whether `s` holds `func(u)` with `u` depending on `x`, for one of `funcs`.
fn holds(s: &Sym, x: &str, funcs: &[Func]) -> bool {
    s.any(&mut |n| matches!(n, Sym::Call(g, args) if funcs.contains(g) && !args[0].free_of(x)))
}

/// `sinh u = (eᵘ − e⁻ᵘ)/2` and `cosh u = (eᵘ + e⁻ᵘ)/2` in an integrand that holds them
/// beside `sin` or `cos`, or of two arguments (`cosh x cos x`, `cosh 2x sinh 3x`): products
/// of exponentials and sines the other rules integrate.
pub(super) fn hyperbolic_as_exponentials(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let hyper = [Func::Sinh, Func::Cosh];
    if !holds(f, &x, &hyper) {
        return None;
    }
    let mut args: Vec<Sym> = Vec::new();
    f.any(&mut |n| {
        if let Sym::Call(Func::Sinh | Func::Cosh, a) = n
            && !args.contains(&a[0])
        {
            args.push(a[0].clone());
        }
        false
    });
    if args.len() < 2 && !holds(f, &x, &[Func::Sin, Func::Cos]) {
        return None;
    }
    let g = changed(f, &|s| match s {
        Sym::Call(func @ (Func::Sinh | Func::Cosh), a) => {
            let up = Sym::call(Func::Exp, vec![a[0].clone()]);
            let down = Sym::call(Func::Exp, vec![Sym::negate(a[0].clone())]);
            let sign = if *func == Func::Sinh { -1 } else { 1 };
            Some(Sym::product(vec![
                half(),
                Sym::sum(vec![up, Sym::product(vec![Sym::int(sign), down])]),
            ]))
        }
        _ => None,
    })?;
    integrate(&g.expand(), ctx)
}

/// `∫ f` for an integrand holding `|u|` of one linear `u = a x + b` (`x|x|`, `exp(-|x|)`,
/// `sqrt(|x|)`): `F₊` with `|u| = u` and `F₋` with `|u| = −u`, each less its value at the
/// root where that is finite, and written in `|u|` (`x = (±|u| − b)/a` on its side, so that
/// each is defined on both sides), joined as `(G₊ + G₋)/2 + sign(u) (G₊ − G₋)/2`: an
/// antiderivative on either side, continuous across the root.
pub(super) fn linear_abs(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let mut inner: Vec<Sym> = Vec::new();
    f.any(&mut |n| {
        if let Sym::Call(Func::Abs, a) = n
            && !a[0].free_of(&x)
            && !inner.contains(&a[0])
        {
            inner.push(a[0].clone());
        }
        false
    });
    let [u] = &inner[..] else { return None };
    let c = coefficients(u, &x).filter(|c| c.len() == 2)?;
    let root = Sym::negate(Sym::quotient(c[0].clone(), c[1].clone()));
    let abs_u = Sym::call(Func::Abs, vec![u.clone()]);
    let mut side = |sign: i64| -> Option<Sym> {
        let s = Sym::product(vec![Sym::int(sign), u.clone()]);
        let g = f.replace(&abs_u, &s);
        if g.any(&mut |n| matches!(n, Sym::Call(Func::Abs, a) if a[0] == *u)) {
            return None;
        }
        let big = integrate(&g, ctx)?;
        let at_root = big.substitute(&x, &root);
        let finite = at_root.eval(&|_| Some(1.3)).is_ok_and(f64::is_finite);
        let big = if finite {
            Sym::difference(big, at_root)
        } else {
            big
        };
        let mirror = Sym::quotient(
            Sym::difference(
                Sym::product(vec![Sym::int(sign), abs_u.clone()]),
                c[0].clone(),
            ),
            c[1].clone(),
        );
        Some(big.substitute(&x, &mirror))
    };
    let plus = side(1)?;
    let minus = side(-1)?;
    Some(Sym::sum(vec![
        Sym::product(vec![half(), Sym::sum(vec![plus.clone(), minus.clone()])]),
        Sym::product(vec![
            half(),
            Sym::call(Func::Sign, vec![u.clone()]),
            Sym::difference(plus, minus),
        ]),
    ]))
}

/// `sinᵐ u cosⁿ u` with `n` odd and `m` not an integer (`cos³ x/sqrt(sin x)`) written with
/// `cosⁿ⁻¹ u = (1 − sin² u)^((n−1)/2)`, the rest a function of `sin u` times `cos u` that
/// `u = sin x` integrates (and the same with `sin` and `cos` exchanged).
pub(super) fn odd_trig_power(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let fs = super::factors(f);
    let power = |g: &Sym, func: Func| -> Option<(Sym, Number)> {
        match g {
            Sym::Pow(b, e) => match &**b {
                Sym::Call(h, a) if *h == func && !a[0].free_of(&x) => {
                    Some((a[0].clone(), e.as_num()?))
                }
                _ => None,
            },
            _ => None,
        }
    };
    for (odd, other) in [(Func::Cos, Func::Sin), (Func::Sin, Func::Cos)] {
        let Some(i) = fs.iter().position(|g| {
            power(g, odd).is_some_and(|(_, n)| n.as_integer().is_some_and(|n| n >= 3 && n % 2 == 1))
        }) else {
            continue;
        };
        let (u, n) = power(&fs[i], odd)?;
        let fractional = fs
            .iter()
            .any(|g| power(g, other).is_some_and(|(v, m)| v == u && m.as_integer().is_none()));
        if !fractional {
            continue;
        }
        let k = (n.as_integer()? - 1) / 2;
        let one_minus = Sym::difference(
            Sym::one(),
            Sym::pow(Sym::call(other, vec![u.clone()]), Sym::int(2)),
        );
        let mut g = fs.clone();
        g[i] = Sym::product(vec![
            Sym::pow(one_minus, Sym::Num(Number::rational(k, 1))),
            Sym::call(odd, vec![u]),
        ]);
        return integrate(&Sym::product(g).expand(), ctx);
    }
    None
}
