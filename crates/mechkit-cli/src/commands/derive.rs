//! `mechkit derive`: velocity and acceleration from a position-time data file, as CSV and
//! plots.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow, bail};
use mechkit::data::{ColumnRef, Order, Table};
use mechkit::deriv::{Derivation, Difference, SavitzkyGolay, kinematics, uniform_step};
use mechkit::figure::{PlotData, Series};
use mechkit::scenario::{push_number, write_atomic};
use serde_json::json;

use super::{Outcome, print};
use crate::args::DeriveArgs;
use crate::plot::render;

/// One derived column.
struct Derived {
    name: String,
    x: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
}

pub fn derive(args: &DeriveArgs) -> Result<Outcome> {
    let table = Table::read(&args.file).map_err(|e| anyhow!("{e}"))?;
    let t_ref = column_ref(args.t.as_deref().unwrap_or("1"), "--t")?;
    let t_index = table
        .column_index(&t_ref)
        .map_err(|e| anyhow!("--t: {e}"))?;
    let (t, order) = table
        .abscissa(&t_ref, "the derivative")
        .map_err(|e| anyhow!("{e}"))?;
    if order == Order::Decreasing {
        bail!(
            "{}: the time column `{}` decreases; derivatives need increasing time (sort the file by time)",
            table.source(),
            table.label(t_index)
        );
    }
    let xs: Vec<usize> = match &args.x {
        Some(list) => list
            .iter()
            .map(|c| {
                let r = column_ref(c, "--x")?;
                table.column_index(&r).map_err(|e| anyhow!("--x: {e}"))
            })
            .collect::<Result<_>>()?,
        None => (0..table.width()).filter(|&i| i != t_index).collect(),
    };
    if xs.is_empty() {
        bail!(
            "{}: there is no column to differentiate besides the time column",
            table.source()
        );
    }
    // unnamed columns are called t and x (x2, x3, … when there are several)
    let name = |i: usize| match table.names() {
        Some(_) => table.label(i),
        None if i == t_index => "t".to_string(),
        None if xs.len() == 1 => "x".to_string(),
        None => format!("x{}", i + 1),
    };
    let how = derivation(args)?;
    let mut derived = Vec::new();
    for &i in &xs {
        let x = table
            .column(&ColumnRef::Index(i))
            .map_err(|e| anyhow!("{e}"))?;
        let k = kinematics(t, x, how).map_err(|e| anyhow!("{}: {e}", table.source()))?;
        derived.push(Derived {
            name: name(i),
            x: x.to_vec(),
            v: k.velocity,
            a: k.acceleration,
        });
    }
    let dir = args.out.clone().unwrap_or_else(|| {
        let stem = args
            .file
            .file_stem()
            .map_or_else(|| "derive".into(), |s| s.to_string_lossy().into_owned());
        PathBuf::from("out").join(stem)
    });
    std::fs::create_dir_all(&dir).map_err(|e| anyhow!("cannot create {}: {e}", dir.display()))?;
    let t_name = name(t_index);
    let csv = dir.join("derived.csv");
    write_atomic(&csv, csv_text(&t_name, t, &derived).as_bytes())
        .map_err(|e| anyhow!("cannot write {}: {e}", csv.display()))?;
    let plots = if args.no_plots {
        Vec::new()
    } else {
        write_plots(args.plots, &dir, &t_name, t, &derived, &args.file)?
    };
    let method = match how {
        Derivation::SavitzkyGolay(f) => {
            format!("savitzky-golay window {} order {}", f.window(), f.order())
        }
        Derivation::Differences(d) => d.name().to_string(),
        _ => String::new(),
    };
    if args.json {
        let columns: Vec<_> = derived
            .iter()
            .map(|d| {
                json!({
                    "name": d.name,
                    "velocity": stats(&d.v),
                    "acceleration": stats(&d.a),
                })
            })
            .collect();
        let j = json!({
            "file": args.file.display().to_string(),
            "rows": t.len(),
            "time": t_name,
            "uniform_step": uniform_step(t),
            "method": method,
            "columns": columns,
            "csv": csv.display().to_string(),
            "plots": plots.iter().map(|p| p.display().to_string()).collect::<Vec<_>>(),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!(
            "{}: {} rows, time `{t_name}`, {method}\n",
            args.file.display(),
            t.len()
        );
        for d in &derived {
            let (v, a) = (stats(&d.v), stats(&d.a));
            let _ = writeln!(
                out,
                "  {}: v from {:.6} to {:.6}, a from {:.6} to {:.6} (median {:.6})",
                d.name, v["min"], v["max"], a["min"], a["max"], a["median"]
            );
        }
        let _ = writeln!(out, "wrote {}", csv.display());
        for p in &plots {
            let _ = writeln!(out, "wrote {}", p.display());
        }
        print(&out)?;
    }
    Ok(Outcome::Success)
}

fn column_ref(text: &str, flag: &str) -> Result<ColumnRef> {
    ColumnRef::parse(text).map_err(|e| anyhow!("{flag}: {e}"))
}

fn derivation(args: &DeriveArgs) -> Result<Derivation> {
    if let Some(spec) = &args.smooth {
        let (w, o) = spec.split_once(':').unwrap_or((spec, "2"));
        let parse = |s: &str, what: &str| {
            s.trim().parse::<usize>().map_err(|_| {
                anyhow!("--smooth {spec}: the {what} must be a whole number (write WINDOW or WINDOW:ORDER, e.g. 21:2)")
            })
        };
        let filter = SavitzkyGolay::new(parse(w, "window")?, parse(o, "polynomial order")?)
            .map_err(|e| anyhow!("--smooth {spec}: {e}"))?;
        return Ok(Derivation::SavitzkyGolay(filter));
    }
    let scheme = Difference::parse(&args.method).ok_or_else(|| {
        anyhow!(
            "--method: unknown difference `{}`; use central, forward or backward",
            args.method
        )
    })?;
    Ok(Derivation::Differences(scheme))
}

fn stats(values: &[f64]) -> serde_json::Value {
    let mut sorted: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    if n == 0 {
        return json!(null);
    }
    let median = if n % 2 == 1 {
        sorted[n / 2]
    } else {
        0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
    };
    json!({
        "min": sorted[0],
        "max": sorted[n - 1],
        "mean": sorted.iter().sum::<f64>() / n as f64,
        "median": median,
        "first": values[0],
        "last": values[values.len() - 1],
    })
}

fn csv_text(t_name: &str, t: &[f64], derived: &[Derived]) -> String {
    let mut out = String::from(t_name);
    for d in derived {
        let _ = write!(out, ",{0},d{0}_d{1},d2{0}_d{1}2", d.name, t_name);
    }
    out.push('\n');
    for (i, &ti) in t.iter().enumerate() {
        push_number(&mut out, ti);
        for d in derived {
            for v in [d.x[i], d.v[i], d.a[i]] {
                out.push(',');
                push_number(&mut out, v);
            }
        }
        out.push('\n');
    }
    out
}

fn write_plots(
    format: crate::args::PlotFormat,
    dir: &Path,
    t_name: &str,
    t: &[f64],
    derived: &[Derived],
    file: &Path,
) -> Result<Vec<PathBuf>> {
    let title = file
        .file_name()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let mut paths = Vec::new();
    for (what, stem, pick) in [
        ("position", "position", 0),
        ("velocity", "velocity", 1),
        ("acceleration", "acceleration", 2),
    ] {
        let mut plot = PlotData::new(format!("{what}({t_name})"), stem, t_name.to_string(), what);
        for d in derived {
            let ys = match pick {
                0 => &d.x,
                1 => &d.v,
                _ => &d.a,
            };
            let label = match pick {
                0 => d.name.clone(),
                1 => format!("d{}/d{t_name}", d.name),
                _ => format!("d²{}/d{t_name}²", d.name),
            };
            plot.series.push(Series::line(
                label,
                t.iter().copied().zip(ys.iter().copied()).collect(),
            ));
        }
        let path = dir.join(format.file(stem));
        render(&plot, &title, &path, format.dpi)?;
        paths.push(path);
    }
    Ok(paths)
}
