//! `[[rigid_body]]`: a body (parts, a body file, or mass and moment) hinged at a pivot about
//! an axis, with its initial angle and angular velocity.
use std::path::Path;

use mechkit_expr::units::Dimension;

use crate::Real;
use crate::mass::{Body, MassProperties, Vec3};
use crate::rigid::fixed_axis::HingedBody;
use crate::scenario::bodyfile::geometry::{direction, points};
use crate::scenario::bodyfile::{BodyFile, part};
use crate::scenario::build::body_name;
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{Constant, ValueEnv, required_scalar, scalar};

const RIGID_KEYS: &[&str] = &[
    "name",
    "part",
    "body",
    "mass",
    "inertia",
    "centre_of_mass",
    "pivot",
    "axis",
    "theta",
    "omega",
];

/// The rigid bodies of a scenario, read.
pub(crate) struct RigidBodies {
    pub bodies: Vec<HingedBody>,
    pub names: Vec<String>,
    pub theta: Vec<Real>,
    pub omega: Vec<Real>,
    pub pivots: Vec<Vec3>,
    /// Each body's parts as drawn, about its pivot.
    pub outlines: Vec<Vec<Vec<[Real; 3]>>>,
    pub warnings: Vec<String>,
    /// Bodies with dry bearing friction: (body, direction of turning, torque name).
    pub dry: Vec<(usize, Real, String)>,
}

/// Reads every `[[rigid_body]]`; `dir` is where body files are looked for.
pub(crate) fn read_rigid_bodies(
    tables: &[Table<'_, '_>],
    constants: &[Constant],
    dir: Option<&Path>,
) -> Result<RigidBodies, ScenarioError> {
    let env = ValueEnv {
        constants,
        mass: None,
        later: &[],
    };
    let mut out = RigidBodies {
        bodies: Vec::new(),
        names: Vec::new(),
        theta: Vec::new(),
        omega: Vec::new(),
        pivots: Vec::new(),
        outlines: Vec::new(),
        warnings: Vec::new(),
        dry: Vec::new(),
    };
    for (i, t) in tables.iter().enumerate() {
        t.check_keys(RIGID_KEYS)?;
        let name = body_name(t, i, tables.len(), &out.names, "theta")?;
        let pivot = if t.get("pivot").is_some() {
            points(t, "pivot", env, 1, 3)?[0]
        } else {
            Vec3::zeros()
        };
        let axis = if t.get("axis").is_some() {
            direction(t, "axis", env)?
        } else {
            Vec3::z()
        };
        let located = |e: crate::rigid::fixed_axis::FixedAxisError, key: &str| {
            let span = t
                .get(key)
                .map_or_else(|| t.span.clone(), toml::Spanned::span);
            t.src
                .error(ErrorKind::Invalid, e.to_string(), span)
                .with_hint("the axis must pass beside the body's mass: choose another `axis` or `pivot`, or check the shape's orientation")
        };
        let body = if t.get("inertia").is_some() {
            for key in ["part", "body"] {
                if t.get(key).is_some() {
                    return Err(t.src.error(ErrorKind::Invalid, format!("`{key}` and `inertia` both describe the body's mass distribution"), t.key_span(key)).with_hint("give either parts or a body file (the inertia is computed), or `mass`, `inertia` about the axis and `centre_of_mass`"));
                }
            }
            let mass = required_scalar(t, "mass", Dimension::MASS, env)?;
            let moment = required_scalar(t, "inertia", Dimension::MOMENT_OF_INERTIA, env)?;
            let cm = if t.get("centre_of_mass").is_some() {
                points(t, "centre_of_mass", env, 1, 3)?[0]
            } else {
                Vec3::zeros()
            };
            out.outlines
                .push(outline_of_moment(mass, moment, cm - pivot));
            HingedBody::from_moment(name.clone(), mass, moment, cm - pivot, axis)
                .map_err(|e| located(e, "inertia"))?
        } else {
            for key in ["mass", "centre_of_mass"] {
                if t.get(key).is_some() {
                    return Err(t.src.error(ErrorKind::Invalid, format!("`{key}` belongs with `inertia`; with parts or a body file the mass is theirs"), t.key_span(key)));
                }
            }
            let (props, drawn) = mass_properties(t, env, dir)?;
            out.outlines.push(drawn.outline(pivot));
            HingedBody::new(name.clone(), &props, pivot, axis).map_err(|e| located(e, "axis"))?
        };
        if let Some(w) = body.pivot_warning() {
            out.warnings.push(w);
        }
        out.theta
            .push(scalar(t, "theta", Dimension::NONE, env)?.unwrap_or(0.0));
        out.omega
            .push(scalar(t, "omega", Dimension::FREQUENCY, env)?.unwrap_or(0.0));
        out.names.push(name);
        out.bodies.push(body);
        out.pivots.push(pivot);
    }
    Ok(out)
}

/// The mass properties of a rigid body's parts or body file, and the body (to draw it).
pub(crate) fn mass_properties(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    dir: Option<&Path>,
) -> Result<(MassProperties, Body), ScenarioError> {
    let body = match (t.get("part"), t.string("body")?) {
        (Some(_), Some((_, span))) => {
            return Err(t.src.error(
                ErrorKind::Invalid,
                "a rigid body has either `[[rigid_body.part]]` tables or a `body` file, not both",
                span,
            ));
        }
        (Some(_), None) => {
            let parts = t.tables("part")?;
            let mut list = Vec::new();
            for (i, p) in parts.iter().enumerate() {
                list.push(part(p, i, env, None, dir)?);
            }
            Body::new(list)
        }
        (None, Some((file, span))) => {
            let path = dir.map_or_else(|| Path::new(file).to_path_buf(), |d| d.join(file));
            BodyFile::load(&path)
                .map_err(|e| {
                    t.src
                        .error(ErrorKind::Invalid, format!("body file `{file}`: {e}"), span)
                        .with_hint("the body file's path is relative to the scenario file")
                })?
                .body
        }
        (None, None) => {
            return Err(t
                .missing("part", "[[rigid_body.part]]")
                .with_hint("describe the body by `[[rigid_body.part]]` tables (shape, dimensions, mass: as in a body file), a `body = \"file.toml\"`, or `mass`, `inertia` (about the axis) and `centre_of_mass`"));
        }
    };
    let props = body.properties().map_err(|e| {
        t.src.error(
            ErrorKind::Invalid,
            format!("the rigid body: {e}"),
            t.span.clone(),
        )
    })?;
    Ok((props, body))
}

/// The outline of a body given by its mass and moment only: a disk with that moment about
/// its centre, `cm` from the point it turns about (a stick from there to it when apart).
pub(crate) fn outline_of_moment(mass: Real, moment: Real, cm: Vec3) -> Vec<Vec<[Real; 3]>> {
    let radius = (2.0 * moment / mass).sqrt();
    let mut disk = Vec::new();
    if radius.is_finite() && radius > 0.0 {
        for k in 0..32 {
            let a = std::f64::consts::TAU * Real::from(k) / 32.0;
            disk.push([cm.x + radius * a.cos(), cm.y + radius * a.sin(), cm.z]);
        }
    }
    let mut parts = vec![disk];
    if cm.norm() > 0.0 {
        parts.push(vec![[0.0; 3], [cm.x, cm.y, cm.z]]);
    }
    parts
}
