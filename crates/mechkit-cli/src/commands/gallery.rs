//! `mechkit gallery`: list the bundled cases of the course, run one, or run all into the
//! validation report.
//!
//! The text a run prints is in `gallery/text.rs`; `--report FILE [--check]`, the validation
//! report, in `gallery/validation.rs`.

mod text;
mod validation;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Result, bail};
use rayon::prelude::*;
use serde::Serialize;

use super::Outcome;
use super::gallery_run::{self, Bundle};
use crate::args::{GalleryArgs, PlotFormat};
use crate::gallery::{Case, CaseRun, Check, case_of};
use text::{describe, summary_lines};
use validation::write_report;

/// A case as `--list --json` prints it.
#[derive(Serialize)]
struct Listed<'c> {
    id: &'c str,
    chapter: u32,
    topic: &'c str,
    asked: &'c str,
    /// The files that reproduce it, `<stem>.toml` or `<stem>.sh`.
    files: Vec<String>,
}

/// One file run, as `--json` prints it.
#[derive(Serialize)]
struct RunJson<'r> {
    stem: &'r str,
    file: &'r str,
    checks: &'r [Check],
    /// Its plots, under `--out` (none without it).
    plots: Vec<String>,
    error: Option<&'r str>,
}

/// Where the runs' files go: `--out DIR`, or a scratch folder removed on drop.
struct Outputs {
    dir: PathBuf,
    kept: bool,
}

impl Outputs {
    fn new(out: Option<&Path>) -> Self {
        match out {
            Some(dir) => Self {
                dir: dir.to_path_buf(),
                kept: true,
            },
            None => Self {
                dir: scratch("mechkit-gallery-run"),
                kept: false,
            },
        }
    }
}

impl Drop for Outputs {
    fn drop(&mut self) {
        if !self.kept {
            let _ = std::fs::remove_dir_all(&self.dir);
        }
    }
}

/// A new folder name under the temporary directory.
fn scratch(prefix: &str) -> PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    std::env::temp_dir().join(format!("{prefix}-{}-{nanos}", std::process::id()))
}

pub fn gallery(args: &GalleryArgs) -> Result<Outcome> {
    let bundle = match &args.root {
        Some(root) => Bundle::at(root)?,
        None => Bundle::extract()?,
    };
    let cases = bundle.cases()?;
    let files = bundle.files()?;
    if let Some(report) = &args.report_file {
        return write_report(args, &bundle, &cases, &files, report);
    }
    let chosen: Vec<(String, &str)> = match (&args.case, args.all) {
        (Some(id), _) => {
            let case = find_case(&cases, id)?;
            let chosen: Vec<_> = files
                .iter()
                .filter(|(stem, _)| case.expected_of(stem).is_some())
                .cloned()
                .collect();
            if chosen.is_empty() {
                bail!("case `{}` has no scenario or script in the bundle", case.id);
            }
            chosen
        }
        (None, true) => files.clone(),
        (None, false) => return list(args, &cases, &files),
    };
    // without --out the cases run in a scratch folder, and no plots are drawn for nothing
    let outputs = Outputs::new(args.out.as_deref());
    let plots = (outputs.kept && !args.no_plots).then_some(args.plots);
    let runs = run_all(&bundle, &cases, &chosen, &outputs.dir, plots);
    let failed = runs
        .iter()
        .any(|r| r.error.is_some() || r.checks.iter().any(|c| !c.pass));
    let kept = args.out.as_deref();
    let json: Vec<RunJson> = runs.iter().map(|r| run_json(r, kept)).collect();
    super::report(args.report, &json, || {
        if args.case.is_some() {
            describe(&cases, &runs, kept)
        } else {
            summary_lines(&runs, kept)
        }
    })?;
    Ok(if failed {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    })
}

/// The case named by `id`: its exact id, or the one case whose id starts with it.
fn find_case<'c>(cases: &'c [Case], id: &str) -> Result<&'c Case> {
    if let Some(c) = cases
        .iter()
        .find(|c| c.id == id || c.stems().contains(&id.into()))
    {
        return Ok(c);
    }
    let starts: Vec<&Case> = cases.iter().filter(|c| c.id.starts_with(id)).collect();
    match starts.as_slice() {
        [one] => Ok(one),
        [] => bail!("no case `{id}`\n  = hint: `mechkit gallery --list` lists them"),
        many => {
            let ids: Vec<&str> = many.iter().take(6).map(|c| c.id.as_str()).collect();
            let more = if many.len() > ids.len() { ", …" } else { "" };
            bail!(
                "`{id}` names {} cases: {}{more}\n  = hint: give more of the id (`mechkit gallery --list` lists them)",
                many.len(),
                ids.join(", ")
            )
        }
    }
}

fn list(args: &GalleryArgs, cases: &[Case], files: &[(String, &str)]) -> Result<Outcome> {
    let files_of = |case: &Case| -> Vec<String> {
        files
            .iter()
            .filter(|(stem, _)| case.expected_of(stem).is_some())
            .map(|(stem, ext)| format!("{stem}.{ext}"))
            .collect()
    };
    let listed: Vec<Listed> = cases
        .iter()
        .map(|c| Listed {
            id: &c.id,
            chapter: c.chapter,
            topic: &c.topic,
            asked: &c.asked,
            files: files_of(c),
        })
        .collect();
    super::report(args.report, &listed, || {
        let width = cases.iter().map(|c| c.id.len()).max().unwrap_or(0);
        let mut text = String::new();
        for c in &listed {
            let kinds: Vec<&str> = c
                .files
                .iter()
                .map(|f| f.rsplit('.').next().unwrap_or(""))
                .collect();
            let _ = writeln!(text, "{:<width$}  {:<9} {}", c.id, kinds.join("+"), c.topic);
        }
        let _ = writeln!(
            text,
            "\n{} cases; `mechkit gallery ID` runs one, `--all` runs them all",
            cases.len()
        );
        text
    })?;
    Ok(Outcome::Success)
}

/// Runs the chosen files (in parallel), each into `out/<stem>`, drawing the scenarios' plots
/// in `plots` (none for `None`).
fn run_all(
    bundle: &Bundle,
    cases: &[Case],
    chosen: &[(String, &str)],
    out: &Path,
    plots: Option<PlotFormat>,
) -> Vec<CaseRun> {
    // the files of one stem (a scenario and a script) share its folder: they run in turn
    let mut stems: Vec<(&str, Vec<&str>)> = Vec::new();
    for (stem, ext) in chosen {
        match stems.iter_mut().find(|(s, _)| s == stem) {
            Some((_, exts)) => exts.push(ext),
            None => stems.push((stem, vec![ext])),
        }
    }
    let runs: Vec<Vec<CaseRun>> = stems
        .par_iter()
        .map(|(stem, exts)| match case_of(cases, stem) {
            Some(case) => gallery_run::run_stem(bundle, case, stem, exts, &out.join(stem), plots),
            None => exts
                .iter()
                .map(|ext| CaseRun {
                    error: Some("no case of this name in cases.jsonl".into()),
                    ..gallery_run::not_run(stem, ext)
                })
                .collect(),
        })
        .collect();
    runs.into_iter().flatten().collect()
}

/// A run as `--json` prints it: its plots as paths under `--out` (none without it).
fn run_json<'r>(r: &'r CaseRun, out: Option<&Path>) -> RunJson<'r> {
    RunJson {
        stem: &r.stem,
        file: &r.file,
        checks: &r.checks,
        plots: out.map_or_else(Vec::new, |out| {
            r.plots
                .iter()
                .map(|p| out.join(&r.stem).join(p).display().to_string())
                .collect()
        }),
        error: r.error.as_deref(),
    }
}
