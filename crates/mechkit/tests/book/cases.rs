//! Reading `book_cases.jsonl` and the tolerance of an expected value, shared by the library's
//! and the command line's book tests (the CLI test crate includes this file by path).

use std::collections::BTreeMap;
use std::path::Path;

use serde_json::Value;

/// The cases of a `cases.jsonl` file by id.
pub fn cases(path: &Path) -> BTreeMap<String, Value> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let v: Value = serde_json::from_str(l).unwrap();
            (v["id"].as_str().unwrap().to_string(), v)
        })
        .collect()
}

/// The case a file named `stem` reproduces (`<id>` or `<id>.<variant>`) and its expected
/// values (the variant's, for a variant).
pub fn case_of<'c>(cases: &'c BTreeMap<String, Value>, stem: &str) -> (&'c Value, Value) {
    let (id, variant) = if cases.contains_key(stem) {
        (stem, None)
    } else {
        let (id, v) = stem
            .rsplit_once('.')
            .unwrap_or_else(|| panic!("{stem}: no case with this id"));
        (id, Some(v))
    };
    let case = cases
        .get(id)
        .unwrap_or_else(|| panic!("{stem}: no case `{id}` in cases.jsonl"));
    let expected = match variant {
        Some(v) => case["expected"][v].clone(),
        None => case["expected"].clone(),
    };
    assert!(
        !expected.is_null(),
        "{stem}: no expected values (variant `{variant:?}`)"
    );
    (case, expected)
}

/// The tolerance for expected key `key`: `abs_<p>`/`rel_<p>` for keys starting with `p`
/// (longest prefix), else `abs`/`rel`, else half a unit of the expected value's last digit.
pub fn tolerance(tol: &Value, key: &str, expected: f64) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
