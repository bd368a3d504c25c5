//! Running scenarios: outputs are written atomically and kept when a run diverges; a missing
//! t_max is bounded with a warning.

use mechkit::scenario::Scenario;

const DIVERGING: &str = r#"
title = "falls onto a singularity"
[[body]]
name = "probe"
mass = "1e30 kg"
position = "1 m"
velocity = "-1 m/s"
[[force]]
name = "pull"
kind = "expression"
F = "-1/x^2"
[integrator]
method = "euler-cromer"
dt = "0.25 s"
[stop]
t_max = "10 s"
"#;

#[test]
fn divergence_keeps_the_trajectory_and_writes_the_summary() {
    let dir = tempfile::tempdir().unwrap();
    let s = Scenario::from_str("diverging.toml", DIVERGING).unwrap();
    let out = s.run_to_dir(dir.path()).unwrap();
    assert!(out.failed());
    assert_eq!(out.summary.stop_reason, "diverged");
    let d = out.summary.divergence.as_ref().unwrap();
    assert!(d.quantity.contains("pull"), "{d:?}");
    assert_eq!(d.t, 1.0);
    let csv = std::fs::read_to_string(dir.path().join("trajectory.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    // no force has a potential, so there are no U and E columns
    assert_eq!(rows[0], "t,probe.x,probe.vx,K,work.pull,power.pull");
    assert_eq!(rows.len(), 1 + 5, "t = 0 … 1 s");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("summary.json")).unwrap())
            .unwrap();
    assert_eq!(json["stop_reason"], "diverged");
    // no temporary files are left behind
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(names.iter().all(|n| !n.ends_with(".partial")), "{names:?}");
}

#[test]
fn missing_t_max_is_bounded_with_a_warning() {
    let text = r#"
[[body]]
mass = "1 kg"
[integrator]
method = "euler"
dt = "1 s"
[stop]
when = "x < -1"
"#;
    let s = Scenario::from_str("forever.toml", text).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("t_max")));
    let out = s.run().unwrap();
    assert_eq!(out.summary.stop_reason, "max_steps");
    assert_eq!(out.summary.steps, mechkit::simulate::DEFAULT_MAX_STEPS);
    assert!(
        out.summary
            .warnings
            .iter()
            .any(|w| w.contains("never became true"))
    );
}

#[test]
fn decimation_keeps_the_last_row() {
    let dir = tempfile::tempdir().unwrap();
    let text =
        std::fs::read_to_string(crate::util::workspace().join("examples/feather.toml")).unwrap();
    let s = Scenario::from_str("feather.toml", &text).unwrap();
    let out = s.run_to_dir(dir.path()).unwrap();
    let csv = std::fs::read_to_string(dir.path().join("trajectory.csv")).unwrap();
    let last: Vec<f64> = csv
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    assert!((last[0] - out.summary.t_end).abs() < 1e-15);
    assert!(last[1].abs() < 1e-12, "ends on the floor");
    // every 10th of 4835 steps, plus the first row and the located landing
    assert_eq!(out.summary.files.trajectory_rows, 484 + 1);
}
