//! What `mechkit gallery` prints as text: one case in full (`gallery ID`), or a line per file
//! run and the count of the values that pass (`gallery --all`).

use std::fmt::Write as _;
use std::path::Path;

use crate::gallery::report;
use crate::gallery::{Case, CaseRun, case_of};

/// One case in full: the question, each value against the book's, the outputs kept.
pub(super) fn describe(cases: &[Case], runs: &[CaseRun], out: Option<&Path>) -> String {
    let mut text = String::new();
    for run in runs {
        let case = case_of(cases, &run.stem);
        if let Some(case) = case {
            let _ = writeln!(
                text,
                "{}: {} (chapter {})",
                run.stem, case.topic, case.chapter
            );
            let _ = writeln!(text, "  asked: {}", case.asked);
        }
        let _ = writeln!(text, "  file:  {}", run.file);
        let _ = writeln!(
            text,
            "  {:<12} {:>14} {:>14} {:>9}  result",
            "value", "expected", "computed", "error"
        );
        for c in &run.checks {
            let error = c.error.map_or(String::new(), |e| format!("{e:.1e}"));
            let result = match (c.pass, c.note.is_empty()) {
                (true, _) => "pass".to_string(),
                (false, true) => "FAIL".to_string(),
                (false, false) => format!("FAIL: {}", c.note),
            };
            let _ = writeln!(
                text,
                "  {:<12} {:>14} {:>14} {error:>9}  {result}",
                c.key,
                report::value(&c.expected).trim_matches('`'),
                report::value(&c.computed).trim_matches('`'),
            );
        }
        if let Some(e) = &run.error {
            let _ = writeln!(text, "  error: {e}");
        }
        if let Some(out) = out {
            let dir = out.join(&run.stem);
            let _ = writeln!(text, "  outputs: {}", dir.display());
            for p in &run.plots {
                let _ = writeln!(text, "  plot: {}", dir.join(p).display());
            }
        }
    }
    text
}

pub(super) fn summary_lines(runs: &[CaseRun], out: Option<&Path>) -> String {
    let mut text = String::new();
    let (mut passed, mut total) = (0, 0);
    for r in runs {
        let ok = r.checks.iter().filter(|c| c.pass).count();
        passed += ok;
        total += r.checks.len();
        let verdict = if r.error.is_none() && ok == r.checks.len() {
            "pass"
        } else {
            "FAIL"
        };
        let _ = writeln!(
            text,
            "{verdict}  {:<48} {ok}/{}{}",
            r.stem,
            r.checks.len(),
            r.error.as_ref().map_or(String::new(), |e| format!("  {e}"))
        );
    }
    let _ = writeln!(
        text,
        "\n{passed} of {total} values pass in {} files{}",
        runs.len(),
        out.map_or(String::new(), |o| format!("; outputs in {}", o.display()))
    );
    text
}
