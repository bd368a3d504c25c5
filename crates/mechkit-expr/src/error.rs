//! Errors in formulas, each pointing at the offending part of the text.

use std::fmt;

use crate::span::{Span, caret_lines};
use crate::suggest::did_you_mean;

/// What went wrong in a formula.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ExprErrorKind {
    /// The formula is empty.
    Empty,
    /// A character that is not part of the language.
    UnexpectedChar(char),
    /// `=` where `==` (comparison) was probably meant.
    SingleEquals,
    /// A number that does not parse.
    BadNumber(String),
    /// A number too large for a double (`1e309`): it would be read as infinity.
    NumberTooLarge(String),
    /// A token where something else was expected.
    UnexpectedToken {
        /// The token found.
        found: String,
        /// What would have fit.
        expected: String,
    },
    /// The text ended where more was expected.
    UnexpectedEnd {
        /// What would have fit.
        expected: String,
    },
    /// Two operands side by side, e.g. `2 x`.
    MissingOperator {
        /// The operand after the gap.
        found: String,
    },
    /// An unclosed `(`.
    UnclosedParen,
    /// A call of a function that does not exist.
    UnknownFunction {
        /// The name used.
        name: String,
        /// Known functions with similar names.
        suggestions: Vec<String>,
    },
    /// A function called with the wrong number of arguments.
    Arity {
        /// The function.
        name: String,
        /// What it takes.
        expected: String,
        /// How many it got.
        found: usize,
    },
    /// A name that is not defined where the formula is used.
    UndefinedName {
        /// The name.
        name: String,
        /// Defined names that are close to it.
        suggestions: Vec<String>,
        /// Extra context: what names are available here.
        context: Option<String>,
    },
    /// A name used as a value that is a function.
    FunctionAsValue(String),
    /// The formula nests deeper than [`crate::MAX_DEPTH`] levels (a sum or product of more
    /// terms than that is as deep as it is long).
    TooDeep,
    /// Dimensions that do not fit together (e.g. metres plus seconds).
    Dimension {
        /// What does not fit.
        message: String,
        /// What would fix it.
        hint: Option<String>,
    },
}

/// An error in a formula: what, where (a byte span into the formula), and the formula itself.
#[derive(Debug, Clone, PartialEq)]
pub struct ExprError {
    /// What went wrong.
    pub kind: ExprErrorKind,
    /// Where, as bytes of `source`.
    pub span: Span,
    /// The formula.
    pub source: String,
}

impl ExprError {
    /// An error of `kind` at `span` of `source`.
    pub fn new(kind: ExprErrorKind, span: Span, source: &str) -> Self {
        Self {
            kind,
            span,
            source: source.to_string(),
        }
    }

    /// The same error with the name `from` written `to` in its message and hint: a caller that
    /// rewrote a formula before parsing it (a placeholder for a part it evaluates itself) shows
    /// the user's own text again.
    #[must_use]
    pub fn with_text_restored(mut self, from: &str, to: &str) -> Self {
        let fix = |s: &mut String| {
            if s.contains(from) {
                *s = s.replace(from, to);
            }
        };
        match &mut self.kind {
            ExprErrorKind::BadNumber(s)
            | ExprErrorKind::NumberTooLarge(s)
            | ExprErrorKind::FunctionAsValue(s) => fix(s),
            ExprErrorKind::UnexpectedToken { found, expected } => {
                fix(found);
                fix(expected);
            }
            ExprErrorKind::UnexpectedEnd { expected } => fix(expected),
            ExprErrorKind::MissingOperator { found } => fix(found),
            ExprErrorKind::UnknownFunction { name, suggestions } => {
                fix(name);
                suggestions.iter_mut().for_each(fix);
            }
            ExprErrorKind::Arity { name, expected, .. } => {
                fix(name);
                fix(expected);
            }
            ExprErrorKind::UndefinedName {
                name,
                suggestions,
                context,
            } => {
                fix(name);
                suggestions.iter_mut().for_each(fix);
                if let Some(c) = context {
                    fix(c);
                }
            }
            ExprErrorKind::Dimension { message, hint } => {
                fix(message);
                if let Some(h) = hint {
                    fix(h);
                }
            }
            ExprErrorKind::Empty
            | ExprErrorKind::UnexpectedChar(_)
            | ExprErrorKind::SingleEquals
            | ExprErrorKind::UnclosedParen
            | ExprErrorKind::TooDeep => {}
        }
        self
    }

    /// 1-based column of the error in the formula.
    pub fn column(&self) -> usize {
        self.span.column(&self.source)
    }

    /// The problem in one line, without location.
    pub fn message(&self) -> String {
        match &self.kind {
            ExprErrorKind::Empty => "the formula is empty".into(),
            ExprErrorKind::UnexpectedChar(c) => format!("unexpected character `{c}`"),
            ExprErrorKind::SingleEquals => "`=` is not an operator here".into(),
            ExprErrorKind::BadNumber(s) => format!("`{s}` is not a number"),
            ExprErrorKind::NumberTooLarge(s) => {
                format!("`{s}` is too large for a double-precision number (at most about 1.8e308)")
            }
            ExprErrorKind::UnexpectedToken { found, expected } => {
                format!("expected {expected}, found {found}")
            }
            ExprErrorKind::UnexpectedEnd { expected } => {
                format!("the formula ends where {expected} was expected")
            }
            ExprErrorKind::MissingOperator { found } => {
                format!("missing operator before {found}")
            }
            ExprErrorKind::UnclosedParen => "this `(` is never closed".into(),
            ExprErrorKind::UnknownFunction { name, .. } => format!("unknown function `{name}`"),
            ExprErrorKind::Arity {
                name,
                expected,
                found,
            } => format!("`{name}` takes {expected}, but {found} were given"),
            ExprErrorKind::UndefinedName { name, .. } => format!("undefined name `{name}`"),
            ExprErrorKind::FunctionAsValue(name) => {
                format!("`{name}` is a function; call it as `{name}(…)`")
            }
            ExprErrorKind::TooDeep => format!(
                "the formula nests more than {} levels deep here, the most a formula may",
                crate::MAX_DEPTH
            ),
            ExprErrorKind::Dimension { message, .. } => message.clone(),
        }
    }

    /// What would fix it, when something useful can be said.
    pub fn hint(&self) -> Option<String> {
        match &self.kind {
            ExprErrorKind::Empty => Some("write a formula, e.g. `-k*x` or `2*t + 1`".into()),
            ExprErrorKind::UnexpectedChar(_) => Some(
                "formulas use numbers, names, `+ - * / ^`, comparisons (`<`, `==`, …), \
                 `and`, `or`, `not`, parentheses and function calls such as `sin(x)`"
                    .into(),
            ),
            ExprErrorKind::UnexpectedToken { .. } => {
                Some("check for a missing or doubled operator, or a stray `)` or `,`".into())
            }
            ExprErrorKind::SingleEquals => Some("write `==` to compare".into()),
            ExprErrorKind::NumberTooLarge(_) => Some(
                "write it in other units, or scale the formula (divide it by a constant), so \
                 that its numbers stay below 1e308"
                    .into(),
            ),
            ExprErrorKind::MissingOperator { found } => {
                let unit = found
                    .strip_prefix("name `")
                    .and_then(|s| s.strip_suffix('`'))
                    .filter(|name| crate::units::Unit::parse(name).is_ok());
                Some(match unit {
                    Some(u) => format!(
                        "write `*` to multiply; if `{u}` is meant as a unit: formulas have no \
                         units, so give the value a name with its unit (in a scenario, \
                         `c = \"1 {u}\"` in [constants]) and use the name"
                    ),
                    None => "write `*` to multiply, e.g. `2*x` rather than `2 x`".into(),
                })
            }
            ExprErrorKind::UnknownFunction { suggestions, .. } => did_you_mean(suggestions)
                .or_else(|| {
                    let names: Vec<&str> = crate::ast::Func::ALL.iter().map(|f| f.name()).collect();
                    Some(format!("functions: {}", names.join(", ")))
                }),
            ExprErrorKind::UndefinedName {
                suggestions,
                context,
                ..
            } => match (did_you_mean(suggestions), context) {
                (Some(s), Some(c)) => Some(format!("{s} ({c})")),
                (Some(s), None) => Some(s),
                (None, Some(c)) => Some(c.clone()),
                (None, None) => None,
            },
            ExprErrorKind::Dimension { hint, .. } => hint.clone(),
            ExprErrorKind::TooDeep => Some(
                "every operator, sign, function call and pair of parentheses is a level over its \
                 operands, so a sum or product of many terms is as deep as it is long: group the \
                 terms in parentheses, `(a + b + …) + (c + d + …)`, or give parts of the formula \
                 names of their own (in a scenario, [constants])"
                    .into(),
            ),
            ExprErrorKind::UnexpectedEnd { .. } | ExprErrorKind::UnclosedParen => {
                Some("check that every `(` has its `)` and every operator its operands".into())
            }
            _ => None,
        }
    }

    /// The formula with a caret line under the problem.
    pub fn snippet(&self) -> String {
        caret_lines(&self.source, self.span)
    }
}

impl fmt::Display for ExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "{} (column {})", self.message(), self.column())?;
        write!(f, "  {}", self.snippet().replace('\n', "\n  "))?;
        if let Some(h) = self.hint() {
            write!(f, "\n  hint: {h}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ExprError {}

#[cfg(test)]
mod tests {
    use super::{ExprError, ExprErrorKind};
    use crate::Span;

    /// Issue 26: a caller that parsed `_r0___ + _r1_____` for `max(x) + final(v)` showed its
    /// placeholders in the message; `with_text_restored` puts the user's text back.
    #[test]
    fn issue_026_placeholders_are_restored_in_messages_and_hints() {
        let e = ExprError::new(
            ExprErrorKind::Dimension {
                message: "cannot add `_r0___` (m) and `_r1_____` (m/s)".into(),
                hint: Some("check `_r1_____`".into()),
            },
            Span::new(0, 17),
            "max(x) + final(v)",
        )
        .with_text_restored("_r1_____", "final(v)")
        .with_text_restored("_r0___", "max(x)");
        assert_eq!(e.message(), "cannot add `max(x)` (m) and `final(v)` (m/s)");
        assert_eq!(e.hint().as_deref(), Some("check `final(v)`"));
    }
}
