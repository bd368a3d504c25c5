//! `mechkit diff | integrate | solve | units`: the one-question calculus commands. Each reads
//! its arguments, asks `mechkit::calculus`, and prints the answer (its JSON is the library
//! value's).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::calculus::{
    self, CalculusError, Conversion, Differentiation, Integration, Solution, Solved, SystemSolution,
};
use mechkit::expr::sym::Solutions;
use mechkit::inputs::Input;
use mechkit::quad::Rule;

use super::input::{increasing_interval, params, value};
use super::{Outcome, report};
use crate::args::{DiffArgs, IntegrateArgs, SolveArgs, UnitsArgs};

/// `write!` into a String (which cannot fail).
macro_rules! wr {
    ($dst:expr, $($arg:tt)*) => {{
        let _ = write!($dst, $($arg)*);
    }};
}

fn show(p: &[(String, f64)]) -> String {
    p.iter()
        .map(|(k, v)| format!("{k} = {}", mechkit::expr::short_number(*v)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The flag of an input of the calculus commands.
fn flag(input: Input) -> &'static str {
    match input {
        Input::Step => "--step",
        Input::Point => "--at",
        Input::Intervals => "--n",
        Input::Limits => "--from/--to",
        Input::SearchInterval => "--in",
        Input::Unknowns => "--for",
        Input::TargetUnit => "--to",
        Input::Params => "--set",
        Input::Variable => "--var",
        _ => "the formula",
    }
}

/// A library error as the command line says it: a formula's error says which argument held
/// the formula, an input's names its flag.
fn check<T>(r: Result<T, CalculusError>, what: &str) -> Result<T> {
    r.map_err(|e| match e {
        CalculusError::Formula(e) => anyhow!("in the {what}: {e}"),
        CalculusError::Input(e) => anyhow!("{}: {}", flag(e.input), e.message),
        // an answer beyond double precision: exit 1 (the finiteness rule), not 2
        CalculusError::NotFinite {
            ref what, value, ..
        } => anyhow::Error::new(mechkit::finite::NonFinite {
            quantity: what.clone(),
            value,
        })
        .context(e.to_string()),
        other => anyhow!("{other}"),
    })
}

pub fn diff(args: &DiffArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let at = match &args.at {
        Some(at) => {
            // the point and the step are values of the variable: one dimension, which the
            // formula must fit with the units of the `--set` values
            if let Some(step) = &args.step {
                mechkit::values::same_dimension(("--at", at), ("--step", step))?;
            }
            let var_dim = mechkit::values::dimension(at)
                .or_else(|| args.step.as_deref().and_then(mechkit::values::dimension));
            mechkit::values::check_formula_units(
                &args.expr,
                "the formula",
                (&args.var, var_dim, Some("--at")),
                &mechkit::values::param_dimensions(args.set.as_deref().unwrap_or_default()),
                &p,
                None,
            )?;
            let h = args
                .step
                .as_deref()
                .map_or(Ok(0.1), |h| value(h, "--step", &p))?;
            Some((value(at, "--at", &p)?, h))
        }
        None => None,
    };
    let d = check(
        calculus::differentiate(&args.expr, &args.var, at, &p),
        "formula",
    )?;
    report(args.report, &d, || diff_text(&d))?;
    Ok(if d.agrees() {
        Outcome::Success
    } else {
        Outcome::ComputationFailed
    })
}

fn diff_text(d: &Differentiation) -> String {
    let x = &d.var;
    let mut out = format!("d/d{x} {} = {}\n", d.input, d.derivative);
    let short = mechkit::expr::short_number;
    // where the formula has no derivative: a jump (the values on each side), a corner (the
    // slopes on each side), a vertical tangent or a cusp (slopes without bound), or a point
    // where the derivative's formula gives no finite value
    let broken = d.at.and_then(|c| {
        c.jump
            .map(|[l, r]| format!("jumps (from {} to {})", short(l), short(r)))
            .or_else(|| {
                c.kink.map(|[l, r]| {
                    format!(
                        "has a corner (slope {} from the left, {} from the right)",
                        short(l),
                        short(r)
                    )
                })
            })
            .or_else(|| {
                c.vertical.map(|[l, r]| {
                    let shape = if l.signum() == r.signum() {
                        "a vertical tangent"
                    } else {
                        "a cusp"
                    };
                    format!(
                        "has {shape} (its slopes grow without bound on both sides: {l:.2e} from the left and {r:.2e} from the right over the shortest steps)"
                    )
                })
            })
            .map(|what| format!("{} {what}: it has no derivative there", d.input))
            .or_else(|| {
                let numeric = c.numeric.filter(|_| c.estimate_only)?;
                Some(format!(
                    "the formula d/d{x} {} = {} has no value there (a removable singularity: 0/0 or the like), but the numerical derivative is sure: {} ± {:.1e} (central differences, Richardson extrapolation), the formula's limit",
                    d.input,
                    d.derivative,
                    short(numeric),
                    c.numeric_error.unwrap_or(0.0)
                ))
            })
            .or_else(|| {
                c.symbolic.is_none().then(|| {
                    format!(
                        "d/d{x} {} is not a finite number (the point is at the edge of the formula's domain or at a singularity): there is no finite derivative there",
                        d.input
                    )
                })
            })
            .map(|what| (c.at, what))
    });
    if let Some((at, what)) = broken {
        wr!(out, "at {x} = {}: {what}\n", short(at));
    } else if let Some(c) = d.at {
        let opt = |v: Option<f64>| v.map_or_else(|| "-".to_string(), short);
        wr!(
            out,
            "at {x} = {}:\n  symbolic  {}\n  numeric   {} ± {} (central differences, Richardson extrapolation)\n  {}\n",
            short(c.at),
            opt(c.symbolic),
            opt(c.numeric),
            c.numeric_error
                .map_or_else(|| "-".to_string(), |e| format!("{e:.1e}")),
            if c.agree {
                "the two agree"
            } else {
                "they DISAGREE"
            }
        );
    }
    out
}

pub fn integrate(args: &IntegrateArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let limits = match (&args.from, &args.to) {
        (Some(a), Some(b)) => {
            mechkit::values::same_dimension(("--from", a), ("--to", b))?;
            Some((value(a, "--from", &p)?, value(b, "--to", &p)?))
        }
        (None, None) => None,
        _ => bail!("give both --from and --to for a definite integral"),
    };
    let rules =
        match &args.method {
            Some(names) => {
                let rules = Rule::parse_list(names).map_err(|e| anyhow!("--method: {e}"))?;
                if let Some(bad) = args.n.iter().find(|&&n| n == 0) {
                    bail!("--n {bad}: the number of intervals must be at least 1");
                }
                // more evaluations than any rule makes: refused before anything is computed
                for &n in &args.n {
                    if let Some(Err(e)) = rules.iter().map(|r| r.check_intervals(n)).find(|c| {
                        matches!(c, Err(mechkit::quad::RuleError::TooManyEvaluations { .. }))
                    }) {
                        bail!("--n {n}: {e}");
                    }
                }
                rules
            }
            None => Vec::new(),
        };
    let i = check(
        calculus::integration(&args.expr, &args.var, limits, &p, &rules, &args.n),
        "integrand",
    )?;
    report(args.report, &i, || integrate_text(&i))?;
    Ok(if i.found_nothing() {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    })
}

fn integrate_text(i: &Integration) -> String {
    let x = &i.var;
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
        let given = if i.parameters.is_empty() {
            String::new()
        } else {
            format!(" with {}", show(&i.parameters))
        };
        wr!(
            out,
            "from {} to {}{given}:\n",
            mechkit::expr::short_number(d.from),
            mechkit::expr::short_number(d.to)
        );
        if let Some(c) = d.closed_form {
            wr!(out, "  closed form  {}\n", mechkit::expr::short_number(c));
        }
        match &d.quadrature {
            Ok(q) => wr!(
                out,
                "  quadrature   {} ± {:.1e} ({} evaluations)\n",
                mechkit::expr::short_number(q.value),
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
    if let (Some(reference), Some(rows)) = (i.reference, &i.rules) {
        wr!(
            out,
            "fixed rules against the exact value {} (error = estimate - exact):\n",
            mechkit::expr::short_number(reference)
        );
        for r in rows {
            wr!(
                out,
                "  {:<18} n = {:<6} {:<22} error {:+.3e}",
                r.rule.name(),
                r.n,
                mechkit::expr::short_number(r.value),
                r.error
            );
            if let Some(o) = r.observed_order {
                wr!(out, "   order {o:.2}");
            }
            out.push('\n');
        }
    }
    out
}

pub fn solve(args: &SolveArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let unknowns: Vec<&str> = args
        .unknown
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .collect();
    let range = args
        .interval
        .as_deref()
        .map(|t| increasing_interval(t, "--in", &p))
        .transpose()?;
    let what = if unknowns.len() > 1 || args.equation.contains(';') {
        "equations"
    } else {
        "equation"
    };
    let s = check(
        calculus::solve_equations(&args.equation, &unknowns, range, &p),
        what,
    )?;
    report(args.report, &s, || match &s {
        Solved::System(sys) => system_text(sys),
        Solved::Equation(one) => equation_text(one),
        _ => String::new(),
    })?;
    Ok(if s.failed() {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    })
}

fn system_text(s: &SystemSolution) -> String {
    let mut text = String::new();
    for (k, v) in &s.solution {
        wr!(text, "{k} = {v}\n");
    }
    if s.parameters.is_empty() {
        return text;
    }
    let given = show(&s.parameters);
    match &s.numeric {
        _ if s.singular_with_values() => wr!(
            text,
            "with {given} the system has no unique solution (its determinant is zero)\n"
        ),
        Some(values) => {
            // solutions that are plain numbers already say everything
            if !s.solution.iter().all(|(_, v)| plain(v)) {
                wr!(text, "numerically with {given}:\n");
                for (k, v) in values {
                    wr!(text, "  {k} = {}\n", mechkit::expr::short_number(*v));
                }
            }
        }
        None => wr!(
            text,
            "to evaluate it, give values for {} too\n",
            s.missing().join(", ")
        ),
    }
    text
}

/// Whether a solution is a plain decimal number (its numeric value would repeat it).
fn plain(v: &mechkit::expr::Sym) -> bool {
    v.to_string().parse::<f64>().is_ok()
}

fn equation_text(s: &Solution) -> String {
    let x = &s.unknown;
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
        Some(Solutions::NoRealRoot) if s.values_put_in => {
            wr!(
                out,
                "with {}, no {x} solves {} = 0\n",
                show(&s.parameters),
                s.equation
            );
        }
        Some(Solutions::NoRealRoot) => {
            wr!(out, "no real {x} solves {} = 0\n", s.equation);
        }
        Some(Solutions::Every) if s.values_put_in => {
            wr!(
                out,
                "with {}, every {x} solves it ({} = 0)\n",
                show(&s.parameters),
                s.equation
            );
        }
        Some(Solutions::Every) => {
            wr!(out, "every {x} solves it ({} = 0)\n", s.equation);
        }
        None if s.root_bound.is_some() => {
            let (a, b) = s.interval.unwrap_or_default();
            let (a, b) = (
                mechkit::expr::short_number(a),
                mechkit::expr::short_number(b),
            );
            wr!(
                out,
                "real roots of {} = 0 for {x} (all of them: every real root lies in [{a}, {b}], \
                 Cauchy's bound):\n",
                s.equation
            );
        }
        _ => {
            let (a, b) = s.interval.unwrap_or_default();
            let (a, b) = (
                mechkit::expr::short_number(a),
                mechkit::expr::short_number(b),
            );
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
    let show_numeric = match s.roots() {
        None => true,
        Some(r) => !s.numeric.is_empty() && !r.iter().all(plain),
    };
    if show_numeric && !s.numeric.is_empty() {
        if s.symbolic.is_some() {
            let given = if s.parameters.is_empty() {
                String::new()
            } else {
                format!(" with {}", show(&s.parameters))
            };
            wr!(out, "numerically{given}:\n");
        }
        for v in &s.numeric {
            wr!(out, "  {x} = {}\n", mechkit::expr::short_number(*v));
        }
    }
    out
}

pub fn units(args: &UnitsArgs) -> Result<Outcome> {
    let c = check(
        calculus::convert(&args.quantity, args.to.as_deref()),
        "quantity",
    )?;
    report(args.report, &c, || units_text(&c))?;
    Ok(Outcome::Success)
}

/// `60 km/h = 16.67 m/s   [velocity]`, then the value in the unit asked unless that is the SI
/// unit itself (the line would repeat).
fn units_text(c: &Conversion) -> String {
    let mut out = format!(
        "{} = {} {}",
        c.input,
        mechkit::expr::short_number(c.si),
        c.si_unit
    );
    if !c.quantity.is_empty() {
        wr!(out, "   [{}]", c.quantity);
    }
    out.push('\n');
    if let Some(to) = c.converted.as_ref().filter(|_| !c.converted_to_si()) {
        wr!(
            out,
            "{} = {} {}\n",
            c.input,
            mechkit::expr::short_number(to.value),
            to.unit
        );
    }
    out
}
