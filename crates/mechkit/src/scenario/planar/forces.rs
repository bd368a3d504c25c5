//! Forces applied at body points: a `[[force]]` with `at = "body.point"` on a rigid body of a
//! planar mechanism.

use toml::de::DeValue;

use super::joints::Names;
use crate::rigid::planar::Anchor;
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::forces::{ForceContext, build_force};

/// A `[[force]]`, applied at a body point when it has `at = "body.point"` (then it acts on
/// that rigid body alone, and its torque about the centre of mass turns the body).
pub(super) fn force_at(
    t: &Table<'_, '_>,
    fctx: &ForceContext<'_>,
    index: usize,
    names: &Names<'_>,
    n_bodies: usize,
) -> Result<Box<dyn crate::forces::Force>, ScenarioError> {
    let Some(at) = t.get("at") else {
        return build_force(t, fctx, index);
    };
    let src = t.src;
    let DeValue::String(text) = at.get_ref() else {
        return Err(t.wrong_type("at", at, "a body point, such as \"ladder.top\""));
    };
    let anchor = names
        .anchor(text)
        .map_err(|m| src.error(ErrorKind::Invalid, m, at.span()))?;
    let Anchor::Body { body, r } = anchor else {
        return Err(src.error(ErrorKind::Invalid, "`at` is a point of a body", at.span()));
    };
    let Some(k) = body.checked_sub(names.n_particles) else {
        return Err(src
            .error(
                ErrorKind::Invalid,
                format!("`{text}` is a particle: a force on it acts at its centre"),
                at.span(),
            )
            .with_hint("leave out `at`, or apply the force to a [[rigid_body]]'s point"));
    };
    let body_name = names.bodies[body].clone();
    if let Some((on, span)) = t.string("on")?
        && on != body_name
    {
        return Err(src
            .error(
                ErrorKind::Invalid,
                format!("`on = \"{on}\"` but `at` is a point of `{body_name}`"),
                span,
            )
            .with_hint("a force applied at a point acts on that point's body: leave out `on`"));
    }
    let mut entries = t.entries.clone();
    entries.remove("at");
    if t.get("on").is_none() {
        entries.insert(
            toml::Spanned::new(at.span(), std::borrow::Cow::Borrowed("on")),
            toml::Spanned::new(
                at.span(),
                DeValue::String(std::borrow::Cow::Owned(body_name)),
            ),
        );
    }
    let filtered = Table::new(src, &entries, t.span.clone(), t.what.clone());
    let inner = build_force(&filtered, fctx, index)?;
    let angle = 2 * n_bodies + k;
    Ok(Box::new(crate::rigid::planar::AppliedAt::new(
        inner, body, angle, r,
    )))
}
