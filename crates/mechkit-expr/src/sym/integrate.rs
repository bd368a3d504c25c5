//! Antiderivatives from a table of rules: linearity, powers and Laurent terms, functions of a
//! linear argument `f(a x + b)`, substitution when the derivative of an inner expression is a
//! factor (`x/(a + x^2)`, `x*exp(x^2)`), integration by parts for a polynomial times
//! `sin/cos/exp/sinh/cosh` or `ln`, squares of `sin/cos/tan/sinh/cosh/tanh` (by the double
//! angle), `1/(a + b x^2)` (atan, or logarithms when the signs say
//! so), `1/sqrt(a - x^2)`, `1/sqrt(x^2 + a)`, `1/cos^2`, and rational functions whose
//! denominator factors into rational linear terms (partial fractions).
//!
//! Every result is checked by differentiating it back and comparing with the integrand at
//! several points; when no rule applies or the check fails, the answer is `None`, never a wrong
//! closed form.

use super::Sym;
use super::poly::coefficients;
use super::rational_integral::rational;
use crate::ast::Func;
use crate::number::Number;

/// An antiderivative and the assumptions it was derived under.
#[derive(Debug, Clone, PartialEq)]
pub struct Antiderivative {
    /// `F` with `F' = f`.
    pub result: Sym,
    /// Conditions assumed about the other symbols (`a > 0`), in words.
    pub assumptions: Vec<String>,
}

/// Recursion limit of the rule search.
const MAX_DEPTH: usize = 12;

/// Work budget of one integration: each rule search costs 1, each derivative taken to test a
/// substitution costs its size in nodes. The course's integrals and the tests use at most 51;
/// a search that would pass the budget (a tower of 150 powers tried for substitutions at every
/// level took 11 s) gives up, and the answer is "no closed form" (quadrature still gives the
/// definite value).
const FUEL: usize = 20_000;

pub(super) struct Ctx {
    pub x: String,
    pub assumptions: Vec<String>,
    pub positive: Vec<Sym>,
    depth: usize,
    fresh: usize,
    fuel: usize,
}

impl Sym {
    /// An antiderivative with respect to `x`, verified by differentiation; `None` when no rule
    /// of the table applies (fall back to numerical quadrature then).
    ///
    /// # Example
    /// ```
    /// use mechkit_expr::Sym;
    /// let f = Sym::parse("1/(a + x^2)").unwrap();
    /// let anti = f.integrate("x").unwrap();
    /// assert_eq!(anti.result.to_string(), "atan(x/sqrt(a))/sqrt(a)");
    /// assert_eq!(anti.assumptions, vec!["a > 0"]);
    /// ```
    pub fn integrate(&self, x: &str) -> Option<Antiderivative> {
        let mut ctx = Ctx {
            x: x.to_string(),
            assumptions: Vec::new(),
            positive: Vec::new(),
            depth: 0,
            fresh: 0,
            fuel: FUEL,
        };
        let result = integrate(self, &mut ctx)?;
        verify(self, &result, x, &ctx.positive).then_some(Antiderivative {
            result,
            assumptions: ctx.assumptions,
        })
    }
}

pub(super) fn var(x: &str) -> Sym {
    Sym::var(x)
}

pub(super) fn ln_abs(u: Sym) -> Sym {
    Sym::call(Func::Ln, vec![Sym::call(Func::Abs, vec![u])])
}

fn integrate(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    if ctx.depth > MAX_DEPTH || ctx.fuel == 0 {
        return None;
    }
    ctx.fuel -= 1;
    ctx.depth += 1;
    let r = rules(f, ctx);
    ctx.depth -= 1;
    r
}

fn rules(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    if f.free_of(x) {
        return Some(Sym::product(vec![f.clone(), var(x)]));
    }
    if let Sym::Add(terms) = f {
        let parts = terms
            .iter()
            .map(|t| integrate(t, ctx))
            .collect::<Option<Vec<_>>>()?;
        return Some(Sym::sum(parts));
    }
    if let Sym::Mul(factors) = f {
        let (constant, rest): (Vec<Sym>, Vec<Sym>) =
            factors.iter().cloned().partition(|s| s.free_of(x));
        if !constant.is_empty() {
            return Some(Sym::product(vec![
                Sym::product(constant),
                integrate(&Sym::product(rest), ctx)?,
            ]));
        }
    }
    if let Some(r) = table(f, x) {
        return Some(r);
    }
    if let Some(r) = linear_substitution(f, ctx) {
        return Some(r);
    }
    if let Some(r) = derivative_divides(f, ctx) {
        return Some(r);
    }
    let expanded = f.expand();
    if expanded != *f && matches!(expanded, Sym::Add(_)) {
        return integrate(&expanded, ctx);
    }
    if let Some(r) = rational(f, ctx) {
        return Some(r);
    }
    if let Some(r) = root_forms(f, ctx) {
        return Some(r);
    }
    by_parts(f, ctx)
}

/// Antiderivatives of the functions of `x` itself.
fn table(f: &Sym, x: &str) -> Option<Sym> {
    let xv = var(x);
    let is_x = |s: &Sym| *s == xv;
    Some(match f {
        Sym::Var(_) => Sym::product(vec![Sym::rational(1, 2), Sym::pow(xv, Sym::int(2))]),
        Sym::Pow(b, n) if is_x(b) && n.free_of(x) => {
            if n.as_num() == Some(Number::MINUS_ONE) {
                ln_abs(xv)
            } else {
                let n1 = Sym::sum(vec![(**n).clone(), Sym::one()]);
                Sym::quotient(Sym::pow(xv, n1.clone()), n1)
            }
        }
        // squares by the double angle: sin^2 x = (1 - cos 2x)/2, sinh^2 x = (cosh 2x - 1)/2
        Sym::Pow(b, n) if n.as_num() == Some(Number::int(2)) => {
            let Sym::Call(func, a) = &**b else {
                return None;
            };
            if !is_x(&a[0]) {
                return None;
            }
            let quarter = |g: Func| {
                Sym::product(vec![
                    Sym::rational(1, 4),
                    Sym::call(g, vec![Sym::product(vec![Sym::int(2), xv.clone()])]),
                ])
            };
            let half_x = Sym::product(vec![Sym::rational(1, 2), xv.clone()]);
            match func {
                Func::Sin => Sym::difference(half_x, quarter(Func::Sin)),
                Func::Cos => Sym::sum(vec![half_x, quarter(Func::Sin)]),
                Func::Sinh => Sym::difference(quarter(Func::Sinh), half_x),
                Func::Cosh => Sym::sum(vec![quarter(Func::Sinh), half_x]),
                Func::Tan => Sym::difference(Sym::call(Func::Tan, vec![xv.clone()]), xv),
                Func::Tanh => Sym::difference(xv.clone(), Sym::call(Func::Tanh, vec![xv])),
                _ => return None,
            }
        }
        // sec^2 and sech^2
        Sym::Pow(b, n) if n.as_num() == Some(Number::int(-2)) => match &**b {
            Sym::Call(Func::Cos, a) if is_x(&a[0]) => Sym::call(Func::Tan, vec![xv]),
            Sym::Call(Func::Cosh, a) if is_x(&a[0]) => Sym::call(Func::Tanh, vec![xv]),
            _ => return None,
        },
        Sym::Call(func, args) if is_x(&args[0]) && args.len() == 1 => {
            let call = |g: Func| Sym::call(g, vec![xv.clone()]);
            match func {
                Func::Sin => Sym::negate(call(Func::Cos)),
                Func::Cos => call(Func::Sin),
                Func::Tan => Sym::negate(ln_abs(call(Func::Cos))),
                Func::Exp => call(Func::Exp),
                Func::Sinh => call(Func::Cosh),
                Func::Cosh => call(Func::Sinh),
                Func::Tanh => Sym::call(Func::Ln, vec![call(Func::Cosh)]),
                Func::Ln => Sym::difference(Sym::product(vec![xv.clone(), call(Func::Ln)]), xv),
                Func::Atan => Sym::difference(
                    Sym::product(vec![xv.clone(), call(Func::Atan)]),
                    Sym::product(vec![
                        Sym::rational(1, 2),
                        Sym::call(
                            Func::Ln,
                            vec![Sym::sum(vec![Sym::one(), Sym::pow(xv, Sym::int(2))])],
                        ),
                    ]),
                ),
                Func::Asin => Sym::sum(vec![
                    Sym::product(vec![xv.clone(), call(Func::Asin)]),
                    Sym::sqrt(Sym::difference(Sym::one(), Sym::pow(xv, Sym::int(2)))),
                ]),
                Func::Abs => Sym::product(vec![Sym::rational(1, 2), xv.clone(), call(Func::Abs)]),
                Func::Sign => call(Func::Abs),
                Func::Heaviside => Sym::product(vec![xv.clone(), call(Func::Heaviside)]),
                _ => return None,
            }
        }
        _ => return None,
    })
}

/// The sub-expressions that depend on `x`: arguments of calls, bases and exponents of powers.
fn inner_candidates(f: &Sym, x: &str, out: &mut Vec<Sym>) {
    let mut push = |s: &Sym| {
        if !s.free_of(x) && !matches!(s, Sym::Var(v) if v == x) && !out.contains(s) {
            out.push(s.clone());
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
                inner_candidates(s, x, out);
            }
        }
        Sym::Pow(a, b) => {
            inner_candidates(a, x, out);
            inner_candidates(b, x, out);
        }
        _ => {}
    }
}

fn fresh(ctx: &mut Ctx) -> String {
    ctx.fresh += 1;
    format!("__u{}", ctx.fresh)
}

/// `∫ g(a x + b) dx = G(a x + b)/a` when `x` occurs only in one linear expression.
fn linear_substitution(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
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
    }
    None
}

/// `G(u)` with `G' = g` when `f = g(u)` with no `x` left over after writing `u` as a fresh
/// variable: integrates `g` in that variable and substitutes `u` back.
fn substituted(f: &Sym, u: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let t = fresh(ctx);
    let g = f.replace(u, &var(&t));
    if !g.free_of(&ctx.x) {
        return None;
    }
    let saved = std::mem::replace(&mut ctx.x, t.clone());
    let big_g = integrate(&g, ctx);
    ctx.x = saved;
    Some(big_g?.substitute(&t, u))
}

/// `∫ g(u(x)) u'(x) dx = G(u(x))`: tries each inner expression `u` whose derivative divides
/// the integrand.
fn derivative_divides(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
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

/// The number of nodes of an expression.
fn size(s: &Sym) -> usize {
    1 + match s {
        Sym::Num(_) | Sym::Var(_) => 0,
        Sym::Add(items) | Sym::Mul(items) | Sym::Call(_, items) => items.iter().map(size).sum(),
        Sym::Pow(a, b) | Sym::Cmp(_, a, b) | Sym::And(a, b) | Sym::Or(a, b) => size(a) + size(b),
        Sym::Not(a) => size(a),
    }
}

/// `(a + b x^2)^(-1/2)`: `asin(x sqrt(-b/a))/sqrt(-b)` when `b < 0`,
/// `ln(sqrt(b) x + sqrt(a + b x^2))/sqrt(b)` when `b > 0`.
fn root_forms(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let Sym::Pow(base, e) = f else { return None };
    if e.as_num() != Some(Number::rational(-1, 2)) {
        return None;
    }
    let c = coefficients(base, x)?;
    if c.len() != 3 || !c[1].is_zero() {
        return None;
    }
    let (a, b) = (&c[0], &c[2]);
    let xv = var(x);
    let b_negative = match b.as_num() {
        Some(n) => n.is_negative(),
        None => crate::sym::identities::is_negated(b),
    };
    if b_negative {
        let nb = Sym::negate(b.clone());
        if a.as_num().is_none() {
            let statement = format!("{a} > 0");
            if !ctx.assumptions.contains(&statement) {
                ctx.assumptions.push(statement);
                ctx.positive.push(a.clone());
            }
        }
        let sn = Sym::sqrt(nb);
        Some(Sym::quotient(
            Sym::call(
                Func::Asin,
                vec![Sym::quotient(
                    Sym::product(vec![xv, sn.clone()]),
                    Sym::sqrt(a.clone()),
                )],
            ),
            sn,
        ))
    } else {
        let sb = Sym::sqrt(b.clone());
        Some(Sym::quotient(
            Sym::call(
                Func::Ln,
                vec![Sym::sum(vec![
                    Sym::product(vec![sb.clone(), xv]),
                    Sym::sqrt((**base).clone()),
                ])],
            ),
            sb,
        ))
    }
}

/// Integration by parts for `P(x) g(x)` with `P` a polynomial and `g` one of sin, cos, exp,
/// sinh, cosh of a linear argument (`∫ P g = P G - ∫ P' G`), or `P(x) ln(u)`
/// (`∫ P ln u = Q ln u - ∫ Q u'/u`, `Q = ∫ P`).
fn by_parts(f: &Sym, ctx: &mut Ctx) -> Option<Sym> {
    let x = ctx.x.clone();
    let x = x.as_str();
    let Sym::Mul(factors) = f else { return None };
    let (poly, other): (Vec<Sym>, Vec<Sym>) = factors
        .iter()
        .cloned()
        .partition(|s| coefficients(s, x).is_some());
    if poly.is_empty() || other.len() != 1 {
        return None;
    }
    let p = Sym::product(poly);
    let g = &other[0];
    match g {
        Sym::Call(Func::Ln, args) => {
            let q = integrate(&p, ctx)?;
            let rest = Sym::product(vec![
                q.clone(),
                args[0].diff(x),
                Sym::pow(args[0].clone(), Sym::int(-1)),
            ]);
            Some(Sym::difference(
                Sym::product(vec![q, g.clone()]),
                integrate(&rest.expand(), ctx)?,
            ))
        }
        Sym::Call(Func::Sin | Func::Cos | Func::Exp | Func::Sinh | Func::Cosh, _) => {
            let big_g = integrate(g, ctx)?;
            let rest = Sym::product(vec![p.diff(x), big_g.clone()]).expand();
            Some(Sym::difference(
                Sym::product(vec![p, big_g]),
                integrate(&rest, ctx)?,
            ))
        }
        _ => None,
    }
}

/// Checks `F' = f` numerically at several points (other names set to values in [0.6, 1.9],
/// the assumed-positive expressions positive); at least three points must be defined and all
/// defined ones must agree.
fn verify(f: &Sym, big_f: &Sym, x: &str, positive: &[Sym]) -> bool {
    let df = big_f.diff(x);
    let mut names = f.names();
    names.extend(big_f.names());
    names.sort();
    names.dedup();
    names.retain(|n| n != x);
    let mut agree = 0;
    for trial in 0..24u32 {
        let vals: Vec<(String, f64)> = names
            .iter()
            .enumerate()
            .map(|(i, n)| {
                (
                    n.clone(),
                    0.6 + 1.3 * frac(0.37 * f64::from(trial) + 0.61 * i as f64 + 0.13),
                )
            })
            .collect();
        let env_base = |n: &str| vals.iter().find(|(m, _)| m == n).map(|(_, v)| *v);
        if positive
            .iter()
            .any(|p| p.eval(&env_base).is_ok_and(|v| v.is_nan() || v <= 0.0))
        {
            continue;
        }
        let xv = -2.3 + 4.6 * frac(0.754_877_666 * f64::from(trial) + 0.2);
        let env = |n: &str| if n == x { Some(xv) } else { env_base(n) };
        let (Ok(a), Ok(b)) = (f.eval(&env), df.eval(&env)) else {
            return false;
        };
        if !(a.is_finite() && b.is_finite()) {
            continue;
        }
        if (a - b).abs() > 1e-7 * a.abs().max(b.abs()).max(1e-3) {
            return false;
        }
        agree += 1;
    }
    agree >= 3
}

fn frac(v: f64) -> f64 {
    v - v.floor()
}

#[cfg(test)]
#[path = "integrate_tests.rs"]
mod tests;
