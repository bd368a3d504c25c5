//! `[stop]`: `t_max`, `max_steps` and the condition `when`, compiled to an event function.

use mechkit_expr::interval::{Interval, Jet};
use mechkit_expr::units::Dimension;
use mechkit_expr::{BinOp, Expr, Formula};

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::values::{ValueEnv, formula_error, scalar};
use crate::Real;
use crate::particles::{NameContext, StateExpr};
use crate::simulate::Condition;

const STOP_KEYS: &[&str] = &["when", "check", "t_max", "max_steps"];

type Stop = (Option<Condition>, Option<Real>, Option<u64>);

pub(crate) fn read_stop(
    root: &Table<'_, '_>,
    env: ValueEnv<'_>,
    names: &NameContext<'_>,
) -> Result<Stop, ScenarioError> {
    let Some(t) = root.table("stop")? else {
        return Ok((None, None, None));
    };
    t.check_keys(STOP_KEYS)?;
    let t_max = scalar(&t, "t_max", Dimension::TIME, env)?;
    if let Some(tm) = t_max
        && !(tm > 0.0 && tm.is_finite())
    {
        return Err(t.src.error(
            ErrorKind::Invalid,
            format!(
                "`t_max` must be positive, not {} s",
                crate::error::short(tm)
            ),
            t.get("t_max").map_or(t.span.clone(), toml::Spanned::span),
        ));
    }
    let max_steps = match t.count("max_steps")? {
        Some((0, span)) => {
            return Err(t
                .src
                .error(ErrorKind::Invalid, "`max_steps` must be at least 1", span)
                .with_hint("`max_steps = 50000` ends the run after 50,000 steps"));
        }
        other => other.map(|(n, _)| n),
    };
    let step_end = read_check(&t)?;
    let condition = match t.string("when")? {
        None => {
            if t.get("check").is_some() {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        "`check` says how the condition `when` is tested, and there is no `when`",
                        t.key_span("check"),
                    )
                    .with_hint("add `when = \"x > 3\"`, or remove `check`"));
            }
            None
        }
        Some((text, span)) => {
            let c = condition(&t, text, &span, names, "a stop condition")?;
            Some(if step_end { c.at_step_ends() } else { c })
        }
    };
    Ok((condition, t_max, max_steps))
}

/// The step bound of the run the file asks for ([`crate::simulate::check_step_bound`]),
/// checked when it is read so that `mechkit check` reports it: a count of fixed steps or a
/// step too small for the time is located at `dt`, a `max_steps` too large at `max_steps`, an
/// output `interval` that asks for more output times than steps are allowed at `interval`.
pub(crate) fn check_steps(
    root: &Table<'_, '_>,
    stepping: &crate::simulate::Stepping,
    t0: Real,
    t_max: Option<Real>,
    max_steps: Option<u64>,
    interval: Option<Real>,
) -> Result<(), ScenarioError> {
    use crate::simulate::StepBoundError;
    let Err(e) = crate::simulate::check_step_bound(stepping, t0, t_max, max_steps).and_then(|_| {
        match (interval, t_max) {
            (Some(i), Some(tm)) => crate::simulate::check_output_bound(t0, tm, i).map(|_| 0),
            _ => Ok(0),
        }
    }) else {
        return Ok(());
    };
    let (table, key) = match e {
        StepBoundError::MaxStepsTooLarge(_) => ("stop", "max_steps"),
        StepBoundError::TooManyOutputs { .. } => ("output", "interval"),
        _ => ("integrator", "dt"),
    };
    let span = match root.table(table)? {
        Some(t) => t.get(key).map_or(t.span.clone(), toml::Spanned::span),
        None => root.span.clone(),
    };
    Err(root
        .src
        .error(ErrorKind::Invalid, e.to_string(), span)
        .with_hint(e.hint()))
}

/// `check`: `"located"` (the default: the crossing is found inside the step) or `"step-end"`
/// (tested only at step ends, as a textbook loop does); returns whether it is `"step-end"`.
pub(crate) fn read_check(t: &Table<'_, '_>) -> Result<bool, ScenarioError> {
    match t.string("check")? {
        None | Some(("located", _)) => Ok(false),
        Some(("step-end", _)) => Ok(true),
        Some((other, span)) => Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!("unknown check `{other}`"),
                span,
            )
            .with_hint(
                "`located` (the default: the crossing is found inside the step) or `step-end` (tested only where a step ends, like a textbook `while` loop; may overshoot by a step)",
            )),
    }
}

fn compile_state(
    t: &Table<'_, '_>,
    f: &Formula,
    span: &std::ops::Range<usize>,
    names: &NameContext<'_>,
) -> Result<StateExpr, ScenarioError> {
    names
        .compile(f)
        .map_err(|e| formula_error(&t.src, span, &e))
}

/// A stop condition: a comparison becomes a continuous event function (`a < b` has
/// `g = b - a`), anything else a boolean one located by bisection.
pub(crate) fn condition(
    t: &Table<'_, '_>,
    text: &str,
    span: &std::ops::Range<usize>,
    names: &NameContext<'_>,
    what: &str,
) -> Result<Condition, ScenarioError> {
    let f = Formula::parse(text).map_err(|e| formula_error(&t.src, span, &e))?;
    let whole = compile_state(t, &f, span, names)?;
    if let Expr::Binary(op, a, b) = f.expr() {
        if *op == BinOp::Eq || *op == BinOp::Ne {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "{what} cannot use `{}`: an exact equality is never hit between steps",
                        op.symbol()
                    ),
                    span.clone(),
                )
                .with_hint("write the crossing as an inequality, e.g. `x < 0` or `vy < 0`"));
        }
        if op.is_comparison() {
            let lhs = compile_state(
                t,
                &Formula::parse(&a.to_string()).expect("printed expressions re-parse"),
                span,
                names,
            )?;
            let rhs = compile_state(
                t,
                &Formula::parse(&b.to_string()).expect("printed expressions re-parse"),
                span,
                names,
            )?;
            let needs = !(lhs.is_kinematic() && rhs.is_kinematic());
            let (first, second) = if matches!(op, BinOp::Lt | BinOp::Le) {
                (rhs, lhs)
            } else {
                (lhs, rhs)
            };
            let inclusive = matches!(op, BinOp::Le | BinOp::Ge);
            let (first_j, second_j) = (first.clone(), second.clone());
            return Ok(Condition::from_fn(text, inclusive, needs, move |s, sys| {
                let (dim, mass) = (sys.dim(), sys.masses());
                first.eval_sample(s, dim, mass, None) - second.eval_sample(s, dim, mass, None)
            })
            .with_enclosure(move |j, _| {
                Some(first_j.enclose(j, None)? - second_j.enclose(j, None)?)
            }));
        }
    }
    let needs = !whole.is_kinematic();
    let whole_j = whole.clone();
    Ok(Condition::from_fn(text, true, needs, move |s, sys| {
        if whole.eval_sample(s, sys.dim(), sys.masses(), None) == 0.0 {
            -1.0
        } else {
            1.0
        }
    })
    .with_enclosure(move |j, _| Some(truth_jet(whole_j.enclose(j, None)?))))
}

/// The enclosure of a boolean condition's event function (`-1` where the formula is 0, `1`
/// elsewhere) from the enclosure of the formula: constant where the formula's truth is
/// decided, a possible jump (any slope) where it is not.
fn truth_jet(formula: Jet) -> Jet {
    let v = formula.v;
    if v.lo() == 0.0 && v.hi() == 0.0 {
        Jet::constant(-1.0)
    } else if !v.contains_zero() {
        Jet::constant(1.0)
    } else {
        Jet::step(Interval::new(-1.0, 1.0))
    }
}
