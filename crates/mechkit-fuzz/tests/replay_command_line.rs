//! Replays the `command_line` target's seeds (the command lines of the documentation and the
//! gallery) and its saved findings (`fuzz/regressions/command_line/`). Apart from
//! `replay.rs` because the target makes its working directory the process's current one.

use std::fs;
use std::path::{Path, PathBuf};

fn inputs(dir: &Path) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = fs::read_dir(dir)
        .map(|d| d.flatten().map(|e| e.path()).collect())
        .unwrap_or_default();
    out.retain(|p| p.is_file() && p.extension().is_none_or(|e| e != "py"));
    out.sort();
    out
}

#[test]
fn command_line_seeds_and_regressions() {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut paths = inputs(&repo.join("fuzz/seeds/command_line"));
    assert!(paths.len() >= 100, "{} seeds", paths.len());
    paths.extend(inputs(&repo.join("fuzz/regressions/command_line")));
    let mut failed = Vec::new();
    let mut ran = 0;
    for path in &paths {
        let bytes = fs::read(path).expect("a readable input");
        let result = std::panic::catch_unwind(|| mechkit_fuzz::command_line(&bytes));
        if result.is_err() {
            failed.push(path.display().to_string());
        }
        if mechkit_fuzz::command_line::CommandLine::from_bytes(&bytes).is_some() {
            ran += 1;
        }
    }
    assert!(failed.is_empty(), "command_line panicked on: {failed:#?}");
    // the seeds are command lines the target runs, not ones it skips
    assert!(
        ran * 10 >= paths.len() * 9,
        "{ran} of {} inputs ran",
        paths.len()
    );
}

/// Found by the target (2026-12-05, after 541 k inputs): a heavy top at 5,020 rad/s for 51 s
/// took 24 million steps (15 s), inside the product's bounds but past the target's 10 s: the
/// target now skips a `spin` that turns through more than 1,000 rad, and still runs a slower
/// one.
#[test]
fn a_spin_of_many_turns_is_skipped_and_a_slow_one_runs() {
    use mechkit_fuzz::command_line::CommandLine;
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let fast =
        fs::read(repo.join("fuzz/regressions/command_line/spin-top-5020-rad-per-s")).unwrap();
    assert!(CommandLine::from_bytes(&fast).is_none());
    let text = String::from_utf8(fast).unwrap();
    for (omega, runs) in [
        ("0, 0, 5", true),
        ("0, 0, 50 rpm", true),
        ("0, 0, 3 kHz", false),
    ] {
        let bytes = text.replace("0, 0, 5020", omega).into_bytes();
        assert_eq!(CommandLine::from_bytes(&bytes).is_some(), runs, "{omega}");
    }
}

/// Found by the target (2026-12-06, after 798 k inputs): a stick-slip block of 19 kg on a
/// spring of 3.2e19 N/m for 8 s used the whole step budget (10⁶ steps: 2 s in a release build,
/// then the budget's error; 10.7 s in the fuzz build), inside the product's bounds but past
/// the target's 10 s: the target now skips a `friction` run whose spring turns through more
/// than 10⁴ rad, and still runs a slower one.
#[test]
fn a_stiff_spring_of_many_oscillations_is_skipped_and_a_slower_one_runs() {
    use mechkit_fuzz::command_line::CommandLine;
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let stiff =
        fs::read(repo.join("fuzz/regressions/command_line/friction-stiff-spring-step-budget"))
            .unwrap();
    assert!(CommandLine::from_bytes(&stiff).is_none());
    let text = String::from_utf8(stiff).unwrap();
    for (k, runs) in [("100 N/m", true), ("1 MN/m", true), ("1 GN/m", false)] {
        let bytes = text.replace("032EN/m", k).into_bytes();
        assert_eq!(CommandLine::from_bytes(&bytes).is_some(), runs, "{k}");
    }
}
