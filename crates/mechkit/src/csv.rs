//! The one CSV writer: tables of numbers with a unit per column, written as `NAME.csv` and its
//! units sidecar `NAME.units.json`, atomically.
//!
//! Every CSV mechkit writes has one header row of plain column names, then rows of numbers
//! (the shortest text that reads back as the same `f64`), and nothing else, so
//! `pandas.read_csv`, `polars.read_csv` and `numpy.genfromtxt(names=True)` read it without
//! options. The units are in the sidecar, a JSON object from column name to unit in column
//! order (`{"t": "s", "ball.x": "m", "K": "J"}`): `"1"` for a dimensionless column, `null`
//! where the unit is not known (a column of a data file read without units).
//!
//! ```
//! use mechkit::csv::{Column, Table};
//!
//! let mut table = Table::new([Column::new("t", "s"), Column::new("x", "m")]);
//! table.push(&[0.0, 1.5]);
//! table.push(&[0.1, 1.25e-9]);
//! assert_eq!(table.to_csv(), "t,x\n0,1.5\n0.1,1.25e-9\n");
//! assert_eq!(table.units_json(), "{\"t\": \"s\", \"x\": \"m\"}\n");
//! ```

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use crate::Real;

mod bounded;
mod inputs;
pub use bounded::{MAX_DATA_BYTES, format_size, read_bounded, read_bounded_text};
pub use inputs::{InputGuard, note_read, refuse_input_as_output, same_file};

/// A column: its name and its unit.
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Column {
    /// The header name (`t`, `ball.vx`, `work.gravity`).
    pub name: String,
    /// The unit (`m/s`; `1` when dimensionless), `None` when not known.
    pub unit: Option<String>,
}

impl Column {
    /// A column with a known unit (`"1"` for a dimensionless one).
    pub fn new(name: impl Into<String>, unit: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            unit: Some(unit.into()),
        }
    }

    /// A column whose unit is not known (a column of a data file read without units).
    pub fn unknown(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            unit: None,
        }
    }
}

/// A table of numbers with named columns: what every CSV file of mechkit holds.
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Table {
    columns: Vec<Column>,
    /// Row-major values, `columns.len()` per row.
    values: Vec<Real>,
}

impl Table {
    /// An empty table with these columns.
    pub fn new(columns: impl IntoIterator<Item = Column>) -> Self {
        Self {
            columns: columns.into_iter().collect(),
            values: Vec::new(),
        }
    }

    /// Appends a row.
    ///
    /// # Panics
    /// If the row's length is not the number of columns (a programming error).
    pub fn push(&mut self, row: &[Real]) {
        assert_eq!(
            row.len(),
            self.columns.len(),
            "a row of {} values for {} columns",
            row.len(),
            self.columns.len()
        );
        self.values.extend_from_slice(row);
    }

    /// The columns.
    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.values
            .len()
            .checked_div(self.columns.len())
            .unwrap_or_default()
    }

    /// Whether there are no rows.
    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// The rows, each `columns().len()` values.
    pub fn rows(&self) -> impl Iterator<Item = &[Real]> {
        self.values.chunks(self.columns.len().max(1))
    }

    /// The values of the column named `name`.
    pub fn column(&self, name: &str) -> Option<Vec<Real>> {
        let k = self.columns.iter().position(|c| c.name == name)?;
        Some(self.rows().map(|r| r[k]).collect())
    }

    /// The first value that is not finite, as (row from 1, column name, value): what the
    /// finiteness rule checks before a table of results is written.
    ///
    /// ```
    /// use mechkit::csv::{Column, Table};
    /// let mut t = Table::new([Column::new("t", "s"), Column::new("W", "J")]);
    /// t.push(&[0.0, 1.0]);
    /// assert_eq!(t.first_non_finite(), None);
    /// t.push(&[1.0, f64::INFINITY]);
    /// assert_eq!(t.first_non_finite(), Some((2, "W", f64::INFINITY)));
    /// ```
    pub fn first_non_finite(&self) -> Option<(usize, &str, Real)> {
        let k = self.columns.len().max(1);
        let i = self.values.iter().position(|x| !x.is_finite())?;
        let column = self.columns.get(i % k).map_or("", |c| c.name.as_str());
        Some((i / k + 1, column, self.values[i]))
    }

    /// The CSV text: the header row, then one row per line.
    pub fn to_csv(&self) -> String {
        let mut out = header_line(self.columns.iter().map(|c| c.name.as_str()));
        for row in self.rows() {
            push_row(&mut out, row);
        }
        out
    }

    /// The units sidecar's text (see the module doc).
    pub fn units_json(&self) -> String {
        units_json(&self.columns)
    }

    /// Writes `dir/NAME.csv` and `dir/NAME.units.json` atomically; returns the CSV's path.
    ///
    /// # Errors
    /// When a file cannot be written, or a target exists and is not a regular file.
    pub fn write(&self, dir: &Path, name: &str) -> io::Result<PathBuf> {
        let path = dir.join(format!("{name}.csv"));
        write_atomic(&path, self.to_csv().as_bytes())?;
        write_atomic(
            &dir.join(units_file_name(name)),
            self.units_json().as_bytes(),
        )?;
        Ok(path)
    }
}

/// The sidecar's file name for the CSV file named `NAME` or `NAME.csv`: `NAME.units.json`.
pub fn units_file_name(name: &str) -> String {
    let stem = name.strip_suffix(".csv").unwrap_or(name);
    format!("{stem}.units.json")
}

/// The header line (with its newline) of these column names.
pub fn header_line<'a>(names: impl IntoIterator<Item = &'a str>) -> String {
    let mut out = names.into_iter().collect::<Vec<_>>().join(",");
    out.push('\n');
    out
}

/// Appends one row (with its newline).
pub fn push_row(out: &mut String, row: &[Real]) {
    for (k, &x) in row.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        push_number(out, x);
    }
    out.push('\n');
}

/// The units sidecar of these columns: `{"name": "unit", …}` in column order.
pub fn units_json(columns: &[Column]) -> String {
    let mut out = String::from("{");
    for (k, c) in columns.iter().enumerate() {
        if k > 0 {
            out.push_str(", ");
        }
        push_json_string(&mut out, &c.name);
        out.push_str(": ");
        match &c.unit {
            Some(u) => push_json_string(&mut out, u),
            None => out.push_str("null"),
        }
    }
    out.push_str("}\n");
    out
}

fn push_json_string(out: &mut String, s: &str) {
    use std::fmt::Write as _;
    out.push('"');
    for ch in s.chars() {
        match ch {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if u32::from(c) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

/// Appends `x` with the fewest digits that read back as the same number, in exponent form
/// when that is shorter (`1.5e-9`, not `0.0000000015`).
pub fn push_number(out: &mut String, x: Real) {
    use std::fmt::Write as _;
    if crate::error::in_exponent_form(x) {
        let _ = write!(out, "{x:e}");
    } else {
        let _ = write!(out, "{x}");
    }
}

/// Writes `bytes` to `path` atomically: to `NAME.partial` beside it, synced, then renamed
/// over it. A symbolic link (or a chain of them) is written through: the file goes beside the
/// link's final target and replaces that target, so the link stays. A target that exists
/// and is not a regular file (a directory, a device, a pipe, a socket), or that is an input
/// read under an [`InputGuard`], is refused, never replaced or written into. On any failure
/// the partial file is removed.
///
/// # Errors
/// When the file cannot be written, or the target is not a regular file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let path = writable_target(path)?;
    let tmp = partial_path(&path);
    // a stale partial file (or a link by that name) is replaced, never written through
    if fs::symlink_metadata(&tmp).is_ok_and(|m| !m.is_dir()) {
        fs::remove_file(&tmp)?;
    }
    let mut created = false;
    let written = fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&tmp)
        .and_then(|mut f| {
            created = true;
            f.write_all(bytes)?;
            f.sync_all()
        })
        .and_then(|()| fs::rename(&tmp, &path));
    if written.is_err() && created {
        let _ = fs::remove_file(&tmp);
    }
    written
}

/// The most symbolic links followed from one output path (Linux's own limit).
const MAX_LINKS: usize = 40;

/// Where a file meant for `path` goes: `path` itself, or the final target of the symbolic
/// link (or chain of links) at `path`, which need not exist yet; an error that names the
/// path and what it is when that exists and is not a regular file, or when it is an input
/// read under an [`InputGuard`].
///
/// # Errors
/// When the target exists and is not a regular file, or is an input read under an
/// [`InputGuard`], or the links form a loop.
pub fn writable_target(path: &Path) -> io::Result<PathBuf> {
    let mut target = path.to_path_buf();
    let mut links = 0;
    loop {
        match fs::symlink_metadata(&target) {
            Ok(m) if m.file_type().is_symlink() => {
                links += 1;
                if links > MAX_LINKS {
                    return Err(io::Error::new(
                        io::ErrorKind::InvalidInput,
                        format!(
                            "{} is a loop of symbolic links; give the path of a file to write",
                            path.display()
                        ),
                    ));
                }
                let next = fs::read_link(&target)?;
                target = target.parent().unwrap_or(Path::new(".")).join(next);
            }
            Ok(m) if !m.is_file() => {
                let via = if target == path {
                    String::new()
                } else {
                    format!(" (the target of the link {})", path.display())
                };
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    format!(
                        "{}{via} is {}, not a regular file, so mechkit will not write it (nor replace it); give the path of a file to write",
                        target.display(),
                        file_kind(m.file_type())
                    ),
                ));
            }
            _ => {
                inputs::refuse_read_file(&target)?;
                return Ok(target);
            }
        }
    }
}

/// What a file that is not a regular file is, in words: `a directory`, `a character device`.
fn file_kind(t: fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_fifo() {
            return "a named pipe (FIFO)";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "a special file"
    }
}

/// `NAME.partial` beside `path`: where a file is written before it is renamed into place.
pub fn partial_path(path: &Path) -> PathBuf {
    let mut name = path
        .file_name()
        .map(std::ffi::OsStr::to_os_string)
        .unwrap_or_default();
    name.push(".partial");
    path.with_file_name(name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_round_trips_through_text() {
        let mut t = Table::new([Column::new("t", "s"), Column::unknown("F")]);
        t.push(&[0.0, -1.0]);
        t.push(&[1e-12, f64::MAX]);
        assert_eq!(t.len(), 2);
        assert_eq!(t.column("F"), Some(vec![-1.0, f64::MAX]));
        let text = t.to_csv();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("t,F"));
        for (line, row) in lines.zip(t.rows()) {
            let back: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            assert_eq!(back, row);
        }
        assert_eq!(t.units_json(), "{\"t\": \"s\", \"F\": null}\n");
    }

    #[test]
    fn names_are_escaped_in_the_sidecar() {
        let json = units_json(&[Column::new("a\"b\\c", "1")]);
        assert_eq!(json, "{\"a\\\"b\\\\c\": \"1\"}\n");
        assert_eq!(units_file_name("trajectory.csv"), "trajectory.units.json");
        assert_eq!(units_file_name("sweep"), "sweep.units.json");
    }

    #[test]
    fn writes_both_files_and_refuses_a_directory() {
        let dir = tempfile::tempdir().unwrap();
        let mut t = Table::new([Column::new("x", "m")]);
        t.push(&[2.0]);
        let path = t.write(dir.path(), "pos").unwrap();
        assert_eq!(fs::read_to_string(path).unwrap(), "x\n2\n");
        assert_eq!(
            fs::read_to_string(dir.path().join("pos.units.json")).unwrap(),
            "{\"x\": \"m\"}\n"
        );
        fs::create_dir(dir.path().join("d.csv")).unwrap();
        let err = write_atomic(&dir.path().join("d.csv"), b"x").unwrap_err();
        assert!(err.to_string().contains("not a regular file"), "{err}");
        assert!(!dir.path().join("d.csv.partial").exists());
    }

    #[cfg(unix)]
    #[test]
    fn a_symbolic_link_is_written_through() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("real.csv");
        fs::write(&target, "old").unwrap();
        let link = dir.path().join("link.csv");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(
            fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(fs::read_to_string(&target).unwrap(), "new");
    }
}
