//! Issue 23, units: `mechkit units` with rational powers (`N/m^1.5`, `m^(3/2)`, …), exact large
//! powers (`(((m^12)^12)^12)^12` is m^20736, not m^5000), located errors for powers that are
//! not fractions or overflow; `mechkit run` of a scenario in reduced units labels its outputs
//! `1` and prints no SI units.

use crate::util::{Dir, num};

#[test]
fn rational_powers_print_exactly() {
    let dir = Dir::new();
    for (quantity, si) in [
        ("1e5 N/m^1.5", "1e5 N/m^1.5 = 100000 kg/(m^(1/2)*s^2)\n"),
        ("1e5 N/m^(3/2)", "1e5 N/m^(3/2) = 100000 kg/(m^(1/2)*s^2)\n"),
        ("2 m^-1.5", "2 m^-1.5 = 2 1/m^(3/2)\n"),
        ("2 m^(-3/2)", "2 m^(-3/2) = 2 1/m^(3/2)\n"),
        ("3 s^0.5", "3 s^0.5 = 3 s^(1/2)\n"),
        ("3 kg^(1/2)", "3 kg^(1/2) = 3 kg^(1/2)\n"),
        (
            "1 (((m^12)^12)^12)^12",
            "1 (((m^12)^12)^12)^12 = 1 m^20736\n",
        ),
        ("1 m^0.5*m^0.5", "1 m^0.5*m^0.5 = 1 m   [length]\n"),
    ] {
        let out = dir.run(&["units", quantity]);
        out.assert_code(0);
        assert_eq!(out.stdout, si, "{quantity}");
    }
    let j = dir.json(&["units", "1e5 N/cm^1.5", "--to", "N/m^(3/2)", "--json"]);
    assert_eq!(j["dimension"], "kg/(m^(1/2)*s^2)");
    assert!((num(&j, "/converted/value") - 1e5 * 1e3).abs() < 1e-3);
}

#[test]
fn bad_powers_are_located_errors() {
    let dir = Dir::new();
    for (quantity, says) in [
        ("1e5 N/m^3/2", "a fractional power needs parentheses"),
        ("1 m^0.333333", "q at most 1000"),
        ("1 m^99", "out of range"),
        ("1 m^(1/0)", "not a fraction of whole numbers"),
        (
            "1 (((km^12)^12)^12)^12",
            "too large to hold in floating point",
        ),
    ] {
        dir.run(&["units", quantity]).assert_bad_input(&[says]);
    }
    dir.run(&["units", "1e5 N/m^3/2"]).assert_bad_input(&[
        "1e5 N/m^3/2\n",
        "^^^",
        "write `^(3/2)`",
    ]);
}

#[test]
fn a_reduced_scenario_prints_no_si_units() {
    let dir = Dir::new();
    let path = dir.create(
        "lj.toml",
        r#"
title = "Lennard-Jones pair"
units = "reduced"
[[body]]
name = "a"
mass = 1
position = 0
[[body]]
name = "b"
mass = 1
position = 1.2
[[force]]
name = "pair"
kind = "expression"
on = "b"
F = "4*(12*(b.x - a.x)^-13 - 6*(b.x - a.x)^-7)"
[[force]]
name = "pair_a"
kind = "expression"
on = "a"
F = "-4*(12*(b.x - a.x)^-13 - 6*(b.x - a.x)^-7)"
[integrator]
method = "rk4"
dt = 0.001
[stop]
t_max = 1
[observe]
r_end = "final(b.x - a.x)"
[output]
plots = ["x(t)"]
"#,
    );
    let out = dir.run(&["run", path.to_str().unwrap(), "--out", "out"]);
    out.assert_code(0);
    for si in [" m,", " m/s", " J\n", "(J)", " kg"] {
        assert!(!out.stdout.contains(si), "{si:?} in\n{}", out.stdout);
    }
    let units = dir.read_json("out/trajectory.units.json");
    assert!(
        units.as_object().unwrap().values().all(|u| u == "1"),
        "{units}"
    );
    let summary = dir.read_json("out/summary.json");
    assert_eq!(summary["units"], "reduced");
    assert_eq!(summary["observable_units"]["r_end"], "1");
    assert!(dir.read("out/x_t.svg").contains("[1]"));

    let check = dir.run(&["check", path.to_str().unwrap()]);
    check.assert_code(0);
    assert!(
        check.stdout.contains("in reduced units"),
        "{}",
        check.stdout
    );
    for si in [" kg\n", " s\n"] {
        assert!(!check.stdout.contains(si), "{si:?} in\n{}", check.stdout);
    }

    let bad = dir.create(
        "bad.toml",
        &dir.read("lj.toml")
            .replace("position = 1.2", "position = \"1.2 nm\""),
    );
    dir.run(&["check", bad.to_str().unwrap()])
        .assert_bad_input(&["bad.toml:10:17", "reduced units", "the unit `nm`"]);
}
