//! Bodies that eject mass (`mass_rate`, `exhaust_speed`, `burnout_mass`,
//! `thrust_direction` in a `[[body]]`): the rocket as a scenario.

use mechkit_expr::units::Dimension;

use super::build::ROCKET_KEYS;
use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::values::{Constant, ValueEnv, scalar, vector};
use crate::Real;

/// A body that ejects mass.
pub(crate) struct RocketBody {
    pub body: usize,
    /// `|dm/dt|` while burning (kg/s).
    pub rate: Real,
    /// Exhaust speed relative to the body (m/s).
    pub exhaust_speed: Real,
    /// Mass when the burn ends (kg).
    pub burnout_mass: Real,
    /// Unit thrust direction.
    pub direction: Vec<Real>,
}

/// Reads the rocket keys of every `[[body]]` (bodies without them are not rockets).
pub(crate) fn read_rockets(
    root: &Table<'_, '_>,
    dim: usize,
    names: &[String],
    masses: &[Real],
    constants: &[Constant],
) -> Result<Vec<RocketBody>, ScenarioError> {
    let env = ValueEnv {
        constants,
        mass: None,
        later: &[],
    };
    let mut out = Vec::new();
    for (b, t) in root.tables("body")?.iter().enumerate() {
        if !ROCKET_KEYS.iter().any(|k| t.get(k).is_some()) {
            continue;
        }
        let name = &names[b];
        let need = |key: &str, want: Dimension, example: &str| -> Result<Real, ScenarioError> {
            let v = scalar(t, key, want, env)?.ok_or_else(|| {
                t.missing(key, example).with_hint(format!(
                    "a body that ejects mass needs `mass_rate`, `exhaust_speed` and `burnout_mass`: `{name}` lacks `{key}`"
                ))
            })?;
            if !(v > 0.0 && v.is_finite()) {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        format!("`{key}` of `{name}` must be positive, not {v}"),
                        t.key_span(key),
                    )
                    .with_hint(format!("for example {key} = {example}")));
            }
            Ok(v)
        };
        let rate = need("mass_rate", Dimension::LINEAR_DRAG, "\"2 kg/s\"")?;
        let exhaust_speed = need("exhaust_speed", Dimension::VELOCITY, "\"2500 m/s\"")?;
        let burnout_mass = need("burnout_mass", Dimension::MASS, "\"100 kg\"")?;
        if burnout_mass >= masses[b] {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`burnout_mass` = {burnout_mass} kg of `{name}` is not below its starting mass {} kg",
                        masses[b]
                    ),
                    t.key_span("burnout_mass"),
                )
                .with_hint("the body burns from `mass` down to `burnout_mass`: the dry mass is the smaller"));
        }
        let direction =
            vector(t, "thrust_direction", Dimension::NONE, dim, env)?.unwrap_or_else(|| {
                let mut up = vec![0.0; dim];
                up[dim - 1] = 1.0;
                up
            });
        let len = direction.iter().map(|x| x * x).sum::<Real>().sqrt();
        if !(len > 0.0 && len.is_finite()) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    "`thrust_direction` must not be zero",
                    t.key_span("thrust_direction"),
                )
                .with_hint(
                    "the direction the thrust pushes the body; up (the last axis) by default",
                ));
        }
        out.push(RocketBody {
            body: b,
            rate,
            exhaust_speed,
            burnout_mass,
            direction: direction.iter().map(|x| x / len).collect(),
        });
    }
    Ok(out)
}
