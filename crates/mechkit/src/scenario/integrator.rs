//! `[integrator]`: the method and its step size, fixed (`dt`) or adaptive (`rtol`, `atol`,
//! `h0`, `h_max`, `h_min`).

use mechkit_expr::nearest;
use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::values::{ValueEnv, resolve, scalar};
use crate::Real;
use crate::error::short;
use crate::ode::{AdaptiveConfig, MIN_RTOL, Method, MethodKind, SecondOrderSystem, Tolerance};
use crate::particles::ParticleSystem;
use crate::simulate::Stepping;

const KEYS: &[&str] = &["method", "dt", "rtol", "atol", "h0", "h_max", "h_min"];
const ADAPTIVE_KEYS: &[&str] = &["rtol", "atol", "h0", "h_max", "h_min"];

fn method_names(kind: Option<MethodKind>) -> String {
    Method::ALL
        .iter()
        .filter(|m| kind.is_none_or(|k| m.kind() == k))
        .map(|m| m.name())
        .collect::<Vec<_>>()
        .join(", ")
}

pub(crate) fn read_integrator(
    root: &Table<'_, '_>,
    env: ValueEnv<'_>,
    system: &ParticleSystem,
) -> Result<Stepping, ScenarioError> {
    let Some(t) = root.table("integrator")? else {
        return Err(
            ScenarioError::new(ErrorKind::Missing, "the scenario has no [integrator]").with_hint(
                "add:\n  [integrator]\n  method = \"rk4\"      # or dopri5 with rtol/atol, yoshida4, …\n  dt = \"1 ms\"",
            ),
        );
    };
    t.check_keys(KEYS)?;
    let (method, method_span) = match t.string("method")? {
        None => (Method::Rk4, t.span.clone()),
        Some((m, span)) => {
            let method = Method::from_name(m).ok_or_else(|| {
                let names: Vec<&str> = Method::ALL.iter().map(|m| m.name()).collect();
                let hint = mechkit_expr::did_you_mean(&nearest(m, names.iter().copied()))
                    .unwrap_or_else(|| format!("available: {}", names.join(", ")));
                t.src
                    .error(
                        ErrorKind::Invalid,
                        format!("unknown integration method `{m}`"),
                        span.clone(),
                    )
                    .with_hint(hint)
            })?;
            (method, span)
        }
    };
    let adaptive_key = ADAPTIVE_KEYS.iter().find(|k| t.get(k).is_some()).copied();
    let dt = scalar(&t, "dt", Dimension::TIME, env)?;
    if let Some(dt) = dt
        && !(dt > 0.0 && dt.is_finite())
    {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!("the time step `dt` must be positive, not {} s", short(dt)),
                value_span(&t, "dt"),
            )
            .with_hint("e.g. `dt = \"1 ms\"`"));
    }
    if method.needs_position_forces() && system.velocity_dependent() {
        let culprits: Vec<&str> = system
            .forces()
            .iter()
            .filter(|f| f.velocity_dependent())
            .map(crate::forces::Force::name)
            .collect();
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "`{}` is a symplectic splitting method: it needs forces of position and time only, but {} depend{} on the velocity",
                    method.name(),
                    culprits.iter().map(|c| format!("`{c}`")).collect::<Vec<_>>().join(", "),
                    if culprits.len() == 1 { "s" } else { "" }
                ),
                method_span,
            )
            .with_hint("use rk4, or dopri5 with rtol/atol; verlet accepts velocity-dependent forces at 2nd order"));
    }
    if !method.is_adaptive() {
        if let Some(key) = adaptive_key {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`{key}` controls adaptive steps, but `{}` takes fixed steps of `dt`",
                        method.name()
                    ),
                    t.key_span(key),
                )
                .with_hint(format!(
                    "remove `{key}`, or choose an adaptive method: {}",
                    method_names(Some(MethodKind::Adaptive))
                )));
        }
        let dt = dt.ok_or_else(|| {
            t.missing("dt", "\"1 ms\"").with_hint(format!(
                "`{}` takes fixed steps: add e.g. `dt = \"1 ms\"`, or choose an adaptive method ({}) with rtol/atol",
                method.name(),
                method_names(Some(MethodKind::Adaptive))
            ))
        })?;
        return Ok(Stepping::Fixed { method, dt });
    }
    if let Some(dt) = dt {
        if method.kind() == MethodKind::Implicit {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`{}` {} and chooses its own steps by its error estimate: it takes no `dt`",
                        method.name(),
                        if method == Method::Auto {
                            "turns implicit where the problem is stiff"
                        } else {
                            "is implicit"
                        }
                    ),
                    t.key_span("dt"),
                )
                .with_hint(
                    "remove `dt`; set rtol/atol for the accuracy, and h_max to bound the steps",
                ));
        }
        if let Some(key) = adaptive_key {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("`dt` fixes the step, but `{key}` asks for adaptive steps"),
                    t.key_span("dt"),
                )
                .with_hint("give one or the other: remove `dt` for adaptive steps (`h0` sets the first one), or remove the adaptive keys for fixed steps"));
        }
        return Ok(Stepping::Fixed { method, dt });
    }
    let mut config = AdaptiveConfig::default();
    if let Some(v) = t.get("rtol") {
        let r = resolve(&t.src, "rtol", v, Dimension::NONE, env)?;
        if !(r > 0.0 && r.is_finite()) {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("`rtol` must be positive, not {}", short(r)),
                    v.span(),
                )
                .with_hint("a relative tolerance such as 1e-8"));
        }
        if r < MIN_RTOL {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`rtol` = {} is below what double precision can deliver",
                        short(r)
                    ),
                    v.span(),
                )
                .with_hint(format!("use {} or more", short(MIN_RTOL))));
        }
        config.rtol = Tolerance::Scalar(r);
    }
    if let Some(v) = t.get("atol") {
        config.atol = atol(&t, v, env, system.dof())?;
    }
    for (key, slot) in [("h0", &mut config.h0), ("h_min", &mut config.h_min)] {
        if let Some(h) = positive_time(&t, key, env)? {
            *slot = Some(h);
        }
    }
    if let Some(h) = positive_time(&t, "h_max", env)? {
        config.h_max = h;
    }
    step_order(&t, &config)?;
    Ok(Stepping::Adaptive { method, config })
}

/// `h_min ≤ h0` and `h_min ≤ h_max`: otherwise the first step fails, mid-run, with no location.
fn step_order(t: &Table<'_, '_>, config: &AdaptiveConfig) -> Result<(), ScenarioError> {
    let Some(h_min) = config.h_min else {
        return Ok(());
    };
    for (large, value) in [("h_max", Some(config.h_max)), ("h0", config.h0)] {
        if let Some(value) = value
            && h_min > value
        {
            let span = t.get("h_min").map_or(t.span.clone(), toml::Spanned::span);
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`h_min` = {} s is larger than `{large}` = {} s: no step can satisfy both",
                        short(h_min),
                        short(value)
                    ),
                    span,
                )
                .with_hint(format!(
                    "make `h_min` at most `{large}`, or remove `h_min` (the default is set by the precision of t)"
                )));
        }
    }
    Ok(())
}

fn positive_time(
    t: &Table<'_, '_>,
    key: &str,
    env: ValueEnv<'_>,
) -> Result<Option<Real>, ScenarioError> {
    let v = scalar(t, key, Dimension::TIME, env)?;
    if let Some(h) = v
        && !(h > 0.0 && h.is_finite())
    {
        return Err(t.src.error(
            ErrorKind::Invalid,
            format!("`{key}` must be a positive time, not {} s", short(h)),
            value_span(t, key),
        ));
    }
    Ok(v)
}

/// `atol`: a number for every component, or `{ position = "1 mm", velocity = "1 mm/s" }`.
fn atol(
    t: &Table<'_, '_>,
    v: &toml::Spanned<DeValue<'_>>,
    env: ValueEnv<'_>,
    dof: usize,
) -> Result<Tolerance, ScenarioError> {
    let check = |a: Real, span: std::ops::Range<usize>| {
        if a >= 0.0 && a.is_finite() {
            Ok(a)
        } else {
            Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("`atol` must be zero or positive, not {}", short(a)),
                    span,
                )
                .with_hint("an absolute tolerance such as 1e-9"))
        }
    };
    if matches!(v.get_ref(), DeValue::Table(_)) {
        let Some(sub) = t.table("atol")? else {
            unreachable!("atol is a table")
        };
        sub.check_keys(&["position", "velocity"])?;
        let mut parts = Vec::new();
        for (key, dim) in [
            ("position", Dimension::LENGTH),
            ("velocity", Dimension::VELOCITY),
        ] {
            let value = sub.get(key).ok_or_else(|| {
                sub.missing(
                    key,
                    if key == "position" {
                        "\"1 um\""
                    } else {
                        "\"1 um/s\""
                    },
                )
                .with_hint("give both: atol = { position = \"1 um\", velocity = \"1 um/s\" }")
            })?;
            parts.push(check(resolve(&t.src, key, value, dim, env)?, value.span())?);
        }
        let mut per = vec![parts[0]; dof];
        per.extend(std::iter::repeat_n(parts[1], dof));
        return Ok(Tolerance::PerComponent(per));
    }
    if let DeValue::String(s) = v.get_ref()
        && s.trim().parse::<f64>().is_err()
    {
        return Err(t
            .src
            .error(
                ErrorKind::Invalid,
                format!("`atol` = \"{s}\": a single absolute tolerance applies to positions and velocities alike, so it takes no unit"),
                v.span(),
            )
            .with_hint("give a number (SI: metres and metres per second), or a table: atol = { position = \"1 mm\", velocity = \"1 mm/s\" }"));
    }
    let a = resolve(&t.src, "atol", v, Dimension::NONE, env)?;
    Ok(Tolerance::Scalar(check(a, v.span())?))
}

fn value_span(t: &Table<'_, '_>, key: &str) -> std::ops::Range<usize> {
    t.get(key).map_or(t.span.clone(), toml::Spanned::span)
}
