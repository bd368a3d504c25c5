//! Issue 11 (reliability): four command-line bugs found while cataloguing the error messages.
//! Each input used to be accepted silently or refused with a misleading message.

use crate::util::Dir;

/// `com --mass … --mark out.png` ignored `--mark` (exit 0): an image-only flag is refused.
#[test]
fn issue_011_com_mark_with_point_masses_is_refused() {
    let dir = Dir::new();
    dir.run(&["com", "--mass", "1 kg", "--at", "0 m", "--mark", "out.png"])
        .assert_bad_input(&["--mark applies to an image", "point masses"]);
    assert!(!dir.path().join("out.png").exists());
    for extra in [
        ["--threshold", "0.5"],
        ["--total-mass", "2 kg"],
        ["--about", "1 m"],
    ] {
        let mut args = vec!["com", "--mass", "1 kg", "--at", "0 m"];
        args.extend(extra);
        dir.run(&args).assert_bad_input(&[extra[0], "point masses"]);
    }
    // point masses alone still work
    dir.run(&[
        "com", "--mass", "1 kg", "--at", "0 m", "--mass", "1 kg", "--at", "2 m",
    ])
    .assert_code(0);
}

/// `md --density -1` was taken by clap for a flag ("unexpected argument '-1'"); negative
/// numbers are values of every numeric option and reach mechkit's own checks.
#[test]
fn issue_011_negative_numbers_are_option_values() {
    let dir = Dir::new();
    let out = dir.run(&["md", "--density", "-1"]);
    out.assert_bad_input(&["--density", "must be positive"]);
    assert!(
        !out.stderr.contains("unexpected argument"),
        "{}",
        out.stderr
    );
    dir.run(&["md", "--cells", "-1"])
        .assert_bad_input(&["not a whole number"]);
    // meaningful negative values parse with a space
    dir.run(&["potential", "x^2", "--range", "-1:2", "--energy", "-0.5"])
        .assert_code(0);
    dir.run(&[
        "collide", "--m1", "1", "--v1", "-3", "--m2", "1", "--v2", "-5", "-e", "1",
    ])
    .assert_code(0);
    dir.run(&["integrate", "x", "--from", "-1", "--to", "2"])
        .assert_code(0);
}

/// `potential x^2 --range 2:1` was accepted; a range must be increasing. The limits of an
/// integral stay oriented (∫ from 1 to 0 = −∫ from 0 to 1).
#[test]
fn issue_011_reversed_range_is_refused() {
    let dir = Dir::new();
    dir.run(&["potential", "x^2", "--range", "2:1"])
        .assert_bad_input(&["must be increasing", "--range 1:2"]);
    dir.run(&["solve", "cos(x) = x", "--for", "x", "--in", "1:0"])
        .assert_bad_input(&["must be increasing", "--in 0:1"]);
    let out = dir.run(&["integrate", "x", "--from", "1", "--to", "0", "--json"]);
    out.assert_code(0);
    let v = out.json();
    assert_eq!(v["definite"]["closed_form"].as_f64(), Some(-0.5), "{v}");
}

/// `solve "…" --for y` without `y` said "no real y solves" (exit 1): it is bad input, and the
/// names that do appear are listed.
#[test]
fn issue_011_solve_for_a_name_not_in_the_equation() {
    let dir = Dir::new();
    let out = dir.run(&["solve", "a*x + b = 0", "--for", "y"]);
    out.assert_bad_input(&["`y` does not appear", "`a`, `b`, `x`"]);
    assert!(!out.stderr.contains("no real"), "{}", out.stderr);
    dir.run(&["solve", "x + y = 1; x - y = 0", "--for", "x,z"])
        .assert_bad_input(&["`z` does not appear"]);
    // a name that cancels out is still in the equation: no real root
    let out = dir.run(&["solve", "x = x + 1", "--for", "x"]);
    assert!(out.stdout.contains("no real x"), "{}", out.stdout);
}
