//! The files a scenario names (`body = "part.toml"` of a rigid body, `file = "mesh.obj"` of a
//! part, and the mesh files of those body files), checked before the library reads them: each
//! must lie in the workspace, or the scenario is refused with an error at that string.

use std::ops::Range;
use std::path::Path;

use mechkit::scenario::{ErrorKind, Location, MAX_SCENARIO_BYTES, ScenarioError};
use toml::de::{DeTable, DeValue};

use super::workspace::Workspace;

/// The keys whose string values name files, relative to the file they are written in.
const FILE_KEYS: [&str; 2] = ["body", "file"];

/// An error at the first file that `text` (the scenario `name` in directory `dir`) or a body
/// file it names refers to outside `workspace`; `None` when all are inside (or `text` is not
/// TOML: the library reports that without reading any file).
pub fn outside(name: &str, text: &str, dir: &Path, workspace: &Workspace) -> Option<ScenarioError> {
    for (file, span) in references(text) {
        let path = dir.join(&file);
        let nested = if workspace.contains(&path) {
            nested_outside(&path, workspace)
        } else {
            Some(file.clone())
        };
        if let Some(bad) = nested {
            let through = if bad == file {
                String::new()
            } else {
                format!(" (through `{file}`)")
            };
            return Some(at(
                name,
                text,
                span,
                format!("`{bad}`{through} is outside the workspace: the app reads no file there"),
            ));
        }
    }
    None
}

/// The first file a body file names outside the workspace, if any.
fn nested_outside(path: &Path, workspace: &Workspace) -> Option<String> {
    let meta = std::fs::metadata(path).ok()?;
    if !meta.is_file() || meta.len() > MAX_SCENARIO_BYTES {
        return None;
    }
    let text = mechkit::csv::read_bounded_text(path, MAX_SCENARIO_BYTES).ok()?;
    let dir = path.parent()?;
    references(&text)
        .into_iter()
        .map(|(file, _)| file)
        .find(|file| !workspace.contains(&dir.join(file)))
}

/// The strings of `FILE_KEYS` anywhere in the TOML text, with their spans.
fn references(text: &str) -> Vec<(String, Range<usize>)> {
    let Ok(doc) = DeTable::parse(text) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (key, value) in doc.get_ref() {
        walk(key.get_ref(), value.get_ref(), value.span(), &mut out);
    }
    out
}

fn walk(key: &str, value: &DeValue<'_>, span: Range<usize>, out: &mut Vec<(String, Range<usize>)>) {
    match value {
        DeValue::String(s) if FILE_KEYS.contains(&key) => out.push((s.to_string(), span)),
        DeValue::Table(t) => {
            for (k, v) in t {
                walk(k.get_ref(), v.get_ref(), v.span(), out);
            }
        }
        DeValue::Array(items) => {
            for item in items {
                walk(key, item.get_ref(), item.span(), out);
            }
        }
        _ => {}
    }
}

/// An error located at `span` of `text`, as the library locates its own.
fn at(name: &str, text: &str, span: Range<usize>, message: String) -> ScenarioError {
    let start = span.start.min(text.len());
    let before = text.get(..start).unwrap_or("");
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let line_text = text[line_start..].lines().next().unwrap_or("").to_string();
    let column = text
        .get(line_start..start)
        .map_or(1, |s| s.chars().count() + 1);
    let width = text
        .get(start..span.end.min(text.len()))
        .map_or(1, |s| s.chars().count().max(1));
    let mut e = ScenarioError::new(ErrorKind::Invalid, message).with_hint(
        "name files inside the workspace, relative to the scenario (`mechkit run` reads any)",
    );
    e.location = Some(Box::new(Location {
        file: name.to_string(),
        line,
        column,
        line_text,
        width,
    }));
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn body_and_mesh_files_are_found_with_their_place() {
        let text = "title = 'x'\n[[rigid_body]]\nname = 'a'\nbody  = '../b.toml'\n[[rigid_body.part]]\nfile = \"/etc/passwd\"\n";
        let refs = references(text);
        let files: Vec<&str> = refs.iter().map(|(f, _)| f.as_str()).collect();
        assert_eq!(files, ["../b.toml", "/etc/passwd"]);
        let e = at("s.toml", text, refs[0].1.clone(), "m".into());
        let loc = e.location.unwrap();
        assert_eq!((loc.line, loc.column), (4, 9));
        assert_eq!(loc.line_text, "body  = '../b.toml'");
    }
}
