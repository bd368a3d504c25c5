//! `mechkit relative` (steering through a current, frames) and `mechkit terminal` (drag from a
//! terminal velocity), beyond the book's cases.

use std::fmt::Write as _;

use crate::util::{Dir, num};

#[test]
fn a_boat_crossing_a_river_heads_upstream_and_crosses_slower() {
    let dir = Dir::new();
    // 2 m/s through the water, a 1 m/s current towards +x, to cross along +y
    let out = dir.run(&[
        "relative",
        "--speed",
        "2 m/s",
        "--current",
        "1 m/s",
        "--track",
        "90 deg",
        "--json",
    ]);
    out.assert_code(0);
    let j = out.json();
    assert!((num(&j, "/ground_speed") - 3f64.sqrt()).abs() < 1e-12);
    assert!((num(&j, "/angle_to_upstream_deg") - 60.0).abs() < 1e-9);
    assert!((num(&j, "/correction_deg") - 30.0).abs() < 1e-9);
    assert!((num(&j, "/heading_deg") - 120.0).abs() < 1e-9);
    // a tailwind along the track adds, a headwind subtracts
    let with = dir.run(&[
        "relative",
        "--speed",
        "100 km/h",
        "--current",
        "20 km/h",
        "--current-direction",
        "north",
        "--track",
        "north",
        "--in",
        "km/h",
        "--json",
    ]);
    assert!((num(&with.json(), "/ground_speed") - 120.0).abs() < 1e-9);
}

#[test]
fn an_impossible_crossing_fails_and_a_bad_direction_is_bad_input() {
    let dir = Dir::new();
    dir.run(&[
        "relative",
        "--speed",
        "1 m/s",
        "--current",
        "2 m/s",
        "--track",
        "north",
    ])
    .assert_code(1)
    .assert_stderr_contains("faster than the craft");
    dir.run(&[
        "relative",
        "--speed",
        "1 m/s",
        "--current",
        "0.5 m/s",
        "--track",
        "nord",
    ])
    .assert_bad_input(&["--track", "`nord`", "compass word"]);
}

#[test]
fn rain_seen_from_a_moving_car_comes_slanted() {
    let dir = Dir::new();
    // rain falling at 8 m/s, a car at 15 m/s: 17 m/s relative to the driver
    let out = dir.run(&[
        "relative",
        "--velocity",
        "0, -8 m/s",
        "--relative-to",
        "15, 0 m/s",
        "--json",
    ]);
    let j = out.json();
    assert_eq!(j["velocity"], serde_json::json!([-15.0, -8.0]));
    assert!((num(&j, "/speed") - 17.0).abs() < 1e-12);
    // and back: the velocity in the car's frame plus the car's velocity is the rain's
    let back = dir.run(&[
        "relative",
        "--velocity",
        "-15, -8 m/s",
        "--frame-velocity",
        "15, 0 m/s",
        "--json",
    ]);
    assert_eq!(back.json()["velocity"], serde_json::json!([0.0, -8.0]));
}

#[test]
fn a_line_through_a_steady_fall_gives_the_drag() {
    // y = y0 − ln(cosh(√(g k) t))/k with k = D/m = 0.5 1/m: v_T = √(g/k)
    let (g, k) = (9.81_f64, 0.5_f64);
    let mut text = String::from("t,y\n");
    for i in 0..=600 {
        let t = f64::from(i) * 0.01;
        let y = 100.0 - ((g * k).sqrt() * t).cosh().ln() / k;
        let _ = writeln!(text, "{t},{y}");
    }
    let dir = Dir::new();
    dir.create("fall.csv", &text);
    let out = dir.run(&["terminal", "--data", "fall.csv", "--from", "3 s", "--json"]);
    out.assert_code(0);
    let j = out.json();
    assert!((num(&j, "/terminal_speed") - (g / k).sqrt()).abs() < 1e-6);
    assert!((num(&j, "/per_mass") - k).abs() < 1e-6);
    assert!(j.get("warning").is_none());
    // in its first second the body still accelerates: the fit says so
    let first_second = text.lines().take(102).collect::<Vec<_>>().join("\n");
    dir.create("early.csv", &first_second);
    let early = dir.run(&["terminal", "--data", "early.csv", "--from", "0 s", "--json"]);
    early.assert_stderr_contains("not steady");
    // C_d of a ball: 2 m g/(ρ A v_T²)
    let ball = dir.run(&[
        "terminal",
        "--velocity",
        "20 m/s",
        "--mass",
        "57 g",
        "--density",
        "1.2 kg/m^3",
        "--radius",
        "3.3 cm",
        "--json",
    ]);
    let want = 2.0 * 0.057 * g / (1.2 * std::f64::consts::PI * 0.033f64.powi(2) * 400.0);
    assert!((num(&ball.json(), "/drag_coefficient") - want).abs() < 1e-12 * want);
    dir.run(&["terminal", "--velocity", "20 m/s", "--law", "cubic"])
        .assert_bad_input(&["--law", "quadratic", "linear"]);
    // 1/v_T² of 1e300 m/s underflows: refused at the flag, not printed as 0 with exit 0
    dir.run(&["terminal", "--velocity=-1e300"])
        .assert_bad_input(&["--velocity", "D/(m g)", "past what a double holds"]);
}
