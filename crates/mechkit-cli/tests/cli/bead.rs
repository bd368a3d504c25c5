//! `mechkit bead`: sliding off a cylinder (departure at cos φ = 2/3 + v₀²/3gR), the loop from
//! a drop height (no departure from 5R/2 up), a bead in a bowl (turning points), path.csv and
//! path.svg, and bad input.

use crate::util::{Csv, Dir, at, num};

#[test]
fn sliding_off_a_cylinder_and_the_csv() {
    let dir = Dir::new();
    let out = dir.run(&[
        "bead", "--circle", "2 m", "--side", "outside", "--start", "0", "--speed", "1 m/s",
        "--t-max", "3 s", "--out", "o", "--json",
    ]);
    out.assert_code(0);
    let j: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    let exact = (2.0 + 1.0 / (9.81 * 2.0)) / 3.0;
    assert!((num(&j, "/departure/cos_angle") - exact).abs() < 1e-9);
    assert!(num(&j, "/energy_drift_per_mass") < 1e-8);
    let csv = Csv::parse(&dir.read("o/path.csv"));
    let on = csv.column("on_curve");
    let n = csv.column("normal_force");
    // on the curve N ≥ 0 down to rounding, then the free flight
    assert!(
        csv.rows
            .iter()
            .filter(|r| r[on] == 1.0)
            .all(|r| r[n] > -1e-9)
    );
    assert!(csv.rows.iter().any(|r| r[on] == 0.0));
    let svg = dir.read("o/path.svg");
    assert!(svg.contains("<svg") && svg.contains("leaves (N = 0)"));
}

#[test]
fn the_loop_from_a_drop_height() {
    let run = |h: &str| {
        let out = Dir::new().run(&[
            "bead",
            "--circle",
            "1 m",
            "--side",
            "inside",
            "--start",
            "180 deg",
            "--drop-height",
            h,
            "--t-max",
            "2 s",
            "--no-plots",
            "--json",
        ]);
        out.assert_code(0);
        serde_json::from_str::<serde_json::Value>(&out.stdout).unwrap()
    };
    assert!(at(&run("2.51 m"), "/departure").is_null());
    let low = run("2.3 m");
    assert!((num(&low, "/departure/cos_angle") - (2.0 * 2.3 - 2.0) / 3.0).abs() < 1e-9);
    assert_eq!(at(&low, "/stop_reason").as_str(), Some("landed"));
}

#[test]
fn a_bead_in_a_bowl_and_the_text() {
    let out = Dir::new().run(&[
        "bead",
        "--curve",
        "x^2/(2*R)",
        "--set",
        "R=1 m",
        "--start",
        "0.5 m",
        "--t-max",
        "3 s",
        "--no-plots",
    ]);
    out.assert_code(0);
    assert!(out.stdout.contains("y' = x/R"), "{}", out.stdout);
    assert!(out.stdout.contains("stays on the curve") && out.stdout.contains("turning points"));
}

#[test]
fn bad_bead_input() {
    let dir = Dir::new();
    dir.run(&["bead", "--t-max", "1 s"])
        .assert_bad_input(&["--circle"]);
    dir.run(&["bead", "--circle", "0 m", "--t-max", "1 s"])
        .assert_bad_input(&["--circle", "radius"]);
    dir.run(&[
        "bead", "--circle", "1 m", "--side", "left", "--t-max", "1 s",
    ])
    .assert_bad_input(&["--side", "outside, inside"]);
    dir.run(&[
        "bead",
        "--curve",
        "sqrt(1-x^2)",
        "--start",
        "2 m",
        "--t-max",
        "1 s",
    ])
    .assert_bad_input(&["--start", "undefined or vertical at x = 2"]);
    dir.run(&["bead", "--curve", "k*x^2", "--t-max", "1 s"])
        .assert_bad_input(&["--curve", "--set k="]);
}
