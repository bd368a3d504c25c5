//! Adaptive runs, events and `--compare-methods` through the binary.

use approx::assert_abs_diff_eq;

use crate::util::{Csv, Dir, at, examples, num};

#[test]
fn bouncing_ball_writes_events_step_control_and_output_times() {
    let dir = Dir::new();
    let file = examples().join("bouncing_ball.toml");
    let out = dir.run(&["run", file.to_str().unwrap(), "--out", "out"]);
    out.assert_code(0);
    let s = dir.read_json("out/summary.json");
    assert_eq!(at(&s, "/step_control/mode"), "adaptive");
    assert_abs_diff_eq!(num(&s, "/step_control/rtol"), 1e-10);
    assert!(num(&s, "/step_control/accepted") > 10.0);
    assert_eq!(at(&s, "/events/1/name"), "bounce");
    assert_eq!(at(&s, "/events/1/occurrence").as_u64(), Some(1));
    assert_abs_diff_eq!(
        num(&s, "/events/1/t"),
        (2.0f64 / 9.81).sqrt(),
        epsilon = 1e-12
    );
    assert_abs_diff_eq!(
        num(&s, "/events/1/after/ball/velocity/1"),
        -0.9 * num(&s, "/events/1/state/ball/velocity/1"),
        epsilon = 1e-12
    );
    assert!(num(&s, "/energy/events_change") < 0.0);
    assert!(num(&s, "/energy/relative_drift").abs() < 1e-12);
    // rows every 5 ms, plus the events (before and after each bounce)
    let csv = Csv::parse(&dir.read("out/trajectory.csv"));
    let t: Vec<f64> = csv.rows.iter().map(|r| r[csv.column("t")]).collect();
    assert!(t.windows(2).all(|w| w[0] <= w[1]));
    assert!(t.iter().any(|x| (x - 0.005).abs() < 1e-15));
    assert!((t.len() as f64 - 1200.0).abs() < 60.0, "{} rows", t.len());
    assert!(out.stdout.contains("adaptive (rtol"), "{}", out.stdout);
}

#[test]
fn compare_methods_writes_a_table_json_and_plots() {
    let dir = Dir::new();
    let file = examples().join("feather.toml");
    let out = dir.run(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        "cmp",
        "--compare-methods",
        "euler,euler-cromer,rk4,dopri5",
    ]);
    out.assert_code(0);
    for m in [
        "euler with dt",
        "euler-cromer with dt",
        "rk4 with dt",
        "dopri5, adaptive",
    ] {
        assert!(out.stdout.contains(m), "{m}:\n{}", out.stdout);
    }
    let c = dir.read_json("cmp/compare.json");
    assert_eq!(c["methods"].as_array().unwrap().len(), 4);
    let rk4 = num(&c, "/methods/2/max_position_error");
    let euler = num(&c, "/methods/0/max_position_error");
    assert!(rk4 < 1e-9 && euler > 1e-5, "rk4 {rk4}, euler {euler}");
    assert!(dir.path().join("cmp/compare_error.svg").exists());
    assert!(dir.path().join("cmp/compare_energy.svg").exists());
    // an adaptive scenario needs --dt for fixed-step methods
    let bb = examples().join("bouncing_ball.toml");
    let out = dir.run(&[
        "run",
        bb.to_str().unwrap(),
        "--out",
        "cmp2",
        "--compare-methods",
        "rk4,dop853",
        "--no-plots",
    ]);
    out.assert_code(0);
    assert!(out.stdout.contains("give --dt"), "{}", out.stdout);
    let out = dir.run(&[
        "run",
        bb.to_str().unwrap(),
        "--out",
        "cmp3",
        "--compare-methods",
        "rk4",
        "--dt",
        "2 ms",
        "--no-plots",
    ]);
    out.assert_code(0);
    assert!(
        out.stdout.contains("rk4 with dt = 0.002 s"),
        "{}",
        out.stdout
    );
}

#[test]
fn compare_methods_bad_input() {
    let dir = Dir::new();
    let file = examples().join("feather.toml");
    let f = file.to_str().unwrap();
    dir.run(&["run", f, "--compare-methods", "rk5"])
        .assert_bad_input(&["unknown method `rk5`", "dopri5"]);
    dir.run(&["run", f, "--compare-methods", "rk4", "--dt", "3 kg"])
        .assert_bad_input(&["not a time"]);
    dir.run(&["run", f, "--dt", "1 ms"]).assert_code(2);
}

#[test]
fn event_errors_are_located() {
    let dir = Dir::new();
    let base = r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
position = "1 m"
[[force]]
kind = "uniform-gravity"
[integrator]
method = "dopri5"
[stop]
t_max = "1 s"
"#;
    for (event, needles) in [
        (
            "[[event]]\nfunction = \"height\"",
            &["e.toml:13:13", "`height`"][..],
        ),
        (
            "[[event]]\nfunction = \"x\"\ndirection = \"sideways\"",
            &["e.toml:14:13", "unknown direction"][..],
        ),
        (
            "[[event]]\nwhen = \"x < 0\"\nfunction = \"x\"",
            &["not both"][..],
        ),
        (
            "[[event]]\nfunction = \"x\"\naction = \"stop\"\nset = { v = \"-v\" }",
            &["cannot change the state"][..],
        ),
        (
            "[[event]]\nfunction = \"x\"\nset = { K = \"0\" }",
            &["`set` can change position and velocity"][..],
        ),
        (
            "[[event]]\nfunction = \"x\"\nset = { v = \"2 m\" }",
            &["e.toml:14:"][..],
        ),
        (
            "[[event]]\nfunction = \"x\"\ncount = 2",
            &["action = \"stop\"", "`count`"][..],
        ),
    ] {
        dir.create("e.toml", &format!("{base}{event}\n"));
        let out = dir.run(&["run", "e.toml", "--out", "out"]);
        out.assert_bad_input(needles);
    }
}

#[test]
fn list_integrators_shows_kinds_and_orders() {
    let out = Dir::new().run(&["list-integrators"]);
    out.assert_code(0);
    for m in [
        "dopri5",
        "dop853",
        "bs3",
        "heun",
        "yoshida4",
        "forest-ruth",
        "pefrl",
        "yoshida6",
    ] {
        assert!(
            out.stdout.lines().any(|l| l.starts_with(m)),
            "{m}:\n{}",
            out.stdout
        );
    }
    assert!(out.stdout.contains("adaptive") && out.stdout.contains("symplectic"));
}
