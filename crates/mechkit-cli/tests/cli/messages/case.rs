//! One catalogue entry (`Case`), its run through the binary, and the snapshot of its stderr.

use std::sync::OnceLock;

use crate::util::Dir;

/// The contents of an input file of a case.
pub enum Contents {
    /// A text file.
    Text(&'static str),
    /// A binary file, made when the case runs (images).
    Bytes(fn() -> Vec<u8>),
    /// An empty directory (where a file is meant: a target that is not a regular file).
    Folder,
}

/// One kind of error: the input that provokes it and what is expected of the run.
pub struct Case {
    /// The area of the catalogue (a file of this module): `scenario`, `formula`, `data`, …
    pub area: &'static str,
    /// The kind of error, unique within its area; also the snapshot's name.
    pub kind: &'static str,
    /// Input files written into the working directory before the run.
    pub files: &'static [(&'static str, Contents)],
    /// The arguments of `mechkit`.
    pub args: &'static [&'static str],
    /// The expected exit code.
    pub code: i32,
}

/// What a case produced, with temporary paths replaced by `[TMP]`.
pub struct Ran {
    /// The case.
    pub case: &'static Case,
    /// The exit code (`None` if killed by a signal).
    pub code: Option<i32>,
    /// Standard error.
    pub stderr: String,
}

impl Case {
    /// The command line as a user would type it (arguments with spaces quoted).
    pub fn command(&self) -> String {
        let mut s = String::from("mechkit");
        for a in self.args {
            s.push(' ');
            if a.is_empty() || a.contains([' ', '$', '(', ')', '*', '|', '&', ';', '<', '>', '@']) {
                s.push('"');
                s.push_str(a);
                s.push('"');
            } else {
                s.push_str(a);
            }
        }
        s
    }

    /// The snapshot's name, also its file name without `.snap`: `area__kind`.
    pub fn snapshot_name(&self) -> String {
        format!("{}__{}", self.area.replace(' ', "_"), self.kind)
    }

    fn run(&'static self) -> Ran {
        let dir = Dir::new();
        for (name, contents) in self.files {
            match contents {
                Contents::Text(text) => {
                    dir.create(name, text);
                }
                Contents::Bytes(make) => {
                    std::fs::write(dir.path().join(name), make()).expect("the file is written");
                }
                Contents::Folder => {
                    std::fs::create_dir_all(dir.path().join(name)).expect("the folder is made");
                }
            }
        }
        let out = dir.run(self.args);
        let mut stderr = out.stderr;
        let tmp = dir.path().display().to_string();
        let canonical = dir
            .path()
            .canonicalize()
            .map_or_else(|_| tmp.clone(), |p| p.display().to_string());
        stderr = stderr.replace(&canonical, "[TMP]").replace(&tmp, "[TMP]");
        Ran {
            case: self,
            code: out.code,
            stderr,
        }
    }
}

impl Ran {
    /// The snapshot text: the command, the exit code and stderr.
    pub fn snapshot(&self) -> String {
        let code = self
            .code
            .map_or_else(|| "killed by a signal".to_string(), |c| c.to_string());
        format!(
            "$ {}\nexit code: {code}\n--- stderr\n{}",
            self.case.command(),
            self.stderr
        )
    }

    /// Checks the exit code and compares the snapshot with the committed one.
    pub fn assert_snapshot(&self) {
        assert_eq!(
            self.code,
            Some(self.case.code),
            "{}/{}: unexpected exit code\n{}",
            self.case.area,
            self.case.kind,
            self.snapshot()
        );
        let mut settings = insta::Settings::clone_current();
        settings.set_prepend_module_to_snapshot(false);
        settings.set_omit_expression(true);
        settings.set_description(self.case.command());
        settings.bind(|| {
            insta::assert_snapshot!(self.case.snapshot_name(), self.snapshot());
        });
    }
}

/// Every case of the catalogue, in the order of the table.
pub fn all_cases() -> impl Iterator<Item = &'static Case> {
    [
        super::scenario::CASES,
        super::scenario_values::CASES,
        super::calculus::CASES,
        super::body::CASES,
        super::data::CASES,
        super::image::CASES,
        super::md::CASES,
        super::cli_flags::CASES,
        super::commands::CASES,
        super::runtime::CASES,
        super::planar::CASES,
        super::limits::CASES,
        super::reliability::CASES,
        super::answers::CASES,
    ]
    .into_iter()
    .flatten()
}

/// Every case run once (in parallel, a few at a time), shared by the tests of this process.
pub fn all_runs() -> &'static [Ran] {
    static RUNS: OnceLock<Vec<Ran>> = OnceLock::new();
    RUNS.get_or_init(|| {
        let cases: Vec<&'static Case> = all_cases().collect();
        let mut runs: Vec<Option<Ran>> = cases.iter().map(|_| None).collect();
        std::thread::scope(|s| {
            for (chunk, slots) in cases.chunks(8).zip(runs.chunks_mut(8)) {
                s.spawn(move || {
                    for (case, slot) in chunk.iter().zip(slots) {
                        *slot = Some(case.run());
                    }
                });
            }
        });
        runs.into_iter()
            .map(|r| r.expect("every case ran"))
            .collect()
    })
}

/// Snapshots every case of `cases` (one file's list).
pub fn assert_cases(cases: &'static [Case]) {
    assert!(!cases.is_empty());
    for case in cases {
        let ran = all_runs()
            .iter()
            .find(|r| std::ptr::eq(r.case, case))
            .expect("every case is in `all_cases`");
        ran.assert_snapshot();
    }
}
