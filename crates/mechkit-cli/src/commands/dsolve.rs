//! `mechkit dsolve`: an ordinary differential equation in closed form. Reads its arguments,
//! asks `mechkit::calculus::dsolve`, and prints the answer (its JSON is the library value's).

use std::fmt::Write as _;

use anyhow::{Result, anyhow};
use mechkit::calculus::{self, CalculusError, OdeSolved};
use mechkit::expr::sym::dsolve::Verification;
use mechkit::inputs::Input;

use super::input::params;
use super::{Outcome, report};
use crate::args::DsolveArgs;

pub fn dsolve(args: &DsolveArgs) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let s = match calculus::dsolve(
        &args.equation,
        &args.func,
        &args.var,
        args.ic.as_deref(),
        &p,
    ) {
        Ok(s) => s,
        // a well-posed equation without a closed form: the computation failed (exit 1)
        Err(CalculusError::NoClosedForm(m)) => {
            eprintln!("error: in the equation: {m}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(CalculusError::Formula(e)) => return Err(anyhow!("in the equation: {e}")),
        Err(CalculusError::Input(e)) => {
            let flag = match e.input {
                Input::Function => "--func",
                Input::Variable => "--var",
                Input::InitialConditions => "--ic",
                Input::Params => "--set",
                _ => "the equation",
            };
            return Err(anyhow!("{flag}: {}", e.message));
        }
        Err(other) => return Err(anyhow!("{other}")),
    };
    report(args.report, &s, || text(&s))?;
    Ok(Outcome::Success)
}

fn text(s: &OdeSolved) -> String {
    let mut out = format!("{}({}) = {}\n", s.func, s.var, s.solution);
    let _ = writeln!(out, "  equation      {}", s.equation);
    let _ = writeln!(out, "  method        {}", s.method);
    if !s.ic.is_empty() {
        let fixed: Vec<String> = s
            .determined
            .iter()
            .map(|(k, v)| format!("{k} = {v}"))
            .collect();
        let _ = writeln!(
            out,
            "  conditions    {}   ({})",
            s.ic.join(", "),
            fixed.join(", ")
        );
    }
    if !s.constants.is_empty() {
        let _ = writeln!(out, "  constants     {} (free)", s.constants.join(", "));
    }
    if !s.assumptions.is_empty() {
        let _ = writeln!(out, "  assuming      {}", s.assumptions.join(" and "));
    }
    let how = match s.verification {
        Verification::Symbolic => "the residual simplifies to 0".to_string(),
        Verification::Numeric { points } => {
            format!("the residual vanishes at {points} points (relative 1e-8)")
        }
    };
    let _ = writeln!(out, "  verified      by substitution: {how}");
    out
}
