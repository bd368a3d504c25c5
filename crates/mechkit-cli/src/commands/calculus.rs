//! `mechkit diff | integrate | solve | units`: the one-question calculus commands.

use std::fmt::Write as _;

use anyhow::{Result, bail};
use mechkit::calculus::{self, CalculusError, Params};
use mechkit::expr::sym::Solutions;
use mechkit::quad::Rule;
use serde_json::json;

use super::input::{increasing_interval, params, value};
use super::{Outcome, print};
use crate::args::{DiffArgs, IntegrateArgs, SolveArgs, UnitsArgs};

/// `write!` into a String (which cannot fail).
macro_rules! wr {
    ($dst:expr, $($arg:tt)*) => {{
        let _ = write!($dst, $($arg)*);
    }};
}

fn show(p: &Params) -> String {
    p.iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn check_expr<T>(r: Result<T, CalculusError>, flag: &str) -> Result<T> {
    r.map_err(|e| match e {
        CalculusError::Formula(e) => anyhow::anyhow!("in the {flag}: {e}"),
        other => anyhow::anyhow!("{other}"),
    })
}

pub fn diff(args: &DiffArgs) -> Result<Outcome> {
    let d = check_expr(calculus::derivative(&args.expr, &args.var), "formula")?;
    let p = params(args.set.as_deref())?;
    let check = match &args.at {
        Some(at) => {
            let at = value(at, "--at", &p)?;
            let h = args
                .step
                .as_deref()
                .map_or(Ok(0.1), |h| value(h, "--step", &p))?;
            if h.is_nan() || h <= 0.0 {
                bail!("--step must be positive");
            }
            Some(check_expr(
                calculus::derivative_at(&args.expr, &args.var, at, &p, h),
                "formula",
            )?)
        }
        None => None,
    };
    let x = &args.var;
    if args.json {
        let j = json!({
            "input": d.input.to_string(),
            "var": x,
            "derivative": d.result.to_string(),
            "at": check.map(|c| json!({
                "x": c.at, "symbolic": c.symbolic, "numeric": c.numeric,
                "numeric_error": c.numeric_error, "agree": c.agree,
            })),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!("d/d{x} {} = {}\n", d.input, d.result);
        if let Some(c) = check {
            wr!(
                out,
                "at {x} = {}:\n  symbolic  {}\n  numeric   {} ± {:.1e} (central differences, Richardson extrapolation)\n  {}\n",
                c.at,
                c.symbolic,
                c.numeric,
                c.numeric_error,
                if c.agree {
                    "the two agree"
                } else {
                    "they DISAGREE"
                }
            );
        }
        print(&out)?;
    }
    Ok(if check.is_some_and(|c| !c.agree) {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    })
}

pub fn integrate(args: &IntegrateArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let limits = match (&args.from, &args.to) {
        (Some(a), Some(b)) => Some((value(a, "--from", &p)?, value(b, "--to", &p)?)),
        (None, None) => None,
        _ => bail!("give both --from and --to for a definite integral"),
    };
    let i = check_expr(
        calculus::integral(&args.expr, &args.var, limits, &p),
        "integrand",
    )?;
    let x = &args.var;
    let rules = match (&args.method, limits) {
        (Some(names), Some(lim)) => {
            let rules = rule_list(names)?;
            if let Some(bad) = args.n.iter().find(|&&n| n == 0) {
                bail!("--n {bad}: the number of intervals must be at least 1");
            }
            Some(check_expr(
                calculus::rule_estimates(&args.expr, x, lim, &p, &rules, &args.n),
                "integrand",
            )?)
        }
        _ => None,
    };
    if args.json {
        let definite = i.definite.as_ref().map(|d| {
            json!({
                "from": d.from, "to": d.to,
                "closed_form": d.closed_form,
                "quadrature": d.quadrature.as_ref().ok().map(|q| json!({"value": q.value, "error": q.error, "evaluations": q.evaluations})),
                "quadrature_error": d.quadrature.as_ref().err(),
                "agree": d.agree,
            })
        });
        let j = json!({
            "input": i.input.to_string(),
            "var": x,
            "antiderivative": i.antiderivative.as_ref().map(ToString::to_string),
            "assumptions": i.assumptions,
            "parameters": p.iter().map(|(k, v)| (k.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
            "definite": definite,
            "reference": rules.as_ref().map(|r| r.0),
            "rules": rules.as_ref().map(|(_, rows)| rows.iter().map(|r| json!({
                "rule": r.rule.name(), "n": r.n, "value": r.value, "error": r.error,
                "observed_order": r.observed_order,
            })).collect::<Vec<_>>()),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = match &i.antiderivative {
            Some(f) => {
                let mut s = format!("∫ {} d{x} = {f} + C", i.input);
                if !i.assumptions.is_empty() {
                    wr!(s, "   (assuming {})", i.assumptions.join(" and "));
                }
                s + "\n"
            }
            None => format!(
                "∫ {} d{x}: no closed form found by the rule table (the definite value needs quadrature)\n",
                i.input
            ),
        };
        if let Some(d) = &i.definite {
            let given = if p.is_empty() {
                String::new()
            } else {
                format!(" with {}", show(&p))
            };
            wr!(out, "from {} to {}{given}:\n", d.from, d.to);
            if let Some(c) = d.closed_form {
                wr!(out, "  closed form  {c}\n");
            }
            match &d.quadrature {
                Ok(q) => wr!(
                    out,
                    "  quadrature   {} ± {:.1e} ({} evaluations)\n",
                    q.value,
                    q.error,
                    q.evaluations
                ),
                Err(e) => wr!(out, "  quadrature   failed: {e}\n"),
            }
            match d.agree {
                Some(true) => out.push_str("  the two agree\n"),
                Some(false) => out.push_str("  they DISAGREE: the antiderivative may jump inside the interval (ln|u| across 0); trust the quadrature\n"),
                None => {}
            }
        }
        if let Some((reference, rows)) = &rules {
            wr!(
                out,
                "fixed rules against the exact value {reference} (error = estimate - exact):\n"
            );
            for r in rows {
                wr!(
                    out,
                    "  {:<18} n = {:<6} {:<22} error {:+.3e}",
                    r.rule.name(),
                    r.n,
                    r.value,
                    r.error
                );
                if let Some(o) = r.observed_order {
                    wr!(out, "   order {o:.2}");
                }
                out.push('\n');
            }
        }
        print(&out)?;
    }
    let nothing =
        i.antiderivative.is_none() && i.definite.as_ref().is_none_or(|d| d.quadrature.is_err());
    Ok(if nothing {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    })
}

fn rule_list(names: &[String]) -> Result<Vec<Rule>> {
    let mut rules = Vec::new();
    for name in names.iter().map(|n| n.trim()) {
        if name == "all" {
            rules.extend(Rule::BASIC);
            rules.push(Rule::GaussLegendre(Rule::DEFAULT_GAUSS_POINTS));
            continue;
        }
        match Rule::parse(name) {
            Some(r) => rules.push(r),
            None => bail!(
                "--method: unknown rule `{name}`; use left, right, midpoint, trapezoid, simpson, gauss-legendre-N (e.g. gauss-legendre-5) or all"
            ),
        }
    }
    Ok(rules)
}

pub fn solve(args: &SolveArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let unknowns: Vec<&str> = args
        .unknown
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .collect();
    if unknowns.len() > 1 || args.equation.contains(';') {
        let sol = check_expr(
            calculus::solve_system(&args.equation, &unknowns),
            "equations",
        )?;
        if args.json {
            let m: serde_json::Map<_, _> = sol
                .iter()
                .map(|(k, v)| (k.clone(), json!(v.to_string())))
                .collect();
            print(&format!("{:#}\n", json!({ "solution": m })))?;
        } else {
            let mut text = String::new();
            for (k, v) in &sol {
                wr!(text, "{k} = {v}\n");
            }
            print(&text)?;
        }
        return Ok(Outcome::Success);
    }
    let x = unknowns.first().copied().unwrap_or("x");
    let range = args
        .interval
        .as_deref()
        .map(|t| increasing_interval(t, "--in", &p))
        .transpose()?;
    let s = check_expr(calculus::solve(&args.equation, x, range, &p), "equation")?;
    let symbolic: Option<Vec<String>> = match &s.symbolic {
        Some(Solutions::Roots(r)) => Some(r.iter().map(ToString::to_string).collect()),
        Some(_) | None => None,
    };
    if args.json {
        let j = json!({
            "equation": format!("{} = 0", s.equation),
            "unknown": x,
            "symbolic": symbolic,
            "no_real_root": matches!(s.symbolic, Some(Solutions::NoRealRoot)),
            "every_value": matches!(s.symbolic, Some(Solutions::Every)),
            "assumptions": s.assumptions,
            "numeric": s.numeric,
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = String::new();
        match &s.symbolic {
            Some(Solutions::Roots(r)) => {
                for root in r {
                    wr!(out, "{x} = {root}\n");
                }
                if !s.assumptions.is_empty() {
                    wr!(out, "  (assuming {})\n", s.assumptions.join(" and "));
                }
            }
            Some(Solutions::NoRealRoot) => {
                wr!(out, "no real {x} solves {} = 0\n", s.equation);
            }
            Some(Solutions::Every) => {
                wr!(out, "every {x} solves it ({} = 0)\n", s.equation);
            }
            None => {
                let (a, b) = range.unwrap_or_default();
                if s.numeric.is_empty() {
                    wr!(
                        out,
                        "no root of {} = 0 found for {x} in [{a}, {b}]\n",
                        s.equation
                    );
                } else {
                    wr!(out, "roots of {} = 0 for {x} in [{a}, {b}]:\n", s.equation);
                }
            }
        }
        // numeric values of symbolic roots that are not plain numbers, and roots found on the
        // interval
        let plain = |t: &String| t.parse::<f64>().is_ok();
        let show_numeric = match &symbolic {
            None => true,
            Some(r) => !s.numeric.is_empty() && !r.iter().all(plain),
        };
        if show_numeric && !s.numeric.is_empty() {
            if s.symbolic.is_some() {
                let given = if p.is_empty() {
                    String::new()
                } else {
                    format!(" with {}", show(&p))
                };
                wr!(out, "numerically{given}:\n");
            }
            for v in &s.numeric {
                wr!(out, "  {x} = {v}\n");
            }
        }
        print(&out)?;
    }
    let none =
        s.numeric.is_empty() && !matches!(s.symbolic, Some(Solutions::Roots(_) | Solutions::Every));
    Ok(if none {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    })
}

pub fn units(args: &UnitsArgs) -> Result<Outcome> {
    let c = check_expr(
        calculus::convert(&args.quantity, args.to.as_deref()),
        "quantity",
    )?;
    let unit = c
        .dimension
        .derived_symbol()
        .map_or_else(|| c.dimension.to_string(), str::to_string);
    let name = c.dimension.quantity_name().unwrap_or("");
    if args.json {
        let j = json!({
            "input": args.quantity,
            "si": c.si,
            "si_unit": unit,
            "dimension": c.dimension.to_string(),
            "quantity": name,
            "converted": c.converted.as_ref().map(|(v, u)| json!({"value": v, "unit": u})),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!("{} = {} {unit}", args.quantity, c.si);
        if !name.is_empty() {
            wr!(out, "   [{name}]");
        }
        out.push('\n');
        if let Some((v, u)) = &c.converted {
            wr!(out, "{} = {v} {u}\n", args.quantity);
        }
        print(&out)?;
    }
    Ok(Outcome::Success)
}
