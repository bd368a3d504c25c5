//! `mechkit rigid-collide`: a hinged body (a rod, a body file, or a given moment of inertia)
//! struck by a block, with restitution, through `mechkit::rigid::impact::hinged_report`; the
//! release from an angle gives ω₀ by energy conservation (`PivotedBody::released`).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::collisions::Restitution;
use mechkit::expr::units::Dimension;
use mechkit::rigid::Input;
use mechkit::rigid::impact::{
    Contact, HingedReport, ImpactError, Particle, PivotedBody, hinged_report,
};

use super::input::{quantity, show, split_top_level};
use super::{Outcome, report};
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

/// The flag of an input of `mechkit rigid-collide` (the body file's name for the inertia of a
/// body given by `--body`).
pub(super) fn flag(input: Option<Input>, args: &RigidCollideArgs) -> String {
    if let (Some(Input::Inertia), Some(file)) = (input, &args.body) {
        return format!("--body {}", file.display());
    }
    match input {
        Some(Input::Inertia) => "--inertia",
        Some(Input::Normal) => "--normal",
        Some(Input::BlockMass) => "--block-mass",
        Some(Input::BlockVelocity) | None => "--block-velocity",
        Some(Input::Length) => "--length",
        Some(Input::Pivot) if args.rod => "--pivot-at",
        Some(Input::Pivot) => "--pivot",
        Some(Input::CentreOfMass) => "--cm-distance",
        Some(Input::ReleaseAngle) => "--release-angle",
        Some(Input::Gravity) => "--g",
        Some(Input::AngularVelocity) => "--omega",
        Some(Input::ContactPoint) => "--hit-at",
        Some(Input::Restitution) => "--restitution",
        Some(Input::Tilt) => "--tilt",
        Some(Input::Velocity) => "--velocity",
        _ => "--mass",
    }
    .to_string()
}

/// The hinged body (at rest), the default contact point (the lower end of a rod), and the
/// body in words.
fn hinged(args: &RigidCollideArgs) -> Result<(PivotedBody, Option<[f64; 2]>, String)> {
    let err = |e: ImpactError| anyhow!("{}: {e}", flag(e.input(), args));
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
        let (rod, lower_end) = PivotedBody::hinged_rod(mass()?, l, from_top).map_err(err)?;
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
            mechkit::expr::span::printable(&loaded.title),
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
    let err = |e: ImpactError| anyhow!("{}: {e}", flag(e.input(), args));
    let (body, default_hit, what) = hinged(args)?;
    let (body, release) = match (&args.omega, &args.release_angle) {
        (Some(w), _) => (
            PivotedBody {
                omega: quantity(w, "--omega", Dimension::FREQUENCY)?,
                ..body
            },
            None,
        ),
        (None, Some(a)) => {
            let theta0 = quantity(a, "--release-angle", Dimension::NONE)?;
            let g = quantity(&args.g, "--g", Dimension::ACCELERATION)?;
            (body.released(g, theta0).map_err(err)?, Some(theta0))
        }
        (None, None) => {
            bail!("give --omega (the body's angular velocity at the impact) or --release-angle")
        }
    };
    let point = match &args.hit_at {
        Some(text) if text.contains(',') => planar(text, "--hit-at", Dimension::LENGTH)?,
        Some(text) => [0.0, -quantity(text, "--hit-at", Dimension::LENGTH)?],
        None => default_hit.ok_or_else(|| {
            anyhow!("give --hit-at: the distance of the contact below the pivot, or \"x, y\"")
        })?,
    };
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
        normal: planar(&args.normal, "--normal", Dimension::NONE)?,
        restitution: restitution(&args.restitution)?,
    };
    let result = hinged_report(&body, &block, &contact, release).map_err(err)?;
    for w in &result.warnings {
        eprintln!("warning: {w}");
    }
    report(args.report, &result, || text(&what, &result))?;
    Ok(Outcome::Success)
}

fn text(what: &str, r: &HingedReport) -> String {
    let v2 = |v: [f64; 2]| format!("({}, {})", show(v[0]), show(v[1]));
    let mut out = format!("hinged {what}\n");
    if let Some(theta0) = r.release_angle {
        let _ = writeln!(
            out,
            "released from rest at {} rad: ω₀ = sqrt(2 M g d (1 − cos θ₀)/I_O) = {} rad/s",
            show(theta0),
            show(r.omega0)
        );
    } else {
        let _ = writeln!(out, "ω before = {} rad/s", show(r.omega0));
    }
    let (c, b) = (&r.contact, &r.block);
    let _ = writeln!(
        out,
        "block {} kg at {} m with velocity {} m/s, normal {}, e = {}",
        show(b.mass),
        v2(c.point),
        v2(b.velocity_before),
        v2(c.normal),
        show(c.restitution)
    );
    let _ = writeln!(
        out,
        "after: ω = {} rad/s, block velocity {} m/s",
        show(r.omega_after),
        v2(b.velocity_after)
    );
    let _ = writeln!(
        out,
        "impulse on the block J = {} N s (effective mass {} kg); hinge impulse {} N s",
        show(r.impulse),
        show(r.effective_mass),
        v2(r.hinge_impulse)
    );
    let k = &r.kinetic_energy;
    let _ = writeln!(
        out,
        "kinetic energy {} J → {} J (ΔK = {} J; closed form −½(1 − e²) m_eff u² = {} J)",
        show(k.before),
        show(k.after),
        show(k.change),
        show(k.change_closed_form + 0.0)
    );
    let l = &r.angular_momentum_about_pivot;
    let _ = writeln!(
        out,
        "angular momentum about the pivot {} → {} kg m²/s (difference {:.1e})",
        show(l.before),
        show(l.after),
        l.difference
    );
    if let Some(cp) = r.body.centre_of_percussion {
        let _ = writeln!(
            out,
            "centre of percussion {} m from the pivot (a blow there leaves no hinge impulse)",
            show(cp)
        );
    }
    out
}
