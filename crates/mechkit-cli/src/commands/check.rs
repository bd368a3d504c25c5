//! `mechkit check FILE`: load and validate a scenario, say what it contains.

use std::fmt::Write as _;

use anyhow::Result;
use mechkit::scenario::Scenario;

use super::{Outcome, print};
use crate::args::CheckArgs;

pub fn check(args: &CheckArgs) -> Result<Outcome> {
    let s = Scenario::load(&args.file)?;
    let sys = &s.system;
    let plural =
        |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let mut text = String::new();
    let _ = writeln!(text, "ok: {}", s.title);
    let _ = writeln!(
        text,
        "  {}, {}, {}",
        plural(s.dim, "dimension", "dimensions"),
        plural(sys.bodies().len(), "body", "bodies"),
        plural(sys.forces().len(), "force", "forces")
    );
    for b in sys.bodies() {
        let _ = writeln!(text, "  body {}: {} kg", b.name, b.mass);
    }
    for f in sys.forces().iter() {
        let _ = writeln!(text, "  force {}", f.name());
    }
    let _ = writeln!(text, "  method {}", s.stepping.describe());
    for e in &s.events {
        let _ = writeln!(
            text,
            "  event `{}`{}",
            e.name(),
            e.state_change_description()
                .map(|d| format!(": set {d}"))
                .unwrap_or_default()
        );
    }
    let _ = match (&s.stop, s.t_max) {
        (Some(c), Some(t)) => writeln!(text, "  stops when `{}` or at t = {t} s", c.description()),
        (Some(c), None) => writeln!(text, "  stops when `{}`", c.description()),
        (None, Some(t)) => writeln!(text, "  stops at t = {t} s"),
        (None, None) => Ok(()),
    };
    for o in &s.observables {
        let _ = writeln!(text, "  observe {} = {}", o.name, o.source);
    }
    for p in &s.plots {
        let _ = writeln!(text, "  plot {}", p.spec);
    }
    for w in &s.warnings {
        eprintln!("warning: {w}");
    }
    print(&text)?;
    Ok(Outcome::Success)
}
