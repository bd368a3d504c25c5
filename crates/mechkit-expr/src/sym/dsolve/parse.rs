//! Reading an equation written with primes: `x''` becomes the placeholder `__x_d2` before the
//! formula parser sees it, and an error is reported at the user's own column.

use super::solve::DsolveError;
use crate::ExprError;
use crate::sym::Sym;

/// The placeholder name of the `k`-th derivative of `func` (`k = 0` is `func` itself).
///
/// ```
/// use mechkit_expr::sym::dsolve::derivative_name;
/// assert_eq!(derivative_name("x", 2), "__x_d2");
/// ```
pub fn derivative_name(func: &str, k: usize) -> String {
    if k == 0 {
        func.to_string()
    } else {
        format!("__{func}_d{k}")
    }
}

/// An ordinary differential equation `residual = 0` for `func` of `var`.
#[derive(Debug, Clone, PartialEq)]
pub struct Ode {
    /// The unknown function's name (`x`).
    pub func: String,
    /// The independent variable (`t`).
    pub var: String,
    /// The highest derivative written.
    pub order: usize,
    /// `lhs - rhs`, with the derivatives as [`derivative_name`]s.
    pub residual: Sym,
}

/// One edit of the text: at `new_start` of the rewritten text, `new_len` bytes replaced
/// `old_len` bytes of the original.
struct Edit {
    new_start: usize,
    new_len: usize,
    old_len: usize,
}

fn ident_continue(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Replaces `x'`, `x''`, … (and `x(t)`, `x'(t)`) by placeholder names.
fn rewrite(text: &str, func: &str, var: &str) -> Result<(String, Vec<Edit>), DsolveError> {
    let mut out = String::with_capacity(text.len() + 16);
    let mut edits = Vec::new();
    let mut i = 0;
    while i < text.len() {
        let rest = &text[i..];
        let before_ok = !text[..i].chars().next_back().is_some_and(ident_continue);
        let after = rest.get(func.len()..).unwrap_or("");
        if before_ok && rest.starts_with(func) && !after.chars().next().is_some_and(ident_continue)
        {
            let primes = after.chars().take_while(|&c| c == '\'').count();
            let mut old_len = func.len() + primes;
            let call = format!("({var})");
            if after[primes..].starts_with(&call) {
                old_len += call.len();
            }
            let name = derivative_name(func, primes);
            edits.push(Edit {
                new_start: out.len(),
                new_len: name.len(),
                old_len,
            });
            out.push_str(&name);
            i += old_len;
            continue;
        }
        let c = rest.chars().next().expect("not at the end");
        if c == '\'' {
            return Err(DsolveError::Invalid(format!(
                "`{text}`: a prime `'` (column {}) must follow the function's name `{func}`, \
                 as in {func}' or {func}''",
                text[..i].chars().count() + 1
            )));
        }
        out.push(c);
        i += c.len_utf8();
    }
    Ok((out, edits))
}

/// The position in the original text of a byte position of the rewritten text.
fn original(pos: usize, edits: &[Edit]) -> usize {
    let mut shift: isize = 0;
    for e in edits {
        if pos >= e.new_start + e.new_len {
            shift += e.new_len as isize - e.old_len as isize;
        } else if pos > e.new_start {
            return (e.new_start as isize - shift) as usize;
        }
    }
    (pos as isize - shift).max(0) as usize
}

/// An error of the rewritten text, told about the user's text.
fn relocate(e: ExprError, text: &str, func: &str, edits: &[Edit]) -> ExprError {
    let mut e = e;
    for k in (1..=4).rev() {
        e = e.with_text_restored(
            &derivative_name(func, k),
            &format!("{func}{}", "'".repeat(k)),
        );
    }
    let start = original(e.span.start, edits).min(text.len());
    let end = original(e.span.end, edits).clamp(start, text.len());
    e.span = crate::Span::new(start, end);
    e.source = text.to_string();
    e
}

/// Positions of the single `=` signs (not `==`, `<=`, `>=`, `!=`).
fn equals_signs(b: &[u8]) -> Vec<usize> {
    (0..b.len())
        .filter(|&i| {
            b[i] == b'='
                && !(i > 0 && matches!(b[i - 1], b'=' | b'<' | b'>' | b'!'))
                && !(i + 1 < b.len() && b[i + 1] == b'=')
        })
        .collect()
}

impl Ode {
    /// Reads `lhs = rhs` (or an expression equal to zero) written with primes for the
    /// derivatives of `func` with respect to `var`.
    ///
    /// ```
    /// use mechkit_expr::sym::dsolve::Ode;
    /// let ode = Ode::parse("m*x'' = -k*x", "x", "t").unwrap();
    /// assert_eq!(ode.order, 2);
    /// assert_eq!(ode.residual.to_string(), "__x_d2*m + k*x");
    /// ```
    pub fn parse(text: &str, func: &str, var: &str) -> Result<Ode, DsolveError> {
        if func == var {
            return Err(DsolveError::Invalid(format!(
                "the function and the variable are both `{func}`: give the unknown function \
                 with --func and the variable it depends on with --var"
            )));
        }
        let (rewritten, edits) = rewrite(text, func, var)?;
        let parse = |from: usize, to: usize| {
            crate::parse(&rewritten[from..to])
                .map(|p| Sym::from_expr(&p.expr))
                .map_err(|mut e| {
                    e.span = e.span.shifted(from);
                    DsolveError::Formula(relocate(e, text, func, &edits))
                })
        };
        let residual = match equals_signs(rewritten.as_bytes()).as_slice() {
            [] => parse(0, rewritten.len())?,
            [i] => Sym::difference(parse(0, *i)?, parse(i + 1, rewritten.len())?),
            _ => {
                return Err(DsolveError::Invalid(format!(
                    "`{text}` has more than one `=`: write one equation, `lhs = rhs`"
                )));
            }
        };
        let order = (1..=8)
            .rev()
            .find(|&k| !residual.free_of(&derivative_name(func, k)))
            .unwrap_or(0);
        if order == 0 {
            return Err(DsolveError::Invalid(format!(
                "`{text}` has no derivative of `{func}`: write it with primes, as in \
                 {func}' = -k*{func} (or name the function with --func)"
            )));
        }
        Ok(Ode {
            func: func.to_string(),
            var: var.to_string(),
            order,
            residual,
        })
    }

    /// The same equation with values (or formulas) for some names.
    #[must_use]
    pub fn with_values(&self, values: &[(String, Sym)]) -> Ode {
        let mut residual = self.residual.clone();
        for (k, v) in values {
            residual = residual.substitute(k, v);
        }
        Ode {
            residual,
            ..self.clone()
        }
    }

    /// The equation solved for its highest derivative, `x^(n) = f(t, x, …, x^(n-1))`, when it
    /// is linear in it (what a numerical integrator needs).
    pub fn explicit(&self) -> Option<Sym> {
        let top = derivative_name(&self.func, self.order);
        let c = crate::sym::poly::coefficients(&self.residual, &top)?;
        if c.len() != 2 || c[1].is_zero() || !c[1].free_of(&top) {
            return None;
        }
        Some(Sym::negate(Sym::quotient(c[0].clone(), c[1].clone())))
    }

    /// The residual with `solution` (and its derivatives) put in for the function.
    pub fn residual_of(&self, solution: &Sym) -> Sym {
        let mut r = self.residual.clone();
        let mut d = solution.clone();
        for k in 0..=self.order {
            r = r.substitute(&derivative_name(&self.func, k), &d);
            d = d.diff(&self.var);
        }
        r
    }

    /// The names other than the function, its derivatives and the variable.
    pub fn parameters(&self) -> Vec<String> {
        let placeholder = format!("__{}_d", self.func);
        self.residual
            .names()
            .into_iter()
            .filter(|n| *n != self.func && *n != self.var && !n.starts_with(&placeholder))
            .collect()
    }
}
