//! Joining the parts of a sharded sweep into the whole: from their files ([`merge_parts`],
//! what `mechkit sweep-merge` does) or in memory ([`merge_tables`], what a sweep spread over
//! other processes does). Both go through one join, with the same checks: the parts are of
//! the same sweep (the same manifest line and header row), and hold every run exactly once;
//! the rows come out in run order, so the whole equals the unsharded sweep byte for byte.

use std::collections::BTreeMap;

use super::table::MAGIC;
use super::{SweepError, SweepTable};

/// One part of a sharded sweep, as read from its files.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepPart {
    /// The CSV file's name (for messages).
    pub name: String,
    /// The CSV text.
    pub csv: String,
    /// The text of the manifest beside it ([`SweepTable::manifest_json`]).
    pub manifest: String,
}

/// The runs of the parts of one sweep, gathered and checked as they come.
struct Join<T> {
    /// The parts' names, in the order given.
    names: Vec<String>,
    /// The sweep's identity (its manifest line) and header row, from the first part.
    sweep: Option<(String, String)>,
    /// How many runs the whole sweep has.
    runs: usize,
    /// Each run's row and the part it came from.
    rows: BTreeMap<usize, (usize, T)>,
    /// Runs given twice, described.
    duplicates: Vec<String>,
}

impl<T> Join<T> {
    fn new() -> Self {
        Self {
            names: Vec::new(),
            sweep: None,
            runs: 0,
            rows: BTreeMap::new(),
            duplicates: Vec::new(),
        }
    }

    /// Starts the part `name` of the sweep `identity` with the header row `header` and `runs`
    /// runs: an error when it is from another sweep than the first part.
    fn part(
        &mut self,
        name: &str,
        identity: &str,
        header: &str,
        runs: usize,
    ) -> Result<(), SweepError> {
        match &self.sweep {
            None => {
                self.runs = runs;
                self.sweep = Some((identity.to_string(), header.to_string()));
            }
            Some((m, h)) => {
                let what = if m != identity {
                    "the manifest"
                } else if h != header {
                    "the header row"
                } else {
                    ""
                };
                if !what.is_empty() {
                    return Err(SweepError::Mismatch {
                        first: self.names[0].clone(),
                        file: name.to_string(),
                        what: what.into(),
                    });
                }
            }
        }
        self.names.push(name.to_string());
        Ok(())
    }

    /// Adds the row of run `index` from the current part.
    fn row(&mut self, index: usize, row: T) {
        let part = self.names.len() - 1;
        if let Some((other, _)) = self.rows.insert(index, (part, row)) {
            self.duplicates.push(format!(
                "run {index} is in {} and {}",
                self.names[other], self.names[part]
            ));
        }
    }

    /// The sweep's identity, header row, number of runs and rows in run order; an error when
    /// there were no parts, or a run is given twice or missing.
    fn finish(self) -> Result<(String, String, usize, Vec<T>), SweepError> {
        let Some((identity, header)) = self.sweep else {
            return Err(SweepError::Coverage(
                "no parts to merge\n  = hint: give the directory of the sweep.partK.csv files, or the files".into(),
            ));
        };
        if !self.duplicates.is_empty() {
            return Err(SweepError::Coverage(format!(
                "runs given twice: {}\n  = hint: give each shard's part once",
                self.duplicates.join("; ")
            )));
        }
        let runs = self.runs;
        if self.rows.len() != runs {
            let missing: Vec<usize> = (0..runs).filter(|i| !self.rows.contains_key(i)).collect();
            let shown: Vec<String> = missing.iter().take(10).map(ToString::to_string).collect();
            return Err(SweepError::Coverage(format!(
                "{} of {runs} runs are missing: {}{}\n  = hint: run the missing shards (with --shard K/N, run i is in shard i % N + 1) and merge again",
                missing.len(),
                shown.join(", "),
                if missing.len() > 10 { ", …" } else { "" }
            )));
        }
        let rows = self.rows.into_values().map(|(_, row)| row).collect();
        Ok((identity, header, runs, rows))
    }
}

/// Merges the parts of one sharded sweep into the whole: its CSV text and its manifest
/// (`shard` null). The parts must come from the same sweep (the same manifest line and header)
/// and hold every run exactly once; rows come out in run order, byte for byte as the
/// unsharded sweep writes them.
pub fn merge_parts(parts: &[SweepPart]) -> Result<(String, String), SweepError> {
    let mut join = Join::new();
    for part in parts {
        let file = &part.name;
        let not = |reason: &str| SweepError::NotATable {
            file: file.clone(),
            reason: reason.to_string(),
        };
        let manifest: serde_json::Value = serde_json::from_str(&part.manifest)
            .map_err(|e| not(&format!("its manifest is not JSON: {e}")))?;
        let identity = manifest
            .get("sweep")
            .and_then(serde_json::Value::as_str)
            .filter(|m| m.starts_with(MAGIC))
            .ok_or_else(|| not("its manifest has no `sweep` of `mechkit sweep of …`"))?;
        let n = manifest
            .get("runs")
            .and_then(serde_json::Value::as_u64)
            .ok_or_else(|| not("its manifest has no number of `runs`"))?;
        let n = usize::try_from(n).map_err(|_| not("too many runs"))?;
        let mut lines = part.csv.lines();
        let header = lines.next().ok_or_else(|| not("no header row"))?;
        join.part(file, identity, header, n)?;
        let runs = join.runs;
        for line in lines.filter(|l| !l.is_empty()) {
            let index = line
                .split(',')
                .next()
                .and_then(|i| i.parse::<usize>().ok())
                .filter(|&i| i < runs)
                .ok_or_else(|| not(&format!("the row `{line}` has no run index below {runs}")))?;
            join.row(index, line);
        }
    }
    let (identity, header, runs, rows) = join.finish()?;
    let mut out = format!("{header}\n");
    for line in rows {
        out.push_str(line);
        out.push('\n');
    }
    let whole = serde_json::json!({"sweep": identity, "runs": runs, "shard": null});
    Ok((out, format!("{whole:#}\n")))
}

/// Merges the tables of the shards of one sweep, run elsewhere (other processes, other
/// machines) and brought back in memory, into the whole table, with the checks of
/// [`merge_parts`]: its [`SweepTable::to_csv`] equals the unsharded sweep's byte for byte,
/// and each row keeps its recorded plot. A part is named by its file name
/// ([`SweepTable::file_name`], `sweep.part2.csv`) in errors.
pub fn merge_tables(parts: Vec<SweepTable>) -> Result<SweepTable, SweepError> {
    let mut join = Join::new();
    let mut first: Option<SweepTable> = None;
    for mut part in parts {
        let name = part.file_name();
        join.part(&name, &part.manifest, &part.header().join(","), part.runs)?;
        for row in std::mem::take(&mut part.rows) {
            if row.index >= join.runs {
                return Err(SweepError::NotATable {
                    file: name,
                    reason: format!("run {} is not below {} runs", row.index, join.runs),
                });
            }
            join.row(row.index, row);
        }
        first.get_or_insert(part);
    }
    let (_, _, runs, rows) = join.finish()?;
    let first = first.expect("a part was joined");
    Ok(SweepTable {
        runs,
        shard: None,
        rows,
        ..first
    })
}
