//! `mechkit check FILE`: load and validate a scenario, say what it contains.

use anyhow::Result;

use super::Outcome;
use crate::args::CheckArgs;

pub fn check(args: &CheckArgs) -> Result<Outcome> {
    let s = super::run::load(&args.file, args.set.as_deref())?;
    let report = s.check_report();
    for w in &report.warnings {
        eprintln!("warning: {w}");
    }
    super::report(args.report, &report, || report.to_text())?;
    Ok(Outcome::Success)
}
