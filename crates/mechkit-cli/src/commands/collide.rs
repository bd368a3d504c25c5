//! `mechkit collide`: two bodies colliding with a coefficient of restitution (and optional
//! Coulomb friction), in 1-D, 2-D or 3-D: `mechkit::collisions::CollisionSetup::report`.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::collisions::{
    Collided, CollisionError, CollisionInput, CollisionReport, CollisionSetup, Contact, Restitution,
};
use mechkit::expr::units::Dimension;

use super::input::{quantity, show, split_top_level};
use super::{Outcome as Exit, report};
use crate::args::CollideArgs;

/// A vector flag: components separated by commas, each a quantity of `dim`.
fn vector(text: &str, flag: &str, dim: Dimension) -> Result<Vec<f64>> {
    let parts = split_top_level(text, ',');
    if parts.len() > 3 || parts.iter().any(|p| p.is_empty()) {
        bail!(
            "{flag} `{text}`: give 1, 2 or 3 components separated by commas, e.g. \"3 m/s, -1 m/s\""
        );
    }
    parts.iter().map(|p| quantity(p, flag, dim)).collect()
}

/// A mass: a quantity, or `inf` (`wall`) for an immovable body; its sign is checked by the
/// library.
fn mass(text: &str, flag: &str) -> Result<f64> {
    let t = text.trim().to_ascii_lowercase();
    if ["inf", "infinity", "∞", "wall"].contains(&t.as_str()) {
        return Ok(f64::INFINITY);
    }
    quantity(text, flag, Dimension::MASS)
}

/// The flag of an input of the collision.
fn flag(e: &CollisionError) -> Option<&'static str> {
    Some(match e.input()? {
        CollisionInput::Mass1 => "--m1",
        CollisionInput::Mass2 => "--m2",
        CollisionInput::Velocity1 => "--v1",
        CollisionInput::Velocity2 => "--v2",
        CollisionInput::Restitution => "--restitution",
        CollisionInput::Normal if matches!(e, CollisionError::NormalNeeded { .. }) => {
            "--normal (or --r1 and --r2)"
        }
        CollisionInput::Normal => "--normal",
        CollisionInput::Centres => "--r1/--r2",
        CollisionInput::Friction => "--friction",
        CollisionInput::Gravity => "--g",
        _ => return None,
    })
}

/// The library's error with the flag of the input it is about.
#[allow(clippy::needless_pass_by_value)] // the shape `map_err` wants
fn with_flag(e: CollisionError) -> anyhow::Error {
    match flag(&e) {
        Some(flag) => anyhow!("{flag}: {e}"),
        None => anyhow!("{e}"),
    }
}

fn fmt_vec(v: &[f64]) -> String {
    if v.len() == 1 {
        show(v[0] + 0.0)
    } else {
        format!(
            "({})",
            v.iter()
                .map(|x| show(x + 0.0))
                .collect::<Vec<_>>()
                .join(", ")
        )
    }
}

/// The flags as a [`CollisionSetup`].
fn setup(args: &CollideArgs) -> Result<CollisionSetup> {
    let contact = match (&args.normal, &args.r1, &args.r2) {
        (Some(n), None, None) => Contact::Normal(vector(n, "--normal", Dimension::NONE)?),
        (None, Some(a), Some(b)) => Contact::Centres {
            r1: vector(a, "--r1", Dimension::LENGTH)?,
            r2: vector(b, "--r2", Dimension::LENGTH)?,
        },
        (None, None, None) => Contact::HeadOn,
        (Some(_), _, _) => bail!("give either --normal or the centres --r1 and --r2, not both"),
        _ => bail!("give both centres, --r1 and --r2"),
    };
    let g = match &args.g {
        Some(text) => Some(quantity(text, "--g", Dimension::ACCELERATION)?),
        None => None,
    };
    Ok(CollisionSetup {
        m1: mass(&args.m1, "--m1")?,
        m2: mass(&args.m2, "--m2")?,
        v1: vector(&args.v1, "--v1", Dimension::VELOCITY)?,
        v2: vector(&args.v2, "--v2", Dimension::VELOCITY)?,
        restitution: Restitution::parse(&args.restitution).map_err(with_flag)?,
        contact,
        friction: args.friction.unwrap_or(0.0),
        g,
    })
}

pub fn collide(args: &CollideArgs) -> Result<Exit> {
    let result = setup(args)?.report().map_err(with_flag)?;
    report(args.report, &result, || match &result {
        CollisionReport::Separating(s) => format!(
            "no collision: along the normal the bodies are not approaching (they separate at {} m/s), so no impulse is applied\n",
            show(-s.approach_speed + 0.0)
        ),
        CollisionReport::Collided(c) => text(&c.without_noise()),
    })?;
    Ok(Exit::Success)
}

fn text(o: &Collided) -> String {
    let mut out = format!(
        "collision with e = {}{}:\n",
        show(o.restitution),
        if o.friction > 0.0 {
            format!(", friction μ = {}", show(o.friction))
        } else {
            String::new()
        }
    );
    let _ = writeln!(
        out,
        "  body 1: {} -> {} m/s",
        fmt_vec(&o.v1_before),
        fmt_vec(&o.v1)
    );
    let _ = writeln!(
        out,
        "  body 2: {} -> {} m/s",
        fmt_vec(&o.v2_before),
        fmt_vec(&o.v2)
    );
    let _ = writeln!(
        out,
        "  impulse on body 2: {} N s (normal {}{})",
        fmt_vec(&o.impulse),
        show(o.normal_impulse),
        match o.sticks {
            Some(true) => format!(
                ", tangential {}: the contact sticks",
                show(o.tangential_impulse)
            ),
            Some(false) => format!(
                ", tangential {}: the contact slides",
                show(o.tangential_impulse)
            ),
            None => String::new(),
        }
    );
    let _ = writeln!(
        out,
        "  approach speed {} m/s, separation speed {} m/s",
        show(o.approach_speed),
        show(o.separation_speed)
    );
    // an immovable body: the energies are in its frame (the library's), where it does no work
    let immovable = [o.m1, o.m2].iter().position(|m| m.is_infinite());
    let frame = immovable.map_or_else(String::new, |k| {
        format!(
            " in the frame of body {} (immovable: the centre-of-mass frame)",
            k + 1
        )
    });
    let _ = writeln!(
        out,
        "  kinetic energy{frame} {} J -> {} J, lost {} J ({:.2} %)",
        show(o.kinetic_before),
        show(o.kinetic_after),
        show(o.kinetic_lost),
        if o.kinetic_before > 0.0 {
            // the ratio first: 100·K_lost overflows for energies near 1e308
            100.0 * (o.kinetic_lost / o.kinetic_before)
        } else {
            0.0
        }
    );
    let _ = writeln!(out, "  centre of mass moves at {} m/s", fmt_vec(&o.v_cm));
    let _ = writeln!(
        out,
        "  in the centre-of-mass frame: body 1 {} -> {}, body 2 {} -> {} m/s",
        fmt_vec(&o.cm_frame.before.v1),
        fmt_vec(&o.cm_frame.after.v1),
        fmt_vec(&o.cm_frame.before.v2),
        fmt_vec(&o.cm_frame.after.v2)
    );
    if let Some(r) = &o.rise {
        let _ = writeln!(
            out,
            "  rise afterwards, h = v²/(2g) with g = {} m/s²: body 1 {} m, body 2 {} m",
            show(r.g),
            show(r.rise1),
            show(r.rise2)
        );
    }
    out
}
