//! One expected value compared with the computed one: numbers within the case's tolerance,
//! patterns in `n` (a family of values), text as it is.

use serde_json::Value;

use super::Case;

/// One expected value compared with the computed one.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Check {
    /// The file stem that computed it (`<id>` or `<id>.<variant>`).
    #[serde(skip)]
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
pub(super) struct Family {
    pub(super) offset: f64,
    pub(super) step: f64,
}

impl Family {
    /// `None` when the text is not `name = formula` with a formula linear in `n` whose other
    /// names are numbers among `inputs`.
    pub(super) fn parse(pattern: &str, inputs: &Value) -> Option<Family> {
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
                    "{} is not of the pattern (nearest member {})",
                    mechkit::expr::short_number(x),
                    mechkit::expr::short_number(nearest)
                ));
            }
        }
        Ok(())
    }
}

/// Writes the products of `n b` or `(n+1/2) b` explicitly: a space between two operands
/// becomes `*`.
pub(super) fn implicit_products(text: &str) -> String {
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
