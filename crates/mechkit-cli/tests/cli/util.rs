//! Helpers for the command-line tests, in the style of ripgrep's `tests/util.rs`: a temporary
//! directory to write scenario files into and to run the `mechkit` binary in.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use tempfile::TempDir;

/// What a run of the binary produced.
#[derive(Debug)]
pub struct Output {
    /// Standard output, as text.
    pub stdout: String,
    /// Standard error, as text.
    pub stderr: String,
    /// The exit code (`None` if the process was killed by a signal).
    pub code: Option<i32>,
}

impl Output {
    /// Standard output as JSON, after checking that the command succeeded.
    pub fn json(&self) -> serde_json::Value {
        self.assert_code(0);
        serde_json::from_str(&self.stdout)
            .unwrap_or_else(|e| panic!("stdout is not JSON ({e}):\n{}", self.stdout))
    }

    /// Panics with the whole output unless the exit code is `code`.
    pub fn assert_code(&self, code: i32) -> &Self {
        assert_eq!(
            self.code,
            Some(code),
            "expected exit code {code}\n--- stdout\n{}\n--- stderr\n{}",
            self.stdout,
            self.stderr
        );
        self
    }

    /// Panics unless stderr contains `needle` (and shows stderr if it does not).
    pub fn assert_stderr_contains(&self, needle: &str) -> &Self {
        assert!(
            self.stderr.contains(needle),
            "stderr does not contain {needle:?}\n--- stderr\n{}",
            self.stderr
        );
        self
    }

    /// The checks every bad-input error shares: exit code 2, stderr starting with `error:`, no
    /// panic, and each of `needles` in stderr.
    pub fn assert_bad_input(&self, needles: &[&str]) -> &Self {
        self.assert_code(2);
        assert!(
            self.stderr.starts_with("error:"),
            "stderr does not start with `error:`\n--- stderr\n{}",
            self.stderr
        );
        assert!(
            !self.stderr.contains("panicked"),
            "the binary panicked\n--- stderr\n{}",
            self.stderr
        );
        for needle in needles {
            self.assert_stderr_contains(needle);
        }
        self
    }
}

/// A temporary working directory, removed when dropped.
pub struct Dir {
    tmp: TempDir,
}

impl Dir {
    /// A fresh empty directory.
    pub fn new() -> Dir {
        let tmp = tempfile::Builder::new()
            .prefix("mechkit-cli-test-")
            .tempdir()
            .expect("a temporary directory can be created");
        Dir { tmp }
    }

    /// The directory's path.
    pub fn path(&self) -> &Path {
        self.tmp.path()
    }

    /// Writes `contents` to `name` inside the directory. A leading newline is dropped, so a
    /// scenario can be written as a raw string that starts on the line after `r#"` and still
    /// have its first key on line 1.
    pub fn create(&self, name: &str, contents: &str) -> PathBuf {
        let path = self.path().join(name);
        let contents = contents.strip_prefix('\n').unwrap_or(contents);
        fs::write(&path, contents).expect("the scenario file can be written");
        path
    }

    /// Runs `mechkit` with `args`, with this directory as the working directory (so relative
    /// file names in arguments and messages are the names given to `create`).
    pub fn run(&self, args: &[&str]) -> Output {
        self.run_with_env(args, &[])
    }

    /// Runs `mechkit` with `head` and then `tail`: a command with the arguments a test file
    /// always gives it, then those of one case.
    pub fn run_with(&self, head: &[&str], tail: &[&str]) -> Output {
        self.run(&[head, tail].concat())
    }

    /// Runs `mechkit` with `args` (which ask for `--json`) and parses its standard output, after
    /// checking that it exited 0.
    pub fn json(&self, args: &[&str]) -> serde_json::Value {
        self.run(args).json()
    }

    /// [`Dir::json`] of `head`, then `tail`, then `--json`.
    pub fn json_with(&self, head: &[&str], tail: &[&str]) -> serde_json::Value {
        self.json(&[head, tail, &["--json"]].concat())
    }

    /// [`Dir::run`] with environment variables set.
    pub fn run_with_env(&self, args: &[&str], env: &[(&str, &str)]) -> Output {
        let out = Command::new(env!("CARGO_BIN_EXE_mechkit"))
            .args(args)
            .envs(env.iter().copied())
            .current_dir(self.path())
            .output()
            .expect("the mechkit binary runs");
        Output {
            stdout: String::from_utf8(out.stdout).expect("stdout is UTF-8"),
            stderr: String::from_utf8(out.stderr).expect("stderr is UTF-8"),
            code: out.status.code(),
        }
    }

    /// Reads a file inside the directory.
    pub fn read(&self, name: &str) -> String {
        let path = self.path().join(name);
        fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
    }

    /// The names of the files in the folder `sub` of the directory (`"."` for the directory
    /// itself), sorted; none if it does not exist.
    pub fn files(&self, sub: &str) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(self.path().join(sub))
            .map(|entries| {
                entries
                    .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                    .collect()
            })
            .unwrap_or_default();
        names.sort();
        names
    }

    /// Reads and parses a JSON file inside the directory.
    pub fn read_json(&self, name: &str) -> serde_json::Value {
        serde_json::from_str(&self.read(name)).unwrap_or_else(|e| panic!("{name} is not JSON: {e}"))
    }
}

/// The repository's `examples` directory.
pub fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The file `path` under the repository's `examples` directory (e.g. `data/forcedata.d`), as
/// an argument for the binary; it must exist.
pub fn example(path: &str) -> String {
    let path = examples().join(path);
    assert!(path.exists(), "{}", path.display());
    path.display().to_string()
}

/// A parsed CSV file of numbers: the header and the rows.
#[derive(Debug)]
pub struct Csv {
    /// Column names.
    pub header: Vec<String>,
    /// Rows of numbers (`NaN` and `inf` included as read).
    pub rows: Vec<Vec<f64>>,
}

impl Csv {
    /// Parses CSV text whose cells after the header are all numbers.
    pub fn parse(text: &str) -> Csv {
        let mut lines = text.lines();
        let header: Vec<String> = lines
            .next()
            .expect("the CSV has a header")
            .split(',')
            .map(str::to_string)
            .collect();
        let rows: Vec<Vec<f64>> = lines
            .enumerate()
            .map(|(i, line)| {
                line.split(',')
                    .map(|cell| {
                        cell.parse::<f64>().unwrap_or_else(|e| {
                            panic!(
                                "row {} has a cell {cell:?} that is not a number: {e}",
                                i + 1
                            )
                        })
                    })
                    .collect::<Vec<f64>>()
            })
            .collect();
        for (i, row) in rows.iter().enumerate() {
            assert_eq!(
                row.len(),
                header.len(),
                "row {} has {} cells, the header {}",
                i + 1,
                row.len(),
                header.len()
            );
        }
        Csv { header, rows }
    }

    /// The index of a column.
    pub fn column(&self, name: &str) -> usize {
        self.header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name:?} in {:?}", self.header))
    }
}

/// Follows a `/`-separated path into a JSON value, panicking with the path if it is absent.
pub fn at<'v>(v: &'v serde_json::Value, pointer: &str) -> &'v serde_json::Value {
    v.pointer(pointer)
        .unwrap_or_else(|| panic!("the JSON has no {pointer}:\n{v:#}"))
}

/// The number at `pointer`.
pub fn num(v: &serde_json::Value, pointer: &str) -> f64 {
    at(v, pointer)
        .as_f64()
        .unwrap_or_else(|| panic!("{pointer} is not a number: {}", at(v, pointer)))
}
