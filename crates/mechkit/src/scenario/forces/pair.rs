//! `kind = "pair"`: a potential `U(r)` of the separation between bodies (`between`), its force
//! `-dU/dr` derived symbolically ([`RadialPotential`]), an optional `cutoff`.

use mechkit_expr::units::Dimension;
use mechkit_expr::{Dim, Formula, MapScope};
use toml::de::DeValue;

use super::ForceContext;
use crate::Real;
use crate::forces::{Force, PairError, PairForce, RadialPotential};
use crate::particles::{BodyRef, Coordinates, NameContext, VarLevel};
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{formula_error, scalar};

/// The name of the separation in `U`.
const SEPARATION: &str = "r";

/// Reads a `pair` force.
pub(super) fn pair(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    name: String,
    on_given: bool,
) -> Result<Box<dyn Force>, ScenarioError> {
    if on_given {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                "`on` does not go with a pair force",
                t.key_span("on"),
            )
            .with_hint(
                "list the bodies that interact with `between = [\"a\", \"b\"]` (every pair among them), or write `between = \"all\"`",
            ));
    }
    let pairs = pairs(t, ctx)?;
    let law = potential(t, ctx)?;
    let law = match scalar(t, "cutoff", Dimension::LENGTH, ctx.env(None))? {
        None => law,
        Some(rc) => law.with_cutoff(rc).map_err(|e| {
            let hint = match e {
                PairError::NotFiniteAtCutoff { .. } => {
                    "put the cut-off where the potential is defined (it is shifted by U(cutoff))"
                }
                _ => "write a positive length, e.g. `cutoff = \"2.5*s\"`",
            };
            t.src
                .error(
                    ErrorKind::Invalid,
                    format!("`cutoff`: {e}"),
                    t.key_span("cutoff"),
                )
                .with_hint(hint)
        })?,
    };
    Ok(Box::new(PairForce::new(name, pairs, law)))
}

/// The pairs of `between`: one pair, every pair of a list, or every pair of all bodies
/// (`"all"`).
fn pairs(t: &Table<'_, '_>, ctx: &ForceContext<'_>) -> Result<Vec<(usize, usize)>, ScenarioError> {
    let all = t
        .get("between")
        .is_some_and(|v| matches!(v.get_ref(), DeValue::String(s) if s.as_ref() == "all"));
    let bodies = if all {
        (0..ctx.bodies.len()).collect()
    } else {
        ctx.body_list(t, "between")?.ok_or_else(|| {
            t.missing("between", "[\"a\", \"b\"]").with_hint(
                "a pair force acts between bodies: `between = [\"a\", \"b\"]`, a longer list (every pair among them), or `between = \"all\"`",
            )
        })?
    };
    if bodies.len() < 2 {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                if all {
                    "`between = \"all\"` needs at least two bodies in the scenario".to_string()
                } else {
                    format!(
                        "`between` needs at least two bodies, it lists {}",
                        bodies.len()
                    )
                },
                t.key_span("between"),
            )
            .with_hint("a pair force acts between two or more bodies"));
    }
    Ok(PairForce::all_pairs(&bodies))
}

/// `U`: a formula of the separation `r` and the constants, with the dimension of an energy (in
/// reduced units, only consistent in itself).
fn potential(t: &Table<'_, '_>, ctx: &ForceContext<'_>) -> Result<RadialPotential, ScenarioError> {
    let (text, span) = t.string("U")?.ok_or_else(|| {
        t.missing("U", "\"4*eps*((s/r)^12 - (s/r)^6)\"").with_hint(
            "give the potential energy of a pair as a formula of their separation `r`, e.g. `U = \"k*(r - L)^2/2\"`",
        )
    })?;
    let f = Formula::parse(text).map_err(|e| formula_error(&t.src, &span, &e))?;
    let constants: Vec<(String, Real)> = ctx
        .constants
        .iter()
        .filter(|(n, _, _)| n != SEPARATION)
        .map(|(n, v, _)| (n.clone(), *v))
        .collect();
    let mut scope = MapScope::new();
    for (n, v) in &constants {
        scope = scope.constant(n, *v);
    }
    let listed: Vec<&str> = constants.iter().map(|(n, _)| n.as_str()).collect();
    let scope = scope.slot(SEPARATION, 0).described(if listed.is_empty() {
        "`U` is a formula of the separation `r` alone (add others to [constants])".to_string()
    } else {
        format!(
            "`U` is a formula of the separation `r` and the constants: {}",
            listed.join(", ")
        )
    });
    f.check_names(&scope)
        .map_err(|e| formula_error(&t.src, &span, &e))?;
    // `r` has the dimension of a position (a length, or none in reduced units)
    let r_dim = NameContext {
        dim: ctx.dim,
        bodies: ctx.bodies,
        forces: &[],
        constants: &[],
        bare: Some(BodyRef::Local),
        level: VarLevel::Kinematic,
        coordinates: Coordinates::Cartesian,
        units: t.src.units,
        planar: &crate::particles::NO_PLANAR,
    }
    .dim_of(SEPARATION);
    let dims = |n: &str| {
        if n == SEPARATION {
            r_dim
        } else {
            ctx.constants
                .iter()
                .find(|(c, _, _)| c == n)
                .map_or(Dim::Unknown, |(_, _, d)| *d)
        }
    };
    let values = |n: &str| constants.iter().find(|(c, _)| c == n).map(|(_, v)| *v);
    f.expect_dimension_in(
        t.src.units,
        Dimension::ENERGY,
        "a pair potential `U`",
        &dims,
        &values,
    )
    .map_err(|e| formula_error(&t.src, &span, &e))?;
    RadialPotential::new(f.expr(), SEPARATION, &constants).map_err(|e| {
        t.src
            .error(ErrorKind::Formula, e.to_string(), span.clone())
            .with_hint("`U` may use the separation `r` and the constants")
    })
}
