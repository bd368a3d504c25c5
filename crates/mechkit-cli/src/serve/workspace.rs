//! The workspace: the one directory whose files the app may read. A path from a request is
//! relative, without `..` or a root, and what it names, its symlinks resolved, must lie in
//! the canonical workspace.

use std::path::{Component, Path, PathBuf};

use anyhow::{Context as _, Result, bail};
use serde::Serialize;

use super::error::ApiError;

/// The most scenario files listed (the list is for browsing, not for a whole disk).
pub const MAX_LISTED: usize = 500;

/// How deep the listing goes below the workspace.
const MAX_DEPTH: usize = 8;

/// A directory whose files may be read.
#[derive(Debug, Clone)]
pub struct Workspace {
    root: PathBuf,
}

/// A scenario file of the workspace, as `/api/files` lists it.
#[derive(Debug, Clone, Serialize)]
pub struct Listed {
    /// Its path relative to the workspace, with `/` between the parts.
    pub path: String,
    /// Its size in bytes.
    pub bytes: u64,
}

impl Workspace {
    /// The workspace at `dir`, which must be a directory.
    pub fn open(dir: &Path) -> Result<Self> {
        let root = dir
            .canonicalize()
            .with_context(|| format!("--dir {}: cannot open the workspace", dir.display()))?;
        if !root.is_dir() {
            bail!("--dir {}: the workspace must be a directory", dir.display());
        }
        Ok(Self { root })
    }

    /// Its canonical path.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// `rel` as a path under the workspace, checked by its text alone: relative, no `..`, no
    /// root or drive, no NUL (403 otherwise). The file need not exist.
    pub fn join(&self, rel: &str) -> Result<PathBuf, ApiError> {
        let refuse = |why: &str| {
            Err(ApiError::forbidden(format!(
                "`{rel}` is not a path inside the workspace: {why}"
            )))
        };
        if rel.trim().is_empty() {
            return refuse("it is empty");
        }
        if rel.contains('\0') {
            return refuse("it holds a NUL character");
        }
        let path = Path::new(rel);
        for c in path.components() {
            match c {
                Component::Normal(_) | Component::CurDir => {}
                Component::ParentDir => return refuse("`..` leaves it"),
                Component::RootDir | Component::Prefix(_) => {
                    return refuse("give it relative to the workspace");
                }
            }
        }
        let joined = self.root.join(path);
        if !self.contains(&joined) {
            return refuse("a symbolic link leads out of it");
        }
        Ok(joined)
    }

    /// The regular file `rel` of the workspace (403 outside it, 404 if there is none).
    pub fn file(&self, rel: &str) -> Result<PathBuf, ApiError> {
        let path = self.join(rel)?;
        match std::fs::metadata(&path) {
            Ok(meta) if meta.is_file() => Ok(path),
            Ok(_) => Err(ApiError::not_found(format!("`{rel}` is not a file"))),
            Err(_) => Err(ApiError::not_found(format!(
                "no file `{rel}` in the workspace"
            ))),
        }
    }

    /// Whether `path` (absolute) lies in the workspace once its symbolic links are followed:
    /// each existing prefix is resolved by the operating system, the rest (which does not
    /// exist yet) by its text. A dangling link is outside.
    pub fn contains(&self, path: &Path) -> bool {
        let mut at = PathBuf::new();
        for c in path.components() {
            match c {
                Component::ParentDir => {
                    at.pop();
                }
                Component::CurDir => {}
                other => {
                    at.push(other);
                    match std::fs::symlink_metadata(&at) {
                        Ok(meta) if meta.file_type().is_symlink() => match at.canonicalize() {
                            Ok(real) => at = real,
                            Err(_) => return false,
                        },
                        Ok(_) | Err(_) => {}
                    }
                }
            }
        }
        path.is_absolute() && at.starts_with(&self.root)
    }

    /// The scenario files (`*.toml`) under the workspace, sorted by path: at most
    /// [`MAX_LISTED`], at most [`MAX_DEPTH`] folders down, symbolic links and hidden
    /// folders skipped (`.git`), and `target` and `node_modules` (build outputs) too.
    pub fn scenario_files(&self) -> Vec<Listed> {
        let mut out = Vec::new();
        walk(&self.root, "", 0, &mut out);
        out.sort_by(|a, b| a.path.cmp(&b.path));
        out
    }
}

fn walk(dir: &Path, prefix: &str, depth: usize, out: &mut Vec<Listed>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.flatten().collect();
    entries.sort_by_key(std::fs::DirEntry::file_name);
    for entry in entries {
        if out.len() >= MAX_LISTED {
            return;
        }
        let name = entry.file_name().to_string_lossy().into_owned();
        // the entry's own type: a symbolic link is not followed
        let Ok(kind) = entry.file_type() else {
            continue;
        };
        let rel = format!("{prefix}{name}");
        if kind.is_dir() {
            if depth < MAX_DEPTH
                && !name.starts_with('.')
                && name != "target"
                && name != "node_modules"
            {
                walk(&entry.path(), &format!("{rel}/"), depth + 1, out);
            }
        } else if kind.is_file()
            && Path::new(&name)
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("toml"))
        {
            let bytes = entry.metadata().map_or(0, |m| m.len());
            out.push(Listed { path: rel, bytes });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_stay_inside() {
        let tmp = std::env::temp_dir().join(format!("mechkit-ws-test-{}", std::process::id()));
        std::fs::create_dir_all(tmp.join("ws/sub")).unwrap();
        std::fs::write(tmp.join("ws/sub/a.toml"), "title = 'a'").unwrap();
        std::fs::write(tmp.join("secret.toml"), "x").unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink(tmp.join("secret.toml"), tmp.join("ws/out.toml")).unwrap();
        let ws = Workspace::open(&tmp.join("ws")).unwrap();
        assert!(ws.file("sub/a.toml").is_ok());
        assert!(ws.file("./sub/a.toml").is_ok());
        for bad in [
            "../secret.toml",
            "/etc/passwd",
            "sub/../../secret.toml",
            "",
            "a\0b",
        ] {
            let e = ws.join(bad).unwrap_err();
            assert_eq!(e.status, 403, "{bad}");
        }
        #[cfg(unix)]
        assert_eq!(ws.file("out.toml").unwrap_err().status, 403);
        assert_eq!(ws.file("none.toml").unwrap_err().status, 404);
        assert!(ws.join("new/file.toml").is_ok());
        let listed: Vec<String> = ws.scenario_files().into_iter().map(|l| l.path).collect();
        assert_eq!(listed, ["sub/a.toml"]);
        std::fs::remove_dir_all(&tmp).unwrap();
    }
}
