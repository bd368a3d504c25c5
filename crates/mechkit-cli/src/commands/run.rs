//! `mechkit run FILE`: simulate, write the trajectory, summary and plots, print the summary.

use std::path::Path;

use anyhow::{Context as _, Result, anyhow, bail};
use mechkit::expr::short_number as show;
use mechkit::ode::{AdaptiveConfig, Method, Tolerance};
use mechkit::scenario::{CompareSettings, ConstantOverride, Scenario, parse_size, write_atomic};
use mechkit::simulate::Cancel;
use mechkit::units::{Dimension, Quantity};

use super::Outcome;
use crate::args::RunArgs;
use crate::plot;

pub fn run(args: &RunArgs, cancel: &Cancel) -> Result<Outcome> {
    let mut scenario = load(&args.file, args.set.as_deref())?;
    scenario.cancel = cancel.clone();
    if let Some(size) = &args.max_output {
        scenario.max_output = parse_size(size).map_err(|e| anyhow!("--max-output: {e}"))?;
    }
    let dir = args.out.clone();
    if let Some(methods) = &args.compare_methods {
        return compare(args, &scenario, methods, dir.as_deref());
    }
    if let Some(dir) = &dir
        && !args.no_plots
    {
        refuse_special_files(&scenario, dir, args.plots)?;
    }
    let mut bar = progress_bar(&scenario, args.report);
    let out = match &dir {
        Some(dir) => scenario.run_to_dir_then(dir, |out| {
            bar.finish();
            if args.no_plots || cancel.is_urgent() {
                return Ok(());
            }
            let urgent = || cancel.is_urgent();
            plot::render_plots(&scenario, out, dir, args.plots, &urgent)
                .and_then(|()| {
                    if urgent() {
                        return Ok(());
                    }
                    super::animate::write_animations(&scenario, dir).map(|_| ())
                })
                .map_err(|e| crate::failure::message(&e))
        })?,
        None => scenario.run()?,
    };
    bar.finish();
    for w in &out.summary.warnings {
        eprintln!("warning: {w}");
    }
    let wrote = dir.as_ref().map_or_else(
        || {
            "no files written (give -o DIR to write trajectory.csv, summary.json and plots)\n"
                .to_string()
        },
        |d| format!("wrote {}\n", d.display()),
    );
    super::report_summary(args.report, &out.summary, || {
        format!("{}{wrote}", out.summary.to_text())
    })?;
    let held = dir.as_ref().map_or_else(String::new, |d| {
        format!(": the outputs in {} hold the run up to there", d.display())
    });
    if out.summary.stop_reason == "interrupted" {
        eprintln!(
            "interrupted at t = {} s{held}",
            mechkit::expr::short_number(out.summary.t_end)
        );
        return Ok(Outcome::Interrupted);
    }
    if let Some(error) = &out.summary.files.error
        && out.summary.stop_reason != "output_error"
    {
        eprintln!("error: {error}");
        return Ok(Outcome::ComputationFailed);
    }
    let files = &out.summary.files;
    let held = match (dir.as_ref(), files.trajectory_last_t) {
        // the rows after the limit are not in the file: say where it ends
        (Some(d), Some(last)) if out.summary.stop_reason == "output_limit" => format!(
            ": {} holds {} rows, up to t = {} s",
            d.join("trajectory.csv").display(),
            files.trajectory_rows,
            mechkit::expr::short_number(last)
        ),
        _ => held,
    };
    if let Some(why) = match out.summary.stop_reason.as_str() {
        "output_limit" => Some("its output reached the limit"),
        "output_error" => Some("its output could not be written"),
        _ => None,
    } {
        // the message, with what to do, is among the warnings printed above
        eprintln!(
            "error: the run stopped at t = {} s because {why}{held}",
            mechkit::expr::short_number(out.summary.t_end)
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

fn compare(
    args: &RunArgs,
    scenario: &Scenario,
    names: &[String],
    dir: Option<&Path>,
) -> Result<Outcome> {
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
            bail!("{flag} must be positive, not {}", show(v));
        }
    }
    if let Some(rtol) = args.rtol {
        // the adaptive integrators' own rule (above double precision), at the flag
        AdaptiveConfig {
            rtol: Tolerance::Scalar(rtol),
            ..AdaptiveConfig::default()
        }
        .validate(1)
        .map_err(|e| anyhow!("--rtol: {e}"))?;
    }
    let settings = CompareSettings {
        dt,
        rtol: args.rtol,
        atol: args.atol,
    };
    let dir = dir.ok_or_else(|| {
        anyhow!(
            "--compare-methods writes compare.json and its plots: give the directory with -o DIR"
        )
    })?;
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
    super::report(args.report, &cmp, || {
        format!("{}wrote {}\n", cmp.to_text(), dir.display())
    })?;
    Ok(Outcome::Success)
}

/// Refuses, before the run, a plot or animation in `dir` whose name is taken by something
/// that is not a regular file (a device, a pipe, a directory): it would be refused only
/// after the run. The run's own files are checked by the library before it starts.
fn refuse_special_files(
    scenario: &Scenario,
    dir: &Path,
    format: crate::args::PlotFormat,
) -> Result<()> {
    let plots = scenario.plots.iter().map(|p| format.file(&p.file_stem()));
    let bars = scenario
        .energy_bars
        .then(|| format.file(mechkit::scenario::ENERGY_BARS));
    let animations = scenario.animation.iter().map(|a| a.file_name());
    for name in plots.chain(bars).chain(animations) {
        mechkit::csv::writable_target(&dir.join(name)).map_err(|e| {
            anyhow!("--out: {e}\n  = hint: move it away, or choose another directory with --out")
        })?;
    }
    Ok(())
}

/// Reads the scenario, with `--set` overrides of its constants.
pub fn load(file: &Path, set: Option<&str>) -> Result<Scenario> {
    let overrides = match set {
        Some(text) => ConstantOverride::parse_list(text)?,
        None => Vec::new(),
    };
    Ok(Scenario::load_with(file, &overrides)?)
}

/// A progress bar for a run with an end time, on a terminal and unless `-q`: it follows the
/// scenario's [`Progress`](mechkit::simulate::Progress) from a thread and appears only when
/// the run lasts more than half a second.
fn progress_bar(scenario: &Scenario, flags: crate::args::Report) -> ProgressBar {
    use std::io::IsTerminal as _;
    let Some(t_max) = scenario.t_max.filter(|t| t.is_finite() && *t > 0.0) else {
        return ProgressBar::none();
    };
    if flags.quiet || flags.json || !std::io::stderr().is_terminal() {
        return ProgressBar::none();
    }
    ProgressBar::follow(scenario.progress.clone(), t_max)
}

/// A terminal progress bar fed by a thread that polls a run's time.
struct ProgressBar {
    stop: Option<(
        std::sync::Arc<std::sync::atomic::AtomicBool>,
        std::thread::JoinHandle<()>,
    )>,
}

impl ProgressBar {
    fn none() -> Self {
        Self { stop: None }
    }

    fn follow(progress: mechkit::simulate::Progress, t_max: f64) -> Self {
        use std::sync::atomic::{AtomicBool, Ordering};
        let stop = std::sync::Arc::new(AtomicBool::new(false));
        let done = std::sync::Arc::clone(&stop);
        let thread = std::thread::spawn(move || {
            let start = std::time::Instant::now();
            let mut bar: Option<indicatif::ProgressBar> = None;
            while !done.load(Ordering::Relaxed) {
                std::thread::sleep(std::time::Duration::from_millis(100));
                if start.elapsed() < std::time::Duration::from_millis(500) {
                    continue;
                }
                let b = bar.get_or_insert_with(|| {
                    let b = indicatif::ProgressBar::new(1000);
                    if let Ok(style) = indicatif::ProgressStyle::with_template(
                        "{bar:40} {percent:>3}% t = {msg}  {elapsed} (eta {eta})",
                    ) {
                        b.set_style(style);
                    }
                    b
                });
                let t = progress.time();
                if t.is_finite() {
                    let frac = (t / t_max).clamp(0.0, 1.0);
                    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                    b.set_position((frac * 1000.0) as u64);
                    b.set_message(format!(
                        "{} s of {} s",
                        mechkit::expr::short_fixed(t, 4),
                        show(t_max)
                    ));
                }
            }
            if let Some(b) = bar {
                b.finish_and_clear();
            }
        });
        Self {
            stop: Some((stop, thread)),
        }
    }

    fn finish(&mut self) {
        if let Some((stop, thread)) = self.stop.take() {
            stop.store(true, std::sync::atomic::Ordering::Relaxed);
            let _ = thread.join();
        }
    }
}
