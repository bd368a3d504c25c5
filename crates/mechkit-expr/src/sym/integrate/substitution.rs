//! Substitutions: a linear argument, `u = g(x)` when `g'` divides the integrand, `w = x²` for
//! an odd power of `x` times an even function, `u = exp(c x)` for functions of exponentials
//! (hyperbolic functions rewritten), `v = sqrt(a x + b)`.

use super::{Ctx, Sym, size, var};
use crate::ast::Func;
use crate::number::Number;
use crate::sym::poly::coefficients;

/// The sub-expressions that depend on `x`: arguments of calls, bases and exponents of powers,
/// each once.
fn inner_candidates(f: &Sym, x: &str, out: &mut Vec<Sym>) {
    let mut keys = Vec::new();
    collect_candidates(f, x, out, &mut keys);
}

/// [`inner_candidates`], with the hashes of those found (`keys`): a deep candidate is told
/// apart from the others by its hash before it is compared with them node by node.
fn collect_candidates(f: &Sym, x: &str, out: &mut Vec<Sym>, keys: &mut Vec<u64>) {
    let mut push = |s: &Sym| {
        if s.free_of(x) || matches!(s, Sym::Var(v) if v == x) {
            return;
        }
        let key = crate::sym::build::hash_of(s);
        if !(0..out.len()).any(|i| keys[i] == key && out[i] == *s) {
            out.push(s.clone());
            keys.push(key);
        }
    };
    match f {
        Sym::Call(_, args) => {
            for a in args {
                push(a);
            }
            push(f); // sin(x) in sin(x)*cos(x)
        }
        Sym::Pow(b, e) => {
            push(b);
            push(e);
        }
        _ => {}
    }
    match f {
        Sym::Add(xs) | Sym::Mul(xs) | Sym::Call(_, xs) => {
            for s in xs {
                collect_candidates(s, x, out, keys);
            }
        }
        Sym::Pow(a, b) => {
            collect_candidates(a, x, out, keys);
            collect_candidates(b, x, out, keys);
        }
        _ => {}
    }
}

/// `∫ g(a x + b) dx = G(a x + b)/a` when `x` occurs only in one linear expression.
pub(super) fn linear_substitution(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let mut cands = Vec::new();
    inner_candidates(f, x, &mut cands);
    for u in cands {
        let Some(c) = coefficients(&u, x) else {
            continue;
        };
        if c.len() != 2 || !c[1].free_of(x) || c[1].is_zero() {
            continue;
        }
        if let Some(big_g) = substituted(f, &u, ctx) {
            return Some(Sym::quotient(big_g, c[1].clone()));
        }
        if let Some(big_g) = polynomial_times(f, &u, &c, ctx) {
            return Some(big_g);
        }
    }
    None
}

/// `∫ P(x) g(u) dx` with `u = c₀ + c₁ x` and `P` a polynomial: `x = (t − c₀)/c₁` makes it
/// `∫ P((t − c₀)/c₁) g(t) dt/c₁`, multiplied out (`x/(a + b*x)`, `x^2/(a + b*x)^2`,
/// `x*(a + b*x)^n`).
fn polynomial_times(f: &Sym, u: &Sym, c: &[Sym], ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let t = ctx.fresh();
    let g = f.replace(u, &var(&t));
    let (poly, rest): (Vec<Sym>, Vec<Sym>) = super::factors(&g)
        .into_iter()
        .partition(|fac| !fac.free_of(&x));
    if poly.is_empty() || rest.iter().all(|r| r.free_of(&t)) {
        return None;
    }
    let p = Sym::product(poly);
    let pc = coefficients(&p, &x)?;
    if pc.len() > 16 || pc.iter().any(|k| !k.free_of(&x) || !k.free_of(&t)) {
        return None;
    }
    let x_of_t = Sym::quotient(Sym::difference(var(&t), c[0].clone()), c[1].clone());
    let p_of_t = p.substitute(&x, &x_of_t);
    if !ctx.spend(super::size(&p_of_t)) {
        return None;
    }
    let integrand = Sym::product(vec![p_of_t, Sym::product(rest)]).expand();
    let big_g = ctx.integrate_in(&integrand, &t)?;
    Some(Sym::quotient(big_g.substitute(&t, u), c[1].clone()))
}

/// `G(u)` with `G' = g` when `f = g(u)` with no `x` left over after writing `u` as a fresh
/// variable: integrates `g` in that variable and substitutes `u` back.
fn substituted(f: &Sym, u: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let t = ctx.fresh();
    let g = f.replace(u, &var(&t));
    if !g.free_of(&ctx.x) {
        return None;
    }
    Some(ctx.integrate_in(&g, &t)?.substitute(&t, u))
}

/// `∫ g(u(x)) u'(x) dx = G(u(x))`: tries each inner expression `u` whose derivative divides
/// the integrand.
pub(super) fn derivative_divides(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let mut cands = Vec::new();
    inner_candidates(f, x, &mut cands);
    for u in cands {
        if ctx.fuel == 0 {
            return None;
        }
        let du = u.diff(x);
        ctx.fuel = ctx.fuel.saturating_sub(size(&du));
        if du.is_zero() {
            continue;
        }
        let q = Sym::quotient(f.clone(), du);
        if let Some(big_g) = substituted(&q, &u, ctx) {
            return Some(big_g);
        }
    }
    None
}

/// The power of `x` among the factors of `f` (`x^k`, `k` an integer) and the other factors.
pub(super) fn split_power_of_x(f: &Sym, x: &str) -> (i64, Vec<Sym>) {
    let mut k = 0i64;
    let mut rest = Vec::new();
    for fac in super::factors(f) {
        match &fac {
            Sym::Var(v) if v == x => k += 1,
            Sym::Pow(b, e)
                if matches!(&**b, Sym::Var(v) if v == x)
                    && e.as_num().and_then(Number::as_integer).is_some() =>
            {
                let n = e.as_num().and_then(Number::as_integer).unwrap_or(0);
                k = k.saturating_add(i64::try_from(n).unwrap_or(i64::MAX));
            }
            _ => rest.push(fac),
        }
    }
    (k, rest)
}

/// `∫ x^(2j+1) g(x²) dx = ½ ∫ w^j g(w) dw` (`w = x²`) when the rest `g` is an even function of
/// `x`: `x^3*sqrt(1 - x^2)`, `x^3*exp(x^2)`, `1/(x*sqrt(x^2 - 1))`.
pub(super) fn odd_power_of_x(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let (k, rest) = split_power_of_x(f, &x);
    if k % 2 == 0 || rest.is_empty() || k.abs() > 1000 {
        return None;
    }
    let g = Sym::product(rest);
    let xv = var(&x);
    if g.free_of(&x) || g.substitute(&x, &Sym::negate(xv.clone())) != g {
        return None;
    }
    let w = ctx.fresh();
    let wv = var(&w);
    let gw = g.substitute(&x, &Sym::sqrt(wv.clone()));
    if !gw.free_of(&x) || has_root_of(&gw, &w) {
        return None;
    }
    let integrand = Sym::product(vec![
        Sym::rational(1, 2),
        Sym::pow(wv, Sym::int((k - 1) / 2)),
        gw,
    ]);
    let big_g = ctx.integrate_in(&integrand, &w)?;
    Some(big_g.substitute(&w, &Sym::pow(xv, Sym::int(2))))
}

/// Whether `w` occurs under a fractional power by itself (`sqrt(w)`): the substitution
/// `x = sqrt(w)` did not make the integrand a function of `w`.
fn has_root_of(s: &Sym, w: &str) -> bool {
    match s {
        Sym::Pow(b, e) if matches!(&**b, Sym::Var(v) if v == w) => {
            e.as_num().and_then(Number::as_integer).is_none()
        }
        Sym::Add(xs) | Sym::Mul(xs) | Sym::Call(_, xs) => xs.iter().any(|c| has_root_of(c, w)),
        Sym::Pow(a, b) => has_root_of(a, w) || has_root_of(b, w),
        _ => false,
    }
}

/// `v = sqrt(a x + b)` for an integrand with a half-integer power of a linear expression:
/// `x = (v² - b)/a`, `dx = 2 v/a dv`, which makes it a rational function of `v`
/// (`x*sqrt(x + 1)`, `1/(1 + sqrt(x))`).
pub(super) fn linear_root(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let base = find_linear_root(f, &x)?;
    let c = coefficients(&base, &x)?;
    let v = ctx.fresh();
    let vv = var(&v);
    let g = replace_root(f, &base, &vv);
    let x_of_v = Sym::quotient(
        Sym::difference(Sym::pow(vv.clone(), Sym::int(2)), c[0].clone()),
        c[1].clone(),
    );
    let g = g.substitute(&x, &x_of_v);
    if !g.free_of(&x) {
        return None;
    }
    let integrand = Sym::product(vec![
        Sym::int(2),
        vv,
        Sym::pow(c[1].clone(), Sym::int(-1)),
        g,
    ]);
    let big_g = ctx.integrate_in(&integrand, &v)?;
    Some(big_g.substitute(&v, &Sym::sqrt(base)))
}

fn find_linear_root(s: &Sym, x: &str) -> Option<Sym> {
    match s {
        Sym::Pow(b, e)
            if e.as_num()
                .and_then(Number::as_rational)
                .is_some_and(|(_, q)| q == 2)
                && coefficients(b, x).is_some_and(|c| {
                    c.len() == 2 && c[1].free_of(x) && !c[1].is_zero() && c[0].free_of(x)
                }) =>
        {
            Some((**b).clone())
        }
        Sym::Add(xs) | Sym::Mul(xs) | Sym::Call(_, xs) => {
            xs.iter().find_map(|c| find_linear_root(c, x))
        }
        Sym::Pow(a, b) => find_linear_root(a, x).or_else(|| find_linear_root(b, x)),
        _ => None,
    }
}

/// Replaces `base^(p/2)` by `v^p` and `base^n` by `v^(2n)`.
fn replace_root(s: &Sym, base: &Sym, v: &Sym) -> Sym {
    if s == base {
        return Sym::pow(v.clone(), Sym::int(2));
    }
    if let Sym::Pow(b, e) = s
        && **b == *base
        && let Some(n) = e.as_num()
        && n.is_exact()
    {
        return Sym::pow(v.clone(), Sym::Num(n.times(Number::int(2))));
    }
    s.map_children(|c| replace_root(c, base, v))
}

/// `u = exp(c x)` when `x` occurs only in exponentials `exp(n c x)` and hyperbolic functions
/// of `n c x` (`n` an integer): `dx = du/(c u)`, a rational function of `u`
/// (`1/(1 + exp(x))`, `1/cosh(x)`, `exp(2*x)/(1 + exp(x))`).
pub(super) fn exponential(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let mut rates = Vec::new();
    exp_rates(f, &x, &mut rates);
    for c in rates {
        let u = ctx.fresh();
        let uv = var(&u);
        let Some(g) = rewrite_exp(f, &x, &c, &uv) else {
            continue;
        };
        if !g.free_of(&x) {
            continue;
        }
        let integrand = Sym::quotient(g, Sym::product(vec![c.clone(), uv]));
        if let Some(big_g) = ctx.integrate_in(&clear_negative_powers(&integrand, &u), &u) {
            let ecx = Sym::call(Func::Exp, vec![Sym::product(vec![c, var(&x)])]);
            return Some(big_g.substitute(&u, &ecx));
        }
    }
    None
}

/// The rates `c` of the exponentials and hyperbolic functions `exp(c x)`, `sinh(c x)`.
fn exp_rates(s: &Sym, x: &str, out: &mut Vec<Sym>) {
    if let Sym::Call(Func::Exp | Func::Sinh | Func::Cosh | Func::Tanh, args) = s
        && let Some(c) = coefficients(&args[0], x)
        && c.len() == 2
        && c[0].is_zero()
        && c[1].free_of(x)
    {
        if !out.contains(&c[1]) {
            out.push(c[1].clone());
        }
        return;
    }
    match s {
        Sym::Add(xs) | Sym::Mul(xs) | Sym::Call(_, xs) => {
            for c in xs {
                exp_rates(c, x, out);
            }
        }
        Sym::Pow(a, b) => {
            exp_rates(a, x, out);
            exp_rates(b, x, out);
        }
        _ => {}
    }
}

/// `s` with `exp(n c x)` written `u^n` (and `sinh`, `cosh`, `tanh` through exponentials);
/// `None` when some rate is not an integer multiple of `c` (or a large one).
fn rewrite_exp(s: &Sym, x: &str, c: &Sym, u: &Sym) -> Option<Sym> {
    if let Sym::Call(func @ (Func::Exp | Func::Sinh | Func::Cosh | Func::Tanh), args) = s
        && !args[0].free_of(x)
    {
        let ratio = Sym::quotient(args[0].clone(), Sym::product(vec![c.clone(), var(x)]));
        let n = ratio.as_num()?.as_integer()?;
        if n.abs() > 64 {
            return None;
        }
        let up = Sym::pow(u.clone(), Sym::int(n as i64));
        let um = Sym::pow(u.clone(), Sym::int(-n as i64));
        return Some(match func {
            Func::Exp => up,
            Func::Sinh => Sym::product(vec![Sym::rational(1, 2), Sym::difference(up, um)]),
            Func::Cosh => Sym::product(vec![Sym::rational(1, 2), Sym::sum(vec![up, um])]),
            _ => Sym::quotient(
                Sym::difference(Sym::pow(u.clone(), Sym::int(2 * n as i64)), Sym::one()),
                Sym::sum(vec![
                    Sym::pow(u.clone(), Sym::int(2 * n as i64)),
                    Sym::one(),
                ]),
            ),
        });
    }
    Some(match s {
        Sym::Num(_) | Sym::Var(_) => s.clone(),
        Sym::Add(xs) => Sym::sum(
            xs.iter()
                .map(|t| rewrite_exp(t, x, c, u))
                .collect::<Option<_>>()?,
        ),
        Sym::Mul(xs) => Sym::product(
            xs.iter()
                .map(|t| rewrite_exp(t, x, c, u))
                .collect::<Option<_>>()?,
        ),
        Sym::Pow(a, b) => Sym::pow(rewrite_exp(a, x, c, u)?, rewrite_exp(b, x, c, u)?),
        Sym::Call(func, xs) => Sym::call(
            *func,
            xs.iter()
                .map(|t| rewrite_exp(t, x, c, u))
                .collect::<Option<_>>()?,
        ),
        _ => return None,
    })
}

/// Writes each integer power of a sum holding negative powers of `u` as a power of a
/// polynomial times a power of `u`: `(u + u^-1)^-1 = u (u^2 + 1)^-1`, so that partial
/// fractions see a rational function.
fn clear_negative_powers(s: &Sym, u: &str) -> Sym {
    match s {
        Sym::Pow(b, e)
            if matches!(&**b, Sym::Add(_)) && e.as_num().and_then(Number::as_integer).is_some() =>
        {
            let Sym::Add(terms) = b.expand() else {
                return s.clone();
            };
            let low = terms
                .iter()
                .map(|t| split_power_of_x(t, u).0)
                .min()
                .unwrap_or(0);
            if low >= 0 {
                return s.clone();
            }
            let shift = Sym::pow(var(u), Sym::int(-low));
            let poly = Sym::product(vec![shift.clone(), Sym::Add(terms)]).expand();
            Sym::product(vec![
                Sym::pow(poly, (**e).clone()),
                Sym::pow(shift, Sym::negate((**e).clone())),
            ])
        }
        _ => s.map_children(|c| clear_negative_powers(c, u)),
    }
}
