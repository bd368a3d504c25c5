//! Euler–Cauchy equations, `c2 t² x'' + c1 t x' + c0 x = g(t)` (constant `c_k`): with
//! `t = e^s` they have constant coefficients, characteristic polynomial
//! `c2 r(r - 1) + c1 r + c0`, so the basis `e^{rs}` of that case becomes `t^r`, `t^r ln t`,
//! `t^α cos(β ln t)`, `t^α sin(β ln t)` (for `t > 0`); a forcing by variation of parameters.

use super::constant::{basis, general, linear_parts, variation};
use super::first_order::exp_of;
use super::parse::Ode;
use super::solve::General;
use crate::ast::Func;
use crate::sym::Sym;

/// The name of `s = ln t` while the basis is built.
const S: &str = "__euler_s";

/// `exp(u)` with the logarithms of `u` taken out (`exp(2 ln t) = t^2`), everywhere in `s`.
fn powers(s: &Sym) -> Sym {
    let s = s.map_children(powers);
    match &s {
        Sym::Call(Func::Exp, u) => exp_of(&u[0]),
        _ => s,
    }
}

/// The general solution of an Euler–Cauchy equation of order 2; `None` for any other.
pub(super) fn solve(ode: &Ode, constants: &[&str]) -> Option<General> {
    let t = ode.var.as_str();
    if ode.order != 2 {
        return None;
    }
    let (a, g) = linear_parts(ode)?;
    if a.iter().all(|ak| ak.free_of(t)) {
        return None;
    }
    let c: Vec<Sym> = a
        .iter()
        .enumerate()
        .map(|(k, ak)| Sym::quotient(ak.clone(), Sym::pow(Sym::var(t), Sym::int(k as i64))))
        .collect();
    if c.iter().any(|ck| !ck.free_of(t)) {
        return None;
    }
    let shifted = [
        c[0].clone(),
        Sym::difference(c[1].clone(), c[2].clone()),
        c[2].clone(),
    ];
    let b = basis(&shifted, S);
    let ln_t = Sym::call(Func::Ln, vec![Sym::var(t)]);
    let functions: Vec<Sym> = b
        .functions
        .iter()
        .map(|f| powers(&f.substitute(S, &ln_t)))
        .collect();
    // the damping words of the constant-coefficient case do not fit: keep the roots
    let roots = b.case.split_once('(').map_or(String::new(), |(_, r)| {
        format!(", {}", r.trim_end_matches(')'))
    });
    let mut method = format!("Euler–Cauchy (t = e^s){roots}");
    let particular = if g.is_zero() {
        Sym::zero()
    } else {
        method.push_str(", variation of parameters");
        variation(&a[2], &functions, &g, t)?
    };
    Some(General {
        candidates: vec![general(&functions, constants, particular)],
        method,
        assumptions: [vec![format!("{t} > 0")], b.assumptions].concat(),
        positive: b
            .positive
            .into_iter()
            .map(|p| p.substitute(S, &ln_t))
            .collect(),
    })
}
