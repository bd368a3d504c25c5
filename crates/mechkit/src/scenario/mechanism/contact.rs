//! The surface and the friction of a `contact` joint: `surface = { point, normal | angle, on }`,
//! `mu` or `mu_s` and `mu_k`, `rolling`.

use std::ops::Range;

use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::joints::{Names, key_or};
use crate::Real;
use crate::rigid::mechanism::Friction;
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
/// inclination; the normal is the direction turned a quarter turn counter-clockwise); in space
/// `{ point = [x, y, z], normal = [nx, ny, nz] }`, a plane. The default is the floor (`y = 0`
/// in a plane, `z = 0` in space) with its normal up.
pub(super) fn surface(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    kind_span: &Range<usize>,
    dim: usize,
) -> Result<([Real; 3], [Real; 3]), ScenarioError> {
    let up = if dim == 2 {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let Some(s) = t.table("surface")? else {
        return Ok(([0.0; 3], up));
    };
    s.check_keys(&["point", "normal", "angle", "on"])?;
    if dim == 3
        && let Some(v) = s.get("angle")
    {
        return Err(s
            .src
            .error(
                ErrorKind::Invalid,
                "in space a surface is a plane: give its `normal`, not an `angle`",
                v.span(),
            )
            .with_hint("an incline of angle a rising along x: normal = [\"-sin(a)\", 0, \"cos(a)\"] written out as numbers"));
    }
    let mut point =
        vector(&s, "point", Dimension::LENGTH, dim, env)?.unwrap_or_else(|| vec![0.0; dim]);
    point.resize(3, 0.0);
    let normal = match (
        vector(&s, "normal", Dimension::NONE, dim, env)?,
        scalar(&s, "angle", Dimension::NONE, env)?,
    ) {
        (Some(_), Some(_)) => {
            return Err(s.src.error(
                ErrorKind::Invalid,
                "give the surface's `normal` or its `angle`, not both",
                s.key_span("angle"),
            ));
        }
        (Some(mut n), None) => {
            n.resize(3, 0.0);
            n
        }
        (None, Some(a)) => vec![-a.sin(), a.cos(), 0.0],
        (None, None) => up.to_vec(),
    };
    let len = normal.iter().map(|x| x * x).sum::<Real>().sqrt();
    if !(len > 0.0 && len.is_finite()) {
        return Err(s
            .src
            .error(
                ErrorKind::Invalid,
                "the surface's `normal` must not be zero",
                key_or(&s, "normal", kind_span),
            )
            .with_hint(
                "the direction away from the surface, towards the body: [0, 1] for a floor ([0, 0, 1] in space)",
            ));
    }
    Ok((
        [point[0], point[1], point[2]],
        [normal[0] / len, normal[1] / len, normal[2] / len],
    ))
}

/// `mu` (both), or `mu_s` and `mu_k`; `rolling = true` for a contact that never slides.
pub(super) fn friction(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    new_mode: &mut impl FnMut(&str) -> usize,
    dim: usize,
) -> Result<Friction, ScenarioError> {
    let coefficient = |key: &str| -> Result<Option<Real>, ScenarioError> {
        let mu = scalar(t, key, Dimension::NONE, env)?;
        if let Some(m) = mu
            && !(m >= 0.0 && m.is_finite())
        {
            return Err(t.src.error(
                ErrorKind::Invalid,
                format!(
                    "`{key}` must be zero or positive, not {}",
                    crate::error::short(m)
                ),
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
    if dim == 3 {
        let key = ["mu", "mu_s", "mu_k"]
            .into_iter()
            .find(|k| t.get(k).is_some())
            .unwrap_or("mu");
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                "sliding friction on a plane in space is not supported yet: its direction turns",
                t.key_span(key),
            )
            .with_hint("in space a contact is smooth (no `mu`) or rolls without slipping (`rolling = true`); friction with sticking and sliding works in a plane (`dimensions = 2`)"));
    }
    if mu_k > mu_s {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "`mu_k` = {} is larger than `mu_s` = {}",
                    crate::error::short(mu_k),
                    crate::error::short(mu_s)
                ),
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
