//! Every way a data file can be wrong, with the message a student sees: it starts with
//! `file:line:` (and the character column for a single value), says what was expected and how
//! to fix it.

use mechkit::data::{ColumnRef, DataError, Table};

fn error(text: &str) -> DataError {
    Table::parse(text, "forcedata.d").unwrap_err()
}

#[test]
fn ragged_row_against_the_first_row() {
    let e = error("# x F\n0.0 1.0\n0.1 1.5 7\n");
    assert_eq!(
        e.to_string(),
        "forcedata.d:3: this row has 3 cells but the first row on line 2 has 2; every row needs \
         one value per column: fill in the missing value, remove the extra one, or mark the line \
         as a comment with # or %"
    );
}

#[test]
fn ragged_row_against_the_header() {
    let e = error("x,F\n0.0,1.0\n0.1\n");
    assert!(
        e.to_string()
            .starts_with("forcedata.d:3: this row has 1 cell but the header on line 1 has 2;")
    );
}

#[test]
fn non_numeric_cell() {
    let e = error("0.0 1.0\n0.1 1.5\n0.2 abc\n");
    assert_eq!(
        e.to_string(),
        "forcedata.d:3:5: column 2 is `abc`, which is not a number; expected a number such as \
         1.5 or -2.3e-4: remove it or mark the line as a comment with # or %"
    );
    let e = error("x,F\n0.0,1.0\n0.1,,2\n");
    assert!(matches!(e, DataError::Ragged { line: 3, .. }));
    let e = error("x,F\n0.0,1.0\n,2\n");
    assert!(
        e.to_string()
            .starts_with("forcedata.d:3:1: column 1 is empty; expected a number")
    );
}

#[test]
fn a_header_in_the_middle_is_a_non_numeric_cell() {
    let e = error("0 1\n1 2\nx F\n2 3\n");
    assert!(matches!(
        e,
        DataError::NotANumber {
            line: 3,
            column: 1,
            cell: 1,
            ..
        }
    ));
}

#[test]
fn nan_and_infinity() {
    let e = error("t y\n0 1\n0.001 nan\n");
    assert_eq!(
        e.to_string(),
        "forcedata.d:3:7: column 2 is `nan`, which is not a finite number; integrals and \
         derivatives need finite numbers: replace it with a measured value, or remove the line \
         or mark it as a comment with # or %"
    );
    let e = error("0 1\n1e999 2\n");
    assert!(matches!(
        e,
        DataError::NotFinite {
            line: 2,
            cell: 1,
            ..
        }
    ));
    let e = error("0 1\n1 -inf\n");
    assert!(matches!(
        e,
        DataError::NotFinite {
            line: 2,
            cell: 2,
            ..
        }
    ));
}

#[test]
fn empty_and_single_row_files() {
    let e = error("# nothing yet\n\n");
    assert_eq!(
        e.to_string(),
        "forcedata.d: no data rows; at least 2 are needed (blank lines, comment lines starting \
         with # or % and a header line do not count): check that this is the right file"
    );
    assert!(
        error("")
            .to_string()
            .starts_with("forcedata.d: no data rows;")
    );
    assert!(
        error("x F\n")
            .to_string()
            .starts_with("forcedata.d: no data rows;")
    );
    assert!(
        error("x F\n1 2\n")
            .to_string()
            .starts_with("forcedata.d: only 1 data row;")
    );
}

#[test]
fn unknown_columns() {
    let table = Table::parse("t [s] y [m]\n0 1\n1 2\n", "ball.txt").unwrap();
    let e = table.column(&"v".parse().unwrap()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "ball.txt: no column named `v`; the columns are `t [s]`, `y [m]`: use one of these names \
         or a column number from 1 to 2"
    );
    let e = table.column(&"3".parse().unwrap()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "ball.txt: there is no column 3; the file has 2 columns, numbered 1 to 2"
    );
    let bare = Table::parse("0 1\n1 2\n", "forcedata.d").unwrap();
    let e = bare.column(&ColumnRef::Name("F".into())).unwrap_err();
    assert_eq!(
        e.to_string(),
        "forcedata.d: no column named `F`: the file has no header line, so refer to the columns \
         by number, from 1 to 2"
    );
    assert_eq!(
        ColumnRef::parse("0").unwrap_err().to_string(),
        "columns are numbered from 1 (the first column is 1), so there is no column 0"
    );
}

#[test]
fn ambiguous_column() {
    let table = Table::parse("x [m],x [cm]\n0,0\n1,100\n", "pos.csv").unwrap();
    let e = table.column(&"x".parse().unwrap()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "pos.csv: `x` could mean any of the columns `x [m]`, `x [cm]`; use the full name or the \
         column number"
    );
}

#[test]
fn abscissa_duplicate_and_reversal() {
    let table = Table::parse("x F\n0.1 1\n0.2 2\n0.3 2\n0.3 3\n", "forcedata.d").unwrap();
    let e = table
        .abscissa(&"x".parse().unwrap(), "the work integral")
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "forcedata.d:5: x = 0.3 appears on lines 4 and 5; the work integral needs distinct \
         points: remove one or average them"
    );
    let table = Table::parse("t y\n0 1\n2 1\n1 1\n", "ball.txt").unwrap();
    let e = table
        .abscissa(&"t".parse().unwrap(), "the derivative")
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "ball.txt:4: t turns back here: it was increasing, but goes from 2 on line 3 to 1 on \
         line 4; the derivative follows the path in file order, so t must increase (or \
         decrease) along it; sort the file by t if the rows are not in path order"
    );
}
