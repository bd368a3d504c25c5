//! Reading a `[[rigid_body]]` in space: its mass, inertia tensor, initial state (position,
//! orientation, velocity, angular velocity) and named points.

use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use crate::Real;
use crate::particles::spin::{self, Mat3, Quat};
use crate::scenario::build::body_name;
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::rigid::bodies::{mass_properties, outline_of_moment};
use crate::scenario::values::{ValueEnv, required_scalar, resolve, vector};

use super::points::read_points;
use super::{Rigid, RigidTurn};

const SPATIAL_RIGID_KEYS: &[&str] = &[
    "name",
    "free",
    "part",
    "body",
    "mass",
    "inertia",
    "position",
    "velocity",
    "orientation",
    "omega",
    "points",
];

/// Field names of a rigid body in space: a point cannot take one.
const FIELDS: &[&str] = &[
    "x", "y", "z", "vx", "vy", "vz", "ax", "ay", "az", "v", "a", "r", "m", "K", "speed", "wx",
    "wy", "wz", "w1", "w2", "w3", "omega", "q0", "q1", "q2", "q3", "Lx", "Ly", "Lz", "L", "alphax",
    "alphay", "alphaz",
];

/// Reads the `[[rigid_body]]` `t`, the `index`th of `count`, whose name must differ from
/// `taken`; `dir` is where its `body` file is looked for.
pub(super) fn read_rigid3(
    t: &Table<'_, '_>,
    index: usize,
    count: usize,
    taken: &[String],
    env: ValueEnv<'_>,
    dir: Option<&std::path::Path>,
) -> Result<Rigid, ScenarioError> {
    t.check_keys(SPATIAL_RIGID_KEYS)?;
    let name = body_name(t, index, count, taken, "wx")?;
    super::check_free(
        t,
        "`free` must be true: in space every rigid body is free",
        "a body turning about a fixed axis is a [[rigid_body]] of a scenario without `dimensions`",
    )?;
    let (mass, inertia, cm, outline) = if t.get("inertia").is_some() {
        let mass = required_scalar(t, "mass", Dimension::MASS, env)?;
        let inertia = inertia(t, env)?;
        let outline = outline_of_moment(mass, inertia[2][2], crate::mass::Vec3::zeros());
        (mass, inertia, [0.0; 3], outline)
    } else if t.get("mass").is_some() {
        return Err(t
            .missing("inertia", "[\"0.1 kg m^2\", \"0.1 kg m^2\", \"0.2 kg m^2\"]")
            .with_hint("give the inertia about the centre of mass: one moment (a sphere), the three principal moments along the body axes, or the 3×3 tensor; or describe the body by `[[rigid_body.part]]` tables or a `body` file"));
    } else {
        let (props, body) = mass_properties(t, env, dir)?;
        let c = props.centre_of_mass;
        let i = props.inertia;
        (
            props.mass,
            [0, 1, 2].map(|r| [0, 1, 2].map(|k| i[(r, k)])),
            [c[0], c[1], c[2]],
            body.outline(c),
        )
    };
    if !crate::invertible(mass) {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                crate::scenario::error::positive_message(
                    &format!("the mass of rigid body `{name}`"),
                    mass,
                    "kg",
                ),
                t.key_span("mass"),
            )
            .with_hint("a rigid body needs a positive mass and inertia"));
    }
    let m = nalgebra::Matrix3::from_fn(|r, c| inertia[r][c]);
    let mut moments: Vec<Real> = m.symmetric_eigen().eigenvalues.iter().copied().collect();
    moments.sort_by(Real::total_cmp);
    let problem = if spin::invert_spd(&inertia).is_none() {
        Some(format!(
            "the inertia of rigid body `{name}` must be a symmetric tensor with positive principal moments, not ({})",
            inertia
                .map(|row| crate::error::short_tuple(&row))
                .join(", ")
        ))
    } else if moments[2] > (moments[0] + moments[1]) * (1.0 + 1e-9) {
        Some(format!(
            "no body has the principal moments {} of rigid body `{name}`: the largest must be at most the sum of the other two",
            crate::error::short_tuple(&moments)
        ))
    } else {
        None
    };
    if let Some(message) = problem {
        return Err(t
            .src
            .error(ErrorKind::Invalid, message, t.key_span("inertia"))
            .with_hint("give the moments about the centre of mass: a sphere has one moment, a box three, e.g. [\"0.1 kg m^2\", \"0.2 kg m^2\", \"0.25 kg m^2\"]"));
    }
    let three = |key: &str, want: Dimension| -> Result<[Real; 3], ScenarioError> {
        Ok(vector(t, key, want, 3, env)?.map_or([0.0; 3], |v| [v[0], v[1], v[2]]))
    };
    let points = read_points(t, &name, env, 3, cm, FIELDS)?;
    Ok(Rigid {
        outline,
        name,
        mass,
        position: three("position", Dimension::LENGTH)?.to_vec(),
        velocity: three("velocity", Dimension::VELOCITY)?.to_vec(),
        points,
        turn: RigidTurn::Space {
            inertia,
            orientation: orientation(t, env)?,
            omega: three("omega", Dimension::FREQUENCY)?,
        },
    })
}

/// `inertia`: one moment (`I` times the identity), three principal moments along the body
/// axes, or a 3×3 tensor.
fn inertia(t: &Table<'_, '_>, env: ValueEnv<'_>) -> Result<Mat3, ScenarioError> {
    let v = t.get("inertia").expect("checked by the caller");
    let want = Dimension::MOMENT_OF_INERTIA;
    let one = |item| resolve(&t.src, "inertia", item, want, env);
    let hint = "one moment \"0.4 kg m^2\", three principal moments [I1, I2, I3], or a 3×3 tensor [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]]";
    match v.get_ref() {
        DeValue::Array(rows) if rows.len() == 3 => {
            if rows
                .iter()
                .all(|r| matches!(r.get_ref(), DeValue::Array(_)))
            {
                let mut m = [[0.0; 3]; 3];
                for (i, row) in rows.iter().enumerate() {
                    let DeValue::Array(items) = row.get_ref() else {
                        unreachable!("checked above")
                    };
                    if items.len() != 3 {
                        return Err(t
                            .component_count("inertia", items.len(), 3, row.span())
                            .with_hint(hint));
                    }
                    for (k, item) in items.iter().enumerate() {
                        m[i][k] = one(item)?;
                    }
                }
                Ok(m)
            } else {
                let d = [one(&rows[0])?, one(&rows[1])?, one(&rows[2])?];
                Ok([[d[0], 0.0, 0.0], [0.0, d[1], 0.0], [0.0, 0.0, d[2]]])
            }
        }
        DeValue::Array(rows) => Err(t
            .component_count("inertia", rows.len(), 3, v.span())
            .with_hint(hint)),
        _ => {
            let i = one(v)?;
            Ok([[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]])
        }
    }
}

/// `orientation`: a quaternion `[w, x, y, z]` (normalised), or `{ axis = [x, y, z], angle = … }`;
/// the identity when absent.
fn orientation(t: &Table<'_, '_>, env: ValueEnv<'_>) -> Result<Quat, ScenarioError> {
    let Some(v) = t.get("orientation") else {
        return Ok([1.0, 0.0, 0.0, 0.0]);
    };
    let hint = "write `orientation = [w, x, y, z]` (a quaternion, body → world) or `orientation = { axis = [0, 0, 1], angle = \"30 deg\" }`";
    let span = v.span();
    let q = if let DeValue::Table(table) = v.get_ref() {
        let p = Table::new(t.src, table, v.span(), "`orientation`");
        p.check_keys(&["axis", "angle"])?;
        let axis = vector(&p, "axis", Dimension::NONE, 3, env)?
            .ok_or_else(|| p.missing("axis", "[0, 0, 1]"))?;
        let angle = required_scalar(&p, "angle", Dimension::NONE, env)?;
        let n = axis.iter().map(|x| x * x).sum::<Real>().sqrt();
        if !(n > 0.0 && n.is_finite() && angle.is_finite()) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "the axis {} has no direction",
                        crate::error::short_tuple(&axis)
                    ),
                    p.key_span("axis"),
                )
                .with_hint(hint));
        }
        let (s, c) = (0.5 * angle).sin_cos();
        [c, s * axis[0] / n, s * axis[1] / n, s * axis[2] / n]
    } else {
        let q = vector(t, "orientation", Dimension::NONE, 4, env)
            .map_err(|e| e.with_hint(hint))?
            .unwrap_or_default();
        [q[0], q[1], q[2], q[3]]
    };
    let n = spin::norm2(q).sqrt();
    if !(n > 0.0 && n.is_finite()) {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "the orientation {} is not a rotation (its length is {})",
                    crate::error::short_tuple(&q),
                    crate::error::short(n)
                ),
                span,
            )
            .with_hint(hint));
    }
    Ok(q.map(|x| x / n))
}
