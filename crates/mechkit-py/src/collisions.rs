//! `mechkit.collide(m1, v1, m2, v2, restitution=...)`: `mechkit collide` from Python, two
//! bodies colliding with a coefficient of restitution (and Coulomb friction) in 1-D, 2-D or
//! 3-D: the library's `CollisionSetup::report`, as the command's `--json` (a dict).

use mechkit::collisions::{CollisionError, CollisionInput, CollisionSetup, Contact, Restitution};
use mechkit::units::Dimension;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arguments::{Scalar, error, from_json, json_error, quantity, scalar, vector};

/// The argument an input of the collision is given by.
fn argument(e: &CollisionError) -> Option<&'static str> {
    Some(match e.input()? {
        CollisionInput::Mass1 => "m1",
        CollisionInput::Mass2 => "m2",
        CollisionInput::Velocity1 => "v1",
        CollisionInput::Velocity2 => "v2",
        CollisionInput::Restitution => "restitution",
        CollisionInput::Normal if matches!(e, CollisionError::NormalNeeded { .. }) => {
            "normal (or r1 and r2)"
        }
        CollisionInput::Normal => "normal",
        CollisionInput::Centres => "r1/r2",
        CollisionInput::Friction => "friction",
        CollisionInput::Gravity => "g",
        _ => return None,
    })
}

/// The library's error with the argument it is about.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
fn collision_error(e: CollisionError) -> PyErr {
    match argument(&e) {
        Some(name) => error(format!("{name}: {e}")),
        None => error(e.to_string()),
    }
}

/// A mass: a number (`inf` for an immovable body), or a string with units or `"inf"`
/// (`"wall"`); its sign is checked by the library.
fn mass(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    match scalar(obj, name)? {
        Scalar::Number(m) if m == f64::INFINITY => Ok(m),
        Scalar::Text(t)
            if ["inf", "infinity", "∞", "wall"]
                .contains(&t.trim().to_ascii_lowercase().as_str()) =>
        {
            Ok(f64::INFINITY)
        }
        _ => quantity(obj, name, Dimension::MASS),
    }
}

/// A coefficient of restitution: a number, or `"elastic"` / `"perfectly-inelastic"`.
fn restitution(obj: &Bound<'_, PyAny>) -> PyResult<Restitution> {
    match scalar(obj, "restitution")? {
        Scalar::Number(e) => Restitution::new(e),
        Scalar::Text(t) => Restitution::parse(&t),
    }
    .map_err(collision_error)
}

/// `mechkit collide` as a function: two bodies collide with a coefficient of `restitution`
/// (0 to 1, `"elastic"` or `"perfectly-inelastic"`); the result is the command's `--json`
/// (a dict: `collided`, and the velocities after, the impulse on body 2, the kinetic energy
/// lost, the centre-of-mass frame).
///
/// Masses are numbers (kg), strings with units, or `float("inf")` / `"wall"` for an
/// immovable body; velocities have 1 to 3 components (`2`, `"3, -1 m/s"`, `[3, -1]`; a
/// single 0 is at rest in any dimension). In 2-D/3-D give the contact `normal` from body 1
/// to body 2, or the sphere centres `r1` and `r2`; `friction` is Coulomb's coefficient along
/// the contact plane; with `g` each body's rise `v²/(2g)` afterwards.
#[pyfunction]
#[pyo3(signature = (m1, v1, m2, v2, *, restitution, normal = None, r1 = None, r2 = None, friction = None, g = None))]
#[allow(clippy::too_many_arguments)] // the command's flags
pub fn collide<'py>(
    py: Python<'py>,
    m1: &Bound<'py, PyAny>,
    v1: &Bound<'py, PyAny>,
    m2: &Bound<'py, PyAny>,
    v2: &Bound<'py, PyAny>,
    restitution: &Bound<'py, PyAny>,
    normal: Option<&Bound<'py, PyAny>>,
    r1: Option<&Bound<'py, PyAny>>,
    r2: Option<&Bound<'py, PyAny>>,
    friction: Option<&Bound<'py, PyAny>>,
    g: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let contact = match (normal, r1, r2) {
        (Some(n), None, None) => Contact::Normal(vector(n, "normal", Dimension::NONE)?),
        (None, Some(a), Some(b)) => Contact::Centres {
            r1: vector(a, "r1", Dimension::LENGTH)?,
            r2: vector(b, "r2", Dimension::LENGTH)?,
        },
        (None, None, None) => Contact::HeadOn,
        (Some(_), _, _) => {
            return Err(error(
                "give either normal or the centres r1 and r2, not both",
            ));
        }
        _ => return Err(error("give both centres, r1 and r2")),
    };
    let setup = CollisionSetup {
        m1: mass(m1, "m1")?,
        m2: mass(m2, "m2")?,
        v1: vector(v1, "v1", Dimension::VELOCITY)?,
        v2: vector(v2, "v2", Dimension::VELOCITY)?,
        restitution: self::restitution(restitution)?,
        contact,
        friction: friction.map_or(Ok(0.0), |f| quantity(f, "friction", Dimension::NONE))?,
        g: g.map(|g| quantity(g, "g", Dimension::ACCELERATION))
            .transpose()?,
    };
    let report = setup.report().map_err(collision_error)?;
    from_json(py, &serde_json::to_string(&report).map_err(json_error)?)
}
