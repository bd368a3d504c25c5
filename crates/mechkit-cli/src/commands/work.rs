//! `mechkit work`: the work (or impulse) from sampled force data, or of a force field along a
//! path.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::data::{ColumnRef, Order, Table};
use mechkit::energy::SampledIntegral;
use mechkit::expr::units::Dimension;
use mechkit::figure::{PlotData, Series};
use mechkit::quad::SampleRule;
use mechkit::scenario::{push_number, write_atomic};
use serde_json::json;

use super::input::quantity;
use super::work_field::field_work;
use super::{Outcome, print};
use crate::args::{ImpulseArgs, WorkArgs};
use crate::plot::render;

pub fn work(args: &WorkArgs) -> Result<Outcome> {
    match (&args.field, &args.file) {
        (Some(field), None) => field_work(args, field),
        (Some(_), Some(_)) => bail!("give either a data file or --field, not both"),
        (None, Some(file)) => data_work(args, file, false),
        (None, None) => bail!(
            "give a data file of x and F columns (mechkit work forcedata.d), or a force field with --field and a path"
        ),
    }
}

/// `mechkit impulse FILE`: `mechkit work FILE --of time`, with time required to increase.
pub fn impulse(args: &ImpulseArgs) -> Result<Outcome> {
    let work_args = WorkArgs {
        file: Some(args.file.clone()),
        x: args.t.clone(),
        f: args.f.clone(),
        method: args.method.clone(),
        of: Some("time".into()),
        mass: args.mass.clone(),
        v0: args.v0.clone(),
        out: args.out.clone(),
        plot: args.plot.clone(),
        dpi: args.dpi,
        field: None,
        path: None,
        param: None,
        through: None,
        set: None,
        json: args.json,
    };
    data_work(&work_args, &args.file, true)
}

fn column(text: &str, flag: &str) -> Result<ColumnRef> {
    ColumnRef::parse(text).map_err(|e| anyhow!("{flag}: {e}"))
}

/// Whether the abscissa is a time: by --of, else by the column's name.
fn over_time(args: &WorkArgs, name: &str) -> bool {
    if let Some(of) = args.of.as_deref() {
        return of == "time";
    }
    let n = name.trim().to_ascii_lowercase();
    let head = n.split([' ', '[', '(']).next().unwrap_or("");
    head == "t" || head == "time"
}

fn data_work(args: &WorkArgs, file: &Path, increasing_time: bool) -> Result<Outcome> {
    let table = Table::read(file).map_err(|e| anyhow!("{e}"))?;
    let (x_ref, f_ref) = (
        column(args.x.as_deref().unwrap_or("1"), "--x")?,
        column(args.f.as_deref().unwrap_or("2"), "--f")?,
    );
    let x_index = table
        .column_index(&x_ref)
        .map_err(|e| anyhow!("--x: {e}"))?;
    let f_index = table
        .column_index(&f_ref)
        .map_err(|e| anyhow!("--f: {e}"))?;
    let time = over_time(args, &table.label(x_index));
    let what = if time {
        "the impulse integral"
    } else {
        "the work integral"
    };
    let (x, order) = table.abscissa(&x_ref, what).map_err(|e| anyhow!("{e}"))?;
    if increasing_time && order == Order::Decreasing {
        bail!(
            "{}: the time column `{}` decreases (negative time steps); an impulse needs increasing time: sort the file by time",
            table.source(),
            table.label(x_index)
        );
    }
    let f = table.column(&f_ref).map_err(|e| anyhow!("{e}"))?;
    let rule = SampleRule::parse(&args.method).ok_or_else(|| {
        anyhow!(
            "--method: unknown rule `{}`; use trapezoid, simpson, left, right or midpoint",
            args.method
        )
    })?;
    let w = SampledIntegral::new(x, f, rule).map_err(|e| anyhow!("{}: {e}", table.source()))?;
    let mass = args
        .mass
        .as_deref()
        .map(|m| quantity(m, "--mass", Dimension::MASS))
        .transpose()?;
    if mass.is_some_and(|m| m.is_nan() || m <= 0.0) {
        bail!("--mass must be positive");
    }
    let v0 = args
        .v0
        .as_deref()
        .map_or(Ok(0.0), |v| quantity(v, "--v0", Dimension::VELOCITY))?;
    // unnamed columns are called t or x, and F
    let (x_name, f_name) = match table.names() {
        Some(_) => (table.label(x_index), table.label(f_index)),
        None => ((if time { "t" } else { "x" }).to_string(), "F".to_string()),
    };
    let speeds = mass.filter(|_| !time).map(|m| w.speeds(m, v0));
    let turning = mass
        .filter(|_| !time)
        .and_then(|m| w.turning_point(x, m, v0));
    if let Some(path) = &args.out {
        write_atomic(
            path,
            csv(
                &x_name,
                &f_name,
                x,
                f,
                &w.cumulative,
                speeds.as_deref(),
                time,
            )
            .as_bytes(),
        )
        .map_err(|e| anyhow!("cannot write {}: {e}", path.display()))?;
    }
    if let Some(path) = &args.plot {
        let (name, unit) = if time { ("J", "N s") } else { ("W", "J") };
        let plot = PlotData::new(
            format!("{name}({x_name}) = ∫ F d{x_name} ({})", rule.name()),
            "work",
            x_name.clone(),
            format!("{name} [{unit}]"),
        )
        .with_series(Series::line(
            format!("{name}({x_name})"),
            x.iter()
                .copied()
                .zip(w.cumulative.iter().copied())
                .collect(),
        ));
        let title = file
            .file_name()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        render(&plot, &title, path, args.dpi)?;
    }
    let delta_v = mass.filter(|_| time).map(|m| w.total / m);
    if args.json {
        let j = json!({
            "file": file.display().to_string(),
            "rows": x.len(),
            "x": x_name, "f": f_name,
            "of": if time { "time" } else { "position" },
            "rule": rule.name(),
            "integral": w.total,
            "work": (!time).then_some(w.total),
            "impulse": time.then_some(w.total),
            "span": w.span,
            "mean_force": w.mean(),
            "peak": {"x": w.peak.0, "f": w.peak.1},
            "mass": mass, "v0": v0,
            "delta_v": delta_v,
            "v_end": delta_v.map(|d| v0 + d).or_else(|| speeds.as_ref().and_then(|s| s.last().copied()).filter(|v| v.is_finite())),
            "turning_point": turning,
            "cumulative": w.cumulative,
            "csv": args.out.as_ref().map(|p| p.display().to_string()),
            "plot": args.plot.as_ref().map(|p| p.display().to_string()),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!(
            "{}: {} rows, {} rule\n",
            file.display(),
            x.len(),
            rule.name()
        );
        if time {
            let _ = writeln!(
                out,
                "impulse J = ∫ F d{x_name} = {} N s over {} s",
                w.total, w.span
            );
            let _ = writeln!(out, "average force J/Δt = {} N", w.mean());
        } else {
            let _ = writeln!(
                out,
                "work W = ∫ F d{x_name} = {} J over {} m",
                w.total, w.span
            );
            let _ = writeln!(out, "average force W/Δx = {} N", w.mean());
        }
        let _ = writeln!(out, "largest |F| = {} at {x_name} = {}", w.peak.1, w.peak.0);
        if let Some(d) = delta_v {
            let _ = writeln!(
                out,
                "Δv = J/m = {d} m/s, so v goes from {v0} to {} m/s",
                v0 + d
            );
        }
        if let Some(s) = &speeds {
            match turning {
                Some(t) => {
                    let _ = writeln!(out, "the body stops (v² = 0) at {x_name} = {t}");
                }
                None => {
                    let _ = writeln!(out, "speed at the end v = {} m/s", s[s.len() - 1]);
                }
            }
        }
        for (flag, p) in [("csv", &args.out), ("plot", &args.plot)] {
            if let Some(p) = p {
                let _ = writeln!(out, "{flag}: {}", p.display());
            }
        }
        print(&out)?;
    }
    Ok(Outcome::Success)
}

fn csv(
    x_name: &str,
    f_name: &str,
    x: &[f64],
    f: &[f64],
    w: &[f64],
    v: Option<&[f64]>,
    time: bool,
) -> String {
    let mut out = format!("{x_name},{f_name},{}", if time { "J" } else { "W" });
    if v.is_some() {
        out.push_str(",v");
    }
    out.push('\n');
    for i in 0..x.len() {
        push_number(&mut out, x[i]);
        for value in [f[i], w[i]].into_iter().chain(v.map(|v| v[i])) {
            out.push(',');
            push_number(&mut out, value);
        }
        out.push('\n');
    }
    out
}
