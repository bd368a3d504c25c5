//! Initial conditions, `x(0)=1, x'(0)=v0`.

use super::parse::{Ode, derivative_name};
use super::solve::DsolveError;
use crate::sym::Sym;

/// `func^(order)(at) = value`.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// Which derivative (0 for the function itself).
    pub order: usize,
    /// Where.
    pub at: Sym,
    /// Its value.
    pub value: Sym,
}

impl std::fmt::Display for Condition {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}({}) = {}",
            "'".repeat(self.order),
            self.at,
            self.value
        )
    }
}

/// Splits at the commas outside parentheses.
fn split_top(text: &str) -> Vec<&str> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' | ';' if depth == 0 => {
                parts.push(&text[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

impl Condition {
    /// Reads `x(0)=1, x'(0)=0` for the function `func`.
    ///
    /// ```
    /// use mechkit_expr::sym::dsolve::Condition;
    /// let c = Condition::parse_list("x(0)=1, x'(0)=v0", "x").unwrap();
    /// assert_eq!((c[1].order, c[1].value.to_string()), (1, "v0".to_string()));
    /// ```
    pub fn parse_list(text: &str, func: &str) -> Result<Vec<Condition>, DsolveError> {
        let mut out: Vec<Condition> = Vec::new();
        for part in split_top(text) {
            let part = part.trim();
            if part.is_empty() {
                continue;
            }
            let bad = |why: &str| {
                DsolveError::Condition(format!(
                    "`{part}`: {why}; write conditions as {func}(0)=1, {func}'(0)=0"
                ))
            };
            let rest = part
                .strip_prefix(func)
                .ok_or_else(|| bad(&format!("it does not start with `{func}`")))?;
            let order = rest.chars().take_while(|&c| c == '\'').count();
            let rest = rest[order..].trim_start();
            let inner = rest
                .strip_prefix('(')
                .ok_or_else(|| bad("the point is missing, as in (0)"))?;
            let mut depth = 1;
            let close = inner
                .char_indices()
                .find(|&(_, c)| {
                    depth += match c {
                        '(' => 1,
                        ')' => -1,
                        _ => 0,
                    };
                    depth == 0
                })
                .map(|(i, _)| i)
                .ok_or_else(|| bad("unclosed `(`"))?;
            let value = inner[close + 1..]
                .trim_start()
                .strip_prefix('=')
                .ok_or_else(|| bad("`=` and a value are missing"))?;
            let read = |s: &str, what: &str| {
                Sym::parse(s)
                    .map_err(|e| bad(&format!("its {what} `{}`: {}", s.trim(), e.message())))
            };
            let c = Condition {
                order,
                at: read(&inner[..close], "point")?,
                value: read(value, "value")?,
            };
            // the same derivative at two points is a boundary condition (`x(0)=0, x(1)=1`)
            if out.iter().any(|o| o.order == c.order && o.at == c.at) {
                return Err(bad("that derivative is given twice at the same point"));
            }
            out.push(c);
        }
        Ok(out)
    }
}

impl Ode {
    /// Refuses initial conditions at a point where the equation is singular: with the function
    /// and its derivatives below the highest all given there, the highest derivative the
    /// equation asks for is not a finite number (`x' = 1/x` with `x(0) = 0`), or, in an
    /// equation linear in it, its coefficient vanishes (`t x' = x` at `t = 0`). Through such a
    /// point a solution need not exist, nor be unique (`x = √(2t)` and `x = −√(2t)` both leave
    /// `x(0) = 0` for `x' = 1/x`), so no formula is "the" solution. Conditions whose point or
    /// values are not numbers are not checked.
    pub(super) fn check_regular(&self, conditions: &[Condition]) -> Result<(), DsolveError> {
        let n = self.order;
        let Some(first) = conditions.first() else {
            return Ok(());
        };
        if n == 0 || conditions.len() != n || conditions.iter().any(|c| c.at != first.at) {
            return Ok(());
        }
        let number = |s: &Sym| s.eval(&|_| None).ok().filter(|v| v.is_finite());
        let Some(t0) = number(&first.at) else {
            return Ok(());
        };
        let mut values = vec![0.0; n];
        for c in conditions {
            let Some(v) = number(&c.value) else {
                return Ok(());
            };
            values[c.order] = v;
        }
        let top = derivative_name(&self.func, n);
        let residual_with = |highest: f64| {
            self.residual.eval(&|name| {
                if name == self.var {
                    return Some(t0);
                }
                if name == top {
                    return Some(highest);
                }
                (0..n)
                    .find(|&k| derivative_name(&self.func, k) == name)
                    .map(|k| values[k])
            })
        };
        let (Ok(r0), Ok(r1)) = (residual_with(0.0), residual_with(1.0)) else {
            return Ok(());
        };
        let linear = self.residual.diff(&top).free_of(&top);
        let singular = !(r0.is_finite() && r1.is_finite()) || (linear && r1 == r0);
        if !singular {
            return Ok(());
        }
        let given: Vec<String> = conditions
            .iter()
            .map(|c| format!("{}{c}", self.func))
            .collect();
        let highest = format!("{}{}", self.func, "'".repeat(n));
        Err(DsolveError::Condition(format!(
            "the equation {} is singular at the initial point: with {} it does not give \
             {highest} as a finite number there, so a solution through that point need not \
             exist, nor be unique; give the conditions at a point where the equation is regular",
            self.display(),
            given.join(", ")
        )))
    }
}
