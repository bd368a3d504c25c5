//! The case file, checks, scripts and the report, on a small case file of their own.

use serde_json::Value;

use super::case::tolerance;
use super::check::{Family, implicit_products};
use super::report::{self, MarkerError, add_markers, report, significant, splice};
use super::script::shell_words;
use super::{Case, CaseRun, Check, Script, case_of};

const FILE: &str = r#"{"id": "a", "topic": "drag", "expected": {"v": -4.8042, "y": 0.78709}, "tolerance": {"rel": 0.001}}

{"id": "b", "expected": {"stable": "x = n b", "unstable": "x = (n+1/2) b", "dU": 0.31831}, "inputs": {"b": 2.0}, "tolerance": {"rel": 1e-6}}
{"id": "c", "expected": {"v0=8": {"x": 0.0087}, "v0=10": {"x": 14.465}}, "tolerance": {"abs": 0.02}}
{"id": "d", "expected": 98000.0, "tolerance": {"rel": 0.01, "abs_t": 0.5}}
{"id": "e", "expected": "1/2 x^2"}"#;

/// A JSON value from its text.
fn v(text: &str) -> Value {
    serde_json::from_str(text).unwrap()
}

fn cases() -> Vec<Case> {
    Case::parse_all(FILE).unwrap()
}

#[test]
fn a_case_file_is_read_with_its_variants_and_stems() {
    let cases = cases();
    assert_eq!(cases.len(), 5);
    assert_eq!(cases[2].stems(), ["c.v0=10", "c.v0=8"]);
    assert_eq!(cases[3].stems(), ["d"]);
    assert!(case_of(&cases, "c").is_none(), "c has variants only");
    assert_eq!(case_of(&cases, "c.v0=8").unwrap().id, "c");
    assert_eq!(
        cases[3].expected_of("d").unwrap(),
        [("answer".to_string(), v("98000.0"))]
    );
    assert!(case_of(&cases, "a.nothing").is_none());
}

#[test]
fn a_bad_case_file_line_is_reported_by_number() {
    let e = Case::parse_all("{\"id\": \"x\", \"expected\": 1}\n{\"id\": \"x\", \"expected\": 2}")
        .unwrap_err();
    assert_eq!(e.line, 2);
    assert!(e.message.contains("second case"), "{e}");
    let e = Case::parse_all("\n{\"id\": \"y\"}").unwrap_err();
    assert_eq!((e.line, e.message.contains("expected")), (2, true));
    assert_eq!(Case::parse_all("{oops").unwrap_err().line, 1);
}

#[test]
fn tolerances_take_the_longest_prefix_then_the_default_then_the_last_digit() {
    let tol = v(r#"{"rel": 0.01, "abs_t": 0.5, "abs_t_max": 0.1}"#);
    assert_eq!(tolerance(&tol, "t_max", 3.0), 0.1);
    assert_eq!(tolerance(&tol, "t_end", 3.0), 0.5);
    assert_eq!(tolerance(&tol, "v", 3.0), 0.03);
    assert!((tolerance(&v("{}"), "v", 4.834) - 5e-4).abs() < 1e-15);
    // the feather's: a key with no prefix of its own gets half its last digit
    let t = v(r#"{"abs_t": 0.001, "abs_x": 1e-4}"#);
    assert_eq!(tolerance(&t, "x_last", 2.8e-4), 1e-4);
    assert!((tolerance(&t, "v_last", -0.5) - 0.05).abs() < 1e-15);
    let t = v(r#"{"abs_W": 0.5, "rel_v": 0.01}"#);
    assert_eq!(tolerance(&t, "W_F", 900.0), 0.5);
    assert!((tolerance(&t, "v", 11.0) - 0.11).abs() < 1e-12);
}

#[test]
fn numbers_compare_within_the_tolerance() {
    let cases = cases();
    let c = Check::new(&cases[0], "a", "v", &v("-4.80426"));
    assert!(c.pass, "{c:?}");
    assert!((c.error.unwrap() - 1.25e-5).abs() < 1e-7);
    let c = Check::new(&cases[0], "a", "y", &v("0.79"));
    assert!(!c.pass);
    let c = Check::new(&cases[0], "a", "v", &Value::Null);
    assert_eq!((c.pass, c.note.as_str()), (false, "not computed"));
    let c = Check::new(&cases[0], "a", "w", &v("1.0"));
    assert!(!c.pass && c.note.contains("expects no"));
    let c = Check::new(&cases[3], "d", "answer", &v(r#""98000""#));
    assert!(!c.pass && c.note.contains("not a number"));
}

#[test]
fn a_pattern_in_n_is_a_family_of_values() {
    let cases = cases();
    // b = 2: stable at x = 2n, unstable at 2n + 1
    let stable = Check::new(&cases[1], "b", "stable", &v("[-2.0, 0.0, 2.0, 4.0]"));
    assert!(stable.pass, "{stable:?}");
    let unstable = Check::new(&cases[1], "b", "unstable", &v("[-1.0, 1.0000000001, 3.0]"));
    assert!(unstable.pass, "{unstable:?}");
    let wrong = Check::new(&cases[1], "b", "unstable", &v("[1.0, 2.0]"));
    assert!(
        !wrong.pass && wrong.note.contains("not of the pattern"),
        "{wrong:?}"
    );
    let empty = Check::new(&cases[1], "b", "stable", &v("[]"));
    assert!(!empty.pass);
    // not a pattern: compared as text
    assert!(Check::new(&cases[4], "e", "answer", &v(r#""1/2 x^2""#)).pass);
    assert!(!Check::new(&cases[4], "e", "answer", &v(r#""x^2/2""#)).pass);
}

#[test]
fn patterns_need_linear_formulas_of_known_names() {
    let inputs = v(r#"{"b": 2.0}"#);
    let f = Family::parse("x = (n+1/2) b", &inputs).unwrap();
    assert_eq!((f.offset, f.step), (1.0, 2.0));
    assert!(Family::parse("x = n^2 b", &inputs).is_none());
    assert!(Family::parse("x = n c", &inputs).is_none());
    assert!(Family::parse("x = b", &inputs).is_none());
    assert!(Family::parse("no equals sign", &inputs).is_none());
    assert_eq!(implicit_products(" (n+1/2) b "), "(n+1/2)*b");
    assert_eq!(implicit_products("2 pi n"), "2*pi*n");
    assert_eq!(implicit_products("n + 1"), "n+1");
}

#[test]
fn the_report_has_a_row_per_expected_value_and_fails_what_nothing_computed() {
    let cases = cases();
    let runs = vec![CaseRun {
        stem: "a".into(),
        file: "../examples/book/a.toml".into(),
        checks: vec![Check::new(&cases[0], "a", "v", &v("-4.80426"))],
        plots: vec!["gallery/a/trajectory.svg".into()],
        error: None,
    }];
    let text = report(&cases, &runs);
    assert!(
        text.starts_with("1 of 9 expected values of 5 cases"),
        "{text}"
    );
    assert!(text.contains(
        "| [a](../examples/book/a.toml) | drag | v | -4.8042 | -4.80426 | 1.2e-5 | pass | [trajectory](gallery/a/trajectory.svg) |"
    ), "{text}");
    assert!(
        text.contains("|  |  | y | 0.78709 | — |  | **fail**: not computed |  |"),
        "{text}"
    );
    assert!(
        text.contains(
            "| c.v0=10 |  | x | 14.465 | — |  | **fail**: no scenario or script computes it |"
        ),
        "{text}"
    );
    let rows = report::checks(&cases, &runs);
    assert_eq!(rows.len(), 9);
}

#[test]
fn the_report_goes_between_the_markers() {
    let doc = format!("# V\n\n{}\nold\n{}\nafter\n", report::BEGIN, report::END);
    let new = splice(&doc, "new\n").unwrap();
    assert_eq!(
        new,
        format!("# V\n\n{}\nnew\n{}\nafter\n", report::BEGIN, report::END)
    );
    assert_eq!(splice(&new, "new\n").unwrap(), new);
    assert_eq!(splice("# V\n", "x"), Err(MarkerError::Missing));
    assert_eq!(
        splice(&format!("{}\n", report::BEGIN), "x"),
        Err(MarkerError::NoEnd)
    );
    assert_eq!(
        splice(&format!("{}\n{}\n", report::END, report::BEGIN), "x"),
        Err(MarkerError::NoEnd)
    );
    assert_eq!(
        splice(&format!("a\n{}\n", report::END), "x"),
        Err(MarkerError::NoBegin)
    );
    // a marker quoted in the text is not a marker line
    let quoted = format!("see `{}`\n", report::BEGIN);
    assert_eq!(splice(&quoted, "x"), Err(MarkerError::Missing));
}

#[test]
fn markers_are_added_at_the_end_of_a_document_without_them() {
    let marked = add_markers("# V\ntext");
    assert_eq!(
        marked,
        format!("# V\ntext\n\n{}\n{}\n", report::BEGIN, report::END)
    );
    assert_eq!(
        splice(&marked, "table\n").unwrap(),
        format!("# V\ntext\n\n{}\ntable\n{}\n", report::BEGIN, report::END)
    );
    // a new file: the markers alone
    assert_eq!(
        add_markers(""),
        format!("{}\n{}\n", report::BEGIN, report::END)
    );
}

#[test]
fn link_targets_survive_parentheses() {
    assert_eq!(
        report::link("gallery/c10/motorbike/v(t).svg"),
        "gallery/c10/motorbike/v%28t%29.svg"
    );
    assert_eq!(report::link("a b%"), "a%20b%25");
}

#[test]
fn numbers_print_to_seven_significant_digits() {
    assert_eq!(significant(153.8), "153.8");
    assert_eq!(significant(-4.804_260_000_001), "-4.80426");
    assert_eq!(significant(2193.2283), "2193.228");
    assert_eq!(significant(98000.0), "98000");
    assert_eq!(significant(-4.013_333_3e-3), "-0.004013333");
    assert_eq!(significant(2.79904e-5), "2.79904e-5");
    assert_eq!(significant(1.5e11), "1.5e11");
    assert_eq!(significant(0.0), "0");
}

#[test]
fn scripts_are_calls_bindings_and_comments() {
    let s = Script::parse(
        "# the wire\n# k = 98 kN/m\nmechkit solve 'k*x = m*g' --for k --json\n#> answer = /solutions/0\n\nmechkit units \"9.8 N\" --json\n#> a = \n",
    )
    .unwrap();
    assert_eq!(s.header, ["the wire", "k = 98 kN/m"]);
    assert_eq!(s.steps.len(), 2);
    assert_eq!(s.steps[1].line, 6);
    assert_eq!(s.keys().collect::<Vec<_>>(), ["answer", "a"]);
    assert_eq!(
        s.steps[0].bindings[0].value(&v(r#"{"solutions": [3]}"#)),
        Some(&v("3"))
    );
    for (bad, line) in [
        ("#> a = /x\n", 1),
        ("mechkit x\n#> a /x\n", 2),
        ("mechkit x\n#> a = x\n", 2),
        ("echo hi\n", 1),
        ("mechkit \"x\n", 1),
    ] {
        assert_eq!(Script::parse(bad).unwrap_err().line, line, "{bad}");
    }
}

#[test]
fn shell_words_follow_the_shell() {
    assert_eq!(
        shell_words(r#"potential "U0*(a/r)^12" --range=-1:2 --set 'a=1, b=2' x"y z" "a\"b\\c\d""#)
            .unwrap(),
        [
            "potential",
            "U0*(a/r)^12",
            "--range=-1:2",
            "--set",
            "a=1, b=2",
            "xy z",
            r#"a"b\c\d"#
        ]
    );
    assert!(shell_words("'open").is_err());
    assert_eq!(shell_words("''").unwrap(), [""]);
}
