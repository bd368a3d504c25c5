//! Running one file of the bundled gallery: a scenario through the library, a script's calls
//! through this same binary. The bundle (`examples/book` and the files its cases read) is
//! compiled in by `build.rs` and written to a scratch folder for the run.

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context as _, Result, anyhow, bail};
use mechkit::scenario::Scenario;
use serde_json::Value;

use crate::gallery::{Case, CaseRun, Check, Script};
use crate::plot::{self, PlotFormat};

mod bundle {
    include!(concat!(env!("OUT_DIR"), "/gallery_bundle.rs"));
}

/// Where the book's cases live in the bundle (and in the repository).
pub const BOOK: &str = "examples/book";

/// The case files a gallery runs: the bundled ones, extracted to a scratch folder that is
/// removed on drop, or a folder of the user's (`--root`).
pub struct Bundle {
    root: PathBuf,
    scratch: bool,
}

impl Bundle {
    /// Writes every bundled file under a new scratch folder.
    pub fn extract() -> Result<Bundle> {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        let root =
            std::env::temp_dir().join(format!("mechkit-gallery-{}-{nanos}", std::process::id()));
        let bundle = Bundle {
            root,
            scratch: true,
        };
        for (name, bytes) in bundle::FILES {
            let path = bundle.root.join(name);
            if let Some(parent) = path.parent() {
                std::fs::create_dir_all(parent)
                    .with_context(|| format!("cannot create {}", parent.display()))?;
            }
            std::fs::write(&path, bytes)
                .with_context(|| format!("cannot write {}", path.display()))?;
        }
        Ok(bundle)
    }

    /// The case files under `root/examples/book` (a checkout, or a copy with edited cases).
    pub fn at(root: &Path) -> Result<Bundle> {
        let book = root.join(BOOK);
        if !book.join("cases.jsonl").is_file() {
            bail!(
                "--root {}: no {BOOK}/cases.jsonl there\n  = hint: give the folder that holds examples/ (a mechkit checkout)",
                root.display()
            );
        }
        let root = root
            .canonicalize()
            .with_context(|| format!("cannot read {}", root.display()))?;
        Ok(Bundle {
            root,
            scratch: false,
        })
    }

    /// The folder that holds `examples/`.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// Whether these are the bundled files (not a folder of the user's).
    pub fn is_bundled(&self) -> bool {
        self.scratch
    }

    /// The cases of `examples/book/cases.jsonl`.
    pub fn cases(&self) -> Result<Vec<Case>> {
        let path = self.root.join(BOOK).join("cases.jsonl");
        let text = std::fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", path.display()))?;
        Case::parse_all(&text).map_err(|e| anyhow!("{}: {e}", path.display()))
    }

    /// The case files: (stem, extension) of every `.toml` and `.sh` in `examples/book`,
    /// sorted.
    pub fn files(&self) -> Result<Vec<(String, &'static str)>> {
        let dir = self.root.join(BOOK);
        let mut files = Vec::new();
        for entry in
            std::fs::read_dir(&dir).with_context(|| format!("cannot read {}", dir.display()))?
        {
            let name = entry?.file_name().to_string_lossy().into_owned();
            for ext in ["toml", "sh"] {
                if let Some(stem) = name.strip_suffix(ext).and_then(|s| s.strip_suffix('.')) {
                    files.push((stem.to_string(), ext));
                }
            }
        }
        files.sort();
        Ok(files)
    }
}

impl Drop for Bundle {
    fn drop(&mut self) {
        if self.scratch {
            let _ = std::fs::remove_dir_all(&self.root);
        }
    }
}

/// The run of `examples/book/<stem>.<ext>` before it runs: nothing computed, no error.
pub fn not_run(stem: &str, ext: &str) -> CaseRun {
    CaseRun {
        stem: stem.to_string(),
        file: format!("{BOOK}/{stem}.{ext}"),
        checks: Vec::new(),
        plots: Vec::new(),
        error: None,
    }
}

/// Runs the files of one stem (`examples/book/<stem>.toml` and/or `.sh`) of `case`, writing
/// their outputs into `dir` (emptied first), a scenario's plots in `plots` (none for `None`).
/// The plot files written (SVG and PNG) are the first run's `plots`, as paths under `dir`.
pub fn run_stem(
    bundle: &Bundle,
    case: &Case,
    stem: &str,
    exts: &[&str],
    dir: &Path,
    plots: Option<PlotFormat>,
) -> Vec<CaseRun> {
    let mut runs: Vec<CaseRun> = exts.iter().map(|ext| not_run(stem, ext)).collect();
    if dir.exists()
        && let Err(e) = std::fs::remove_dir_all(dir)
    {
        for run in &mut runs {
            run.error = Some(format!("cannot empty {}: {e}", dir.display()));
        }
        return runs;
    }
    for (run, ext) in runs.iter_mut().zip(exts) {
        let path = bundle.root().join(&run.file);
        let result = match *ext {
            "toml" => run_scenario(&path, case, stem, dir, plots, &mut run.checks),
            _ => run_script(bundle, &path, case, stem, dir, &mut run.checks),
        };
        if let Err(e) = result {
            run.error = Some(format!("{e:#}"));
        }
    }
    let mut pictures = Vec::new();
    collect_plots(dir, &mut pictures);
    pictures.sort();
    if let Some(first) = runs.first_mut() {
        first.plots = pictures
            .iter()
            .filter_map(|p| p.strip_prefix(dir).ok())
            .map(|p| p.to_string_lossy().replace('\\', "/"))
            .collect();
    }
    runs
}

fn run_scenario(
    path: &Path,
    case: &Case,
    stem: &str,
    dir: &Path,
    plots: Option<PlotFormat>,
    checks: &mut Vec<Check>,
) -> Result<()> {
    let scenario = Scenario::load(path)?;
    let mut out = scenario.run_to_dir(dir)?;
    if let Some(format) = plots {
        plot::render_run(&scenario, &mut out, dir, format)?;
    }
    for (key, _) in case.expected_of(stem).unwrap_or_default() {
        if let Some(&v) = out.summary.observables.get(&key) {
            checks.push(Check::new(case, stem, &key, &serde_json::Value::from(v)));
        }
    }
    if out.failed() {
        let why = out
            .summary
            .divergence
            .as_ref()
            .map_or_else(|| out.summary.stop_reason.clone(), |d| d.message.clone());
        return Err(anyhow!("the run failed: {why}"));
    }
    Ok(())
}

fn run_script(
    bundle: &Bundle,
    path: &Path,
    case: &Case,
    stem: &str,
    dir: &Path,
    checks: &mut Vec<Check>,
) -> Result<()> {
    let text = std::fs::read_to_string(path)?;
    let script = Script::parse(&text).map_err(|e| anyhow!("{stem}.sh: {e}"))?;
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    // the program that runs `mechkit ARGS`: this one, or what an embedding front names (the
    // Python package's console script runs the command line inside the interpreter)
    let exe = match std::env::var_os("MECHKIT_EXE") {
        Some(exe) => std::path::PathBuf::from(exe),
        None => std::env::current_exe().context("cannot find the mechkit binary")?,
    };
    for step in &script.steps {
        let args: Vec<String> = step.args.iter().map(|w| local_path(bundle, w)).collect();
        let output = Command::new(&exe)
            .args(&args)
            .current_dir(dir)
            .output()
            .with_context(|| format!("cannot run {}", exe.display()))?;
        let call = format!("{stem}.sh:{}: `mechkit {}`", step.line, step.args.join(" "));
        if !output.status.success() {
            let stderr = String::from_utf8_lossy(&output.stderr);
            return Err(anyhow!(
                "{call} failed ({}): {}",
                output.status,
                stderr.lines().next().unwrap_or("")
            ));
        }
        let json: Value = serde_json::from_slice(&output.stdout)
            .map_err(|e| anyhow!("{call} printed no JSON ({e}); add --json"))?;
        for b in &step.bindings {
            let got = b.value(&json).cloned().unwrap_or(Value::Null);
            let mut check = Check::new(case, stem, &b.key, &got);
            if got.is_null() {
                check.note = format!("line {}: no `{}` in the output", b.line, b.pointer);
            }
            checks.push(check);
        }
    }
    Ok(())
}

/// A script's word as the gallery runs it: files under `examples/` are the bundle's, and
/// outputs under `out/` land in the case's folder (`out/book/x.svg` → `x.svg`).
fn local_path(bundle: &Bundle, word: &str) -> String {
    if word.starts_with("examples/") {
        bundle.root().join(word).display().to_string()
    } else if let Some(rest) = word.strip_prefix("out/") {
        let rest = rest.strip_prefix("book/").unwrap_or(rest);
        rest.to_string()
    } else {
        word.to_string()
    }
}

/// The plot files (SVG and PNG) under `dir`, at any depth.
fn collect_plots(dir: &Path, into: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            collect_plots(&path, into);
        } else if path.extension().is_some_and(|e| e == "svg" || e == "png") {
            into.push(path);
        }
    }
}
