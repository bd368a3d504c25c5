//! [`StreamFile`]: a file written as a stream of whole records (CSV rows, XYZ frames) under
//! a temporary name, and renamed into place however the run ends.

use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::Real;
use crate::csv::{partial_path, writable_target};

/// How often a [`StreamFile`] hands its buffer to the operating system, at the least: a
/// process killed outright loses at most about this much of its output.
pub const FLUSH_INTERVAL: Duration = Duration::from_secs(1);

/// Bytes buffered before they are handed to the operating system.
const BUFFER: usize = 1 << 16;

/// A file written as a stream of records (a CSV row, an XYZ frame): to `NAME.partial`
/// beside it, flushed at least every [`FLUSH_INTERVAL`] and only ever at the end of a record,
/// held to a size limit, and renamed into place by [`StreamFile::finish`] (or when dropped),
/// so a reader never sees half a file under the final name.
///
/// What is on disk is always whole records: a write that fails part-way (a full disk, a
/// file size limit) is cut back to the end of the last record that reached the disk, and the
/// file then takes nothing more. A process killed outright (SIGKILL) leaves `NAME.partial`
/// holding the records up to its last flush.
pub struct StreamFile {
    file: File,
    buf: Vec<u8>,
    /// Where each record in `buf` ends in the file, and its tag (see [`StreamFile::append_row`]).
    pending: Vec<(u64, Real)>,
    tmp: PathBuf,
    path: PathBuf,
    /// Bytes accepted: on disk and in the buffer.
    written: u64,
    /// Bytes on disk: whole records.
    on_disk: u64,
    records_on_disk: u64,
    last_tag_on_disk: Real,
    limit: u64,
    full: bool,
    /// The write that failed: nothing is written after it.
    failed: Option<(io::ErrorKind, String)>,
    last_flush: Instant,
    appends: u32,
    done: bool,
}

impl StreamFile {
    /// Starts `path.partial`; the file may hold at most `limit` bytes. A symbolic link at
    /// `path` is written through (the partial file goes beside its final target); a `path`
    /// that exists and is not a regular file is refused (see
    /// [`writable_target`](crate::csv::writable_target)). A stale `path.partial` left by an
    /// earlier run is replaced, never written through.
    pub fn create(path: &Path, limit: u64) -> io::Result<Self> {
        let path = writable_target(path)?;
        let tmp = partial_path(&path);
        match fs::symlink_metadata(&tmp) {
            Ok(m) if !m.is_dir() => fs::remove_file(&tmp)?,
            _ => {}
        }
        let file = OpenOptions::new().write(true).create_new(true).open(&tmp)?;
        Ok(Self {
            file,
            buf: Vec::with_capacity(BUFFER),
            pending: Vec::new(),
            tmp,
            path,
            written: 0,
            on_disk: 0,
            records_on_disk: 0,
            last_tag_on_disk: Real::NAN,
            limit,
            full: false,
            failed: None,
            last_flush: Instant::now(),
            appends: 0,
            done: false,
        })
    }

    /// Appends one record (a header, a frame), unless it would take the file past its limit:
    /// then nothing is written, now or later, and the result is `false`
    /// ([`StreamFile::is_full`]).
    ///
    /// # Errors
    /// When the file cannot be written (a full disk): what is on disk is then cut back to
    /// whole records, and every later append fails the same way.
    pub fn append(&mut self, bytes: &[u8]) -> io::Result<bool> {
        self.append_row(bytes, Real::NAN)
    }

    /// [`StreamFile::append`] of a record tagged with `tag` (the time of a row): after a
    /// failed write, [`StreamFile::last_tag_on_disk`] says how far the file got.
    ///
    /// # Errors
    /// As [`StreamFile::append`].
    pub fn append_row(&mut self, bytes: &[u8], tag: Real) -> io::Result<bool> {
        if let Some(e) = self.failure() {
            return Err(e);
        }
        if self.full || self.written + bytes.len() as u64 > self.limit {
            self.full = true;
            return Ok(false);
        }
        self.buf.extend_from_slice(bytes);
        self.written += bytes.len() as u64;
        self.pending.push((self.written, tag));
        self.appends += 1;
        if self.buf.len() >= BUFFER
            || (self.appends.is_multiple_of(64) && self.last_flush.elapsed() >= FLUSH_INTERVAL)
        {
            self.flush_records()?;
        }
        Ok(true)
    }

    /// Hands the buffered records to the operating system (at a record's end, as always).
    ///
    /// # Errors
    /// When the write fails: the file is then cut back to the end of the last whole record
    /// on disk ([`StreamFile::records_on_disk`]).
    pub fn flush(&mut self) -> io::Result<()> {
        self.flush_records()
    }

    /// Hands the buffered records to the operating system. When the write fails part-way,
    /// the file is cut back to the end of the last whole record on disk.
    fn flush_records(&mut self) -> io::Result<()> {
        if let Some(e) = self.failure() {
            return Err(e);
        }
        self.last_flush = Instant::now();
        let mut done = 0;
        let error = loop {
            if done == self.buf.len() {
                break None;
            }
            match self.file.write(&self.buf[done..]) {
                Ok(0) => break Some(io::Error::from(io::ErrorKind::WriteZero)),
                Ok(n) => done += n,
                Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                Err(e) => break Some(e),
            }
        };
        let reached = self.on_disk + done as u64;
        let whole = self.pending.iter().take_while(|(end, _)| *end <= reached);
        for &(end, tag) in whole {
            self.on_disk = end;
            self.records_on_disk += 1;
            self.last_tag_on_disk = tag;
        }
        self.buf.clear();
        self.pending.clear();
        let Some(e) = error else {
            return Ok(());
        };
        // cut a record the disk took only part of
        if reached > self.on_disk {
            let _ = self.file.set_len(self.on_disk);
        }
        self.written = self.on_disk;
        self.failed = Some((e.kind(), e.to_string()));
        Err(e)
    }

    fn failure(&self) -> Option<io::Error> {
        self.failed
            .as_ref()
            .map(|(kind, text)| io::Error::new(*kind, text.clone()))
    }

    /// Whether an append was refused because of the limit.
    pub fn is_full(&self) -> bool {
        self.full
    }

    /// Whether a write failed (the file then takes nothing more).
    pub fn has_failed(&self) -> bool {
        self.failed.is_some()
    }

    /// Bytes written so far (after a failed write: the whole records on disk).
    pub fn len(&self) -> u64 {
        self.written
    }

    /// Whether nothing was written.
    pub fn is_empty(&self) -> bool {
        self.written == 0
    }

    /// Records (rows, frames, the header) on disk.
    pub fn records_on_disk(&self) -> u64 {
        self.records_on_disk
    }

    /// The tag of the last record on disk ([`StreamFile::append_row`]; NaN when it had none).
    pub fn last_tag_on_disk(&self) -> Real {
        self.last_tag_on_disk
    }

    /// The size limit.
    pub fn limit(&self) -> u64 {
        self.limit
    }

    /// The final path (the file is written beside it until [`StreamFile::finish`]); the
    /// target of a symbolic link given as the path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The temporary path being written.
    pub fn partial_path(&self) -> &Path {
        &self.tmp
    }

    /// Flushes, syncs and renames the file into place. After a failed write the whole
    /// records on disk are renamed into place all the same (a file that holds nothing is
    /// removed), and the error is returned.
    ///
    /// # Errors
    /// The failed write, or a failure to flush, sync or rename.
    pub fn finish(mut self) -> io::Result<()> {
        self.close()
    }

    fn close(&mut self) -> io::Result<()> {
        if self.done {
            return Ok(());
        }
        self.done = true;
        let flushed = self.flush_records().and_then(|()| self.file.sync_all());
        if flushed.is_err() && self.on_disk == 0 {
            let _ = fs::remove_file(&self.tmp);
            return flushed;
        }
        if flushed.is_err() {
            // on a full disk a sync may fail too; what is on disk is whole records
            let _ = self.file.sync_all();
        }
        fs::rename(&self.tmp, &self.path)?;
        flushed
    }
}

impl Drop for StreamFile {
    /// A stream left unfinished (an error on the way out, a panic) is finished as
    /// [`StreamFile::finish`] does, ignoring errors: files are renamed however the run ends.
    fn drop(&mut self) {
        let _ = self.close();
    }
}
