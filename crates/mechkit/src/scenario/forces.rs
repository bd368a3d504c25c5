//! `[[force]]` tables: one builder per kind.

mod pair;
mod rigid;
mod ties;

pub(crate) use rigid::force_at;

use std::ops::Range;

use mechkit_expr::Formula;
use mechkit_expr::units::Dimension;
use mechkit_expr::units::Quantity;
use toml::de::DeValue;

use super::doc::{Table, string_list};
use super::error::{ErrorKind, ScenarioError};
use super::values::{Constant, ValueEnv, formula_error, required_scalar, scalar, vector};
use crate::Real;
use crate::forces::{
    ConstantForce, ExpressionForce, Force, LinearDrag, QuadraticDrag, Target, UniformGravity, Wind,
};
use crate::particles::{BodyRef, NameContext, VarLevel};

/// The force kinds and the parameters each takes (besides `name`, `kind`, `on`).
pub(crate) const KINDS: &[(&str, &[&str], &str)] = &[
    (
        "constant",
        &["F"],
        "a constant force F (vector; scalar in 1-D)",
    ),
    (
        "uniform-gravity",
        &["g"],
        "-m g along the last axis (default g = 9.81 m/s^2)",
    ),
    (
        "newtonian-gravity",
        &["GM", "M", "G", "center", "between"],
        "-G M m/r^2 towards a fixed centre (GM, or M with G), or between bodies (between, G)",
    ),
    (
        "spring",
        &["k", "rest_length", "anchor", "between"],
        "-k (r - rest_length) towards a fixed anchor, or between two bodies",
    ),
    ("linear-drag", &["b", "wind"], "-b (v - wind)"),
    ("quadratic-drag", &["D", "wind"], "-D |v - wind| (v - wind)"),
    (
        "expression",
        &["F"],
        "a formula of t, x, v, m, … per component",
    ),
    (
        "torque",
        &["T"],
        "a torque T on a rigid body (`on`): its z component in a plane, its world components in space",
    ),
    (
        "pair",
        &["between", "U", "cutoff"],
        "-dU/dr along the line of centres, from a potential U(r) of the separation, between every pair of the bodies in `between`",
    ),
];

const ALIASES: &[(&str, &str)] = &[
    ("gravity", "uniform-gravity"),
    ("weight", "uniform-gravity"),
    ("gravitation", "newtonian-gravity"),
    ("drag", "quadratic-drag"),
    ("viscous-drag", "linear-drag"),
    ("formula", "expression"),
    ("potential", "pair"),
    ("pair-potential", "pair"),
];

/// What a force table needs from the rest of the scenario.
pub(crate) struct ForceContext<'c> {
    pub dim: usize,
    pub bodies: &'c [String],
    pub masses: &'c [Real],
    pub constants: &'c [Constant],
    /// The rigid bodies whose angles and angular velocities formulas may read.
    pub rigid: &'c crate::particles::PlanarNames,
}

impl ForceContext<'_> {
    fn env(&self, mass: Option<Real>) -> ValueEnv<'_> {
        ValueEnv {
            constants: self.constants,
            mass,
            later: &[],
        }
    }

    fn body(
        &self,
        t: &Table<'_, '_>,
        name: &str,
        span: Range<usize>,
    ) -> Result<usize, ScenarioError> {
        self.bodies.iter().position(|b| b == name).ok_or_else(|| {
            let hint = mechkit_expr::did_you_mean(&mechkit_expr::nearest(
                name,
                self.bodies.iter().map(String::as_str),
            ))
            .unwrap_or_else(|| format!("the bodies are: {}", self.bodies.join(", ")));
            t.src
                .error(
                    ErrorKind::Invalid,
                    format!("there is no body named `{name}`"),
                    span,
                )
                .with_hint(hint)
        })
    }

    /// The bodies named by `key` (`on` or `between`); `None` when the key is absent.
    fn body_list(&self, t: &Table<'_, '_>, key: &str) -> Result<Option<Vec<usize>>, ScenarioError> {
        let Some(list) = string_list(t, key)? else {
            return Ok(None);
        };
        let mut out = Vec::new();
        for (name, span) in list {
            let b = self.body(t, name, span.clone())?;
            if out.contains(&b) {
                return Err(t.src.error(
                    ErrorKind::Invalid,
                    format!("`{name}` is listed twice"),
                    span,
                ));
            }
            out.push(b);
        }
        Ok(Some(out))
    }
}

fn canonical_kind(kind: &str) -> Option<&'static str> {
    KINDS
        .iter()
        .map(|(k, _, _)| *k)
        .find(|k| *k == kind)
        .or_else(|| ALIASES.iter().find(|(a, _)| *a == kind).map(|(_, k)| *k))
}

/// Reads every `[[force]]` table of `root`, each applied at a body point when it has `at`
/// (`at_points`: in a scenario of free rigid bodies), refusing two forces of one name or a
/// force named like one of `taken`.
pub(crate) fn read_forces(
    root: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    taken: &[String],
    at_points: bool,
) -> Result<Vec<Box<dyn Force>>, ScenarioError> {
    let mut forces: Vec<Box<dyn Force>> = Vec::new();
    for (i, t) in root.tables("force")?.iter().enumerate() {
        let f = if at_points {
            force_at(t, ctx, i)?
        } else {
            build_force(t, ctx, i)?
        };
        if forces.iter().any(|o| o.name() == f.name()) || taken.iter().any(|n| n == f.name()) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("two forces are named `{}`", f.name()),
                    t.key_span("name"),
                )
                .with_hint(
                    "give each [[force]] its own `name`; the energy ledger lists work by name",
                ));
        }
        forces.push(f);
    }
    Ok(forces)
}

/// Reads one `[[force]]` table.
pub(crate) fn build_force(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    index: usize,
) -> Result<Box<dyn Force>, ScenarioError> {
    let (kind_text, kind_span) = t.string("kind")?.ok_or_else(|| {
        let kinds: Vec<&str> = KINDS.iter().map(|(k, _, _)| *k).collect();
        t.missing("kind", "\"uniform-gravity\"")
            .with_hint(format!("add `kind = \"…\"`, one of: {}", kinds.join(", ")))
    })?;
    let kind = canonical_kind(kind_text).ok_or_else(|| {
        let kinds: Vec<&str> = KINDS.iter().map(|(k, _, _)| *k).collect();
        let hint =
            mechkit_expr::did_you_mean(&mechkit_expr::nearest(kind_text, kinds.iter().copied()))
                .unwrap_or_else(|| format!("kinds: {}", kinds.join(", ")));
        t.src
            .error(
                ErrorKind::Invalid,
                format!("unknown force kind `{kind_text}`"),
                kind_span,
            )
            .with_hint(hint)
    })?;
    let params = KINDS
        .iter()
        .find(|(k, _, _)| *k == kind)
        .map_or(&[][..], |(_, p, _)| *p);
    let mut allowed = vec!["name", "kind", "on"];
    allowed.extend_from_slice(params);
    t.check_keys(&allowed).map_err(|mut e| {
        if e.hint.as_deref().is_none_or(|h| h.starts_with("the keys")) {
            e.hint = Some(format!("a `{kind}` force takes: {}", allowed.join(", ")));
        }
        e
    })?;
    let name = match t.string("name")? {
        Some((n, span)) => {
            if n.is_empty() || !n.chars().all(|c| c.is_alphanumeric() || c == '_') {
                return Err(t.src.error(
                    ErrorKind::Invalid,
                    format!(
                        "force name `{n}` must be letters, digits or `_` (formulas use it as `work.{n}`)"
                    ),
                    span,
                ));
            }
            n.to_string()
        }
        None if index == 0 => kind.split('-').next_back().unwrap_or(kind).to_string(),
        None => format!(
            "{}{}",
            kind.split('-').next_back().unwrap_or(kind),
            index + 1
        ),
    };
    let all: Vec<usize> = (0..ctx.bodies.len()).collect();
    let on = ctx.body_list(t, "on")?;
    let targets = on.clone().unwrap_or(all);
    let dim = ctx.dim;
    Ok(match kind {
        "constant" => {
            let mut per_body = Vec::new();
            for &b in &targets {
                let f = vector(t, "F", Dimension::FORCE, dim, ctx.env(Some(ctx.masses[b])))?
                    .ok_or_else(|| t.missing("F", "\"5 N\""))?;
                per_body.push((b, f));
            }
            Box::new(ConstantForce::per_body(name, per_body))
        }
        "uniform-gravity" => {
            let g = scalar(t, "g", Dimension::ACCELERATION, ctx.env(None))?.unwrap_or(9.81);
            if g.is_nan() || g < 0.0 {
                // "down is negative" written into the strength would turn gravity upwards
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        format!(
                            "`g` is the strength of gravity and must not be negative (it is {} m/s^2)",
                            crate::expr::short_number(g)
                        ),
                        t.key_span("g"),
                    )
                    .with_hint("uniform gravity already points down (-y, or -x on a line): write `g = \"9.81 m/s^2\"`"));
            }
            Box::new(UniformGravity::new(name, targets, g))
        }
        "newtonian-gravity" => ties::newtonian(t, ctx, name, targets)?,
        "spring" => ties::spring(t, ctx, name, on.is_some(), targets)?,
        "linear-drag" | "quadratic-drag" => {
            let (key, want) = if kind == "linear-drag" {
                ("b", Dimension::LINEAR_DRAG)
            } else {
                ("D", Dimension::QUADRATIC_DRAG)
            };
            let mut list = Vec::new();
            for &b in &targets {
                let c = required_scalar(t, key, want, ctx.env(Some(ctx.masses[b])))?;
                if c.is_nan() || c < 0.0 {
                    return Err(t.src.error(
                        ErrorKind::Invalid,
                        format!(
                            "the drag coefficient `{key}` must not be negative (it is {})",
                            crate::error::short(c)
                        ),
                        t.key_span(key),
                    ));
                }
                list.push(Target::new(b, c));
            }
            let wind = wind(t, ctx)?;
            if kind == "linear-drag" {
                Box::new(LinearDrag::new(name, list).with_wind(wind))
            } else {
                Box::new(QuadraticDrag::new(name, list).with_wind(wind))
            }
        }
        "expression" => expression(t, ctx, name, targets)?,
        "pair" => pair::pair(t, ctx, name, on.is_some())?,
        "torque" => rigid::torque(t, ctx, name, on.as_deref())?,
        _ => unreachable!("kind {kind} is listed in KINDS"),
    })
}

/// Formulas with their spans.
type Components = Vec<(String, Range<usize>)>;

fn formula_components(
    t: &Table<'_, '_>,
    key: &str,
    dim: usize,
) -> Result<Option<Components>, ScenarioError> {
    let Some(v) = t.get(key) else {
        return Ok(None);
    };
    let items: Components = match v.get_ref() {
        DeValue::String(s) => vec![(s.to_string(), v.span())],
        DeValue::Array(items) => items
            .iter()
            .map(|item| match item.get_ref() {
                DeValue::String(s) => Ok((s.to_string(), item.span())),
                DeValue::Integer(i) => Ok((i.as_str().to_string(), item.span())),
                DeValue::Float(f) => Ok((f.as_str().to_string(), item.span())),
                _ => Err(t.wrong_type(key, item, "a formula (a string)")),
            })
            .collect::<Result<_, _>>()?,
        DeValue::Integer(i) => vec![(i.as_str().to_string(), v.span())],
        DeValue::Float(f) => vec![(f.as_str().to_string(), v.span())],
        _ => return Err(t.wrong_type(key, v, "a formula or a list of formulas")),
    };
    if items.len() != dim {
        return Err(t
            .component_count(key, items.len(), dim, v.span())
            .with_hint(if dim == 1 {
                format!("write `{key} = \"…\"`")
            } else {
                format!(
                    "write one formula per component: `{key} = [{}]`",
                    vec!["\"…\""; dim].join(", ")
                )
            }));
    }
    Ok(Some(items))
}

fn compile_components(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    key: &str,
    want: Dimension,
    what: &str,
) -> Result<Option<Vec<crate::particles::StateExpr>>, ScenarioError> {
    compile_n(t, ctx, key, want, what, ctx.dim)
}

/// `count` formulas under `key` of dimension `want`, compiled with bare names meaning the
/// body they act on.
pub(crate) fn compile_n(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    key: &str,
    want: Dimension,
    what: &str,
    count: usize,
) -> Result<Option<Vec<crate::particles::StateExpr>>, ScenarioError> {
    let Some(items) = formula_components(t, key, count)? else {
        return Ok(None);
    };
    let names = NameContext {
        dim: ctx.dim,
        bodies: ctx.bodies,
        forces: &[],
        constants: ctx.constants,
        bare: Some(BodyRef::Local),
        level: VarLevel::Kinematic,
        coordinates: crate::particles::Coordinates::Cartesian,
        units: t.src.units,
        planar: ctx.rigid,
    };
    let mut out = Vec::new();
    for (text, span) in items {
        let f = Formula::parse(&text).map_err(|e| formula_error(&t.src, &span, &e))?;
        let expr = names
            .compile(&f)
            .map_err(|e| formula_error(&t.src, &span, &e))?;
        f.expect_dimension_in(names.units, want, what, &|n| names.dim_of(n), &|n| {
            names.constant(n)
        })
        .map_err(|e| formula_error(&t.src, &span, &e))?;
        out.push(expr);
    }
    Ok(Some(out))
}

fn wind(t: &Table<'_, '_>, ctx: &ForceContext<'_>) -> Result<Wind, ScenarioError> {
    // A constant wind is written with units ("5 m/s"); a wind field as formulas of x, y, z, t.
    let quantities = |v: &toml::Spanned<DeValue<'_>>| match v.get_ref() {
        DeValue::String(s) => Quantity::parse(s).is_ok(),
        DeValue::Array(items) => items.iter().all(|i| match i.get_ref() {
            DeValue::String(s) => Quantity::parse(s).is_ok(),
            _ => true,
        }),
        _ => true,
    };
    if t.get("wind").is_some_and(quantities) {
        let w = vector(t, "wind", Dimension::VELOCITY, ctx.dim, ctx.env(None))?.unwrap_or_default();
        return Ok(if w.iter().all(|x| *x == 0.0) {
            Wind::Calm
        } else {
            Wind::Constant(w)
        });
    }
    match compile_components(t, ctx, "wind", Dimension::VELOCITY, "the wind")? {
        None => Ok(Wind::Calm),
        Some(exprs) => {
            if let Some(c) = exprs
                .iter()
                .map(crate::particles::StateExpr::as_constant)
                .collect::<Option<Vec<Real>>>()
            {
                return Ok(Wind::Constant(c));
            }
            if exprs
                .iter()
                .any(crate::particles::StateExpr::reads_velocity)
            {
                return Err(t.src.error(
                    ErrorKind::Invalid,
                    "the wind may depend on position and time, not on the body's velocity",
                    t.key_span("wind"),
                ));
            }
            Ok(Wind::Field(exprs))
        }
    }
}

fn expression(
    t: &Table<'_, '_>,
    ctx: &ForceContext<'_>,
    name: String,
    targets: Vec<usize>,
) -> Result<Box<dyn Force>, ScenarioError> {
    let comps = compile_components(t, ctx, "F", Dimension::FORCE, "a force")?.ok_or_else(|| {
        t.missing(
            "F",
            if ctx.dim == 1 {
                "\"-k*x\""
            } else {
                "[\"-k*x\", \"-k*y\"]"
            },
        )
    })?;
    Ok(Box::new(ExpressionForce::new(name, targets, comps)))
}
