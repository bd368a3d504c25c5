//! An output never replaces an input: a command that reads files and writes one refuses a
//! target that is one of the files it reads, however the path is spelled (`./a.csv`,
//! `dir/../a.csv`, a symbolic link to it, a hard link).

use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The files read while an [`InputGuard`] is held, or `None` when none is: how many guards
/// are held, and the paths read.
static READ: Mutex<Option<(usize, Vec<PathBuf>)>> = Mutex::new(None);

/// While held, every input file the library reads (scenarios, their data files and meshes,
/// data tables, images, atom files) is noted, and [`writable_target`](super::writable_target)
/// (through which every output goes) refuses to write over one of them, however spelled: a
/// command's fixed output names (`-o DIR` holding `work.csv`, `trajectory.csv`) can never
/// replace the file it read. A front that runs one command per process (the CLI) holds one
/// for the command; a session that reads a file and later means to rewrite it (a notebook)
/// holds none. Guards nest; the notes are dropped with the last one.
#[must_use = "inputs are guarded only while the guard is held"]
pub struct InputGuard(());

impl InputGuard {
    /// Starts noting the files read (see [`InputGuard`]).
    pub fn hold() -> Self {
        let mut read = READ
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        match read.as_mut() {
            Some((held, _)) => *held += 1,
            None => *read = Some((1, Vec::new())),
        }
        Self(())
    }
}

impl Drop for InputGuard {
    fn drop(&mut self) {
        let mut read = READ
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some((held, _)) = read.as_mut() {
            *held -= 1;
            if *held == 0 {
                *read = None;
            }
        }
    }
}

/// Notes `path` as read, while an [`InputGuard`] is held (else does nothing).
pub fn note_read(path: &Path) {
    let mut read = READ
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    if let Some((_, paths)) = read.as_mut()
        && !paths.iter().any(|p| same_file(p, path))
    {
        paths.push(path.to_path_buf());
    }
}

/// Refuses `output` when it is a file noted as read under an [`InputGuard`].
pub(super) fn refuse_read_file(output: &Path) -> io::Result<()> {
    let read = READ
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    match read.as_ref() {
        Some((_, paths)) => {
            let paths: Vec<&Path> = paths.iter().map(PathBuf::as_path).collect();
            refuse_input_as_output(output, &paths)
        }
        None => Ok(()),
    }
}

/// Whether `a` and `b` name the same existing file (the same device and inode on Unix, the
/// same canonical path elsewhere); `false` when either does not exist.
pub fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (fs::metadata(a), fs::metadata(b)) {
            (Ok(x), Ok(y)) => x.dev() == y.dev() && x.ino() == y.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        match (fs::canonicalize(a), fs::canonicalize(b)) {
            (Ok(x), Ok(y)) => x == y,
            _ => false,
        }
    }
}

/// Refuses to write `output` when it is one of `inputs` (see [`same_file`]).
///
/// # Errors
/// [`io::ErrorKind::InvalidInput`], naming both spellings, when it is.
///
/// ```
/// # let dir = std::env::temp_dir().join(format!("mechkit-doc-inputs-{}", std::process::id()));
/// # std::fs::create_dir_all(&dir).unwrap();
/// let part = dir.join("part1.csv");
/// std::fs::write(&part, "i\n0\n").unwrap();
/// let spelled = dir.join(".").join("part1.csv");
/// assert!(mechkit::csv::refuse_input_as_output(&spelled, &[part.as_path()]).is_err());
/// assert!(mechkit::csv::refuse_input_as_output(&dir.join("all.csv"), &[part.as_path()]).is_ok());
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn refuse_input_as_output(output: &Path, inputs: &[&Path]) -> io::Result<()> {
    match inputs.iter().find(|i| same_file(output, i)) {
        Some(input) => Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!(
                "{} is the input {}: writing it would replace what is being read; give another output path (or `-o` directory)",
                output.display(),
                input.display()
            ),
        )),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_input_reached_through_a_link_or_another_spelling_is_the_same_file() {
        let dir = std::env::temp_dir().join(format!("mechkit-same-file-{}", std::process::id()));
        fs::create_dir_all(dir.join("sub")).unwrap();
        let part = dir.join("part.csv");
        fs::write(&part, "x\n1\n").unwrap();
        assert!(same_file(
            &part,
            &dir.join("sub").join("..").join("part.csv")
        ));
        #[cfg(unix)]
        {
            let link = dir.join("link.csv");
            let _ = fs::remove_file(&link);
            std::os::unix::fs::symlink(&part, &link).unwrap();
            assert!(same_file(&link, &part));
            assert!(refuse_input_as_output(&link, &[part.as_path()]).is_err());
        }
        assert!(!same_file(&part, &dir.join("missing.csv")));
        assert!(refuse_input_as_output(&dir.join("out.csv"), &[part.as_path()]).is_ok());
        fs::remove_dir_all(&dir).unwrap();
    }
}
