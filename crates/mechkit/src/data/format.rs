//! How a line of a data file splits into cells: the separator (detected once per file), double
//! quotes around names, and what counts as a number.

use crate::Real;

/// What separates the cells of a row, detected once per file.
///
/// Detection looks at every line that is not blank or a comment, ignoring text inside double
/// quotes: a `;` anywhere makes the file semicolon-separated (spreadsheets that write decimal
/// commas separate with semicolons, so `1,5` then reads as 1.5); otherwise a `,` makes it
/// comma-separated; otherwise cells are separated by runs of spaces and tabs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Separator {
    /// Runs of spaces and tabs (the course's `.d` and `.txt` files, and tab-separated ones).
    /// A header line with tabs between its names is split at tabs only, so that names with
    /// spaces (`t [s]`) stay whole; in a header without tabs, a unit in brackets or parentheses
    /// joins the name before it (`t [s]  F (N)` is two names).
    Whitespace,
    /// Commas (CSV). Every comma separates, so `1,,2` has an empty middle cell.
    Comma,
    /// Semicolons; a decimal comma in a number is read as a point.
    Semicolon,
}

impl Separator {
    /// The separator's name: `whitespace`, `comma`, `semicolon`, `tab`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Whitespace => "whitespace",
            Self::Comma => "comma",
            Self::Semicolon => "semicolon",
        }
    }

    /// Detects the separator of the given content lines (see [`Separator`]).
    pub(crate) fn detect<'a>(lines: impl IntoIterator<Item = &'a str>) -> Self {
        let mut comma = false;
        for line in lines {
            let mut quoted = false;
            for c in line.chars() {
                match c {
                    '"' => quoted = !quoted,
                    ';' if !quoted => return Self::Semicolon,
                    ',' if !quoted => comma = true,
                    _ => {}
                }
            }
        }
        if comma { Self::Comma } else { Self::Whitespace }
    }

    /// Reads a cell as a number (NaN and infinities included; the caller rejects them).
    pub(crate) fn number(self, text: &str) -> Option<Real> {
        if let Ok(x) = text.parse::<Real>() {
            return Some(x);
        }
        if self == Self::Semicolon && text.matches(',').count() == 1 && !text.contains('.') {
            return text.replace(',', ".").parse().ok();
        }
        None
    }
}

/// One cell of a row.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Cell {
    /// The text, trimmed, without surrounding double quotes.
    pub text: String,
    /// 1-based character column where the cell starts.
    pub column: usize,
}

/// Where a line splits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Splitter {
    /// Runs of spaces and tabs.
    Blanks,
    /// Runs of tabs.
    Tabs,
    /// Every occurrence of the character.
    Char(char),
}

impl Splitter {
    fn of(sep: Separator) -> Self {
        match sep {
            Separator::Whitespace => Self::Blanks,
            Separator::Comma => Self::Char(','),
            Separator::Semicolon => Self::Char(';'),
        }
    }

    fn splits_at(self, c: char) -> bool {
        match self {
            Self::Blanks => c == ' ' || c == '\t',
            Self::Tabs => c == '\t',
            Self::Char(s) => c == s,
        }
    }

    /// Whether a run of separators counts as one.
    fn merges_runs(self) -> bool {
        matches!(self, Self::Blanks | Self::Tabs)
    }
}

/// Splits a data line into cells (see [`split_with`]).
pub(crate) fn split(line: &str, sep: Separator) -> Vec<Cell> {
    split_with(line, Splitter::of(sep))
}

/// Splits a header line into names: as a data line, except that a whitespace-separated header
/// with tabs between names splits at tabs only, and one without joins units to names (see
/// [`Separator::Whitespace`]).
pub(crate) fn split_header(line: &str, sep: Separator) -> Vec<Cell> {
    if sep != Separator::Whitespace {
        split(line, sep)
    } else if line.trim().contains('\t') {
        split_with(line, Splitter::Tabs)
    } else {
        join_units(split(line, sep))
    }
}

/// Splits a line into cells. Double quotes group text containing separators (`"t [s]"`); a
/// doubled quote inside them is a literal quote, as in CSV.
fn split_with(line: &str, sep: Splitter) -> Vec<Cell> {
    let mut cells = Vec::new();
    let mut text = String::new();
    let mut start: Option<usize> = None;
    let mut quoted = false;
    let mut chars = line.chars().enumerate().peekable();
    let mut after_separator = false;
    while let Some((i, c)) = chars.next() {
        if quoted {
            if c == '"' {
                if chars.peek().is_some_and(|&(_, d)| d == '"') {
                    chars.next();
                    text.push('"');
                } else {
                    quoted = false;
                }
            } else {
                text.push(c);
            }
        } else if sep.splits_at(c) {
            if start.is_some() || !sep.merges_runs() {
                let column = start.unwrap_or(i + 1);
                cells.push(Cell {
                    text: text.trim().to_string(),
                    column,
                });
                text.clear();
                start = None;
            }
            after_separator = true;
        } else if c == '"' {
            quoted = true;
            start.get_or_insert(i + 1);
        } else if !c.is_whitespace() || start.is_some() {
            start.get_or_insert(i + 1);
            text.push(c);
        }
    }
    if start.is_some() || (after_separator && !sep.merges_runs()) {
        let column = start.unwrap_or(line.chars().count() + 1);
        cells.push(Cell {
            text: text.trim().to_string(),
            column,
        });
    }
    cells
}

/// In a whitespace-separated header, a unit in brackets or parentheses belongs to the name
/// before it: `t [s]  F (N)` is two names, `t [s]` and `F (N)`.
fn join_units(cells: Vec<Cell>) -> Vec<Cell> {
    let mut out: Vec<Cell> = Vec::with_capacity(cells.len());
    for cell in cells {
        match out.last_mut() {
            Some(prev) if cell.text.starts_with(['[', '(']) => {
                prev.text.push(' ');
                prev.text.push_str(&cell.text);
            }
            _ => out.push(cell),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(line: &str, sep: Separator) -> Vec<String> {
        split(line, sep).into_iter().map(|c| c.text).collect()
    }

    #[test]
    fn detection() {
        assert_eq!(Separator::detect(["1 2", "3 4"]), Separator::Whitespace);
        assert_eq!(Separator::detect(["1 2", "3, 4"]), Separator::Comma);
        assert_eq!(Separator::detect(["1,5;2", "3;4"]), Separator::Semicolon);
        assert_eq!(
            Separator::detect(["t [s]\tF [N]", "1\t2"]),
            Separator::Whitespace
        );
        assert_eq!(
            Separator::detect(["\"a,b\" c", "1 2"]),
            Separator::Whitespace
        );
    }

    #[test]
    fn whitespace_cells_and_columns() {
        let cells = split("  1.0\t 2e-3   x ", Separator::Whitespace);
        let got: Vec<(&str, usize)> = cells.iter().map(|c| (c.text.as_str(), c.column)).collect();
        assert_eq!(got, [("1.0", 3), ("2e-3", 8), ("x", 15)]);
    }

    #[test]
    fn comma_cells_keep_empty_ones() {
        assert_eq!(texts(" 1 , ,3", Separator::Comma), ["1", "", "3"]);
        assert_eq!(texts("1,2,", Separator::Comma), ["1", "2", ""]);
        let cells = split("1,,3", Separator::Comma);
        assert_eq!(cells[1].column, 3);
    }

    #[test]
    fn quotes_group_and_escape() {
        assert_eq!(
            texts("\"t [s]\" \"F \"\"N\"\"\"", Separator::Whitespace),
            ["t [s]", "F \"N\""]
        );
        assert_eq!(texts("\"a, b\",c", Separator::Comma), ["a, b", "c"]);
    }

    #[test]
    fn tab_separated_header_keeps_spaces() {
        let names = split_header("\tt [s]\t\tF [N]", Separator::Whitespace);
        let names: Vec<&str> = names.iter().map(|c| c.text.as_str()).collect();
        assert_eq!(names, ["t [s]", "F [N]"]);
    }

    #[test]
    fn numbers() {
        assert_eq!(Separator::Comma.number(" 1.5".trim()), Some(1.5));
        assert_eq!(Separator::Whitespace.number("-2.5E+01"), Some(-25.0));
        assert_eq!(Separator::Semicolon.number("1,5"), Some(1.5));
        assert_eq!(Separator::Comma.number("1,5"), None);
        assert!(Separator::Whitespace.number("nan").unwrap().is_nan());
        assert_eq!(Separator::Whitespace.number("t"), None);
    }

    #[test]
    fn units_join_their_names() {
        let cells = split_header("t [s]  F (N) x", Separator::Whitespace);
        let names: Vec<&str> = cells.iter().map(|c| c.text.as_str()).collect();
        assert_eq!(names, ["t [s]", "F (N)", "x"]);
    }
}
