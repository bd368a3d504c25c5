//! A formula as the user typed it: source text, expression tree, and where each name occurs,
//! so that every later error (an undefined name, a dimension mismatch) can point at the text.

use crate::ast::{Expr, Func};
use crate::compile::Program;
use crate::error::{ExprError, ExprErrorKind};
use crate::parser::parse;
use crate::scope::{Scope, builtin_constant};
use crate::span::Span;
use crate::suggest::nearest;

/// A parsed formula.
///
/// # Example
/// ```
/// use mechkit_expr::{Formula, MapScope};
/// let f = Formula::parse("-m*g*Dmg*v*abs(v)").unwrap();
/// let scope = MapScope::new()
///     .constant("m", 1e-3).constant("g", 9.8).constant("Dmg", 4.0)
///     .slot("v", 0);
/// let force = f.compile(&scope).unwrap();
/// assert!((force.eval(&[-0.5]) - 9.8e-3).abs() < 1e-15);
///
/// let err = Formula::parse("-m*g*Dmgg*v").unwrap().compile(&scope).unwrap_err();
/// assert_eq!(err.column(), 6);
/// assert!(err.to_string().contains("did you mean `Dmg`?"));
/// ```
#[derive(Debug, Clone)]
pub struct Formula {
    source: String,
    expr: Expr,
    names: Vec<(String, Span)>,
}

impl Formula {
    /// Parses `source`.
    pub fn parse(source: &str) -> Result<Formula, ExprError> {
        let parsed = parse(source)?;
        Ok(Formula {
            source: source.to_string(),
            expr: parsed.expr,
            names: parsed.names,
        })
    }

    /// The text as given.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The expression tree.
    pub fn expr(&self) -> &Expr {
        &self.expr
    }

    /// Distinct names used as values, in order of first use.
    pub fn names(&self) -> Vec<&str> {
        let mut out: Vec<&str> = Vec::new();
        for (n, _) in &self.names {
            if !out.contains(&n.as_str()) {
                out.push(n);
            }
        }
        out
    }

    /// Where `name` first occurs.
    pub fn span_of(&self, name: &str) -> Option<Span> {
        self.names.iter().find(|(n, _)| n == name).map(|(_, s)| *s)
    }

    /// The whole formula's span.
    pub fn full_span(&self) -> Span {
        Span::new(0, self.source.len())
    }

    /// An error of `kind` located at `span` of this formula.
    pub fn error(&self, kind: ExprErrorKind, span: Span) -> ExprError {
        ExprError::new(kind, span, &self.source)
    }

    /// Checks that every name is defined in `scope` (or is `pi`/`e`); the error names the first
    /// one that is not, with its column and the nearest defined names.
    pub fn check_names(&self, scope: &dyn Scope) -> Result<(), ExprError> {
        for (name, span) in &self.names {
            if scope.lookup(name).is_some() || builtin_constant(name).is_some() {
                continue;
            }
            let kind = if Func::from_name(name).is_some() || Func::reciprocal_of(name).is_some() {
                ExprErrorKind::FunctionAsValue(name.clone())
            } else {
                let candidates = scope.candidates();
                ExprErrorKind::UndefinedName {
                    name: name.clone(),
                    suggestions: nearest(name, candidates.iter().map(String::as_str)),
                    context: scope.describe(),
                }
            };
            return Err(self.error(kind, *span));
        }
        Ok(())
    }

    /// Compiles for fast evaluation against `scope`.
    pub fn compile(&self, scope: &dyn Scope) -> Result<Program, ExprError> {
        self.check_names(scope)?;
        Program::compile(&self.expr, scope).map_err(|name| {
            let span = self.span_of(&name).unwrap_or(self.full_span());
            self.error(
                ExprErrorKind::UndefinedName {
                    name,
                    suggestions: Vec::new(),
                    context: None,
                },
                span,
            )
        })
    }

    /// Evaluates once, looking names up with `env` (then `pi` and `e`); an unknown name is a
    /// located error.
    pub fn eval_with(&self, env: &dyn Fn(&str) -> Option<f64>) -> Result<f64, ExprError> {
        let lookup = |n: &str| env(n).or_else(|| builtin_constant(n));
        self.expr.eval_with(&lookup).map_err(|name| {
            let span = self.span_of(&name).unwrap_or(self.full_span());
            self.error(
                ExprErrorKind::UndefinedName {
                    name,
                    suggestions: Vec::new(),
                    context: None,
                },
                span,
            )
        })
    }
}

impl std::fmt::Display for Formula {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.source)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scope::MapScope;

    #[test]
    fn undefined_name_error_has_column_and_suggestion() {
        let scope = MapScope::new().slot("feather.v", 0).constant("g", 9.8);
        let err = Formula::parse("g*feather.vv")
            .unwrap()
            .compile(&scope)
            .unwrap_err();
        assert_eq!(err.column(), 3);
        assert_eq!(err.hint().as_deref(), Some("did you mean `feather.v`?"));
        let text = err.to_string();
        assert!(
            text.contains("undefined name `feather.vv` (column 3)"),
            "{text}"
        );
        assert!(text.contains("g*feather.vv\n    ^^^^^^^^^^"), "{text}");
    }

    #[test]
    fn function_name_used_as_value() {
        let err = Formula::parse("sin + 1")
            .unwrap()
            .compile(&MapScope::new())
            .unwrap_err();
        assert_eq!(err.kind, ExprErrorKind::FunctionAsValue("sin".into()));
    }

    #[test]
    fn scope_overrides_builtin_e() {
        let scope = MapScope::new().constant("e", 0.8);
        let p = Formula::parse("e").unwrap().compile(&scope).unwrap();
        assert_eq!(p.as_constant(), Some(0.8));
    }
}
