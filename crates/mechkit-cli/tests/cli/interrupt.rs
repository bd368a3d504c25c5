//! Ctrl-C during a run: mechkit stops after the current step, finishes the trajectory and the
//! summary (`stop_reason = "interrupted"`), and exits with 130. Both loops: the general one
//! (an `[observe]` reduction sees every step) and the fused kernel (output every 10⁵ steps).

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::util::{Csv, Dir, at, num};

/// A feather that would fall for a very long time.
fn endless(extra: &str) -> String {
    format!(
        r#"
title = "a long fall"
[[body]]
name = "feather"
mass = "1 g"
position = "2.4 m"
[[force]]
kind = "uniform-gravity"
[[force]]
name = "air"
kind = "expression"
F = "-0.04*v*abs(v)"
[integrator]
method = "euler-cromer"
dt = "1 us"
[stop]
t_max = "1000 s"
{extra}
"#
    )
}

/// Runs the scenario, sends SIGINT once the trajectory file exists, returns the exit code
/// and the time from the signal to the exit.
fn interrupt(dir: &Dir, file: &str) -> (Option<i32>, Duration) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_mechkit"))
        .args(["run", file, "--out", "out", "--no-plots"])
        .current_dir(dir.path())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("mechkit starts");
    let partial = dir.path().join("out/trajectory.csv.partial");
    let start = Instant::now();
    while !partial.exists() && start.elapsed() < Duration::from_mins(1) {
        std::thread::sleep(Duration::from_millis(20));
    }
    // let it compute for a moment
    std::thread::sleep(Duration::from_millis(300));
    let sent = Instant::now();
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(kill.success());
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        assert!(
            sent.elapsed() < Duration::from_secs(30),
            "mechkit did not stop after SIGINT"
        );
        std::thread::sleep(Duration::from_millis(10));
    };
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    assert!(stderr.contains("interrupted at t ="), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    (status.code(), sent.elapsed())
}

fn check_outputs(dir: &Dir) {
    assert!(!dir.path().join("out/trajectory.csv.partial").exists());
    let s = dir.read_json("out/summary.json");
    assert_eq!(at(&s, "/stop_reason"), "interrupted");
    let t_end = num(&s, "/t_end");
    assert!(t_end > 0.0 && t_end < 1e7, "t_end = {t_end}");
    let csv = Csv::parse(&dir.read("out/trajectory.csv"));
    assert!(csv.rows.len() >= 2);
    // the last row is the state the run stopped in (the CSV writes 15 significant digits)
    let t = csv.column("t");
    let last = csv.rows.last().unwrap()[t];
    assert!((last - t_end).abs() <= 1e-14 * t_end, "{last} vs {t_end}");
}

#[test]
fn ctrl_c_in_the_general_loop_keeps_the_outputs() {
    let dir = Dir::new();
    dir.create(
        "fall.toml",
        &endless("[observe]\nvmax = \"max(abs(v))\"\n[output]\nevery = 1000"),
    );
    let (code, took) = interrupt(&dir, "fall.toml");
    assert_eq!(code, Some(130));
    assert!(took < Duration::from_secs(20), "{took:?}");
    check_outputs(&dir);
    let s = dir.read_json("out/summary.json");
    assert_eq!(num(&s, "/step_control/fused_steps"), 0.0);
}

#[test]
fn ctrl_c_in_the_fused_kernel_keeps_the_outputs() {
    let dir = Dir::new();
    dir.create(
        "fall.toml",
        &endless("[output]\nevery = 100000\nplots = []"),
    );
    let (code, took) = interrupt(&dir, "fall.toml");
    assert_eq!(code, Some(130));
    assert!(took < Duration::from_secs(20), "{took:?}");
    check_outputs(&dir);
    let s = dir.read_json("out/summary.json");
    assert!(num(&s, "/step_control/fused_steps") > 0.0);
}

#[test]
fn ctrl_c_during_md_writes_the_thermo_so_far() {
    let dir = Dir::new();
    let child = Command::new(env!("CARGO_BIN_EXE_mechkit"))
        .args([
            "md",
            "--cells",
            "4",
            "--steps",
            "100000000",
            "--thermo-every",
            "10",
        ])
        .args(["--out", "out"])
        .current_dir(dir.path())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("mechkit starts");
    std::thread::sleep(Duration::from_millis(500));
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(kill.success());
    let out = child.wait_with_output().expect("mechkit ends");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("interrupted after"), "{stderr}");
    let thermo = dir.read("out/thermo.csv");
    assert!(thermo.lines().count() >= 2, "{thermo}");
}
