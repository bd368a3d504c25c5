//! First order, `x' = f(t, x)`: linear (integrating factor), separable, Bernoulli.

use super::invert::solve_for;
use super::parse::{Ode, derivative_name};
use super::solve::General;
use crate::ast::Func;
use crate::number::Number;
use crate::sym::Sym;
use crate::sym::build::split_coefficient;
use crate::sym::poly::coefficients;

/// The general solution of a first-order equation linear in `x'`, by the first method that
/// applies.
pub(super) fn solve(ode: &Ode, constants: &[&str]) -> Option<General> {
    let (x, t) = (ode.func.as_str(), ode.var.as_str());
    let p = derivative_name(x, 1);
    let c = coefficients(&ode.residual, &p)?;
    if c.len() != 2 || c[1].is_zero() || !c[1].free_of(&p) {
        return None;
    }
    let f = Sym::negate(Sym::quotient(c[0].clone(), c[1].clone()));
    let k = constants[0];
    linear(&f, x, t, k)
        .or_else(|| separable(&f, x, t, k))
        .or_else(|| bernoulli(&f, x, t, k))
}

/// `x' = a(t) x + b(t)`.
fn linear(f: &Sym, x: &str, t: &str, k: &str) -> Option<General> {
    let c = coefficients(f, x)?;
    if c.len() > 2 || c.iter().any(|s| !s.free_of(x)) {
        return None;
    }
    let a = c.get(1).cloned().unwrap_or_else(Sym::zero);
    let (solution, assumptions) = integrating_factor(&Sym::negate(a), &c[0], t, k)?;
    Some(General {
        candidates: vec![solution],
        method: "linear first order (integrating factor)".into(),
        assumptions,
        positive: Vec::new(),
    })
}

/// The solution of `x' + p x = q`: `(∫ q μ dt + C)/μ` with `μ = e^{∫p}`.
pub(super) fn integrating_factor(p: &Sym, q: &Sym, t: &str, k: &str) -> Option<(Sym, Vec<String>)> {
    let ip = p.integrate(t)?;
    let mu = exp_of(&ip.result);
    let iq = Sym::product(vec![q.clone(), mu.clone()]).integrate(t)?;
    let mut assumptions = ip.assumptions;
    assumptions.extend(iq.assumptions);
    let solution = Sym::quotient(Sym::sum(vec![iq.result, Sym::var(k)]), mu);
    Some((solution, assumptions))
}

/// `e^s` with the logarithms in `s` taken out: `e^{2 ln|t| + t} = t^2 e^t` (an integrating
/// factor's sign does not matter, so `|t|` is `t`).
pub(super) fn exp_of(s: &Sym) -> Sym {
    let terms = match s {
        Sym::Add(ts) => ts.clone(),
        other => vec![other.clone()],
    };
    let mut factors = Vec::new();
    let mut rest = Vec::new();
    for term in terms {
        match split_coefficient(&term) {
            (n, Some(Sym::Call(Func::Ln, u))) => {
                let inner = match &u[0] {
                    Sym::Call(Func::Abs, v) => v[0].clone(),
                    other => other.clone(),
                };
                factors.push(Sym::pow(inner, Sym::Num(n)));
            }
            _ => rest.push(term),
        }
    }
    factors.push(Sym::call(Func::Exp, vec![Sym::sum(rest)]));
    Sym::product(factors)
}

/// `x' = g(t) h(x)`: `∫ dx/h = ∫ g dt + C`, inverted.
fn separable(f: &Sym, x: &str, t: &str, k: &str) -> Option<General> {
    let (g, h) = factor_separable(f, x, t)?;
    let big_h = Sym::quotient(Sym::one(), h).integrate(x)?;
    let big_g = g.integrate(t)?;
    let rhs = Sym::sum(vec![big_g.result, Sym::var(k)]);
    let candidates = solve_for(&big_h.result, x, &rhs, Some(k));
    if candidates.is_empty() {
        return None;
    }
    let mut assumptions = big_h.assumptions;
    assumptions.extend(big_g.assumptions);
    Some(General {
        candidates,
        method: "separable".into(),
        assumptions,
        positive: Vec::new(),
    })
}

/// `f(t, x) = g(t) h(x)`: the factors of a product sorted (an exponential of a sum split,
/// `e^{t - x} = e^t e^{-x}`), or else the terms of the expanded
/// sum grouped by their factor in `x` (`t + t x² = t (1 + x²)`), each group's factor in `t`
/// a multiple of the first group's.
fn factor_separable(f: &Sym, x: &str, t: &str) -> Option<(Sym, Sym)> {
    let split = |s: &Sym| -> (Sym, Sym) {
        let factors = crate::sym::integrate::factors(s);
        let (mut g, mut h) = (Vec::new(), Vec::new());
        for f in factors {
            match &f {
                _ if f.free_of(x) => g.push(f),
                // e^{a(t) + b(x)} = e^{a(t)} e^{b(x)}
                Sym::Call(Func::Exp, u) if matches!(&u[0], Sym::Add(_)) => {
                    let Sym::Add(ts) = &u[0] else { unreachable!() };
                    let (a, b): (Vec<Sym>, Vec<Sym>) =
                        ts.iter().cloned().partition(|s| s.free_of(x));
                    g.push(Sym::call(Func::Exp, vec![Sym::sum(a)]));
                    h.push(Sym::call(Func::Exp, vec![Sym::sum(b)]));
                }
                _ => h.push(f),
            }
        }
        (Sym::product(g), Sym::product(h))
    };
    let (g, h) = split(f);
    if h.free_of(t) {
        return (!h.free_of(x)).then_some((g, h));
    }
    let Sym::Add(terms) = f.expand() else {
        return None;
    };
    let mut groups: Vec<(Sym, Vec<Sym>)> = Vec::new();
    for term in &terms {
        let (g, h) = split(term);
        if !h.free_of(t) {
            return None;
        }
        match groups.iter_mut().find(|(k, _)| *k == h) {
            Some((_, gs)) => gs.push(g),
            None => groups.push((h, vec![g])),
        }
    }
    let g = Sym::sum(groups[0].1.clone());
    let mut h = Vec::new();
    for (hk, gk) in groups {
        let ratio = Sym::quotient(Sym::sum(gk), g.clone());
        if !ratio.free_of(t) {
            return None;
        }
        h.push(Sym::product(vec![ratio, hk]));
    }
    let h = Sym::sum(h);
    (!h.free_of(x)).then_some((g, h))
}

/// The power of `x` in a term and its coefficient.
fn power_of(term: &Sym, x: &str) -> Option<(Number, Sym)> {
    let factors = crate::sym::integrate::factors(term);
    let mut n = Number::ZERO;
    let mut rest = Vec::new();
    for f in factors {
        match &f {
            Sym::Var(v) if v == x => n = n.plus(Number::ONE),
            Sym::Pow(b, e) if matches!(&**b, Sym::Var(v) if v == x) => n = n.plus(e.as_num()?),
            other if other.free_of(x) => rest.push(f),
            _ => return None,
        }
    }
    Some((n, Sym::product(rest)))
}

/// `x' = a(t) x + b(t) x^n`: linear in `v = x^{1-n}`, `v' = (1-n)(a v + b)`.
fn bernoulli(f: &Sym, x: &str, t: &str, k: &str) -> Option<General> {
    let terms = match f.expand() {
        Sym::Add(ts) => ts,
        other => vec![other],
    };
    let mut a = Vec::new();
    let mut b = Vec::new();
    let mut n: Option<Number> = None;
    for term in &terms {
        let (p, c) = power_of(term, x)?;
        if p.is_one() {
            a.push(c);
        } else if p.is_zero() || n.is_some_and(|m| m != p) {
            return None;
        } else {
            n = Some(p);
            b.push(c);
        }
    }
    let n = n?;
    let m = Number::ONE.plus(n.negated());
    let ms = Sym::Num(m);
    let p = Sym::negate(Sym::product(vec![ms.clone(), Sym::sum(a)]));
    let q = Sym::product(vec![ms.clone(), Sym::sum(b)]);
    let (v, assumptions) = integrating_factor(&p, &q, t, k)?;
    let root = Sym::pow(v, Sym::quotient(Sym::one(), ms));
    let even = m.as_rational().is_some_and(|(p, _)| p % 2 == 0);
    let mut candidates = vec![root.clone()];
    if even {
        candidates.push(Sym::negate(root));
    }
    Some(General {
        candidates,
        method: format!("Bernoulli (linear in {x}^{})", Sym::Num(m)),
        assumptions,
        positive: Vec::new(),
    })
}
