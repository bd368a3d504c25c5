//! A swept parameter: `--set "v0=0:5:51"` (51 points from 0 to 5), `"v0=0 m/s:5 m/s:51"`
//! (with units), `"k=1,2,4"` (a list) or `"k=2 N/m"` (one value).

use mechkit_expr::Dim;
use mechkit_expr::units::{Dimension, Quantity, UnitErrorKind};

use super::SweepError;
use crate::Real;
use crate::scenario::{ErrorKind, ScenarioError};

/// A constant of the scenario given another value (SI; `dim` is `None` for a bare number,
/// which takes the dimension of the constant it replaces).
#[derive(Debug, Clone, PartialEq)]
pub struct ConstantOverride {
    /// The constant's name.
    pub name: String,
    /// The value in SI units.
    pub value: Real,
    /// The dimension of the value, when it was given with units.
    pub dim: Option<Dimension>,
}

impl ConstantOverride {
    /// Reads `"m=2 kg, th=pi/6, k=100"`: each value a quantity with units (checked against
    /// the constant's dimension when applied), a bare number (SI, taking the constant's
    /// dimension), or a formula of `pi`, `e` and the names before it
    /// ([`crate::values::params`]).
    ///
    /// # Errors
    /// What [`crate::values::params`] refuses.
    pub fn parse_list(text: &str) -> Result<Vec<ConstantOverride>, crate::values::ValueError> {
        let values = crate::values::params(text)?;
        Ok(values
            .into_iter()
            .map(|(name, value)| {
                let given = crate::values::split_top_level(text, ',')
                    .into_iter()
                    .filter_map(|item| item.split_once('='))
                    .rfind(|(n, _)| n.trim() == name)
                    .map(|(_, v)| v.trim());
                let dim = given
                    .and_then(|v| Quantity::parse(v).ok())
                    .map(|q| q.dim)
                    .filter(|d| !d.is_none());
                ConstantOverride { name, value, dim }
            })
            .collect())
    }

    /// The value and dimension the constant takes, given the dimension it has in the file:
    /// an error when both are known and differ.
    pub(crate) fn apply(&self, file: Dim) -> Result<(Real, Dim), ScenarioError> {
        let Some(d) = self.dim else {
            return Ok((self.value, file));
        };
        if let Dim::Known(k) = file
            && k != d
        {
            return Err(ScenarioError::new(
                ErrorKind::Dimension,
                format!(
                    "the value given for `{}` in --set is {}, but the constant is {} in the scenario",
                    self.name,
                    d.describe(),
                    k.describe()
                ),
            )
            .with_hint(format!(
                "give `{}` in units of {}, or as a bare number in SI",
                self.name,
                k.describe()
            )));
        }
        Ok((self.value, Dim::Known(d)))
    }
}

/// The error for a swept name that is not among the constants `names` of the file.
pub(crate) fn unknown_override(o: &ConstantOverride, names: &[&str]) -> ScenarioError {
    let hint = mechkit_expr::did_you_mean(&mechkit_expr::nearest(&o.name, names.iter().copied()));
    let list = if names.is_empty() {
        "the scenario has no [constants]".to_string()
    } else {
        format!("its constants are {}", names.join(", "))
    };
    ScenarioError::new(
        ErrorKind::UnknownKey,
        format!(
            "`{}` (in --set) is not a constant of the scenario: {list}",
            o.name
        ),
    )
    .with_hint(hint.unwrap_or_else(|| {
        "a sweep varies entries of [constants]; add the parameter there and use it in the formulas".into()
    }))
}

/// One swept constant and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    /// The constant's name.
    pub name: String,
    /// The `--set` text as given (trimmed), recorded in the table's manifest.
    pub text: String,
    /// The grid values (SI).
    pub values: Vec<Real>,
    /// For a range `a:b:n`, its bounds (random samples are drawn uniformly between them).
    pub range: Option<(Real, Real)>,
    /// The dimension the values were given in, if any.
    pub dim: Option<Dimension>,
}

fn bad(text: &str, reason: impl Into<String>, hint: &str) -> SweepError {
    SweepError::BadSet {
        text: text.to_string(),
        reason: reason.into(),
        hint: hint.to_string(),
    }
}

/// The most runs a sweep makes (and points a range has): ten million, about six hours at the
/// measured 438 runs per second on one thread.
pub const MAX_RUNS: usize = 10_000_000;

const USAGE: &str =
    "write NAME=START:END:COUNT (\"v0=0:5:51\", \"v0=0 m/s:5 m/s:51\"), NAME=A,B,C or NAME=VALUE";

impl Parameter {
    /// Parses a `--set` text.
    ///
    /// # Example
    /// ```
    /// use mechkit::scenario::sweep::Parameter;
    /// let p = Parameter::parse("v0=0 km/h:36 km/h:3").unwrap();
    /// assert_eq!(p.values, vec![0.0, 5.0, 10.0]);
    /// assert_eq!(Parameter::parse("k=1,2,4").unwrap().values, vec![1.0, 2.0, 4.0]);
    /// assert!(Parameter::parse("k=1:2").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Parameter, SweepError> {
        let text = text.trim();
        let Some((name, spec)) = text.split_once('=') else {
            return Err(bad(
                text,
                "no `=` between the constant and its values",
                USAGE,
            ));
        };
        let name = name.trim();
        let valid = name
            .chars()
            .next()
            .is_some_and(|c| c.is_alphabetic() || c == '_')
            && name.chars().all(|c| c.is_alphanumeric() || c == '_');
        if !valid {
            return Err(bad(
                text,
                format!("`{name}` is not a constant name"),
                "name a constant of the scenario's [constants] before the `=`",
            ));
        }
        let spec = spec.trim();
        let mut p = Parameter {
            name: name.to_string(),
            text: text.to_string(),
            values: Vec::new(),
            range: None,
            dim: None,
        };
        if spec.contains(':') {
            let parts: Vec<&str> = spec.split(':').map(str::trim).collect();
            let [a, b, n] = parts[..] else {
                return Err(bad(
                    text,
                    format!(
                        "a range has three parts START:END:COUNT, not {}",
                        parts.len()
                    ),
                    USAGE,
                ));
            };
            let count: usize = n.parse().map_err(|_| {
                bad(
                    text,
                    format!("the count `{n}` is not a whole number"),
                    "the last part of a range is how many points, e.g. 0:5:51",
                )
            })?;
            if count > MAX_RUNS {
                return Err(bad(
                    text,
                    format!(
                        "a range of {count} points is more than a sweep runs (at most {MAX_RUNS})"
                    ),
                    "use fewer points, or --random N for a sample of a large space",
                ));
            }
            if count < 2 {
                return Err(bad(
                    text,
                    format!("a range needs at least 2 points, not {count}"),
                    "give one value as NAME=VALUE",
                ));
            }
            let ab = p.quantities(&[a, b])?;
            let (a, b) = (ab[0], ab[1]);
            p.range = Some((a, b));
            p.values = (0..count)
                .map(|i| {
                    if i == count - 1 {
                        b
                    } else {
                        a + (b - a) * (i as Real / (count - 1) as Real)
                    }
                })
                .collect();
        } else {
            let items: Vec<&str> = spec.split(',').map(str::trim).collect();
            p.values = p.quantities(&items)?;
        }
        Ok(p)
    }

    /// Reads values, which must all be of one dimension (or all bare numbers).
    fn quantities(&mut self, items: &[&str]) -> Result<Vec<Real>, SweepError> {
        let mut out = Vec::new();
        for (i, item) in items.iter().enumerate() {
            if item.is_empty() {
                return Err(bad(&self.text, "a value is missing", USAGE));
            }
            let q = Quantity::parse(item).map_err(|e| {
                bad(
                    &self.text,
                    // the unit message quotes `item` itself when it has no number
                    if matches!(e.kind, UnitErrorKind::NoNumber) {
                        e.message()
                    } else {
                        format!("`{item}`: {}", e.message())
                    },
                    &e.hint().unwrap_or_else(|| USAGE.to_string()),
                )
            })?;
            if !q.value.is_finite() {
                return Err(bad(&self.text, format!("`{item}` is not finite"), USAGE));
            }
            let dim = (!q.dim.is_none()).then_some(q.dim);
            if i == 0 {
                self.dim = dim;
            } else if self.dim != dim {
                return Err(bad(
                    &self.text,
                    format!("`{item}` is not in the same units as `{}`", items[0]),
                    "give every value units of the same quantity, or none (SI)",
                ));
            }
            out.push(q.value);
        }
        Ok(out)
    }

    /// The override of one of its values.
    pub fn with_value(&self, value: Real) -> ConstantOverride {
        ConstantOverride {
            name: self.name.clone(),
            value,
            dim: self.dim,
        }
    }
}
