//! Replays the fuzz targets' seeds and every input that once made a target fail
//! (`fuzz/regressions/TARGET/`), without libFuzzer, so a regression fails the ordinary test
//! suite. A target that panics fails the test with the input's file name.

use std::fs;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Files under `dir` (recursively) whose name ends with one of `endings` (all if empty).
fn files(dir: &Path, endings: &[&str]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let Ok(entries) = fs::read_dir(dir) else {
        return out;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            out.extend(files(&path, endings));
        } else if endings.is_empty() || endings.iter().any(|e| path.to_string_lossy().ends_with(e))
        {
            out.push(path);
        }
    }
    out.sort();
    out
}

/// Lines of a seed list, each one input.
fn lines(path: &Path) -> Vec<(String, Vec<u8>)> {
    let text = fs::read_to_string(path).expect("the seed list is readable");
    text.lines()
        .enumerate()
        .map(|(i, l)| {
            (
                format!("{}:{}", path.display(), i + 1),
                l.as_bytes().to_vec(),
            )
        })
        .collect()
}

fn replay(target: &str, inputs: &[(String, Vec<u8>)], at_least: usize) {
    let (_, run) = mechkit_fuzz::TARGETS
        .iter()
        .find(|(name, _)| *name == target)
        .expect("a known target");
    assert!(
        inputs.len() >= at_least,
        "{target}: {} inputs, expected at least {at_least}",
        inputs.len()
    );
    let mut failed = Vec::new();
    for (name, bytes) in inputs {
        if catch_unwind(AssertUnwindSafe(|| run(bytes))).is_err() {
            failed.push(name.clone());
        }
    }
    assert!(failed.is_empty(), "{target} panicked on: {failed:#?}");
}

fn read_all(paths: Vec<PathBuf>) -> Vec<(String, Vec<u8>)> {
    paths
        .into_iter()
        .map(|p| {
            let bytes = fs::read(&p).expect("a readable input");
            (p.display().to_string(), bytes)
        })
        .collect()
}

fn regressions(target: &str) -> Vec<(String, Vec<u8>)> {
    read_all(files(&repo().join("fuzz/regressions").join(target), &[]))
}

/// The formulas both the `expression` and the `calculus` targets read: the seed list and
/// both targets' findings.
fn formulas() -> Vec<(String, Vec<u8>)> {
    let mut inputs = lines(&repo().join("fuzz/seeds/expression.txt"));
    inputs.extend(regressions("expression"));
    inputs.extend(regressions("calculus"));
    inputs
}

#[test]
fn expression_seeds_and_regressions() {
    replay("expression", &formulas(), 20);
}

#[test]
fn calculus_seeds_and_regressions() {
    replay("calculus", &formulas(), 20);
}

#[test]
fn units_seeds_and_regressions() {
    let mut inputs = lines(&repo().join("fuzz/seeds/units.txt"));
    inputs.extend(regressions("units"));
    replay("units", &inputs, 20);
}

#[test]
fn scenario_examples_and_regressions() {
    let mut inputs = read_all(files(&repo().join("examples"), &[".toml"]));
    inputs.extend(regressions("scenario"));
    replay("scenario", &inputs, 30);
}

#[test]
fn data_file_examples_and_regressions() {
    let mut inputs = read_all(files(&repo().join("examples"), &[".csv", ".txt", ".d"]));
    inputs.extend(read_all(files(&repo().join("fuzz/seeds/data_file"), &[])));
    inputs.extend(regressions("data_file"));
    replay("data_file", &inputs, 8);
}

#[test]
fn image_seeds_and_regressions() {
    let mut inputs = read_all(files(&repo().join("fuzz/seeds/image"), &[]));
    inputs.extend(read_all(files(&repo().join("examples/data"), &[".png"])));
    inputs.extend(regressions("image"));
    replay("image", &inputs, 8);
}

#[test]
fn options_seeds_and_regressions() {
    let mut inputs = lines(&repo().join("fuzz/seeds/options.txt"));
    inputs.extend(regressions("options"));
    replay("options", &inputs, 20);
}

#[test]
fn browser_seeds_and_regressions() {
    let mut inputs = read_all(files(&repo().join("fuzz/seeds/browser"), &[]));
    inputs.extend(regressions("browser"));
    replay("browser", &inputs, 20);
}

#[test]
fn python_front_seeds_and_regressions() {
    let mut inputs = read_all(files(&repo().join("fuzz/seeds/python_front"), &[]));
    inputs.extend(regressions("python_front"));
    replay("python_front", &inputs, 10);
}
