//! Substituting a solution back: the residual must simplify to 0, or vanish numerically at
//! many points where the assumptions hold; a solution that holds only on an interval (a
//! square root's branch) is checked on the stretch around the conditions' point instead.

use super::conditions::Condition;
use super::parse::Ode;
use super::solve::Verification;
use crate::sym::Sym;

/// Points tried, and how many must be usable (finite, assumptions holding).
const TRIALS: u32 = 60;
const NEEDED: usize = 8;
/// Relative tolerance of the numerical check.
const RTOL: f64 = 1e-8;
/// The local check: steps from the conditions' point, their number each side, and the draws
/// of the other names.
const LOCAL_STEP: f64 = 0.05;
const LOCAL_STEPS: u32 = 40;
const LOCAL_DRAWS: u32 = 4;

/// How `solution` was verified to solve `ode` with `conditions`, and where, when it holds
/// only near the conditions' point (`t from -0.95 to 2`); `None` if it does not.
pub(super) fn verify(
    ode: &Ode,
    solution: &Sym,
    conditions: &[Condition],
    positive: &[Sym],
) -> Option<(Verification, Option<String>)> {
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
    // the extent of a solution with no free names, from the first condition's point
    let extent_from_conditions = || {
        let free = solution.names().iter().any(|n| *n != ode.var)
            || conds.iter().any(|(_, v)| !v.names().is_empty());
        let t0 = conditions.first()?.at.eval(&|_| None).ok()?;
        (!free)
            .then(|| extent(&ode.var, solution, &residual, &terms, t0))
            .flatten()
    };
    if residual.expand().is_zero()
        && conds
            .iter()
            .all(|(a, v)| Sym::difference(a.clone(), v.clone()).expand().is_zero())
    {
        return Some((Verification::Symbolic, extent_from_conditions()));
    }
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
        let vals = draw_values(&names, trial);
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
            return local(ode, &residual, &terms, &conds, conditions, &names, positive)
                .map(|(v, note)| (v, extent_from_conditions().or(note)));
        }
        if !conditions_hold(&conds, &base) {
            return None;
        }
        agree += 1;
    }
    if agree < NEEDED {
        return None;
    }
    Some((
        Verification::Numeric { points: agree },
        extent_from_conditions(),
    ))
}

/// How far from `t0` a solution with no free names holds, when not everywhere: up to the
/// nearest root of a squared base past which the residual no longer vanishes (`(a - b t)^2`
/// solves `h' = -k sqrt(h)` only while `a - b t ≥ 0`: a tank that empties), or up to the
/// nearest pole or end of an even root's domain, not reached (`1/(1 - t)` from `x' = x^2`,
/// `sqrt(2 t - 1)` from `x' = 1/x`). Roots are found by their sign changes, stepping
/// out geometrically to `t0 ± 10⁶`, then bisected.
fn extent(var: &str, solution: &Sym, residual: &Sym, terms: &[Sym], t0: f64) -> Option<String> {
    let at = |s: &Sym, tv: f64| s.eval(&|n| (n == var).then_some(tv)).unwrap_or(f64::NAN);
    let fails = |tv: f64| {
        let scale: f64 = terms.iter().map(|t| at(t, tv).abs()).sum();
        let r = at(residual, tv);
        scale.is_finite() && r.is_finite() && r.abs() > 1e-6 * scale
    };
    let mut squared = Vec::new();
    let mut poles = Vec::new();
    solution.any(&mut |n| {
        if let Sym::Pow(b, e) = n
            && !b.free_of(var)
            && let Some((p, q)) = e.as_num().and_then(crate::number::Number::as_rational)
        {
            if p < 0 || q % 2 == 0 {
                // a pole, or the end of an even root's domain
                poles.push((**b).clone());
            } else if q == 1 && p % 2 == 0 {
                squared.push((**b).clone());
            }
        }
        false
    });
    // the nearest sign change of `s` from t0 in direction `dir`
    let root = |s: &Sym, dir: f64| -> Option<f64> {
        let s0 = at(s, t0);
        if !s0.is_finite() || s0 == 0.0 {
            return None;
        }
        let (mut good, mut step) = (t0, LOCAL_STEP);
        while step < 1e6 {
            let tv = t0 + dir * step;
            let v = at(s, tv);
            if v.is_finite() && v * s0 <= 0.0 {
                let mut bad = tv;
                for _ in 0..60 {
                    let mid = 0.5 * (good + bad);
                    if at(s, mid) * s0 > 0.0 {
                        good = mid;
                    } else {
                        bad = mid;
                    }
                }
                return Some(0.5 * (good + bad));
            }
            good = tv;
            step *= 1.25;
        }
        None
    };
    // the nearest end each way, and whether it is a pole (not reached)
    let end = |dir: f64| -> Option<(f64, bool)> {
        let past = |r: f64| r + dir * LOCAL_STEP.min(0.1 * (r - t0).abs());
        let ends = poles
            .iter()
            .filter_map(|p| Some((root(p, dir)?, true)))
            .chain(
                squared
                    .iter()
                    .filter_map(|b| root(b, dir))
                    .filter(|&r| fails(past(r)))
                    .map(|r| (r, false)),
            );
        ends.min_by(|a, b| (a.0 - t0).abs().total_cmp(&(b.0 - t0).abs()))
    };
    // six significant digits
    let show = |v: f64| crate::short_number(format!("{v:.5e}").parse().unwrap_or(v));
    let sign = |pole: bool| if pole { "<" } else { "≤" };
    match (end(-1.0), end(1.0)) {
        (None, None) => None,
        (Some((a, p)), None) => Some(format!("it holds for {} {} {var}", show(a), sign(p))),
        (None, Some((b, p))) => Some(format!("it holds for {var} {} {}", sign(p), show(b))),
        (Some((a, p)), Some((b, q))) => Some(format!(
            "it holds for {} {} {var} {} {}",
            show(a),
            sign(p),
            sign(q),
            show(b)
        )),
    }
}

/// Whether each condition's value matches (relative 1e-8 of the terms of the solution there).
fn conditions_hold(conds: &[(Sym, Sym)], base: &dyn Fn(&str) -> Option<f64>) -> bool {
    conds.iter().all(|(a, v)| {
        let scale = match a {
            Sym::Add(ts) => ts
                .iter()
                .map(|t| t.eval(base).map_or(f64::NAN, f64::abs))
                .sum(),
            other => other.eval(base).map_or(f64::NAN, f64::abs),
        };
        match (a.eval(base), v.eval(base)) {
            (Ok(a), Ok(v)) => {
                (a - v).is_finite() && (a - v).abs() <= RTOL * scale.max(v.abs()).max(1e-300)
            }
            _ => false,
        }
    })
}

/// The check near the conditions' point `t0`, for a solution that holds only on an interval
/// (`(t + 1)^2` solves `x' = 2 sqrt(x)` for `t ≥ -1`): from `t0` outwards in steps of
/// `LOCAL_STEP`, each side up to the first point where the residual does not vanish; `t0`
/// itself and every condition's point must be inside, with at least `NEEDED` points, for each
/// of a few draws of the other names.
fn local(
    ode: &Ode,
    residual: &Sym,
    terms: &[Sym],
    conds: &[(Sym, Sym)],
    conditions: &[Condition],
    names: &[String],
    positive: &[Sym],
) -> Option<(Verification, Option<String>)> {
    let mut points = 0;
    let mut span = (f64::INFINITY, f64::NEG_INFINITY);
    for draw in 0..LOCAL_DRAWS {
        let vals = draw_values(names, draw);
        let base = |n: &str| vals.iter().find(|(m, _)| *m == n).map(|(_, v)| *v);
        if positive
            .iter()
            .any(|p| p.eval(&base).is_ok_and(|v| v.is_nan() || v <= 0.0))
            || !conditions_hold(conds, &base)
        {
            return None;
        }
        let at: Vec<f64> = conditions
            .iter()
            .map(|c| c.at.eval(&base).ok().filter(|v| v.is_finite()))
            .collect::<Option<_>>()?;
        let t0 = *at.first()?;
        let holds = |tv: f64| {
            let env = |n: &str| if n == ode.var { Some(tv) } else { base(n) };
            let scale: f64 = terms
                .iter()
                .map(|t| t.eval(&env).map_or(f64::NAN, f64::abs))
                .sum();
            residual.eval(&env).is_ok_and(|r| {
                r.is_finite() && scale.is_finite() && r.abs() <= RTOL * scale.max(1e-300)
            })
        };
        if !holds(t0) {
            return None;
        }
        let mut ends = [t0, t0];
        let mut count = 1;
        for (side, dir) in [(0, -1.0), (1, 1.0)] {
            for j in 1..=LOCAL_STEPS {
                let tv = t0 + dir * LOCAL_STEP * f64::from(j);
                if !holds(tv) {
                    break;
                }
                ends[side] = tv;
                count += 1;
            }
        }
        if count < NEEDED || at.iter().any(|&a| a < ends[0] || a > ends[1]) {
            return None;
        }
        points += count;
        span = (span.0.min(ends[0]), span.1.max(ends[1]));
    }
    let note = format!(
        "it holds near {} = {}, on [{}, {}] where checked",
        ode.var,
        conditions[0].at,
        crate::short_number((span.0 * 100.0).round() / 100.0),
        crate::short_number((span.1 * 100.0).round() / 100.0)
    );
    Some((Verification::Numeric { points }, Some(note)))
}

fn frac(v: f64) -> f64 {
    v - v.floor()
}

/// Values in [0.6, 1.9] for the free names, the `draw`-th of a fixed low-discrepancy
/// sequence (the same draws for every check).
fn draw_values(names: &[String], draw: u32) -> Vec<(&str, f64)> {
    names
        .iter()
        .enumerate()
        .map(|(i, n)| {
            let v = 0.6 + 1.3 * frac(0.37 * f64::from(draw) + 0.61 * i as f64 + 0.13);
            (n.as_str(), v)
        })
        .collect()
}
