//! Resource limits: output size (`--max-output`, `[output] max_size`), the step limit, the
//! size of a scenario file. Each stops cleanly, keeps what was computed, and says how to
//! raise the limit.

use crate::util::{Csv, Dir, at, examples};

const FALL: &str = r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
position = "100 m"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
t_max = "4 s"
"#;

/// Asserts the trajectory is whole rows only, at most `limit` bytes, and returns its rows.
fn whole_rows(dir: &Dir, limit: usize) -> Csv {
    let text = dir.read("out/trajectory.csv");
    assert!(
        text.len() <= limit,
        "{} bytes, over the limit {limit}",
        text.len()
    );
    assert!(text.ends_with('\n'), "the last row is cut off");
    assert!(
        !dir.path().join("out/trajectory.csv.partial").exists(),
        "the partial file was left behind"
    );
    Csv::parse(&text)
}

#[test]
fn max_output_stops_the_run_with_whole_rows_and_a_summary() {
    let dir = Dir::new();
    dir.create("fall.toml", FALL);
    let out = dir.run(&["run", "fall.toml", "--out", "out", "--max-output", "20kB"]);
    out.assert_code(1);
    out.assert_stderr_contains("trajectory.csv reached the output limit of 20 kB")
        .assert_stderr_contains("--max-output")
        .assert_stderr_contains("max_size");
    let csv = whole_rows(&dir, 20_000);
    assert!(csv.rows.len() > 100, "{} rows", csv.rows.len());
    let summary = dir.read_json("out/summary.json");
    assert_eq!(at(&summary, "/stop_reason"), "output_limit");
    // the run stopped at the first row that did not fit
    let t_last = csv.rows.last().expect("rows")[0];
    let t_end = at(&summary, "/t_end").as_f64().expect("t_end");
    assert!(t_end > t_last && t_end - t_last < 2e-3, "{t_last} {t_end}");
}

#[test]
fn the_scenario_can_set_its_output_limit_and_the_flag_overrides_it() {
    let dir = Dir::new();
    dir.create(
        "fall.toml",
        &format!("{FALL}[output]\nmax_size = \"10 kB\"\n"),
    );
    dir.run(&["run", "fall.toml", "--out", "out", "--no-plots"])
        .assert_code(1)
        .assert_stderr_contains("output limit of 10 kB");
    whole_rows(&dir, 10_000);
    dir.run(&[
        "run",
        "fall.toml",
        "--out",
        "out",
        "--no-plots",
        "--max-output",
        "1 MB",
    ])
    .assert_code(0);
    let csv = whole_rows(&dir, 1_000_000);
    assert_eq!(csv.rows.len(), 4001);
}

#[test]
fn bad_sizes_are_refused_with_what_is_accepted() {
    let dir = Dir::new();
    dir.create("fall.toml", FALL);
    dir.run(&["run", "fall.toml", "--out", "out", "--max-output", "20 kX"])
        .assert_bad_input(&["--max-output", "`kX` is not a unit of size", "MB"]);
    dir.create(
        "sized.toml",
        &format!("{FALL}[output]\nmax_size = \"lots\"\n"),
    );
    dir.run(&["run", "sized.toml", "--out", "out"])
        .assert_bad_input(&["sized.toml:16:12", "`max_size`", "500 MB"]);
    dir.create("typed.toml", &format!("{FALL}[output]\nmax_size = 1.5\n"));
    dir.run(&["run", "typed.toml", "--out", "out"])
        .assert_bad_input(&["typed.toml:16", "max_size", "whole number of bytes"]);
}

#[test]
fn md_streams_its_files_and_stops_at_the_output_limit() {
    let dir = Dir::new();
    let out = dir.run(&[
        "md",
        "--cells",
        "4",
        "--steps",
        "100",
        "--xyz-every",
        "5",
        "--out",
        "out",
        "--max-output",
        "60kB",
    ]);
    out.assert_code(1);
    out.assert_stderr_contains("trajectory.xyz reached the output limit of 60 kB at step")
        .assert_stderr_contains("--xyz-every");
    let xyz = dir.read("out/trajectory.xyz");
    assert!(xyz.len() <= 60_000 && !xyz.is_empty());
    let frame = xyz
        .lines()
        .next()
        .expect("a count line")
        .trim()
        .parse::<usize>()
        .expect("atoms");
    assert_eq!(xyz.lines().count() % (frame + 2), 0, "a frame is cut off");
    let thermo = Csv::parse(&dir.read("out/thermo.csv"));
    assert!(thermo.rows.len() >= 2, "the row of the stop is written");
    assert!(!dir.path().join("out/trajectory.xyz.partial").exists());
}

#[test]
fn a_step_limit_before_t_max_says_how_to_raise_it() {
    let dir = Dir::new();
    dir.create(
        "fall.toml",
        &FALL.replace("t_max = \"4 s\"", "t_max = \"4 s\"\nmax_steps = 50"),
    );
    let out = dir.run(&["run", "fall.toml", "--out", "out", "--no-plots"]);
    out.assert_code(0)
        .assert_stderr_contains("step limit of 50 steps")
        .assert_stderr_contains("raise [stop] max_steps");
    assert_eq!(
        at(&dir.read_json("out/summary.json"), "/stop_reason"),
        "max_steps"
    );
}

#[test]
fn a_huge_file_is_not_read_as_a_scenario() {
    let dir = Dir::new();
    let big = "# padding\n".repeat(1_700_000);
    dir.create("huge.toml", &big);
    dir.run(&["run", "huge.toml", "--out", "out"])
        .assert_bad_input(&["huge.toml is 17 MB", "more than a scenario file can be"]);
    // the examples are far below the bound
    assert!(
        std::fs::metadata(examples().join("feather.toml"))
            .expect("feather")
            .len()
            < 10_000
    );
}

/// A disk that fills up mid-run (here a file size limit, which the kernel enforces as it does
/// a full disk; a real full tmpfs in `issue_026_integrity`): the run stops cleanly where the
/// write failed, says so, and still writes its summary. (A link from the partial file to
/// `/dev/full` was used before; a stale partial file is now replaced, never written through.)
#[cfg(target_os = "linux")]
#[test]
fn a_full_disk_mid_run_stops_cleanly_with_a_summary() {
    let dir = Dir::new();
    dir.create("fall.toml", FALL);
    // 4000 rows, about 200 kB: the limit cuts them
    let out = super::issue_026_integrity::run_with_file_limit(
        &dir,
        &["run", "fall.toml", "--out", "out", "--no-plots"],
        128 * 1024,
    );
    out.assert_code(1)
        .assert_stderr_contains("cannot write")
        .assert_stderr_contains("File too large")
        .assert_stderr_contains("could not be written");
    assert!(!out.stderr.contains("panicked"));
    let summary = dir.read_json("out/summary.json");
    assert_eq!(at(&summary, "/stop_reason"), "output_error");
    let t_end = at(&summary, "/t_end").as_f64().expect("t_end");
    assert!(t_end > 0.1 && t_end < 3.0, "{t_end}");
}

/// Counts a user types are bounded before anything is allocated or started: atoms of a
/// lattice (`--cells 2000` asked for 768 GB and aborted), threads (`--threads 100000` started
/// them all), runs of a sweep.
#[test]
fn huge_counts_are_refused_before_anything_is_allocated() {
    let dir = Dir::new();
    dir.run(&["md", "--cells", "2000", "--steps", "1"])
        .assert_bad_input(&["--cells", "32000000000", "more than 10000000"]);
    dir.run(&["md", "--cells", "8", "--steps", "1", "--threads", "100000"])
        .assert_bad_input(&["--threads", "more than 256"]);
    dir.create("fall.toml", FALL);
    dir.run(&[
        "sweep",
        "fall.toml",
        "--set",
        "g=1:2:100000000000",
        "--out",
        "out",
    ])
    .assert_bad_input(&["more than a sweep runs"]);
}
