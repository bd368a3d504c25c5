//! The course's worked problems (`examples/book/cases.jsonl`, a copy of
//! `shared/book_cases.jsonl`) reproduced through scenario files: every `examples/book/*.toml`
//! is run, and each of its `[observe]` values named like an expected key is compared with the
//! expected value within the case's tolerance ([`Check`]). A value no file computes fails
//! the CLI test `gallery::the_validation_report_is_current`.

use std::path::PathBuf;

use mechkit::scenario::Scenario;

use super::{Case, Check, case_of};

/// The workspace root.
fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn cases() -> Vec<Case> {
    let text = std::fs::read_to_string(workspace().join("examples/book/cases.jsonl")).unwrap();
    Case::parse_all(&text).unwrap()
}

#[test]
fn the_copy_of_the_cases_is_current() {
    let shared = workspace().join("../shared/book_cases.jsonl");
    if let Ok(original) = std::fs::read_to_string(&shared) {
        let copy = std::fs::read_to_string(workspace().join("examples/book/cases.jsonl")).unwrap();
        assert_eq!(
            copy, original,
            "examples/book/cases.jsonl differs from shared/book_cases.jsonl"
        );
    }
}

#[test]
fn book_cases_reproduce_the_expected_answers() {
    let cases = cases();
    let mut failures = Vec::new();
    let mut checked = 0;
    let mut dir: Vec<_> = std::fs::read_dir(workspace().join("examples/book"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    dir.sort();
    assert!(!dir.is_empty());
    for path in dir {
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        let case = case_of(&cases, &stem).unwrap_or_else(|| panic!("{stem}: no such case"));
        let summary = Scenario::load(&path).unwrap().run().unwrap().summary;
        for (key, _) in case.expected_of(&stem).unwrap() {
            let Some(&got) = summary.observables.get(&key) else {
                println!("{stem}: `{key}` not observed here");
                continue;
            };
            let check = Check::new(case, &stem, &key, &serde_json::Value::from(got));
            checked += 1;
            println!(
                "{stem}: {key} expected {} got {got} (tolerance {:?}) {}",
                check.expected,
                check.tolerance,
                if check.pass { "ok" } else { "FAIL" }
            );
            if !check.pass {
                failures.push(format!(
                    "{stem}: {key} expected {} ± {:?}, got {got}",
                    check.expected, check.tolerance
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(checked >= 25, "only {checked} values were checked");
}
