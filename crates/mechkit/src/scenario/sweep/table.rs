//! The sweep's table: one CSV row per run, under a manifest line that identifies the sweep
//! (scenario text hash, `--set` values, sampling, number of runs), so parts written by shards
//! can be checked and merged.
//!
//! ```text
//! # mechkit sweep of ball.toml (fnv1a 3c4b…) --set "v0=0:5:51" grid; 51 runs
//! # shard 2/3                          (parts only)
//! index,v0,stop_reason,t_end,steps,x_max,K_end,U_end,E_end,work_energy_residual
//! 1,0.1,event:stop,…
//! ```

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use super::{Shard, SweepError, SweepGrid, SweepRow};
use crate::figure::{PlotData, Series};
use crate::scenario::push_number;

const MAGIC: &str = "# mechkit sweep of ";

/// The rows of a sweep, or of one shard of it.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepTable {
    /// The manifest line's text (without `# `).
    pub manifest: String,
    /// How many runs the whole sweep has.
    pub runs: usize,
    /// The slice these rows are, if not all.
    pub shard: Option<Shard>,
    /// Parameter names (columns after `index`).
    pub params: Vec<String>,
    /// Observable names.
    pub observables: Vec<String>,
    /// The rows, by run index.
    pub rows: Vec<SweepRow>,
}

/// The manifest of a sweep of `text`: what every part of it has in common.
pub(crate) fn manifest(name: &str, text: &str, grid: &SweepGrid) -> String {
    let file = Path::new(name)
        .file_name()
        .map_or_else(|| name.to_string(), |f| f.to_string_lossy().into_owned());
    format!(
        "{}{file} (fnv1a {:016x}) {}; {} runs",
        &MAGIC[2..],
        fnv1a(text.as_bytes()),
        grid.describe(),
        grid.len()
    )
}

use crate::scenario::provenance::fnv1a;

fn field(out: &mut String, s: &str) {
    if s.contains([',', '"', '\n']) {
        out.push('"');
        out.push_str(&s.replace('"', "\"\""));
        out.push('"');
    } else {
        out.push_str(s);
    }
}

impl SweepTable {
    /// The column names.
    pub fn header(&self) -> Vec<String> {
        let mut h = vec!["index".to_string()];
        h.extend(self.params.iter().cloned());
        h.extend(["stop_reason", "t_end", "steps"].map(String::from));
        h.extend(self.observables.iter().cloned());
        h.extend(["K_end", "U_end", "E_end", "work_energy_residual"].map(String::from));
        h
    }

    /// The CSV text: manifest, shard line (parts only), header, one row per run. Numbers
    /// are SI, printed to round-trip; an absent potential energy is an empty cell.
    pub fn to_csv(&self) -> String {
        let mut out = format!("# {}\n", self.manifest);
        if let Some(s) = self.shard {
            let _ = writeln!(out, "# shard {}/{}", s.k, s.n);
        }
        let header: Vec<String> = self
            .header()
            .iter()
            .map(|h| {
                let mut s = String::new();
                field(&mut s, h);
                s
            })
            .collect();
        out.push_str(&header.join(","));
        out.push('\n');
        for r in &self.rows {
            out.push_str(&r.index.to_string());
            for &v in &r.values {
                out.push(',');
                push_number(&mut out, v);
            }
            out.push(',');
            field(&mut out, &r.stop_reason);
            out.push(',');
            push_number(&mut out, r.t_end);
            let _ = write!(out, ",{}", r.steps);
            for &v in r.observables.iter().chain([&r.kinetic_end]) {
                out.push(',');
                push_number(&mut out, v);
            }
            out.push(',');
            if let Some(u) = r.potential_end {
                push_number(&mut out, u);
            }
            for v in [r.energy_end, r.work_energy_residual] {
                out.push(',');
                push_number(&mut out, v);
            }
            out.push('\n');
        }
        out
    }

    /// The file name of this table: `sweep.csv`, or `sweep.partK.csv` for shard K.
    pub fn file_name(&self) -> String {
        match self.shard {
            Some(s) => format!("sweep.part{}.csv", s.k),
            None => "sweep.csv".into(),
        }
    }

    /// The recorded plots of all runs in one figure, each curve labelled by its parameter
    /// values; with more than `legend` curves, only about `legend` evenly spaced ones are
    /// labelled. `None` when no plot was recorded.
    pub fn overlay(&self, legend: usize) -> Option<PlotData> {
        let first = self.rows.iter().find_map(|r| r.plot.as_ref())?;
        let mut plot = PlotData::new(
            first.spec.clone(),
            format!("sweep_{}", first.file_stem),
            first.x_label.clone(),
            first.y_label.clone(),
        );
        plot.equal_aspect = first.equal_aspect;
        let stride = self.rows.len().div_ceil(legend.max(1)).max(1);
        for (n, r) in self.rows.iter().enumerate() {
            let Some(p) = &r.plot else { continue };
            let label = self
                .params
                .iter()
                .zip(&r.values)
                .map(|(name, v)| format!("{name} = {}", short(*v)))
                .collect::<Vec<_>>()
                .join(", ");
            for s in &p.series {
                let mut l = label.clone();
                if p.series.len() > 1 {
                    l = format!("{l} ({})", s.label);
                }
                let shown = n % stride == 0 || n + 1 == self.rows.len();
                plot.series.push(Series::line(
                    if shown { l } else { String::new() },
                    s.points.clone(),
                ));
            }
        }
        Some(plot)
    }
}

/// A value for a legend: 4 significant digits.
fn short(v: f64) -> String {
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s.is_empty() || s == "-" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// Joins the parts written by `mechkit sweep --shard K/N` (given as file name and text) into
/// the table of the whole sweep, sorted by run index: byte for byte what the unsharded sweep
/// writes. The parts must have the same manifest and header, and together hold every run
/// exactly once.
pub fn merge_parts(parts: &[(String, String)]) -> Result<String, SweepError> {
    let Some((first_name, _)) = parts.first() else {
        return Err(SweepError::Coverage(
            "no parts to merge\n  = hint: give the directory of the sweep.partK.csv files, or the files".into(),
        ));
    };
    let mut manifest: Option<(&str, &str)> = None;
    let mut rows: BTreeMap<usize, (&str, &str)> = BTreeMap::new();
    let mut duplicates = Vec::new();
    let mut runs = 0;
    for (file, text) in parts {
        let not = |reason: &str| SweepError::NotATable {
            file: file.clone(),
            reason: reason.to_string(),
        };
        let mut lines = text.lines();
        let head = lines
            .next()
            .filter(|l| l.starts_with(MAGIC))
            .ok_or_else(|| not("the first line is not a `# mechkit sweep of …` manifest"))?;
        let mut header = lines.next().ok_or_else(|| not("no header row"))?;
        if header.starts_with("# shard ") {
            header = lines.next().ok_or_else(|| not("no header row"))?;
        }
        match manifest {
            None => {
                manifest = Some((head, header));
                runs = head
                    .rsplit_once("; ")
                    .and_then(|(_, r)| r.strip_suffix(" runs"))
                    .and_then(|r| r.parse::<usize>().ok())
                    .ok_or_else(|| not("the manifest does not end in `; N runs`"))?;
            }
            Some((m, h)) => {
                let what = if m != head {
                    "the manifest line"
                } else if h != header {
                    "the header row"
                } else {
                    ""
                };
                if !what.is_empty() {
                    return Err(SweepError::Mismatch {
                        first: first_name.clone(),
                        file: file.clone(),
                        what: what.into(),
                    });
                }
            }
        }
        for line in lines.filter(|l| !l.is_empty()) {
            let index = line
                .split(',')
                .next()
                .and_then(|i| i.parse::<usize>().ok())
                .filter(|&i| i < runs)
                .ok_or_else(|| not(&format!("the row `{line}` has no run index below {runs}")))?;
            if let Some((other, _)) = rows.insert(index, (file.as_str(), line)) {
                duplicates.push(format!("run {index} is in {other} and {file}"));
            }
        }
    }
    if !duplicates.is_empty() {
        return Err(SweepError::Coverage(format!(
            "runs given twice: {}\n  = hint: give each shard's part once",
            duplicates.join("; ")
        )));
    }
    if rows.len() != runs {
        let missing: Vec<usize> = (0..runs).filter(|i| !rows.contains_key(i)).collect();
        let shown: Vec<String> = missing.iter().take(10).map(ToString::to_string).collect();
        return Err(SweepError::Coverage(format!(
            "{} of {runs} runs are missing: {}{}\n  = hint: run the missing shards (with --shard K/N, run i is in shard i % N + 1) and merge again",
            missing.len(),
            shown.join(", "),
            if missing.len() > 10 { ", …" } else { "" }
        )));
    }
    let (head, header) = manifest.expect("at least one part was read");
    let mut out = format!("{head}\n{header}\n");
    for (_, line) in rows.values() {
        out.push_str(line);
        out.push('\n');
    }
    Ok(out)
}
