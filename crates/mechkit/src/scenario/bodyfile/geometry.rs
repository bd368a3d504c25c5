//! The geometric values of a body file: points and lists of points with units, directions,
//! and triangle meshes (inline or from an OBJ file).

use std::path::Path;

use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::invalid;
use crate::mass::{TriangleMesh, Vec3};
use crate::scenario::doc::{Table, Value, type_name};
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{ValueEnv, resolve, resolve_any};

/// A list of points `[[x, y(, z)], …]` (or one point `[x, y(, z)]`), lengths, padded with
/// zeros to 3-D.
pub(crate) fn points(
    t: &Table<'_, '_>,
    key: &str,
    env: ValueEnv<'_>,
    min: usize,
    max: usize,
) -> Result<Vec<Vec3>, ScenarioError> {
    let v = t.get(key).ok_or_else(|| t.missing(key, "[0, 0, 0]"))?;
    let src = &t.src;
    let one = |item: &Value<'_>| -> Result<Vec3, ScenarioError> {
        let comps: Vec<&Value<'_>> = match item.get_ref() {
            DeValue::Array(c) => c.iter().collect(),
            DeValue::Integer(_) | DeValue::Float(_) | DeValue::String(_) if min == 1 => {
                vec![item]
            }
            other => {
                return Err(src.error(
                    ErrorKind::WrongType,
                    format!(
                        "`{key}` must hold points like [\"1 cm\", 0], not {}",
                        type_name(other)
                    ),
                    item.span(),
                ));
            }
        };
        if !(min..=max).contains(&comps.len()) {
            return Err(src.error(
                ErrorKind::Invalid,
                format!(
                    "a point of `{key}` has {} coordinates; it needs {}",
                    comps.len(),
                    if min == max {
                        min.to_string()
                    } else {
                        format!("{min} to {max}")
                    }
                ),
                item.span(),
            ));
        }
        let mut p = Vec3::zeros();
        for (k, c) in comps.iter().enumerate() {
            p[k] = resolve(src, key, c, Dimension::LENGTH, env)?;
        }
        Ok(p)
    };
    match v.get_ref() {
        DeValue::Array(items)
            if items
                .iter()
                .all(|i| matches!(i.get_ref(), DeValue::Array(_)))
                && !items.is_empty() =>
        {
            items.iter().map(one).collect()
        }
        _ => Ok(vec![one(v)?]),
    }
}

pub(crate) fn direction(
    t: &Table<'_, '_>,
    key: &str,
    env: ValueEnv<'_>,
) -> Result<Vec3, ScenarioError> {
    let v = t.get(key).ok_or_else(|| t.missing(key, "[0, 0, 1]"))?;
    let DeValue::Array(items) = v.get_ref() else {
        return Err(t.wrong_type(key, v, "a direction like [0, 0, 1]"));
    };
    if !(2..=3).contains(&items.len()) {
        return Err(invalid(t, key, format!("`{key}` needs 2 or 3 components")));
    }
    let mut d = Vec3::zeros();
    for (k, c) in items.iter().enumerate() {
        d[k] = resolve_any(&t.src, key, c, env)?.0;
    }
    if d.norm() == 0.0 {
        return Err(invalid(t, key, format!("`{key}` has no length")));
    }
    Ok(d)
}

pub(super) fn mesh(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    dir: Option<&Path>,
) -> Result<TriangleMesh, ScenarioError> {
    if let Some((file, span)) = t.string("file")? {
        let path = dir.map_or_else(|| Path::new(file).to_path_buf(), |d| d.join(file));
        let text =
            crate::csv::read_bounded_text(&path, crate::csv::MAX_DATA_BYTES).map_err(|e| {
                t.src.error(
                    ErrorKind::Io,
                    format!("cannot read the mesh {}: {e}", path.display()),
                    span.clone(),
                )
            })?;
        return TriangleMesh::from_obj(&text).map_err(|e| {
            t.src
                .error(ErrorKind::Invalid, format!("{}: {e}", path.display()), span)
        });
    }
    let vertices = points(t, "vertices", env, 3, 3)?;
    let f = t
        .get("faces")
        .ok_or_else(|| t.missing("faces", "[[1, 2, 3], …] (1-based)"))?;
    let bad = || {
        t.wrong_type(
            "faces",
            f,
            "a list of vertex triples like [[1, 2, 3], [1, 3, 4]] (1-based)",
        )
    };
    let DeValue::Array(items) = f.get_ref() else {
        return Err(bad());
    };
    let mut faces = Vec::new();
    for item in items {
        let DeValue::Array(idx) = item.get_ref() else {
            return Err(bad());
        };
        let mut face = [0usize; 3];
        if idx.len() != 3 {
            return Err(t.src.error(
                ErrorKind::Invalid,
                "a face has 3 vertex numbers",
                item.span(),
            ));
        }
        for (k, i) in idx.iter().enumerate() {
            face[k] = match i.get_ref() {
                DeValue::Integer(n) => {
                    n.as_str()
                        .parse::<usize>()
                        .ok()
                        .filter(|n| *n >= 1)
                        .ok_or_else(|| {
                            t.src
                                .error(ErrorKind::Invalid, "vertex numbers start at 1", i.span())
                        })?
                        - 1
                }
                _ => return Err(bad()),
            };
        }
        faces.push(face);
    }
    TriangleMesh::new(vertices, faces).map_err(|e| invalid(t, "faces", e.to_string()))
}
