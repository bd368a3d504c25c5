//! Issue 26, broken promises of "no lost output": a full disk, targets that are not regular
//! files, and symbolic links.
//!
//! A full disk is made two ways: a real one, a small tmpfs mounted in a user namespace
//! (`unshare -rm`), when the machine allows it (skipped with a note when not); and always a
//! file size limit (RLIMIT_FSIZE, SIGXFSZ ignored), set in the child before it starts: the
//! kernel then fails a write past the limit part-way with EFBIG, as it fails one on a full
//! disk with ENOSPC. Signals (double Ctrl-C, SIGKILL, SIGTERM) are in
//! `issue_026_integrity_signals.rs`.

use std::path::Path;
use std::process::Command;

use super::util::{Csv, Dir, Output, at, num};

/// A ball falling for a long time, 1 ms steps: about 50 bytes a row, a MB in 0.02 s of
/// simulated time... rather, in 20,000 rows.
pub(super) const LONG_FALL: &str = r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
position = "100 m"
[[force]]
name = "gravity"
kind = "uniform-gravity"
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
t_max = "100000 s"
[output]
plots = ["x(t)"]
"#;

/// Runs `mechkit args` in `dir` with every file it writes limited to `bytes` (RLIMIT_FSIZE)
/// and SIGXFSZ ignored, so a write past the limit fails with EFBIG ("File too large").
#[cfg(target_os = "linux")]
pub(super) fn run_with_file_limit(dir: &Dir, args: &[&str], bytes: u64) -> Output {
    use std::os::unix::process::CommandExt as _;
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_mechkit"));
    cmd.args(args).current_dir(dir.path());
    #[allow(unsafe_code)]
    // SAFETY: between fork and exec the closure calls only setrlimit and signal, both
    // async-signal-safe, and allocates nothing.
    unsafe {
        cmd.pre_exec(move || {
            let limit = libc::rlimit {
                rlim_cur: bytes,
                rlim_max: bytes,
            };
            if libc::setrlimit(libc::RLIMIT_FSIZE, &raw const limit) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            Ok(())
        });
    }
    let out = cmd.output().expect("the mechkit binary runs");
    Output {
        stdout: String::from_utf8(out.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(out.stderr).expect("stderr is UTF-8"),
        code: out.status.code(),
    }
}

/// Asserts `text` is a CSV of whole rows: a header, then rows of as many numbers, each line
/// ended; returns the rows.
pub(super) fn assert_whole_rows(text: &str) -> Csv {
    assert!(
        text.ends_with('\n'),
        "the last row is cut off: {:?}",
        &text[text.len().saturating_sub(80)..]
    );
    let columns = text.lines().next().expect("a header").split(',').count();
    for (k, line) in text.lines().enumerate().skip(1) {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields.len(), columns, "row {k} is cut: {line:?}");
        for f in fields {
            f.parse::<f64>()
                .unwrap_or_else(|_| panic!("row {k} holds a cut number {f:?}: {line:?}"));
        }
    }
    Csv::parse(text)
}

/// No `NAME.partial` is left anywhere in `dir`.
pub(super) fn assert_no_partial(dir: &Path) {
    let left: Vec<String> = std::fs::read_dir(dir)
        .expect("the directory")
        .map(|e| {
            e.expect("an entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .filter(|n| n.ends_with(".partial"))
        .collect();
    assert!(
        left.is_empty(),
        "left behind in {}: {left:?}",
        dir.display()
    );
}

/// The trajectory and summary a run left in `out` after a write failed with `reason`:
/// exit 1 with a message naming the file, the trajectory renamed into place with whole rows
/// only, and a valid summary that says why and how far the file got.
fn assert_stopped_cleanly(out: &Output, dir: &Path, reason: &str) {
    out.assert_code(1)
        .assert_stderr_contains("trajectory.csv")
        .assert_stderr_contains(reason)
        .assert_stderr_contains("could not be written");
    assert!(!out.stderr.contains("panicked"), "{}", out.stderr);
    assert_no_partial(dir);
    let text = std::fs::read_to_string(dir.join("trajectory.csv")).expect("trajectory.csv");
    let csv = assert_whole_rows(&text);
    assert!(csv.rows.len() > 100, "only {} rows", csv.rows.len());
    let summary: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("summary.json")).expect("summary.json"),
    )
    .expect("summary.json is JSON");
    assert_eq!(at(&summary, "/stop_reason"), "output_error");
    let error = at(&summary, "/files/error").as_str().expect("files.error");
    assert!(
        error.contains("trajectory.csv") && error.contains(reason),
        "{error}"
    );
    assert_eq!(
        at(&summary, "/files/trajectory_rows").as_u64(),
        Some(csv.rows.len() as u64)
    );
    let last_t = csv.rows.last().expect("a row")[csv.column("t")];
    assert_eq!(num(&summary, "/files/trajectory_last_t"), last_t);
    assert!(num(&summary, "/t_end") >= last_t);
}

#[cfg(target_os = "linux")]
#[test]
fn issue_026_a_file_size_limit_mid_run_keeps_whole_rows_and_a_valid_summary() {
    let dir = Dir::new();
    dir.create("fall.toml", LONG_FALL);
    let out = run_with_file_limit(&dir, &["run", "fall.toml", "--out", "out"], 1 << 20);
    assert_stopped_cleanly(&out, &dir.path().join("out"), "File too large");
    // the plot of the rows so far fits; the summary lists what was written
    let summary = dir.read_json("out/summary.json");
    assert_eq!(at(&summary, "/files/plots/0"), "x_t.svg");
    assert!(dir.read("out/x_t.svg").ends_with("</svg>\n"));
}

/// Runs `script` (sh, with `$MECHKIT` the binary) inside a fresh user and mount namespace
/// with a tmpfs of `size` mounted on `dir/disk` and as the working directory; what it copies
/// to `..` stays. `None` when this machine cannot mount one (no user namespaces).
#[cfg(target_os = "linux")]
fn on_small_tmpfs(dir: &Dir, size: &str, script: &str) -> Option<Output> {
    let disk = dir.path().join("disk");
    std::fs::create_dir_all(&disk).expect("the mount point");
    let wrapped = format!(
        "mount -t tmpfs -o size={size} tmpfs \"$1\" 2>/dev/null || exit 200\ncd \"$1\" || exit 200\n{script}"
    );
    let out = Command::new("unshare")
        .args(["-rm", "sh", "-c", &wrapped, "sh"])
        .arg(&disk)
        .env("MECHKIT", env!("CARGO_BIN_EXE_mechkit"))
        .current_dir(dir.path())
        .output();
    let out = match out {
        Ok(o)
            if o.status.code() != Some(200)
                && !String::from_utf8_lossy(&o.stderr).starts_with("unshare:") =>
        {
            o
        }
        _ => {
            eprintln!(
                "note: no tmpfs could be mounted here (unshare -rm); the full-disk test ran with a file size limit only"
            );
            return None;
        }
    };
    Some(Output {
        stdout: String::from_utf8(out.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(out.stderr).expect("stderr is UTF-8"),
        code: out.status.code(),
    })
}

#[cfg(target_os = "linux")]
#[test]
fn issue_026_a_full_tmpfs_mid_run_keeps_whole_rows_and_a_valid_summary() {
    let dir = Dir::new();
    dir.create("fall.toml", LONG_FALL);
    let script = "\"$MECHKIT\" run ../fall.toml --out out\ncode=$?\ncp -r out ../copy\nexit $code";
    let Some(out) = on_small_tmpfs(&dir, "1m", script) else {
        return;
    };
    assert_stopped_cleanly(&out, &dir.path().join("copy"), "No space left on device");
}

#[cfg(target_os = "linux")]
#[test]
fn issue_026_md_on_a_full_disk_keeps_whole_rows_and_frames() {
    let dir = Dir::new();
    let args = [
        "md",
        "--cells",
        "4",
        "--steps",
        "100000",
        "--thermo-every",
        "1",
        "--xyz-every",
        "1",
        "--out",
        "out",
    ];
    let out = run_with_file_limit(&dir, &args, 200_000);
    out.assert_code(1)
        .assert_stderr_contains("File too large")
        .assert_stderr_contains("trajectory.xyz")
        .assert_stderr_contains("keeps whole frames up to step");
    assert_no_partial(&dir.path().join("out"));
    let xyz = dir.read("out/trajectory.xyz");
    let atoms: usize = xyz
        .lines()
        .next()
        .expect("a count")
        .trim()
        .parse()
        .expect("atoms");
    assert!(xyz.ends_with('\n'));
    assert_eq!(xyz.lines().count() % (atoms + 2), 0, "a frame is cut off");
    assert!(xyz.lines().count() / (atoms + 2) > 5);
    assert_whole_rows(&dir.read("out/thermo.csv"));
}

#[cfg(target_os = "linux")]
#[test]
fn issue_026_a_plot_that_cannot_be_written_leaves_no_partial_file() {
    let dir = Dir::new();
    let mut data = String::new();
    for k in 0..200 {
        std::fmt::Write::write_fmt(&mut data, format_args!("{} {k}\n", f64::from(k) * 0.1))
            .expect("a string takes it");
    }
    dir.create("f.csv", &data);
    // the CSV (4 kB) fits, the plot (a PNG at 600 dpi, over 60 kB) does not
    let out = run_with_file_limit(
        &dir,
        &[
            "work", "f.csv", "--out", "out", "--format", "png", "--dpi", "600",
        ],
        60 * 1024,
    );
    assert_ne!(out.code, Some(0), "{}", out.stderr);
    out.assert_stderr_contains("cannot write out/W_x.png: File too large");
    assert_no_partial(&dir.path().join("out"));
    assert!(!dir.path().join("out/W_x.png").exists());
    assert!(dir.path().join("out/work.csv").is_file());
}

/// Makes a named pipe (FIFO) at `path`.
#[cfg(unix)]
fn mkfifo(path: &Path) {
    let made = Command::new("mkfifo")
        .arg(path)
        .status()
        .expect("mkfifo runs");
    assert!(made.success());
}

#[cfg(unix)]
fn is_fifo(path: &Path) -> bool {
    use std::os::unix::fs::FileTypeExt as _;
    std::fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_fifo())
}

fn image(name: &str) -> String {
    super::util::examples()
        .join("data")
        .join(name)
        .display()
        .to_string()
}

#[cfg(unix)]
#[test]
fn issue_026_a_device_or_pipe_as_an_output_is_refused_and_left_alone() {
    use std::os::unix::fs::FileTypeExt as _;
    let dir = Dir::new();
    // a character device as a file option (through a link, as --mark wants a .png name):
    // refused, and still a device after
    let disk = image("disk_r150.png");
    std::os::unix::fs::symlink("/dev/null", dir.path().join("null.png")).expect("a link");
    dir.run(&["com", &disk, "--mark", "null.png"])
        .assert_bad_input(&[
            "/dev/null (the target of the link null.png) is a character device, not a regular file",
        ]);
    assert!(
        std::fs::metadata("/dev/null")
            .expect("/dev/null")
            .file_type()
            .is_char_device()
    );
    assert!(!Path::new("/dev/null.partial").exists());
    // a pipe, the same
    mkfifo(&dir.path().join("pipe.png"));
    dir.run(&["com", &disk, "--mark", "pipe.png"])
        .assert_bad_input(&["pipe.png is a named pipe (FIFO), not a regular file"]);
    assert!(is_fifo(&dir.path().join("pipe.png")));
    // the run's streamed trajectory, its summary and its plot: a pipe in their place is
    // refused before the run starts
    dir.create("fall.toml", &LONG_FALL.replace("100000 s", "1 s"));
    std::fs::create_dir(dir.path().join("out")).expect("out");
    for name in ["trajectory.csv", "summary.json", "x_t.svg"] {
        let fifo = dir.path().join("out").join(name);
        mkfifo(&fifo);
        dir.run(&["run", "fall.toml", "--out", "out"])
            .assert_bad_input(&[name, "is a named pipe (FIFO), not a regular file"]);
        assert!(is_fifo(&fifo), "{name} was replaced");
        assert_no_partial(&dir.path().join("out"));
        assert!(
            !dir.path().join("out/trajectory.csv").is_file(),
            "the run started"
        );
        std::fs::remove_file(&fifo).expect("removed");
    }
    // md's streamed files
    mkfifo(&dir.path().join("out/thermo.csv"));
    dir.run(&["md", "--cells", "4", "--steps", "10", "--out", "out"])
        .assert_bad_input(&["thermo.csv", "is a named pipe (FIFO)"]);
    assert!(is_fifo(&dir.path().join("out/thermo.csv")));
}

/// `link` -> `link2` -> `real/NAME`: a chain of symbolic links to a file in another folder,
/// the first one `to_link2` (relative to the link's folder, or absolute).
#[cfg(unix)]
fn link_chain(dir: &Dir, link: &str, to_link2: &Path, target: &str) {
    let p = dir.path();
    std::fs::create_dir_all(p.join("real")).expect("real");
    std::os::unix::fs::symlink(p.join("real").join(target), p.join("link2")).expect("link2");
    std::os::unix::fs::symlink(to_link2, p.join(link)).expect("link");
}

#[cfg(unix)]
#[test]
fn issue_026_outputs_are_written_through_symbolic_links() {
    let dir = Dir::new();
    let is_link = |name: &str| {
        std::fs::symlink_metadata(dir.path().join(name)).is_ok_and(|m| m.file_type().is_symlink())
    };
    // the run's streamed trajectory and its summary through a chain of links (the last one
    // dangling: its file is made)
    dir.create("fall.toml", &LONG_FALL.replace("100000 s", "1 s"));
    std::fs::create_dir(dir.path().join("out")).expect("out");
    link_chain(
        &dir,
        "out/trajectory.csv",
        Path::new("../link2"),
        "traj.csv",
    );
    std::os::unix::fs::symlink(
        dir.path().join("real/summary.json"),
        dir.path().join("out/summary.json"),
    )
    .expect("a link");
    dir.run(&["run", "fall.toml", "--out", "out"])
        .assert_code(0);
    assert!(is_link("out/trajectory.csv") && is_link("link2") && is_link("out/summary.json"));
    let csv = assert_whole_rows(&dir.read("real/traj.csv"));
    assert_eq!(csv.rows.len(), 1001);
    assert_eq!(
        at(&dir.read_json("real/summary.json"), "/stop_reason"),
        "t_max"
    );
    assert_no_partial(&dir.path().join("out"));
    assert_no_partial(&dir.path().join("real"));
    // a file option through a link to an existing file: replaced, the links stay
    std::fs::remove_file(dir.path().join("link2")).expect("removed");
    std::fs::remove_file(dir.path().join("out/trajectory.csv")).expect("removed");
    link_chain(&dir, "marked.png", &dir.path().join("link2"), "marked.png");
    std::fs::write(dir.path().join("real/marked.png"), "old").expect("an old file");
    dir.run(&["com", &image("disk_r150.png"), "--mark", "marked.png"])
        .assert_code(0);
    assert!(is_link("marked.png") && is_link("link2"));
    let bytes = std::fs::read(dir.path().join("real/marked.png")).expect("the target");
    assert!(bytes.starts_with(b"\x89PNG"));
    assert_no_partial(dir.path());
    assert_no_partial(&dir.path().join("real"));
}

#[test]
fn issue_026_an_output_never_replaces_a_file_the_command_read() {
    let dir = Dir::new();
    // `derive FILE -o DIR` writes DIR/derived.csv: here, the data file itself
    let data = "t,x\n0,0\n0.1,0.01\n0.2,0.04\n0.3,0.09\n0.4,0.16\n";
    dir.create("derived.csv", data);
    dir.run(&["derive", "derived.csv", "-o", "."])
        .assert_code(2)
        .assert_stderr_contains("is the input");
    assert_eq!(dir.read("derived.csv"), data);
    // however it is spelled: through a link to the directory
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(dir.path(), dir.path().join("here")).expect("a link");
        dir.run(&["derive", "derived.csv", "-o", "here"])
            .assert_code(2)
            .assert_stderr_contains("is the input");
        assert_eq!(dir.read("derived.csv"), data);
    }
    // an image marked onto itself
    std::fs::copy(image("disk_r150.png"), dir.path().join("disk.png")).expect("copied");
    let before = std::fs::read(dir.path().join("disk.png")).expect("the image");
    dir.run(&["com", "disk.png", "--mark", "disk.png"])
        .assert_code(2)
        .assert_stderr_contains("is the input");
    assert_eq!(
        std::fs::read(dir.path().join("disk.png")).expect("the image"),
        before
    );
    assert_no_partial(dir.path());
    // another directory is fine
    dir.run(&["derive", "derived.csv", "-o", "out"])
        .assert_code(0);
}
