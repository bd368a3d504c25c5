//! Output files: the trajectory CSV, streamed during the run, and atomic writes (a temporary
//! file renamed into place, so a reader never sees half a file).
//!
//! The CSV is written to `trajectory.csv.partial` and renamed to `trajectory.csv` when the run
//! ends for any reason (including divergence), so everything computed is kept.

use std::fs::{self, File};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::csv::partial_path as temp_path;
pub use crate::csv::write_atomic;

/// How often a [`StreamFile`] hands its buffer to the operating system, at the least: a
/// process killed outright loses at most about this much of its output.
pub const FLUSH_INTERVAL: Duration = Duration::from_secs(1);

/// A file written as a stream: to `NAME.partial` beside it, flushed at least every
/// [`FLUSH_INTERVAL`], held to a size limit, and renamed into place by
/// [`StreamFile::finish`], so a reader never sees half a file under the final name.
pub struct StreamFile {
    out: BufWriter<File>,
    tmp: PathBuf,
    path: PathBuf,
    written: u64,
    limit: u64,
    full: bool,
    last_flush: Instant,
    appends: u32,
}

impl StreamFile {
    /// Starts `path.partial`; the file may hold at most `limit` bytes.
    pub fn create(path: &Path, limit: u64) -> io::Result<Self> {
        let tmp = temp_path(path);
        Ok(Self {
            out: BufWriter::with_capacity(1 << 16, File::create(&tmp)?),
            tmp,
            path: path.to_path_buf(),
            written: 0,
            limit,
            full: false,
            last_flush: Instant::now(),
            appends: 0,
        })
    }

    /// Appends `bytes`, unless they would take the file past its limit: then nothing is
    /// written, now or later, and the result is `false` ([`StreamFile::is_full`]).
    pub fn append(&mut self, bytes: &[u8]) -> io::Result<bool> {
        if self.full || self.written + bytes.len() as u64 > self.limit {
            self.full = true;
            return Ok(false);
        }
        self.out.write_all(bytes)?;
        self.written += bytes.len() as u64;
        self.appends += 1;
        if self.appends.is_multiple_of(64) && self.last_flush.elapsed() >= FLUSH_INTERVAL {
            self.out.flush()?;
            self.last_flush = Instant::now();
        }
        Ok(true)
    }

    /// Whether an append was refused because of the limit.
    pub fn is_full(&self) -> bool {
        self.full
    }

    /// Bytes written so far.
    pub fn len(&self) -> u64 {
        self.written
    }

    /// Whether nothing was written.
    pub fn is_empty(&self) -> bool {
        self.written == 0
    }

    /// The size limit.
    pub fn limit(&self) -> u64 {
        self.limit
    }

    /// The final path (the file is written beside it until [`StreamFile::finish`]).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The temporary path being written.
    pub fn partial_path(&self) -> &Path {
        &self.tmp
    }

    /// Flushes, syncs and renames the file into place.
    pub fn finish(mut self) -> io::Result<()> {
        self.out.flush()?;
        self.out.get_ref().sync_all()?;
        fs::rename(&self.tmp, &self.path)
    }

    /// After a failed write: renames what reached the disk into place, without insisting on
    /// the rest of the buffer.
    pub fn keep_what_was_written(mut self) -> io::Result<()> {
        let _ = self.out.flush();
        fs::rename(&self.tmp, &self.path)
    }
}

/// The message of a run stopped by an output file reaching its limit: which file, the limit,
/// when (`at`, e.g. `t = 1.02 s`), and `how` to raise the limit or write less.
pub fn output_limit_message(file: &Path, limit: u64, at: &str, how: &str) -> String {
    format!(
        "{} reached the output limit of {} at {at}, so the run stopped there; {how}",
        file.file_name().map_or_else(
            || file.display().to_string(),
            |n| n.to_string_lossy().into_owned()
        ),
        super::limits::format_size(limit),
    )
}

/// How to raise a scenario run's output limit.
pub(crate) const SCENARIO_LIMIT_HINT: &str = "raise the limit with `[output] max_size = \"10 GB\"` (or `mechkit run --max-output 10GB`), or write fewer rows with `[output] every = 10` or `interval`";

mod csv_writer;
mod row;
mod table;

pub(crate) use csv_writer::CsvWriter;
pub(crate) use row::Keep;
pub use row::{csv_columns, csv_columns_in, csv_header};
pub use table::Trajectory;
pub(crate) use table::TrajectoryTable;

pub use crate::csv::push_number;

#[cfg(test)]
mod tests {
    use super::{FLUSH_INTERVAL, StreamFile, push_number};

    #[test]
    fn a_stream_reaches_the_disk_within_the_flush_interval_and_keeps_to_its_limit() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let path = dir.path().join("rows.csv");
        let mut f = StreamFile::create(&path, 1000).expect("created");
        let partial = f.partial_path().to_path_buf();
        assert!(f.append(b"first\n").expect("written"));
        let on_disk = || std::fs::metadata(&partial).expect("the partial file").len();
        assert_eq!(on_disk(), 0, "a fresh row waits in the buffer");
        std::thread::sleep(FLUSH_INTERVAL + std::time::Duration::from_millis(20));
        for _ in 0..63 {
            assert!(f.append(b"row\n").expect("written"));
        }
        assert_eq!(on_disk(), 6 + 63 * 4, "flushed once the interval passed");
        assert!(!path.exists(), "the final name appears only at the end");
        // 258 bytes so far; 185 rows of 4 bytes would pass 1000
        let accepted = (0..200)
            .take_while(|_| f.append(b"row\n").expect("ok"))
            .count();
        assert_eq!(accepted, (1000 - 258) / 4);
        assert!(
            f.is_full() && !f.append(b"\n").expect("ok"),
            "nothing more once full"
        );
        assert_eq!(f.len(), 258 + 185 * 4);
        f.finish().expect("renamed");
        assert_eq!(std::fs::metadata(&path).expect("final").len(), 998);
        assert!(!partial.exists());
    }

    #[test]
    fn numbers_round_trip_compactly() {
        for (x, text) in [
            (0.0, "0"),
            (2.4, "2.4"),
            (1.5e-9, "1.5e-9"),
            (-4.8e-21, "-4.8e-21"),
            (1e20, "1e20"),
            (f64::NAN, "NaN"),
        ] {
            let mut s = String::new();
            push_number(&mut s, x);
            assert_eq!(s, text);
            if x.is_finite() {
                assert_eq!(s.parse::<f64>().unwrap(), x);
            }
        }
    }
}
