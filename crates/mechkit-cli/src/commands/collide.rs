//! `mechkit collide`: two bodies colliding with a coefficient of restitution (and optional
//! Coulomb friction), in 1-D, 2-D or 3-D.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::collisions::{Collision, Outcome, Resolution, Restitution};
use mechkit::expr::units::Dimension;
use serde_json::json;

use super::input::{quantity, show, split_top_level};
use super::{Outcome as Exit, print};
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

fn mass(text: &str, flag: &str) -> Result<f64> {
    let t = text.trim().to_ascii_lowercase();
    if ["inf", "infinity", "∞", "wall"].contains(&t.as_str()) {
        return Ok(f64::INFINITY);
    }
    let m = quantity(text, flag, Dimension::MASS)?;
    if m.is_nan() || m <= 0.0 {
        bail!("{flag} {text}: a mass must be positive (use inf for an immovable wall)");
    }
    Ok(m)
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

pub fn collide(args: &CollideArgs) -> Result<Exit> {
    let (m1, m2) = (mass(&args.m1, "--m1")?, mass(&args.m2, "--m2")?);
    let v1 = vector(&args.v1, "--v1", Dimension::VELOCITY)?;
    let v2 = vector(&args.v2, "--v2", Dimension::VELOCITY)?;
    let restitution =
        Restitution::parse(&args.restitution).map_err(|e| anyhow!("--restitution: {e}"))?;
    let d = v1.len().max(v2.len());
    // a single number for the other body's velocity means that component along x, 0 elsewhere
    let pad = |mut v: Vec<f64>, flag: &str| -> Result<Vec<f64>> {
        if v.len() == 1 && d > 1 && v[0] == 0.0 {
            v.resize(d, 0.0);
        }
        if v.len() != d {
            bail!(
                "{flag} has {} components but the other velocity has {d}",
                v.len()
            );
        }
        Ok(v)
    };
    let (v1, v2) = (pad(v1, "--v1")?, pad(v2, "--v2")?);
    let normal = match (&args.normal, &args.r1, &args.r2) {
        (Some(n), None, None) => vector(n, "--normal", Dimension::NONE)?,
        (None, Some(a), Some(b)) => {
            let (a, b) = (
                vector(a, "--r1", Dimension::LENGTH)?,
                vector(b, "--r2", Dimension::LENGTH)?,
            );
            Collision::normal_between(&a, &b).map_err(|e| anyhow!("--r1/--r2: {e}"))?
        }
        (None, None, None) if d == 1 => vec![1.0],
        (None, None, None) => bail!(
            "in {d}-D give the contact normal from body 1 to body 2 (--normal \"1,0\") or the centres of the two spheres (--r1 and --r2)"
        ),
        (Some(_), _, _) => bail!("give either --normal or the centres --r1 and --r2, not both"),
        _ => bail!("give both centres, --r1 and --r2"),
    };
    if normal.len() != d {
        bail!(
            "the normal has {} components but the velocities have {d}",
            normal.len()
        );
    }
    let friction = args.friction.unwrap_or(0.0);
    let g = match &args.g {
        None => None,
        Some(text) => {
            let g = quantity(text, "--g", Dimension::ACCELERATION)?;
            if !(g > 0.0 && g.is_finite()) {
                bail!(
                    "--g {text}: the gravitational acceleration must be positive, e.g. \"9.81 m/s^2\""
                );
            }
            Some(g)
        }
    };
    let c = Collision {
        m1,
        m2,
        v1,
        v2,
        normal,
        restitution,
        friction,
    };
    let resolution = c.resolve().map_err(|e| anyhow!("{e}"))?;
    match resolution {
        Resolution::Separating { approach_speed } => {
            if args.json {
                let j = json!({"collided": false, "approach_speed": approach_speed});
                print(&format!("{j:#}\n"))?;
            } else {
                print(&format!(
                    "no collision: along the normal the bodies are not approaching (they separate at {} m/s), so no impulse is applied\n",
                    show(-approach_speed + 0.0)
                ))?;
            }
        }
        Resolution::Collided(o) => {
            if args.json {
                let mut j = to_json(&c, &o);
                if let Some(g) = g {
                    let [h1, h2] = o.rise(g);
                    j["g"] = json!(g);
                    j["rise1"] = json!(h1);
                    j["rise2"] = json!(h2);
                }
                print(&format!("{j:#}\n"))?;
            } else {
                let mut out = text(&c, &o);
                if let Some(g) = g {
                    let [h1, h2] = o.rise(g);
                    let _ = writeln!(
                        out,
                        "  rise afterwards, h = v²/(2g) with g = {} m/s²: body 1 {} m, body 2 {} m",
                        show(g),
                        show(h1),
                        show(h2)
                    );
                }
                print(&out)?;
            }
        }
    }
    Ok(Exit::Success)
}

fn clean(o: &Outcome, speed: f64) -> Outcome {
    let snap = |x: f64, scale: f64| if x.abs() <= 1e-12 * scale { 0.0 } else { x };
    let vec = |v: &[f64], scale: f64| v.iter().map(|&x| snap(x, scale)).collect::<Vec<_>>();
    let mut o = o.clone();
    for v in [&mut o.v1, &mut o.v2, &mut o.v_cm] {
        *v = vec(v, speed);
    }
    for v in o
        .cm_frame_before
        .iter_mut()
        .chain(o.cm_frame_after.iter_mut())
    {
        *v = vec(v, speed);
    }
    o.separation_speed = snap(o.separation_speed, speed);
    o.kinetic_after = snap(o.kinetic_after, o.kinetic_before);
    o
}

fn to_json(c: &Collision, o: &Outcome) -> serde_json::Value {
    let m = |x: f64| {
        if x.is_finite() {
            json!(x)
        } else {
            json!("inf")
        }
    };
    json!({
        "collided": true,
        "m1": m(c.m1), "m2": m(c.m2),
        "restitution": c.restitution.value(),
        "friction": c.friction,
        "v1_before": c.v1, "v2_before": c.v2,
        "v1": o.v1, "v2": o.v2,
        "impulse": o.impulse,
        "normal_impulse": o.normal_impulse,
        "tangential_impulse": o.tangential_impulse,
        "sticks": o.sticks,
        "approach_speed": o.approach_speed,
        "separation_speed": o.separation_speed,
        "kinetic_before": o.kinetic_before,
        "kinetic_after": o.kinetic_after,
        "kinetic_lost": o.energy_lost(),
        "v_cm": o.v_cm,
        "cm_frame": {
            "before": {"v1": o.cm_frame_before[0], "v2": o.cm_frame_before[1]},
            "after": {"v1": o.cm_frame_after[0], "v2": o.cm_frame_after[1]},
        },
    })
}

fn text(c: &Collision, o: &Outcome) -> String {
    // values below 1e-12 of the speeds involved are rounding noise: print them as 0
    let scale =
        c.v1.iter()
            .chain(&c.v2)
            .fold(o.approach_speed, |m, v| m.max(v.abs()));
    let o = &clean(o, scale);
    let mut out = format!(
        "collision with e = {}{}:\n",
        c.restitution.value(),
        if c.friction > 0.0 {
            format!(", friction μ = {}", c.friction)
        } else {
            String::new()
        }
    );
    let _ = writeln!(
        out,
        "  body 1: {} -> {} m/s",
        fmt_vec(&c.v1),
        fmt_vec(&o.v1)
    );
    let _ = writeln!(
        out,
        "  body 2: {} -> {} m/s",
        fmt_vec(&c.v2),
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
    let lost = o.energy_lost();
    let _ = writeln!(
        out,
        "  kinetic energy {} J -> {} J, lost {} J ({:.2} %)",
        show(o.kinetic_before),
        show(o.kinetic_after),
        show(lost + 0.0),
        if o.kinetic_before > 0.0 {
            100.0 * lost / o.kinetic_before
        } else {
            0.0
        }
    );
    let _ = writeln!(out, "  centre of mass moves at {} m/s", fmt_vec(&o.v_cm));
    let _ = writeln!(
        out,
        "  in the centre-of-mass frame: body 1 {} -> {}, body 2 {} -> {} m/s",
        fmt_vec(&o.cm_frame_before[0]),
        fmt_vec(&o.cm_frame_after[0]),
        fmt_vec(&o.cm_frame_before[1]),
        fmt_vec(&o.cm_frame_after[1])
    );
    out
}
