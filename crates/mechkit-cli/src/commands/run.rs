//! `mechkit run FILE`: simulate, write the trajectory, summary and plots, print the summary.

use std::path::{Path, PathBuf};

use anyhow::{Context as _, Result, anyhow, bail};
use mechkit::ode::Method;
use mechkit::scenario::{CompareSettings, Scenario, parse_size, write_atomic};
use mechkit::simulate::Cancel;
use mechkit::units::{Dimension, Quantity};

use super::{Outcome, print};
use crate::args::RunArgs;
use crate::plot;

pub fn run(args: &RunArgs, cancel: &Cancel) -> Result<Outcome> {
    let mut scenario = Scenario::load(&args.file)?;
    scenario.cancel = cancel.clone();
    if let Some(size) = &args.max_output {
        scenario.max_output = parse_size(size).map_err(|e| anyhow!("--max-output: {e}"))?;
    }
    let dir = args.out.clone().unwrap_or_else(|| {
        let stem = args
            .file
            .file_stem()
            .map_or_else(|| "run".into(), |s| s.to_string_lossy().into_owned());
        PathBuf::from("out").join(stem)
    });
    if let Some(methods) = &args.compare_methods {
        return compare(args, &scenario, methods, &dir);
    }
    let mut out = scenario.run_to_dir(&dir)?;
    if !args.no_plots {
        plot::render_run(&scenario, &mut out, &dir, args.plots)?;
    }
    for w in &out.summary.warnings {
        eprintln!("warning: {w}");
    }
    if args.json {
        print(&out.summary.to_json())?;
    } else {
        print(&format!(
            "{}wrote {}\n",
            out.summary.to_text(),
            dir.display()
        ))?;
    }
    if out.summary.stop_reason == "interrupted" {
        eprintln!(
            "interrupted at t = {} s: the outputs in {} hold the run up to there",
            out.summary.t_end,
            dir.display()
        );
        return Ok(Outcome::Interrupted);
    }
    if let Some(why) = match out.summary.stop_reason.as_str() {
        "output_limit" => Some("its output reached the limit"),
        "output_error" => Some("its output could not be written"),
        _ => None,
    } {
        // the message, with what to do, is among the warnings printed above
        eprintln!(
            "error: the run stopped at t = {} s because {why}; {} holds the run up to there",
            out.summary.t_end,
            dir.display()
        );
        return Ok(Outcome::ComputationFailed);
    }
    if out.failed() {
        if let Some(d) = &out.summary.divergence {
            let what = match out.summary.stop_reason.as_str() {
                "diverged" => "the simulation diverged",
                "step_too_small" => "the adaptive step size underflowed",
                "zeno" => "an event fired endlessly",
                _ => "the simulation failed",
            };
            eprintln!("error: {what}: {}", d.message);
        }
        return Ok(Outcome::ComputationFailed);
    }
    Ok(Outcome::Success)
}

fn compare(args: &RunArgs, scenario: &Scenario, names: &[String], dir: &Path) -> Result<Outcome> {
    let mut methods = Vec::new();
    for n in names.iter().map(|n| n.trim()).filter(|n| !n.is_empty()) {
        let m = Method::from_name(n).ok_or_else(|| {
            let all: Vec<&str> = Method::ALL.iter().map(|m| m.name()).collect();
            anyhow!(
                "--compare-methods: unknown method `{n}`\n  = hint: available: {}",
                all.join(", ")
            )
        })?;
        methods.push(m);
    }
    if methods.is_empty() {
        bail!(
            "--compare-methods needs at least one method\n  = hint: e.g. --compare-methods euler,rk4,dopri5"
        );
    }
    let dt = match &args.dt {
        None => None,
        Some(text) => {
            let q =
                Quantity::parse(text).map_err(|e| anyhow!("--dt \"{text}\": {}", e.message()))?;
            if q.dim != Dimension::TIME && q.dim != Dimension::NONE {
                bail!("--dt \"{text}\" is not a time\n  = hint: e.g. --dt \"1 ms\"");
            }
            if !(q.value > 0.0 && q.value.is_finite()) {
                bail!("--dt must be positive, not {text}");
            }
            Some(q.value)
        }
    };
    for (flag, v) in [("--rtol", args.rtol), ("--atol", args.atol)] {
        if let Some(v) = v
            && !(v >= 0.0 && v.is_finite() && (flag == "--atol" || v > 0.0))
        {
            bail!("{flag} must be positive, not {v}");
        }
    }
    let settings = CompareSettings {
        dt,
        rtol: args.rtol,
        atol: args.atol,
    };
    let cmp = scenario.compare(&methods, &settings)?;
    std::fs::create_dir_all(dir)
        .with_context(|| format!("cannot create the output directory {}", dir.display()))?;
    write_atomic(&dir.join("compare.json"), cmp.to_json().as_bytes())
        .with_context(|| format!("cannot write {}", dir.join("compare.json").display()))?;
    if !args.no_plots {
        for p in &cmp.plots {
            let path = dir.join(args.plots.file(&p.file_stem));
            plot::render(p, &scenario.title, &path, args.plots)?;
        }
    }
    if args.json {
        print(&cmp.to_json())?;
    } else {
        print(&format!("{}wrote {}\n", cmp.to_text(), dir.display()))?;
    }
    Ok(Outcome::Success)
}
