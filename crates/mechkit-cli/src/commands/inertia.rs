//! `mechkit inertia BODYFILE`: mass, centre of mass, the inertia tensor about the centre of
//! mass and about a point, principal moments and axes, and the moment about an axis.

use std::fmt::Write as _;

use anyhow::{Result, anyhow};
use mechkit::expr::units::Dimension;
use mechkit::mass::{Mat3, Vec3};
use serde_json::{Value, json};

use super::body::{load, parts_json, parts_text, point, vec_json, vec_text};
use super::input::{output_unit, show};
use super::{Outcome, print};
use crate::args::InertiaArgs;

fn tensor_json(m: &Mat3, scale: f64) -> Value {
    (0..3)
        .map(|r| (0..3).map(|c| m[(r, c)] / scale + 0.0).collect::<Vec<_>>())
        .collect()
}

fn tensor_text(m: &Mat3, scale: f64, indent: &str) -> String {
    let cells: Vec<Vec<String>> = (0..3)
        .map(|r| (0..3).map(|c| show(m[(r, c)] / scale + 0.0)).collect())
        .collect();
    let width = cells.iter().flatten().map(String::len).max().unwrap_or(1);
    let mut out = String::new();
    for row in &cells {
        let row: Vec<String> = row.iter().map(|c| format!("{c:>width$}")).collect();
        let _ = writeln!(out, "{indent}[ {} ]", row.join("  "));
    }
    out
}

pub fn inertia(args: &InertiaArgs) -> Result<Outcome> {
    let body = load(&args.file, args.total_mass.as_deref())?;
    let (scale, unit) = output_unit(
        args.unit.as_deref(),
        Dimension::MOMENT_OF_INERTIA,
        (
            "kg*m^2",
            "a unit of moment of inertia (mass × length²)",
            "\"g*cm^2\" or \"u*pm^2\"",
        ),
        false,
    )?;
    let about = match &args.about {
        Some(p) => point(p, "--about", Dimension::LENGTH)?,
        None => Vec3::zeros(),
    };
    let p = &body.whole;
    let i_about = p.inertia_about(&about);
    let principal = p.principal();
    let axis = match &args.axis {
        Some(a) => {
            let d = point(a, "--axis", Dimension::NONE)?;
            let moment = p
                .moment_about_axis(&about, &d)
                .map_err(|e| anyhow!("--axis: {e}"))?;
            Some((d.normalize(), moment))
        }
        None => None,
    };
    if args.json {
        let axes: Vec<Value> = (0..3)
            .map(|k| vec_json(&principal.axes.column(k).into_owned()))
            .collect();
        let j = json!({
            "title": body.title,
            "mass": p.mass,
            "centre_of_mass": vec_json(&p.centre_of_mass),
            "unit": unit,
            "inertia_cm": tensor_json(&p.inertia, scale),
            "about": vec_json(&about),
            "inertia_about": tensor_json(&i_about, scale),
            "principal_moments": principal.moments.map(|m| m / scale + 0.0),
            "principal_axes": axes,
            "axis": axis.map(|(d, m)| json!({
                "direction": vec_json(&d),
                "through": vec_json(&about),
                "moment": m / scale,
                "radius_of_gyration": (m / p.mass).sqrt(),
            })),
            "parts": parts_json(&body),
        });
        print(&format!("{j:#}\n"))?;
        return Ok(Outcome::Success);
    }
    let mut out = format!("{}\n", body.title);
    let _ = writeln!(out, "mass {} kg", show(p.mass));
    let _ = writeln!(out, "centre of mass {} m", vec_text(&p.centre_of_mass));
    let _ = writeln!(out, "inertia tensor about the centre of mass ({unit}):");
    out.push_str(&tensor_text(&p.inertia, scale, "  "));
    if about != p.centre_of_mass {
        let _ = writeln!(
            out,
            "inertia tensor about {} m ({unit}, parallel-axis theorem):",
            vec_text(&about)
        );
        out.push_str(&tensor_text(&i_about, scale, "  "));
    }
    let _ = writeln!(
        out,
        "principal moments about the centre of mass ({unit}) and axes:"
    );
    for k in 0..3 {
        let _ = writeln!(
            out,
            "  I{} = {:<14} along {}",
            k + 1,
            show(principal.moments[k] / scale + 0.0),
            vec_text(&principal.axes.column(k).into_owned())
        );
    }
    if let Some((d, m)) = axis {
        let _ = writeln!(
            out,
            "about the axis along {} through {} m: I = {} {unit}, radius of gyration {} m",
            vec_text(&d),
            vec_text(&about),
            show(m / scale),
            show((m / p.mass).sqrt())
        );
    }
    out.push_str(&parts_text(&body));
    print(&out)?;
    Ok(Outcome::Success)
}
