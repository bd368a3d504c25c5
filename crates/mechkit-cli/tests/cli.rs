//! Command-line tests of the `mechkit` binary, run as a separate process in a temporary
//! directory.
//!
//! What is checked:
//! - `mechkit run examples/feather.toml --out DIR` exits 0 and writes `trajectory.csv` (header,
//!   landing row), `summary.json` (the contract keys: t_end, steps, stop_reason, bodies, work,
//!   kinetic and potential energy, work-energy residual, events with the last step before the
//!   landing, observables) and the SVG plots listed in `files.plots` (relative to the summary);
//! - `--json` prints the same summary on stdout;
//! - `mechkit check` accepts every scenario in `examples/` and `examples/book/`;
//! - `--help` shows examples and the exit codes; `list-integrators` lists every method;
//! - every bad input exits 2 with `error:` first on stderr, the location `file.toml:LINE:COL`
//!   and the specific message: unknown key (with the nearest valid key), missing, negative or
//!   zero mass, zero or negative dt, unknown unit (with a suggestion), wrong dimension (both
//!   dimensions named), undefined name in a formula (its column in the file line), invalid
//!   TOML, a missing scenario file, an unwritable output directory;
//! - a run that hits a non-finite value exits 1, explains what diverged and when, and keeps
//!   the trajectory computed so far and a summary with `stop_reason = "diverged"`;
//! - a run with no `t_max` whose stop condition never fires ends at the default step budget,
//!   exits 0 and warns about `t_max`.
//!
//! Numbers from files are compared within tolerances, never as strings.

mod util;

use approx::assert_abs_diff_eq;
use util::{Csv, Dir, at, examples, num};

/// Runs the feather example into `DIR/out` and returns the directory.
fn run_feather(extra: &[&str]) -> (Dir, util::Output) {
    let dir = Dir::new();
    let feather = examples().join("feather.toml");
    let mut args = vec![
        "run",
        feather.to_str().expect("a UTF-8 path"),
        "--out",
        "out",
    ];
    args.extend_from_slice(extra);
    let out = dir.run(&args);
    (dir, out)
}

#[test]
fn feather_run_writes_trajectory_summary_and_plots() {
    let (dir, out) = run_feather(&[]);
    out.assert_code(0);

    // trajectory.csv: the header, then the landing as the last row
    let csv = Csv::parse(&dir.read("out/trajectory.csv"));
    assert_eq!(
        csv.header.join(","),
        "t,feather.x,feather.vx,K,U,E,work.gravity,work.air"
    );
    assert!(csv.rows.len() > 10, "only {} rows", csv.rows.len());
    let first = &csv.rows[0];
    assert_abs_diff_eq!(first[csv.column("t")], 0.0);
    assert_abs_diff_eq!(first[csv.column("feather.x")], 2.4, epsilon = 1e-12);
    let last = csv.rows.last().expect("rows");
    let t_land = last[csv.column("t")];
    assert_abs_diff_eq!(t_land, 4.8354, epsilon = 1e-3);
    assert_abs_diff_eq!(t_land, 4.8346, epsilon = 1e-4);
    assert_abs_diff_eq!(last[csv.column("feather.x")], 0.0, epsilon = 1e-9);
    assert_abs_diff_eq!(last[csv.column("feather.vx")], -0.5, epsilon = 1e-6);

    // summary.json: the contract keys
    let s = dir.read_json("out/summary.json");
    assert_abs_diff_eq!(num(&s, "/t_end"), t_land, epsilon = 1e-12);
    let steps = at(&s, "/steps").as_u64().expect("steps is a whole number");
    assert!((4834..=4835).contains(&steps), "steps: {steps}");
    assert_eq!(at(&s, "/stop_reason"), "event");
    let position = at(&s, "/bodies/feather/position")
        .as_array()
        .expect("position is an array");
    assert_eq!(position.len(), 1);
    assert_abs_diff_eq!(num(&s, "/bodies/feather/position/0"), 0.0, epsilon = 1e-9);
    assert_abs_diff_eq!(num(&s, "/bodies/feather/velocity/0"), -0.5, epsilon = 1e-6);
    let w_gravity = num(&s, "/work/gravity");
    let w_air = num(&s, "/work/air");
    // gravity does m g h = 1 g * 9.8 m/s^2 * 2.4 m, up to the O(dt) error of integrating the
    // power along the Euler-Cromer path (2.45e-6 J here); the air takes almost all of it back
    assert_abs_diff_eq!(w_gravity, 0.001 * 9.8 * 2.4, epsilon = 1e-5);
    assert!(
        w_air < 0.0 && w_air > -w_gravity,
        "work of the air: {w_air}"
    );
    assert_abs_diff_eq!(num(&s, "/kinetic_energy/start"), 0.0);
    assert_abs_diff_eq!(
        num(&s, "/kinetic_energy/end"),
        0.5 * 0.001 * 0.25,
        epsilon = 1e-9
    );
    assert_abs_diff_eq!(
        num(&s, "/potential_energy/start"),
        0.001 * 9.8 * 2.4,
        epsilon = 1e-12
    );
    assert_abs_diff_eq!(num(&s, "/potential_energy/end"), 0.0, epsilon = 1e-9);
    let residual = num(&s, "/work_energy_residual");
    assert!(residual.abs() < 1e-3 * w_gravity, "residual {residual}");

    let events = at(&s, "/events").as_array().expect("events is an array");
    assert_eq!(events.len(), 1);
    assert_eq!(at(&s, "/events/0/name"), "x < 0");
    assert_abs_diff_eq!(num(&s, "/events/0/t"), t_land, epsilon = 1e-12);
    assert_abs_diff_eq!(
        num(&s, "/events/0/state/feather/position/0"),
        0.0,
        epsilon = 1e-9
    );
    assert_abs_diff_eq!(num(&s, "/events/0/last_step/t"), 4.834, epsilon = 1e-9);
    assert!(num(&s, "/events/0/last_step/state/feather/position/0") > 0.0);

    let observables = at(&s, "/observables")
        .as_object()
        .expect("observables is an object");
    for name in ["t_land", "v_land", "v_min", "x_half_t"] {
        assert!(observables.contains_key(name), "no observable {name}");
    }
    assert_abs_diff_eq!(num(&s, "/observables/t_land"), t_land, epsilon = 1e-12);
    assert_abs_diff_eq!(num(&s, "/observables/v_land"), -0.5, epsilon = 1e-6);

    // the plots listed in the summary exist and are SVG
    let plots = at(&s, "/files/plots")
        .as_array()
        .expect("plots is an array");
    assert_eq!(plots.len(), 4, "feather.toml asks for four plots");
    for p in plots {
        // paths are relative to the directory of summary.json
        let p = p.as_str().expect("a plot is a path");
        assert!(
            !p.contains('/'),
            "{p} should be a file name in the output directory"
        );
        let text = dir.read(&format!("out/{p}"));
        assert!(text.starts_with("<svg"), "{p} does not start with <svg");
    }
}

#[test]
fn json_flag_prints_the_summary_on_stdout() {
    let (dir, out) = run_feather(&["--json"]);
    out.assert_code(0);
    let printed: serde_json::Value = serde_json::from_str(&out.stdout)
        .unwrap_or_else(|e| panic!("stdout is not JSON: {e}\n{}", out.stdout));
    let written = dir.read_json("out/summary.json");
    assert_eq!(printed, written);
    assert_eq!(at(&printed, "/stop_reason"), "event");
    assert_abs_diff_eq!(num(&printed, "/t_end"), 4.8354, epsilon = 1e-3);
}

#[test]
fn check_accepts_every_example() {
    let dir = Dir::new();
    let mut files = Vec::new();
    for sub in [examples(), examples().join("book")] {
        for entry in std::fs::read_dir(&sub).expect("the examples directory exists") {
            let path = entry.expect("a directory entry").path();
            if path.extension().is_some_and(|e| e == "toml") {
                files.push(path);
            }
        }
    }
    files.sort();
    assert!(files.len() >= 10, "only {} examples found", files.len());
    let failures: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let out = dir.run(&["check", f.to_str().expect("a UTF-8 path")]);
            (out.code != Some(0))
                .then(|| format!("{} (exit {:?}):\n{}", f.display(), out.code, out.stderr))
        })
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn help_shows_examples_and_exit_codes() {
    let out = Dir::new().run(&["--help"]);
    out.assert_code(0);
    assert!(out.stdout.contains("Examples:"), "{}", out.stdout);
    assert!(
        out.stdout.contains("mechkit run examples/feather.toml"),
        "{}",
        out.stdout
    );
    assert!(out.stdout.contains("Exit codes"), "{}", out.stdout);
    for code in ["0 success", "1 the computation failed", "2 bad input"] {
        assert!(out.stdout.contains(code), "no {code:?} in\n{}", out.stdout);
    }
}

#[test]
fn list_integrators_lists_every_method() {
    let out = Dir::new().run(&["list-integrators"]);
    out.assert_code(0);
    let names: Vec<&str> = out
        .stdout
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    for m in ["euler", "euler-cromer", "verlet", "rk4"] {
        assert!(names.contains(&m), "{m} is not listed:\n{}", out.stdout);
    }
}

// ---------------------------------------------------------------------------------------------
// Bad input: exit 2, `error:` first, `file.toml:LINE:COL`, the specific message. Each run is
// `mechkit run FILE --out out`, which must not create `out`.

/// Writes `text` as `name`, runs it and checks the common contract of a bad input.
fn bad_input(name: &str, text: &str, needles: &[&str]) -> util::Output {
    let dir = Dir::new();
    dir.create(name, text);
    let out = dir.run(&["run", name, "--out", "out"]);
    out.assert_bad_input(needles);
    assert!(
        !dir.path().join("out").exists(),
        "a scenario with an error must not create the output directory"
    );
    out
}

/// Checks that stderr shows `line_text` followed by a caret line whose carets start under
/// `target` within it.
fn assert_caret_under(stderr: &str, line_text: &str, target: &str) {
    let lines: Vec<&str> = stderr.lines().collect();
    let i = lines
        .iter()
        .position(|l| l.ends_with(line_text))
        .unwrap_or_else(|| panic!("stderr does not quote {line_text:?}:\n{stderr}"));
    let quoted = lines[i];
    let carets = lines
        .get(i + 1)
        .expect("a caret line follows the quoted line");
    let want = quoted.find(line_text).expect("the line is quoted")
        + line_text.find(target).expect("target is in the line");
    assert_eq!(
        carets.find('^'),
        Some(want),
        "the caret is not under `{target}`:\n{stderr}"
    );
    assert_eq!(
        carets[want..].chars().take_while(|c| *c == '^').count(),
        target.chars().count(),
        "the carets do not underline `{target}`:\n{stderr}"
    );
}

#[test]
fn unknown_key_is_named_with_the_nearest_valid_key() {
    let out = bad_input(
        "unknown.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
masss = "1 g"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["unknown.toml:4:1", "`masss`", "`mass`"],
    );
    assert_caret_under(&out.stderr, r#"masss = "1 g""#, "masss");
}

#[test]
fn missing_mass_is_an_error() {
    bad_input(
        "missing_mass.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
position = "1 m"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["missing_mass.toml:2:1", "`mass`", "ball"],
    );
}

#[test]
fn negative_mass_is_an_error() {
    bad_input(
        "negative_mass.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "-2 kg"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["negative_mass.toml:4:8", "mass", "positive", "-2"],
    );
}

#[test]
fn zero_mass_is_an_error() {
    bad_input(
        "zero_mass.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "0 kg"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["zero_mass.toml:4:8", "mass", "positive"],
    );
}

#[test]
fn zero_dt_is_an_error() {
    bad_input(
        "zero_dt.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
[integrator]
method = "rk4"
dt = "0 s"
[stop]
t_max = "1 s"
"#,
        &["zero_dt.toml:7:6", "`dt`", "positive"],
    );
}

#[test]
fn negative_dt_is_an_error() {
    bad_input(
        "negative_dt.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
[integrator]
method = "rk4"
dt = "-1 ms"
[stop]
t_max = "1 s"
"#,
        &["negative_dt.toml:7:6", "`dt`", "positive"],
    );
}

#[test]
fn unknown_unit_is_named_with_a_suggestion() {
    let out = bad_input(
        "unknown_unit.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
velocity = "3 mps"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["unknown_unit.toml:5:15", "`mps`", "`m/s`"],
    );
    assert_caret_under(&out.stderr, r#"velocity = "3 mps""#, "mps");
}

#[test]
fn wrong_dimension_names_both_dimensions() {
    bad_input(
        "wrong_dimension.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "3 m"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        &["wrong_dimension.toml:4:8", "`mass`", "kg", "m (length)"],
    );
}

#[test]
fn undefined_name_in_a_formula_is_located_in_the_line() {
    let out = bad_input(
        "undefined_name.toml",
        r#"
dimensions = 1
[constants]
k = "10 N/m"
[[body]]
name = "block"
mass = "1 kg"
position = "0.1 m"
[[force]]
name = "spring"
kind = "expression"
F = "-k*xx"
[integrator]
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
        // `xx` starts at column 9 of `F = "-k*xx"`
        &["undefined_name.toml:11:9", "`xx`"],
    );
    assert_caret_under(&out.stderr, r#"F = "-k*xx""#, "xx");
}

#[test]
fn invalid_toml_is_located() {
    bad_input(
        "syntax.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = = "1 kg"
[integrator]
dt = "1 ms"
"#,
        &["syntax.toml:4:8", "invalid TOML"],
    );
}

#[test]
fn nonexistent_scenario_file_is_an_error() {
    let dir = Dir::new();
    let out = dir.run(&["run", "no_such_file.toml", "--out", "out"]);
    out.assert_bad_input(&["no_such_file.toml"]);
    assert!(!dir.path().join("out").exists());
}

#[test]
fn unwritable_output_directory_is_an_error() {
    let dir = Dir::new();
    dir.create(
        "ok.toml",
        r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
[integrator]
dt = "0.1 s"
[stop]
t_max = "1 s"
"#,
    );
    dir.create("afile", "a regular file, not a directory\n");
    let out = dir.run(&["run", "ok.toml", "--out", "afile/sub"]);
    out.assert_bad_input(&["afile/sub"]);
    assert!(dir.path().join("afile").is_file());
}

// ---------------------------------------------------------------------------------------------
// Runs that fail or do not end by themselves.

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

#[test]
fn a_closed_stdout_is_not_a_crash() {
    // `mechkit … | head`: the reader goes away; mechkit must stop quietly, not panic.
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_mechkit"))
        .arg("list-integrators")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("mechkit starts");
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("mechkit ends");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(out.status.code(), Some(0), "{stderr}");
}
