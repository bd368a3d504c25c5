//! `mechkit work` and `mechkit impulse`: the work (or impulse) from sampled force data
//! (`mechkit::energy::data_work`), or of a force field along a path (`work_field.rs`).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow, bail};
use mechkit::data::{ColumnRef, Table};
use mechkit::energy::{Abscissa, DataWork, DataWorkError, DataWorkQuestion, data_work};
use mechkit::expr::units::Dimension;
use mechkit::inputs::Input;
use mechkit::quad::SampleRule;

use super::input::{quantity, show};
use super::outputs::{create_dir, write_plots, write_table};
use super::work_field::field_work;
use super::{Outcome, note, report};
use crate::args::{ImpulseArgs, PlotFormat, WorkArgs};

pub fn work(args: &WorkArgs) -> Result<Outcome> {
    match (&args.field, &args.file) {
        (Some(field), None) => field_work(args, field),
        (Some(_), Some(_)) => bail!("give either a data file or --field, not both"),
        (None, Some(file)) => data(&Data {
            file,
            x: (args.x.as_deref(), "--x"),
            f: args.f.as_deref(),
            method: &args.method,
            of: args.of.as_deref().map(|of| {
                if of == "time" {
                    Abscissa::Time
                } else {
                    Abscissa::Position
                }
            }),
            mass: args.mass.as_deref(),
            v0: args.v0.as_deref(),
            out: args.out.as_deref(),
            no_plots: args.no_plots,
            plots: args.plots,
            report: args.report,
        }),
        (None, None) => bail!(
            "give a data file of x and F columns (mechkit work forcedata.d), or a force field with --field and a path"
        ),
    }
}

/// `mechkit impulse FILE`: `mechkit work FILE --of time`.
pub fn impulse(args: &ImpulseArgs) -> Result<Outcome> {
    data(&Data {
        file: &args.file,
        x: (args.t.as_deref(), "--t"),
        f: args.f.as_deref(),
        method: &args.method,
        of: Some(Abscissa::Time),
        mass: args.mass.as_deref(),
        v0: args.v0.as_deref(),
        out: args.out.as_deref(),
        no_plots: args.no_plots,
        plots: args.plots,
        report: args.report,
    })
}

/// The arguments `work FILE` and `impulse FILE` share.
struct Data<'a> {
    file: &'a PathBuf,
    /// The abscissa column and its flag (`--x`, `--t`).
    x: (Option<&'a str>, &'static str),
    f: Option<&'a str>,
    method: &'a str,
    of: Option<Abscissa>,
    mass: Option<&'a str>,
    v0: Option<&'a str>,
    out: Option<&'a Path>,
    no_plots: bool,
    plots: PlotFormat,
    report: crate::args::Report,
}

fn column(text: Option<&str>, default: &str, flag: &str) -> Result<ColumnRef> {
    ColumnRef::parse(text.unwrap_or(default)).map_err(|e| anyhow!("{flag}: {e}"))
}

fn data(args: &Data<'_>) -> Result<Outcome> {
    let (x_text, x_flag) = args.x;
    let table = Table::read(args.file).map_err(|e| anyhow!("{e}"))?;
    let rule = SampleRule::parse(args.method).ok_or_else(|| {
        anyhow!(
            "--method: unknown rule `{}`; use trapezoid, simpson, left, right or midpoint",
            args.method
        )
    })?;
    let question = DataWorkQuestion {
        table: &table,
        x: column(x_text, "1", x_flag)?,
        f: column(args.f, "2", "--f")?,
        rule,
        of: args.of,
        mass: args
            .mass
            .map(|m| quantity(m, "--mass", Dimension::MASS))
            .transpose()?,
        v0: args
            .v0
            .map_or(Ok(0.0), |v| quantity(v, "--v0", Dimension::VELOCITY))?,
    };
    let mut w = data_work(&question).map_err(|e| match e {
        DataWorkError::Column { input, error } => {
            let flag = if input == Input::AbscissaColumn {
                x_flag
            } else {
                "--f"
            };
            anyhow!("{flag}: {error}")
        }
        DataWorkError::Input(e) => {
            let flag = match e.input {
                Input::Mass => "--mass",
                Input::StartSpeed => "--v0",
                _ => "--method",
            };
            anyhow!("{flag}: {}", e.message)
        }
        other => anyhow!("{other}"),
    })?;
    // the finiteness rule before any file: an answer that is not finite writes nothing
    mechkit::finite::check_finite(&w)?;
    if let Some(dir) = args.out {
        write_files(args, dir, &mut w)?;
    }
    report(args.report, &w, || text(&w))?;
    Ok(Outcome::Success)
}

/// With `-o DIR`: `work.csv` (or `impulse.csv`) with its units, and the plot `W_x` (`J_t`).
fn write_files(args: &Data<'_>, dir: &Path, w: &mut DataWork) -> Result<()> {
    create_dir(dir)?;
    let csv = write_table(dir, w.name(), &w.table())?;
    note(args.report, &format!("wrote {csv}"));
    w.csv = Some(csv);
    if !args.no_plots {
        let title = args
            .file
            .file_name()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        w.plot = write_plots(dir, &[w.plot()], &title, args.plots)?.pop();
        if let Some(path) = &w.plot {
            note(args.report, &format!("wrote {path}"));
        }
    }
    Ok(())
}

fn text(w: &DataWork) -> String {
    let x = &w.x;
    let mut out = format!("{}: {} rows, {} rule\n", w.file, w.rows, w.rule.name());
    match w.of {
        Abscissa::Time => {
            let _ = writeln!(
                out,
                "impulse J = ∫ F d{x} = {} N s over {} s",
                show(w.integral),
                show(w.span)
            );
            let _ = writeln!(out, "average force J/Δt = {} N", show(w.mean_force));
        }
        Abscissa::Position => {
            let _ = writeln!(
                out,
                "work W = ∫ F d{x} = {} J over {} m",
                show(w.integral),
                show(w.span)
            );
            let _ = writeln!(out, "average force W/Δx = {} N", show(w.mean_force));
        }
    }
    let _ = writeln!(
        out,
        "largest |F| = {} N (F = {} at {x} = {})",
        show(w.peak.magnitude),
        show(w.peak.f),
        show(w.peak.x)
    );
    if let Some(d) = w.delta_v {
        let _ = writeln!(
            out,
            "Δv = J/m = {} m/s, so v goes from {} to {} m/s",
            show(d),
            show(w.v0),
            show(w.v0 + d)
        );
    }
    if w.mass.is_some() && w.of == Abscissa::Position {
        match (w.turning_point, w.v_end) {
            (Some(t), _) => {
                let _ = writeln!(out, "the body stops (v² = 0) at {x} = {}", show(t));
            }
            (None, Some(v)) => {
                let _ = writeln!(out, "speed at the end v = {} m/s", show(v));
            }
            (None, None) => {}
        }
    }
    out
}
