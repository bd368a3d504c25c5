//! The course's worked problems (`examples/book/cases.jsonl`, a copy of
//! `shared/book_cases.jsonl`) reproduced through scenario files: every `examples/book/*.toml`
//! is run, and each of its `[observe]` values named like an expected key is compared with the
//! expected value within the case's tolerance. Keys with no observable are listed (the gallery
//! issue turns them into failures).

use std::collections::BTreeMap;

use mechkit::scenario::Scenario;
use serde_json::Value;

use crate::util::workspace;

mod cases;
use cases::tolerance;

fn cases() -> BTreeMap<String, Value> {
    cases::cases(&workspace().join("examples/book/cases.jsonl"))
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
        let (case, expected) = cases::case_of(&cases, &stem);
        let summary = Scenario::load(&path).unwrap().run().unwrap().summary;
        let pairs: Vec<(String, Value)> = match &expected {
            Value::Object(map) => map.iter().map(|(k, v)| (k.clone(), v.clone())).collect(),
            other => vec![("answer".to_string(), other.clone())],
        };
        for (key, want) in pairs {
            let Some(&got) = summary.observables.get(&key) else {
                println!("{stem}: `{key}` not covered");
                continue;
            };
            let want = match want {
                Value::Bool(b) => f64::from(u8::from(b)),
                Value::Number(n) => n.as_f64().unwrap(),
                other => {
                    println!("{stem}: `{key}` = {other} is not a number");
                    continue;
                }
            };
            let tol = tolerance(&case["tolerance"], &key, want);
            checked += 1;
            let ok = (got - want).abs() <= tol;
            println!(
                "{stem}: {key} expected {want} got {got} (tolerance {tol:e}) {}",
                if ok { "ok" } else { "FAIL" }
            );
            if !ok {
                failures.push(format!(
                    "{stem}: {key} expected {want} ± {tol:e}, got {got}"
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
    assert!(checked >= 25, "only {checked} values were checked");
}
