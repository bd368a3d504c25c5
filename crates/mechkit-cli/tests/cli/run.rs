//! Successful runs: files written, JSON on stdout, `check`, `--help`, `list-integrators`, a
//! closed stdout.

use approx::assert_abs_diff_eq;

use crate::util::{self, Csv, Dir, at, examples, num};

/// Runs the feather example into `DIR/out` and returns the directory.
fn run_feather(extra: &[&str]) -> (Dir, util::Output) {
    let dir = Dir::new();
    let feather = examples().join("feather.toml");
    let head = [
        "run",
        feather.to_str().expect("a UTF-8 path"),
        "--out",
        "out",
    ];
    let out = dir.run_with(&head, extra);
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
        "t,feather.x,feather.vx,K,U,E,work.gravity,work.air,power.gravity,power.air"
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
    for sub in [
        examples(),
        examples().join("book"),
        examples().join("friction"),
        examples().join("md"),
        examples().join("rigid"),
        examples().join("sweep"),
        examples().join("../bench/workloads"),
    ] {
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

/// A hinged rigid body runs end to end: the CSV has the angle and angular velocity, the
/// summary says `"coordinates": "angle"`, the text summary names theta and omega, and the
/// plots (theta(t), omega(t), energy(t), omega(theta)) are written.
#[test]
fn rigid_body_scenario_runs_end_to_end() {
    let dir = Dir::new();
    let file = examples().join("rigid/physical_pendulum.toml");
    let out = dir.run(&["run", file.to_str().unwrap(), "--out", "out"]);
    out.assert_code(0);
    assert!(out.stdout.contains("rod: theta"), "{}", out.stdout);
    let csv = Csv::parse(&dir.read("out/trajectory.csv"));
    let theta = csv.column("rod.theta");
    let omega = csv.column("rod.omega");
    assert!((csv.rows[0][theta] - 120f64.to_radians()).abs() < 1e-15);
    assert_eq!(csv.rows[0][omega], 0.0);
    let s = dir.read_json("out/summary.json");
    assert_eq!(at(&s, "/coordinates"), "angle");
    assert!((num(&s, "/bodies/rod/mass") - 0.336).abs() < 1e-14);
    for plot in [
        "theta_t.svg",
        "omega_t.svg",
        "energy_t.svg",
        "omega_theta.svg",
    ] {
        assert!(dir.path().join("out").join(plot).exists(), "{plot}");
    }
}

/// `"energy-bars"` draws the ledger as a waterfall: the bouncing ball's kinetic energy at the
/// start, the work of gravity, the energy its 31 bounces took, and its kinetic energy at the
/// end, with the values the summary reports.
#[test]
fn energy_bars_draw_the_ledger() {
    let dir = Dir::new();
    let example = examples().join("bouncing_ball_floor.toml");
    let out = dir.run(&["run", example.to_str().unwrap(), "--out", "out", "--json"]);
    out.assert_code(0);
    let s = out.json();
    let plots: Vec<&str> = at(&s, "/files/plots")
        .as_array()
        .expect("plots is an array")
        .iter()
        .map(|p| p.as_str().expect("a file name"))
        .collect();
    assert!(plots.contains(&"energy-bars.svg"), "{plots:?}");
    let svg = dir.read("out/energy-bars.svg");
    for label in [
        "K start",
        "W gravity",
        "events",
        "K end",
        "work-energy residual",
    ] {
        assert!(svg.contains(label), "no {label} in the bars");
    }
    // the work of gravity, as the summary gives it, written to four significant digits
    let w = num(&s, "/work/gravity");
    assert!(w > 0.5, "gravity did work on the falling ball: {w}");
    assert!(svg.contains(&format!("+{w:.4} J")) || svg.contains(&format!("+{w:.3} J")));
}
