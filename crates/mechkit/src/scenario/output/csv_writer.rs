//! The trajectory streamed to a CSV file during the run.

use std::io;
use std::path::Path;

use super::row::{Keep, RowLayout, RowSink, csv_header};
use super::{SCENARIO_LIMIT_HINT, StreamFile, output_limit_message, push_number, rows_end};
use crate::Real;
use crate::particles::{ParticleSystem, Sample};
use crate::simulate::StopReason;

/// Streams samples to a CSV file (the kept ones, see [`Keep`], and the last).
pub(crate) struct CsvWriter {
    out: StreamFile,
    keep: Keep,
    layout: RowLayout,
    values: Vec<Real>,
    last_t: Option<Real>,
    line: String,
    rows: u64,
    /// Why the run must stop: the file reached its limit, or could not be written.
    halt: Option<(StopReason, String)>,
}

impl CsvWriter {
    pub fn create(
        path: &Path,
        sys: &ParticleSystem,
        has_potential: bool,
        keep: Keep,
        limit: u64,
    ) -> std::io::Result<Self> {
        let mut out = StreamFile::create(path, limit)?;
        let header = format!("{}\n", csv_header(sys, has_potential).join(","));
        if !out.append(header.as_bytes())? {
            return Err(io::Error::other(format!(
                "the output limit of {limit} bytes is too small for even the header of {}",
                path.display()
            )));
        }
        Ok(Self {
            out,
            keep,
            layout: RowLayout::new(sys, has_potential),
            values: Vec::new(),
            last_t: None,
            line: String::with_capacity(256),
            rows: 0,
            halt: None,
        })
    }

    fn write_row(&mut self, s: &Sample<'_>) {
        self.layout.values(s, &mut self.values);
        self.line.clear();
        for (i, &x) in self.values.iter().enumerate() {
            if i > 0 {
                self.line.push(',');
            }
            push_number(&mut self.line, x);
        }
        self.line.push('\n');
        if self.halt.is_some() {
            return;
        }
        match self.out.append_row(self.line.as_bytes(), s.t) {
            Ok(true) => {}
            Ok(false) => {
                self.halt = Some((
                    StopReason::OutputLimit,
                    output_limit_message(
                        self.out.path(),
                        self.out.limit(),
                        &rows_end(s.t, self.rows, self.last_t),
                        SCENARIO_LIMIT_HINT,
                    ),
                ));
                return;
            }
            Err(e) => {
                // a full disk, a quota: stop cleanly, keep the whole rows already on disk
                let kept = match self.out.records_on_disk() {
                    0 | 1 => "no rows".to_string(),
                    n => format!(
                        "{} rows up to t = {} s",
                        n - 1,
                        crate::error::short(self.out.last_tag_on_disk())
                    ),
                };
                self.halt = Some((
                    StopReason::OutputError,
                    format!(
                        "cannot write {} at t = {} s: {}, so the run stopped there; the file keeps {kept}; free space or choose another --out",
                        self.out.path().display(),
                        crate::error::short(s.t),
                        e,
                    ),
                ));
                return;
            }
        }
        self.last_t = Some(s.t);
        self.rows += 1;
    }

    /// Flushes and renames the file into place; returns the rows and the time of the last
    /// row in it, and whether finishing failed. However it ends, the file holds whole rows and
    /// is renamed into place (after a failed write: the rows that reached the disk).
    pub fn close(self) -> (u64, Option<Real>, std::io::Result<()>) {
        if self.out.has_failed() {
            let rows = self.out.records_on_disk().saturating_sub(1);
            let last = Some(self.out.last_tag_on_disk()).filter(|_| rows > 0);
            // the failure was reported when it happened (`RowSink::stop`)
            let _ = self.out.finish();
            return (rows, last, Ok(()));
        }
        let (rows, last_t) = (self.rows, self.last_t);
        let mut out = self.out;
        // flush here, to learn how far the file got if the flush fails
        match out.flush() {
            Ok(()) => (rows, last_t, out.finish()),
            Err(e) => {
                let rows = out.records_on_disk().saturating_sub(1);
                let last = Some(out.last_tag_on_disk()).filter(|_| rows > 0);
                let _ = out.finish();
                (rows, last, Err(e))
            }
        }
    }
}

impl RowSink for CsvWriter {
    fn keep(&self) -> Keep {
        self.keep
    }

    fn last_t(&self) -> Option<Real> {
        self.last_t
    }

    fn write(&mut self, s: &Sample<'_>) {
        self.write_row(s);
    }

    fn stop(&self) -> Option<(StopReason, String)> {
        self.halt.clone()
    }
}
