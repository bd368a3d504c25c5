//! A scenario in a plane (`dimensions = 2`) with free `[[rigid_body]]`s and `[[joint]]`s: a
//! planar mechanism ([`crate::rigid::planar`]) run as one particle system.

mod contact;
mod joints;
mod rigid;

use std::sync::Arc;

use mechkit_expr::units::Dimension;

use super::Scenario;
use super::build::{Model, assemble, bodies};
use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::forces::{ForceContext, force_at};
use super::integrator::read_integrator;
use super::values::{Constant, ValueEnv, scalar};
use crate::ode::State;
use crate::particles::{ParticleSystem, PlanarNames, RigidName};
use crate::rigid::planar::{Joint, JointForce, Mechanism, PlanarBody};
use crate::simulate::Stepping;
use joints::{Names, read_joint};
use rigid::read_rigid;

/// Builds a planar mechanism scenario.
pub(crate) fn build_planar(
    name: &str,
    root: &Table<'_, '_>,
    title: String,
    constants: Vec<Constant>,
    rigid_tables: &[Table<'_, '_>],
) -> Result<Scenario, ScenarioError> {
    let src = root.src;
    for key in ["torque", "contact", "wall", "plane"] {
        if let Some(v) = root.get(key) {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("a scenario of free rigid bodies (`dimensions = 2`) cannot have `{key}`"),
                    v.span(),
                )
                .with_hint("surfaces are [[joint]]s of kind \"contact\" (with `surface`, `mu_s`, `mu_k`); torques are forces applied at body points"));
        }
    }
    let env = ValueEnv {
        constants: &constants,
        mass: None,
        later: &[],
    };
    let (mut names, mut masses, mut q, mut v, _radius) = if root.get("body").is_some() {
        bodies(root, 2, &constants)?
    } else {
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new())
    };
    for t in root.tables("body")? {
        if let Some(key) = super::build::ROCKET_KEYS
            .iter()
            .find(|k| t.get(k).is_some())
        {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`{key}`: a body that ejects mass is not yet part of a mechanism in a plane"
                    ),
                    t.key_span(key),
                )
                .with_hint("run the rocket in a scenario without [[rigid_body]] and [[joint]]"));
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
    let joint_tables = root.tables("joint")?;

    // coordinates: positions, then one angle per rigid body, then the joints' modes
    let angle_of = |k: usize| 2 * n_bodies + k;
    let mut planar_bodies: Vec<PlanarBody> = (0..n_particles)
        .map(|b| PlanarBody {
            x: 2 * b,
            angle: None,
            inv_mass: 1.0 / masses[b],
            inv_inertia: 0.0,
        })
        .collect();
    for (k, r) in rigid.iter().enumerate() {
        planar_bodies.push(PlanarBody {
            x: 2 * (n_particles + k),
            angle: Some(angle_of(k)),
            inv_mass: 1.0 / r.mass,
            inv_inertia: 1.0 / r.inertia,
        });
    }
    let mut modes: Vec<String> = Vec::new();
    let mut joints = Vec::new();
    let ctx = Names {
        bodies: &names,
        n_particles,
        rigid: &rigid,
        env,
    };
    for (i, t) in joint_tables.iter().enumerate() {
        let j = read_joint(t, i, &ctx, &q, &mut modes, angle_of(rigid.len()))?;
        if names.contains(&j.name) || joints.iter().any(|o: &Joint| o.name == j.name) {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "the name `{}` is taken: joints, bodies and forces need names of their own",
                        j.name
                    ),
                    t.key_span("name"),
                )
                .with_hint("give the [[joint]] another `name`"));
        }
        joints.push(j);
    }
    let dof = 2 * n_bodies + rigid.len() + modes.len();
    let mechanism = Arc::new(Mechanism::new(planar_bodies, joints, dof));

    let rigid_names: Vec<RigidName> = rigid
        .iter()
        .enumerate()
        .map(|(k, r)| RigidName {
            body: n_particles + k,
            angle: angle_of(k),
            inertia: r.inertia,
            points: r
                .points
                .iter()
                .map(|(n, p)| (n.clone(), [p[0], p[1], 0.0]))
                .collect(),
            spin: None,
        })
        .collect();
    // what force formulas may read: the bodies' angles and angular velocities
    let turning = PlanarNames {
        rigid: rigid_names.clone(),
        ..PlanarNames::default()
    };
    let fctx = ForceContext {
        dim: 2,
        bodies: &names,
        masses: &masses,
        constants: &constants,
        rigid: &turning,
    };
    let mut builder = ParticleSystem::builder(2);
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
    let first_joint = force_names.len();
    let mut joint_names = Vec::new();
    for (ji, j) in mechanism.joints().iter().enumerate() {
        if force_names.contains(&j.name) {
            return Err(ScenarioError::new(
                ErrorKind::Invalid,
                format!("the joint `{}` has the name of a force", j.name),
            )
            .with_hint(
                "joints are booked in the energy ledger with the forces: give it another name",
            ));
        }
        joint_names.push((j.name.clone(), force_names.len()));
        force_names.push(j.name.clone());
        builder = builder.force(JointForce::new(
            Arc::clone(&mechanism),
            ji,
            (0..n_bodies).collect(),
        ));
    }
    for (k, r) in rigid.iter().enumerate() {
        builder = builder.rotor(r.name.clone(), n_particles + k, r.inertia);
        q.push(r.theta);
        v.push(r.omega);
    }
    for m in &modes {
        builder = builder.mode(m.clone());
        q.push(0.0);
        v.push(0.0);
    }
    let mut warnings = Vec::new();
    if force_names.is_empty() {
        warnings.push("no [[force]] is defined: the bodies move in straight lines".into());
    }
    let system = builder
        .build()
        .map_err(|e| ScenarioError::new(ErrorKind::Invalid, e.to_string()))?;
    let stepping = read_integrator(root, env, &system)?;
    let tau = match scalar(root, "stabilisation", Dimension::TIME, env)? {
        Some(tau) if tau > 0.0 => tau,
        Some(tau) => {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("`stabilisation` must be a positive time, not {tau} s"),
                    root.key_span("stabilisation"),
                )
                .with_hint("the time constant over which joints pull a drift back: \"10 ms\""));
        }
        None => match &stepping {
            Stepping::Fixed { dt, .. } => 10.0 * dt,
            Stepping::Adaptive { .. } => 1e-2,
        },
    };
    mechanism.set_tau(tau);
    let scale = q[..2 * n_bodies]
        .iter()
        .fold(0.0_f64, |m, x| m.max(x.abs()))
        .max(1.0);
    mechanism.initial_modes(&system, &mut q, &mut v, 1e-9 * scale);
    if let Some((ji, c)) = mechanism.violation(&q, &v, 1e-6 * scale) {
        let joint = &mechanism.joints()[ji];
        let span = joint_tables
            .get(ji)
            .map_or_else(|| root.span.clone(), |t| t.span.clone());
        return Err(src
            .error(
                ErrorKind::Invalid,
                format!(
                    "the joint `{}` does not hold at the start: its constraint is off by {c} m",
                    joint.name
                ),
                span,
            )
            .with_hint("place the bodies where the joint holds them (a contact on or above its surface, a string no longer than its `length`, a rod's ends at its `length`), or leave `length` out to take the distance at the start"));
    }
    let events = mechanism.events(first_joint);
    let planar = PlanarNames {
        rigid: rigid_names,
        joints: joint_names,
        extras: rigid.len() + modes.len(),
        modes: modes
            .iter()
            .enumerate()
            .map(|(i, m)| (m.clone(), angle_of(rigid.len()) + i))
            .collect(),
        masses: Vec::new(),
    };
    assemble(
        root,
        Model {
            name,
            title,
            dim: 2,
            constants,
            system,
            initial: State::from_qv(0.0, &q, &v),
            stepping,
            bodies: names,
            forces: force_names,
            events,
            warnings,
            planar,
        },
    )
}
