//! The named points of a rigid body: reading `points = { top = [...] }` and finding
//! `"body.point"`.

use mechkit_expr::units::Dimension;

use crate::Real;
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{ValueEnv, vector};

/// A named point: its name and its offset from the centre of mass in the body frame (`z` 0
/// in a plane).
pub(crate) type NamedPoint = (String, [Real; 3]);

/// Reads the `points` of the rigid body `name` (`dim` components each, measured from `origin`,
/// which is subtracted: the centre of mass in the frame the points are given in); a point
/// cannot take the name of one of `fields` (`x`, `theta`, …).
pub(super) fn read_points(
    t: &Table<'_, '_>,
    name: &str,
    env: ValueEnv<'_>,
    dim: usize,
    origin: [Real; 3],
    fields: &[&str],
) -> Result<Vec<NamedPoint>, ScenarioError> {
    let mut points = Vec::new();
    let Some(p) = t.table("points")? else {
        return Ok(points);
    };
    for (key, _) in p.entries {
        let point: &str = key.get_ref();
        let valid = point
            .chars()
            .next()
            .is_some_and(|c| c.is_alphabetic() || c == '_')
            && point.chars().all(|c| c.is_alphanumeric() || c == '_');
        if !valid || fields.contains(&point) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("`{point}` cannot name a point: formulas would read `{name}.{point}` as something else"),
                    key.span(),
                )
                .with_hint(format!(
                    "a letter or `_` then letters, digits or `_`, not a field name such as {} or {}",
                    fields[0],
                    fields[fields.len() - 1]
                )));
        }
        let r = vector(&p, point, Dimension::LENGTH, dim, env)?.unwrap_or_default();
        let mut offset = [0.0; 3];
        for (k, o) in offset.iter_mut().enumerate().take(dim) {
            *o = r[k] - origin[k];
        }
        points.push((point.to_string(), offset));
    }
    Ok(points)
}

/// The offset of point `point` of the rigid body `body`, whose points are `points`; `Err` says
/// which points it has.
pub(crate) fn find_point(
    points: &[NamedPoint],
    body: &str,
    point: &str,
) -> Result<[Real; 3], String> {
    points
        .iter()
        .find(|(n, _)| n == point)
        .map(|(_, r)| *r)
        .ok_or_else(|| {
            let known: Vec<&str> = points.iter().map(|(n, _)| n.as_str()).collect();
            format!(
                "`{body}` has no point `{point}`; its points are: {} (add it under `points`)",
                if known.is_empty() {
                    "none".to_string()
                } else {
                    known.join(", ")
                }
            )
        })
}
