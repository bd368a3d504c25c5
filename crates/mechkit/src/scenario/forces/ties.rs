//! Forces that tie bodies to each other or to a fixed point: Newtonian gravity (a fixed
//! attracting mass, or mutual) and springs (to an anchor, or between two bodies).

use mechkit_expr::units::Dimension;

use super::ForceContext;
use crate::forces::{Force, NewtonianGravity, Spring, SpringEnds};
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{required_scalar, scalar, vector};

pub(super) fn newtonian(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    name: String,
    targets: Vec<usize>,
) -> Result<Box<dyn Force>, ScenarioError> {
    let env = ctx.env(None);
    let g = scalar(t, "G", Dimension::GRAVITATIONAL_CONSTANT, env)?;
    if let Some(between) = ctx.body_list(t, "between")? {
        for key in ["on", "GM", "M", "center"] {
            if t.get(key).is_some() {
                return Err(t
                    .src
                    .error(ErrorKind::Invalid, format!("`{key}` does not go with `between`"), t.key_span(key))
                    .with_hint("`between` makes the listed bodies attract each other; `GM`/`M` and `center` describe a fixed attracting mass"));
            }
        }
        if between.len() < 2 {
            return Err(t.src.error(
                ErrorKind::Invalid,
                "`between` needs at least two bodies",
                t.key_span("between"),
            ));
        }
        return Ok(Box::new(NewtonianGravity::mutual(
            name,
            between,
            g.unwrap_or(NewtonianGravity::G),
        )));
    }
    let gm = match (
        scalar(t, "GM", Dimension::GRAVITATIONAL_PARAMETER, env)?,
        scalar(t, "M", Dimension::MASS, env)?,
    ) {
        (Some(gm), None) => gm,
        (None, Some(m)) => g.unwrap_or(NewtonianGravity::G) * m,
        (Some(_), Some(_)) => {
            return Err(t.src.error(
                ErrorKind::Invalid,
                "give either `GM` or `M`, not both",
                t.key_span("M"),
            ));
        }
        (None, None) => {
            return Err(t
                .missing("GM", "\"3.986e14 m^3/s^2\"")
                .with_hint("give the attracting mass as `GM` (m^3/s^2) or `M` (kg, with G defaulting to 6.6743e-11), or write `between = [\"a\", \"b\"]` for mutual attraction"));
        }
    };
    let center =
        vector(t, "center", Dimension::LENGTH, ctx.dim, env)?.unwrap_or_else(|| vec![0.0; ctx.dim]);
    Ok(Box::new(NewtonianGravity::fixed_centre(
        name, targets, gm, center,
    )))
}

pub(super) fn spring(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    name: String,
    on_given: bool,
    targets: Vec<usize>,
) -> Result<Box<dyn Force>, ScenarioError> {
    let env = ctx.env(None);
    let k = required_scalar(t, "k", Dimension::STIFFNESS, env)?;
    if k.is_nan() || k < 0.0 {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "the spring constant `k` must not be negative (it is {} N/m)",
                    crate::expr::short_number(k)
                ),
                t.key_span("k"),
            )
            .with_hint("a spring pulls its ends back towards `rest_length` with k > 0; a force that pushes away is a `kind = \"expression\"` force"));
    }
    let rest = scalar(t, "rest_length", Dimension::LENGTH, env)?.unwrap_or(0.0);
    if rest < 0.0 {
        return Err(t.src.error(
            ErrorKind::Invalid,
            format!(
                "`rest_length` must not be negative (it is {} m)",
                crate::error::short(rest)
            ),
            t.key_span("rest_length"),
        ));
    }
    let ends = if let Some(between) = ctx.body_list(t, "between")? {
        if on_given || t.get("anchor").is_some() {
            let key = if on_given { "on" } else { "anchor" };
            return Err(t
                .src
                .error(ErrorKind::Invalid, format!("`{key}` does not go with `between`"), t.key_span(key))
                .with_hint("a spring either ties bodies to a fixed `anchor` (with `on`) or joins two bodies (`between`)"));
        }
        match between.as_slice() {
            [a, b] => SpringEnds::Pair(*a, *b),
            _ => {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        format!(
                            "a spring joins exactly two bodies, `between` lists {}",
                            between.len()
                        ),
                        t.key_span("between"),
                    )
                    .with_hint("add one [[force]] per spring"));
            }
        }
    } else {
        let anchor = vector(t, "anchor", Dimension::LENGTH, ctx.dim, env)?
            .unwrap_or_else(|| vec![0.0; ctx.dim]);
        SpringEnds::Anchor {
            bodies: targets,
            anchor,
        }
    };
    Ok(Box::new(Spring::new(name, k, rest, ends)))
}
