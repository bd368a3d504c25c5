//! `mechkit derive`: velocity and acceleration from a position-time data file
//! (`mechkit::deriv::derive_motion`), with `-o DIR` as CSV and plots.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow};
use mechkit::data::{ColumnRef, Table};
use mechkit::deriv::{
    Derivation, DeriveError, DeriveQuestion, DerivedMotion, Difference, SavitzkyGolay,
    derive_motion,
};
use mechkit::inputs::Input;

use super::input::fixed;
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::DeriveArgs;

pub fn derive(args: &DeriveArgs) -> Result<Outcome> {
    let table = Table::read(&args.file).map_err(|e| anyhow!("{e}"))?;
    let question = DeriveQuestion {
        table: &table,
        t: column_ref(args.t.as_deref().unwrap_or("1"), "--t")?,
        x: args
            .x
            .as_ref()
            .map(|list| list.iter().map(|c| column_ref(c, "--x")).collect())
            .transpose()?,
        how: derivation(args)?,
    };
    let mut d = derive_motion(&question).map_err(|e| match e {
        DeriveError::Column { input, error } => {
            let flag = if input == Input::AbscissaColumn {
                "--t"
            } else {
                "--x"
            };
            anyhow!("{flag}: {error}")
        }
        other => anyhow!("{other}"),
    })?;
    // the finiteness rule before any file: an answer that is not finite writes nothing
    mechkit::finite::check_finite(&d)?;
    // the finiteness rule: a column whose derivative is not finite anywhere has no answer
    if let Some(c) = d
        .columns
        .iter()
        .find(|c| c.velocity.is_none() || c.acceleration.is_none())
    {
        eprintln!(
            "error: the derivative of `{}` is not finite: its values or their differences \
             overflow double precision\n  = hint: rescale the data (other units) before \
             differentiating",
            c.name
        );
        return Ok(Outcome::ComputationFailed);
    }
    if let Some(dir) = &args.out {
        write_files(args, dir, &mut d)?;
    }
    report(args.report, &d, || text(&d))?;
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

/// With `-o DIR`: `derived.csv` with its units, and the plots of positions, velocities and
/// accelerations.
fn write_files(args: &DeriveArgs, dir: &Path, d: &mut DerivedMotion) -> Result<()> {
    create_dir(dir)?;
    let csv = write_table(dir, "derived", &d.table())?;
    note(args.report, &format!("wrote {csv}"));
    d.csv = Some(csv);
    if !args.no_plots {
        let title = args
            .file
            .file_name()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        d.plots = write_plots(dir, &d.plots(), &title, args.plots)?;
        for path in &d.plots {
            note(args.report, &format!("wrote {path}"));
        }
    }
    Ok(())
}

fn text(d: &DerivedMotion) -> String {
    let mut out = format!(
        "{}: {} rows, time `{}`, {}\n",
        d.file, d.rows, d.time, d.method
    );
    for c in &d.columns {
        let (Some(v), Some(a)) = (c.velocity, c.acceleration) else {
            let _ = writeln!(out, "  {}: no finite derivative", c.name);
            continue;
        };
        let _ = writeln!(
            out,
            "  {}: v from {} to {}, a from {} to {} (median {})",
            c.name,
            fixed(v.min, 6),
            fixed(v.max, 6),
            fixed(a.min, 6),
            fixed(a.max, 6),
            fixed(a.median, 6)
        );
    }
    out
}
