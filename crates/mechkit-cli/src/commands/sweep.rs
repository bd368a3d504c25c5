//! `mechkit sweep FILE --set …`: a scenario over a grid or a random sample of its constants,
//! in parallel; `mechkit sweep-merge`: the parts of a sharded sweep joined.

use std::fmt::Write as _;
use std::io::IsTerminal as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context as _, Result, anyhow, bail};
use indicatif::{ProgressBar, ProgressStyle};
use mechkit::scenario::sweep::{
    Parameter, Sampling, Shard, SweepGrid, SweepOptions, SweepPart, manifest_name, merge_parts,
    run_sweep,
};
use mechkit::scenario::write_atomic;
use mechkit::simulate::Cancel;

use super::Outcome;
use crate::args::{SweepArgs, SweepMergeArgs};
use crate::plot;

/// Curves labelled in the overlay's legend at most.
const LEGEND: usize = 10;

pub fn sweep(args: &SweepArgs, cancel: &Cancel) -> Result<Outcome> {
    let params = args
        .set
        .iter()
        .map(|s| Parameter::parse(s))
        .collect::<Result<Vec<_>, _>>()?;
    let sampling = match args.random {
        Some(n) => Sampling::Random { n, seed: args.seed },
        None => Sampling::Grid,
    };
    let grid = SweepGrid::new(params, sampling);
    grid.check()?;
    let shard = args.shard.as_deref().map(Shard::parse).transpose()?;
    let threads = match args.threads {
        Some(0) => bail!("--threads must be at least 1\n  = hint: leave it out to use every core"),
        Some(n) if n > mechkit::md::MAX_THREADS => bail!(
            "--threads {n} is more than {}\n  = hint: leave it out to use every core; more threads than cores only slow a sweep down",
            mechkit::md::MAX_THREADS
        ),
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, std::num::NonZero::get),
    };
    let text = mechkit::scenario::read_source(&args.file)?;
    let name = args.file.display().to_string();
    let dir = args.out.clone();
    let options = SweepOptions {
        shard,
        plot: if args.no_plots {
            None
        } else {
            Some(args.plot.clone().unwrap_or_default())
        },
        cancel: cancel.clone(),
    };
    let count = shard.map_or(grid.len(), |s| s.indices(grid.len()).len());
    let bar = if args.report.quiet || args.report.json || !std::io::stderr().is_terminal() {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(count as u64).with_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} runs {per_sec} eta {eta}")
                .expect("the template is valid"),
        )
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("cannot start the worker threads")?;
    let start = Instant::now();
    let result = pool.install(|| run_sweep(&name, &text, &grid, &options, &|| bar.inc(1)));
    bar.finish_and_clear();
    let table = result?;
    let seconds = start.elapsed().as_secs_f64();

    let Some(dir) = dir else {
        return print_table(args, &table, cancel, count, seconds, threads);
    };
    let base = mechkit::scenario::Scenario::from_str(&name, &text)?;
    std::fs::create_dir_all(&dir)
        .with_context(|| format!("cannot create the output directory {}", dir.display()))?;
    let csv = dir.join(table.file_name());
    write_atomic(&csv, table.to_csv().as_bytes())
        .with_context(|| format!("cannot write {}", csv.display()))?;
    let units = dir.join(mechkit::csv::units_file_name(&table.file_name()));
    write_atomic(
        &units,
        mechkit::csv::units_json(&table.columns(&base)).as_bytes(),
    )
    .with_context(|| format!("cannot write {}", units.display()))?;
    let manifest = dir.join(table.manifest_file_name());
    write_atomic(&manifest, table.manifest_json().as_bytes())
        .with_context(|| format!("cannot write {}", manifest.display()))?;
    let mut plot_path = None;
    if let Some(overlay) = table.overlay(LEGEND) {
        let stem = match shard {
            Some(s) => format!("{}.part{}", overlay.file_stem, s.k),
            None => overlay.file_stem.clone(),
        };
        let path = dir.join(args.plots.file(&stem));
        let sets: Vec<&str> = grid.params.iter().map(|p| p.text.as_str()).collect();
        let title = format!("{} runs, {}", table.rows.len(), sets.join("; "));
        plot::render(&overlay, &title, &path, args.plots)?;
        plot_path = Some(path);
    }
    let failed = failures(&table, &csv.display().to_string());
    let rate = table.rows.len() as f64 / seconds.max(1e-9);
    let done = SweepDone {
        scenario: name.clone(),
        runs: grid.len(),
        rows: table.rows.len(),
        shard: shard.map(|s| format!("{}/{}", s.k, s.n)),
        threads,
        seconds,
        runs_per_second: rate,
        failed,
        csv: Some(csv.display().to_string()),
        plot: plot_path.as_ref().map(|p| p.display().to_string()),
    };
    super::report(args.report, &done, || {
        let mut text = format!(
            "{} runs of {} on {threads} thread{} in {seconds:.3} s ({rate:.0} runs/s)\nwrote {}\n",
            table.rows.len(),
            name,
            if threads == 1 { "" } else { "s" },
            csv.display()
        );
        if let Some(p) = &plot_path {
            let _ = writeln!(text, "wrote {}", p.display());
        }
        text
    })?;
    if cancel.is_cancelled() {
        eprintln!(
            "interrupted: {} of {count} runs in {} (those cut short have stop_reason `interrupted`); the rest were not started",
            table.rows.len(),
            csv.display()
        );
        return Ok(Outcome::Interrupted);
    }
    Ok(outcome(&table))
}

/// The number of failed runs, with a warning on stderr naming `file` when there are any
/// (and the first failure's diagnosis when every run failed).
fn failures(table: &mechkit::scenario::sweep::SweepTable, file: &str) -> usize {
    let failed = table.rows.iter().filter(|r| r.failed()).count();
    if failed == 0 {
        return 0;
    }
    if failed == table.rows.len() {
        let first = table.rows.iter().find(|r| r.failed());
        let diagnosis = first
            .map(|r| {
                let why = r.diagnosis.as_deref().unwrap_or(r.stop_reason.as_str());
                format!(
                    "; the first, run {} ({}), {}: {why}",
                    r.index,
                    params_text(table, r),
                    r.stop_reason
                )
            })
            .unwrap_or_default();
        eprintln!(
            "error: every run failed ({failed} of {}){diagnosis}\n  = hint: see stop_reason in {file}; \
             run one point with `mechkit run` (its constants set in the file) to see it fail",
            table.rows.len()
        );
    } else {
        eprintln!(
            "warning: {failed} of {} runs failed (see stop_reason in {file})",
            table.rows.len()
        );
    }
    failed
}

/// `v0=1, k=2`: a run's parameter values.
fn params_text(
    table: &mechkit::scenario::sweep::SweepTable,
    row: &mechkit::scenario::sweep::SweepRow,
) -> String {
    table
        .params
        .iter()
        .zip(&row.values)
        .map(|(p, v)| format!("{p}={}", super::input::show(*v)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Exit 1 when every run failed (a sweep of nothing but failures answers nothing); else 0,
/// the failed runs being rows with their `stop_reason` and a warning.
fn outcome(table: &mechkit::scenario::sweep::SweepTable) -> Outcome {
    if !table.rows.is_empty()
        && table
            .rows
            .iter()
            .all(mechkit::scenario::sweep::SweepRow::failed)
    {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    }
}

/// A sweep without `-o`: its table on stdout as CSV (or, with `--json`, what was done), a
/// note on stderr, no file.
fn print_table(
    args: &SweepArgs,
    table: &mechkit::scenario::sweep::SweepTable,
    cancel: &Cancel,
    count: usize,
    seconds: f64,
    threads: usize,
) -> Result<Outcome> {
    let rate = table.rows.len() as f64 / seconds.max(1e-9);
    let done = SweepDone {
        scenario: args.file.display().to_string(),
        runs: count,
        rows: table.rows.len(),
        shard: None,
        threads,
        seconds,
        runs_per_second: rate,
        failed: failures(table, "the table"),
        csv: None,
        plot: None,
    };
    super::report(args.report, &done, || table.to_csv())?;
    super::note(
        args.report,
        &format!(
            "{} runs on {threads} thread{} in {seconds:.3} s ({rate:.0} runs/s); no files written (give -o DIR for sweep.csv, its units and manifest, and the plot)",
            table.rows.len(),
            if threads == 1 { "" } else { "s" },
        ),
    );
    if cancel.is_cancelled() {
        return Ok(Outcome::Interrupted);
    }
    Ok(outcome(table))
}

pub fn sweep_merge(args: &SweepMergeArgs) -> Result<Outcome> {
    let mut files: Vec<PathBuf> = Vec::new();
    for p in &args.parts {
        if p.is_dir() {
            let mut found: Vec<PathBuf> = std::fs::read_dir(p)
                .with_context(|| format!("cannot read the directory {}", p.display()))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| {
                    f.extension().is_some_and(|e| e == "csv")
                        && f.file_name()
                            .and_then(|n| n.to_str())
                            .is_some_and(|n| n.starts_with("sweep.part"))
                })
                .collect();
            if found.is_empty() {
                bail!(
                    "{} holds no sweep.partK.csv files\n  = hint: give the directory `mechkit sweep --shard K/N --out DIR` wrote to",
                    p.display()
                );
            }
            found.sort();
            files.extend(found);
        } else {
            files.push(p.clone());
        }
    }
    let out = args.out.clone().unwrap_or_else(|| {
        files[0]
            .parent()
            .unwrap_or_else(|| Path::new("."))
            .join("sweep.csv")
    });
    let out_name = out
        .file_name()
        .map_or_else(|| "sweep.csv".into(), |n| n.to_string_lossy().into_owned());
    let manifest_path = out.with_file_name(manifest_name(&out_name));
    // the merged table and its manifest never replace a part or a part's manifest
    let read: Vec<PathBuf> = files
        .iter()
        .flat_map(|f| [f.clone(), f.with_file_name(manifest_name(&file_name(f)))])
        .collect();
    let inputs: Vec<&Path> = read.iter().map(PathBuf::as_path).collect();
    for target in [&out, &manifest_path] {
        mechkit::csv::refuse_input_as_output(target, &inputs).map_err(|e| {
            anyhow!("-o: {e}\n  = hint: write the merged table beside the parts under another name, e.g. sweep.csv")
        })?;
    }
    let mut parts = Vec::new();
    for f in &files {
        let csv = mechkit::csv::read_bounded_text(f, mechkit::csv::MAX_DATA_BYTES).with_context(
            || format!("cannot read {}\n  = hint: check the file name", f.display()),
        )?;
        let sidecar = f.with_file_name(manifest_name(&file_name(f)));
        let manifest = mechkit::csv::read_bounded_text(&sidecar, mechkit::csv::MAX_DATA_BYTES).with_context(|| {
            format!(
                "cannot read {}, the manifest of {}\n  = hint: keep each part's .manifest.json beside its CSV (mechkit sweep --shard writes both)",
                sidecar.display(),
                f.display()
            )
        })?;
        parts.push(SweepPart {
            name: f.display().to_string(),
            csv,
            manifest,
        });
    }
    let (merged, manifest) = merge_parts(&parts)?;
    write_atomic(&out, merged.as_bytes())
        .with_context(|| format!("cannot write {}", out.display()))?;
    write_atomic(&manifest_path, manifest.as_bytes())
        .with_context(|| format!("cannot write {}", manifest_path.display()))?;
    let units = files[0].with_file_name(mechkit::csv::units_file_name(&file_name(&files[0])));
    if let Ok(text) = mechkit::csv::read_bounded(&units, mechkit::csv::MAX_DATA_BYTES) {
        let target = out.with_file_name(mechkit::csv::units_file_name(&out_name));
        write_atomic(&target, &text)
            .with_context(|| format!("cannot write {}", target.display()))?;
    }
    let rows = merged.lines().count() - 1;
    let done = MergeDone {
        parts: files.iter().map(|f| f.display().to_string()).collect(),
        rows,
        csv: out.display().to_string(),
    };
    super::report(args.report, &done, || {
        format!(
            "merged {} parts, {rows} runs\nwrote {}\n",
            files.len(),
            out.display()
        )
    })?;
    Ok(Outcome::Success)
}

/// What `mechkit sweep --json` prints: the run of the sweep itself (the results are in
/// sweep.csv).
#[derive(serde::Serialize)]
struct SweepDone {
    scenario: String,
    runs: usize,
    rows: usize,
    shard: Option<String>,
    threads: usize,
    seconds: f64,
    runs_per_second: f64,
    failed: usize,
    csv: Option<String>,
    plot: Option<String>,
}

/// What `mechkit sweep-merge --json` prints.
#[derive(serde::Serialize)]
struct MergeDone {
    parts: Vec<String>,
    rows: usize,
    csv: String,
}

/// A path's file name as text (empty for none).
fn file_name(p: &Path) -> String {
    p.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}
