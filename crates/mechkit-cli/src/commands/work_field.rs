//! `mechkit work --field F --path r(s)`: the work of a force field along a curve, the curl,
//! a potential when there is one, and the verdict on whether the field is conservative.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::energy::{ForceField, Path};
use mechkit::function::Function;
use mechkit::quad::Tolerance;
use serde_json::json;

use super::input::{interval, params, split_top_level, value};
use super::{Outcome, print};
use crate::args::WorkArgs;

pub fn field_work(args: &WorkArgs, field: &str) -> Result<Outcome> {
    let p = params(args.set.as_deref())?;
    let components = split_top_level(field, ',');
    let f = ForceField::parse(&components, &p).map_err(|e| anyhow!("--field: {e}"))?;
    let n = f.dim();
    let path = match (&args.path, &args.through) {
        (Some(curve), None) => {
            let Some((var, range)) = args.param.as_deref().and_then(|t| t.split_once('=')) else {
                bail!("--path needs the parameter and its range, e.g. --param s=0:1 (or s=0:2*pi)");
            };
            let var = var.trim();
            let (from, to) = interval(range.trim(), "--param", &p)?;
            let parts = split_top_level(curve, ',');
            let components = parts
                .iter()
                .map(|c| Function::parse(c, &[var], &p))
                .collect::<Result<Vec<_>, _>>()
                .map_err(|e| anyhow!("--path: {e}"))?;
            Path::Parametric {
                components,
                from,
                to,
            }
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
                    "--through: every point needs {n} coordinates like the field (points separated by `;`, coordinates by `,`), but one has {}",
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
    let w = f
        .work_along(
            &path,
            Tolerance {
                abs: 1e-12,
                rel: 1e-12,
            },
        )
        .map_err(|e| anyhow!("{e}"))?;
    let curl: Vec<String> = f.curl().iter().map(ToString::to_string).collect();
    let conservative = f.is_conservative();
    let potential = f.potential();
    if args.json {
        let j = json!({
            "field": f.formulas().iter().map(ToString::to_string).collect::<Vec<_>>(),
            "work": w.work,
            "error": w.error,
            "closed": w.closed,
            "length": w.length,
            "curl": curl,
            "conservative": conservative,
            "potential": potential.as_ref().map(ToString::to_string),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!(
            "W = ∫F·dr = {} ± {:.1e} along a path of length {}{}\n",
            w.work,
            w.error,
            w.length,
            if w.closed { " (closed)" } else { "" }
        );
        let _ = writeln!(out, "curl F = {}", curl.join(", "));
        let _ = match conservative {
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
        if let Some(u) = &potential {
            let _ = writeln!(out, "potential U = {u} (F = -∇U)");
        }
        print(&out)?;
    }
    Ok(Outcome::Success)
}
