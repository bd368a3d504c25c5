//! `mechkit com`: the centre of mass of point masses (with velocities: momentum, the
//! centre-of-mass frame and the kinetic-energy split).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::{Dimension, Quantity};
use mechkit::mass::PointMasses;
use serde_json::json;

use super::input::{quantity, show, split_top_level};
use super::{Outcome, print};
use crate::args::ComArgs;

fn vector(text: &str, flag: &str, dim: Dimension) -> Result<Vec<f64>> {
    split_top_level(text, ',')
        .into_iter()
        .map(|c| quantity(c, flag, dim))
        .collect()
}

fn fmt(v: &[f64], scale: f64) -> String {
    let parts: Vec<String> = v.iter().map(|x| show(x / scale + 0.0)).collect();
    if parts.len() == 1 {
        parts[0].clone()
    } else {
        format!("({})", parts.join(", "))
    }
}

/// Whether a path names an image (by its extension; only PNG and JPEG are read, the others
/// get an error that names their format).
fn is_image(path: &std::path::Path) -> bool {
    path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
        matches!(
            e.to_ascii_lowercase().as_str(),
            "png" | "jpg" | "jpeg" | "gif" | "bmp" | "tif" | "tiff" | "webp" | "heic" | "avif"
        )
    })
}

pub fn com(args: &ComArgs) -> Result<Outcome> {
    if let Some(file) = &args.file {
        if is_image(file) {
            return super::com_image::com_image(args);
        }
        bail!("{}: body files are not read yet", file.display());
    }
    if args.mass.is_empty() {
        bail!(
            "give the bodies as --mass M --at POSITION pairs, e.g. --mass \"2 kg\" --at \"0 m\" --mass \"1 kg\" --at \"3 m\""
        );
    }
    if args.at.len() != args.mass.len() {
        bail!(
            "{} masses but {} positions: give one --at after each --mass",
            args.mass.len(),
            args.at.len()
        );
    }
    if !args.velocity.is_empty() && args.velocity.len() != args.mass.len() {
        bail!(
            "{} masses but {} velocities: give a --velocity for every body, or none",
            args.mass.len(),
            args.velocity.len()
        );
    }
    let masses = args
        .mass
        .iter()
        .map(|m| quantity(m, "--mass", Dimension::MASS))
        .collect::<Result<Vec<_>>>()?;
    let positions: Vec<Vec<f64>> = args
        .at
        .iter()
        .map(|p| vector(p, "--at", Dimension::LENGTH))
        .collect::<Result<_>>()?;
    let dim = positions[0].len();
    if !(1..=3).contains(&dim) || positions.iter().any(|p| p.len() != dim) {
        bail!("every --at needs the same number of coordinates, 1 to 3 (e.g. \"1 m, 2 m\")");
    }
    let velocities = if args.velocity.is_empty() {
        None
    } else {
        let v: Vec<Vec<f64>> = args
            .velocity
            .iter()
            .map(|p| vector(p, "--velocity", Dimension::VELOCITY))
            .collect::<Result<_>>()?;
        if v.iter().any(|x| x.len() != dim) {
            bail!("every --velocity needs {dim} components, like the positions");
        }
        Some(v.concat())
    };
    let (scale, unit) = match &args.unit {
        Some(u) => {
            // a unit alone ("pm") is one of it
            let q = Quantity::parse(u)
                .or_else(|_| Quantity::parse(&format!("1 {u}")))
                .map_err(|e| anyhow!("--in: {e}"))?;
            if !(q.dim == Dimension::LENGTH || q.dim.is_none())
                || q.value.is_nan()
                || q.value <= 0.0
            {
                bail!("--in `{u}` must be a positive length, e.g. \"6371 km\" or \"pm\"");
            }
            (q.value, u.clone())
        }
        None => (1.0, "m".to_string()),
    };
    let points = PointMasses::new(dim, masses, positions.concat(), velocities)
        .map_err(|e| anyhow!("--mass: {e}"))?;
    let s = points.summary();
    if args.json {
        let j = json!({
            "total_mass": s.total_mass,
            "centre_of_mass": s.centre_of_mass,
            "centre_of_mass_in_unit": s.centre_of_mass.iter().map(|x| x / scale).collect::<Vec<_>>(),
            "unit": unit,
            "cm_velocity": s.cm_velocity,
            "momentum": s.momentum,
            "cm_frame_velocities": s.cm_frame_velocities,
            "kinetic": s.kinetic,
            "kinetic_cm": s.kinetic_cm,
            "kinetic_internal": s.kinetic_internal,
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!("total mass {} kg\n", show(s.total_mass));
        let _ = writeln!(
            out,
            "centre of mass at {} {}",
            fmt(&s.centre_of_mass, scale),
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
                fmt(v, 1.0),
                fmt(p, 1.0)
            );
            let _ = writeln!(
                out,
                "kinetic energy {} J = {} J (centre of mass, ½MV²) + {} J (relative to it)",
                show(s.kinetic.unwrap_or(0.0)),
                show(s.kinetic_cm.unwrap_or(0.0)),
                show(s.kinetic_internal.unwrap_or(0.0))
            );
        }
        print(&out)?;
    }
    Ok(Outcome::Success)
}
