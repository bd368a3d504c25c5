//! `mechkit gallery`: list the bundled cases of the course, run one, or run all into the
//! validation report.

use std::fmt::Write as _;
use std::path::{Component, Path, PathBuf};

use anyhow::{Context as _, Result, anyhow, bail};
use mechkit::scenario::write_atomic;
use rayon::prelude::*;
use serde::Serialize;

use super::gallery_run::{self, Bundle};
use super::{Outcome, note};
use crate::args::{GalleryArgs, PlotFormat};
use crate::gallery::report::{self, MarkerError};
use crate::gallery::{Case, CaseRun, Check, case_of};

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

/// One case in full: the question, each value against the book's, the outputs kept.
fn describe(cases: &[Case], runs: &[CaseRun], out: Option<&Path>) -> String {
    let mut text = String::new();
    for run in runs {
        let case = case_of(cases, &run.stem);
        if let Some(case) = case {
            let _ = writeln!(
                text,
                "{}: {} (chapter {})",
                run.stem, case.topic, case.chapter
            );
            let _ = writeln!(text, "  asked: {}", case.asked);
        }
        let _ = writeln!(text, "  file:  {}", run.file);
        let _ = writeln!(
            text,
            "  {:<12} {:>14} {:>14} {:>9}  result",
            "value", "expected", "computed", "error"
        );
        for c in &run.checks {
            let error = c.error.map_or(String::new(), |e| format!("{e:.1e}"));
            let result = match (c.pass, c.note.is_empty()) {
                (true, _) => "pass".to_string(),
                (false, true) => "FAIL".to_string(),
                (false, false) => format!("FAIL: {}", c.note),
            };
            let _ = writeln!(
                text,
                "  {:<12} {:>14} {:>14} {error:>9}  {result}",
                c.key,
                report::value(&c.expected).trim_matches('`'),
                report::value(&c.computed).trim_matches('`'),
            );
        }
        if let Some(e) = &run.error {
            let _ = writeln!(text, "  error: {e}");
        }
        if let Some(out) = out {
            let dir = out.join(&run.stem);
            let _ = writeln!(text, "  outputs: {}", dir.display());
            for p in &run.plots {
                let _ = writeln!(text, "  plot: {}", dir.join(p).display());
            }
        }
    }
    text
}

fn summary_lines(runs: &[CaseRun], out: Option<&Path>) -> String {
    let mut text = String::new();
    let (mut passed, mut total) = (0, 0);
    for r in runs {
        let ok = r.checks.iter().filter(|c| c.pass).count();
        passed += ok;
        total += r.checks.len();
        let verdict = if r.error.is_none() && ok == r.checks.len() {
            "pass"
        } else {
            "FAIL"
        };
        let _ = writeln!(
            text,
            "{verdict}  {:<48} {ok}/{}{}",
            r.stem,
            r.checks.len(),
            r.error.as_ref().map_or(String::new(), |e| format!("  {e}"))
        );
    }
    let _ = writeln!(
        text,
        "\n{passed} of {total} values pass in {} files{}",
        runs.len(),
        out.map_or(String::new(), |o| format!("; outputs in {}", o.display()))
    );
    text
}

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
fn write_report(
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
    super::report(args.report, &summary, || {
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
