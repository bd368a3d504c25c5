//! Forces on rigid bodies: `kind = "torque"` (a torque `T` given by formulas) and any force
//! applied at a body point (`at = "body.point"`), in a plane or in space.

use toml::de::DeValue;

use super::{ForceContext, build_force, compile_n};
use crate::forces::Force;
use crate::particles::RigidName;
use crate::rigid::at::{AppliedAt, Torque, Turn};
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use mechkit_expr::units::Dimension;

fn turn(r: &RigidName) -> Turn {
    if r.spin.is_some() {
        Turn::Quaternion(r.angle)
    } else {
        Turn::Angle(r.angle)
    }
}

fn rigid_list(ctx: &ForceContext<'_>) -> String {
    let names: Vec<&str> = ctx
        .rigid
        .rigid
        .iter()
        .map(|r| ctx.bodies[r.body].as_str())
        .collect();
    if names.is_empty() {
        "the scenario has no [[rigid_body]]".into()
    } else {
        format!("its rigid bodies: {}", names.join(", "))
    }
}

/// Reads a `torque`: on one rigid body (`on`, which may be left out when there is only one),
/// `T` one formula in a plane (the `z` component) or three in space (world components).
pub(super) fn torque(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    name: String,
    on: Option<&[usize]>,
) -> Result<Box<dyn Force>, ScenarioError> {
    let src = t.src;
    let rigid = match on {
        Some([b]) => ctx
            .rigid
            .rigid
            .iter()
            .find(|r| r.body == *b)
            .ok_or_else(|| {
                src.error(
                    ErrorKind::Invalid,
                    format!(
                        "`{}` is not a rigid body: a torque turns a [[rigid_body]]",
                        ctx.bodies[*b]
                    ),
                    t.key_span("on"),
                )
                .with_hint(rigid_list(ctx))
            })?,
        Some(_) => {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    "a torque acts on one rigid body",
                    t.key_span("on"),
                )
                .with_hint("write one [[force]] of kind \"torque\" per body"));
        }
        None => match ctx.rigid.rigid.as_slice() {
            [r] => r,
            _ => {
                return Err(t.missing("on", "\"wheel\"").with_hint(format!(
                    "name the body the torque turns; {}",
                    rigid_list(ctx)
                )));
            }
        },
    };
    let count = if rigid.spin.is_some() { 3 } else { 1 };
    let example = if count == 1 {
        "\"0.5\" (N m, about the z axis)"
    } else {
        "[\"0\", \"0\", \"0.5\"] (N m, world axes)"
    };
    let comps = compile_n(t, ctx, "T", Dimension::ENERGY, "a torque", count)?
        .ok_or_else(|| t.missing("T", example))?;
    Ok(Box::new(Torque::new(name, rigid.body, turn(rigid), comps)))
}

/// A `[[force]]`, applied at a body point when it has `at = "body.point"` (then it acts on
/// that rigid body alone, and its torque about the centre of mass turns the body).
pub(crate) fn force_at(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    index: usize,
) -> Result<Box<dyn Force>, ScenarioError> {
    let Some(at) = t.get("at") else {
        return build_force(t, ctx, index);
    };
    let src = t.src;
    let DeValue::String(text) = at.get_ref() else {
        return Err(t.wrong_type("at", at, "a body point, such as \"ladder.top\""));
    };
    let (rigid, r) = point(ctx, text).map_err(|m| src.error(ErrorKind::Invalid, m, at.span()))?;
    let body_name = ctx.bodies[rigid.body].clone();
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
    if let Some(list) = crate::scenario::doc::string_list(t, "between")? {
        // a force between bodies tied to a point of one of them: that end is at the point
        if !list.iter().any(|(n, _)| *n == body_name) {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("`at` is a point of `{body_name}`, which is not in `between`"),
                    at.span(),
                )
                .with_hint("tie one end of the force to a point of one of the bodies it joins"));
        }
    }
    let mut entries = t.entries.clone();
    entries.remove("at");
    if t.get("on").is_none() && t.get("between").is_none() {
        entries.insert(
            toml::Spanned::new(at.span(), std::borrow::Cow::Borrowed("on")),
            toml::Spanned::new(
                at.span(),
                DeValue::String(std::borrow::Cow::Owned(body_name)),
            ),
        );
    }
    let filtered = Table::new(src, &entries, t.span.clone(), t.what.clone());
    let inner = build_force(&filtered, ctx, index)?;
    let formula = matches!(
        t.string("kind")?.map(|(k, _)| k),
        Some("expression" | "formula")
    );
    let applied = AppliedAt::turning(inner, rigid.body, turn(rigid), r);
    Ok(Box::new(if formula { applied } else { applied.at_point() }))
}

/// The rigid body and body-frame offset of `"body.point"` (or of `"body"`, its centre).
fn point<'c>(
    ctx: &'c ForceContext<'_>,
    text: &str,
) -> Result<(&'c RigidName, [crate::Real; 3]), String> {
    let (body, point) = text.split_once('.').unwrap_or((text, ""));
    let Some(b) = ctx.bodies.iter().position(|n| n == body) else {
        let hint = mechkit_expr::did_you_mean(&mechkit_expr::nearest(
            body,
            ctx.bodies.iter().map(String::as_str),
        ))
        .map_or_else(String::new, |h| format!("; {h}"));
        return Err(format!("there is no body named `{body}`{hint}"));
    };
    let Some(rigid) = ctx.rigid.rigid.iter().find(|r| r.body == b) else {
        return Err(format!(
            "`{body}` is a particle: a force on it acts at its centre; leave out `at`, or apply the force to a [[rigid_body]]'s point"
        ));
    };
    if point.is_empty() {
        return Ok((rigid, [0.0; 3]));
    }
    crate::scenario::mechanism::points::find_point(&rigid.points, body, point).map(|r| (rigid, r))
}
