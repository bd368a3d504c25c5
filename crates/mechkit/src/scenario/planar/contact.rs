//! The surface and the friction of a `contact` joint: `surface = { point, normal | angle, on }`,
//! `mu` or `mu_s` and `mu_k`, `rolling`.

use std::ops::Range;

use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::joints::{Names, key_or};
use crate::Real;
use crate::rigid::planar::Friction;
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{ValueEnv, scalar, vector};

/// `surface.on`: the particle whose surface it is (its `point` is then from that particle's
/// position), or none for a fixed surface.
pub(super) fn surface_body(
    t: &Table<'_, '_>,
    ctx: &Names<'_>,
) -> Result<Option<usize>, ScenarioError> {
    let Some(s) = t.table("surface")? else {
        return Ok(None);
    };
    let Some((name, span)) = s.string("on")? else {
        return Ok(None);
    };
    match ctx.bodies.iter().position(|b| b == name) {
        Some(b) if b < ctx.n_particles => Ok(Some(b)),
        Some(_) => Err(s
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "`{name}` is a rigid body: a surface on a turning body is not supported yet"
                ),
                span,
            )
            .with_hint(
                "carry the surface on a [[body]] (a cart, a block: it moves without turning)",
            )),
        None => Err(s
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "`{name}` is not a body; the bodies are: {}",
                    ctx.bodies.join(", ")
                ),
                span,
            )
            .with_hint("`on` names the [[body]] that carries the surface")),
    }
}

/// `surface = { point = [x, y], normal = [nx, ny] }` or `{ point, angle }` (the line's
/// inclination; the normal is the direction turned a quarter turn counter-clockwise). The
/// default is the floor `y = 0` with its normal up.
pub(super) fn surface(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    kind_span: &Range<usize>,
) -> Result<([Real; 2], [Real; 2]), ScenarioError> {
    let Some(s) = t.table("surface")? else {
        return Ok(([0.0; 2], [0.0, 1.0]));
    };
    s.check_keys(&["point", "normal", "angle", "on"])?;
    let point = vector(&s, "point", Dimension::LENGTH, 2, env)?.unwrap_or_else(|| vec![0.0; 2]);
    let normal = match (
        vector(&s, "normal", Dimension::NONE, 2, env)?,
        scalar(&s, "angle", Dimension::NONE, env)?,
    ) {
        (Some(_), Some(_)) => {
            return Err(s.src.error(
                ErrorKind::Invalid,
                "give the surface's `normal` or its `angle`, not both",
                s.key_span("angle"),
            ));
        }
        (Some(n), None) => n,
        (None, Some(a)) => vec![-a.sin(), a.cos()],
        (None, None) => vec![0.0, 1.0],
    };
    let len = normal[0].hypot(normal[1]);
    if !(len > 0.0 && len.is_finite()) {
        return Err(s
            .src
            .error(
                ErrorKind::Invalid,
                "the surface's `normal` must not be zero",
                key_or(&s, "normal", kind_span),
            )
            .with_hint(
                "the direction away from the surface, towards the body: [0, 1] for a floor",
            ));
    }
    Ok(([point[0], point[1]], [normal[0] / len, normal[1] / len]))
}

/// `mu` (both), or `mu_s` and `mu_k`; `rolling = true` for a contact that never slides.
pub(super) fn friction(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    new_mode: &mut impl FnMut(&str) -> usize,
) -> Result<Friction, ScenarioError> {
    let coefficient = |key: &str| -> Result<Option<Real>, ScenarioError> {
        let mu = scalar(t, key, Dimension::NONE, env)?;
        if let Some(m) = mu
            && !(m >= 0.0 && m.is_finite())
        {
            return Err(t.src.error(
                ErrorKind::Invalid,
                format!("`{key}` must be zero or positive, not {m}"),
                t.key_span(key),
            ));
        }
        Ok(mu)
    };
    let rolling = match t.get("rolling") {
        None => false,
        Some(v) => match v.get_ref() {
            DeValue::Boolean(b) => *b,
            _ => return Err(t.wrong_type("rolling", v, "true or false")),
        },
    };
    let (mu, mu_s, mu_k) = (
        coefficient("mu")?,
        coefficient("mu_s")?,
        coefficient("mu_k")?,
    );
    if rolling {
        if let Some(key) = ["mu", "mu_s", "mu_k"]
            .into_iter()
            .find(|k| t.get(k).is_some())
        {
            return Err(t.src.error(ErrorKind::Invalid, format!("`rolling = true` never slides, so `{key}` would not be used"), t.key_span(key)).with_hint("for rolling that may turn into sliding give `mu_s` and `mu_k` without `rolling`"));
        }
        return Ok(Friction::NoSlip);
    }
    let (mu_s, mu_k) = match (mu, mu_s, mu_k) {
        (None, None, None) => return Ok(Friction::None),
        (Some(m), None, None) => (m, m),
        (None, Some(s), Some(k)) => (s, k),
        (None, Some(s), None) => (s, s),
        (None, None, Some(k)) => (k, k),
        (Some(_), _, _) => {
            return Err(t.src.error(
                ErrorKind::Invalid,
                "`mu` sets both coefficients: give `mu`, or `mu_s` and `mu_k`",
                t.key_span("mu"),
            ));
        }
    };
    if mu_k > mu_s {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!("`mu_k` = {mu_k} is larger than `mu_s` = {mu_s}"),
                t.key_span("mu_k"),
            )
            .with_hint("kinetic friction is at most static friction: swap them?"));
    }
    Ok(Friction::Coulomb {
        mu_s,
        mu_k,
        mode: new_mode("sliding"),
    })
}
