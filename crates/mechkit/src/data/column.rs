//! Referring to a column: by its number as users count (from 1) or by its header name.

use std::fmt;
use std::str::FromStr;

use super::DataError;

/// A column of a [`Table`](super::Table), by position or by name.
///
/// Users count columns from 1: [`ColumnRef::parse`] reads `"1"` as the first column, which is
/// `Index(0)`. The `Index` inside is 0-based, as Rust indices are, and [`Display`](fmt::Display)
/// prints it 1-based again.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ColumnRef {
    /// The column at this 0-based position (`Index(0)` is what users call column 1).
    Index(usize),
    /// The column with this header name (see [`ColumnRef::parse`] for how names match).
    Name(String),
}

impl ColumnRef {
    /// Reads a user's column reference: digits are a column number counted from 1 (`"2"` is
    /// `Index(1)`); anything else is a name, trimmed.
    ///
    /// A name matches a header name exactly, else ignoring case, else by its alias: the part of
    /// the header name before a space or bracket (`t` for `t [s]`, `F` for `F(N)`), again
    /// exactly and then ignoring case. A name matching several columns equally well is an error.
    ///
    /// # Example
    /// ```
    /// use mechkit::data::ColumnRef;
    ///
    /// assert_eq!(ColumnRef::parse("2").unwrap(), ColumnRef::Index(1));
    /// assert_eq!(ColumnRef::parse(" F ").unwrap(), ColumnRef::Name("F".into()));
    /// assert!(ColumnRef::parse("0").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Self, DataError> {
        let text = text.trim();
        if !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit()) {
            return match text.parse::<usize>() {
                Ok(0) => Err(DataError::ColumnZero),
                Ok(n) => Ok(Self::Index(n - 1)),
                // More digits than a usize holds: no file has that many columns.
                Err(_) => Ok(Self::Index(usize::MAX)),
            };
        }
        Ok(Self::Name(text.to_string()))
    }

    /// A 0-based index from a 1-based column number.
    ///
    /// # Panics
    /// If `number` is 0.
    pub fn number(number: usize) -> Self {
        assert!(number > 0, "column numbers count from 1");
        Self::Index(number - 1)
    }
}

impl FromStr for ColumnRef {
    type Err = DataError;

    /// As [`ColumnRef::parse`].
    fn from_str(text: &str) -> Result<Self, DataError> {
        Self::parse(text)
    }
}

impl fmt::Display for ColumnRef {
    /// `column 2` for `Index(1)`, the name itself for a name.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Index(i) => write!(f, "column {}", i.saturating_add(1)),
            Self::Name(n) => f.write_str(n),
        }
    }
}

/// The short name a header name also answers to: the text before the first space, `[` or `(`
/// (`t` for `t [s]`). `None` if that is empty or the whole name.
pub(crate) fn alias(name: &str) -> Option<&str> {
    let end = name.find(|c: char| c.is_whitespace() || c == '[' || c == '(')?;
    let short = name[..end].trim();
    (!short.is_empty()).then_some(short)
}

/// The position of the column called `name`, trying exact names, names ignoring case, aliases,
/// aliases ignoring case, in that order. `Err` holds the names matched when more than one does.
pub(crate) fn find(names: &[String], name: &str) -> Result<Option<usize>, Vec<String>> {
    type Rule = fn(&str, &str) -> bool;
    let exact: Rule = |header, name| header == name;
    let caseless: Rule = |header, name| header.to_lowercase() == name.to_lowercase();
    let alias_exact: Rule = |header, name| alias(header) == Some(name);
    let alias_caseless: Rule =
        |header, name| alias(header).is_some_and(|a| a.to_lowercase() == name.to_lowercase());
    for rule in [exact, caseless, alias_exact, alias_caseless] {
        let hits: Vec<usize> = (0..names.len())
            .filter(|&i| rule(&names[i], name))
            .collect();
        match hits.as_slice() {
            [] => {}
            [one] => return Ok(Some(*one)),
            many => return Err(many.iter().map(|&i| names[i].clone()).collect()),
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(list: &[&str]) -> Vec<String> {
        list.iter().map(ToString::to_string).collect()
    }

    #[test]
    fn parse_counts_from_one() {
        assert_eq!(ColumnRef::parse("1").unwrap(), ColumnRef::Index(0));
        assert_eq!(ColumnRef::parse("12").unwrap(), ColumnRef::Index(11));
        assert_eq!(
            ColumnRef::parse("t [s]").unwrap(),
            ColumnRef::Name("t [s]".into())
        );
        assert_eq!(
            ColumnRef::parse("-1").unwrap(),
            ColumnRef::Name("-1".into())
        );
        assert_eq!(ColumnRef::Index(1).to_string(), "column 2");
        assert_eq!(ColumnRef::number(3), ColumnRef::Index(2));
    }

    #[test]
    fn aliases() {
        assert_eq!(alias("t [s]"), Some("t"));
        assert_eq!(alias("F(N)"), Some("F"));
        assert_eq!(alias("time"), None);
        assert_eq!(alias("[s]"), None);
    }

    #[test]
    fn matching_order() {
        let header = names(&["t [s]", "T", "x [m]", "v"]);
        assert_eq!(find(&header, "T"), Ok(Some(1)));
        assert_eq!(
            find(&header, "t"),
            Ok(Some(1)),
            "a name ignoring case before an alias"
        );
        assert_eq!(find(&header, "x"), Ok(Some(2)));
        assert_eq!(find(&header, "X"), Ok(Some(2)));
        assert_eq!(find(&header, "V"), Ok(Some(3)));
        assert_eq!(find(&header, "y"), Ok(None));
        let twice = names(&["x [m]", "x [km]"]);
        assert_eq!(find(&twice, "x"), Err(twice.clone()));
        assert_eq!(find(&twice, "x [km]"), Ok(Some(1)));
    }
}
