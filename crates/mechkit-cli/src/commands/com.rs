//! `mechkit com`: the centre of mass of point masses (with velocities: momentum, the
//! centre-of-mass frame and the kinetic-energy split).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::mass::image::FileFormat;
use mechkit::mass::{PointMassInput, PointMasses};

use super::body::{load, parts_text, point, vec_text};
use super::input::{output_unit, quantity, show, split_top_level};
use super::{Outcome, report};
use crate::args::ComArgs;

fn vector(text: &str, flag: &str, dim: Dimension) -> Result<Vec<f64>> {
    split_top_level(text, ',')
        .into_iter()
        .map(|c| quantity(c, flag, dim))
        .collect()
}

fn fmt(v: &[f64]) -> String {
    let parts: Vec<String> = v.iter().map(|x| show(x + 0.0)).collect();
    if parts.len() == 1 {
        parts[0].clone()
    } else {
        format!("({})", parts.join(", "))
    }
}

/// `mechkit com BODYFILE`: mass and centre of mass of the body and of each part.
fn body_file(args: &ComArgs, file: &std::path::Path) -> Result<Outcome> {
    for (flag, given) in [
        ("--mass/--at", !args.mass.is_empty() || !args.at.is_empty()),
        ("--mark", args.mark.is_some()),
        ("--pixel-size", args.pixel_size.is_some()),
        ("--threshold", args.threshold.is_some()),
    ] {
        if given {
            bail!("{flag} does not apply to a body file ({})", file.display());
        }
    }
    let body = load(file, args.total_mass.as_deref())?;
    let (scale, unit) = output_unit(
        args.unit.as_deref(),
        Dimension::LENGTH,
        ("m", "a positive length", "\"6371 km\" or \"pm\""),
        true,
    )?;
    let about = match &args.about {
        Some(a) => Some(point(a, "--about", Dimension::LENGTH)?),
        None => None,
    };
    let result = body.centre_of_mass(&unit, scale, about);
    report(args.report, &result, || {
        let mut out = format!(
            "{}\ntotal mass {} kg\n",
            mechkit::expr::span::printable(&result.title),
            show(result.total_mass)
        );
        let _ = writeln!(
            out,
            "centre of mass at {} {}",
            vec_text(&result.centre_of_mass_in_unit),
            if args.unit.is_some() {
                format!("(in units of {unit})")
            } else {
                "m".into()
            }
        );
        if let Some(a) = &result.about {
            let _ = writeln!(
                out,
                "distance from {} m: {} m",
                vec_text(&a.point),
                show(a.distance)
            );
        }
        out.push_str(&parts_text(&result.parts));
        out
    })?;
    Ok(Outcome::Success)
}

/// Flags of an image (or a body file) have no meaning with point masses: refused rather than
/// ignored.
fn reject_body_flags(args: &ComArgs) -> Result<()> {
    for (given, flag, example) in [
        (args.mark.is_some(), "--mark", "--mark marked.png"),
        (args.threshold.is_some(), "--threshold", "--threshold 1.5"),
        (args.channel != "sum", "--channel", "--channel r"),
        (args.invert, "--invert", "--invert"),
        (
            args.density_from_darkness,
            "--density-from-darkness",
            "--density-from-darkness",
        ),
        (
            args.pixel_size.is_some(),
            "--pixel-size",
            "--pixel-size \"0.5 mm\"",
        ),
        (
            args.scale.is_some(),
            "--scale",
            "--scale \"240 px = 12 cm\"",
        ),
        (args.origin.is_some(), "--origin", "--origin \"0, 480\""),
    ] {
        if given {
            bail!(
                "{flag} applies to an image of the body (mechkit com body.png {example}); it cannot be used with point masses (--mass)"
            );
        }
    }
    if args.total_mass.is_some() {
        bail!(
            "--total-mass applies to an image or a body file; with point masses the total is the sum of the --mass values"
        );
    }
    if args.about.is_some() {
        bail!(
            "--about applies to an image or a body file (mechkit com body.toml --about \"0 m, 0 m\"); it cannot be used with point masses (--mass)"
        );
    }
    Ok(())
}

pub fn com(args: &ComArgs) -> Result<Outcome> {
    if let Some(file) = &args.file {
        if FileFormat::names_an_image(file) {
            return super::com_image::com_image(args);
        }
        return body_file(args, file);
    }
    reject_body_flags(args)?;
    if args.mass.is_empty() {
        bail!(
            "give the bodies as --mass M --at POSITION pairs, e.g. --mass \"2 kg\" --at \"0 m\" --mass \"1 kg\" --at \"3 m\""
        );
    }
    // "5.97e24 kg@0, 0": the position inline, or one --at per --mass
    let inline = args.mass.iter().filter(|m| m.contains('@')).count();
    let (mass_texts, at_texts): (Vec<&str>, Vec<&str>) = if inline == 0 {
        if args.at.len() != args.mass.len() {
            bail!(
                "--mass is given {} but --at {}: give one --at after each --mass, or write --mass \"2 kg@1 m, 0\"",
                times(args.mass.len()),
                times(args.at.len())
            );
        }
        (
            args.mass.iter().map(String::as_str).collect(),
            args.at.iter().map(String::as_str).collect(),
        )
    } else if inline == args.mass.len() && args.at.is_empty() {
        args.mass
            .iter()
            .filter_map(|m| m.split_once('@'))
            .map(|(m, at)| (m.trim(), at.trim()))
            .unzip()
    } else {
        bail!(
            "give every position inline (--mass \"2 kg@1 m, 0\") or every one with --at, not a mix"
        );
    };
    if !args.velocity.is_empty() && args.velocity.len() != args.mass.len() {
        bail!(
            "--mass is given {} but --velocity {}: give a --velocity for every body, or none",
            times(args.mass.len()),
            times(args.velocity.len())
        );
    }
    let masses = mass_texts
        .iter()
        .map(|m| quantity(m, "--mass", Dimension::MASS))
        .collect::<Result<Vec<_>>>()?;
    let positions: Vec<Vec<f64>> = at_texts
        .iter()
        .map(|p| vector(p, "--at", Dimension::LENGTH))
        .collect::<Result<_>>()?;
    let velocities: Option<Vec<Vec<f64>>> = if args.velocity.is_empty() {
        None
    } else {
        Some(
            args.velocity
                .iter()
                .map(|p| vector(p, "--velocity", Dimension::VELOCITY))
                .collect::<Result<_>>()?,
        )
    };
    let (scale, unit) = output_unit(
        args.unit.as_deref(),
        Dimension::LENGTH,
        ("m", "a positive length", "\"6371 km\" or \"pm\""),
        true,
    )?;
    let points = PointMasses::from_bodies(&masses, &positions, velocities.as_deref()).map_err(
        |e| match e.input() {
            Some(PointMassInput::Position) => anyhow!("--at: {e}"),
            Some(PointMassInput::Velocity) => anyhow!("--velocity: {e}"),
            _ => anyhow!("--mass: {e}"),
        },
    )?;
    let s = points.report(&unit, scale);
    report(args.report, &s, || {
        let mut out = format!("total mass {} kg\n", show(s.total_mass));
        let _ = writeln!(
            out,
            "centre of mass at {} {}",
            fmt(&s.centre_of_mass_in_unit),
            if args.unit.is_some() {
                format!("(in units of {unit})")
            } else {
                "m".into()
            }
        );
        if let (Some(v), Some(p)) = (&s.cm_velocity, &s.momentum) {
            let _ = writeln!(
                out,
                "centre-of-mass velocity {} m/s, momentum P = M V = {} kg·m/s",
                fmt(v),
                fmt(p)
            );
            let _ = writeln!(
                out,
                "kinetic energy {} J = {} J (centre of mass, ½MV²) + {} J (relative to it)",
                show(s.kinetic.unwrap_or(0.0)),
                show(s.kinetic_cm.unwrap_or(0.0)),
                show(s.kinetic_internal.unwrap_or(0.0))
            );
        }
        out
    })?;
    Ok(Outcome::Success)
}

/// How often a flag is given, for messages: `once`, `twice`, `3 times`, `not at all`.
fn times(n: usize) -> String {
    match n {
        0 => "not at all".into(),
        1 => "once".into(),
        2 => "twice".into(),
        n => format!("{n} times"),
    }
}
