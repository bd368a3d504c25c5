//! `mechkit check FILE`: load and validate a scenario, say what it contains.

use anyhow::Result;
use mechkit::scenario::Scenario;

use super::Outcome;
use crate::args::CheckArgs;

pub fn check(args: &CheckArgs) -> Result<Outcome> {
    let s = Scenario::load(&args.file)?;
    let sys = &s.system;
    println!("ok: {}", s.title);
    println!(
        "  {} dimension{}, {} bod{}, {} force{}",
        s.dim,
        if s.dim == 1 { "" } else { "s" },
        sys.bodies().len(),
        if sys.bodies().len() == 1 { "y" } else { "ies" },
        sys.forces().len(),
        if sys.forces().len() == 1 { "" } else { "s" }
    );
    for b in sys.bodies() {
        println!("  body {}: {} kg", b.name, b.mass);
    }
    for f in sys.forces().iter() {
        println!("  force {}", f.name());
    }
    println!("  method {} with dt = {} s", s.method, s.dt);
    match (&s.stop, s.t_max) {
        (Some(c), Some(t)) => println!("  stops when `{}` or at t = {t} s", c.description()),
        (Some(c), None) => println!("  stops when `{}`", c.description()),
        (None, Some(t)) => println!("  stops at t = {t} s"),
        (None, None) => {}
    }
    for o in &s.observables {
        println!("  observe {} = {}", o.name, o.source);
    }
    for p in &s.plots {
        println!("  plot {}", p.spec);
    }
    for w in &s.warnings {
        eprintln!("warning: {w}");
    }
    Ok(Outcome::Success)
}
