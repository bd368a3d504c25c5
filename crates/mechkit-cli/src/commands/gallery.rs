//! `mechkit gallery`: list the bundled cases of the course, run one, or run all into the
//! validation report.

use std::fmt::Write as _;
use std::path::{Component, Path, PathBuf};

use anyhow::{Context as _, Result, anyhow, bail};
use mechkit::gallery::{Case, CaseRun, report};
use mechkit::scenario::write_atomic;
use rayon::prelude::*;
use serde_json::{Value, json};

use super::gallery_run::{self, Bundle};
use super::{Outcome, print};
use crate::args::GalleryArgs;

pub fn gallery(args: &GalleryArgs) -> Result<Outcome> {
    let bundle = match &args.root {
        Some(root) => Bundle::at(root)?,
        None => Bundle::extract()?,
    };
    let cases = bundle.cases()?;
    let files = bundle.files()?;
    if let Some(report) = &args.report {
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
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out/gallery"));
    let runs = run_all(&bundle, &cases, &chosen, &out, !args.no_plots);
    let failed = runs
        .iter()
        .any(|r| r.error.is_some() || r.checks.iter().any(|c| !c.pass));
    if args.json {
        print(&format!("{:#}\n", runs_json(&runs, &out)))?;
    } else if args.case.is_some() {
        print(&describe(&cases, &runs, &out))?;
    } else {
        print(&summary_lines(&runs, &out))?;
    }
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
    if args.json {
        let list: Vec<Value> = cases
            .iter()
            .map(|c| {
                json!({"id": c.id, "chapter": c.chapter, "topic": c.topic, "asked": c.asked,
                       "files": files_of(c)})
            })
            .collect();
        print(&format!("{:#}\n", Value::Array(list)))?;
        return Ok(Outcome::Success);
    }
    let width = cases.iter().map(|c| c.id.len()).max().unwrap_or(0);
    let mut text = String::new();
    for c in cases {
        let kinds: Vec<String> = files_of(c)
            .iter()
            .map(|f| f.rsplit('.').next().unwrap_or("").to_string())
            .collect();
        let _ = writeln!(text, "{:<width$}  {:<9} {}", c.id, kinds.join("+"), c.topic);
    }
    let _ = writeln!(
        text,
        "\n{} cases; `mechkit gallery ID` runs one, `--all` runs them all",
        cases.len()
    );
    print(&text)?;
    Ok(Outcome::Success)
}

/// Runs the chosen files (in parallel), each into `out/<stem>`.
fn run_all(
    bundle: &Bundle,
    cases: &[Case],
    chosen: &[(String, &str)],
    out: &Path,
    plots: bool,
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
        .map(
            |(stem, exts)| match mechkit::gallery::case_of(cases, stem) {
                Some(case) => {
                    gallery_run::run_stem(bundle, case, stem, exts, &out.join(stem), plots)
                }
                None => exts
                    .iter()
                    .map(|ext| CaseRun {
                        error: Some("no case of this name in cases.jsonl".into()),
                        ..gallery_run::not_run(stem, ext)
                    })
                    .collect(),
            },
        )
        .collect();
    runs.into_iter().flatten().collect()
}

fn runs_json(runs: &[CaseRun], out: &Path) -> Value {
    let runs: Vec<Value> = runs
        .iter()
        .map(|r| {
            let checks: Vec<Value> = r
                .checks
                .iter()
                .map(|c| {
                    json!({"key": c.key, "expected": c.expected, "computed": c.computed,
                           "tolerance": c.tolerance, "error": c.error, "pass": c.pass,
                           "note": c.note})
                })
                .collect();
            let plots: Vec<String> = r
                .plots
                .iter()
                .map(|p| out.join(&r.stem).join(p).display().to_string())
                .collect();
            json!({"stem": r.stem, "file": r.file, "checks": checks, "plots": plots,
                   "error": r.error})
        })
        .collect();
    Value::Array(runs)
}

/// One case in full: the question, each value against the book's, the outputs.
fn describe(cases: &[Case], runs: &[CaseRun], out: &Path) -> String {
    let mut text = String::new();
    for run in runs {
        let case = mechkit::gallery::case_of(cases, &run.stem);
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
        let dir = out.join(&run.stem);
        let _ = writeln!(text, "  outputs: {}", dir.display());
        for p in &run.plots {
            let _ = writeln!(text, "  plot: {}", dir.join(p).display());
        }
    }
    text
}

fn summary_lines(runs: &[CaseRun], out: &Path) -> String {
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
        "\n{passed} of {total} values pass in {} files; outputs in {}",
        runs.len(),
        out.display()
    );
    text
}

/// `--report FILE [--check]`: run every case and put the table between the markers of FILE.
fn write_report(
    args: &GalleryArgs,
    bundle: &Bundle,
    cases: &[Case],
    files: &[(String, &str)],
    path: &Path,
) -> Result<Outcome> {
    let document = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read the report file {}", path.display()))?;
    // the markers are checked before the cases run
    let unmarked = |e: String| {
        anyhow!(
            "{}: {e}\n  = hint: put the two lines\n      {}\n      {}\n    where the table should go",
            path.display(),
            report::BEGIN,
            report::END
        )
    };
    report::splice(&document, "").map_err(unmarked)?;
    let report_dir = absolute(path.parent().unwrap_or(Path::new("")))?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| report_dir.join("gallery"));
    // the cases run in a scratch folder; the report keeps their plots only (--check none)
    let scratch =
        std::env::temp_dir().join(format!("mechkit-gallery-report-{}", std::process::id()));
    let mut runs = run_all(bundle, cases, files, &scratch, !args.no_plots);
    let kept = if args.check {
        Ok(())
    } else {
        keep_plots(&runs, &scratch, &out)
    };
    let _ = std::fs::remove_dir_all(&scratch);
    kept?;
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
    let updated = report::splice(&document, &section).map_err(unmarked)?;
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
    }
    print(&format!(
        "{} of {} expected values pass; {} {}\n",
        rows.len() - failing,
        rows.len(),
        path.display(),
        if args.check { "is current" } else { "written" }
    ))?;
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
