//! [`ReservedFile`]: a file whose room on disk is taken before the work starts, so that it
//! can still be written when the disk has filled up meanwhile (the run's summary).

use std::fs::{self, File, OpenOptions};
use std::io::{self, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

use crate::csv::{partial_path, writable_target};

/// The room a run's summary takes on disk before the run: far more than a summary without
/// thousands of events holds (a few KiB).
pub const SUMMARY_RESERVE: u64 = 64 * 1024;

/// A file written once, at the end, into room taken at the start: `NAME.partial` is created
/// at once and filled with `reserve` bytes (a placeholder JSON object padded with spaces:
/// real blocks, not a sparse file, so the room is truly taken). [`ReservedFile::write`] then
/// overwrites it in place, cuts it to length, syncs it and renames it into place: a text
/// that fits the reserve needs no new room on a full disk. Dropped unwritten, the partial
/// file is removed.
pub struct ReservedFile {
    file: Option<File>,
    tmp: PathBuf,
    path: PathBuf,
    reserve: u64,
}

impl ReservedFile {
    /// Takes `reserve` bytes for the file at `path` (a link is written through, a path that is
    /// not a regular file refused, as by [`write_atomic`](crate::csv::write_atomic)).
    ///
    /// # Errors
    /// When the target is not a regular file or the room cannot be taken (the partial file
    /// is then removed).
    pub fn create(path: &Path, reserve: u64) -> io::Result<Self> {
        let path = writable_target(path)?;
        let tmp = partial_path(&path);
        if fs::symlink_metadata(&tmp).is_ok_and(|m| !m.is_dir()) {
            fs::remove_file(&tmp)?;
        }
        let file = OpenOptions::new().write(true).create_new(true).open(&tmp)?;
        let mut this = Self {
            file: Some(file),
            tmp,
            path,
            reserve,
        };
        this.fill()?;
        Ok(this)
    }

    /// Fills the reserve: a placeholder, then spaces up to `reserve` bytes.
    fn fill(&mut self) -> io::Result<()> {
        let placeholder = b"{\"stop_reason\": \"running\"}\n";
        let mut block = vec![b' '; 1 << 16];
        let file = self.file.as_mut().expect("open until written");
        file.write_all(placeholder)?;
        let mut left = self.reserve.saturating_sub(placeholder.len() as u64);
        while left > 0 {
            let n = left.min(block.len() as u64) as usize;
            block.truncate(n);
            file.write_all(&block)?;
            left -= n as u64;
        }
        file.sync_all()
    }

    /// The bytes taken.
    pub fn reserve(&self) -> u64 {
        self.reserve
    }

    /// Writes `bytes` over the reserve, cuts the file to their length, syncs it and renames it
    /// into place. When `bytes` need more room than the reserve and the disk has none, the
    /// file is cut back to the reserve and the error returned: the reserve is still held, to
    /// write a shorter text.
    ///
    /// # Errors
    /// When the file cannot be written or renamed; it stays reserved (and is removed when
    /// dropped).
    pub fn write(&mut self, bytes: &[u8]) -> io::Result<()> {
        let Some(file) = self.file.as_mut() else {
            return Err(io::Error::other("the file was written already"));
        };
        let written = file
            .seek(SeekFrom::Start(0))
            .and_then(|_| file.write_all(bytes))
            .and_then(|()| file.set_len(bytes.len() as u64))
            .and_then(|()| file.sync_all());
        if let Err(e) = written {
            let _ = file.set_len(self.reserve);
            return Err(e);
        }
        fs::rename(&self.tmp, &self.path)?;
        self.file = None;
        Ok(())
    }

    /// The final path.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Drop for ReservedFile {
    /// A reserve never written holds nothing of value: it is removed.
    fn drop(&mut self) {
        if self.file.take().is_some() {
            let _ = fs::remove_file(&self.tmp);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reserve_is_taken_then_overwritten_cut_and_renamed() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let path = dir.path().join("summary.json");
        let mut r = ReservedFile::create(&path, 1000).expect("reserved");
        let partial = partial_path(&path);
        assert_eq!(fs::metadata(&partial).expect("partial").len(), 1000);
        assert!(!path.exists());
        r.write(b"{\"a\": 1}\n").expect("written");
        assert_eq!(fs::read_to_string(&path).expect("final"), "{\"a\": 1}\n");
        assert!(!partial.exists());
        drop(r);
        assert!(path.exists(), "a written file stays");
        // a reserve dropped unwritten leaves nothing
        let other = dir.path().join("other.json");
        drop(ReservedFile::create(&other, 10).expect("reserved"));
        assert!(!partial_path(&other).exists() && !other.exists());
    }
}
