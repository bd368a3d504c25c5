//! Body files on the command line: loading (with an optional total mass), points typed as
//! "x, y, z" with units, and the parts as JSON and text.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::mass::{MassProperties, Vec3};
use mechkit::scenario::BodyFile;
use serde_json::{Value, json};

use super::input::{quantity, show, split_top_level};

/// A loaded body: the whole and its parts (body frame), rescaled to `--total-mass`.
pub struct Loaded {
    pub title: String,
    pub whole: MassProperties,
    /// (name, shape, hole, properties)
    pub parts: Vec<(String, &'static str, bool, MassProperties)>,
}

pub fn load(path: &Path, total_mass: Option<&str>) -> Result<Loaded> {
    let file = BodyFile::load(path)?;
    let mut parts: Vec<MassProperties> = file
        .body
        .part_properties()
        .map_err(|e| anyhow!("{}: {e}", path.display()))?;
    let mut whole = MassProperties::sum(&parts).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    if let Some(m) = total_mass {
        let m = quantity(m, "--total-mass", Dimension::MASS)?;
        if !(m.is_finite() && m > 0.0) {
            bail!("--total-mass must be a positive mass, e.g. \"2 kg\"");
        }
        let factor = m / whole.mass;
        whole = whole.scaled(factor);
        parts = parts.iter().map(|p| p.scaled(factor)).collect();
    }
    let parts = file
        .body
        .parts()
        .iter()
        .zip(parts)
        .map(|(p, props)| (p.name.clone(), p.shape.name(), p.hole, props))
        .collect();
    Ok(Loaded {
        title: file.title,
        whole,
        parts,
    })
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

pub fn vec_json(v: &Vec3) -> Value {
    json!([v.x + 0.0, v.y + 0.0, v.z + 0.0])
}

pub fn vec_text(v: &Vec3) -> String {
    format!(
        "({}, {}, {})",
        show(v.x + 0.0),
        show(v.y + 0.0),
        show(v.z + 0.0)
    )
}

pub fn parts_json(loaded: &Loaded) -> Value {
    loaded
        .parts
        .iter()
        .map(|(name, shape, hole, p)| {
            json!({
                "name": name,
                "shape": shape,
                "hole": hole,
                "mass": p.mass,
                "centre_of_mass": vec_json(&p.centre_of_mass),
            })
        })
        .collect()
}

pub fn parts_text(loaded: &Loaded) -> String {
    let mut out = String::new();
    if loaded.parts.len() > 1 {
        out.push_str("parts:\n");
        for (name, shape, hole, p) in &loaded.parts {
            let _ = writeln!(
                out,
                "  {name} ({shape}{}): mass {} kg, centre of mass {} m",
                if *hole { ", hole" } else { "" },
                show(p.mass),
                vec_text(&p.centre_of_mass)
            );
        }
    }
    out
}
