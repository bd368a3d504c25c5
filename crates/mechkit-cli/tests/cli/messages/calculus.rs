//! Formulas and quantities given on the command line (`diff`, `units`, `integrate`, `solve`):
//! each message quotes the argument with a caret under the problem.

use super::case::{Case, assert_cases};

#[test]
fn formula_and_unit_messages() {
    assert_cases(CASES);
}

/// A `mechkit diff FORMULA` case.
macro_rules! diff {
    ($kind:literal, $formula:literal) => {
        Case {
            area: "formula",
            kind: $kind,
            files: &[],
            args: &["diff", $formula],
            code: 2,
        }
    };
}

/// A `mechkit units …` case.
macro_rules! units {
    ($kind:literal, $($arg:literal),+) => {
        Case {
            area: "unit",
            kind: $kind,
            files: &[],
            args: &["units", $($arg),+],
            code: 2,
        }
    };
}

pub static CASES: &[Case] = &[
    diff!("empty", ""),
    diff!("unexpected_character", "x $ 2"),
    diff!("single_equals", "x = 2"),
    diff!("unexpected_token", "x^^2"),
    diff!("unexpected_end", "x +"),
    diff!("missing_operator", "2 x"),
    diff!("unclosed_paren", "sin(x"),
    diff!("unmatched_close_paren", "x)"),
    diff!("unknown_function", "sinn(x)"),
    diff!("wrong_argument_count", "sin(x, 2)"),
    // a flat sum of 258 terms is 257 levels deep, one more than a formula may be
    diff!(
        "too_deep",
        "x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x+x"
    ),
    Case {
        area: "formula",
        kind: "undefined_name_at_a_point",
        files: &[],
        args: &["diff", "a*x^2", "--at", "1"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "bad_set_flag",
        files: &[],
        args: &["diff", "a*x^2", "--at", "1", "--set", "a:2"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "integrate_bound_missing",
        files: &[],
        args: &["integrate", "x^2", "--from", "0"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "solve_no_equation",
        files: &[],
        args: &["solve", "x^2 + 1 == 0"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "solve_unknown_not_in_equation",
        files: &[],
        args: &["solve", "a*x + b = 0", "--for", "y"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "solve_interval_reversed",
        files: &[],
        args: &["solve", "cos(x) = x", "--for", "x", "--in", "1:0"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "solve_cubic_needs_values",
        files: &[],
        args: &["solve", "k*x^3 - 6*x^2 + 11*x - 6 = 0", "--for", "x"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "dsolve_missing_operand",
        files: &[],
        args: &["dsolve", "x'' + * x = 0"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "dsolve_bad_condition",
        files: &[],
        args: &["dsolve", "x'' + x = 0", "--ic", "x(0)"],
        code: 2,
    },
    Case {
        area: "formula",
        kind: "dsolve_no_closed_form",
        files: &[],
        args: &["dsolve", "x'' + sin(x) = 0"],
        code: 1,
    },
    units!("unknown_unit", "3 mps"),
    units!("no_number", "abc"),
    units!("bad_power", "3 m^^2"),
    units!("fractional_power_without_parentheses", "1e5 N/m^3/2"),
    units!("inexact_power", "1 m^0.333333"),
    units!("unit_too_large", "1 (((km^12)^12)^12)^12"),
    units!("trailing_operator", "3 m/"),
    units!("incompatible_conversion", "3 m/s", "--to", "s"),
];
