//! Body files: a rigid body described in TOML as parts (shape, dimensions with units,
//! density or mass, position, orientation, `hole = true`), read into a [`Body`].
//!
//! ```
//! use mechkit::scenario::BodyFile;
//! let file = BodyFile::from_str("dumbbell.toml", r#"
//!     [[part]]
//!     shape = "rod"
//!     length = "1 m"
//!     mass = "1 kg"
//!     axis = [1, 0, 0]
//!     [[part]]
//!     shape = "sphere"
//!     radius = "10 cm"
//!     mass = "0.5 kg"
//!     position = ["-0.5 m", 0, 0]
//!     [[part]]
//!     shape = "sphere"
//!     radius = "10 cm"
//!     mass = "0.5 kg"
//!     position = ["0.5 m", 0, 0]
//! "#, None).unwrap();
//! let p = file.body.properties().unwrap();
//! // m L²/12 + 2 (2/5 M R² + M (L/2)²)
//! assert!((p.inertia[(2, 2)] - 0.337333333).abs() < 1e-8);
//! ```

use std::ops::Range;
use std::path::Path;

use mechkit_expr::Dim;
use mechkit_expr::units::Dimension;
use nalgebra::Rotation3;
use toml::de::{DeTable, DeValue};

pub(crate) mod geometry;

use super::constants::constants;
use super::doc::{Source, Table, Value};
use super::error::{ErrorKind, ScenarioError};
use super::values::{ValueEnv, dim_text, required_scalar, resolve, resolve_any, scalar};
use crate::Real;
use crate::mass::{Amount, Body, Extent, MassError, Part, Polygon, Shape, Vec3};
use geometry::{direction, mesh, points};

const TOP_KEYS: &[&str] = &["title", "description", "density", "constants", "part"];
const PART_KEYS: &[&str] = &[
    "name", "shape", "mass", "density", "position", "axis", "rotation", "hole",
];
/// The keys that give a shape's dimensions (each shape takes some of them).
const DIMENSION_KEYS: &[&str] = &[
    "length",
    "radius",
    "inner_radius",
    "height",
    "width",
    "size",
    "angle",
    "vertices",
    "faces",
    "file",
];

/// The shapes a part may have, and the dimension keys each needs.
const SHAPES: &[(&str, &[&str])] = &[
    ("point", &[]),
    ("rod", &["length"]),
    ("ring", &["radius"]),
    ("disk", &["radius", "inner_radius"]),
    ("cylinder", &["radius", "inner_radius", "height"]),
    ("tube", &["radius", "height"]),
    ("sphere", &["radius", "inner_radius"]),
    ("spherical-shell", &["radius"]),
    ("cone", &["radius", "height"]),
    ("box", &["size"]),
    ("plate", &["width", "height"]),
    ("triangle", &["vertices"]),
    ("sector", &["radius", "angle"]),
    ("tetrahedron", &["vertices"]),
    ("polygon", &["vertices"]),
    ("mesh", &["vertices", "faces", "file"]),
];

/// A body file, read and checked.
#[derive(Debug, Clone)]
pub struct BodyFile {
    /// The title (the file name if none is given).
    pub title: String,
    /// The body.
    pub body: Body,
}

impl BodyFile {
    /// Reads a body file; meshes named by `file = "part.obj"` are found next to it.
    pub fn load(path: &Path) -> Result<BodyFile, ScenarioError> {
        let text = super::read_source(path)?;
        Self::from_str(&path.display().to_string(), &text, path.parent())
    }

    /// Reads a body from TOML text; `name` is used in error locations, `dir` to find mesh
    /// files.
    #[allow(clippy::should_implement_trait)]
    pub fn from_str(name: &str, text: &str, dir: Option<&Path>) -> Result<BodyFile, ScenarioError> {
        let src = Source {
            name,
            text,
            units: mechkit_expr::units::UnitSystem::Si,
        };
        let doc = DeTable::parse(text).map_err(|e| {
            src.error(
                ErrorKind::Syntax,
                format!("invalid TOML: {}", e.message().trim()),
                e.span().unwrap_or(0..0),
            )
            .with_hint("see docs/scenario.md#body-files for the format")
        })?;
        let root = Table::new(src, doc.get_ref(), 0..0, "the body file");
        root.check_keys(TOP_KEYS)?;
        let title = root
            .string("title")?
            .map_or_else(|| name.to_string(), |(s, _)| s.to_string());
        let constants = constants(&root, &[])?;
        let env = ValueEnv {
            constants: &constants,
            mass: None,
            later: &[],
        };
        let default_density = root
            .get("density")
            .map(|v| resolve_any(&src, "density", v, env).map(|d| (d, v.span())))
            .transpose()?;
        let tables = root.tables("part")?;
        if tables.is_empty() {
            return Err(src
                .error(ErrorKind::Missing, "the body file has no parts", 0..0)
                .with_hint(
                    "add a part: [[part]] shape = \"sphere\" radius = \"5 cm\" density = \"7800 kg/m^3\"",
                ));
        }
        let mut parts = Vec::new();
        for (i, t) in tables.iter().enumerate() {
            parts.push(part(t, i, env, default_density.as_ref(), dir)?);
        }
        let body = Body::new(parts);
        // a hole outside the solid parts, located at its table (its `position`)
        if let Err(e @ MassError::Hole { index, .. }) = body.check_holes() {
            let span = tables.get(index).map_or(0..0, |t| {
                t.get("position")
                    .map_or_else(|| t.span.clone(), Value::span)
            });
            return Err(src
                .error(ErrorKind::Invalid, e.to_string(), span)
                .with_hint("place the hole inside the parts it is cut from (its `position` is its centre in the body frame), or make it smaller"));
        }
        Ok(BodyFile { title, body })
    }
}

fn invalid(t: &Table<'_, '_>, key: &str, message: String) -> ScenarioError {
    let span = t.get(key).map_or_else(|| t.span.clone(), Value::span);
    t.src.error(ErrorKind::Invalid, message, span)
}

pub(crate) fn part(
    t: &Table<'_, '_>,
    index: usize,
    env: ValueEnv<'_>,
    default_density: Option<&((Real, Dim), Range<usize>)>,
    dir: Option<&Path>,
) -> Result<Part, ScenarioError> {
    t.check_keys(&[PART_KEYS, DIMENSION_KEYS].concat())?;
    let (kind, kind_span) = t
        .string("shape")?
        .ok_or_else(|| t.missing("shape", "\"sphere\""))?;
    let Some((kind, keys)) = SHAPES.iter().find(|(k, _)| *k == kind) else {
        let names: Vec<&str> = SHAPES.iter().map(|(k, _)| *k).collect();
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!("unknown shape `{kind}`"),
                kind_span,
            )
            .with_hint(
                mechkit_expr::did_you_mean(&mechkit_expr::nearest(kind, names.iter().copied()))
                    .unwrap_or_else(|| format!("the shapes are: {}", names.join(", "))),
            ));
    };
    let name = t
        .string("name")?
        .map_or_else(|| format!("{kind} {}", index + 1), |(s, _)| s.to_string());
    for &key in DIMENSION_KEYS {
        if t.get(key).is_some() && !keys.contains(&key) {
            return Err(t
                .src
                .error(
                    ErrorKind::UnknownKey,
                    format!("a {kind} has no `{key}`"),
                    t.key_span(key),
                )
                .with_hint(if keys.is_empty() {
                    format!("a {kind} takes only a mass and a position")
                } else {
                    format!("a {kind} takes: {}", keys.join(", "))
                }));
        }
    }
    let len = |key: &str| required_scalar(t, key, Dimension::LENGTH, env);
    let inner = || {
        Ok::<_, ScenarioError>(scalar(t, "inner_radius", Dimension::LENGTH, env)?.unwrap_or(0.0))
    };
    let shape = match *kind {
        "point" => Shape::Point,
        "rod" => Shape::Rod {
            length: len("length")?,
        },
        "ring" => Shape::Ring {
            radius: len("radius")?,
        },
        "disk" => Shape::Disk {
            radius: len("radius")?,
            inner_radius: inner()?,
        },
        "cylinder" => Shape::Cylinder {
            radius: len("radius")?,
            inner_radius: inner()?,
            height: len("height")?,
        },
        "tube" => Shape::Tube {
            radius: len("radius")?,
            height: len("height")?,
        },
        "sphere" => Shape::Sphere {
            radius: len("radius")?,
            inner_radius: inner()?,
        },
        "spherical-shell" => Shape::SphericalShell {
            radius: len("radius")?,
        },
        "cone" => Shape::Cone {
            radius: len("radius")?,
            height: len("height")?,
        },
        "box" => {
            let s = points(t, "size", env, 3, 3)?;
            let [s] = s.as_slice() else {
                return Err(invalid(
                    t,
                    "size",
                    "`size` must be one list [a, b, c]".into(),
                ));
            };
            Shape::Cuboid { size: *s }
        }
        "plate" => Shape::Plate {
            width: len("width")?,
            height: len("height")?,
        },
        "sector" => Shape::Sector {
            radius: len("radius")?,
            angle: required_scalar(t, "angle", Dimension::NONE, env)?,
        },
        "triangle" | "tetrahedron" => {
            let n = if *kind == "triangle" { 3 } else { 4 };
            let v = points(t, "vertices", env, 2, 3)?;
            if v.len() != n {
                return Err(invalid(
                    t,
                    "vertices",
                    format!("a {kind} has {n} vertices, not {}", v.len()),
                ));
            }
            if n == 3 {
                Shape::Triangle {
                    vertices: [v[0], v[1], v[2]],
                }
            } else {
                Shape::Tetrahedron {
                    vertices: [v[0], v[1], v[2], v[3]],
                }
            }
        }
        "polygon" => {
            let v = points(t, "vertices", env, 2, 2)?;
            Shape::Polygon(
                Polygon::new(v.iter().map(|p| [p.x, p.y]).collect())
                    .map_err(|e| invalid(t, "vertices", e.to_string()))?,
            )
        }
        _ => Shape::Mesh(mesh(t, env, dir)?),
    };
    let amount = amount(t, &shape, env, default_density)?;
    let position = if t.get("position").is_some() {
        points(t, "position", env, 1, 3)?[0]
    } else {
        Vec3::zeros()
    };
    let mut part = Part::new(name, shape, amount).at(position);
    if t.get("axis").is_some() {
        let a = direction(t, "axis", env)?;
        part = part.along(a);
    }
    if let Some(r) = t.table("rotation")? {
        r.check_keys(&["axis", "angle"])?;
        let axis = direction(&r, "axis", env)?;
        let angle = required_scalar(&r, "angle", Dimension::NONE, env)?;
        part = part.rotated(Rotation3::from_axis_angle(
            &nalgebra::Unit::new_normalize(axis),
            angle,
        ));
    }
    match t.get("hole").map(|v| (v.get_ref(), v)) {
        Some((DeValue::Boolean(true), _)) => part = part.hole(),
        None | Some((DeValue::Boolean(false), _)) => {}
        Some((_, v)) => return Err(t.wrong_type("hole", v, "true or false")),
    }
    Ok(part)
}

/// The density's dimension for a shape: kg/m, kg/m² or kg/m³.
fn density_dimension(extent: Extent) -> Option<Dimension> {
    let per = match extent {
        Extent::Line => 1,
        Extent::Surface => 2,
        Extent::Solid => 3,
        Extent::Point => return None,
    };
    Some(Dimension::MASS / Dimension::LENGTH.powi(per))
}

fn amount(
    t: &Table<'_, '_>,
    shape: &Shape,
    env: ValueEnv<'_>,
    default_density: Option<&((Real, Dim), Range<usize>)>,
) -> Result<Amount, ScenarioError> {
    let want = density_dimension(shape.extent());
    let mass = scalar(t, "mass", Dimension::MASS, env)?;
    let density = match (t.get("density"), want) {
        (Some(v), Some(d)) => Some(resolve(&t.src, "density", v, d, env)?),
        (Some(_), None) => {
            return Err(invalid(
                t,
                "density",
                "a point has no density; give its `mass`".into(),
            ));
        }
        (None, _) => None,
    };
    let positive = |key: &str, x: Real| {
        if crate::invertible(x) {
            Ok(x)
        } else {
            Err(invalid(
                t,
                key,
                format!(
                    "`{key}` is {}; it must be positive and at least 2.2e-308 (to remove material write `hole = true`)",
                    crate::error::short(x)
                ),
            ))
        }
    };
    match (mass, density) {
        (Some(_), Some(_)) => Err(invalid(
            t,
            "density",
            "give the part a `mass` or a `density`, not both".into(),
        )),
        (Some(m), None) => Ok(Amount::Mass(positive("mass", m)?)),
        (None, Some(rho)) => Ok(Amount::Density(positive("density", rho)?)),
        (None, None) => {
            let example = want.map_or("\"1 kg\"".to_string(), |d| {
                format!("\"{} {}\"", 1000, super::observe::unit_text(d))
            });
            let Some(((rho, dim), span)) = default_density else {
                return Err(t
                    .missing("mass", "\"1 kg\"")
                    .with_hint(format!(
                        "give the {} a `mass = \"1 kg\"` or a `density = {example}`, or a `density` for all parts at the top of the file",
                        shape.name()
                    )));
            };
            match (dim, want) {
                (_, None) => Err(t.missing("mass", "\"1 kg\"").with_hint(
                    "a point takes its `mass`; the file's density does not apply to it",
                )),
                (Dim::Known(d), Some(w)) if *d != w => Err(t
                    .src
                    .error(
                        ErrorKind::Dimension,
                        format!(
                            "the file's density has dimension {}, but this {} needs {}",
                            dim_text(*d),
                            shape.name(),
                            dim_text(w)
                        ),
                        span.clone(),
                    )
                    .with_hint(format!(
                        "give this part its own `density = {example}` or a `mass`"
                    ))),
                _ => Ok(Amount::Density(positive("density", *rho)?)),
            }
        }
    }
}
