//! Issue 26, output integrity under signals: a double Ctrl-C still finishes every streamed
//! file at a whole row and writes the summary, at once; SIGTERM ends a run, an `md` and a
//! sweep within a second with their outputs finished; SIGKILL, which cannot be caught, leaves
//! `NAME.partial` holding whole rows up to the last flush.

use std::path::Path;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

use super::issue_026_integrity::{LONG_FALL, assert_no_partial, assert_whole_rows};
use super::util::{Dir, at};

/// Starts `mechkit args` in `dir`.
fn start(dir: &Dir, args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_mechkit"))
        .args(args)
        .current_dir(dir.path())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("mechkit starts")
}

/// Waits until `path` exists, then `settle` more.
fn wait_for(path: &Path, settle: Duration) {
    let start = Instant::now();
    while !path.exists() {
        assert!(
            start.elapsed() < Duration::from_mins(1),
            "{} never appeared",
            path.display()
        );
        std::thread::sleep(Duration::from_millis(10));
    }
    std::thread::sleep(settle);
}

fn send(child: &Child, signal: &str) {
    let sent = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(sent.success());
}

/// Waits for the exit; returns the status, the time it took and stderr.
fn wait(child: &mut Child) -> (ExitStatus, Duration, String) {
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if start.elapsed() > Duration::from_secs(20) {
            let _ = child.kill();
            panic!("mechkit did not stop within 20 s");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let took = start.elapsed();
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().expect("stderr"), &mut stderr)
        .expect("stderr is text");
    assert!(!stderr.contains("panicked"), "{stderr}");
    (status, took, stderr)
}

/// The run in `dir/out` was interrupted and its files finished: whole rows renamed into
/// place, the summary says so, nothing partial left.
fn assert_finished_after_interrupt(dir: &Dir) {
    assert_no_partial(&dir.path().join("out"));
    let csv = assert_whole_rows(&dir.read("out/trajectory.csv"));
    assert!(!csv.rows.is_empty());
    let summary = dir.read_json("out/summary.json");
    assert_eq!(at(&summary, "/stop_reason"), "interrupted");
    assert_eq!(
        at(&summary, "/files/trajectory_rows").as_u64(),
        Some(csv.rows.len() as u64)
    );
}

#[test]
fn issue_026_a_double_ctrl_c_finishes_the_files_and_the_summary_at_once() {
    let dir = Dir::new();
    dir.create("fall.toml", LONG_FALL);
    let mut child = start(&dir, &["run", "fall.toml", "--out", "out"]);
    wait_for(
        &dir.path().join("out/trajectory.csv.partial"),
        Duration::from_millis(300),
    );
    send(&child, "-INT");
    // close together, as a user's two presses reach a busy process: the old handler then
    // exited before the files were renamed (two signals of one kind still pending merge
    // into one, a plain Ctrl-C, which finishes everything too)
    std::thread::sleep(Duration::from_millis(2));
    send(&child, "-INT");
    let (status, took, stderr) = wait(&mut child);
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert_finished_after_interrupt(&dir);
}

#[test]
fn issue_026_sigterm_ends_a_run_within_a_second_with_its_files_finished() {
    let dir = Dir::new();
    dir.create("fall.toml", LONG_FALL);
    let mut child = start(&dir, &["run", "fall.toml", "--out", "out"]);
    wait_for(
        &dir.path().join("out/trajectory.csv.partial"),
        Duration::from_millis(500),
    );
    send(&child, "-TERM");
    let (status, took, stderr) = wait(&mut child);
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert_finished_after_interrupt(&dir);
}

#[test]
fn issue_026_sigterm_ends_md_within_a_second_with_whole_rows_and_frames() {
    let dir = Dir::new();
    let mut child = start(
        &dir,
        &[
            "md",
            "--cells",
            "5",
            "--steps",
            "100000000",
            "--xyz-every",
            "10",
            "--out",
            "out",
        ],
    );
    wait_for(
        &dir.path().join("out/thermo.csv.partial"),
        Duration::from_millis(500),
    );
    send(&child, "-TERM");
    let (status, took, stderr) = wait(&mut child);
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert_no_partial(&dir.path().join("out"));
    assert_whole_rows(&dir.read("out/thermo.csv"));
    let xyz = dir.read("out/trajectory.xyz");
    let atoms: usize = xyz
        .lines()
        .next()
        .expect("a count")
        .trim()
        .parse()
        .expect("atoms");
    assert_eq!(xyz.lines().count() % (atoms + 2), 0, "a frame is cut off");
}

#[test]
fn issue_026_sigterm_ends_a_sweep_within_a_second() {
    let dir = Dir::new();
    let scenario = LONG_FALL
        .replace("[output]\nplots = [\"x(t)\"]\n", "")
        .replace("[[force]]", "[constants]\nk = 1\n[[force]]")
        .replace(
            "kind = \"uniform-gravity\"",
            "kind = \"uniform-gravity\"\ng = \"k\"",
        );
    dir.create("fall.toml", &scenario);
    let mut child = start(
        &dir,
        &[
            "sweep",
            "fall.toml",
            "--set",
            "k=1:2:8",
            "--no-plots",
            "--out",
            "out",
        ],
    );
    std::thread::sleep(Duration::from_millis(800));
    send(&child, "-TERM");
    let (status, took, stderr) = wait(&mut child);
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(took < Duration::from_secs(1), "{took:?}");
    assert_no_partial(&dir.path().join("out"));
}

/// SIGKILL cannot be caught: what is left is `trajectory.csv.partial`, holding whole rows up
/// to the last flush (rows are handed to the system only whole), and the summary's reserved
/// room `summary.json.partial`, a placeholder that says the run was still going. The one
/// exception is the kernel's own: a kill that lands inside the write itself stops it at a
/// page boundary (4096 bytes), so a torn last row can only end there.
#[cfg(unix)]
#[test]
fn issue_026_sigkill_leaves_whole_rows_up_to_the_last_flush() {
    let dir = Dir::new();
    dir.create("fall.toml", LONG_FALL);
    let mut child = start(&dir, &["run", "fall.toml", "--out", "out"]);
    let partial = dir.path().join("out/trajectory.csv.partial");
    wait_for(&partial, Duration::from_millis(1500));
    send(&child, "-KILL");
    let (status, _, _) = wait(&mut child);
    assert_eq!(status.code(), None, "killed by the signal");
    let mut text = dir.read("out/trajectory.csv.partial");
    if !text.ends_with('\n') {
        assert_eq!(text.len() % 4096, 0, "a row torn away from a page boundary");
        text.truncate(text.rfind('\n').expect("a whole row") + 1);
    }
    let csv = assert_whole_rows(&text);
    assert!(csv.rows.len() > 100, "{} rows after 1.5 s", csv.rows.len());
    assert!(!dir.path().join("out/trajectory.csv").exists());
    let placeholder = dir.read_json("out/summary.json.partial");
    assert_eq!(at(&placeholder, "/stop_reason"), "running");
}
