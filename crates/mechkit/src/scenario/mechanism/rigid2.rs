//! Reading a `[[rigid_body]]` in a plane (`dimensions = 2`): its mass, moment of inertia, initial state and named
//! points.

use mechkit_expr::units::Dimension;

use crate::Real;
use crate::scenario::build::body_name;
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::rigid::bodies::{mass_properties, outline_of_moment};
use crate::scenario::values::{ValueEnv, scalar, vector};

use super::points::read_points;
use super::{Rigid, RigidTurn};

const PLANAR_RIGID_KEYS: &[&str] = &[
    "name", "free", "part", "body", "mass", "inertia", "position", "velocity", "theta", "omega",
    "points",
];

/// Reads the `[[rigid_body]]` `t`, the `index`th of `count`, whose name must differ from
/// `taken`; `dir` is where its `body` file is looked for.
pub(super) fn read_rigid2(
    t: &Table<'_, '_>,
    index: usize,
    count: usize,
    taken: &[String],
    env: ValueEnv<'_>,
    dir: Option<&std::path::Path>,
) -> Result<Rigid, ScenarioError> {
    t.check_keys(PLANAR_RIGID_KEYS)?;
    let name = body_name(t, index, count, taken, "theta")?;
    super::check_free(
        t,
        "`free` must be true: in a plane every rigid body is free unless a [[joint]] holds it",
        "hinge it with a [[joint]] of kind \"hinge\", or leave out `dimensions` for a body turning about a fixed axis",
    )?;
    // the body frame's origin: the centre of mass, or the parts' frame
    let (mass, inertia, cm, outline) = if t.get("inertia").is_some() {
        let mass = scalar(t, "mass", Dimension::MASS, env)?
            .ok_or_else(|| t.missing("mass", "\"1 kg\""))?;
        let inertia = scalar(t, "inertia", Dimension::MOMENT_OF_INERTIA, env)?.unwrap_or(0.0);
        let outline = outline_of_moment(mass, inertia, crate::mass::Vec3::zeros());
        (mass, inertia, [0.0, 0.0], outline)
    } else if t.get("mass").is_some() {
        return Err(t
            .missing("inertia", "\"0.5 kg m^2\"")
            .with_hint("give the moment of inertia about the centre of mass, or describe the body by `[[rigid_body.part]]` tables or a `body` file"));
    } else {
        let (props, body) = mass_properties(t, env, dir)?;
        let c = props.centre_of_mass;
        let outline = body.outline(c);
        (props.mass, props.inertia[(2, 2)], [c[0], c[1]], outline)
    };
    for (key, value, span) in [
        ("mass", mass, t.key_span("mass")),
        ("inertia", inertia, t.key_span("inertia")),
    ] {
        if !crate::invertible(value) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    crate::scenario::error::positive_message(
                        &format!("the {key} of rigid body `{name}`"),
                        value,
                        "",
                    ),
                    span,
                )
                .with_hint("a particle (no rotation) is a [[body]]; a rigid body needs a mass and a moment of inertia about its centre of mass"));
        }
    }
    let two = |key: &str, want: Dimension| -> Result<[Real; 2], ScenarioError> {
        Ok(vector(t, key, want, 2, env)?.map_or([0.0; 2], |v| [v[0], v[1]]))
    };
    let points = read_points(
        t,
        &name,
        env,
        2,
        [cm[0], cm[1], 0.0],
        &[
            "x", "y", "vx", "vy", "theta", "omega", "alpha", "K", "m", "v", "r",
        ],
    )?;
    Ok(Rigid {
        name,
        mass,
        position: two("position", Dimension::LENGTH)?.to_vec(),
        velocity: two("velocity", Dimension::VELOCITY)?.to_vec(),
        points,
        outline,
        turn: RigidTurn::Plane {
            inertia,
            theta: scalar(t, "theta", Dimension::NONE, env)?.unwrap_or(0.0),
            omega: scalar(t, "omega", Dimension::FREQUENCY, env)?.unwrap_or(0.0),
        },
    })
}
