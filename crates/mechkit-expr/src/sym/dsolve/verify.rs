//! Substituting a solution back: the residual must simplify to 0, or vanish numerically at
//! many points where the assumptions hold.

use super::conditions::Condition;
use super::parse::Ode;
use super::solve::Verification;
use crate::sym::Sym;

/// Points tried, and how many must be usable (finite, assumptions holding).
const TRIALS: u32 = 60;
const NEEDED: usize = 8;
/// Relative tolerance of the numerical check.
const RTOL: f64 = 1e-8;

/// How `solution` was verified to solve `ode` with `conditions`; `None` if it does not.
pub(super) fn verify(
    ode: &Ode,
    solution: &Sym,
    conditions: &[Condition],
    positive: &[Sym],
) -> Option<Verification> {
    let residual = ode.residual_of(solution);
    let at = |c: &Condition| {
        let mut d = solution.clone();
        for _ in 0..c.order {
            d = d.diff(&ode.var);
        }
        d.substitute(&ode.var, &c.at)
    };
    let conds: Vec<(Sym, Sym)> = conditions
        .iter()
        .map(|c| (at(c), c.value.clone()))
        .collect();
    if residual.expand().is_zero()
        && conds
            .iter()
            .all(|(a, v)| Sym::difference(a.clone(), v.clone()).expand().is_zero())
    {
        return Some(Verification::Symbolic);
    }
    // the scale of the residual: its terms before they cancel
    let terms: Vec<Sym> = match &ode.residual {
        Sym::Add(ts) => ts.clone(),
        other => vec![other.clone()],
    };
    let terms: Vec<Sym> = terms
        .iter()
        .map(|t| {
            Ode {
                residual: t.clone(),
                ..ode.clone()
            }
            .residual_of(solution)
        })
        .collect();
    let mut names = residual.names();
    names.extend(solution.names());
    names.extend(ode.residual.names());
    for (a, v) in &conds {
        names.extend(a.names());
        names.extend(v.names());
    }
    let placeholder = format!("__{}_d", ode.func);
    names.retain(|n| *n != ode.func && !n.starts_with(&placeholder));
    names.sort();
    names.dedup();
    names.retain(|n| *n != ode.var);
    let mut agree = 0;
    for trial in 0..TRIALS {
        let vals: Vec<(&str, f64)> = names
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let v = 0.6 + 1.3 * frac(0.37 * f64::from(trial) + 0.61 * i as f64 + 0.13);
                (n.as_str(), v)
            })
            .collect();
        let base = |n: &str| vals.iter().find(|(m, _)| *m == n).map(|(_, v)| *v);
        if positive
            .iter()
            .any(|p| p.eval(&base).is_ok_and(|v| v.is_nan() || v <= 0.0))
        {
            continue;
        }
        let tv = -1.5 + 4.0 * frac(0.754_877_666 * f64::from(trial) + 0.2);
        let env = |n: &str| if n == ode.var { Some(tv) } else { base(n) };
        let Ok(r) = residual.eval(&env) else {
            return None;
        };
        let scale: f64 = terms
            .iter()
            .map(|t| t.eval(&env).map_or(f64::NAN, f64::abs))
            .sum();
        if !(r.is_finite() && scale.is_finite()) {
            continue;
        }
        if r.abs() > RTOL * scale.max(1e-300) && r != 0.0 {
            return None;
        }
        for (a, v) in &conds {
            // the scale of the condition: the terms of the solution's value there
            let scale = match a {
                Sym::Add(ts) => ts
                    .iter()
                    .map(|t| t.eval(&base).map_or(f64::NAN, f64::abs))
                    .sum(),
                other => other.eval(&base).map_or(f64::NAN, f64::abs),
            };
            let (a, v) = (a.eval(&base).ok()?, v.eval(&base).ok()?);
            if !(a - v).is_finite() || (a - v).abs() > RTOL * scale.max(v.abs()).max(1e-300) {
                return None;
            }
        }
        agree += 1;
    }
    (agree >= NEEDED).then_some(Verification::Numeric { points: agree })
}

fn frac(v: f64) -> f64 {
    v - v.floor()
}
