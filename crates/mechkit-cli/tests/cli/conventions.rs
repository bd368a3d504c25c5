//! Issue 22's conventions, over every command: `--json` and `-q/--quiet` on each; nothing
//! written unless `-o` is given; `run --set`, `check --json`, `list-integrators --json`;
//! completions and the manual page; the trajectory's units sidecar.

use super::util::{Dir, examples};

/// The subcommands, from `mechkit --help`.
fn subcommands(dir: &Dir) -> Vec<String> {
    let text = dir.run(&["--help"]).assert_code(0).stdout.clone();
    let list = text
        .split("Commands:")
        .nth(1)
        .and_then(|t| t.split("Options:").next())
        .unwrap();
    list.lines()
        .filter_map(|l| l.strip_prefix("  "))
        .filter(|l| !l.starts_with(' '))
        .filter_map(|l| l.split_whitespace().next())
        .map(str::to_string)
        .filter(|c| c != "help")
        .collect()
}

#[test]
fn every_command_has_json_and_quiet() {
    let dir = Dir::new();
    let commands = subcommands(&dir);
    assert!(commands.len() > 25, "{commands:?}");
    for c in &commands {
        let out = dir.run(&[c, "--help"]);
        out.assert_code(0);
        let help = &out.stdout;
        for flag in ["--json", "-q, --quiet"] {
            assert!(
                help.contains(flag),
                "`mechkit {c} --help` has no {flag}:\n{help}"
            );
        }
    }
}

/// The examples of `mechkit --help`, with their `-o`/`--out` and `--plot PATH` removed and
/// `examples/` made absolute.
fn examples_without_outputs(dir: &Dir) -> Vec<Vec<String>> {
    let text = dir
        .run_with_env(&["--help"], &[("COLUMNS", "100")])
        .assert_code(0)
        .stdout
        .clone();
    let root = examples();
    let root = root.parent().unwrap();
    text.lines()
        .filter_map(|l| l.trim().strip_prefix("mechkit "))
        .map(|line| {
            let words = shell_words(line);
            let mut out = Vec::new();
            let mut skip = false;
            for w in words {
                if skip {
                    skip = false;
                    continue;
                }
                if ["-o", "--out", "--plot"].contains(&w.as_str()) && !line.starts_with("sweep") {
                    skip = true;
                    continue;
                }
                if w.starts_with("examples/") {
                    out.push(root.join(&w).display().to_string());
                } else {
                    out.push(w);
                }
            }
            out
        })
        .collect()
}

/// Splits a command line at spaces outside double quotes.
fn shell_words(line: &str) -> Vec<String> {
    let (mut words, mut word, mut quoted) = (Vec::new(), String::new(), false);
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ' ' if !quoted => {
                if !word.is_empty() {
                    words.push(std::mem::take(&mut word));
                }
            }
            c => word.push(c),
        }
    }
    if !word.is_empty() {
        words.push(word);
    }
    words
}

#[test]
fn nothing_is_written_unless_asked() {
    let dir = Dir::new();
    let lines = examples_without_outputs(&dir);
    assert!(lines.len() > 20, "{lines:?}");
    for words in lines {
        let args: Vec<&str> = words.iter().map(String::as_str).collect();
        let out = dir.run(&args);
        let code = out.code;
        assert!(
            code == Some(0),
            "mechkit {}: exit {code:?}\n{}",
            words.join(" "),
            out.stderr
        );
        let left: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert!(
            left.is_empty(),
            "mechkit {} wrote {left:?} into the working directory",
            words.join(" ")
        );
    }
}

#[test]
fn run_set_overrides_a_constant_and_check_reports_json() {
    let dir = Dir::new();
    let file = examples().join("projectile.toml");
    let file = file.to_str().unwrap();
    let check = dir.run(&["check", file, "--json"]).assert_code(0).json();
    let constants = check["constants"].as_array().unwrap();
    let (name, value) = constants
        .iter()
        .map(|c| (c["name"].as_str().unwrap(), c["value"].as_f64().unwrap()))
        .find(|(_, v)| *v > 0.0)
        .expect("projectile.toml has a positive constant");
    let set = format!("{name}={}", value * 2.0);
    let changed = dir
        .run(&["check", file, "--json", "--set", &set])
        .assert_code(0)
        .json();
    let v = changed["constants"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["name"] == name)
        .unwrap()["value"]
        .as_f64()
        .unwrap();
    assert_eq!(v, value * 2.0);
    let a = dir.run(&["run", file, "--json"]).assert_code(0).json();
    let b = dir
        .run(&["run", file, "--json", "--set", &set])
        .assert_code(0)
        .json();
    assert_ne!(a["t_end"], b["t_end"], "--set {set} changed nothing");
    dir.run(&["run", file, "--set", "no_such_constant=1"])
        .assert_bad_input(&["no_such_constant", "not a constant"]);
    dir.run(&["run", file, "-q"]).assert_code(0);
    let quiet = dir.run(&["run", file, "-q"]);
    assert!(quiet.stdout.is_empty(), "-q printed on stdout");
}

#[test]
fn a_run_states_the_units_of_its_columns() {
    let dir = Dir::new();
    let file = examples().join("projectile.toml");
    dir.run(&["run", file.to_str().unwrap(), "-o", "p", "--no-plots"])
        .assert_code(0);
    let summary = dir.read_json("p/summary.json");
    assert_eq!(summary["files"]["units"], "trajectory.units.json");
    let units = dir.read_json("p/trajectory.units.json");
    let header = dir.read("p/trajectory.csv");
    let header: Vec<&str> = header.lines().next().unwrap().split(',').collect();
    let keys: Vec<&str> = units
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(keys.len(), header.len());
    for h in &header {
        assert!(units.get(*h).is_some(), "no unit for {h}");
    }
    assert_eq!(units["t"], "s");
    assert_eq!(units["K"], "J");
}

#[test]
fn list_integrators_completions_and_man_page() {
    let dir = Dir::new();
    let list = dir
        .run(&["list-integrators", "--json"])
        .assert_code(0)
        .json();
    let names: Vec<&str> = list
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["name"].as_str().unwrap())
        .collect();
    assert!(
        names.contains(&"rk4") && names.contains(&"dop853"),
        "{names:?}"
    );
    for shell in ["bash", "zsh", "fish"] {
        let out = dir.run(&["completions", shell]);
        out.assert_code(0);
        let script = &out.stdout;
        assert!(script.contains("list-integrators"), "{shell}: {script}");
    }
    let man = dir.run(&["man"]);
    man.assert_code(0);
    let page = &man.stdout;
    assert!(page.contains(".TH mechkit"), "{page}");
    dir.run(&["man", "-o", "man1"]).assert_code(0);
    assert!(dir.path().join("man1/mechkit.1").is_file());
    assert!(dir.path().join("man1/mechkit-run.1").is_file());
}

#[test]
fn help_is_wrapped() {
    let dir = Dir::new();
    for c in ["run", "sweep", "rocket"] {
        let out = dir.run(&[c, "--help"]);
        let help = &out.stdout;
        for line in help.lines() {
            assert!(
                line.chars().count() <= 120,
                "`mechkit {c} --help` has a line of {} characters:\n{line}",
                line.chars().count()
            );
        }
    }
}
