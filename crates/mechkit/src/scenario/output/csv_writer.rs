//! The trajectory streamed to a CSV file during the run.

use std::io;
use std::path::Path;

use super::row::{Keep, RowLayout, RowSink, csv_header};
use super::{SCENARIO_LIMIT_HINT, StreamFile, output_limit_message, push_number};
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
        match self.out.append(self.line.as_bytes()) {
            Ok(true) => {}
            Ok(false) => {
                self.halt = Some((
                    StopReason::OutputLimit,
                    output_limit_message(
                        self.out.path(),
                        self.out.limit(),
                        &format!("t = {} s", s.t),
                        SCENARIO_LIMIT_HINT,
                    ),
                ));
                return;
            }
            Err(e) => {
                // a full disk, a quota: stop cleanly, keep the rows already on disk
                self.halt = Some((
                    StopReason::OutputError,
                    format!(
                        "cannot write {} at t = {} s ({e}), so the run stopped there; the rows written before are kept; free space or choose another --out",
                        self.out.partial_path().display(),
                        s.t
                    ),
                ));
                return;
            }
        }
        self.last_t = Some(s.t);
        self.rows += 1;
    }

    /// Flushes and renames the file into place; returns the number of rows written.
    /// After a failed write, what reached the disk is renamed into place.
    pub fn close(self) -> std::io::Result<u64> {
        if matches!(self.halt, Some((StopReason::OutputError, _))) {
            self.out.keep_what_was_written()?;
        } else {
            self.out.finish()?;
        }
        Ok(self.rows)
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
