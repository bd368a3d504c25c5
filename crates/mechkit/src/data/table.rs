//! A table of measured numbers read from a text file: columns of equal length, an optional
//! header of names, and the source line of every row for error messages.

use std::path::Path;

use super::DataError;
use super::column::{self, ColumnRef};
use super::format::{self, Cell, Separator};
use super::order::{Order, check_abscissa};
use crate::Real;
use mechkit_expr::units::Unit;

/// Columns of finite numbers read from a data file.
///
/// The format is the plain one of measurement files and spreadsheet exports:
/// - cells separated by whitespace (spaces, tabs), commas or semicolons, detected once per
///   file (see [`Separator`]); cells are trimmed;
/// - blank lines, and comment lines whose first non-blank character is `#` or `%`, are
///   skipped (only whole lines: a `#` after the numbers is not a comment);
/// - the first remaining line is a header if any of its cells is not a number and does not
///   start like one (a digit, or a sign or point before a digit: `1.2.3` is a mistyped
///   number, reported as such, rather than a name; so is an empty cell). Names are
///   trimmed and may be double-quoted (`"t [s]"`); in a whitespace-separated header a unit in
///   brackets joins the name before it (`t [s]  F [N]` is two names);
/// - every other line is a row of numbers, one per column; NaN and infinities are refused;
/// - `\n` and `\r\n` line endings, and a UTF-8 byte-order mark, are accepted.
///
/// A table has at least two rows.
///
/// # Example
/// ```
/// use mechkit::data::{ColumnRef, Table};
///
/// let text = "# bat on ball\nt [s], F [N]\n0.0, 122.3\n4.04e-5, 217.4\n";
/// let table = Table::parse(text, "forcedata.csv").unwrap();
/// assert_eq!((table.len(), table.width()), (2, 2));
/// let force = table.column(&ColumnRef::parse("F").unwrap()).unwrap();
/// assert_eq!(force, &[122.3, 217.4]);
/// assert_eq!(table.line_of(1), 4);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    source: String,
    separator: Separator,
    names: Option<Vec<String>>,
    header_line: Option<usize>,
    columns: Vec<Vec<Real>>,
    lines: Vec<usize>,
}

impl Table {
    /// Reads a table from `text`; `source` names it in error messages (a file name, `<stdin>`).
    pub fn parse(text: &str, source: &str) -> Result<Self, DataError> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let content: Vec<(usize, &str)> = text
            .lines()
            .enumerate()
            .map(|(i, line)| (i + 1, line))
            .filter(|(_, line)| {
                let t = line.trim_start();
                !(t.trim_end().is_empty() || t.starts_with(['#', '%']))
            })
            .collect();
        let separator = Separator::detect(content.iter().map(|&(_, line)| line));
        let mut lines = content.into_iter();

        let mut table = Self {
            source: source.to_string(),
            separator,
            names: None,
            header_line: None,
            columns: Vec::new(),
            lines: Vec::new(),
        };
        let Some((first_line, first_text)) = lines.next() else {
            return Err(table.too_few_rows());
        };
        let first = format::split(first_text, separator);
        if first.iter().any(|c| is_name(&c.text, separator)) {
            let names = format::split_header(first_text, separator);
            table.columns = vec![Vec::new(); names.len()];
            table.names = Some(names.into_iter().map(|c| c.text).collect());
            table.header_line = Some(first_line);
        } else {
            table.columns = vec![Vec::new(); first.len()];
            table.push_row(first_line, &first)?;
        }
        for (line, text) in lines {
            table.push_row(line, &format::split(text, separator))?;
        }
        if table.lines.len() < 2 {
            return Err(table.too_few_rows());
        }
        Ok(table)
    }

    /// Reads the file at `path` (see [`Table::parse`]); errors name it as given.
    pub fn read(path: &Path) -> Result<Self, DataError> {
        let text =
            crate::csv::read_bounded_text(path, crate::csv::MAX_DATA_BYTES).map_err(|error| {
                DataError::Io {
                    path: path.to_path_buf(),
                    error,
                }
            })?;
        Self::parse(&text, &path.display().to_string())
    }

    /// A table of columns a program already holds (arrays rather than a file), named
    /// `names` (one per column, as a header would name them: `t`, `F [kN]`); `source` names
    /// it in messages, where row `i` (0-based) is on "line" `i + 1`.
    ///
    /// ```
    /// use mechkit::data::{ColumnRef, Table};
    /// let t = Table::from_columns("<arrays>", &["t", "F"], vec![vec![0.0, 0.1], vec![2.0, 3.0]])
    ///     .unwrap();
    /// assert_eq!(t.column(&ColumnRef::parse("F").unwrap()).unwrap(), &[2.0, 3.0]);
    /// assert_eq!(t.line_of(1), 2);
    /// assert!(Table::from_columns("<arrays>", &["t", "F"], vec![vec![0.0], vec![1.0]]).is_err());
    /// ```
    ///
    /// # Errors
    /// Another number of names than of columns, columns of different lengths, fewer than two
    /// rows, a value that is not finite: [`DataError::Columns`].
    pub fn from_columns(
        source: &str,
        names: &[&str],
        columns: Vec<Vec<Real>>,
    ) -> Result<Self, DataError> {
        let fail = |message: String| DataError::Columns {
            file: source.to_string(),
            message,
        };
        if names.len() != columns.len() {
            return Err(fail(format!(
                "{} names for {} columns; give one name per column",
                names.len(),
                columns.len()
            )));
        }
        let rows = columns.first().map_or(0, Vec::len);
        if let Some(k) = columns.iter().position(|c| c.len() != rows) {
            return Err(fail(format!(
                "`{}` has {} values but `{}` has {rows}; every column needs one value per row",
                names[k],
                columns[k].len(),
                names[0]
            )));
        }
        if rows < 2 {
            let what = names
                .first()
                .map_or_else(|| "the table".to_string(), |n| format!("`{n}`"));
            let values = if rows == 0 { "no values" } else { "1 value" };
            return Err(fail(format!(
                "{what} has {values}; at least 2 rows are needed"
            )));
        }
        for (name, column) in names.iter().zip(&columns) {
            if let Some(i) = column.iter().position(|v| !v.is_finite()) {
                return Err(fail(format!(
                    "`{name}` is {} at row {}, which is not a finite number; integrals and \
                     derivatives need finite numbers",
                    column[i],
                    i + 1
                )));
            }
        }
        Ok(Self {
            source: source.to_string(),
            separator: Separator::Comma,
            names: Some(names.iter().map(ToString::to_string).collect()),
            header_line: None,
            columns,
            lines: (1..=rows).collect(),
        })
    }

    fn too_few_rows(&self) -> DataError {
        DataError::TooFewRows {
            file: self.source.clone(),
            rows: self.lines.len(),
        }
    }

    fn push_row(&mut self, line: usize, cells: &[Cell]) -> Result<(), DataError> {
        if cells.len() != self.width() {
            return Err(DataError::Ragged {
                file: self.source.clone(),
                line,
                found: cells.len(),
                expected: self.width(),
                reference_line: self.header_line.unwrap_or_else(|| self.lines[0]),
                header: self.names.is_some(),
            });
        }
        for (i, cell) in cells.iter().enumerate() {
            let value = self.separator.number(&cell.text);
            let (file, column, cell_no, text) =
                (self.source.clone(), cell.column, i + 1, cell.text.clone());
            match value {
                None => {
                    return Err(DataError::NotANumber {
                        file,
                        line,
                        column,
                        cell: cell_no,
                        text,
                    });
                }
                Some(x) if !x.is_finite() => {
                    return Err(DataError::NotFinite {
                        file,
                        line,
                        column,
                        cell: cell_no,
                        text,
                    });
                }
                Some(_) => {}
            }
        }
        for (column, cell) in self.columns.iter_mut().zip(cells) {
            column.extend(self.separator.number(&cell.text));
        }
        self.lines.push(line);
        Ok(())
    }

    /// The name given to [`Table::parse`] or the path given to [`Table::read`].
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The separator detected.
    pub fn separator(&self) -> Separator {
        self.separator
    }

    /// The number of data rows (at least 2).
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    /// Always `false`: a table has at least two rows.
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }

    /// The number of columns.
    pub fn width(&self) -> usize {
        self.columns.len()
    }

    /// The header's names, trimmed and unquoted, if the file has a header.
    pub fn names(&self) -> Option<&[String]> {
        self.names.as_deref()
    }

    /// The 1-based source line of data row `row` (0-based).
    ///
    /// # Panics
    /// If `row >= self.len()`.
    pub fn line_of(&self, row: usize) -> usize {
        self.lines[row]
    }

    /// The 0-based position of a column (see [`ColumnRef::parse`] for how names match).
    pub fn column_index(&self, column: &ColumnRef) -> Result<usize, DataError> {
        match column {
            ColumnRef::Index(i) if *i < self.width() => Ok(*i),
            ColumnRef::Index(i) => Err(DataError::ColumnOutOfRange {
                file: self.source.clone(),
                number: i.saturating_add(1),
                width: self.width(),
            }),
            ColumnRef::Name(name) => {
                let found = match &self.names {
                    Some(names) => column::find(names, name),
                    None => Ok(None),
                };
                match found {
                    Ok(Some(i)) => Ok(i),
                    Ok(None) => Err(DataError::UnknownColumn {
                        file: self.source.clone(),
                        name: name.clone(),
                        names: self.names.clone(),
                        width: self.width(),
                    }),
                    Err(matches) => Err(DataError::AmbiguousColumn {
                        file: self.source.clone(),
                        name: name.clone(),
                        matches,
                    }),
                }
            }
        }
    }

    /// The values of a column, one per row.
    pub fn column(&self, column: &ColumnRef) -> Result<&[Real], DataError> {
        Ok(&self.columns[self.column_index(column)?])
    }

    /// What messages call column `index` (0-based): its header name, else `column {index + 1}`.
    ///
    /// # Panics
    /// If `index >= self.width()`.
    pub fn label(&self, index: usize) -> String {
        assert!(index < self.width(), "column {index} of {}", self.width());
        match &self.names {
            Some(names) => names[index].clone(),
            None => format!("column {}", index + 1),
        }
    }

    /// The unit the header gives column `index` (0-based), as in `t [s]`; `None` without a
    /// header or a unit mechkit knows.
    ///
    /// # Panics
    /// If `index >= self.width()`.
    pub fn unit(&self, index: usize) -> Option<String> {
        assert!(index < self.width(), "column {index} of {}", self.width());
        self.names
            .as_ref()
            .and_then(|names| super::header_unit(&names[index]))
    }

    /// Column `index` (0-based) in SI with its SI unit (`ms` read as seconds: `s`), when the
    /// header gives its unit; else the values as written, without a unit (taken as SI by the
    /// calculations, but not known).
    ///
    /// ```
    /// use mechkit::data::Table;
    /// let t = Table::parse("t [ms], x\n0, 1\n5, 2\n", "f.csv").unwrap();
    /// assert_eq!(t.si(0), (vec![0.0, 0.005], Some("s".to_string())));
    /// assert_eq!(t.si(1), (vec![1.0, 2.0], None));
    /// ```
    ///
    /// # Panics
    /// If `index >= self.width()`.
    pub fn si(&self, index: usize) -> (Vec<Real>, Option<String>) {
        let values = &self.columns[index];
        match self.unit(index).and_then(|u| Unit::parse(&u).ok()) {
            Some(u) if u.factor > 0.0 && u.factor.is_finite() => {
                let si = u
                    .dim
                    .derived_symbol()
                    .map_or_else(|| u.dim.to_string(), str::to_string);
                (values.iter().map(|v| v * u.factor).collect(), Some(si))
            }
            _ => (values.clone(), None),
        }
    }

    /// A column that serves as the abscissa of `what` (`"the work integral"`, `"the
    /// derivative"`), checked to be strictly monotone (see [`check_abscissa`]), with its
    /// direction.
    pub fn abscissa(&self, column: &ColumnRef, what: &str) -> Result<(&[Real], Order), DataError> {
        let index = self.column_index(column)?;
        let x = &self.columns[index];
        let order = check_abscissa(x, self, &self.label(index), what)?;
        Ok((x, order))
    }
}

/// Whether a cell of the first line makes it a header (see [`Table`]).
fn is_name(text: &str, separator: Separator) -> bool {
    let mut chars = text.chars().skip_while(|c| matches!(c, '+' | '-' | '.'));
    let looks_numeric = chars.next().is_none_or(|c| c.is_ascii_digit());
    separator.number(text).is_none() && !looks_numeric
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> Table {
        Table::parse(text, "test.d").unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn whitespace_without_header() {
        let t = table("0.0 1.0\n0.1   2.0\n\t0.2\t3.0\n");
        assert_eq!((t.len(), t.width()), (3, 2));
        assert_eq!(t.names(), None);
        assert_eq!(t.separator(), Separator::Whitespace);
        assert_eq!(t.column(&ColumnRef::Index(1)).unwrap(), &[1.0, 2.0, 3.0]);
        assert_eq!(t.label(0), "column 1");
    }

    #[test]
    fn comments_blank_lines_and_line_numbers() {
        let t = table("# measured 2024\n\n% matlab style\n  # indented\n1 2\n\n3 4\n");
        assert_eq!((t.line_of(0), t.line_of(1)), (5, 7));
    }

    #[test]
    fn comma_with_header_and_crlf() {
        let t = table("t [s],x [m]\r\n0,1.5\r\n1, 2.5\r\n");
        assert_eq!(t.separator(), Separator::Comma);
        assert_eq!(t.names().unwrap(), ["t [s]", "x [m]"]);
        let x = t.column(&ColumnRef::Name("x".into())).unwrap();
        assert_eq!(x, &[1.5, 2.5]);
        assert_eq!(t.label(1), "x [m]");
    }

    #[test]
    fn semicolons_with_decimal_commas() {
        let t = table("t;F\n0,5;1\n1,5;2\n");
        assert_eq!(t.separator(), Separator::Semicolon);
        assert_eq!(t.column(&ColumnRef::Index(0)).unwrap(), &[0.5, 1.5]);
    }

    #[test]
    fn tab_separated_names_with_spaces() {
        let t = table("t [s]\tF [N]\n0\t1\n1\t2\n");
        assert_eq!(t.separator(), Separator::Whitespace);
        assert_eq!(t.names().unwrap(), ["t [s]", "F [N]"]);
    }

    #[test]
    fn whitespace_header_units_and_quotes() {
        let t = table("t [s]   F [N]\n0 1\n1 2\n");
        assert_eq!(t.names().unwrap(), ["t [s]", "F [N]"]);
        let t = table("\"time t\" \"F\"\n0 1\n1 2\n");
        assert_eq!(t.names().unwrap(), ["time t", "F"]);
        assert_eq!(t.column_index(&ColumnRef::Name("time".into())).unwrap(), 0);
    }

    #[test]
    fn header_with_a_numeric_name() {
        let t = table("x 2\n1 2\n3 4\n");
        assert_eq!(t.names().unwrap(), ["x", "2"]);
        assert_eq!(t.len(), 2);
    }

    #[test]
    fn a_mistyped_first_number_is_not_a_header() {
        let e = Table::parse("0.0 1.2.3\n1 2\n2 3\n", "f.d").unwrap_err();
        assert!(
            matches!(
                e,
                DataError::NotANumber {
                    line: 1,
                    cell: 2,
                    ..
                }
            ),
            "{e}"
        );
        let e = Table::parse("0,,1\n1,2,3\n", "f.csv").unwrap_err();
        assert!(
            matches!(
                e,
                DataError::NotANumber {
                    line: 1,
                    cell: 2,
                    ..
                }
            ),
            "{e}"
        );
        let t = table("-x,.y,+\n1,2,3\n3,4,5\n");
        assert_eq!(t.names().unwrap(), ["-x", ".y", "+"]);
    }

    #[test]
    fn byte_order_mark() {
        let t = table("\u{feff}t,x\n0,1\n1,2\n");
        assert_eq!(t.names().unwrap(), ["t", "x"]);
    }
}
