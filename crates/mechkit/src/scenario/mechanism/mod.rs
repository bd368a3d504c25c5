//! A scenario of free `[[rigid_body]]`s and `[[joint]]`s, in a plane (`dimensions = 2`) or in
//! space (`dimensions = 3`): a mechanism ([`crate::rigid::mechanism`]) run as one particle
//! system. A rigid body's centre of mass is among the positions; how it turns follows them: one
//! angle in a plane, a quaternion of four coordinates in space ([`crate::particles::spin`]);
//! the joints' modes come last.

mod contact;
mod distinct;
mod joints;
pub(crate) mod points;
mod rigid2;
mod rigid3;

use std::sync::Arc;

use mechkit_expr::units::Dimension;

use super::Scenario;
use super::build::{Model, assemble, bodies};
use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::forces::{ForceContext, read_forces};
use super::integrator::read_integrator;
use super::values::{Constant, ValueEnv, scalar};
use crate::Real;
use crate::ode::State;
use crate::particles::spin::{Mat3, Quat, Spinner, rate_for};
use crate::particles::{ParticleSystem, PlanarNames, RigidName, SpinRef};
use crate::rigid::mechanism::{Joint, JointForce, Mechanism, MechanismBody};
use crate::simulate::Stepping;
use joints::{Names, read_joint};
use rigid2::read_rigid2;
use rigid3::read_rigid3;

/// A rigid body as read, before the system is built.
pub(super) struct Rigid {
    pub(super) name: String,
    pub(super) mass: Real,
    /// Centre of mass (`dimensions` components).
    pub(super) position: Vec<Real>,
    pub(super) velocity: Vec<Real>,
    /// Named points, body frame, from the centre of mass (`z` 0 in a plane).
    pub(super) points: Vec<(String, [Real; 3])>,
    pub(super) turn: RigidTurn,
    /// Its parts as drawn, body frame, from the centre of mass.
    pub(super) outline: Vec<Vec<[Real; 3]>>,
}

/// How a rigid body turns, and its initial turning.
pub(super) enum RigidTurn {
    /// In a plane: moment of inertia about the centre of mass, angle, angular velocity.
    Plane {
        inertia: Real,
        theta: Real,
        omega: Real,
    },
    /// In space: inertia tensor about the centre of mass (body frame), orientation (a unit
    /// quaternion, body → world), angular velocity (world).
    Space {
        inertia: Mat3,
        orientation: Quat,
        omega: [Real; 3],
    },
}

impl RigidTurn {
    /// How many coordinates it takes.
    fn coordinates(&self) -> usize {
        match self {
            RigidTurn::Plane { .. } => 1,
            RigidTurn::Space { .. } => 4,
        }
    }
}

/// Refuses a `free` key other than `true` on the rigid body `t`, with `message` and `hint`.
pub(super) fn check_free(
    t: &Table<'_, '_>,
    message: &str,
    hint: &str,
) -> Result<(), ScenarioError> {
    match t.get("free") {
        Some(v) if !matches!(v.get_ref(), toml::de::DeValue::Boolean(true)) => Err(t
            .src
            .error(ErrorKind::Invalid, message, v.span())
            .with_hint(hint)),
        _ => Ok(()),
    }
}

/// Builds a scenario of rigid bodies and joints in `dim` dimensions (2 or 3).
pub(crate) fn build_mechanism(
    name: &str,
    root: &Table<'_, '_>,
    title: String,
    constants: Vec<Constant>,
    rigid_tables: &[Table<'_, '_>],
    dim: usize,
) -> Result<Scenario, ScenarioError> {
    let src = root.src;
    for key in ["torque", "contact", "wall", "plane"] {
        if let Some(v) = root.get(key) {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("a scenario of free rigid bodies (`dimensions = {dim}`) cannot have `{key}`"),
                    v.span(),
                )
                .with_hint("surfaces are [[joint]]s of kind \"contact\" (with `surface`); torques are [[force]]s of kind \"torque\" or forces applied at body points (`at`)"));
        }
    }
    let env = ValueEnv {
        constants: &constants,
        mass: None,
        later: &[],
    };
    let (mut names, mut masses, mut q, mut v, radius) = if root.get("body").is_some() {
        bodies(root, dim, &constants)?
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
                    format!("`{key}`: a body that ejects mass is not yet part of a mechanism"),
                    t.key_span(key),
                )
                .with_hint("run the rocket in a scenario without [[rigid_body]] and [[joint]]"));
        }
    }
    let n_particles = names.len();
    let dir = std::path::Path::new(name).parent();
    let mut rigid = Vec::new();
    for (i, t) in rigid_tables.iter().enumerate() {
        let r = if dim == 2 {
            read_rigid2(t, i, rigid_tables.len(), &names, env, dir)?
        } else {
            read_rigid3(t, i, rigid_tables.len(), &names, env, dir)?
        };
        names.push(r.name.clone());
        masses.push(r.mass);
        q.extend(&r.position);
        v.extend(&r.velocity);
        rigid.push(r);
    }
    let n_bodies = names.len();
    let joint_tables = root.tables("joint")?;

    // coordinates: positions, then each rigid body's turning (an angle or a quaternion), then
    // the joints' modes
    let mut turn_of = Vec::with_capacity(rigid.len());
    let mut next = dim * n_bodies;
    for r in &rigid {
        turn_of.push(next);
        next += r.turn.coordinates();
    }
    let first_mode = next;
    let mut mechanism_bodies: Vec<MechanismBody> = (0..n_particles)
        .map(|b| MechanismBody {
            x: dim * b,
            angle: None,
            spinner: None,
            inv_mass: 1.0 / masses[b],
            inv_inertia: 0.0,
        })
        .collect();
    let mut rigid_names = Vec::with_capacity(rigid.len());
    for (k, r) in rigid.iter().enumerate() {
        let body = n_particles + k;
        let (angle, spinner, inv_inertia, spin) = match &r.turn {
            RigidTurn::Plane { inertia, .. } => (Some(turn_of[k]), None, 1.0 / inertia, None),
            RigidTurn::Space { inertia, .. } => (
                None,
                Spinner::new(body, turn_of[k], *inertia),
                0.0,
                Some(SpinRef::new(body, turn_of[k], inertia)),
            ),
        };
        mechanism_bodies.push(MechanismBody {
            x: dim * body,
            angle,
            spinner,
            inv_mass: 1.0 / r.mass,
            inv_inertia,
        });
        rigid_names.push(RigidName {
            body,
            angle: turn_of[k],
            inertia: match r.turn {
                RigidTurn::Plane { inertia, .. } => inertia,
                RigidTurn::Space { .. } => 0.0,
            },
            points: r.points.clone(),
            spin,
        });
    }
    let mut modes: Vec<String> = Vec::new();
    let mut joints = Vec::new();
    let ctx = Names {
        dim,
        bodies: &names,
        n_particles,
        rigid: &rigid,
        env,
    };
    for (i, t) in joint_tables.iter().enumerate() {
        let j = read_joint(t, i, &ctx, &q, &mut modes, first_mode)?;
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
    let dof = first_mode + modes.len();
    let mechanism = Arc::new(Mechanism::new(mechanism_bodies, joints, dof, dim));

    // what force formulas may read: the bodies' angles and angular velocities
    let turning = PlanarNames {
        rigid: rigid_names.clone(),
        ..PlanarNames::default()
    };
    let fctx = ForceContext {
        dim,
        bodies: &names,
        masses: &masses,
        constants: &constants,
        rigid: &turning,
    };
    let mut builder = ParticleSystem::builder(dim);
    for (b, m) in names.iter().zip(&masses) {
        builder = builder.body(b.clone(), *m);
    }
    let mut force_names: Vec<String> = Vec::new();
    for f in read_forces(root, &fctx, &names, true)? {
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
        match r.turn {
            RigidTurn::Plane {
                inertia,
                theta,
                omega,
            } => {
                builder = builder.rotor(r.name.clone(), n_particles + k, inertia);
                q.push(theta);
                v.push(omega);
            }
            RigidTurn::Space {
                inertia,
                orientation,
                omega,
            } => {
                builder = builder.spinner(&r.name, n_particles + k, inertia);
                q.extend(orientation);
                v.extend(rate_for(orientation, omega));
            }
        }
    }
    for m in &modes {
        builder = builder.mode(m.clone());
        q.push(0.0);
        v.push(0.0);
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
    let mut scene = crate::animation::Scene::of_system(&system);
    for (body, r) in scene.bodies.iter_mut().zip(&radius) {
        if let Some(radius) = r.filter(|r| *r > 0.0) {
            body.shape = crate::animation::BodyShape::Sphere { radius };
        }
    }
    for (body, r) in scene.bodies.iter_mut().skip(n_particles).zip(&rigid) {
        body.shape = crate::animation::BodyShape::Outline {
            parts: r.outline.clone(),
        };
    }
    let stepping = read_integrator(root, env, &system)?;
    let tau = match scalar(root, "stabilisation", Dimension::TIME, env)? {
        Some(tau) if tau > 0.0 => tau,
        Some(tau) => {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`stabilisation` must be a positive time, not {} s",
                        crate::error::short(tau)
                    ),
                    root.key_span("stabilisation"),
                )
                .with_hint("the time constant over which joints pull a drift back: \"10 ms\""));
        }
        // adaptive steps keep the drift at the tolerance's level; pulling it back faster than
        // the motion changes would only cap their size (an eigenvalue of -1/τ)
        None => match &stepping {
            Stepping::Fixed { dt, .. } => 10.0 * dt,
            Stepping::Adaptive { .. } => {
                let t_max = match root.table("stop")? {
                    Some(stop) => scalar(&stop, "t_max", Dimension::TIME, env)?,
                    None => None,
                };
                t_max.filter(|t| *t > 0.0).map_or(0.1, |t| t / 20.0)
            }
        },
    };
    mechanism.set_tau(tau);
    let scale = q[..dim * n_bodies]
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
                    "the joint `{}` does not hold at the start: its constraint is off by {} m",
                    joint.name,
                    crate::error::short(c)
                ),
                span,
            )
            .with_hint("place the bodies where the joint holds them (a contact on or above its surface, a string no longer than its `length`, a rod's ends at its `length`), or leave `length` out to take the distance at the start"));
    }
    let speed = v[..dim * n_bodies]
        .iter()
        .fold(0.0_f64, |m, x| m.max(x.abs()))
        .max(1.0);
    if let Some((ji, rate)) = mechanism.velocity_violation(&q, &v, 1e-9 * speed) {
        mechanism.project_velocities(&q, &mut v);
        warnings.push(format!(
            "the initial velocities break the joint `{}` (its constraint changes at a rate of {}, in m/s for a point it holds, rad/s for an axis it keeps): they were projected onto what the joints allow, as an inelastic impulse at t = 0; give velocities the joints allow (a body turning about a pivot moves its centre at ω × r; a hinge lets it turn about its axis only) to start from your own",
            mechanism.joints()[ji].name,
            crate::expr::short_number(rate)
        ));
    }
    let events = mechanism.events(first_joint);
    let planar = PlanarNames {
        rigid: rigid_names,
        joints: joint_names,
        extras: first_mode - dim * n_bodies + modes.len(),
        modes: modes
            .iter()
            .enumerate()
            .map(|(i, m)| (m.clone(), first_mode + i))
            .collect(),
        masses: Vec::new(),
    };
    assemble(
        root,
        Model {
            name,
            title,
            dim,
            constants,
            system,
            initial: State::from_qv(0.0, &q, &v),
            stepping,
            bodies: names,
            forces: force_names,
            events,
            warnings,
            planar,
            scene,
        },
    )
}
