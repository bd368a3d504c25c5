//! Runs that fail (exit 1, output kept) and runs bounded by the default step budget.

use approx::assert_abs_diff_eq;

use crate::util::{self, Csv, Dir, at, num};

/// Checks the output of a diverged run in `dir/out`: exit 1, the explanation on stderr, the
/// rows before the failure in trajectory.csv and `stop_reason = "diverged"` in summary.json.
/// Returns the summary.
fn assert_diverged(dir: &Dir, out: &util::Output, min_rows: usize) -> serde_json::Value {
    out.assert_code(1);
    assert!(
        out.stderr.starts_with("error:"),
        "stderr does not start with `error:`:\n{}",
        out.stderr
    );
    assert!(!out.stderr.contains("panicked"), "{}", out.stderr);
    out.assert_stderr_contains("diverged");

    let csv = Csv::parse(&dir.read("out/trajectory.csv"));
    assert!(
        csv.rows.len() >= min_rows,
        "only {} rows before the failure",
        csv.rows.len()
    );
    let positions: Vec<usize> = csv
        .header
        .iter()
        .enumerate()
        .filter(|(_, h)| h.rsplit('.').next() == Some("x"))
        .map(|(i, _)| i)
        .collect();
    assert!(
        !positions.is_empty(),
        "no position column in {:?}",
        csv.header
    );
    for row in &csv.rows {
        assert!(row[0].is_finite(), "non-finite time in {row:?}");
        for &i in &positions {
            assert!(row[i].is_finite(), "non-finite position in {row:?}");
        }
    }
    let s = dir.read_json("out/summary.json");
    assert_eq!(at(&s, "/stop_reason"), "diverged");
    let d = at(&s, "/divergence");
    assert!(d.is_object(), "divergence is {d}");
    for key in ["t", "quantity", "message"] {
        assert!(d.get(key).is_some(), "divergence has no {key}: {d}");
    }
    assert_eq!(
        at(&s, "/files/trajectory_rows").as_u64(),
        Some(csv.rows.len() as u64)
    );
    let last_t = csv.rows.last().expect("rows")[0];
    assert!(last_t <= num(&s, "/divergence/t") + 1e-12);
    s
}

#[test]
fn division_by_zero_during_the_run_exits_1_and_keeps_the_output() {
    // `bead` moves freely from x = 1 m at -1 m/s, so with dt = 0.25 s it is exactly at
    // x = 0 at t = 1 s, where the force 1/bead.x on `probe` is infinite.
    let dir = Dir::new();
    dir.create(
        "division.toml",
        r#"
dimensions = 1
[constants]
c = "1 N*m"
[[body]]
name = "probe"
mass = "1 kg"
[[body]]
name = "bead"
mass = "1 kg"
position = "1 m"
velocity = "-1 m/s"
[[force]]
name = "repel"
kind = "expression"
on = "probe"
F = "c/bead.x"
[integrator]
method = "euler"
dt = "0.25 s"
[stop]
t_max = "10 s"
"#,
    );
    let out = dir.run(&["run", "division.toml", "--out", "out"]);
    let s = assert_diverged(&dir, &out, 4);
    out.assert_stderr_contains("`repel`")
        .assert_stderr_contains("t = 1 s");
    assert_abs_diff_eq!(num(&s, "/divergence/t"), 1.0, epsilon = 1e-12);
    let quantity = at(&s, "/divergence/quantity").as_str().expect("a string");
    assert!(quantity.contains("repel"), "quantity: {quantity}");
}

#[test]
fn step_leaving_the_domain_of_a_formula_exits_1_and_keeps_the_output() {
    // sqrt(x) is defined until the bead, moving from x = 1 m at about -1 m/s, passes x = 0
    // between t = 1 s and 1.25 s; an RK4 stage there makes the state NaN.
    let dir = Dir::new();
    dir.create(
        "sqrt.toml",
        r#"
dimensions = 1
[constants]
c = 0.01
[[body]]
name = "bead"
mass = "1 kg"
position = "1 m"
velocity = "-1 m/s"
[[force]]
name = "push"
kind = "expression"
F = "c*sqrt(x)"
[integrator]
method = "rk4"
dt = "0.25 s"
[stop]
t_max = "10 s"
"#,
    );
    let out = dir.run(&["run", "sqrt.toml", "--out", "out"]);
    let s = assert_diverged(&dir, &out, 4);
    out.assert_stderr_contains("bead.x")
        .assert_stderr_contains("t = 1 s");
    assert_abs_diff_eq!(num(&s, "/divergence/t"), 1.0, epsilon = 1e-12);
    assert_eq!(at(&s, "/divergence/quantity"), "bead.x");
}

#[test]
fn stop_condition_that_never_fires_ends_at_the_step_budget() {
    // No t_max and a condition that never holds: the default budget of 1,000,000 steps ends
    // the run. Few rows are kept (`every`) and no plots drawn, to keep the test fast.
    let dir = Dir::new();
    dir.create(
        "never.toml",
        r#"
dimensions = 1
[[body]]
name = "rock"
mass = "1 kg"
[integrator]
method = "euler-cromer"
dt = "1 s"
[stop]
when = "x < -1000"
[output]
every = 100000
"#,
    );
    let out = dir.run(&["run", "never.toml", "--out", "out", "--no-plots"]);
    out.assert_code(0);
    assert!(
        out.stderr
            .lines()
            .any(|l| l.starts_with("warning:") && l.contains("t_max")),
        "no warning about t_max:\n{}",
        out.stderr
    );
    let s = dir.read_json("out/summary.json");
    assert_eq!(at(&s, "/stop_reason"), "max_steps");
    assert_eq!(at(&s, "/steps").as_u64(), Some(1_000_000));
    assert_abs_diff_eq!(num(&s, "/t_end"), 1e6, epsilon = 1e-6);
    assert_abs_diff_eq!(num(&s, "/bodies/rock/position/0"), 0.0);
    let csv = Csv::parse(&dir.read("out/trajectory.csv"));
    assert_abs_diff_eq!(csv.rows.last().expect("rows")[0], 1e6, epsilon = 1e-6);
}
