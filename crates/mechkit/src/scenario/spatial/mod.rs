//! A scenario in space (`dimensions = 3`) with free `[[rigid_body]]`s: each body's centre of
//! mass among the particle system's positions, its orientation a quaternion of four extra
//! coordinates turned by Euler's equations ([`crate::particles::spin`]), run as one particle
//! system with the particles of `[[body]]`.

mod rigid;

use super::Scenario;
use super::build::{Model, ROCKET_KEYS, assemble, bodies};
use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::forces::{ForceContext, force_at};
use super::integrator::read_integrator;
use super::values::{Constant, ValueEnv};
use crate::ode::State;
use crate::particles::spin::rate_for;
use crate::particles::{ParticleSystem, PlanarNames, RigidName, SpinRef};
use rigid::read_rigid;

/// Builds a scenario of rigid bodies in space.
pub(crate) fn build_spatial(
    name: &str,
    root: &Table<'_, '_>,
    title: String,
    constants: Vec<Constant>,
    rigid_tables: &[Table<'_, '_>],
) -> Result<Scenario, ScenarioError> {
    let src = root.src;
    for key in ["torque", "contact", "wall", "plane", "joint"] {
        if let Some(v) = root.get(key) {
            let hint = if key == "joint" {
                "joints hold bodies in a plane (`dimensions = 2`); in space, bodies are free: apply forces at their points (`at = \"body.point\"`) and torques (kind \"torque\")"
            } else {
                "torques are [[force]]s of kind \"torque\" (or forces applied at body points, `at = \"body.point\"`)"
            };
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "a scenario of rigid bodies in space (`dimensions = 3`) cannot have `{key}`"
                    ),
                    v.span(),
                )
                .with_hint(hint));
        }
    }
    let env = ValueEnv {
        constants: &constants,
        mass: None,
        later: &[],
    };
    let (mut names, mut masses, mut q, mut v, _radius) = if root.get("body").is_some() {
        bodies(root, 3, &constants)?
    } else {
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new())
    };
    for t in root.tables("body")? {
        if let Some(key) = ROCKET_KEYS.iter().find(|k| t.get(k).is_some()) {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("`{key}`: a body that ejects mass does not yet fly with rigid bodies"),
                    t.key_span(key),
                )
                .with_hint("run the rocket in a scenario without [[rigid_body]]"));
        }
    }
    let n_particles = names.len();
    let dir = std::path::Path::new(name).parent();
    let mut rigid = Vec::new();
    for (i, t) in rigid_tables.iter().enumerate() {
        let r = read_rigid(t, i, rigid_tables.len(), &names, env, dir)?;
        names.push(r.name.clone());
        masses.push(r.mass);
        q.extend(r.position);
        v.extend(r.velocity);
        rigid.push(r);
    }
    let n_bodies = names.len();
    // coordinates: positions, then four per rigid body (its quaternion)
    let first = |k: usize| 3 * n_bodies + 4 * k;
    let turning = PlanarNames {
        rigid: rigid
            .iter()
            .enumerate()
            .map(|(k, r)| RigidName {
                body: n_particles + k,
                angle: first(k),
                inertia: 0.0,
                points: r.points.clone(),
                spin: Some(SpinRef::new(n_particles + k, first(k), &r.inertia)),
            })
            .collect(),
        extras: 4 * rigid.len(),
        ..PlanarNames::default()
    };
    let fctx = ForceContext {
        dim: 3,
        bodies: &names,
        masses: &masses,
        constants: &constants,
        rigid: &turning,
    };
    let mut builder = ParticleSystem::builder(3);
    for (b, m) in names.iter().zip(&masses) {
        builder = builder.body(b.clone(), *m);
    }
    let mut force_names: Vec<String> = Vec::new();
    for (i, t) in root.tables("force")?.iter().enumerate() {
        let f = force_at(t, &fctx, i)?;
        if force_names.iter().any(|n| n == f.name()) || names.iter().any(|n| n == f.name()) {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("two forces are named `{}`", f.name()),
                    t.key_span("name"),
                )
                .with_hint(
                    "give each [[force]] its own `name`; the energy ledger lists work by name",
                ));
        }
        force_names.push(f.name().to_string());
        builder = builder.boxed_force(f);
    }
    for (k, r) in rigid.iter().enumerate() {
        builder = builder.spinner(&r.name, n_particles + k, r.inertia);
        q.extend(r.orientation);
        v.extend(rate_for(r.orientation, r.omega));
    }
    let mut warnings = Vec::new();
    if force_names.is_empty() {
        warnings.push(
            "no [[force]] is defined: the bodies move in straight lines and turn freely".into(),
        );
    }
    let system = builder
        .build()
        .map_err(|e| ScenarioError::new(ErrorKind::Invalid, e.to_string()))?;
    let stepping = read_integrator(root, env, &system)?;
    assemble(
        root,
        Model {
            name,
            title,
            dim: 3,
            constants,
            system,
            initial: State::from_qv(0.0, &q, &v),
            stepping,
            bodies: names,
            forces: force_names,
            events: Vec::new(),
            warnings,
            planar: turning,
        },
    )
}
