//! Errors in scenario files, each with the file, line and column, the line itself with a caret
//! under the problem, and a hint.

use std::fmt;

/// What kind of problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The file is not valid TOML.
    Syntax,
    /// A key that the schema does not have.
    UnknownKey,
    /// A required key is absent.
    Missing,
    /// A value of the wrong TOML type.
    WrongType,
    /// A unit that does not exist.
    Unit,
    /// A value or formula of the wrong dimension.
    Dimension,
    /// A formula that does not parse or names something undefined.
    Formula,
    /// A value outside its valid range (negative mass, zero step).
    Invalid,
    /// The file or an output could not be read or written.
    Io,
}

/// A place in a source file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// File name as given.
    pub file: String,
    /// 1-based line.
    pub line: usize,
    /// 1-based column (in characters).
    pub column: usize,
    /// The text of the line.
    pub line_text: String,
    /// How many characters to underline.
    pub width: usize,
}

/// An error in a scenario, or in reading or writing its files.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenarioError {
    /// What kind of problem.
    pub kind: ErrorKind,
    /// What is wrong, in one line.
    pub message: String,
    /// Where, when it is in a file.
    pub location: Option<Box<Location>>,
    /// What would fix it.
    pub hint: Option<String>,
}

impl ScenarioError {
    /// An error without a location.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Self {
            kind,
            message: message.into(),
            location: None,
            hint: None,
        }
    }

    /// Adds a hint.
    #[must_use]
    pub fn with_hint(mut self, hint: impl Into<String>) -> Self {
        self.hint = Some(hint.into());
        self
    }

    /// Adds a hint if there is one.
    #[must_use]
    pub fn with_hint_opt(mut self, hint: Option<String>) -> Self {
        if hint.is_some() {
            self.hint = hint;
        }
        self
    }
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.message)?;
        if let Some(loc) = &self.location {
            let number = loc.line.to_string();
            let pad = " ".repeat(number.len());
            write!(f, "\n{pad}--> {}:{}:{}", loc.file, loc.line, loc.column)?;
            write!(f, "\n{pad} |")?;
            let (text, at, width) = mechkit_expr::span::excerpt(
                &loc.line_text,
                loc.column.saturating_sub(1),
                loc.width.max(1),
            );
            write!(f, "\n{number} | {text}")?;
            write!(f, "\n{pad} | {}{}", " ".repeat(at), "^".repeat(width))?;
        }
        if let Some(h) = &self.hint {
            let indent = self
                .location
                .as_ref()
                .map_or(1, |l| l.line.to_string().len());
            write!(f, "\n{} = hint: {h}", " ".repeat(indent))?;
        }
        Ok(())
    }
}

impl std::error::Error for ScenarioError {}

/// The message for an amount that must be positive and invertible ([`crate::invertible`]):
/// `what` (`the mass of \`ball\``), its value and unit (`kg`, or empty).
pub(crate) fn positive_message(what: &str, value: crate::Real, unit: &str) -> String {
    let value = crate::error::short(value);
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    if value
        .parse::<crate::Real>()
        .is_ok_and(|v| v > 0.0 && v.is_finite())
    {
        format!(
            "{what} must be at least 2.2e-308{unit} (smaller, its reciprocal overflows), not {value}{unit}"
        )
    } else {
        format!("{what} must be positive, not {value}{unit}")
    }
}
