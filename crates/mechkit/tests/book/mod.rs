//! The course's worked problems (`examples/book/cases.jsonl`, a copy of
//! `shared/book_cases.jsonl`) reproduced through scenario files: every `examples/book/*.toml`
//! is run, and each of its `[observe]` values named like an expected key is compared with the
//! expected value within the case's tolerance. Keys with no observable are listed (the gallery
//! issue turns them into failures).

use std::collections::BTreeMap;

use mechkit::scenario::Scenario;
use serde_json::Value;

use crate::util::workspace;

fn cases() -> BTreeMap<String, Value> {
    let text = std::fs::read_to_string(workspace().join("examples/book/cases.jsonl")).unwrap();
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let v: Value = serde_json::from_str(l).unwrap();
            (v["id"].as_str().unwrap().to_string(), v)
        })
        .collect()
}

/// The tolerance for expected key `key`: `abs_<p>`/`rel_<p>` for keys starting with `p`
/// (longest prefix), else `abs`/`rel`, else half a unit of the expected value's last digit.
fn tolerance(tol: &Value, key: &str, expected: f64) -> f64 {
    let mut best: Option<(usize, f64)> = None;
    if let Some(map) = tol.as_object() {
        for (k, v) in map {
            let v = v.as_f64().unwrap();
            let (kind, prefix) = k.split_once('_').unwrap_or((k.as_str(), ""));
            if !prefix.is_empty()
                && key.starts_with(prefix)
                && best.is_none_or(|(n, _)| prefix.len() > n)
            {
                let t = if kind == "rel" { v * expected.abs() } else { v };
                best = Some((prefix.len(), t));
            }
        }
        if best.is_none() {
            if let Some(r) = map.get("rel").and_then(Value::as_f64) {
                return r * expected.abs();
            }
            if let Some(a) = map.get("abs").and_then(Value::as_f64) {
                return a;
            }
        }
    }
    best.map_or_else(|| half_last_digit(expected), |(_, t)| t)
}

fn half_last_digit(x: f64) -> f64 {
    let text = format!("{x}");
    let decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
    0.5 * 10f64.powi(-(decimals as i32))
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
        let (id, variant) = if cases.contains_key(&stem) {
            (stem.clone(), None)
        } else {
            let (id, v) = stem
                .rsplit_once('.')
                .unwrap_or_else(|| panic!("{stem}: no case with this id"));
            (id.to_string(), Some(v.to_string()))
        };
        let case = cases
            .get(&id)
            .unwrap_or_else(|| panic!("{stem}: no case `{id}` in cases.jsonl"));
        let mut expected = case["expected"].clone();
        if let Some(v) = &variant {
            expected = expected[v.as_str()].clone();
            assert!(
                !expected.is_null(),
                "{stem}: no variant `{v}` in the expected values"
            );
        }
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

#[test]
fn tolerance_rules() {
    let t: Value = serde_json::json!({"abs_t": 0.001, "abs_x": 1e-4});
    assert_eq!(tolerance(&t, "t_last", 4.834), 0.001);
    assert_eq!(tolerance(&t, "x_last", 2.8e-4), 1e-4);
    assert!((tolerance(&t, "v_last", -0.5) - 0.05).abs() < 1e-15);
    let t: Value = serde_json::json!({"rel": 1e-3});
    assert!((tolerance(&t, "v", -4.8042) - 4.8042e-3).abs() < 1e-15);
    let t: Value = serde_json::json!({"abs_W": 0.5, "rel_v": 0.01});
    assert_eq!(tolerance(&t, "W_F", 900.0), 0.5);
    assert!((tolerance(&t, "v", 11.0) - 0.11).abs() < 1e-12);
}
