//! The data commands: `work` on force samples (work, impulse, speed, turning point, the CSV
//! and plot), `derive` on position samples, `diff --at`, and every bad data file the issue
//! names: a ragged row, a non-numeric cell, NaN, unsorted or duplicate x, fewer than 2 points.

use std::fmt::Write as _;

use crate::util::{Csv, Dir, example, num};

#[test]
fn work_of_a_spring_from_a_csv_with_a_header() {
    let dir = Dir::new();
    // F = -k (x - L0) with k = 100 N/m, L0 = 1 m, from x = 1.2 to 0.9 (the path runs backwards)
    let mut text = String::from("# a spring\nx [m], F [N]\n");
    for i in 0..=30 {
        let x = 1.2 - 0.01 * f64::from(i);
        writeln!(text, "{x}, {}", -100.0 * (x - 1.0)).unwrap();
    }
    dir.create("spring.csv", &text);
    let j = dir.json(&[
        "work",
        "spring.csv",
        "--x",
        "x",
        "--f",
        "F",
        "-o",
        "w",
        "--json",
    ]);
    // W = k(x0-L0)²/2 - k(x1-L0)²/2 = 2 - 0.5 = 1.5 J, exact for trapezoids of a linear force
    assert!((num(&j, "/work") - 1.5).abs() < 1e-12, "{j}");
    assert_eq!(j["of"], "position");
    // issue 22: plain column names, their units in the sidecar, the plot W_x in the directory
    let csv = Csv::parse(&dir.read("w/work.csv"));
    assert_eq!(csv.header, ["x", "F", "W"]);
    assert!((csv.rows[30][2] - 1.5).abs() < 1e-12);
    assert_eq!(
        dir.read_json("w/work.units.json"),
        serde_json::json!({"x": "m", "F": "N", "W": "J"})
    );
    assert!(dir.read("w/W_x.svg").starts_with("<svg"));
}

#[test]
fn work_energy_speed_and_turning_point_from_samples() {
    let dir = Dir::new();
    let j = dir.json(&[
        "work",
        &example("data/forcedata.d"),
        "--mass",
        "1 kg",
        "--v0",
        "0.5 m/s",
        "--json",
    ]);
    // ½ v0² = 0.125 J runs out where (1 - cos 2πx)/2π = 0.125
    let exact = (1.0 - 0.125 * std::f64::consts::TAU).acos() / std::f64::consts::TAU;
    assert!((num(&j, "/turning_point") - exact).abs() < 1e-5, "{j}");
}

#[test]
fn impulse_of_the_baseball_bat() {
    let dir = Dir::new();
    let out = dir.run(&[
        "work",
        &example("data/baseballforce.d"),
        "--of",
        "time",
        "--mass",
        "0.145",
    ]);
    out.assert_code(0);
    assert!(out.stdout.contains("impulse J"), "{}", out.stdout);
    assert!(out.stdout.contains("Δv = J/m = 93.87"), "{}", out.stdout);
}

#[test]
fn derive_the_falling_tennis_ball() {
    let dir = Dir::new();
    let j = dir.json(&[
        "derive",
        &example("data/fallingtennisball02.txt"),
        "--smooth",
        "21:2",
        "--out",
        "tb",
        "--json",
    ]);
    assert_eq!(num(&j, "/rows"), 2500.0);
    assert!((num(&j, "/uniform_step") - 1e-3).abs() < 1e-12);
    // released from rest: a ≈ -g at the start
    assert!(
        (num(&j, "/columns/0/acceleration/first") + 9.8).abs() < 0.01,
        "{j}"
    );
    let csv = Csv::parse(&dir.read("tb/derived.csv"));
    assert_eq!(csv.header, ["t", "x", "dx_dt", "d2x_dt2"]);
    assert_eq!(csv.rows.len(), 2500);
    // issue 22: plots named <y>_<x>
    for plot in ["x_t", "v_t", "a_t"] {
        assert!(dir.read(&format!("tb/{plot}.svg")).starts_with("<svg"));
    }
    // forward differences, the course's loop, without plots
    let j = dir.json(&[
        "derive",
        &example("data/fallingtennisball02.txt"),
        "--method",
        "forward",
        "--no-plots",
        "--out",
        "f",
        "--json",
    ]);
    assert_eq!(j["method"], "forward");
}

#[test]
fn diff_checks_the_symbolic_derivative_numerically() {
    let dir = Dir::new();
    let j = dir.json(&[
        "diff",
        "-F0*sin(2*pi*x/b)",
        "--at",
        "0.1",
        "--set",
        "F0=2,b=1",
        "--json",
    ]);
    let exact = -2.0 * std::f64::consts::TAU * (std::f64::consts::TAU * 0.1).cos();
    assert!((num(&j, "/at/symbolic") - exact).abs() < 1e-12);
    assert!((num(&j, "/at/numeric") - exact).abs() < 1e-9);
    assert_eq!(j["at"]["agree"], true);
}

#[test]
fn bad_data_files_say_which_line() {
    let dir = Dir::new();
    let cases: &[(&str, &str, &[&str])] = &[
        ("ragged.d", "0 1\n1 2 3\n2 3\n", &["ragged.d:2", "3 cells"]),
        (
            "word.d",
            "0 1\n1 abc\n",
            &["word.d:2", "`abc`", "not a number"],
        ),
        ("nan.d", "0 1\n1 NaN\n2 3\n", &["nan.d:2"]),
        (
            "dup.d",
            "0 1\n0.5 2\n0.5 3\n",
            &["lines 2 and 3", "distinct"],
        ),
        ("unsorted.d", "0 1\n1 2\n0.5 3\n", &["unsorted.d:3", "path"]),
        ("one.d", "% just one row\n0 1\n", &["one.d", "2"]),
    ];
    for (name, text, needles) in cases {
        dir.create(name, text);
        dir.run(&["work", name]).assert_bad_input(needles);
    }
    dir.run(&["work", "missing.d"])
        .assert_bad_input(&["missing.d"]);
    dir.create("ok.d", "0 1\n1 2\n2 3\n");
    dir.run(&["work", "ok.d", "--f", "5"])
        .assert_bad_input(&["--f", "5"]);
    dir.run(&["work", "ok.d", "--method", "romberg"])
        .assert_bad_input(&["romberg", "simpson"]);
    dir.create("even.d", "0 1\n1 2\n2 3\n3 4\n");
    dir.run(&["work", "even.d", "--method", "midpoint"])
        .assert_bad_input(&["even number"]);
    dir.run(&["work", "ok.d", "--mass", "2 m"])
        .assert_bad_input(&["--mass", "length"]);
    dir.run(&["derive", "ok.d", "--smooth", "4"])
        .assert_bad_input(&["--smooth", "odd"]);
    dir.create("back.d", "2 1\n1 2\n0 3\n");
    dir.run(&["derive", "back.d"])
        .assert_bad_input(&["increasing time"]);
}
