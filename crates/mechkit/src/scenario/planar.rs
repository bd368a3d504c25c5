//! A scenario in a plane (`dimensions = 2`) with free `[[rigid_body]]`s and `[[joint]]`s: a
//! planar mechanism ([`crate::rigid::planar`]) run as one particle system.

use std::ops::Range;
use std::sync::Arc;

use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::Scenario;
use super::build::{Model, assemble, bodies, body_name};
use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::forces::{ForceContext, build_force};
use super::integrator::read_integrator;
use super::rigid::bodies::mass_properties;
use super::values::{Constant, ValueEnv, scalar, vector};
use crate::Real;
use crate::ode::State;
use crate::particles::{ParticleSystem, PlanarNames, RigidName};
use crate::rigid::planar::{Anchor, Friction, Joint, JointForce, JointKind, Mechanism, PlanarBody};
use crate::simulate::Stepping;

const PLANAR_RIGID_KEYS: &[&str] = &[
    "name", "free", "part", "body", "mass", "inertia", "position", "velocity", "theta", "omega",
    "points",
];
const JOINT_KEYS: &[&str] = &[
    "name", "kind", "a", "b", "on", "length", "radius", "surface", "mu", "mu_s", "mu_k", "rolling",
    "centre", "center", "wheel", "y",
];
const JOINT_KINDS: &[&str] = &["hinge", "rod", "string", "contact", "pulley", "curve"];

/// A rigid body as read, before the system is built.
struct Rigid {
    name: String,
    mass: Real,
    inertia: Real,
    position: [Real; 2],
    velocity: [Real; 2],
    theta: Real,
    omega: Real,
    points: Vec<(String, [Real; 2])>,
}

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

    let fctx = ForceContext {
        dim: 2,
        bodies: &names,
        masses: &masses,
        constants: &constants,
    };
    let mut builder = ParticleSystem::builder(2);
    for (b, m) in names.iter().zip(&masses) {
        builder = builder.body(b.clone(), *m);
    }
    let mut force_names: Vec<String> = Vec::new();
    for (i, t) in root.tables("force")?.iter().enumerate() {
        let f = force_at(t, &fctx, i, &ctx, n_bodies)?;
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
        rigid: rigid
            .iter()
            .enumerate()
            .map(|(k, r)| RigidName {
                body: n_particles + k,
                angle: angle_of(k),
                inertia: r.inertia,
                points: r.points.clone(),
            })
            .collect(),
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

fn read_rigid(
    t: &Table<'_, '_>,
    index: usize,
    count: usize,
    taken: &[String],
    env: ValueEnv<'_>,
    dir: Option<&std::path::Path>,
) -> Result<Rigid, ScenarioError> {
    t.check_keys(PLANAR_RIGID_KEYS)?;
    let name = body_name(t, index, count, taken, "theta")?;
    if let Some(v) = t.get("free")
        && !matches!(v.get_ref(), DeValue::Boolean(true))
    {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                "`free` must be true: in a plane every rigid body is free unless a [[joint]] holds it",
                v.span(),
            )
            .with_hint("hinge it with a [[joint]] of kind \"hinge\", or leave out `dimensions` for a body turning about a fixed axis"));
    }
    // the body frame's origin: the centre of mass, or the parts' frame
    let (mass, inertia, cm) = if t.get("inertia").is_some() {
        let mass = scalar(t, "mass", Dimension::MASS, env)?
            .ok_or_else(|| t.missing("mass", "\"1 kg\""))?;
        let inertia = scalar(t, "inertia", Dimension::MOMENT_OF_INERTIA, env)?.unwrap_or(0.0);
        (mass, inertia, [0.0, 0.0])
    } else if t.get("mass").is_some() {
        return Err(t
            .missing("inertia", "\"0.5 kg m^2\"")
            .with_hint("give the moment of inertia about the centre of mass, or describe the body by `[[rigid_body.part]]` tables or a `body` file"));
    } else {
        let props = mass_properties(t, env, dir)?;
        let c = props.centre_of_mass;
        (props.mass, props.inertia[(2, 2)], [c[0], c[1]])
    };
    for (key, value, span) in [
        ("mass", mass, t.key_span("mass")),
        ("inertia", inertia, t.key_span("inertia")),
    ] {
        if !(value > 0.0 && value.is_finite()) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("the {key} of rigid body `{name}` must be positive, not {value}"),
                    span,
                )
                .with_hint("a particle (no rotation) is a [[body]]; a rigid body needs a mass and a moment of inertia about its centre of mass"));
        }
    }
    let two = |key: &str, want: Dimension| -> Result<[Real; 2], ScenarioError> {
        Ok(vector(t, key, want, 2, env)?.map_or([0.0; 2], |v| [v[0], v[1]]))
    };
    let mut points = Vec::new();
    if let Some(p) = t.table("points")? {
        for (key, _) in p.entries {
            let point: &str = key.get_ref();
            let valid = point
                .chars()
                .next()
                .is_some_and(|c| c.is_alphabetic() || c == '_')
                && point.chars().all(|c| c.is_alphanumeric() || c == '_');
            if !valid
                || [
                    "x", "y", "vx", "vy", "theta", "omega", "alpha", "K", "m", "v", "r",
                ]
                .contains(&point)
            {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        format!("`{point}` cannot name a point: formulas would read `{name}.{point}` as something else"),
                        key.span(),
                    )
                    .with_hint("a letter or `_` then letters, digits or `_`, not a field name such as x or theta"));
            }
            let r = vector(&p, point, Dimension::LENGTH, 2, env)?.unwrap_or_default();
            points.push((point.to_string(), [r[0] - cm[0], r[1] - cm[1]]));
        }
    }
    Ok(Rigid {
        name,
        mass,
        inertia,
        position: two("position", Dimension::LENGTH)?,
        velocity: two("velocity", Dimension::VELOCITY)?,
        theta: scalar(t, "theta", Dimension::NONE, env)?.unwrap_or(0.0),
        omega: scalar(t, "omega", Dimension::FREQUENCY, env)?.unwrap_or(0.0),
        points,
    })
}

/// What joints refer to.
struct Names<'a> {
    bodies: &'a [String],
    n_particles: usize,
    rigid: &'a [Rigid],
    env: ValueEnv<'a>,
}

impl Names<'_> {
    /// The bodies as the solver sees them (masses left at 1: for geometry only).
    fn solver_bodies(&self) -> Vec<PlanarBody> {
        let n = self.bodies.len();
        (0..n)
            .map(|b| PlanarBody {
                x: 2 * b,
                angle: b.checked_sub(self.n_particles).map(|k| 2 * n + k),
                inv_mass: 1.0,
                inv_inertia: 1.0,
            })
            .collect()
    }

    /// `"body"` (its centre of mass) or `"body.point"`.
    fn anchor(&self, text: &str) -> Result<Anchor, String> {
        let (body, point) = match text.split_once('.') {
            Some((b, p)) => (b, Some(p)),
            None => (text, None),
        };
        let Some(b) = self.bodies.iter().position(|n| n == body) else {
            return Err(format!(
                "`{body}` is not a body; the bodies are: {}",
                self.bodies.join(", ")
            ));
        };
        let Some(point) = point else {
            return Ok(Anchor::Body {
                body: b,
                r: [0.0; 2],
            });
        };
        let Some(rigid) = b.checked_sub(self.n_particles).map(|k| &self.rigid[k]) else {
            return Err(format!(
                "`{body}` is a particle: it has no points; write `{body}`"
            ));
        };
        rigid
            .points
            .iter()
            .find(|(n, _)| n == point)
            .map(|(_, r)| Anchor::Body { body: b, r: *r })
            .ok_or_else(|| {
                let known: Vec<&str> = rigid.points.iter().map(|(n, _)| n.as_str()).collect();
                format!(
                    "`{body}` has no point `{point}`; its points are: {} (add it under `points`)",
                    if known.is_empty() {
                        "none".to_string()
                    } else {
                        known.join(", ")
                    }
                )
            })
    }

    /// An anchor key: a body, a body point, or a fixed point `[x, y]`.
    fn anchor_key(&self, t: &Table<'_, '_>, key: &str) -> Result<Option<Anchor>, ScenarioError> {
        let Some(v) = t.get(key) else {
            return Ok(None);
        };
        if let DeValue::String(s) = v.get_ref() {
            return self.anchor(s).map(Some).map_err(|m| {
                t.src
                    .error(ErrorKind::Invalid, m, v.span())
                    .with_hint("a joint holds a body (`\"cart\"`), a named point of a rigid body (`\"ladder.top\"`) or a fixed point (`[\"0 m\", \"1 m\"]`)")
            });
        }
        let p = vector(t, key, Dimension::LENGTH, 2, self.env)?.unwrap_or_default();
        Ok(Some(Anchor::World([p[0], p[1]])))
    }
}

/// Where an anchor is in the initial state.
fn position(a: Anchor, q: &[Real], rigid_angle: impl Fn(usize) -> Option<Real>) -> [Real; 2] {
    match a {
        Anchor::World(p) => p,
        Anchor::Body { body, r } => {
            let th = rigid_angle(body).unwrap_or(0.0);
            let (s, c) = th.sin_cos();
            [
                q[2 * body] + c * r[0] - s * r[1],
                q[2 * body + 1] + s * r[0] + c * r[1],
            ]
        }
    }
}

fn read_joint(
    t: &Table<'_, '_>,
    index: usize,
    ctx: &Names<'_>,
    q: &[Real],
    modes: &mut Vec<String>,
    first_mode: usize,
) -> Result<Joint, ScenarioError> {
    t.check_keys(JOINT_KEYS)?;
    let src = t.src;
    let name = match t.string("name")? {
        Some((n, span)) => {
            let valid = n
                .chars()
                .next()
                .is_some_and(|c| c.is_alphabetic() || c == '_')
                && n.chars().all(|c| c.is_alphanumeric() || c == '_');
            if !valid {
                return Err(src.error(ErrorKind::Invalid, format!("joint name `{n}` must be a letter or `_` followed by letters, digits or `_` (formulas read `{n}.N`)"), span));
            }
            n.to_string()
        }
        None => format!("joint{}", index + 1),
    };
    let (kind, kind_span) = t.string("kind")?.ok_or_else(|| {
        t.missing("kind", "\"hinge\"")
            .with_hint(format!("the kinds: {}", JOINT_KINDS.join(", ")))
    })?;
    let angle = |body: usize| {
        body.checked_sub(ctx.n_particles)
            .map(|k| ctx.rigid[k].theta)
    };
    let env = ctx.env;
    let need = |key: &str, example: &str| -> Result<Anchor, ScenarioError> {
        ctx.anchor_key(t, key)?.ok_or_else(|| {
            t.missing(key, example).with_hint(format!(
                "a {kind} joint names what it holds: a body, \"body.point\" or a fixed point [x, y]"
            ))
        })
    };
    let mut new_mode = |what: &str| {
        modes.push(format!("{name}.{what}"));
        first_mode + modes.len() - 1
    };
    let length_or = |key: &str, a: Anchor, b: Anchor| -> Result<Real, ScenarioError> {
        let l = if let Some(l) = scalar(t, key, Dimension::LENGTH, env)? {
            l
        } else {
            let (pa, pb) = (position(a, q, angle), position(b, q, angle));
            (pa[0] - pb[0]).hypot(pa[1] - pb[1])
        };
        if !(l > 0.0 && l.is_finite()) {
            return Err(src
                .error(ErrorKind::Invalid, format!("the {kind}'s `{key}` must be positive, not {l} m"), key_or(t, key, &kind_span))
                .with_hint("give `length`, or place the ends apart (the length defaults to their distance at the start)"));
        }
        Ok(l)
    };
    let kind = match kind {
        "hinge" | "pin" => {
            let a = need("a", "\"rod.end\"")?;
            let b = match ctx.anchor_key(t, "b")? {
                Some(b) => b,
                None => Anchor::World(position(a, q, angle)),
            };
            JointKind::Hinge { a, b }
        }
        "rod" => {
            let (a, b) = (need("a", "\"ball\"")?, need("b", "[\"0 m\", \"0 m\"]")?);
            JointKind::Rod {
                a,
                b,
                length: length_or("length", a, b)?,
            }
        }
        "string" | "rope" | "cable" => {
            let (a, b) = (need("a", "\"ball\"")?, need("b", "[\"0 m\", \"0 m\"]")?);
            let length = length_or("length", a, b)?;
            JointKind::String {
                a,
                b,
                length,
                mode: new_mode("taut"),
            }
        }
        "contact" | "surface" => {
            let on = need("on", "\"block\"")?;
            let radius = scalar(t, "radius", Dimension::LENGTH, env)?.unwrap_or(0.0);
            if !(radius >= 0.0 && radius.is_finite()) {
                return Err(src.error(
                    ErrorKind::Invalid,
                    format!("`radius` must be zero or positive, not {radius} m"),
                    t.key_span("radius"),
                ));
            }
            let (point, normal) = surface(t, env, &kind_span)?;
            let point = match surface_body(t, ctx)? {
                Some(body) => Anchor::Body { body, r: point },
                None => Anchor::World(point),
            };
            let mode = new_mode("touching");
            let friction = friction(t, env, &mut new_mode)?;
            JointKind::Contact {
                on,
                radius,
                point,
                normal,
                mode,
                friction,
            }
        }
        "curve" | "track" | "wire" => {
            let on = need("on", "\"bead\"")?;
            let (text, span) = t.string("y")?.ok_or_else(|| {
                t.missing("y", "\"x^2/2\"")
                    .with_hint("the curve as `y = f(x)`: a formula of `x` and the constants")
            })?;
            let parsed = mechkit_expr::parse(text).map_err(|e| {
                src.error(
                    ErrorKind::Invalid,
                    format!("the curve `y`: {e}"),
                    span.clone(),
                )
            })?;
            let constants: Vec<(String, Real)> =
                env.constants.iter().map(|c| (c.0.clone(), c.1)).collect();
            let curve =
                crate::rigid::planar::Curve::new(&parsed.expr, &constants).map_err(|name| {
                    src.error(
                        ErrorKind::Invalid,
                        format!("the curve `y` uses `{name}`, which is neither `x` nor a constant"),
                        span.clone(),
                    )
                    .with_hint("write y as a formula of x and the [constants]: \"x^2/(2*R)\"")
                })?;
            JointKind::Curve {
                on,
                curve: std::sync::Arc::new(curve),
            }
        }
        "pulley" => {
            let (a, b) = (need("a", "\"m1\"")?, need("b", "\"m2\"")?);
            let wheel = match t.string("wheel")? {
                Some((w, span)) => {
                    let body = ctx.bodies.iter().position(|n| n == w).filter(|&i| i >= ctx.n_particles).ok_or_else(|| {
                        src.error(ErrorKind::Invalid, format!("`{w}` is not a rigid body"), span.clone())
                            .with_hint("the wheel is a [[rigid_body]] (a disk) hinged at the pulley's centre")
                    })?;
                    Some(body)
                }
                None => None,
            };
            let centre = match (
                ctx.anchor_key(t, "centre")?,
                ctx.anchor_key(t, "center")?,
                wheel,
            ) {
                (Some(c), _, _) | (None, Some(c), _) => c,
                (None, None, Some(w)) => Anchor::Body {
                    body: w,
                    r: [0.0; 2],
                },
                (None, None, None) => {
                    return Err(t.missing("centre", "[\"0 m\", \"0 m\"]").with_hint("the pulley's axle: a fixed point, or `wheel` (a rigid body whose centre it is)"));
                }
            };
            let radius = scalar(t, "radius", Dimension::LENGTH, env)?.unwrap_or(0.0);
            if !(radius >= 0.0 && radius.is_finite()) {
                return Err(src.error(
                    ErrorKind::Invalid,
                    format!("`radius` must be zero or positive, not {radius} m"),
                    t.key_span("radius"),
                ));
            }
            let c = position(centre, q, angle);
            let (pa, pb) = (position(a, q, angle), position(b, q, angle));
            let outside = |p: [Real; 2]| (p[0] - c[0]).hypot(p[1] - c[1]) > radius;
            if !outside(pa) || !outside(pb) {
                return Err(src
                    .error(
                        ErrorKind::Invalid,
                        "an end of the pulley's string starts on the pulley's rim or inside it",
                        kind_span.clone(),
                    )
                    .with_hint("place the ends farther from the centre than `radius`"));
            }
            let sense = if pb[0] >= pa[0] { 1.0 } else { -1.0 };
            let length = if let Some(l) = scalar(t, "length", Dimension::LENGTH, env)? {
                l
            } else {
                {
                    let zero = vec![0.0; 2 * ctx.bodies.len() + ctx.rigid.len()];
                    let mut qq = q.to_vec();
                    qq.extend(ctx.rigid.iter().map(|r| r.theta));
                    let probe = Mechanism::new(
                        ctx.solver_bodies(),
                        vec![Joint {
                            name: String::new(),
                            kind: JointKind::Pulley {
                                a,
                                b,
                                centre,
                                radius,
                                length: 0.0,
                                sense,
                                wheel: None,
                            },
                        }],
                        qq.len(),
                    );
                    probe.pulley_length(&qq, &zero)
                }
            };
            let wheel = wheel.map(|w| first_mode - ctx.rigid.len() + (w - ctx.n_particles));
            JointKind::Pulley {
                a,
                b,
                centre,
                radius,
                length,
                sense,
                wheel,
            }
        }
        other => {
            let hint = mechkit_expr::did_you_mean(&mechkit_expr::nearest(
                other,
                JOINT_KINDS.iter().copied(),
            ))
            .unwrap_or_else(|| format!("the kinds: {}", JOINT_KINDS.join(", ")));
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("unknown joint kind `{other}`"),
                    kind_span,
                )
                .with_hint(hint));
        }
    };
    Ok(Joint { name, kind })
}

fn key_or(t: &Table<'_, '_>, key: &str, other: &Range<usize>) -> Range<usize> {
    t.get(key)
        .map_or_else(|| other.clone(), toml::Spanned::span)
}

/// `surface.on`: the particle whose surface it is (its `point` is then from that particle's
/// position), or none for a fixed surface.
fn surface_body(t: &Table<'_, '_>, ctx: &Names<'_>) -> Result<Option<usize>, ScenarioError> {
    let Some(s) = t.table("surface")? else {
        return Ok(None);
    };
    let Some((name, span)) = s.string("on")? else {
        return Ok(None);
    };
    match ctx.bodies.iter().position(|b| b == name) {
        Some(b) if b < ctx.n_particles => Ok(Some(b)),
        Some(_) => Err(s
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "`{name}` is a rigid body: a surface on a turning body is not supported yet"
                ),
                span,
            )
            .with_hint(
                "carry the surface on a [[body]] (a cart, a block: it moves without turning)",
            )),
        None => Err(s
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "`{name}` is not a body; the bodies are: {}",
                    ctx.bodies.join(", ")
                ),
                span,
            )
            .with_hint("`on` names the [[body]] that carries the surface")),
    }
}

/// `surface = { point = [x, y], normal = [nx, ny] }` or `{ point, angle }` (the line's
/// inclination; the normal is the direction turned a quarter turn counter-clockwise). The
/// default is the floor `y = 0` with its normal up.
fn surface(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    kind_span: &Range<usize>,
) -> Result<([Real; 2], [Real; 2]), ScenarioError> {
    let Some(s) = t.table("surface")? else {
        return Ok(([0.0; 2], [0.0, 1.0]));
    };
    s.check_keys(&["point", "normal", "angle", "on"])?;
    let point = vector(&s, "point", Dimension::LENGTH, 2, env)?.unwrap_or_else(|| vec![0.0; 2]);
    let normal = match (
        vector(&s, "normal", Dimension::NONE, 2, env)?,
        scalar(&s, "angle", Dimension::NONE, env)?,
    ) {
        (Some(_), Some(_)) => {
            return Err(s.src.error(
                ErrorKind::Invalid,
                "give the surface's `normal` or its `angle`, not both",
                s.key_span("angle"),
            ));
        }
        (Some(n), None) => n,
        (None, Some(a)) => vec![-a.sin(), a.cos()],
        (None, None) => vec![0.0, 1.0],
    };
    let len = normal[0].hypot(normal[1]);
    if !(len > 0.0 && len.is_finite()) {
        return Err(s
            .src
            .error(
                ErrorKind::Invalid,
                "the surface's `normal` must not be zero",
                key_or(&s, "normal", kind_span),
            )
            .with_hint(
                "the direction away from the surface, towards the body: [0, 1] for a floor",
            ));
    }
    Ok(([point[0], point[1]], [normal[0] / len, normal[1] / len]))
}

/// `mu` (both), or `mu_s` and `mu_k`; `rolling = true` for a contact that never slides.
fn friction(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    new_mode: &mut impl FnMut(&str) -> usize,
) -> Result<Friction, ScenarioError> {
    let coefficient = |key: &str| -> Result<Option<Real>, ScenarioError> {
        let mu = scalar(t, key, Dimension::NONE, env)?;
        if let Some(m) = mu
            && !(m >= 0.0 && m.is_finite())
        {
            return Err(t.src.error(
                ErrorKind::Invalid,
                format!("`{key}` must be zero or positive, not {m}"),
                t.key_span(key),
            ));
        }
        Ok(mu)
    };
    let rolling = match t.get("rolling") {
        None => false,
        Some(v) => match v.get_ref() {
            DeValue::Boolean(b) => *b,
            _ => return Err(t.wrong_type("rolling", v, "true or false")),
        },
    };
    let (mu, mu_s, mu_k) = (
        coefficient("mu")?,
        coefficient("mu_s")?,
        coefficient("mu_k")?,
    );
    if rolling {
        if let Some(key) = ["mu", "mu_s", "mu_k"]
            .into_iter()
            .find(|k| t.get(k).is_some())
        {
            return Err(t.src.error(ErrorKind::Invalid, format!("`rolling = true` never slides, so `{key}` would not be used"), t.key_span(key)).with_hint("for rolling that may turn into sliding give `mu_s` and `mu_k` without `rolling`"));
        }
        return Ok(Friction::NoSlip);
    }
    let (mu_s, mu_k) = match (mu, mu_s, mu_k) {
        (None, None, None) => return Ok(Friction::None),
        (Some(m), None, None) => (m, m),
        (None, Some(s), Some(k)) => (s, k),
        (None, Some(s), None) => (s, s),
        (None, None, Some(k)) => (k, k),
        (Some(_), _, _) => {
            return Err(t.src.error(
                ErrorKind::Invalid,
                "`mu` sets both coefficients: give `mu`, or `mu_s` and `mu_k`",
                t.key_span("mu"),
            ));
        }
    };
    if mu_k > mu_s {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!("`mu_k` = {mu_k} is larger than `mu_s` = {mu_s}"),
                t.key_span("mu_k"),
            )
            .with_hint("kinetic friction is at most static friction: swap them?"));
    }
    Ok(Friction::Coulomb {
        mu_s,
        mu_k,
        mode: new_mode("sliding"),
    })
}

/// A `[[force]]`, applied at a body point when it has `at = "body.point"` (then it acts on
/// that rigid body alone, and its torque about the centre of mass turns the body).
fn force_at(
    t: &Table<'_, '_>,
    fctx: &ForceContext<'_>,
    index: usize,
    names: &Names<'_>,
    n_bodies: usize,
) -> Result<Box<dyn crate::forces::Force>, ScenarioError> {
    let Some(at) = t.get("at") else {
        return build_force(t, fctx, index);
    };
    let src = t.src;
    let DeValue::String(text) = at.get_ref() else {
        return Err(t.wrong_type("at", at, "a body point, such as \"ladder.top\""));
    };
    let anchor = names
        .anchor(text)
        .map_err(|m| src.error(ErrorKind::Invalid, m, at.span()))?;
    let Anchor::Body { body, r } = anchor else {
        return Err(src.error(ErrorKind::Invalid, "`at` is a point of a body", at.span()));
    };
    let Some(k) = body.checked_sub(names.n_particles) else {
        return Err(src
            .error(
                ErrorKind::Invalid,
                format!("`{text}` is a particle: a force on it acts at its centre"),
                at.span(),
            )
            .with_hint("leave out `at`, or apply the force to a [[rigid_body]]'s point"));
    };
    let body_name = names.bodies[body].clone();
    if let Some((on, span)) = t.string("on")?
        && on != body_name
    {
        return Err(src
            .error(
                ErrorKind::Invalid,
                format!("`on = \"{on}\"` but `at` is a point of `{body_name}`"),
                span,
            )
            .with_hint("a force applied at a point acts on that point's body: leave out `on`"));
    }
    let mut entries = t.entries.clone();
    entries.remove("at");
    if t.get("on").is_none() {
        entries.insert(
            toml::Spanned::new(at.span(), std::borrow::Cow::Borrowed("on")),
            toml::Spanned::new(
                at.span(),
                DeValue::String(std::borrow::Cow::Owned(body_name)),
            ),
        );
    }
    let filtered = Table::new(src, &entries, t.span.clone(), t.what.clone());
    let inner = build_force(&filtered, fctx, index)?;
    let angle = 2 * n_bodies + k;
    Ok(Box::new(crate::rigid::planar::AppliedAt::new(
        inner, body, angle, r,
    )))
}
