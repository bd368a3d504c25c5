//! Reading the TOML document: tables with their spans, unknown keys reported with the nearest
//! valid key, values of the wrong type reported with what was expected.

use std::ops::Range;

use mechkit_expr::{did_you_mean, nearest};
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use super::error::{ErrorKind, Location, ScenarioError};

/// The scenario text and its name, for locating errors, and its `units`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Source<'a> {
    pub name: &'a str,
    pub text: &'a str,
    pub units: mechkit_expr::units::UnitSystem,
}

impl Source<'_> {
    /// Line, column and line text of a byte span.
    pub fn location(&self, span: Range<usize>) -> Location {
        let start = span.start.min(self.text.len());
        let mut s = start;
        while s > 0 && !self.text.is_char_boundary(s) {
            s -= 1;
        }
        let line_start = self.text[..s].rfind('\n').map_or(0, |i| i + 1);
        let line_end = self.text[s..].find('\n').map_or(self.text.len(), |i| s + i);
        let line = self.text[..s].matches('\n').count() + 1;
        let line_text = self.text[line_start..line_end].trim_end_matches('\r');
        let column = self.text[line_start..s].chars().count() + 1;
        let end = span.end.clamp(s, line_end);
        let mut e = end;
        while e > s && !self.text.is_char_boundary(e) {
            e -= 1;
        }
        let width = self.text[s..e].chars().count().max(1);
        Location {
            file: self.name.to_string(),
            line,
            column,
            line_text: line_text.to_string(),
            width,
        }
    }

    /// An error at `span`.
    pub fn error(
        &self,
        kind: ErrorKind,
        message: impl Into<String>,
        span: Range<usize>,
    ) -> ScenarioError {
        ScenarioError {
            kind,
            message: message.into(),
            location: Some(Box::new(self.location(span))),
            hint: None,
        }
    }

    /// Byte offset where the content of the string value at `span` starts (after its quotes).
    pub fn string_content_start(&self, span: &Range<usize>) -> usize {
        let raw = &self.text[span.start.min(self.text.len())..];
        if raw.starts_with("\"\"\"") || raw.starts_with("'''") {
            let after = span.start + 3;
            // a newline right after the opening delimiter is trimmed
            if self.text[after..].starts_with('\n') {
                after + 1
            } else if self.text[after..].starts_with("\r\n") {
                after + 2
            } else {
                after
            }
        } else if raw.starts_with('"') || raw.starts_with('\'') {
            span.start + 1
        } else {
            span.start
        }
    }
}

/// A TOML value with its span.
pub(crate) type Value<'a> = Spanned<DeValue<'a>>;

/// The TOML type of a value, for messages.
pub(crate) fn type_name(v: &DeValue<'_>) -> &'static str {
    match v {
        DeValue::String(_) => "a string",
        DeValue::Integer(_) => "an integer",
        DeValue::Float(_) => "a number",
        DeValue::Boolean(_) => "a boolean",
        DeValue::Datetime(_) => "a date",
        DeValue::Array(_) => "an array",
        DeValue::Table(_) => "a table",
    }
}

/// A table of the document, with a description for messages ("[[body]] 'feather'").
pub(crate) struct Table<'s, 'a> {
    pub src: Source<'s>,
    pub entries: &'s DeTable<'a>,
    pub span: Range<usize>,
    pub what: String,
}

impl<'s, 'a> Table<'s, 'a> {
    pub fn new(
        src: Source<'s>,
        entries: &'s DeTable<'a>,
        span: Range<usize>,
        what: impl Into<String>,
    ) -> Self {
        Self {
            src,
            entries,
            span,
            what: what.into(),
        }
    }

    /// Fails on the first key not in `allowed`, naming the nearest allowed key.
    pub fn check_keys(&self, allowed: &[&str]) -> Result<(), ScenarioError> {
        for (key, _) in self.entries {
            let name: &str = key.get_ref();
            if !allowed.contains(&name) {
                let suggestions = nearest(name, allowed.iter().copied());
                let hint = did_you_mean(&suggestions).unwrap_or_else(|| {
                    format!("the keys of {} are: {}", self.what, allowed.join(", "))
                });
                return Err(self
                    .src
                    .error(
                        ErrorKind::UnknownKey,
                        format!("unknown key `{name}` in {}", self.what),
                        key.span(),
                    )
                    .with_hint(hint));
            }
        }
        Ok(())
    }

    pub fn get(&self, key: &str) -> Option<&'s Value<'a>> {
        self.entries.get(key)
    }

    /// Span of a key's name, or of the table if the key is absent.
    pub fn key_span(&self, key: &str) -> Range<usize> {
        self.entries
            .get_key_value(key)
            .map_or_else(|| self.span.clone(), |(k, _)| k.span())
    }

    pub fn wrong_type(&self, key: &str, v: &Value<'a>, expected: &str) -> ScenarioError {
        self.src.error(
            ErrorKind::WrongType,
            format!(
                "`{key}` in {} must be {expected}, not {}",
                self.what,
                type_name(v.get_ref())
            ),
            v.span(),
        )
    }

    /// A vector-like value with `found` components in a scenario of `dim` dimensions.
    pub fn component_count(
        &self,
        key: &str,
        found: usize,
        dim: usize,
        span: Range<usize>,
    ) -> ScenarioError {
        self.src.error(
            ErrorKind::Invalid,
            format!(
                "`{key}` has {found} components, but the scenario has {dim} dimension{}",
                if dim == 1 { "" } else { "s" }
            ),
            span,
        )
    }

    pub fn missing(&self, key: &str, example: &str) -> ScenarioError {
        self.src
            .error(
                ErrorKind::Missing,
                format!("{} has no `{key}`", self.what),
                self.span.clone(),
            )
            .with_hint(format!("add `{key} = {example}`"))
    }

    /// A string value.
    pub fn string(&self, key: &str) -> Result<Option<(&'s str, Range<usize>)>, ScenarioError> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => match v.get_ref() {
                DeValue::String(s) => Ok(Some((s.as_ref(), v.span()))),
                _ => Err(self.wrong_type(key, v, "a string")),
            },
        }
    }

    /// A non-negative integer.
    pub fn count(&self, key: &str) -> Result<Option<(u64, Range<usize>)>, ScenarioError> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => match v.get_ref() {
                DeValue::Integer(i) => u64::from_str_radix(i.as_str(), i.radix())
                    .map(|n| Some((n, v.span())))
                    .map_err(|_| {
                        self.src.error(
                            ErrorKind::Invalid,
                            format!("`{key}` must be a non-negative whole number, not {i}"),
                            v.span(),
                        )
                    }),
                _ => Err(self.wrong_type(key, v, "a whole number")),
            },
        }
    }

    /// A sub-table.
    pub fn table(&self, key: &str) -> Result<Option<Table<'s, 'a>>, ScenarioError> {
        match self.get(key) {
            None => Ok(None),
            Some(v) => match v.get_ref() {
                DeValue::Table(t) => {
                    Ok(Some(Table::new(self.src, t, v.span(), format!("[{key}]"))))
                }
                _ => Err(self.wrong_type(key, v, &format!("a table (`[{key}]`)"))),
            },
        }
    }

    /// An array of tables (`[[key]]`), each described as "[[key]] #n".
    pub fn tables(&self, key: &str) -> Result<Vec<Table<'s, 'a>>, ScenarioError> {
        match self.get(key) {
            None => Ok(Vec::new()),
            Some(v) => match v.get_ref() {
                DeValue::Array(items) => items
                    .iter()
                    .enumerate()
                    .map(|(i, item)| match item.get_ref() {
                        DeValue::Table(t) => Ok(Table::new(
                            self.src,
                            t,
                            item.span(),
                            format!("[[{key}]] #{}", i + 1),
                        )),
                        _ => Err(self.wrong_type(key, item, &format!("a table (`[[{key}]]`)"))),
                    })
                    .collect(),
                DeValue::Table(t) => {
                    Ok(vec![Table::new(self.src, t, v.span(), format!("[{key}]"))])
                }
                _ => Err(self.wrong_type(key, v, &format!("an array of tables (`[[{key}]]`)"))),
            },
        }
    }
}

/// Strings with their spans.
pub(crate) type StringList<'s> = Vec<(&'s str, Range<usize>)>;

/// A string or a list of strings (e.g. `on = "ball"` or `on = ["a", "b"]`), with spans.
pub(crate) fn string_list<'s>(
    t: &Table<'s, '_>,
    key: &str,
) -> Result<Option<StringList<'s>>, ScenarioError> {
    let Some(v) = t.get(key) else {
        return Ok(None);
    };
    match v.get_ref() {
        DeValue::String(s) => Ok(Some(vec![(s.as_ref(), v.span())])),
        DeValue::Array(items) => items
            .iter()
            .map(|item| match item.get_ref() {
                DeValue::String(s) => Ok((s.as_ref(), item.span())),
                _ => Err(t.wrong_type(key, item, "a string or a list of strings")),
            })
            .collect::<Result<Vec<_>, _>>()
            .map(Some),
        _ => Err(t.wrong_type(key, v, "a string or a list of strings")),
    }
}
