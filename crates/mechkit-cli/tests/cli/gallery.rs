//! `mechkit gallery`: the course's cases run from the bundle, the validation report kept
//! current, and answers that follow their inputs.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;

use serde_json::Value;

use crate::util::{Dir, examples};

fn workspace() -> std::path::PathBuf {
    examples().join("..")
}

/// Every case of the course passes within its tolerance, every expected value is computed by
/// some file, and docs/validation.md shows exactly what the cases compute now.
#[test]
fn the_validation_report_is_current() {
    let out = Command::new(env!("CARGO_BIN_EXE_mechkit"))
        .args(["gallery", "--report", "docs/validation.md", "--check"])
        .current_dir(workspace())
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "run `mechkit gallery --report docs/validation.md` from the repository root\n{stdout}{stderr}"
    );
    assert!(stdout.contains("is current"), "{stdout}");
    // every plot the report links to is committed
    let doc = std::fs::read_to_string(workspace().join("docs/validation.md")).unwrap();
    let linked: Vec<&str> = doc
        .split("](gallery/")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .collect();
    assert!(linked.len() > 20, "{} plots linked", linked.len());
    for plot in linked {
        let plot = plot
            .replace("%28", "(")
            .replace("%29", ")")
            .replace("%20", " ")
            .replace("%25", "%");
        assert!(
            workspace().join("docs/gallery").join(&plot).is_file(),
            "docs/validation.md links to docs/gallery/{plot}, which is not there"
        );
    }
}

#[test]
fn a_stale_or_unmarked_report_is_refused() {
    let dir = Dir::new();
    let stale = format!(
        "# V\n\n{}\n| old table |\n{}\n",
        mechkit::gallery::report::BEGIN,
        mechkit::gallery::report::END
    );
    dir.create("v.md", &stale);
    let out = dir.run(&["gallery", "--report", "v.md", "--check", "--no-plots"]);
    out.assert_code(1);
    out.assert_stderr_contains("v.md is stale from line 4 on");
    out.assert_stderr_contains("mechkit gallery --report v.md");
    assert_eq!(dir.read("v.md"), stale, "--check writes nothing");
    // written, then current
    dir.run(&["gallery", "--report", "v.md", "--no-plots"])
        .assert_code(0);
    assert!(
        dir.read("v.md")
            .contains("| c08-B9-rotor-blade | uniform circular motion | a | 2193 |")
    );
    dir.run(&["gallery", "--report", "v.md", "--check", "--no-plots"])
        .assert_code(0);
    dir.create("plain.md", "# no markers\n");
    dir.run(&["gallery", "--report", "plain.md", "--no-plots"])
        .assert_bad_input(&["plain.md", "no line `<!-- gallery:begin"]);
}

#[test]
fn one_case_prints_its_answer_and_writes_its_plots() {
    let dir = Dir::new();
    let out = dir.run(&["gallery", "c11-energy"]);
    out.assert_code(0);
    assert!(
        out.stdout
            .contains("stable              x = n b     [-1, 0, 1]"),
        "{}",
        out.stdout
    );
    assert!(
        dir.path()
            .join("out/gallery/c11-energy-diagram-periodic-surface/c11-periodic-surface.svg")
            .is_file()
    );
    let out = dir.run(&["gallery", "c06-B15", "--out", "g", "--json"]);
    out.assert_code(0);
    let runs = out.json();
    assert_eq!(runs[0]["stem"], "c06-B15-electron-beam");
    assert!(
        runs[0]["checks"]
            .as_array()
            .unwrap()
            .iter()
            .all(|c| c["pass"] == true)
    );
    assert!(dir.path().join("g/c06-B15-electron-beam/y_t.svg").is_file());
    assert!(
        dir.path()
            .join("g/c06-B15-electron-beam/trajectory.csv")
            .is_file()
    );
}

#[test]
fn cases_are_listed_and_named_by_a_unique_start() {
    let dir = Dir::new();
    let out = dir.run(&["gallery", "--list"]);
    out.assert_code(0);
    assert!(out.stdout.contains("48 cases"), "{}", out.stdout);
    assert!(
        out.stdout
            .contains("c15-B9-triangular-pendulum            sh+toml")
    );
    assert_eq!(dir.run(&["gallery"]).stdout, out.stdout);
    let list = dir.run(&["gallery", "--list", "--json"]).json();
    assert_eq!(list.as_array().unwrap().len(), 48);
    dir.run(&["gallery", "c1"]).assert_bad_input(&[
        "`c1` names 34 cases: c10-B7-dragging-cart,",
        "give more of the id",
    ]);
    dir.run(&["gallery", "c99"])
        .assert_bad_input(&["no case `c99`", "mechkit gallery --list"]);
    dir.run(&["gallery", "--root", "."])
        .assert_bad_input(&["no examples/book/cases.jsonl", "mechkit checkout"]);
}

/// Multiplies the first nonzero number of the text by 1.1 (a line's first number only): the first value of a scenario (after its
/// title and dimensions), or the first value of a script's calls (not a flag's name, not part
/// of a name such as `c1` or `r150`).
fn perturb_first_number(text: &str, script: bool) -> Option<String> {
    let mut out = String::new();
    let mut done = false;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim_start();
        let eligible = !done
            && if script {
                trimmed.starts_with("mechkit ")
            } else {
                !(trimmed.starts_with('#')
                    || trimmed.starts_with('%')
                    || trimmed.starts_with('[')
                    || trimmed.starts_with("title")
                    || trimmed.starts_with("dimensions")
                    || trimmed.starts_with("method"))
            };
        if !eligible {
            out.push_str(line);
            continue;
        }
        match first_number(line, script) {
            Some((start, end)) if line[start..end].parse::<f64>().is_ok_and(|x| x != 0.0) => {
                let x: f64 = line[start..end].parse().unwrap();
                out.push_str(&line[..start]);
                let _ = write!(out, "{:e}", x * 1.1);
                out.push_str(&line[end..]);
                done = true;
            }
            _ => out.push_str(line),
        }
    }
    done.then_some(out)
}

/// The byte range of the first number in `line` that is a value.
fn first_number(line: &str, script: bool) -> Option<(usize, usize)> {
    let bytes = line.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        // a flag's name (`--m1`) is skipped whole
        if script && c == b'-' && bytes.get(i + 1) == Some(&b'-') {
            while i < bytes.len() && !bytes[i].is_ascii_whitespace() && bytes[i] != b'=' {
                i += 1;
            }
            continue;
        }
        let after_name =
            i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || b"_.".contains(&bytes[i - 1]));
        if c.is_ascii_digit() && !after_name {
            let start = i;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            if i + 1 < bytes.len() && bytes[i] == b'.' && bytes[i + 1].is_ascii_digit() {
                i += 1;
                while i < bytes.len() && bytes[i].is_ascii_digit() {
                    i += 1;
                }
            }
            if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
                let mut j = i + 1;
                if j < bytes.len() && (bytes[j] == b'-' || bytes[j] == b'+') {
                    j += 1;
                }
                if j < bytes.len() && bytes[j].is_ascii_digit() {
                    while j < bytes.len() && bytes[j].is_ascii_digit() {
                        j += 1;
                    }
                    i = j;
                }
            }
            return Some((start, i));
        }
        i += 1;
    }
    None
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        let target = to.join(path.file_name().unwrap());
        if path.is_dir() {
            copy_dir(&path, &target);
        } else {
            std::fs::copy(&path, &target).unwrap();
        }
    }
}

/// The computed values of every file, by file.
fn computed(dir: &Dir, root: &str) -> BTreeMap<String, Vec<Value>> {
    let out = dir.run(&[
        "gallery",
        "--all",
        "--root",
        root,
        "--no-plots",
        "--json",
        "--out",
        "runs",
    ]);
    assert!(out.code == Some(0) || out.code == Some(1), "{}", out.stderr);
    let runs: Value = serde_json::from_str(&out.stdout).unwrap();
    runs.as_array()
        .unwrap()
        .iter()
        .map(|run| {
            let values = run["checks"]
                .as_array()
                .unwrap()
                .iter()
                .map(|c| c["computed"].clone())
                .collect();
            (run["file"].as_str().unwrap().to_string(), values)
        })
        .collect()
}

/// The answers are computed, not stored: in a copy of the cases, changing the first input of
/// every scenario and script (the first file a script reads, else its first number; a number
/// is multiplied by 1.1, a picture replaced) changes what each of them computes.
#[test]
fn changing_an_input_changes_the_answer() {
    let dir = Dir::new();
    for sub in ["book", "data", "bodies", "rigid"] {
        copy_dir(
            &examples().join(sub),
            &dir.path().join("copy/examples").join(sub),
        );
    }
    let before = computed(&dir, "copy");
    assert!(before.len() > 40);
    let book = dir.path().join("copy/examples/book");
    let mut edited = Vec::new();
    for file in before.keys() {
        let path = dir.path().join("copy").join(file);
        let text = std::fs::read_to_string(&path).unwrap();
        // a script's inputs are the files it reads first, then its arguments
        let read = text
            .lines()
            .filter(|l| l.starts_with("mechkit "))
            .flat_map(str::split_whitespace)
            .find(|w| w.starts_with("examples/"));
        match read {
            Some(input) if Path::new(input).extension().is_some_and(|e| e == "png") => {
                // another picture
                let other = if input.contains("disk") {
                    "triangle_b150.png"
                } else {
                    "disk_r150.png"
                };
                std::fs::copy(
                    examples().join("data").join(other),
                    dir.path().join("copy").join(input),
                )
                .unwrap();
            }
            Some(input) => {
                let path = dir.path().join("copy").join(input);
                let text = std::fs::read_to_string(&path).unwrap();
                let new = perturb_first_number(&text, false)
                    .unwrap_or_else(|| panic!("{input}: no number to change"));
                std::fs::write(&path, &new).unwrap();
            }
            None => {
                let script = Path::new(file).extension().is_some_and(|e| e == "sh");
                let new = perturb_first_number(&text, script)
                    .unwrap_or_else(|| panic!("{file}: no number to change"));
                std::fs::write(&path, &new).unwrap();
            }
        }
        edited.push(file.clone());
    }
    assert!(book.join("cases.jsonl").is_file());
    let after = computed(&dir, "copy");
    let unchanged: Vec<&String> = edited
        .iter()
        .filter(|f| before.get(*f) == after.get(*f))
        .collect();
    assert!(
        unchanged.is_empty(),
        "these files compute the same with their first input changed: {unchanged:#?}"
    );
}

#[test]
fn the_first_number_is_a_value_not_a_name() {
    assert_eq!(
        perturb_first_number("mechkit collide --m1 1 --v1 2\n", true).unwrap(),
        "mechkit collide --m1 1.1e0 --v1 2\n"
    );
    assert_eq!(
        perturb_first_number(
            "# 2 m\ntitle = \"c1\"\ndimensions = 1\n[constants]\ng = \"9.8 m/s^2\"\n",
            false
        )
        .unwrap(),
        "# 2 m\ntitle = \"c1\"\ndimensions = 1\n[constants]\ng = \"9.8e0 m/s^2\"\n"
            .replace("9.8e0", &format!("{:e}", 9.8 * 1.1))
    );
    assert_eq!(
        perturb_first_number(
            "mechkit com examples/data/disk_r150.png --threshold 1.5e-1\n",
            true
        )
        .unwrap(),
        format!(
            "mechkit com examples/data/disk_r150.png --threshold {:e}\n",
            0.15 * 1.1
        )
    );
    assert!(perturb_first_number("mechkit units --json\n", true).is_none());
}
