//! The course's worked problems as a gallery: the case file (`cases.jsonl`: inputs, the
//! quantity asked, the expected value and its tolerance), the scripts of command-line calls
//! that answer the one-line questions ([`script`]), the comparison of a computed value with
//! the expected one ([`Check`]) and the validation report ([`mod@report`]).
//!
//! Running a case is the caller's part (the CLI's `mechkit gallery` runs scenarios through
//! [`crate::scenario`] and scripts through its own commands): this module never knows the
//! answer, only how to compare one.
//!
//! ```
//! use mechkit::gallery::{Case, Check};
//! use serde_json::json;
//!
//! // one case per line
//! let line = r#"{"id": "k", "topic": "spring", "expected": 98000.0, "tolerance": {"rel": 0.01}}"#;
//! let cases = Case::parse_all(line).unwrap();
//! let check = Check::new(&cases[0], "k", "answer", &json!(98100.0));
//! assert!(check.pass);
//! ```

pub mod report;
pub mod script;

use serde_json::Value;

pub use report::{CaseRun, report};
pub use script::{Binding, Script, Step, shell_words};

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
    /// The unit(s) of the expected values, as the case file writes them.
    pub unit: String,
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
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("line {line}: {message}")]
pub struct CaseFileError {
    /// 1-based line number.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

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
                unit: text("unit"),
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

/// One expected value compared with the computed one.
#[derive(Debug, Clone)]
pub struct Check {
    /// The file stem that computed it (`<id>` or `<id>.<variant>`).
    pub stem: String,
    /// The expected key (`answer` for a single value).
    pub key: String,
    /// The expected value, as the case file gives it.
    pub expected: Value,
    /// The computed value (`null` when nothing computed it).
    pub computed: Value,
    /// The absolute tolerance, for numbers.
    pub tolerance: Option<f64>,
    /// |computed − expected| / |expected|, for numbers (absolute when expected is 0).
    pub error: Option<f64>,
    /// Whether the computed value is the expected one within the tolerance.
    pub pass: bool,
    /// Why it failed, or how a pattern was matched.
    pub note: String,
}

impl Check {
    /// Compares `computed` with the case's expected value of `key` for file stem `stem`.
    ///
    /// - numbers: |computed − expected| ≤ tolerance; `true`/`false` expected compare as 1/0;
    /// - a string `name = formula in n` (e.g. `"x = (n+1/2) b"`) is a family of values: each
    ///   computed number (a number or an array of them) must be one of the family for an
    ///   integer n, with the formula's other names taken from the case's inputs;
    /// - any other string must equal the computed string.
    pub fn new(case: &Case, stem: &str, key: &str, computed: &Value) -> Check {
        let expected = case
            .expected_of(stem)
            .and_then(|values| values.into_iter().find(|(k, _)| k == key))
            .map_or(Value::Null, |(_, v)| v);
        let mut check = Check {
            stem: stem.to_string(),
            key: key.to_string(),
            expected: expected.clone(),
            computed: computed.clone(),
            tolerance: None,
            error: None,
            pass: false,
            note: String::new(),
        };
        let want = number(&expected);
        match (want, &expected, computed) {
            (_, Value::Null, _) => check.note = format!("the case expects no `{key}`"),
            (_, _, Value::Null) => check.note = "not computed".into(),
            (Some(w), _, got) => match number(got) {
                Some(g) => {
                    let tol = case.tolerance_of(key, w);
                    let diff = (g - w).abs();
                    check.tolerance = Some(tol);
                    check.error = Some(if w == 0.0 { diff } else { diff / w.abs() });
                    check.pass = diff <= tol;
                }
                None => check.note = format!("computed {got}, not a number"),
            },
            (None, Value::String(pattern), got) => match Family::parse(pattern, &case.inputs) {
                Some(family) => {
                    let tol = case.tolerance_of(key, family.step);
                    check.tolerance = Some(tol);
                    match family.matches(got, tol) {
                        Ok(()) => check.pass = true,
                        Err(why) => check.note = why,
                    }
                }
                None => check.pass = got.as_str() == Some(pattern.as_str()),
            },
            (None, other, got) => check.pass = other == got,
        }
        check
    }
}

/// A number, or a boolean as 1/0.
fn number(v: &Value) -> Option<f64> {
    match v {
        Value::Number(n) => n.as_f64(),
        Value::Bool(b) => Some(f64::from(u8::from(*b))),
        _ => None,
    }
}

/// The values `offset + step·n` for integer n, read from a pattern such as `x = (n+1/2) b`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Family {
    offset: f64,
    step: f64,
}

impl Family {
    /// `None` when the text is not `name = formula` with a formula linear in `n` whose other
    /// names are numbers among `inputs`.
    fn parse(pattern: &str, inputs: &Value) -> Option<Family> {
        let (_, rhs) = pattern.split_once('=')?;
        let formula = mechkit_expr::Formula::parse(&implicit_products(rhs)).ok()?;
        let at = |n: f64| {
            formula
                .eval_with(&|name| {
                    if name == "n" {
                        Some(n)
                    } else {
                        inputs.get(name).and_then(Value::as_f64)
                    }
                })
                .ok()
                .filter(|v| v.is_finite())
        };
        let (f0, f1, f2) = (at(0.0)?, at(1.0)?, at(2.0)?);
        let step = f1 - f0;
        let linear = (f2 - f0 - 2.0 * step).abs() <= 1e-12 * (f0.abs() + step.abs());
        (step != 0.0 && linear).then_some(Family { offset: f0, step })
    }

    fn matches(&self, computed: &Value, tol: f64) -> Result<(), String> {
        let values: Vec<&Value> = match computed {
            Value::Array(items) => items.iter().collect(),
            other => vec![other],
        };
        if values.is_empty() {
            return Err("no computed value to compare with the pattern".into());
        }
        for v in values {
            let x = v
                .as_f64()
                .ok_or_else(|| format!("computed {v}, not a number"))?;
            let n = ((x - self.offset) / self.step).round();
            let nearest = self.offset + n * self.step;
            if (x - nearest).abs() > tol.max(f64::EPSILON * x.abs()) {
                return Err(format!(
                    "{x} is not of the pattern (nearest member {nearest})"
                ));
            }
        }
        Ok(())
    }
}

/// Writes the products of `n b` or `(n+1/2) b` explicitly: a space between two operands
/// becomes `*`.
fn implicit_products(text: &str) -> String {
    let mut out = String::new();
    let mut pending_space = false;
    for c in text.trim().chars() {
        if c.is_whitespace() {
            pending_space = true;
            continue;
        }
        if pending_space {
            let before = out.chars().last();
            let operand_before = before.is_some_and(|b| b.is_alphanumeric() || b == ')');
            let operand_after = c.is_alphanumeric() || c == '(';
            if operand_before && operand_after {
                out.push('*');
            }
            pending_space = false;
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests;
