//! A joint ties two different things: two bodies, or a body and a fixed point. One naming the
//! same body at both ends (a pulley's string from `m1` to `m1`, a rod between two points of
//! one rigid body, a contact with the body's own surface) holds nothing or over-constrains
//! the body, and is refused at the key that names the body the second time.

use crate::rigid::mechanism::{Anchor, JointKind};
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};

/// The keys of a joint that name what it holds, each with its anchor, in the file's order.
fn ends(kind: &JointKind) -> Vec<(&'static [&'static str], Anchor)> {
    match *kind {
        JointKind::Hinge { a, b, .. }
        | JointKind::Rod { a, b, .. }
        | JointKind::String { a, b, .. } => {
            vec![(&["a"], a), (&["b"], b)]
        }
        JointKind::Contact { on, point, .. } => vec![(&["on"], on), (&["surface"], point)],
        JointKind::Pulley { a, b, centre, .. } => vec![
            (&["a"], a),
            (&["b"], b),
            (&["centre", "center", "wheel"], centre),
        ],
        JointKind::Curve { .. } => Vec::new(),
    }
}

/// Refuses a joint that names one body twice, located at the second naming.
pub(super) fn refuse_one_body_twice(
    t: &Table<'_, '_>,
    name: &str,
    kind: &JointKind,
    bodies: &[String],
) -> Result<(), ScenarioError> {
    let ends = ends(kind);
    for (k, (keys, anchor)) in ends.iter().enumerate() {
        let Anchor::Body { body, .. } = *anchor else {
            continue;
        };
        let Some((first, _)) = ends[..k]
            .iter()
            .find(|(_, a)| matches!(*a, Anchor::Body { body: b, .. } if b == body))
        else {
            continue;
        };
        let key = keys.iter().find(|k| t.get(k).is_some()).unwrap_or(&keys[0]);
        let span = t
            .get(key)
            .map_or_else(|| t.span.clone(), toml::Spanned::span);
        let body = bodies.get(body).map_or("?", String::as_str);
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "the joint `{name}` names the body `{body}` at both `{}` and `{key}`: a joint ties two different bodies, or a body to a fixed point",
                    first[0]
                ),
                span,
            )
            .with_hint(format!(
                "name the other body in `{key}` (or a fixed point); a body's own points move together and need no joint"
            )));
    }
    Ok(())
}
