//! The table of every error kind in `docs/reliability.md`, built from the runs of the cases,
//! and the check that no message shows Rust internals.

use std::fmt::Write as _;
use std::path::PathBuf;

use super::case::{Contents, Ran, all_cases, all_runs};

const BEGIN: &str = "<!-- errors:begin -->";
const END: &str = "<!-- errors:end -->";

/// What must never reach a user: a panic, a backtrace hint, a `Debug` rendering.
const LEAKS: &[&str] = &[
    "panicked",
    "RUST_BACKTRACE",
    "thread '",
    "Error {",
    "Os {",
    "kind: ",
    "Some(",
    "None",
    "Ok(",
    "Err(",
    "\\\"",
    "\\n",
];

#[test]
fn no_message_shows_a_panic_or_a_debug_format() {
    for r in all_runs() {
        for leak in LEAKS {
            assert!(
                !r.stderr.contains(leak),
                "{}/{}: stderr shows `{leak}`:\n{}",
                r.case.area,
                r.case.kind,
                r.stderr
            );
        }
        // `mechkit` alone prints the help, which is its own explanation
        let help = r.case.args.is_empty() && r.stderr.contains("Usage: mechkit <COMMAND>");
        assert!(
            help || r.stderr.starts_with("error:") || r.stderr.starts_with("warning:"),
            "{}/{}: stderr does not start with `error:` or `warning:`:\n{}",
            r.case.area,
            r.case.kind,
            r.stderr
        );
    }
}

#[test]
fn every_snapshot_belongs_to_a_case_and_every_kind_is_unique() {
    let names: Vec<String> = all_cases().map(super::case::Case::snapshot_name).collect();
    let mut sorted = names.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(
        sorted.len(),
        names.len(),
        "two cases share an area and kind"
    );
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/cli/messages/snapshots");
    for entry in std::fs::read_dir(&dir).expect("the snapshots directory exists") {
        let file = entry.expect("a directory entry").file_name();
        let file = file.to_string_lossy();
        if let Some(name) = file.strip_suffix(".snap") {
            assert!(
                names.iter().any(|n| n == name),
                "{file} belongs to no case: remove it, or restore its case"
            );
        }
    }
}

#[test]
fn the_table_in_docs_reliability_is_current() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../docs/reliability.md");
    let doc = std::fs::read_to_string(&path).expect("docs/reliability.md exists");
    let (Some(b), Some(e)) = (doc.find(BEGIN), doc.find(END)) else {
        panic!("docs/reliability.md has no {BEGIN} … {END} section");
    };
    let current = &doc[b + BEGIN.len()..e];
    let wanted = format!("\n{}", table(all_runs()));
    if current == wanted {
        return;
    }
    if std::env::var_os("MECHKIT_BLESS").is_some_and(|v| v == "1") {
        let new = format!("{}{wanted}{}", &doc[..b + BEGIN.len()], &doc[e..]);
        std::fs::write(&path, new).expect("docs/reliability.md can be written");
        return;
    }
    panic!(
        "the error table in docs/reliability.md is stale; regenerate it with\n  \
         MECHKIT_BLESS=1 cargo test -p mechkit-cli --test cli messages::table"
    );
}

/// The generated section: a summary table, then one subsection per kind.
fn table(runs: &[Ran]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{} kinds of error. Exit code 2 is bad input (nothing is computed), 1 a computation that \
         failed (the output so far is kept).\n",
        runs.len()
    );
    s.push_str("| Area | Kind | Exit | Message (first line) |\n|---|---|---|---|\n");
    for r in runs {
        let first = r.stderr.lines().next().unwrap_or("");
        let _ = writeln!(
            s,
            "| {} | [{}](#{}) | {} | {} |",
            r.case.area,
            r.case.kind,
            anchor(r),
            r.code.unwrap_or(-1),
            code_span(first).replace('|', "\\|")
        );
    }
    for r in runs {
        let _ = write!(s, "\n### {}\n\n", heading(r));
        if let Some(input) = input_excerpt(r) {
            let _ = write!(s, "{input}");
        }
        let _ = write!(s, "```console\n$ {}\n{}```\n", r.case.command(), r.stderr);
    }
    s
}

fn heading(r: &Ran) -> String {
    format!("{}: {}", r.case.area, r.case.kind)
}

/// GitHub's anchor of the heading: lower case, spaces to `-`, punctuation dropped.
fn anchor(r: &Ran) -> String {
    heading(r)
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

fn code_span(text: &str) -> String {
    if text.contains('`') {
        format!("`` {text} ``")
    } else {
        format!("`{text}`")
    }
}

/// The input files of a case, each abbreviated to the line the message points at (when it
/// names `file:LINE`), else to its first lines.
fn input_excerpt(r: &Ran) -> Option<String> {
    let mut s = String::new();
    for (name, contents) in r.case.files {
        let Contents::Text(text) = contents else {
            let _ = writeln!(s, "`{name}`: a generated binary file (an image).\n");
            continue;
        };
        let text = text.strip_prefix('\n').unwrap_or(text);
        let lines: Vec<&str> = text.lines().collect();
        let pointed = located_line(&r.stderr, name).filter(|&l| l >= 1 && l <= lines.len());
        let _ = writeln!(s, "`{name}`:\n\n```text");
        match pointed {
            Some(l) if lines.len() > 1 => {
                if l > 1 {
                    s.push_str("…\n");
                }
                let _ = writeln!(s, "{}", lines[l - 1]);
                if l < lines.len() {
                    s.push_str("…\n");
                }
            }
            _ if lines.len() > 30 => {
                for l in &lines[..30] {
                    let _ = writeln!(s, "{l}");
                }
                s.push_str("…\n");
            }
            _ => {
                for l in &lines {
                    let _ = writeln!(s, "{l}");
                }
            }
        }
        s.push_str("```\n\n");
    }
    (!s.is_empty()).then_some(s)
}

/// The line number in `name:LINE` in the message, if any.
fn located_line(stderr: &str, name: &str) -> Option<usize> {
    let needle = format!("{name}:");
    let at = stderr.find(&needle)? + needle.len();
    let digits: String = stderr[at..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    digits.parse().ok()
}
