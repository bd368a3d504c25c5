//! Issue 26, reliability (second round): inputs that crashed mechkit or made it run for
//! hours are refused before any work, with a message located at the input, or now end.
//!
//! - a formula nests at most `mechkit_expr::MAX_DEPTH` = 256 levels, counted on the tree the
//!   parser builds: a flat sum of 30,000 terms overflowed the stack (SIGABRT) in `run`,
//!   `check`, `[stop] when`, `[observe]`, `[constants]`, a `sweep` worker, and in `diff`,
//!   `integrate`, `solve`, `potential` and `work --field`; the documented 256 parentheses
//!   are accepted, 257 refused;
//! - `md` on a sparse box gets a cell grid sized by its atoms, not its box (8.6 GB before);
//! - a plot whose axis span overflows (bodies at ±1e308) is drawn; its tick loop never ended;
//! - the steps of a run are bounded up front: `t_max = 1e300` with `dt = 1 ms`, a subnormal
//!   `dt`, `max_steps = 9.2e18`, `md --steps 1e18` and `integrate --n 1e12` are refused
//!   (`check` too), and SIGTERM ends a long run within a second.

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::util::{Dir, at};

/// `n` terms `x + x + …`: a tree `n - 1` levels deep.
fn flat_sum(term: &str, n: usize) -> String {
    vec![term; n].join("+")
}

/// A ball in 1-D with `[stop] t_max`, and whatever `extra` adds.
fn ball(extra: &str) -> String {
    format!(
        r#"
dimensions = 1
{extra}
[[body]]
name = "ball"
mass = "1 kg"
position = "1 m"
velocity = "0 m/s"
[[force]]
kind = "uniform-gravity"
[integrator]
method = "rk4"
dt = "10 ms"
"#
    )
}

/// The last line of a caret snippet, and the line above it, are short: a 150 kB formula is
/// shown as an excerpt around the place the error points at.
fn assert_short_snippet(stderr: &str) {
    for line in stderr.lines() {
        assert!(
            line.chars().count() < 300,
            "a line of {} characters in the message:\n{}",
            line.len(),
            &stderr[..stderr.len().min(2000)]
        );
    }
}

#[test]
fn issue_026_a_flat_formula_of_30000_terms_is_refused_where_it_is_written() {
    let dir = Dir::new();
    let sum = flat_sum("1e-5", 30_000);
    let cases = [
        (
            "force.toml",
            ball(&format!(
                "[[force]]\nname = \"f\"\nkind = \"expression\"\nF = \"-m*9.8*({sum})\""
            )),
        ),
        (
            "when.toml",
            ball(&format!("[stop]\nt_max = \"1 s\"\nwhen = \"x < {sum}\"")),
        ),
        (
            "observe.toml",
            ball(&format!(
                "[stop]\nt_max = \"1 s\"\n[observe]\nx_max = \"max(x*({sum}))\""
            )),
        ),
        (
            "constants.toml",
            ball(&format!(
                "[constants]\nk = \"pi*({sum})\"\n[stop]\nt_max = \"1 s\""
            )),
        ),
    ];
    for (name, text) in &cases {
        dir.create(name, text);
        for args in [vec!["check", name], vec!["run", name, "--out", "out"]] {
            let out = dir.run(&args);
            out.assert_bad_input(&[
                "nests more than 256 levels deep",
                &format!("--> {name}:"),
                "group the terms in parentheses",
            ]);
            assert_short_snippet(&out.stderr);
        }
    }
    // a sweep refuses it before any worker runs (and a worker would refuse it too)
    let out = dir.run(&[
        "sweep",
        "constants.toml",
        "--set",
        "k=1:2:4",
        "--out",
        "out",
    ]);
    out.assert_bad_input(&["nests more than 256 levels deep", "constants.toml:"]);
}

#[test]
fn issue_026_formulas_on_the_command_line_are_refused_at_their_column() {
    let dir = Dir::new();
    // x+x+…: 60,000 terms is 120 kB, within what one argument may be
    let sum = format!("x*({})", flat_sum("x", 60_000));
    let field = format!("{sum}, 0");
    for args in [
        vec!["diff", &sum],
        vec!["integrate", &sum],
        vec!["solve", &sum],
        vec!["potential", &sum, "--range", "0:1"],
        vec![
            "work", "--field", &field, "--path", "s, 0", "--param", "s=0:1",
        ],
    ] {
        let out = dir.run(&args);
        out.assert_bad_input(&["nests more than 256 levels deep", "(column 517)"]);
        assert_short_snippet(&out.stderr);
    }
}

#[test]
fn issue_026_the_nesting_limit_is_256_levels_as_documented() {
    let dir = Dir::new();
    // 256 levels: a sum of 257 terms, 256 parentheses, 256 nested calls (of `floor`, whose
    // derivative is quick to take)
    let deepest = [
        flat_sum("x", 257),
        format!("{}x{}", "(".repeat(256), ")".repeat(256)),
        format!("{}x{}", "floor(".repeat(256), ")".repeat(256)),
    ];
    for f in &deepest {
        dir.run(&["diff", f, "--json"]).assert_code(0);
    }
    for (f, column) in [
        (flat_sum("x", 258), "(column 514)"),
        (
            format!("{}x{}", "(".repeat(257), ")".repeat(257)),
            "(column 258)",
        ),
        (
            format!("{}x{}", "floor(".repeat(257), ")".repeat(257)),
            "(column 1543)",
        ),
    ] {
        dir.run(&["diff", &f])
            .assert_bad_input(&["nests more than 256 levels deep", column]);
    }
}

#[test]
fn issue_026_md_on_a_sparse_box_sizes_its_cells_by_its_atoms() {
    let dir = Dir::new();
    let start = Instant::now();
    let out = dir.run(&[
        "md",
        "--cells",
        "4",
        "--density",
        "1e-9",
        "--steps",
        "20",
        "--json",
    ]);
    let v = out.json();
    assert_eq!(at(&v, "/atoms").as_u64(), Some(256), "{v}");
    assert!(
        start.elapsed() < Duration::from_secs(20),
        "{:?}",
        start.elapsed()
    );
}

#[test]
fn issue_026_an_axis_whose_span_overflows_is_drawn() {
    let dir = Dir::new();
    dir.create(
        "far.toml",
        r#"
dimensions = 1
[[body]]
name = "a"
mass = "1 kg"
position = "-1e308 m"
[[body]]
name = "b"
mass = "1 kg"
position = "1e308 m"
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
t_max = "10 ms"
[output]
plots = ["x(t)"]
"#,
    );
    let start = Instant::now();
    dir.run(&["run", "far.toml", "--out", "out"]).assert_code(0);
    assert!(dir.read("out/x_t.svg").contains("</svg>"));
    // its span, 2e308 m, is not a double: refused by the finiteness rule (before, the plot's
    // tick loop never ended)
    dir.create("far.csv", "x,F\n-1e308,1\n0,2\n1e308,1\n");
    dir.run(&["work", "far.csv", "--out", "w"])
        .assert_code(1)
        .assert_stderr_contains("is inf, not a finite number");
    dir.create("fard.csv", "t,x\n0,-1e308\n1,1e308\n2,1e308\n3,-1e308\n");
    let out = dir.run(&["derive", "fard.csv", "--out", "d"]);
    assert!(matches!(out.code, Some(0 | 1)), "{}", out.stderr);
    assert!(
        start.elapsed() < Duration::from_secs(30),
        "{:?}",
        start.elapsed()
    );
}

#[test]
fn issue_026_runs_whose_steps_are_not_bounded_are_refused_by_check_and_run() {
    let dir = Dir::new();
    let cases = [
        (
            "tmax.toml",
            ball("[stop]\nt_max = \"1e300 s\""),
            vec![
                "1e302 steps, more than the 1000000000",
                "tmax.toml:",
                "dt = \"10 ms\"",
                "max_steps",
            ],
        ),
        (
            "subnormal.toml",
            ball("[stop]\nt_max = \"1 s\"").replace("\"10 ms\"", "\"1e-320 s\""),
            vec!["below 2.2e-308 s", "subnormal.toml:"],
        ),
        (
            "max_steps.toml",
            ball("[stop]\nmax_steps = 9200000000000000000"),
            vec![
                "max_steps = 9200000000000000000 is more than",
                "max_steps.toml:",
            ],
        ),
    ];
    for (name, text, needles) in &cases {
        dir.create(name, text);
        for command in ["check", "run"] {
            dir.run(&[command, name]).assert_bad_input(needles);
        }
    }
    // max_steps bounds a run however far its t_max
    dir.create(
        "bounded.toml",
        &ball("[stop]\nt_max = \"1e300 s\"\nmax_steps = 100"),
    );
    dir.run(&["run", "bounded.toml", "--out", "b"])
        .assert_code(0);
    dir.run(&["md", "--steps", "1000000000000000000"])
        .assert_bad_input(&["--steps", "more than 1000000000"]);
    dir.run(&[
        "integrate",
        "x^2",
        "--from",
        "0",
        "--to",
        "1",
        "--method",
        "trapezoid",
        "--n",
        "1000000000000",
    ])
    .assert_bad_input(&["--n 1000000000000", "more than the 100000000"]);
}

#[test]
fn issue_026_sigterm_ends_a_long_run_within_a_second() {
    let dir = Dir::new();
    // 10^9 steps, the most a run may take without max_steps
    dir.create("long.toml", &ball("[stop]\nt_max = \"1e7 s\""));
    let mut child = Command::new(env!("CARGO_BIN_EXE_mechkit"))
        .args(["run", "long.toml", "--out", "out", "--no-plots"])
        .current_dir(dir.path())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("mechkit starts");
    std::thread::sleep(Duration::from_millis(800));
    let sent = Instant::now();
    let kill = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(kill.success());
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if sent.elapsed() > Duration::from_secs(10) {
            let _ = child.kill();
            panic!("mechkit did not stop within 10 s of SIGTERM");
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    assert!(
        sent.elapsed() < Duration::from_secs(1),
        "{:?}",
        sent.elapsed()
    );
    assert_eq!(status.code(), Some(130));
}

/// An endless input (`/dev/zero`, `/dev/urandom`) ends at the size bound of its kind of file,
/// exit 2 with the bound: `check /dev/zero` never ended, `md --positions /dev/zero` filled the
/// memory until the system killed it. Regular files keep their size check before reading.
#[test]
fn issue_026_an_endless_input_ends_at_its_size_bound() {
    let dir = Dir::new();
    for args in [
        &["check", "/dev/zero"][..],
        &["check", "/dev/urandom"],
        &["run", "/dev/zero", "--out", "out"],
    ] {
        dir.run(args).assert_bad_input(&[
            "cannot read /dev/",
            "it goes on past 16 MB, the most mechkit reads from one file",
        ]);
    }
}
