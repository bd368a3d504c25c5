//! What can be wrong with a data file, or with a column asked of it.
//!
//! Every message starts with the file (`{file}:`), its line (`{file}:{line}:`) and, for a single
//! value, the character column where that value starts (`{file}:{line}:{column}:`), as compilers
//! print them, so an editor can jump there. Then it says what was expected and how to fix it.

use std::path::PathBuf;

use thiserror::Error;

use crate::Real;
use mechkit_expr::span::clip;

/// A data file that cannot be read as a table of numbers, or a column it does not have.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum DataError {
    /// The file cannot be read (missing, unreadable, not UTF-8 text).
    ///
    /// The I/O error is part of the message rather than its `source()`, so that printing the
    /// message alone tells the whole story.
    #[error("{}: cannot read the file: {error}; check the path and that it is a text file", path.display())]
    Io {
        /// The path as given.
        path: PathBuf,
        /// What the operating system said.
        error: std::io::Error,
    },
    /// A row with a different number of cells than the header (or the first row).
    #[error(
        "{file}:{line}: this row has {} but {} on line {reference_line} has {expected}; \
         every row needs one value per column: fill in the missing value, remove the extra one, \
         or mark the line as a comment with # or %",
        count_cells(*.found),
        if *.header { "the header" } else { "the first row" }
    )]
    Ragged {
        /// The file name.
        file: String,
        /// 1-based line of the row.
        line: usize,
        /// Cells on that line.
        found: usize,
        /// Cells of the header or the first data row.
        expected: usize,
        /// 1-based line of the header or first data row.
        reference_line: usize,
        /// Whether the reference row is a header.
        header: bool,
    },
    /// A cell that is not a number.
    #[error(
        "{file}:{line}:{column}: {}; expected a number such as 1.5 or -2.3e-4: \
         remove it or mark the line as a comment with # or %",
        describe_cell(.text, *.cell)
    )]
    NotANumber {
        /// The file name.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based character column where the cell starts.
        column: usize,
        /// 1-based number of the table column.
        cell: usize,
        /// The cell's text.
        text: String,
    },
    /// A cell that reads as NaN or infinity (or overflows, like `1e999`).
    #[error(
        "{file}:{line}:{column}: column {cell} is `{}`, which is not a finite number; \
         integrals and derivatives need finite numbers: replace it with a measured value, \
         or remove the line or mark it as a comment with # or %",
        clip(.text)
    )]
    NotFinite {
        /// The file name.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based character column where the cell starts.
        column: usize,
        /// 1-based number of the table column.
        cell: usize,
        /// The cell's text.
        text: String,
    },
    /// Fewer than two data rows.
    #[error(
        "{file}: {}; at least 2 are needed (blank lines, comment lines starting with # or % \
         and a header line do not count): check that this is the right file",
        count_rows(*.rows)
    )]
    TooFewRows {
        /// The file name.
        file: String,
        /// Data rows found.
        rows: usize,
    },
    /// Columns given as arrays ([`Table::from_columns`](super::Table::from_columns)) that do
    /// not make a table: of different lengths, or with a value that is not finite.
    #[error("{file}: {message}")]
    Columns {
        /// What the arrays are called.
        file: String,
        /// What is wrong and how to fix it.
        message: String,
    },
    /// A column name the header does not have (or any name, when there is no header).
    #[error("{file}: {}", unknown_column(.name, .names.as_deref(), *.width))]
    UnknownColumn {
        /// The file name.
        file: String,
        /// The name asked for.
        name: String,
        /// The names of the columns, if the file has a header.
        names: Option<Vec<String>>,
        /// The number of columns.
        width: usize,
    },
    /// A name that matches several columns equally well.
    #[error(
        "{file}: `{}` could mean any of the columns {}; use the full name or the column number",
        clip(.name),
        quote_list(.matches)
    )]
    AmbiguousColumn {
        /// The file name.
        file: String,
        /// The name asked for.
        name: String,
        /// The names it matches.
        matches: Vec<String>,
    },
    /// A column number beyond the last column.
    #[error(
        "{file}: there is no column {number}; the file has {width} columns, numbered 1 to {width}"
    )]
    ColumnOutOfRange {
        /// The file name.
        file: String,
        /// The 1-based number asked for.
        number: usize,
        /// The number of columns.
        width: usize,
    },
    /// Column number 0.
    #[error("columns are numbered from 1 (the first column is 1), so there is no column 0")]
    ColumnZero,
    /// The same abscissa value on two lines.
    #[error(
        "{file}:{second_line}: {} = {} appears on lines {first_line} and {second_line}; \
         {what} needs distinct points: remove one or average them",
        clip(.label),
        crate::error::short(*.value)
    )]
    DuplicateAbscissa {
        /// The file name.
        file: String,
        /// The abscissa's name (`x`, `t [s]`, `column 1`).
        label: String,
        /// The repeated value.
        value: Real,
        /// 1-based line of the first occurrence.
        first_line: usize,
        /// 1-based line of the second occurrence.
        second_line: usize,
        /// What needs the points (`the work integral`, `the derivative`).
        what: String,
    },
    /// An abscissa that turns back: it increased and then decreases, or the other way round.
    #[error(
        "{file}:{line}: {label} turns back here: it was {}, but goes from {} on line \
         {previous_line} to {} on line {line}; {what} follows the path in file order, so \
         {label} must increase (or decrease) along it; sort the file by {label} if the rows are \
         not in path order",
        if *.increasing { "increasing" } else { "decreasing" },
        crate::error::short(*.previous),
        crate::error::short(*.value),
        label = clip(.label)
    )]
    NotMonotone {
        /// The file name.
        file: String,
        /// The abscissa's name.
        label: String,
        /// 1-based line where the direction reverses.
        line: usize,
        /// The value there.
        value: Real,
        /// 1-based line before it.
        previous_line: usize,
        /// The value on that line.
        previous: Real,
        /// Whether the values were increasing until then.
        increasing: bool,
        /// What needs the points in order.
        what: String,
    },
}

fn describe_cell(text: &str, cell: usize) -> String {
    if text.is_empty() {
        format!("column {cell} is empty")
    } else {
        format!("column {cell} is `{}`, which is not a number", clip(text))
    }
}

fn count_cells(cells: usize) -> String {
    if cells == 1 {
        "1 cell".to_string()
    } else {
        format!("{cells} cells")
    }
}

fn count_rows(rows: usize) -> String {
    match rows {
        0 => "no data rows".to_string(),
        1 => "only 1 data row".to_string(),
        n => format!("only {n} data rows"),
    }
}

fn quote_list(names: &[String]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{}`", clip(n))).collect();
    quoted.join(", ")
}

fn unknown_column(name: &str, names: Option<&[String]>, width: usize) -> String {
    match names {
        Some(names) => format!(
            "no column named `{}`; the columns are {}: use one of these names or a column \
             number from 1 to {width}",
            clip(name),
            quote_list(names)
        ),
        None => format!(
            "no column named `{name}`: the file has no header line, so refer to the columns by \
             number, from 1 to {width}"
        ),
    }
}
