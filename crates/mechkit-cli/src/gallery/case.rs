//! The case file: one worked problem per line of `cases.jsonl`, with its expected values and
//! their tolerances.

use serde_json::Value;

/// A worked problem of the case file.
#[derive(Debug, Clone)]
pub struct Case {
    /// Its id, e.g. `c08-B9-rotor-blade`: files reproducing it are named `<id>.toml`,
    /// `<id>.sh`, or `<id>.<variant>.toml` for one of several variants.
    pub id: String,
    /// The chapter of the course.
    pub chapter: u32,
    /// What it is about, e.g. "uniform circular motion".
    pub topic: String,
    /// The question asked.
    pub asked: String,
    /// The case's inputs (names of patterns' parameters are read from here).
    pub inputs: Value,
    /// The expected value: a number or string (key `answer`), an object of values by key, or
    /// an object of such objects by variant.
    pub expected: Value,
    /// The tolerance: `rel`, `abs`, and `rel_<prefix>`/`abs_<prefix>` for keys starting with
    /// the prefix (the longest wins); with none, half a unit of the expected value's last digit.
    pub tolerance: Value,
}

/// A line of the case file that is not a case.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseFileError {
    /// 1-based line number.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for CaseFileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for CaseFileError {}

impl Case {
    /// Reads a JSON-lines case file: one object per line, blank lines ignored.
    pub fn parse_all(text: &str) -> Result<Vec<Case>, CaseFileError> {
        let mut cases = Vec::new();
        for (n, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let err = |message: String| CaseFileError {
                line: n + 1,
                message,
            };
            let v: Value = serde_json::from_str(line).map_err(|e| err(e.to_string()))?;
            let text = |key: &str| v.get(key).and_then(Value::as_str).unwrap_or("").to_string();
            let id = text("id");
            if id.is_empty() {
                return Err(err("a case needs an \"id\" string".into()));
            }
            if cases.iter().any(|c: &Case| c.id == id) {
                return Err(err(format!("a second case with id `{id}`")));
            }
            let expected = v.get("expected").cloned().unwrap_or(Value::Null);
            if expected.is_null() {
                return Err(err(format!("case `{id}` has no \"expected\" value")));
            }
            cases.push(Case {
                chapter: v
                    .get("chapter")
                    .and_then(Value::as_u64)
                    .map_or(0, |c| c as u32),
                topic: text("topic"),
                asked: text("asked"),
                inputs: v.get("inputs").cloned().unwrap_or(Value::Null),
                tolerance: v.get("tolerance").cloned().unwrap_or(Value::Null),
                expected,
                id,
            });
        }
        Ok(cases)
    }

    /// The variants of the case (`expected` is an object of objects), or none.
    pub fn variants(&self) -> Vec<&str> {
        match &self.expected {
            Value::Object(map) if !map.is_empty() && map.values().all(Value::is_object) => {
                map.keys().map(String::as_str).collect()
            }
            _ => Vec::new(),
        }
    }

    /// The expected values of a file stem (`<id>` or `<id>.<variant>`) by key; a single value
    /// is keyed `answer`. `None` when the stem names no variant of this case.
    pub fn expected_of(&self, stem: &str) -> Option<Vec<(String, Value)>> {
        let values = if stem == self.id {
            if !self.variants().is_empty() {
                return None;
            }
            &self.expected
        } else {
            let variant = stem.strip_prefix(self.id.as_str())?.strip_prefix('.')?;
            self.expected.get(variant).filter(|v| v.is_object())?
        };
        Some(match values {
            Value::Object(map) => map.iter().map(|(k, v)| (k.clone(), v.clone())).collect(),
            other => vec![("answer".to_string(), other.clone())],
        })
    }

    /// The file stems that reproduce this case: the id, or one per variant.
    pub fn stems(&self) -> Vec<String> {
        let variants = self.variants();
        if variants.is_empty() {
            vec![self.id.clone()]
        } else {
            variants
                .iter()
                .map(|v| format!("{}.{v}", self.id))
                .collect()
        }
    }

    /// The absolute tolerance for expected value `expected` of key `key`.
    pub fn tolerance_of(&self, key: &str, expected: f64) -> f64 {
        tolerance(&self.tolerance, key, expected)
    }
}

/// The case a file stem reproduces: the case whose id is the stem, or whose id followed by
/// `.variant` is.
pub fn case_of<'c>(cases: &'c [Case], stem: &str) -> Option<&'c Case> {
    cases.iter().find(|c| c.expected_of(stem).is_some())
}

/// The absolute tolerance for expected key `key` of value `expected` under a case's
/// `tolerance` object: `abs_<p>`/`rel_<p>` for keys starting with `p` (longest prefix), else
/// `abs`/`rel`, else half a unit of the expected value's last printed digit.
pub fn tolerance(tol: &Value, key: &str, expected: f64) -> f64 {
    let mut best: Option<(usize, f64)> = None;
    if let Some(map) = tol.as_object() {
        for (k, v) in map {
            let Some(v) = v.as_f64() else { continue };
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
