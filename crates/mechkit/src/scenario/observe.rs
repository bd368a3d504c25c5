//! `[observe]`: named results of a run. Each is a formula of reductions over the run's samples:
//! `max(x)`, `final(v)`, `max(x) - min(x)`, `initial(U) - final(U)`. A formula without any
//! reduction is reduced with `final`.

use mechkit_expr::units::Dimension;
use mechkit_expr::{Dim, Formula, MapScope, Program};

use toml::de::DeValue;

use super::doc::Table;
use super::error::ScenarioError;
use super::values::formula_error;
use crate::Real;
use crate::particles::{NameContext, Sample, StateExpr};
use crate::simulate::{Observer, ObserverError, Reducer, Reduction};

/// One `[observe]` entry.
#[derive(Debug, Clone)]
pub struct Observable {
    /// Its name (the key).
    pub name: String,
    /// The text as written, e.g. `max(x) - min(x)`.
    pub source: String,
    parts: Vec<(Reduction, StateExpr)>,
    outer: Program,
    dim: Dim,
    /// In a scenario of hinged bodies, 1/s and 1/s² are angular rates: shown as rad/s, rad/s².
    angular: bool,
}

impl Observable {
    /// Its dimension, where it is known.
    pub fn dimension(&self) -> Dim {
        self.dim
    }

    /// The SI unit of its value, where its dimension is known: `m`, `m/s`, `J`.
    pub fn unit(&self) -> Option<String> {
        let d = self.dim.known()?;
        if self.angular && d == Dimension::FREQUENCY {
            return Some("rad/s".into());
        }
        if self.angular && d == Dimension::FREQUENCY.powi(2) {
            return Some("rad/s^2".into());
        }
        Some(unit_text(d))
    }

    /// The reductions it combines.
    pub fn parts(&self) -> &[(Reduction, StateExpr)] {
        &self.parts
    }

    /// Compiles `text` against the scenario's names, checking that its parts fit together
    /// dimensionally.
    pub(crate) fn compile(
        name: &str,
        text: &str,
        names: &NameContext<'_>,
    ) -> Result<Observable, mechkit_expr::ExprError> {
        let dim_of = |n: &str| names.dim_of(n);
        let value_of = |n: &str| names.constant(n);
        let calls = extract_reductions(text)?;
        if calls.is_empty() {
            let f = Formula::parse(text)?;
            let expr = names.compile(&f)?;
            return Ok(Observable {
                name: name.to_string(),
                source: text.to_string(),
                parts: vec![(Reduction::Final, expr)],
                outer: Formula::parse("_r0")?.compile(&MapScope::new().slot("_r0", 0))?,
                dim: f.dimension_with(&dim_of, &value_of)?,
                angular: names.coordinates == crate::particles::Coordinates::Angle,
            });
        }
        let mut outer_text = text.to_string();
        let mut parts = Vec::new();
        let mut part_dims: Vec<(String, Dim)> = Vec::new();
        let mut scope = MapScope::new();
        for (k, call) in calls.iter().enumerate() {
            let shifted = |e| shift(e, text, call.inner.start);
            let inner = Formula::parse(&text[call.inner.clone()]).map_err(shifted)?;
            let expr = names.compile(&inner).map_err(shifted)?;
            let d = inner.dimension_with(&dim_of, &value_of).map_err(shifted)?;
            parts.push((call.reduction, expr));
            let mut placeholder = format!("_r{k}");
            while placeholder.len() < call.whole.len() {
                placeholder.push('_');
            }
            outer_text.replace_range(call.whole.clone(), &placeholder);
            scope.insert(&placeholder, mechkit_expr::Binding::Slot(k));
            part_dims.push((placeholder, reduced_dimension(call.reduction, d)));
        }
        for (c, v, _) in names.constants {
            scope.insert(c, mechkit_expr::Binding::Const(*v));
        }
        // the placeholders stand for the user's reductions: errors show those, never `_r0___`
        let mut renamed: Vec<(String, String)> = calls
            .iter()
            .zip(&part_dims)
            .map(|(call, (placeholder, _))| {
                (placeholder.clone(), text[call.whole.clone()].to_string())
            })
            .collect();
        renamed.sort_by_key(|(p, _)| std::cmp::Reverse(p.len()));
        let restored = |e: mechkit_expr::ExprError| {
            renamed.iter().fold(restore(e, text), |e, (p, original)| {
                e.with_text_restored(p, original)
            })
        };
        let outer = Formula::parse(&outer_text).map_err(restored)?;
        for n in outer.names() {
            if names.resolve(n).is_some() && names.constant(n).is_none() {
                let span = outer.span_of(n).unwrap_or(outer.full_span());
                return Err(mechkit_expr::ExprError::new(
                    mechkit_expr::ExprErrorKind::UndefinedName {
                        name: n.to_string(),
                        suggestions: vec![format!("final({n})")],
                        context: Some(format!(
                            "`{n}` changes during the run: use it inside a reduction such as final({n}) or max({n})"
                        )),
                    },
                    span,
                    text,
                ));
            }
        }
        let dim = outer
            .dimension_with(
                &|n| {
                    part_dims
                        .iter()
                        .find(|(p, _)| p == n)
                        .map_or_else(|| dim_of(n), |(_, d)| *d)
                },
                &value_of,
            )
            .map_err(restored)?;
        let outer = outer.compile(&scope).map_err(restored)?;
        Ok(Observable {
            name: name.to_string(),
            source: text.to_string(),
            parts,
            outer,
            dim,
            angular: names.coordinates == crate::particles::Coordinates::Angle,
        })
    }

    /// The result from the reduced values of its parts.
    pub fn value(&self, reduced: &[Real]) -> Real {
        self.outer.eval(reduced)
    }
}

/// The dimension of a reduction of a quantity of dimension `d`.
fn reduced_dimension(r: Reduction, d: Dim) -> Dim {
    match (r, d) {
        (Reduction::ArgMin | Reduction::ArgMax, _) => Dim::Known(Dimension::TIME),
        (Reduction::Integral, Dim::Known(d)) => Dim::Known(d * Dimension::TIME),
        (Reduction::Integral, _) => Dim::Unknown,
        (_, d) => d,
    }
}

/// A unit for people: the derived symbol where there is one (N, J, W), else base units.
pub(crate) fn unit_text(d: Dimension) -> String {
    if d.is_none() {
        String::new()
    } else if d == Dimension::FREQUENCY {
        // a frequency or an angular velocity (rad/s): neither name is safe
        "1/s".to_string()
    } else {
        d.derived_symbol()
            .map_or_else(|| d.to_string(), str::to_string)
    }
}

fn shift(mut e: mechkit_expr::ExprError, text: &str, offset: usize) -> mechkit_expr::ExprError {
    e.span = e.span.shifted(offset);
    e.source = text.to_string();
    e
}

fn restore(mut e: mechkit_expr::ExprError, text: &str) -> mechkit_expr::ExprError {
    e.source = text.to_string();
    e
}

/// A reduction call found in the text.
struct Call {
    reduction: Reduction,
    whole: std::ops::Range<usize>,
    inner: std::ops::Range<usize>,
}

/// Finds the reduction calls (`max(x)` with one argument; `max(a, b)` is the function).
fn extract_reductions(text: &str) -> Result<Vec<Call>, mechkit_expr::ExprError> {
    let b = text.as_bytes();
    let is_ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_' || c == b'.';
    let mut out: Vec<Call> = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if !(b[i].is_ascii_alphabetic() || b[i] == b'_') || (i > 0 && is_ident(b[i - 1])) {
            i += 1;
            continue;
        }
        let start = i;
        while i < b.len() && is_ident(b[i]) {
            i += 1;
        }
        let Some(reduction) = Reduction::from_name(&text[start..i]) else {
            continue;
        };
        let mut j = i;
        while j < b.len() && b[j] == b' ' {
            j += 1;
        }
        if j >= b.len() || b[j] != b'(' {
            continue;
        }
        let open = j;
        let (mut depth, mut top_comma, mut close) = (0i32, false, None);
        for (k, &c) in b.iter().enumerate().skip(open) {
            match c {
                b'(' => depth += 1,
                b')' => {
                    depth -= 1;
                    if depth == 0 {
                        close = Some(k);
                        break;
                    }
                }
                b',' if depth == 1 => top_comma = true,
                _ => {}
            }
        }
        let Some(close) = close else {
            break; // the parser reports the unclosed parenthesis
        };
        if top_comma {
            continue; // min(a, b): the function; look inside it for reductions
        }
        if let Some(outer) = out
            .iter()
            .find(|c| c.whole.start <= start && close < c.whole.end)
        {
            return Err(mechkit_expr::ExprError::new(
                mechkit_expr::ExprErrorKind::UnexpectedToken {
                    found: format!("`{}` inside `{}`", &text[start..i], outer.reduction.name()),
                    expected: "reductions side by side, not nested".into(),
                },
                mechkit_expr::Span::new(start, i),
                text,
            ));
        }
        out.push(Call {
            reduction,
            whole: start..close + 1,
            inner: open + 1..close,
        });
        i = open + 1;
    }
    Ok(out)
}

/// Reads `[observe]`.
pub(crate) fn read_observe(
    root: &Table<'_, '_>,
    names: &NameContext<'_>,
) -> Result<Vec<Observable>, ScenarioError> {
    let Some(t) = root.table("observe")? else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    for (key, value) in t.entries {
        let name: &str = key.get_ref();
        let DeValue::String(text) = value.get_ref() else {
            return Err(t.wrong_type(name, value, "a string such as \"max(x)\""));
        };
        let span = value.span();
        let o =
            Observable::compile(name, text, names).map_err(|e| formula_error(&t.src, &span, &e))?;
        out.push(o);
    }
    Ok(out)
}

/// Evaluates every observable on every sample.
pub(crate) struct ObservableSet<'a> {
    items: &'a [Observable],
    reducers: Vec<Vec<Reducer>>,
    dim: usize,
    mass: &'a [Real],
}

impl<'a> ObservableSet<'a> {
    pub fn new(items: &'a [Observable], dim: usize, mass: &'a [Real]) -> Self {
        Self {
            items,
            reducers: items
                .iter()
                .map(|o| o.parts.iter().map(|(r, _)| Reducer::new(*r)).collect())
                .collect(),
            dim,
            mass,
        }
    }

    /// Name, value and unit (where known) of each observable.
    pub fn values(&self) -> Vec<(String, Real, Option<String>)> {
        self.items
            .iter()
            .zip(&self.reducers)
            .map(|(o, rs)| {
                let reduced: Vec<Real> = rs.iter().map(Reducer::value).collect();
                (o.name.clone(), o.value(&reduced), o.unit())
            })
            .collect()
    }
}

impl Observer for ObservableSet<'_> {
    fn next_step(&self, step: u64) -> Option<u64> {
        // a reduction (max, mean, ...) sees every step
        if self.items.is_empty() {
            None
        } else {
            Some(step + 1)
        }
    }

    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        for (o, rs) in self.items.iter().zip(&mut self.reducers) {
            for ((_, expr), r) in o.parts.iter().zip(rs.iter_mut()) {
                r.push_sample(s.t, expr.eval_sample(s, self.dim, self.mass, None), s.kind);
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_reductions_but_not_functions() {
        let calls = extract_reductions("max(x) - min(x, y) + final(min(a, b))").unwrap();
        let found: Vec<_> = calls.iter().map(|c| c.reduction).collect();
        assert_eq!(found, vec![Reduction::Max, Reduction::Final]);
        assert!(extract_reductions("max(final(x))").is_err());
        assert!(extract_reductions("xmax(t)").unwrap().is_empty());
    }
}
