//! `mechkit rigid-collide`: a hinged body (a rod, a body file, or a given moment of inertia)
//! struck by a block, with restitution; the release from an angle gives ω₀ by energy
//! conservation.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::collisions::Restitution;
use mechkit::expr::units::Dimension;
use mechkit::rigid::impact::{
    Contact, HingedImpact, ImpactError, Particle, PivotedBody, hinged_impact, release_omega,
};
use serde_json::{Value, json};

use super::input::{quantity, show, split_top_level};
use super::{Outcome, print};
use crate::args::RigidCollideArgs;

/// "vx" or "vx, vy" (or "x, y") with units of `dim`.
pub(super) fn planar(text: &str, flag: &str, dim: Dimension) -> Result<[f64; 2]> {
    let items = split_top_level(text, ',');
    if !(1..=2).contains(&items.len()) {
        bail!("{flag} `{text}` needs 1 or 2 components (x, y), e.g. \"2 m/s\" or \"2 m/s, 0\"");
    }
    let mut out = [0.0; 2];
    for (k, c) in items.iter().enumerate() {
        out[k] = quantity(c, flag, dim)?;
        if !out[k].is_finite() {
            bail!("{flag}: `{c}` is not a finite number");
        }
    }
    Ok(out)
}

/// `--restitution`: a number from 0 to 1 or a preset, read as `mechkit collide` reads it.
pub(super) fn restitution(text: &str) -> Result<f64> {
    Restitution::parse(text)
        .map(Restitution::value)
        .map_err(|e| anyhow!("--restitution: {e}"))
}

fn flag_of(e: &ImpactError) -> &'static str {
    match e {
        ImpactError::ZeroInertia { .. } | ImpactError::ParallelAxis { .. } => "--inertia",
        ImpactError::Normal { .. } => "--normal",
        ImpactError::Separating { .. } => "--block-velocity",
        ImpactError::Value { what, .. } if what.contains("particle") => "--block-mass",
        ImpactError::Value { what, .. } if what.contains("length") => "--length",
        ImpactError::Value { what, .. } if what.contains("pivot") => "--pivot-at",
        _ => "--mass",
    }
}

/// The hinged body (at rest) and the default contact point (the lower end of a rod).
fn hinged(args: &RigidCollideArgs) -> Result<(PivotedBody, Option<[f64; 2]>, String)> {
    let err = |e: ImpactError| anyhow!("{}: {e}", flag_of(&e));
    let mass = || -> Result<f64> {
        let m = args
            .mass
            .as_deref()
            .ok_or_else(|| anyhow!("--mass is needed for the hinged body, e.g. --mass \"1 kg\""))?;
        quantity(m, "--mass", Dimension::MASS)
    };
    if args.rod {
        let l = args
            .length
            .as_deref()
            .ok_or_else(|| anyhow!("--rod needs --length, e.g. --length \"1 m\""))?;
        let l = quantity(l, "--length", Dimension::LENGTH)?;
        let from_top = match args.pivot_at.trim() {
            "end" | "top" => 0.0,
            "centre" | "center" | "middle" => 0.5 * l,
            other => quantity(other, "--pivot-at", Dimension::LENGTH)?,
        };
        let rod = PivotedBody::rod(mass()?, l, 0.5 * l - from_top, 0.0).map_err(err)?;
        let lower_end = [0.0, -(l - from_top)];
        let place = if from_top == 0.0 {
            "at its top end".to_string()
        } else {
            format!("{} m from its top end", show(from_top))
        };
        let what = format!(
            "rod M = {} kg, L = {} m, hinged {place}",
            show(rod.mass),
            show(l)
        );
        return Ok((rod, Some(lower_end), what));
    }
    if let Some(i) = &args.inertia {
        let i = quantity(i, "--inertia", Dimension::MOMENT_OF_INERTIA)?;
        let d = args
            .cm_distance
            .as_deref()
            .map_or(Ok(0.0), |d| quantity(d, "--cm-distance", Dimension::LENGTH))?;
        let body = PivotedBody::new(i, mass()?, [0.0, -d], 0.0).map_err(err)?;
        let what = format!(
            "body I_O = {} kg m², M = {} kg, centre of mass {} m below the pivot",
            show(i),
            show(body.mass),
            show(d)
        );
        return Ok((body, None, what));
    }
    if let Some(path) = &args.body {
        let loaded = super::body::load(path, args.mass.as_deref())?;
        let pivot = args.pivot.as_deref().ok_or_else(|| {
            anyhow!("--body needs --pivot \"x, y, z\" (the axis is z through it)")
        })?;
        let pivot = super::body::point(pivot, "--pivot", Dimension::LENGTH)?;
        let body = PivotedBody::from_properties(&loaded.whole, &pivot, 0.0).map_err(err)?;
        let what = format!(
            "{} ({}): I_O = {} kg m² about z through the pivot, M = {} kg",
            loaded.title,
            path.display(),
            show(body.inertia),
            show(body.mass)
        );
        return Ok((body, None, what));
    }
    bail!(
        "give the hinged body: --rod (with --mass, --length), --inertia (with --mass, --cm-distance) or --body FILE --pivot"
    )
}

pub fn rigid_collide(args: &RigidCollideArgs) -> Result<Outcome> {
    if args.landing {
        return super::rigid_landing::landing(args);
    }
    let (body, default_hit, what) = hinged(args)?;
    let g = quantity(&args.g, "--g", Dimension::ACCELERATION)?;
    let (omega, release) = match (&args.omega, &args.release_angle) {
        (Some(w), _) => (quantity(w, "--omega", Dimension::FREQUENCY)?, None),
        (None, Some(a)) => {
            let theta0 = quantity(a, "--release-angle", Dimension::NONE)?;
            if body.cm_distance() == 0.0 {
                bail!(
                    "--release-angle: the centre of mass is at the pivot, so gravity does no work on the swing; give --omega"
                );
            }
            (release_omega(&body, g, theta0), Some(theta0))
        }
        (None, None) => {
            bail!("give --omega (the body's angular velocity at the impact) or --release-angle")
        }
    };
    let body = PivotedBody { omega, ..body };
    let point = match &args.hit_at {
        Some(text) if text.contains(',') => planar(text, "--hit-at", Dimension::LENGTH)?,
        Some(text) => [0.0, -quantity(text, "--hit-at", Dimension::LENGTH)?],
        None => default_hit.ok_or_else(|| {
            anyhow!("give --hit-at: the distance of the contact below the pivot, or \"x, y\"")
        })?,
    };
    let normal = planar(&args.normal, "--normal", Dimension::NONE)?;
    let block = Particle {
        mass: quantity(
            args.block_mass.as_deref().unwrap_or_default(),
            "--block-mass",
            Dimension::MASS,
        )?,
        velocity: planar(
            &args.block_velocity,
            "--block-velocity",
            Dimension::VELOCITY,
        )?,
    };
    let contact = Contact {
        point,
        normal,
        restitution: restitution(&args.restitution)?,
    };
    let warnings = body.warnings(point);
    for w in &warnings {
        eprintln!("warning: {w}");
    }
    let r = hinged_impact(&body, &block, &contact).map_err(|e| anyhow!("{}: {e}", flag_of(&e)))?;
    if args.json {
        print(&format!(
            "{:#}\n",
            to_json(&body, &block, &contact, &r, release, &warnings)
        ))?;
    } else {
        print(&text(&what, &body, &block, &contact, &r, release))?;
    }
    Ok(Outcome::Success)
}

fn to_json(
    body: &PivotedBody,
    block: &Particle,
    c: &Contact,
    r: &HingedImpact,
    release: Option<f64>,
    warnings: &[String],
) -> Value {
    let (k0, k1) = r.kinetic;
    let (l0, l1) = r.angular_momentum;
    json!({
        "body": {
            "inertia": body.inertia, "mass": body.mass, "cm_distance": body.cm_distance(),
            "centre_of_percussion": body.centre_of_percussion(),
        },
        "release_angle": release,
        "omega0": body.omega,
        "omega_after": r.omega_after,
        "contact": {"point": c.point, "normal": c.normal, "restitution": c.restitution},
        "block": {"mass": block.mass, "velocity_before": block.velocity, "velocity_after": r.velocity_after},
        "impulse": r.impulse,
        "hinge_impulse": r.hinge_impulse,
        "effective_mass": r.effective_mass,
        "normal_speed": {"before": r.normal_speed_before, "after": r.normal_speed_after},
        "kinetic_energy": {
            "before": k0, "after": k1, "change": k1 - k0, "change_closed_form": r.kinetic_change_exact,
            "ratio": if k0 > 0.0 { Value::from(k1 / k0) } else { Value::Null },
        },
        "angular_momentum_about_pivot": {"before": l0, "after": l1, "difference": l1 - l0},
        "momentum": {"before": r.momentum.0, "after": r.momentum.1},
        "warnings": warnings,
    })
}

fn text(
    what: &str,
    body: &PivotedBody,
    block: &Particle,
    c: &Contact,
    r: &HingedImpact,
    release: Option<f64>,
) -> String {
    let v2 = |v: [f64; 2]| format!("({}, {})", show(v[0]), show(v[1]));
    let mut out = format!("hinged {what}\n");
    if let Some(theta0) = release {
        let _ = writeln!(
            out,
            "released from rest at {} rad: ω₀ = sqrt(2 M g d (1 − cos θ₀)/I_O) = {} rad/s",
            show(theta0),
            show(body.omega)
        );
    } else {
        let _ = writeln!(out, "ω before = {} rad/s", show(body.omega));
    }
    let _ = writeln!(
        out,
        "block {} kg at {} m with velocity {} m/s, normal {}, e = {}",
        show(block.mass),
        v2(c.point),
        v2(block.velocity),
        v2(c.normal),
        show(c.restitution)
    );
    let _ = writeln!(
        out,
        "after: ω = {} rad/s, block velocity {} m/s",
        show(r.omega_after),
        v2(r.velocity_after)
    );
    let _ = writeln!(
        out,
        "impulse on the block J = {} N s (effective mass {} kg); hinge impulse {} N s",
        show(r.impulse),
        show(r.effective_mass),
        v2(r.hinge_impulse)
    );
    let (k0, k1) = r.kinetic;
    let _ = writeln!(
        out,
        "kinetic energy {} J → {} J (ΔK = {} J; closed form −½(1 − e²) m_eff u² = {} J)",
        show(k0),
        show(k1),
        show(k1 - k0),
        show(r.kinetic_change_exact + 0.0)
    );
    let (l0, l1) = r.angular_momentum;
    let _ = writeln!(
        out,
        "angular momentum about the pivot {} → {} kg m²/s (difference {:.1e})",
        show(l0),
        show(l1),
        l1 - l0
    );
    if let Some(cp) = body.centre_of_percussion() {
        let _ = writeln!(
            out,
            "centre of percussion {} m from the pivot (a blow there leaves no hinge impulse)",
            show(cp)
        );
    }
    out
}
