//! Collisions in a scenario: `radius` on bodies, `[[wall]]` (or `[[plane]]`) tables, and the
//! `[contact]` table: with `model = "impulse"` (restitution and friction, per-pair values in
//! `[[contact.pair]]`) the events of [`Impacts`]; with `model = "spring"` or `"hertz"`
//! (stiffness and damping) a contact force ([`ContactForce`]) active while bodies overlap.

use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::doc::{Table, string_list};
use super::error::{ErrorKind, ScenarioError};
use super::values::{ValueEnv, scalar, vector};
use crate::Real;
use crate::collisions::{Impacts, Restitution, Wall};
use crate::forces::{ContactDamping, ContactForce, ContactLaw, Force};
use crate::simulate::Event;

const WALL_KEYS: &[&str] = &["name", "point", "normal", "restitution", "friction"];
const CONTACT_KEYS: &[&str] = &[
    "model",
    "restitution",
    "friction",
    "pair",
    "stiffness",
    "damping",
];
const PAIR_KEYS: &[&str] = &["bodies", "restitution", "friction"];
const MODELS: &[&str] = &["impulse", "spring", "hertz"];

/// What the collision setup adds to a scenario.
#[derive(Default)]
pub(crate) struct ContactSetup {
    /// Impact events (the impulse model).
    pub events: Vec<Event>,
    /// Contact forces (the spring and Hertz models).
    pub forces: Vec<Box<dyn Force>>,
    /// The walls, as an animation draws them.
    pub walls: Vec<crate::animation::SceneItem>,
}

/// The bodies as the collision setup sees them.
pub(crate) struct Spheres<'b> {
    pub dim: usize,
    pub names: &'b [String],
    pub masses: &'b [Real],
    pub radius: &'b [Option<Real>],
    pub q: &'b [Real],
}

fn restitution(
    t: &Table<'_, '_>,
    env: ValueEnv<'_>,
    default: Restitution,
) -> Result<Restitution, ScenarioError> {
    let Some(e) = scalar(t, "restitution", Dimension::NONE, env)? else {
        return Ok(default);
    };
    Restitution::new(e).map_err(|err| {
        t.src
            .error(
                ErrorKind::Invalid,
                err.to_string(),
                t.key_span("restitution"),
            )
            .with_hint("1 is elastic, 0 perfectly inelastic (the bodies move on together)")
    })
}

fn friction(t: &Table<'_, '_>, env: ValueEnv<'_>, default: Real) -> Result<Real, ScenarioError> {
    match scalar(t, "friction", Dimension::NONE, env)? {
        None => Ok(default),
        Some(mu) if mu >= 0.0 => Ok(mu),
        Some(mu) => Err(t.src.error(
            ErrorKind::Invalid,
            format!(
                "the friction coefficient must be zero or positive, not {}",
                crate::error::short(mu)
            ),
            t.key_span("friction"),
        )),
    }
}

/// The collision events or contact forces of the scenario (none when fewer than two bodies
/// have a radius and there is no wall), after checking that nothing overlaps at the start.
/// Two bodies with a radius collide with no `[contact]` (elastic impulses, the defaults), as
/// `radius` promises.
pub(crate) fn read_contacts(
    root: &Table<'_, '_>,
    s: &Spheres<'_>,
    env: ValueEnv<'_>,
) -> Result<ContactSetup, ScenarioError> {
    let contact = root.table("contact")?;
    let mut walls = root.tables("wall")?;
    walls.extend(root.tables("plane")?);
    let any_radius = s.radius.iter().any(Option::is_some);
    let spheres = s.radius.iter().filter(|r| r.is_some()).count();
    if contact.is_none() && walls.is_empty() && spheres < 2 {
        return Ok(ContactSetup::default());
    }
    if !any_radius {
        let span = contact
            .as_ref()
            .map_or_else(|| walls[0].span.clone(), |c| c.span.clone());
        return Err(root
            .src
            .error(
                ErrorKind::Missing,
                "collisions need bodies with a `radius`, but no [[body]] has one",
                span,
            )
            .with_hint("add `radius = \"0.1 m\"` to each body that collides (0 for a point)"));
    }
    let (mut e0, mut mu0) = (Restitution::ELASTIC, 0.0);
    let mut pairs = Vec::new();
    let mut model = "impulse";
    if let Some(c) = &contact {
        c.check_keys(CONTACT_KEYS)?;
        if let Some((m, span)) = c.string("model")? {
            if !MODELS.contains(&m) {
                return Err(c
                    .src
                    .error(
                        ErrorKind::Invalid,
                        format!("unknown contact model `{m}`"),
                        span,
                    )
                    .with_hint(format!("use one of: {}", MODELS.join(", "))));
            }
            model = m;
        }
        e0 = restitution(c, env, e0)?;
        mu0 = friction(c, env, mu0)?;
        for p in c.tables("pair")? {
            p.check_keys(PAIR_KEYS)?;
            let names = string_list(&p, "bodies")?.ok_or_else(|| {
                p.missing("bodies", "[\"a\", \"b\"]")
                    .with_hint("name the two bodies of the pair: bodies = [\"a\", \"b\"]")
            })?;
            let index = |(n, span): &(&str, std::ops::Range<usize>)| {
                s.names.iter().position(|b| b == n).ok_or_else(|| {
                    p.src
                        .error(
                            ErrorKind::Invalid,
                            format!("no body is named `{n}`"),
                            span.clone(),
                        )
                        .with_hint(format!("the bodies are: {}", s.names.join(", ")))
                })
            };
            if names.len() != 2 {
                return Err(p.src.error(
                    ErrorKind::Invalid,
                    format!("a pair has two bodies, not {}", names.len()),
                    p.key_span("bodies"),
                ));
            }
            let (a, b) = (index(&names[0])?, index(&names[1])?);
            pairs.push((a, b, restitution(&p, env, e0)?, friction(&p, env, mu0)?));
        }
    }
    let mut walls_read = Vec::new();
    for (i, w) in walls.iter().enumerate() {
        w.check_keys(WALL_KEYS)?;
        let name = w
            .string("name")?
            .map_or_else(|| format!("wall{}", i + 1), |(n, _)| n.to_string());
        let point = vector(w, "point", Dimension::LENGTH, s.dim, env)?.ok_or_else(|| {
            w.missing("point", "\"0 m\"")
                .with_hint("a point of the plane, e.g. point = [\"0 m\", \"0 m\"]")
        })?;
        let normal = match w.get("normal") {
            Some(v) if s.dim == 1 && matches!(v.get_ref(), DeValue::Integer(_) | DeValue::Float(_)) => {
                vector(w, "normal", Dimension::NONE, 1, env)?.unwrap_or_default()
            }
            _ => vector(w, "normal", Dimension::NONE, s.dim, env)?.ok_or_else(|| {
                w.missing("normal", "[0, 1]").with_hint(
                    "the normal points from the wall to the side where the bodies are, e.g. normal = [0, 1] for a floor",
                )
            })?,
        };
        let (e, mu) = (restitution(w, env, e0)?, friction(w, env, mu0)?);
        let wall = Wall::new(name, point, &normal, e, mu).ok_or_else(|| {
            w.src.error(
                ErrorKind::Invalid,
                "a wall's normal cannot have zero length",
                w.key_span("normal"),
            )
        })?;
        walls_read.push(wall);
    }
    let drawn: Vec<_> = walls_read
        .iter()
        .map(|w| crate::animation::Scene::wall(&w.point, &w.normal))
        .collect();
    if model != "impulse" {
        let c = contact
            .as_ref()
            .expect("a model other than impulse comes from [contact]");
        let mut setup = contact_force(c, model, s, &walls_read, env)?;
        setup.walls = drawn;
        return Ok(setup);
    }
    let mut impacts = Impacts::new(
        s.dim,
        s.names.to_vec(),
        s.masses.to_vec(),
        s.radius.to_vec(),
    )
    .with_default(e0, mu0)
    .with_start(s.q);
    for (a, b, e, mu) in pairs {
        impacts = impacts.with_pair(a, b, e, mu);
    }
    for wall in walls_read {
        impacts = impacts.with_wall(wall);
    }
    if let Some(o) = impacts.overlap(s.q) {
        let what = match (o.other, o.wall) {
            (Some(b), _) => format!("`{}` and `{}`", s.names[o.body], s.names[b]),
            (_, Some(w)) => format!(
                "`{}` and the wall `{}`",
                s.names[o.body],
                impacts.walls()[w].name
            ),
            _ => format!("`{}`", s.names[o.body]),
        };
        // located at the second body's position (or the wall's point): what to move
        let value_span = |t: &Table<'_, '_>, key: &str| {
            t.get(key)
                .or_else(|| t.get("radius"))
                .map_or(t.span.clone(), toml::Spanned::span)
        };
        let bodies = root.tables("body")?;
        let span = match (o.other, o.wall) {
            (Some(b), _) => bodies.get(b).map(|t| value_span(t, "position")),
            (_, Some(w)) => walls.get(w).map(|t| value_span(t, "point")),
            _ => bodies.get(o.body).map(|t| value_span(t, "radius")),
        }
        .unwrap_or_else(|| root.span.clone());
        return Err(root
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "{what} overlap by {} m at t = 0",
                    // six digits: a difference of positions carries rounding noise
                    crate::error::short(format!("{:.5e}", o.depth).parse().unwrap_or(o.depth))
                ),
                span,
            )
            .with_hint("move them apart (touching is allowed) or make the radii smaller"));
    }
    Ok(ContactSetup {
        events: impacts.events(),
        forces: Vec::new(),
        walls: drawn,
    })
}

/// `model = "spring"` or `"hertz"`: a contact force between every two bodies with a radius and
/// between each of them and every wall, with `stiffness` and optional `damping`.
fn contact_force(
    c: &Table<'_, '_>,
    model: &str,
    s: &Spheres<'_>,
    walls: &[Wall],
    env: ValueEnv<'_>,
) -> Result<ContactSetup, ScenarioError> {
    for key in ["restitution", "friction", "pair"] {
        if c.get(key).is_some() {
            return Err(c
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("`{key}` belongs to the impulse model, not to `model = \"{model}\"`"),
                    c.key_span(key),
                )
                .with_hint("a contact force loses energy through its `damping`"));
        }
    }
    let hertz = model == "hertz";
    // k δ (N/m) or k δ^(3/2) (N/m^(3/2)); damping c δ̇ (N s/m) or Hunt-Crossley α k δ^(3/2) δ̇ (s/m)
    let (k_dim, c_dim) = if hertz {
        (
            Dimension::FORCE / Dimension::LENGTH.pow_ratio(3, 2).expect("m^(3/2) exists"),
            Dimension::TIME / Dimension::LENGTH,
        )
    } else {
        (Dimension::STIFFNESS, Dimension::LINEAR_DRAG)
    };
    let k = scalar(c, "stiffness", k_dim, env)?.ok_or_else(|| {
        c.missing(
            "stiffness",
            if hertz {
                "\"1e6 N/m^1.5\""
            } else {
                "\"1e4 N/m\""
            },
        )
        .with_hint(format!("a `{model}` contact needs its stiffness"))
    })?;
    let law = if hertz {
        ContactLaw::hertz(k)
    } else {
        ContactLaw::linear(k)
    };
    let damping = match scalar(c, "damping", c_dim, env)? {
        None => ContactDamping::None,
        Some(d) if hertz => ContactDamping::HuntCrossley { alpha: d },
        Some(d) => ContactDamping::Linear { c: d },
    };
    let spheres: Vec<(usize, Real)> = s
        .radius
        .iter()
        .enumerate()
        .filter_map(|(i, r)| r.map(|r| (i, r)))
        .collect();
    let mut builder = ContactForce::builder(s.dim)
        .name("contact")
        .law(law)
        .damping(damping)
        .spheres(&spheres);
    for w in walls {
        builder = builder.wall(&w.point, &w.normal, &spheres);
    }
    let force = builder.build().map_err(|e| {
        c.src
            .error(ErrorKind::Invalid, e.to_string(), c.span.clone())
            .with_hint("check `stiffness` and `damping` in [contact]")
    })?;
    Ok(ContactSetup {
        events: Vec::new(),
        forces: force.into_forces(),
        walls: Vec::new(),
    })
}
