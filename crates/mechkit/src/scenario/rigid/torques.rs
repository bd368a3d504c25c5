//! `[[torque]]`: the torques on hinged rigid bodies, one builder per kind.

use mechkit_expr::Formula;
use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use crate::Real;
use crate::forces::{ExpressionForce, Force};
use crate::mass::Vec3;
use crate::particles::{BodyRef, Coordinates, NameContext, VarLevel};
use crate::rigid::fixed_axis::torques::{
    AttachedSpring, ConstantTorque, FrictionLaw, FrictionTorque, TorsionSpring,
};
use crate::scenario::bodyfile::geometry::points;
use crate::scenario::doc::{Table, string_list};
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{Constant, ValueEnv, formula_error, required_scalar, scalar};

use super::bodies::RigidBodies;

/// The torque kinds and the parameters each takes (besides `name`, `kind`, `on`).
pub(crate) const TORQUE_KINDS: &[(&str, &[&str], &str)] = &[
    (
        "gravity",
        &["g"],
        "uniform gravity on the body's centre of mass (g: a number along -y, or a vector)",
    ),
    (
        "torsion-spring",
        &["kappa", "theta0"],
        "-kappa (theta - theta0)",
    ),
    (
        "spring",
        &["k", "rest_length", "at", "anchor"],
        "a spring from the body point `at` to the fixed point `anchor`",
    ),
    (
        "friction",
        &["torque", "b"],
        "bearing friction: dry (constant `torque` against the turning) or viscous (-b omega)",
    ),
    (
        "applied",
        &["torque"],
        "a torque: a constant or a formula of t, theta, omega",
    ),
    (
        "hanging-weight",
        &["mass", "radius", "g"],
        "a weight on a string wound on a drum of (signed) radius on the axle",
    ),
];

/// Reads every `[[torque]]`; hanging weights add their `m r²` to their body.
pub(crate) fn read_torques(
    tables: &[Table<'_, '_>],
    rigid: &mut RigidBodies,
    constants: &[Constant],
) -> Result<Vec<Box<dyn Force>>, ScenarioError> {
    let env = ValueEnv {
        constants,
        mass: None,
        later: &[],
    };
    let mut out: Vec<Box<dyn Force>> = Vec::new();
    for (index, t) in tables.iter().enumerate() {
        let (kind_text, kind_span) = t.string("kind")?.ok_or_else(|| {
            t.missing("kind", "\"gravity\"").with_hint(format!(
                "add `kind = \"…\"`, one of: {}",
                kinds().join(", ")
            ))
        })?;
        let Some((kind, params, _)) = TORQUE_KINDS.iter().find(|(k, _, _)| *k == kind_text) else {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("unknown torque kind `{kind_text}`"),
                    kind_span,
                )
                .with_hint(
                    mechkit_expr::did_you_mean(&mechkit_expr::nearest(kind_text, kinds()))
                        .unwrap_or_else(|| format!("kinds: {}", kinds().join(", "))),
                ));
        };
        let mut allowed = vec!["name", "kind", "on"];
        allowed.extend_from_slice(params);
        t.check_keys(&allowed)?;
        let name = match t.string("name")? {
            Some((n, span)) => {
                if n.is_empty() || !n.chars().all(|c| c.is_alphanumeric() || c == '_') {
                    return Err(t.src.error(ErrorKind::Invalid, format!("torque name `{n}` must be letters, digits or `_` (formulas use it as `work.{n}`)"), span));
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
        let targets = match string_list(t, "on")? {
            None => (0..rigid.bodies.len()).collect(),
            Some(list) => {
                let mut v = Vec::new();
                for (n, span) in list {
                    let b = rigid.names.iter().position(|b| b == n).ok_or_else(|| {
                        t.src
                            .error(
                                ErrorKind::Invalid,
                                format!("no rigid body is named `{n}`"),
                                span,
                            )
                            .with_hint(format!("the rigid bodies are: {}", rigid.names.join(", ")))
                    })?;
                    v.push(b);
                }
                v
            }
        };
        let several = targets.len() > 1;
        for &b in &targets {
            let label = if several {
                format!("{name}_{}", rigid.names[b])
            } else {
                name.clone()
            };
            out.push(torque(t, kind, label, b, rigid, env)?);
        }
    }
    Ok(out)
}

fn kinds() -> Vec<&'static str> {
    TORQUE_KINDS.iter().map(|(k, _, _)| *k).collect()
}

fn non_negative(
    t: &Table<'_, '_>,
    key: &str,
    value: Real,
    what: &str,
) -> Result<Real, ScenarioError> {
    if value >= 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(t.src.error(
            ErrorKind::Invalid,
            format!(
                "{what} `{key}` must not be negative (it is {})",
                crate::error::short(value)
            ),
            t.key_span(key),
        ))
    }
}

fn torque(
    t: &Table<'_, '_>,
    kind: &str,
    name: String,
    b: usize,
    rigid: &mut RigidBodies,
    env: ValueEnv<'_>,
) -> Result<Box<dyn Force>, ScenarioError> {
    let body = &rigid.bodies[b];
    Ok(match kind {
        "gravity" => {
            let g = gravity_vector(t, env)?;
            let axis = body.axis();
            if (g - axis * axis.dot(&g)).norm() <= 1e-12 * g.norm() {
                rigid.warnings.push(format!(
                    "gravity is along the axis of `{}`: it exerts no torque",
                    body.name()
                ));
            }
            Box::new(body.gravity(name, b, g))
        }
        "torsion-spring" => {
            let kappa = required_scalar(t, "kappa", Dimension::ENERGY, env)?;
            let kappa = non_negative(t, "kappa", kappa, "the torsion constant")?;
            let rest = scalar(t, "theta0", Dimension::NONE, env)?.unwrap_or(0.0);
            Box::new(TorsionSpring::new(name, b, kappa, rest))
        }
        "spring" => {
            let k = required_scalar(t, "k", Dimension::STIFFNESS, env)?;
            let k = non_negative(t, "k", k, "the spring constant")?;
            let rest = scalar(t, "rest_length", Dimension::LENGTH, env)?.unwrap_or(0.0);
            let rest = non_negative(t, "rest_length", rest, "the rest length")?;
            let at = points(t, "at", env, 1, 3)?[0];
            let anchor = points(t, "anchor", env, 1, 3)?[0];
            let origin = body_pivot(rigid, b);
            Box::new(AttachedSpring::new(
                name,
                b,
                k,
                rest,
                at - origin,
                anchor - origin,
                rigid.bodies[b].axis(),
            ))
        }
        "friction" => match (t.get("torque"), t.get("b")) {
            (Some(_), None) => {
                let tau = required_scalar(t, "torque", Dimension::ENERGY, env)?;
                let tau = non_negative(t, "torque", tau, "the friction torque")?;
                let w = rigid.omega[b];
                if w == 0.0 {
                    return Err(t.src.error(ErrorKind::Invalid, format!("dry bearing friction on `{}`, which starts at rest", rigid.names[b]), t.key_span("torque")).with_hint("give the body an initial `omega` (the friction opposes the turning; the run ends when the body stops), or use viscous friction `b`"));
                }
                rigid.dry.push((b, w.signum(), name.clone()));
                Box::new(FrictionTorque::new(
                    name,
                    b,
                    FrictionLaw::Coulomb {
                        torque: tau,
                        direction: w.signum(),
                    },
                ))
            }
            (None, Some(_)) => {
                let c = required_scalar(t, "b", Dimension::ENERGY * Dimension::TIME, env)?;
                let c = non_negative(t, "b", c, "the friction coefficient")?;
                Box::new(FrictionTorque::new(name, b, FrictionLaw::Viscous(c)))
            }
            _ => {
                return Err(t
                    .missing("torque", "\"0.2 N*m\"")
                    .with_hint("bearing friction takes either `torque` (dry, constant) or `b` (viscous, -b omega), one of them"));
            }
        },
        "applied" => applied(t, name, b, rigid, env)?,
        "hanging-weight" => {
            let mass = required_scalar(t, "mass", Dimension::MASS, env)?;
            let radius = required_scalar(t, "radius", Dimension::LENGTH, env)?;
            let g = scalar(t, "g", Dimension::ACCELERATION, env)?.unwrap_or(9.81);
            let w = rigid.bodies[b]
                .hang(name, b, mass, radius, g)
                .map_err(|e| {
                    t.src
                        .error(ErrorKind::Invalid, e.to_string(), t.key_span("mass"))
                })?;
            Box::new(w)
        }
        _ => unreachable!("kind {kind} is listed in TORQUE_KINDS"),
    })
}

/// The pivot of body `b` in its own frame: a spring's points are given in the body's frame
/// at `theta = 0`, like the pivot.
fn body_pivot(rigid: &RigidBodies, b: usize) -> Vec3 {
    rigid.pivots[b]
}

/// Whether a formula reads the state (then it is compiled as a torque of the motion).
fn reads_state(f: &Formula, rigid: &RigidBodies, constants: &[Constant]) -> bool {
    f.names().iter().any(|n| {
        if constants.iter().any(|(c, _, _)| c == n) {
            return false;
        }
        let field = n.rsplit_once('.').map_or(*n, |(b, f)| {
            if rigid.names.iter().any(|r| r == b) {
                f
            } else {
                ""
            }
        });
        ["t", "theta", "omega", "I"].contains(&field)
    })
}

fn gravity_vector(t: &Table<'_, '_>, env: ValueEnv<'_>) -> Result<Vec3, ScenarioError> {
    match t.get("g").map(toml::Spanned::get_ref) {
        None => Ok(Vec3::new(0.0, -9.81, 0.0)),
        Some(DeValue::Array(items)) => {
            if !(2..=3).contains(&items.len()) {
                return Err(t.component_count("g", items.len(), 3, t.key_span("g")));
            }
            let mut g = Vec3::zeros();
            for (k, item) in items.iter().enumerate() {
                g[k] = crate::scenario::values::resolve(
                    &t.src,
                    "g",
                    item,
                    Dimension::ACCELERATION,
                    env,
                )?;
            }
            Ok(g)
        }
        Some(_) => {
            let g = required_scalar(t, "g", Dimension::ACCELERATION, env)?;
            Ok(Vec3::new(0.0, -g, 0.0))
        }
    }
}

fn applied(
    t: &Table<'_, '_>,
    name: String,
    b: usize,
    rigid: &RigidBodies,
    env: ValueEnv<'_>,
) -> Result<Box<dyn Force>, ScenarioError> {
    let v = t
        .get("torque")
        .ok_or_else(|| t.missing("torque", "\"2 N*m\""))?;
    if let DeValue::String(text) = v.get_ref()
        && let Ok(f) = Formula::parse(text)
        && reads_state(&f, rigid, env.constants)
    {
        let names = NameContext {
            dim: 1,
            bodies: &rigid.names,
            forces: &[],
            constants: env.constants,
            bare: Some(BodyRef::Local),
            level: VarLevel::Kinematic,
            coordinates: Coordinates::Angle,
            units: t.src.units,
            planar: &crate::particles::NO_PLANAR,
        };
        let expr = names
            .compile(&f)
            .map_err(|e| formula_error(&t.src, &v.span(), &e))?;
        f.expect_dimension_in(
            names.units,
            Dimension::ENERGY,
            "a torque",
            &|n| names.dim_of(n),
            &|n| names.constant(n),
        )
        .map_err(|e| formula_error(&t.src, &v.span(), &e))?;
        return Ok(Box::new(ExpressionForce::new(name, vec![b], vec![expr])));
    }
    let tau = required_scalar(t, "torque", Dimension::ENERGY, env)?;
    Ok(Box::new(ConstantTorque::new(name, b, tau)))
}
