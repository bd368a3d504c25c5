//! `mechkit work --field F --path r(s)`: the work of a force field along a curve, the curl,
//! a potential when there is one, and the verdict on whether the field is conservative
//! (`mechkit::energy::ForceField::work_report`).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::calculus::CalculusError;
use mechkit::energy::{FieldWork, ForceField, Path};
use mechkit::inputs::{Input, count};

use super::input::{interval, params, split_top_level, value};
use super::{Outcome, report};
use crate::args::WorkArgs;

/// The flag of an input of `work --field`.
fn flag(input: Input) -> &'static str {
    match input {
        Input::Path => "--path",
        Input::PathParameter => "--param",
        Input::Through => "--through",
        Input::Params => "--set",
        _ => "--field",
    }
}

/// A library error as the command line says it: formulas name the flag they came from.
fn check<T>(r: Result<T, CalculusError>, formula_flag: &str) -> Result<T> {
    r.map_err(|e| match e {
        CalculusError::Input(e) => anyhow!("{}: {}", flag(e.input), e.message),
        other => anyhow!("{formula_flag}: {other}"),
    })
}

pub fn field_work(args: &WorkArgs, field: &str) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let components = split_top_level(field, ',');
    let f = check(ForceField::parse(&components, &p), "--field")?;
    let n = f.dim();
    let path = match (&args.path, &args.through) {
        (Some(curve), None) => {
            let Some((var, range)) = args.param.as_deref().and_then(|t| t.split_once('=')) else {
                bail!("--path needs the parameter and its range, e.g. --param s=0:1 (or s=0:2*pi)");
            };
            let range = interval(range.trim(), "--param", &p)?;
            let parts = split_top_level(curve, ',');
            check(Path::parametric(&parts, var.trim(), range, &p), "--path")?
        }
        (None, Some(points)) => {
            let points = split_top_level(points, ';')
                .into_iter()
                .filter(|s| !s.is_empty())
                .map(|pt| {
                    split_top_level(pt, ',')
                        .into_iter()
                        .map(|c| value(c, "--through", &p))
                        .collect::<Result<Vec<f64>>>()
                })
                .collect::<Result<Vec<_>>>()?;
            if let Some(bad) = points.iter().find(|q| q.len() != n) {
                bail!(
                    "--through: every point needs {} like the field (points separated by `;`, coordinates by `,`), but one has {}",
                    count(n, "coordinate"),
                    bad.len()
                );
            }
            Path::Polyline(points)
        }
        (Some(_), Some(_)) => {
            bail!("give either --path (a curve r(s)) or --through (straight segments), not both")
        }
        (None, None) => bail!(
            "--field needs a path: --path \"cos(s), sin(s)\" --param s=0:2*pi, or --through \"0,0; 1,0; 1,1\""
        ),
    };
    let w = check(f.work_report(&path), "--field")?;
    report(args.report, &w, || text(&w))?;
    Ok(Outcome::Success)
}

fn text(w: &FieldWork) -> String {
    let mut out = format!(
        "W = ∫F·dr = {} ± {:.1e} along a path of length {}{}\n",
        mechkit::expr::short_number(w.work),
        w.error,
        mechkit::expr::short_number(w.length),
        if w.closed { " (closed)" } else { "" }
    );
    let curl: Vec<String> = w.curl.iter().map(ToString::to_string).collect();
    let _ = writeln!(out, "curl F = {}", curl.join(", "));
    let _ = match w.conservative {
        Some(true) => writeln!(
            out,
            "the curl is zero: F is conservative, the work depends only on the end points{}",
            if w.closed {
                " (and is zero around this loop)"
            } else {
                ""
            }
        ),
        Some(false) => writeln!(
            out,
            "the curl is not zero: F is not conservative, the work depends on the path"
        ),
        None => writeln!(out, "whether the curl vanishes could not be decided"),
    };
    if let Some(u) = &w.potential {
        let _ = writeln!(out, "potential U = {u} (F = -∇U)");
    }
    out
}
