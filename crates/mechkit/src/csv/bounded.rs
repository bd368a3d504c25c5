//! Reading an input file no further than a bound. A regular file larger than the bound is
//! refused from its size before anything is read; a source whose size the file system does
//! not give (`/dev/zero`, `/dev/urandom`, a pipe such as `<(…)`) is read up to the bound and
//! refused past it. Before, `mechkit check /dev/zero` never ended and `md --positions
//! /dev/zero` filled the memory until the system killed it.

use std::fs;
use std::io::{self, Read};
use std::path::Path;

/// The most bytes mechkit reads from one data file: a table (`derive`, `work`, `impulse`,
/// `terminal --data`, `sweep-merge`), an atoms file (`md --positions`), a mesh, an image, a run
/// directory's files (2 GB: a recording of about 50 million rows; reading it takes about 1.5
/// times its size in memory).
pub const MAX_DATA_BYTES: u64 = 2_000_000_000;

/// The bytes of the file at `path`, noted as an input ([`super::note_read`]), if it holds at
/// most `limit` of them; else an error of kind [`io::ErrorKind::FileTooLarge`] that gives the
/// limit.
///
/// ```
/// use mechkit::csv::read_bounded;
/// let e = read_bounded(std::path::Path::new("/dev/zero"), 1000).unwrap_err();
/// assert_eq!(e.kind(), std::io::ErrorKind::FileTooLarge);
/// assert!(e.to_string().contains("goes on past 1 kB"), "{e}");
/// ```
pub fn read_bounded(path: &Path, limit: u64) -> io::Result<Vec<u8>> {
    super::note_read(path);
    let file = fs::File::open(path)?;
    let meta = file.metadata()?;
    if meta.is_file() && meta.len() > limit {
        return Err(io::Error::new(
            io::ErrorKind::FileTooLarge,
            format!(
                "it is {}, more than the {} mechkit reads from one file",
                format_size(meta.len()),
                format_size(limit)
            ),
        ));
    }
    let hint = usize::try_from(meta.len().min(limit)).unwrap_or(0);
    let mut bytes = Vec::with_capacity(if meta.is_file() { hint } else { 0 });
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(io::Error::new(
            io::ErrorKind::FileTooLarge,
            format!(
                "it goes on past {}, the most mechkit reads from one file (an endless source, such as /dev/zero?)",
                format_size(limit)
            ),
        ));
    }
    Ok(bytes)
}

/// [`read_bounded`] as UTF-8 text (the error of [`fs::read_to_string`] when it is not).
pub fn read_bounded_text(path: &Path, limit: u64) -> io::Result<String> {
    String::from_utf8(read_bounded(path, limit)?).map_err(|_| {
        io::Error::new(
            io::ErrorKind::InvalidData,
            "stream did not contain valid UTF-8",
        )
    })
}

/// A size for people: `1 GB`, `250 MB`, `12.5 kB`, `900 B` (decimal units).
pub fn format_size(bytes: u64) -> String {
    let b = bytes as f64;
    for (unit, f) in [("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)] {
        if b >= f {
            let x = b / f;
            return if (x - x.round()).abs() < 1e-9 {
                format!("{x:.0} {unit}")
            } else {
                format!("{} {unit}", format!("{x:.3}").trim_end_matches('0'))
            };
        }
    }
    format!("{bytes} B")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An endless source ends at the bound, a file over it is refused from its size, and a
    /// file within it is read whole.
    #[test]
    fn endless_and_large_sources_end_at_the_bound() {
        for endless in ["/dev/zero", "/dev/urandom"] {
            let e = read_bounded(Path::new(endless), 4096).unwrap_err();
            assert_eq!(e.kind(), io::ErrorKind::FileTooLarge, "{endless}");
            assert!(e.to_string().contains("goes on past 4.096 kB"), "{e}");
        }
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.csv");
        fs::write(&path, "t,x\n0,1\n").unwrap();
        assert_eq!(read_bounded_text(&path, 8).unwrap(), "t,x\n0,1\n");
        let e = read_bounded(&path, 7).unwrap_err();
        assert!(
            e.to_string().contains("it is 8 B, more than the 7 B"),
            "{e}"
        );
        fs::write(&path, [0xff, 0xfe]).unwrap();
        assert_eq!(
            read_bounded_text(&path, 8).unwrap_err().kind(),
            io::ErrorKind::InvalidData
        );
    }
}
