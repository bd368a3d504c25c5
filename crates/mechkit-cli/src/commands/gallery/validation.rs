//! `mechkit gallery --report FILE [--check]`: run every case and put the validation table
//! between the marker lines of FILE (adding them to a file that has neither), keeping the
//! runs' plots beside it; with `--check`, fail if the file is not current.

use std::path::{Component, Path, PathBuf};

use anyhow::{Context as _, Result, anyhow, bail};
use mechkit::scenario::write_atomic;
use serde::Serialize;

use super::{Outputs, run_all};
use crate::args::GalleryArgs;
use crate::commands::gallery_run::Bundle;
use crate::commands::{Outcome, note};
use crate::gallery::report::{self, MarkerError};
use crate::gallery::{Case, CaseRun};

/// What `--report` did, as `--json` prints it.
#[derive(Serialize)]
struct ReportJson<'p> {
    /// The report file.
    file: &'p Path,
    /// Expected values that pass, of `total`.
    passed: usize,
    /// Expected values of every case.
    total: usize,
    /// `written`, or with `--check` `current` (a stale file fails with exit 1).
    status: &'static str,
    /// Whether the marker lines were added (the file had neither, or did not exist).
    markers_added: bool,
}

/// The report file's text with its marker lines, and whether they were added: a file with
/// neither marker (or no file) gets both at its end; a file with one of them only is an
/// error that spells both out.
fn marked_document(path: &Path) -> Result<(String, bool)> {
    let document = match std::fs::read_to_string(path) {
        Ok(text) => text,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => String::new(),
        Err(e) => {
            return Err(e)
                .with_context(|| format!("cannot read the report file {}", path.display()));
        }
    };
    match report::splice(&document, "") {
        Ok(_) => Ok((document, false)),
        Err(MarkerError::Missing) => Ok((report::add_markers(&document), true)),
        Err(e) => bail!(
            "{}: {e}\n  = hint: the table goes between the two lines\n      {}\n      {}\n    (a file with neither gets both added at its end)",
            path.display(),
            report::BEGIN,
            report::END
        ),
    }
}

/// `--report FILE [--check]`: run every case and put the table between the markers of FILE.
pub(super) fn write_report(
    args: &GalleryArgs,
    bundle: &Bundle,
    cases: &[Case],
    files: &[(String, &str)],
    path: &Path,
) -> Result<Outcome> {
    // the markers are checked before the cases run
    if args.check && !path.exists() {
        bail!(
            "cannot read the report file {}: no such file",
            path.display()
        );
    }
    let (document, markers_added) = marked_document(path)?;
    if args.check && markers_added {
        eprintln!(
            "error: {} has no validation table: no lines\n      {}\n      {}\n  = hint: run `mechkit gallery --report {}`, which adds them with the table",
            path.display(),
            report::BEGIN,
            report::END,
            path.display()
        );
        return Ok(Outcome::ComputationFailed);
    }
    let report_dir = absolute(path.parent().unwrap_or(Path::new("")))?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| report_dir.join("gallery"));
    // the cases run in a scratch folder; the report keeps their plots only (--check none)
    let scratch = Outputs::new(None);
    let plots = (!args.no_plots).then_some(args.plots);
    let mut runs = run_all(bundle, cases, files, &scratch.dir, plots);
    if !args.check {
        keep_plots(&runs, &scratch.dir, &out)?;
    }
    drop(scratch);
    let out_link = relative(&report_dir, &absolute(&out)?);
    // the case files are linked where they are: in the checkout the command runs from, or
    // under --root
    let sources = if bundle.is_bundled() {
        std::env::current_dir()?
    } else {
        bundle.root().to_path_buf()
    };
    for run in &mut runs {
        run.plots = run
            .plots
            .iter()
            .map(|p| format!("{out_link}/{}/{p}", run.stem))
            .collect();
        let source = sources.join(&run.file);
        run.file = if source.exists() {
            relative(&report_dir, &source)
        } else {
            String::new()
        };
    }
    let rows = report::checks(cases, &runs);
    let section = report::render(cases, &runs, &rows);
    let updated = report::splice(&document, &section).map_err(|e| anyhow!("{e}"))?;
    let failing = rows.iter().filter(|(c, _)| !c.pass).count();
    if args.check {
        if updated != document {
            let line = document
                .lines()
                .zip(updated.lines())
                .position(|(a, b)| a != b)
                .map_or(document.lines().count().min(updated.lines().count()), |n| n)
                + 1;
            eprintln!(
                "error: {} is stale from line {line} on: the cases compute a different table\n  = hint: run `mechkit gallery --report {}` and commit the result",
                path.display(),
                path.display()
            );
            return Ok(Outcome::ComputationFailed);
        }
    } else {
        write_atomic(path, updated.as_bytes())
            .with_context(|| format!("cannot write {}", path.display()))?;
        if markers_added {
            note(
                args.report,
                &format!(
                    "{} had no gallery marker lines: added them at its end, with the table between them",
                    path.display()
                ),
            );
        }
    }
    let summary = ReportJson {
        file: path,
        passed: rows.len() - failing,
        total: rows.len(),
        status: if args.check { "current" } else { "written" },
        markers_added,
    };
    crate::commands::report(args.report, &summary, || {
        format!(
            "{} of {} expected values pass; {} {}\n",
            summary.passed,
            summary.total,
            path.display(),
            if args.check { "is current" } else { "written" }
        )
    })?;
    Ok(if failing > 0 {
        Outcome::ComputationFailed
    } else {
        Outcome::Success
    })
}

/// Copies the plots of every run from `scratch/<stem>` to `out/<stem>`, emptied first.
fn keep_plots(runs: &[CaseRun], scratch: &Path, out: &Path) -> Result<()> {
    for run in runs {
        let dir = out.join(&run.stem);
        if dir.exists() {
            std::fs::remove_dir_all(&dir)
                .with_context(|| format!("cannot empty {}", dir.display()))?;
        }
    }
    for run in runs {
        for plot in &run.plots {
            let to = out.join(&run.stem).join(plot);
            if let Some(parent) = to.parent() {
                std::fs::create_dir_all(parent)
                    .with_context(|| format!("cannot create {}", parent.display()))?;
            }
            std::fs::copy(scratch.join(&run.stem).join(plot), &to)
                .with_context(|| format!("cannot write {}", to.display()))?;
        }
    }
    Ok(())
}

fn absolute(path: &Path) -> Result<PathBuf> {
    let cwd = std::env::current_dir()?;
    let joined = cwd.join(path);
    let mut out = PathBuf::new();
    for c in joined.components() {
        match c {
            Component::ParentDir => {
                out.pop();
            }
            Component::CurDir => {}
            other => out.push(other),
        }
    }
    Ok(out)
}

/// The path from folder `from` to `to`, with `/` separators (both absolute).
fn relative(from: &Path, to: &Path) -> String {
    let a: Vec<_> = from.components().collect();
    let b: Vec<_> = to.components().collect();
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut parts: Vec<String> = vec!["..".to_string(); a.len() - common];
    parts.extend(
        b[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    if parts.is_empty() {
        ".".into()
    } else {
        parts.join("/")
    }
}
