//! Reading a `[[joint]]` of a mechanism (in a plane or in space): what it holds, its surface
//! and friction, and the modes it switches.

use std::ops::Range;

use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::contact::{friction, surface, surface_body};
use super::{Rigid, RigidTurn};
use crate::Real;
use crate::particles::spin;
use crate::rigid::mechanism::{Anchor, Joint, JointKind, Mechanism, MechanismBody};
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::values::{ValueEnv, scalar, vector};

const JOINT_KEYS: &[&str] = &[
    "name", "kind", "a", "b", "on", "length", "radius", "surface", "mu", "mu_s", "mu_k", "rolling",
    "centre", "center", "wheel", "y", "axis",
];
const JOINT_KINDS: &[&str] = &["hinge", "rod", "string", "contact", "pulley", "curve"];

/// What joints refer to.
pub(super) struct Names<'a> {
    /// Spatial dimensions (2 or 3).
    pub(super) dim: usize,
    pub(super) bodies: &'a [String],
    pub(super) n_particles: usize,
    pub(super) rigid: &'a [Rigid],
    pub(super) env: ValueEnv<'a>,
}

impl Names<'_> {
    /// The bodies of a planar mechanism as the solver sees them (masses left at 1: for
    /// geometry only).
    fn solver_bodies(&self) -> Vec<MechanismBody> {
        let n = self.bodies.len();
        (0..n)
            .map(|b| MechanismBody {
                x: 2 * b,
                angle: b.checked_sub(self.n_particles).map(|k| 2 * n + k),
                spinner: None,
                inv_mass: 1.0,
                inv_inertia: 1.0,
            })
            .collect()
    }

    /// Where `a` is in the initial state `q` (positions only).
    fn position(&self, a: Anchor, q: &[Real]) -> [Real; 3] {
        match a {
            Anchor::World(p) => p,
            Anchor::Body { body, r } => {
                let d = self.dim;
                let w = match body
                    .checked_sub(self.n_particles)
                    .map(|k| &self.rigid[k].turn)
                {
                    Some(RigidTurn::Plane { theta, .. }) => {
                        let (s, c) = theta.sin_cos();
                        [c * r[0] - s * r[1], s * r[0] + c * r[1], r[2]]
                    }
                    Some(RigidTurn::Space { orientation, .. }) => spin::rotate(*orientation, r),
                    None => r,
                };
                let mut p = w;
                for (k, x) in p.iter_mut().enumerate().take(d) {
                    *x += q[d * body + k];
                }
                p
            }
        }
    }

    /// A hinge's `axis` (world directions at the start, in space only), as fixed in the frames
    /// of `a` and `b`.
    fn hinge_axis(
        &self,
        t: &Table<'_, '_>,
        a: Anchor,
        b: Anchor,
    ) -> Result<Option<[[Real; 3]; 2]>, ScenarioError> {
        let Some(v) = t.get("axis") else {
            return Ok(None);
        };
        if self.dim == 2 {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    "in a plane a hinge turns about the plane's normal: it takes no `axis`",
                    v.span(),
                )
                .with_hint("leave out `axis`, or set `dimensions = 3`"));
        }
        let d = vector(t, "axis", Dimension::NONE, 3, self.env)?.unwrap_or_default();
        let n = d.iter().map(|x| x * x).sum::<Real>().sqrt();
        if !(n > 0.0 && n.is_finite()) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    "the hinge's `axis` must not be zero",
                    v.span(),
                )
                .with_hint("the direction the hinge turns about, at the start: [0, 0, 1]"));
        }
        let d = [d[0] / n, d[1] / n, d[2] / n];
        let in_frame = |anchor: Anchor| match anchor {
            Anchor::Body { body, .. } => match body
                .checked_sub(self.n_particles)
                .map(|k| &self.rigid[k].turn)
            {
                Some(RigidTurn::Space { orientation, .. }) => spin::unrotate(*orientation, d),
                _ => d,
            },
            Anchor::World(_) => d,
        };
        Ok(Some([in_frame(a), in_frame(b)]))
    }

    /// The example of a fixed point, for messages.
    fn fixed_point(&self) -> &'static str {
        if self.dim == 2 {
            "[\"0 m\", \"0 m\"]"
        } else {
            "[\"0 m\", \"0 m\", \"0 m\"]"
        }
    }

    /// `"body"` (its centre of mass) or `"body.point"`.
    pub(super) fn anchor(&self, text: &str) -> Result<Anchor, String> {
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
                r: [0.0; 3],
            });
        };
        let Some(rigid) = b.checked_sub(self.n_particles).map(|k| &self.rigid[k]) else {
            return Err(format!(
                "`{body}` is a particle: it has no points; write `{body}`"
            ));
        };
        super::points::find_point(&rigid.points, body, point).map(|r| Anchor::Body { body: b, r })
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
        let p = vector(t, key, Dimension::LENGTH, self.dim, self.env)?.unwrap_or_default();
        Ok(Some(Anchor::World([
            p[0],
            p[1],
            p.get(2).copied().unwrap_or(0.0),
        ])))
    }
}

/// Reads the `[[joint]]` `t` (the `index`th) at the initial positions `q`; the modes it
/// switches are pushed onto `modes`, whose first is coordinate `first_mode`.
pub(super) fn read_joint(
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
    let position = |a: Anchor| ctx.position(a, q);
    let env = ctx.env;
    let plane_only = |what: &str| -> Result<(), ScenarioError> {
        if ctx.dim == 2 {
            return Ok(());
        }
        Err(src
            .error(
                ErrorKind::Invalid,
                format!("a {what} joint works in a plane (`dimensions = 2`), not in space"),
                kind_span.clone(),
            )
            .with_hint(
                "in space: hinge (a ball joint), rod, string, contact (a point or ball on a plane)",
            ))
    };
    let need = |key: &str, example: &str| -> Result<Anchor, ScenarioError> {
        ctx.anchor_key(t, key)?.ok_or_else(|| {
            t.missing(key, example).with_hint(format!(
                "a {kind} joint names what it holds: a body, \"body.point\" or a fixed point {}",
                ctx.fixed_point()
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
            let (pa, pb) = (position(a), position(b));
            crate::rigid::mechanism::distance(pa, pb)
        };
        if !(l > 0.0 && l.is_finite()) {
            return Err(src
                .error(ErrorKind::Invalid, format!("the {kind}'s `{key}` must be positive, not {} m", crate::error::short(l)), key_or(t, key, &kind_span))
                .with_hint("give `length`, or place the ends apart (the length defaults to their distance at the start)"));
        }
        Ok(l)
    };
    let kind = match kind {
        "hinge" | "pin" => {
            let a = need("a", "\"rod.end\"")?;
            let b = match ctx.anchor_key(t, "b")? {
                Some(b) => b,
                None => Anchor::World(position(a)),
            };
            let axis = ctx.hinge_axis(t, a, b)?;
            JointKind::Hinge { a, b, axis }
        }
        "rod" => {
            let (a, b) = (need("a", "\"ball\"")?, need("b", ctx.fixed_point())?);
            JointKind::Rod {
                a,
                b,
                length: length_or("length", a, b)?,
            }
        }
        "string" | "rope" | "cable" => {
            let (a, b) = (need("a", "\"ball\"")?, need("b", ctx.fixed_point())?);
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
                    format!(
                        "`radius` must be zero or positive, not {} m",
                        crate::error::short(radius)
                    ),
                    t.key_span("radius"),
                ));
            }
            let (point, normal) = surface(t, env, &kind_span, ctx.dim)?;
            let point = match surface_body(t, ctx)? {
                Some(body) => Anchor::Body { body, r: point },
                None => Anchor::World(point),
            };
            let mode = new_mode("touching");
            let friction = friction(t, env, &mut new_mode, ctx.dim)?;
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
            plane_only("curve")?;
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
                crate::rigid::mechanism::Curve::new(&parsed.expr, &constants).map_err(|name| {
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
            plane_only("pulley")?;
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
                    r: [0.0; 3],
                },
                (None, None, None) => {
                    return Err(t.missing("centre", "[\"0 m\", \"0 m\"]").with_hint("the pulley's axle: a fixed point, or `wheel` (a rigid body whose centre it is)"));
                }
            };
            let radius = scalar(t, "radius", Dimension::LENGTH, env)?.unwrap_or(0.0);
            if !(radius >= 0.0 && radius.is_finite()) {
                return Err(src.error(
                    ErrorKind::Invalid,
                    format!(
                        "`radius` must be zero or positive, not {} m",
                        crate::error::short(radius)
                    ),
                    t.key_span("radius"),
                ));
            }
            let c = position(centre);
            let (pa, pb) = (position(a), position(b));
            let outside = |p: [Real; 3]| (p[0] - c[0]).hypot(p[1] - c[1]) > radius;
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
                let zero = vec![0.0; 2 * ctx.bodies.len() + ctx.rigid.len()];
                let mut qq = q.to_vec();
                qq.extend(ctx.rigid.iter().map(|r| match r.turn {
                    RigidTurn::Plane { theta, .. } => theta,
                    RigidTurn::Space { .. } => 0.0,
                }));
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
                    2,
                );
                probe.pulley_length(&qq, &zero)
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
    super::distinct::refuse_one_body_twice(t, &name, &kind, ctx.bodies)?;
    Ok(Joint { name, kind })
}

pub(super) fn key_or(t: &Table<'_, '_>, key: &str, other: &Range<usize>) -> Range<usize> {
    t.get(key)
        .map_or_else(|| other.clone(), toml::Spanned::span)
}
