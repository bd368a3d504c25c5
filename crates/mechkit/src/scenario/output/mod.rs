//! Output files: the trajectory CSV, streamed during the run, and atomic writes (a temporary
//! file renamed into place, so a reader never sees half a file).
//!
//! The CSV is written to `trajectory.csv.partial` and renamed to `trajectory.csv` when the run
//! ends for any reason (including divergence), so everything computed is kept.

use std::path::Path;

use crate::Real;
pub use crate::csv::write_atomic;
pub use reserved::{ReservedFile, SUMMARY_RESERVE};
pub use stream::{FLUSH_INTERVAL, StreamFile};

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

/// Where a trajectory cut by its output limit stops and ends (for `at` of
/// [`output_limit_message`]): the time of the row that did not fit, and how many rows the file
/// holds, up to which time (the last one it holds, not the one refused).
pub(crate) fn rows_end(refused_t: Real, rows: u64, last_t: Option<Real>) -> String {
    let short = crate::error::short;
    match last_t {
        Some(last) => format!(
            "t = {} s (the file holds {rows} row{}, up to t = {} s)",
            short(refused_t),
            if rows == 1 { "" } else { "s" },
            short(last)
        ),
        None => format!("t = {} s (the file holds no row)", short(refused_t)),
    }
}

/// How to raise a scenario run's output limit.
pub(crate) const SCENARIO_LIMIT_HINT: &str = "raise the limit with `[output] max_size = \"10 GB\"` (or `mechkit run --max-output 10GB`), or write fewer rows with `[output] every = 10` or `interval`";

mod csv_writer;
mod reserved;
mod row;
mod stream;
mod table;

pub(crate) use csv_writer::CsvWriter;
pub(crate) use row::{Keep, RowSink};
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
