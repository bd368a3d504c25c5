//! The course's worked problems that are one-line questions, reproduced through the command
//! line: every `examples/book/<case id>.sh` is a script of `mechkit …` calls with `--json`;
//! after each call, lines `#> key = /json/pointer` say which value of its output answers which
//! expected key of the case (`examples/book/cases.jsonl`). Each is compared with the case's
//! expected value within its tolerance; numbers are computed by the binary, never copied here.
//! The scripts run as they are from the repository root (`sh examples/book/<id>.sh` with
//! `mechkit` on the PATH).

use std::collections::BTreeMap;
use std::path::Path;

use serde_json::Value;

use crate::util::{Dir, examples};

#[path = "../../../mechkit/tests/book/cases.rs"]
mod shared;

fn cases() -> BTreeMap<String, Value> {
    shared::cases(&examples().join("book/cases.jsonl"))
}

/// Splits a command line into words as a POSIX shell would for the quoting used in the
/// scripts: whitespace separates, `"…"` (with `\"` and `\\`) and `'…'` group.
fn shell_words(line: &str) -> Vec<String> {
    let mut words = Vec::new();
    let mut word = String::new();
    let mut in_word = false;
    let mut chars = line.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                in_word = true;
                while let Some(c) = chars.next() {
                    match c {
                        '"' => break,
                        '\\' => {
                            if let Some(n) = chars.next() {
                                if n != '"' && n != '\\' {
                                    word.push('\\');
                                }
                                word.push(n);
                            }
                        }
                        c => word.push(c),
                    }
                }
            }
            '\'' => {
                in_word = true;
                for c in chars.by_ref() {
                    if c == '\'' {
                        break;
                    }
                    word.push(c);
                }
            }
            c if c.is_whitespace() => {
                if in_word {
                    words.push(std::mem::take(&mut word));
                    in_word = false;
                }
            }
            c => {
                in_word = true;
                word.push(c);
            }
        }
    }
    if in_word {
        words.push(word);
    }
    words
}

/// Runs one script; returns (checked, failures).
fn run_script(path: &Path, case: &Value, expected: &Value) -> (usize, Vec<String>) {
    let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
    let text = std::fs::read_to_string(path).unwrap();
    let root = examples().join("..");
    let dir = Dir::new();
    let mut output: Option<Value> = None;
    let (mut checked, mut failures) = (0, Vec::new());
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if let Some(rest) = line.strip_prefix("mechkit ") {
            // data files are named from the repository root; the run happens in a scratch
            // directory so that plots and outputs do not land in the source tree
            let args: Vec<String> = shell_words(rest)
                .into_iter()
                .map(|w| {
                    if w.starts_with("examples/") {
                        root.join(&w).display().to_string()
                    } else {
                        w
                    }
                })
                .collect();
            let refs: Vec<&str> = args.iter().map(String::as_str).collect();
            let out = dir.run(&refs);
            assert_eq!(
                out.code,
                Some(0),
                "{stem}:{}: `mechkit {rest}` failed:\n{}",
                n + 1,
                out.stderr
            );
            output = Some(serde_json::from_str(&out.stdout).unwrap_or_else(|e| {
                panic!("{stem}:{}: the output is not JSON ({e}); add --json", n + 1)
            }));
        } else if let Some(binding) = line.strip_prefix("#>") {
            let (key, pointer) = binding
                .split_once('=')
                .unwrap_or_else(|| panic!("{stem}:{}: write `#> key = /pointer`", n + 1));
            let (key, pointer) = (key.trim(), pointer.trim());
            let got = output
                .as_ref()
                .unwrap_or_else(|| panic!("{stem}:{}: a binding before any command", n + 1))
                .pointer(pointer)
                .unwrap_or_else(|| panic!("{stem}:{}: no `{pointer}` in the output", n + 1));
            let want = expected
                .get(key)
                .or_else(|| (key == "answer").then_some(expected))
                .unwrap_or_else(|| panic!("{stem}:{}: the case expects no `{key}`", n + 1));
            checked += 1;
            let ok = match (want, got) {
                (Value::Number(w), Value::Number(g)) => {
                    let (w, g) = (w.as_f64().unwrap(), g.as_f64().unwrap());
                    let tol = shared::tolerance(&case["tolerance"], key, w);
                    println!("{stem}: {key} expected {w} got {g} (tolerance {tol:e})");
                    (g - w).abs() <= tol
                }
                (w, g) => {
                    println!("{stem}: {key} expected {w} got {g}");
                    w == g
                }
            };
            if !ok {
                failures.push(format!("{stem}: {key} expected {want}, got {got}"));
            }
        }
    }
    (checked, failures)
}

#[test]
fn book_cases_through_the_command_line() {
    let cases = cases();
    let mut scripts: Vec<_> = std::fs::read_dir(examples().join("book"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "sh"))
        .collect();
    scripts.sort();
    assert!(!scripts.is_empty());
    let (mut checked, mut failures) = (0, Vec::new());
    for path in &scripts {
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        let (case, expected) = shared::case_of(&cases, &stem);
        let (c, f) = run_script(path, case, &expected);
        assert!(c > 0, "{stem}: the script binds no expected value");
        checked += c;
        failures.extend(f);
    }
    assert!(failures.is_empty(), "{failures:#?}");
    println!("{checked} values checked in {} scripts", scripts.len());
}

#[test]
fn shell_words_follow_the_shell() {
    assert_eq!(
        shell_words(r#"potential "U0*(a/r)^12" --range=-1:2 --set 'a=1, b=2' x"y z""#),
        [
            "potential",
            "U0*(a/r)^12",
            "--range=-1:2",
            "--set",
            "a=1, b=2",
            "xy z"
        ]
    );
}
