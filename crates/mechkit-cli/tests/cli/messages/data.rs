//! Data files (`work`, `derive`, `impulse`): every message starts with `file:line:` (and the
//! column for a single value), says what was expected and how to fix it.

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn data_file_messages() {
    assert_cases(CASES);
}

/// A `mechkit work f.dat …` case on the file `text`.
macro_rules! work {
    ($kind:literal, $text:literal $(, $arg:literal)*) => {
        Case {
            area: "data file",
            kind: $kind,
            files: &[("f.dat", Text($text))],
            args: &["work", "f.dat" $(, $arg)*],
            code: 2,
        }
    };
}

pub static CASES: &[Case] = &[
    Case {
        area: "data file",
        kind: "file_not_found",
        files: &[],
        args: &["work", "missing.dat"],
        code: 2,
    },
    work!("ragged_row", "x F\n0 1\n1 2 3\n2 3\n"),
    work!("not_a_number", "x F\n0 1\n1 abc\n2 3\n"),
    work!("empty_cell", "x,F\n0,1\n1,\n2,3\n"),
    work!("not_finite", "x F\n0 1\n1 inf\n2 3\n"),
    work!("too_few_rows", "x F\n0 1\n"),
    work!("unknown_column", "x F\n0 1\n1 2\n2 3\n", "--f", "G"),
    work!(
        "unknown_column_without_header",
        "0 1\n1 2\n2 3\n",
        "--f",
        "F"
    ),
    work!(
        "ambiguous_column",
        "x Fx fx\n0 1 1\n1 2 2\n2 3 3\n",
        "--f",
        "FX"
    ),
    work!("column_out_of_range", "x F\n0 1\n1 2\n2 3\n", "--f", "7"),
    work!("column_zero", "x F\n0 1\n1 2\n2 3\n", "--f", "0"),
    work!("not_monotone", "x F\n0 1\n1 2\n0.5 3\n"),
    work!("time_decreasing", "t,x\n3,1\n2,2\n1,3\n0,4\n"),
    work!(
        "unknown_rule",
        "x F\n0 1\n1 2\n2 3\n",
        "--method",
        "simpsons"
    ),
    Case {
        area: "data file",
        kind: "duplicate_abscissa",
        files: &[("f.dat", Text("t x\n0 1\n0 2\n2 3\n"))],
        args: &["derive", "f.dat", "--no-plots", "--out", "out"],
        code: 2,
    },
    Case {
        area: "data file",
        kind: "smoothing_window",
        files: &[("f.dat", Text("t x\n0 1\n1 2\n2 3\n3 5\n"))],
        args: &[
            "derive",
            "f.dat",
            "--no-plots",
            "--out",
            "out",
            "--smooth",
            "2",
        ],
        code: 2,
    },
    Case {
        area: "data file",
        kind: "output_is_the_input",
        files: &[("derived.csv", Text("t,x\n0,1\n1,2\n2,3\n3,5\n"))],
        args: &["derive", "derived.csv", "--no-plots", "--out", "."],
        code: 2,
    },
];
