//! From TOML text to a runnable [`Scenario`]: every key checked, every value resolved to SI
//! with its dimension checked, every formula compiled, every error located.

use mechkit_expr::units::Dimension;
use toml::de::{DeTable, DeValue};

use super::Scenario;
use super::constants::constants_with;
use super::contact::{Spheres, read_contacts};
use super::doc::{Source, Table};
use super::error::{ErrorKind, ScenarioError, positive_message};
use super::events::read_events;
use super::forces::{ForceContext, read_forces};
use super::integrator::read_integrator;
use super::observe::read_observe;
use super::plot::read_output;
use super::rigid::build_rigid;
use super::stop::read_stop;
use super::sweep::ConstantOverride;
use super::values::{Constant, ValueEnv, scalar, vector};
use crate::Real;
use crate::ode::State;
use crate::particles::{BodyRef, NameContext, ParticleSystem, VarLevel};
use crate::simulate::{Cancel, Progress, Stepping};

const TOP_KEYS: &[&str] = &[
    "title",
    "description",
    "dimensions",
    "constants",
    "body",
    "force",
    "integrator",
    "stop",
    "event",
    "observe",
    "output",
    "contact",
    "wall",
    "plane",
    "rigid_body",
    "torque",
    "units",
    "joint",
    "stabilisation",
];
const BODY_KEYS: &[&str] = &[
    "name",
    "mass",
    "position",
    "velocity",
    "radius",
    "mass_rate",
    "exhaust_speed",
    "burnout_mass",
    "thrust_direction",
];
/// The keys of a body that ejects mass (a rocket).
pub(crate) const ROCKET_KEYS: [&str; 4] = [
    "mass_rate",
    "exhaust_speed",
    "burnout_mass",
    "thrust_direction",
];

/// State names a constant may not take (formulas would become ambiguous).
pub(crate) const RESERVED: &[&str] = &[
    "t", "x", "y", "z", "vx", "vy", "vz", "v", "r", "speed", "ax", "ay", "az", "a", "K", "U", "E",
];

pub(crate) fn build(name: &str, text: &str) -> Result<Scenario, ScenarioError> {
    build_with(name, text, &[])
}

/// [`build`] with some `[constants]` given other values (a sweep's parameters).
pub(crate) fn build_with(
    name: &str,
    text: &str,
    overrides: &[ConstantOverride],
) -> Result<Scenario, ScenarioError> {
    let mut src = Source {
        name,
        text,
        units: mechkit_expr::units::UnitSystem::Si,
    };
    let doc = DeTable::parse(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        let message = e.message().trim();
        let hint = if message.contains("duplicate key") {
            let key = text.get(span.clone()).unwrap_or("").trim();
            format!(
                "`{key}` is already set above in the same table: keep one of them (each key \
                 appears once per table; a second body is a new [[body]])"
            )
        } else {
            "see docs/scenario.md for the file format".to_string()
        };
        src.error(ErrorKind::Syntax, format!("invalid TOML: {message}"), span)
            .with_hint(hint)
    })?;
    src.units = super::values::read_units(&Table::new(src, doc.get_ref(), 0..0, "the scenario"))?;
    let root = Table::new(src, doc.get_ref(), 0..0, "the scenario");
    root.check_keys(TOP_KEYS)?;
    let mut warnings = Vec::new();

    let title = root
        .string("title")?
        .map_or_else(|| name.to_string(), |(s, _)| s.to_string());
    if let Some(d) = root.get("description")
        && !matches!(d.get_ref(), DeValue::String(_))
    {
        return Err(root.wrong_type("description", d, "a string"));
    }
    let dim = match root.count("dimensions")? {
        None => 1,
        Some((d @ 1..=3, _)) => d as usize,
        Some((d, span)) => {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("`dimensions` must be 1, 2 or 3, not {d}"),
                    span,
                )
                .with_hint("1 for motion on a line, 2 in a plane, 3 in space"));
        }
    };

    let rigid_tables = root.tables("rigid_body")?;
    if (!rigid_tables.is_empty() || root.get("joint").is_some()) && dim >= 2 {
        let constants = constants_with(
            &root,
            &[RESERVED, super::rigid::RIGID_RESERVED].concat(),
            overrides,
        )?;
        return super::mechanism::build_mechanism(
            name,
            &root,
            title,
            constants,
            &rigid_tables,
            dim,
        );
    }
    if let Some(v) = root.get("joint") {
        return Err(src
            .error(
                ErrorKind::Invalid,
                "[[joint]]s join bodies in a plane or in space: the scenario needs `dimensions = 2` or `3`",
                v.span(),
            )
            .with_hint(
                "set `dimensions`; joints hold [[body]] particles and [[rigid_body]]s",
            ));
    }
    if !rigid_tables.is_empty() {
        let constants = constants_with(
            &root,
            &[RESERVED, super::rigid::RIGID_RESERVED].concat(),
            overrides,
        )?;
        return build_rigid(name, &root, title, dim, constants, &rigid_tables);
    }
    if let Some(v) = root.get("torque") {
        return Err(src
            .error(
                ErrorKind::Invalid,
                "[[torque]] acts on rigid bodies, and the scenario has no [[rigid_body]]",
                v.span(),
            )
            .with_hint("add a [[rigid_body]] with a `pivot`, or use [[force]] on particles"));
    }
    let constants = constants_with(&root, RESERVED, overrides)?;
    let (bodies, masses, q, v, radius) = bodies(&root, dim, &constants)?;
    for (n, value, _) in &constants {
        if n == "m"
            && masses
                .iter()
                .any(|m| (m - value).abs() > 1e-12 * value.abs())
        {
            warnings.push(format!(
                "the constant `m` = {} kg hides the body mass `m` in formulas, and some body has a different mass",
                crate::error::short(*value)
            ));
        }
    }

    let ctx = ForceContext {
        dim,
        bodies: &bodies,
        masses: &masses,
        constants: &constants,
        rigid: &crate::particles::NO_PLANAR,
    };
    let mut builder = ParticleSystem::builder(dim);
    for (b, m) in bodies.iter().zip(&masses) {
        builder = builder.body(b.clone(), *m);
    }
    let mut force_names: Vec<String> = Vec::new();
    for f in read_forces(&root, &ctx, &[], false)? {
        force_names.push(f.name().to_string());
        builder = builder.boxed_force(f);
    }
    let (mut builder, rockets) = super::rocket::add_rockets(
        &root,
        dim,
        (&bodies, &masses),
        &constants,
        builder,
        &mut force_names,
    )?;
    let contacts = read_contacts(
        &root,
        &Spheres {
            dim,
            names: &bodies,
            masses: &masses,
            radius: &radius,
            q: &q,
        },
        ValueEnv {
            constants: &constants,
            mass: None,
            later: &[],
        },
    )?;
    let contact_forces = !contacts.forces.is_empty();
    let walls = contacts.walls;
    for f in contacts.forces {
        force_names.push(f.name().to_string());
        builder = builder.boxed_force(f);
    }
    if force_names.is_empty() {
        warnings.push("no [[force]] is defined: the bodies move in straight lines".into());
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
    scene.items.extend(walls);
    let mut q = q;
    let mut v = v;
    q.extend(&rockets.q);
    v.extend(&rockets.v);
    let initial = State::from_qv(0.0, &q, &v);
    super::start::check_start(&root, &system, &initial)?;

    let env = ValueEnv {
        constants: &constants,
        mass: None,
        later: &[],
    };
    let mut stepping = read_integrator(&root, env, &system)?;
    if contact_forces && let Stepping::Adaptive { config, .. } = &mut stepping {
        // a contact force switches on and off: the work of each force goes under the error
        // control too, or the steps stride over the kink at the end of a contact and the
        // ledger's split between the spring and its damper suffers
        config
            .error_components
            .get_or_insert(2 * q.len() + force_names.len());
    }
    assemble(
        &root,
        Model {
            name,
            title,
            dim,
            constants,
            system,
            initial,
            stepping,
            bodies,
            forces: force_names,
            events: contacts.events.into_iter().chain(rockets.events).collect(),
            warnings,
            planar: crate::particles::PlanarNames {
                extras: rockets.variable.len(),
                masses: rockets.variable,
                ..Default::default()
            },
            scene,
        },
    )
}

/// What a scenario's model is, before the tables that name its state are read.
pub(crate) struct Model<'n> {
    pub name: &'n str,
    pub title: String,
    pub dim: usize,
    pub constants: Vec<Constant>,
    pub system: ParticleSystem,
    pub initial: State,
    pub stepping: Stepping,
    pub bodies: Vec<String>,
    pub forces: Vec<String>,
    /// Events the model brings (collisions, a wheel stopping), after those of `[[event]]`.
    pub events: Vec<crate::simulate::Event>,
    pub warnings: Vec<String>,
    /// Rigid bodies and joints of a planar mechanism.
    pub planar: crate::particles::PlanarNames,
    /// What the model looks like, for animations.
    pub scene: crate::animation::Scene,
}

/// Reads `[stop]`, `[[event]]`, `[observe]` and `[output]` against the model's names.
pub(crate) fn assemble(root: &Table<'_, '_>, m: Model<'_>) -> Result<Scenario, ScenarioError> {
    let Model {
        name,
        title,
        dim,
        constants,
        system,
        initial,
        stepping,
        bodies,
        forces,
        events: model_events,
        mut warnings,
        planar,
        scene,
    } = m;
    let env = ValueEnv {
        constants: &constants,
        mass: None,
        later: &[],
    };
    let names = NameContext {
        dim,
        bodies: &bodies,
        forces: &forces,
        constants: &constants,
        bare: (bodies.len() == 1).then_some(BodyRef::Index(0)),
        level: VarLevel::Derived,
        coordinates: system.coordinates(),
        units: root.src.units,
        planar: &planar,
    };
    let (stop, t_max, max_steps) = read_stop(root, env, &names)?;
    let mut events = read_events(root, &names)?;
    events.extend(model_events);
    let observables = read_observe(root, &names)?;
    let (every, output_times, plots, energy_bars) = read_output(root, &names, dim, env)?;
    let interval = match &output_times {
        Some(super::OutputTimes::Every(i)) => Some(*i),
        _ => None,
    };
    super::stop::check_steps(root, &stepping, initial.t, t_max, max_steps, interval)?;
    let animation = super::animation_key::read_animation(root)?;
    let max_output = super::limits::read_max_size(root.table("output")?.as_ref())?
        .unwrap_or(super::limits::DEFAULT_MAX_OUTPUT);
    if t_max.is_none() && max_steps.is_none() {
        warnings.push(format!(
            "[stop] has no t_max: the run is bounded by {} steps; set t_max",
            crate::simulate::DEFAULT_MAX_STEPS
        ));
    }
    Ok(Scenario {
        name: name.to_string(),
        title,
        dim,
        constants,
        system,
        initial,
        stepping,
        t_max,
        max_steps,
        max_output,
        cancel: Cancel::new(),
        progress: Progress::new(),
        stop,
        events,
        observables,
        every,
        output_times,
        plots,
        energy_bars,
        warnings,
        units: root.src.units,
        source_hash: super::provenance::fnv1a(root.src.text.as_bytes()),
        planar,
        scene,
        animation,
    })
}

/// The `name` of the `index`-th of `count` bodies (`body`, or `body1`, … when unnamed): a name
/// formulas can use as `name.<field>`, not `work` or `power`, and not one of `taken`.
pub(crate) fn body_name(
    t: &Table<'_, '_>,
    index: usize,
    count: usize,
    taken: &[String],
    field: &str,
) -> Result<String, ScenarioError> {
    let Some((n, span)) = t.string("name")? else {
        return Ok(if count == 1 {
            "body".to_string()
        } else {
            format!("body{}", index + 1)
        });
    };
    let valid = n
        .chars()
        .next()
        .is_some_and(|c| c.is_alphabetic() || c == '_')
        && n.chars().all(|c| c.is_alphanumeric() || c == '_');
    let message = if !valid {
        format!(
            "body name `{n}` must be a letter or `_` followed by letters, digits or `_` (it is used in formulas as `{n}.{field}`)"
        )
    } else if ["work", "power"].contains(&n) {
        format!("`{n}` cannot name a body: `{n}.F` means the {n} of force F")
    } else if taken.iter().any(|b| b == n) {
        format!("two bodies are named `{n}`")
    } else {
        return Ok(n.to_string());
    };
    Err(t
        .src
        .error(ErrorKind::Invalid, message, span)
        .with_hint("every body needs its own name: formulas and output columns use it"))
}

pub(crate) type Bodies = (
    Vec<String>,
    Vec<Real>,
    Vec<Real>,
    Vec<Real>,
    Vec<Option<Real>>,
);

pub(crate) fn bodies(
    root: &Table<'_, '_>,
    dim: usize,
    constants: &[Constant],
) -> Result<Bodies, ScenarioError> {
    let tables = root.tables("body")?;
    if tables.is_empty() {
        return Err(ScenarioError::new(ErrorKind::Missing, "the scenario has no [[body]]").with_hint(
            "add a body:\n  [[body]]\n  name = \"ball\"\n  mass = \"0.1 kg\"\n  position = \"0 m\"\n  velocity = \"0 m/s\"",
        ));
    }
    let (mut names, mut masses, mut q, mut v) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut radius = Vec::new();
    for (i, t) in tables.iter().enumerate() {
        t.check_keys(BODY_KEYS)?;
        let name = body_name(t, i, tables.len(), &names, "x")?;
        let env = ValueEnv {
            constants,
            mass: None,
            later: &[],
        };
        let mass = scalar(t, "mass", Dimension::MASS, env)?.ok_or_else(|| {
            t.missing("mass", "\"1 kg\"").with_hint(format!(
                "every body needs a mass: add `mass = \"1 kg\"` to the body `{name}`"
            ))
        })?;
        if !crate::invertible(mass) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    positive_message(&format!("the mass of `{name}`"), mass, "kg"),
                    t.get("mass").map_or(t.span.clone(), toml::Spanned::span),
                )
                .with_hint("a body's mass is a positive number of kilograms, e.g. \"0.145 kg\""));
        }
        let x =
            vector(t, "position", Dimension::LENGTH, dim, env)?.unwrap_or_else(|| vec![0.0; dim]);
        let u =
            vector(t, "velocity", Dimension::VELOCITY, dim, env)?.unwrap_or_else(|| vec![0.0; dim]);
        let r = scalar(t, "radius", Dimension::LENGTH, env)?;
        if let Some(r) = r
            && !(r >= 0.0 && r.is_finite())
        {
            return Err(t.src.error(
                ErrorKind::Invalid,
                format!(
                    "the radius of `{name}` must be zero or positive, not {} m",
                    crate::error::short(r)
                ),
                t.key_span("radius"),
            ));
        }
        names.push(name);
        masses.push(mass);
        q.extend(x);
        v.extend(u);
        radius.push(r);
    }
    Ok((names, masses, q, v, radius))
}
