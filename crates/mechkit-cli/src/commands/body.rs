//! Body files on the command line: loading (with an optional total mass) into the library's
//! `BodySummary`, points typed as "x, y, z" with units, and the parts and vectors as text.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::mass::{BodySummary, MassError, MassInput, PartSummary, Vec3};
use mechkit::scenario::BodyFile;

use super::input::{quantity, show, split_top_level};

/// A body file's whole and its parts (body frame), rescaled to `--total-mass`.
pub fn load(path: &Path, total_mass: Option<&str>) -> Result<BodySummary> {
    let file = BodyFile::load(path)?;
    let total_mass = match total_mass {
        Some(m) => Some(quantity(m, "--total-mass", Dimension::MASS)?),
        None => None,
    };
    file.body
        .summary(&file.title, total_mass)
        .map_err(|e| mass_error(&e, path))
}

/// A library error with the flag of the input it is about, else the file's name.
pub fn mass_error(e: &MassError, path: &Path) -> anyhow::Error {
    match e.input() {
        Some(MassInput::TotalMass) => anyhow!("--total-mass: {e}"),
        Some(MassInput::Axis) => anyhow!("--axis: {e}"),
        _ => anyhow!("{}: {e}", path.display()),
    }
}

/// "x, y[, z]" with units of `dim`, padded with zeros.
pub fn point(text: &str, flag: &str, dim: Dimension) -> Result<Vec3> {
    let items = split_top_level(text, ',');
    if !(1..=3).contains(&items.len()) {
        bail!("{flag} `{text}` needs 1 to 3 components, e.g. \"0.5 m, 0, 0\"");
    }
    let mut p = Vec3::zeros();
    for (k, c) in items.iter().enumerate() {
        p[k] = if dim.is_none() {
            c.parse::<f64>()
                .map_err(|_| anyhow!("{flag}: `{c}` is not a number"))?
        } else {
            quantity(c, flag, dim)?
        };
        if !p[k].is_finite() {
            bail!("{flag}: `{c}` is not a finite number");
        }
    }
    Ok(p)
}

/// A vector for the text report: `(x, y, z)`.
pub fn vec_text(v: &[f64; 3]) -> String {
    format!(
        "({}, {}, {})",
        show(v[0] + 0.0),
        show(v[1] + 0.0),
        show(v[2] + 0.0)
    )
}

/// The parts for the text report (nothing for a body of one part).
pub fn parts_text(parts: &[PartSummary]) -> String {
    let mut out = String::new();
    if parts.len() > 1 {
        out.push_str("parts:\n");
        for p in parts {
            let _ = writeln!(
                out,
                "  {} ({}{}): mass {} kg, centre of mass {} m",
                p.name,
                p.shape,
                if p.hole { ", hole" } else { "" },
                show(p.mass),
                vec_text(&p.centre_of_mass)
            );
        }
    }
    out
}
