//! An output never replaces an input: a command that reads files and writes one refuses a
//! target that is one of the files it reads, however the path is spelled (`./a.csv`,
//! `dir/../a.csv`, a symbolic link to it, a hard link).

use std::fs;
use std::io;
use std::path::Path;

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
                "{} is the input {}: writing it would replace what is being read; give another output path",
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
