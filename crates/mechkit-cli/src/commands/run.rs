//! `mechkit run FILE`: simulate, write the trajectory, summary and plots, print the summary.

use std::path::PathBuf;

use anyhow::Result;
use mechkit::scenario::Scenario;

use super::{Outcome, print};
use crate::args::RunArgs;
use crate::plot;

pub fn run(args: &RunArgs) -> Result<Outcome> {
    let scenario = Scenario::load(&args.file)?;
    let dir = args.out.clone().unwrap_or_else(|| {
        let stem = args
            .file
            .file_stem()
            .map_or_else(|| "run".into(), |s| s.to_string_lossy().into_owned());
        PathBuf::from("out").join(stem)
    });
    let mut out = scenario.run_to_dir(&dir)?;
    if !args.no_plots {
        for p in &out.plots {
            let path = dir.join(format!("{}.svg", p.file_stem));
            plot::render_svg(p, &scenario.title, &path)?;
            out.summary.files.plots.push(format!("{}.svg", p.file_stem));
        }
        scenario.write_summary(&dir, &out.summary)?;
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
