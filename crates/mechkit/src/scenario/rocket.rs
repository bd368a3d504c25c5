//! Bodies that eject mass (`mass_rate`, `exhaust_speed`, `burnout_mass`,
//! `thrust_direction` in a `[[body]]`): the rocket as a scenario.

use mechkit_expr::units::Dimension;

use super::build::ROCKET_KEYS;
use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::values::{Constant, ValueEnv, scalar, vector};
use crate::Real;
use crate::particles::ParticleSystemBuilder;
use crate::simulate::{Direction, Event};

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

/// What the rockets add to a particle system after its bodies' coordinates: one mass
/// coordinate each (`q` the starting mass, `v` the rate), their burnout events, and
/// `(body, index in q)` of each mass.
pub(crate) struct Rockets {
    pub q: Vec<Real>,
    pub v: Vec<Real>,
    pub events: Vec<Event>,
    pub variable: Vec<(usize, usize)>,
}

/// Reads the rockets among the `[[body]]`s and adds to `builder` their thrust and exhaust
/// (named in `force_names`) and their mass coordinates.
pub(crate) fn add_rockets(
    root: &Table<'_, '_>,
    dim: usize,
    (bodies, masses): (&[String], &[Real]),
    constants: &[Constant],
    mut builder: ParticleSystemBuilder,
    force_names: &mut Vec<String>,
) -> Result<(ParticleSystemBuilder, Rockets), ScenarioError> {
    let rockets = read_rockets(root, dim, bodies, masses, constants)?;
    let first_extra = dim * bodies.len();
    let mut out = Rockets {
        q: Vec::new(),
        v: Vec::new(),
        events: Vec::new(),
        variable: Vec::new(),
    };
    for (k, r) in rockets.iter().enumerate() {
        let coord = first_extra + k;
        let name = &bodies[r.body];
        let (thrust, exhaust) = if rockets.len() == 1 {
            ("thrust".to_string(), "exhaust".to_string())
        } else {
            (format!("{name}_thrust"), format!("{name}_exhaust"))
        };
        if let Some(n) = [&thrust, &exhaust]
            .into_iter()
            .find(|n| force_names.contains(n))
        {
            return Err(root
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("a force is named `{n}`, the name of the rocket's own entry in the ledger"),
                    root.key_span("force"),
                )
                .with_hint("rename that [[force]]: a body with `mass_rate` brings its `thrust` and `exhaust`"));
        }
        builder = builder
            .force(crate::forces::Thrust::new(
                thrust.clone(),
                r.body,
                coord,
                r.exhaust_speed,
                r.direction.clone(),
            ))
            .force(crate::forces::Exhaust::new(exhaust.clone(), r.body, coord))
            .variable_mass(format!("{name}.m"), r.body);
        force_names.push(thrust);
        force_names.push(exhaust);
        out.q.push(masses[r.body]);
        out.v.push(-r.rate);
        out.variable.push((r.body, coord));
        let m1 = r.burnout_mass;
        out.events.push(
            Event::new(format!("{name} burnout"), move |s, _| s.q[coord] - m1)
                .direction(Direction::Falling)
                .max_count(1)
                .set(move |s, _, y| {
                    let n = s.q.len();
                    y[coord] = m1;
                    y[n + coord] = 0.0;
                }),
        );
    }
    Ok((builder, out))
}

/// Reads the rocket keys of every `[[body]]` (bodies without them are not rockets).
fn read_rockets(
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
                        format!(
                            "`{key}` of `{name}` must be positive, not {}",
                            crate::error::short(v)
                        ),
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
                        "`burnout_mass` = {} kg of `{name}` is not below its starting mass {} kg",
                        crate::error::short(burnout_mass),
                        crate::error::short(masses[b])
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
