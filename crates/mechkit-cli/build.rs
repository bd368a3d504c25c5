//! Bundles the course's worked problems (`examples/book`) and the files they read
//! (`examples/data`, `examples/bodies`, `examples/rigid`) into the binary, for
//! `mechkit gallery`: the generated `gallery_bundle.rs` lists every file with its bytes.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

const DIRS: [&str; 4] = ["book", "data", "bodies", "rigid"];

fn main() {
    let examples = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("set by cargo"))
        .join("../../examples");
    let mut files = Vec::new();
    for dir in DIRS {
        let path = examples.join(dir);
        println!("cargo:rerun-if-changed={}", path.display());
        collect(&path, &mut files);
    }
    files.sort();
    let mut code =
        String::from("/// Every bundled file: its path from the repository root, and its bytes.\n");
    code.push_str("pub static FILES: &[(&str, &[u8])] = &[\n");
    for file in &files {
        let name = file
            .strip_prefix(&examples)
            .expect("collected under examples/")
            .to_string_lossy()
            .replace('\\', "/");
        let absolute = file.canonicalize().expect("a listed file exists");
        let _ = writeln!(
            code,
            "    ({:?}, include_bytes!({:?})),",
            format!("examples/{name}"),
            absolute.display().to_string()
        );
    }
    code.push_str("];\n");
    let out =
        PathBuf::from(std::env::var("OUT_DIR").expect("set by cargo")).join("gallery_bundle.rs");
    std::fs::write(&out, code).expect("OUT_DIR is writable");
}

fn collect(dir: &Path, files: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            collect(&path, files);
        } else if path
            .file_name()
            .is_some_and(|n| !n.to_string_lossy().starts_with('.'))
        {
            files.push(path);
        }
    }
}
