//! `mechkit inertia BODYFILE`: mass, centre of mass, the inertia tensor about the centre of
//! mass and about a point, principal moments and axes, and the moment about an axis
//! (`mechkit::mass::BodySummary::inertia`).

use std::fmt::Write as _;

use anyhow::Result;
use mechkit::expr::units::Dimension;
use mechkit::mass::{InertiaReport, Vec3};

use super::body::{load, mass_error, parts_text, point, vec_text};
use super::input::{output_unit, show};
use super::{Outcome, report};
use crate::args::InertiaArgs;

fn tensor_text(m: &[[f64; 3]; 3], indent: &str) -> String {
    let cells: Vec<Vec<String>> = m
        .iter()
        .map(|row| row.iter().map(|x| show(x + 0.0)).collect())
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
    let axis = match &args.axis {
        Some(a) => Some(point(a, "--axis", Dimension::NONE)?),
        None => None,
    };
    let result = body
        .inertia(&unit, scale, about, axis)
        .map_err(|e| mass_error(&e, &args.file))?;
    report(args.report, &result, || text(&result))?;
    Ok(Outcome::Success)
}

fn text(r: &InertiaReport) -> String {
    let unit = &r.unit;
    let mut out = format!("{}\n", mechkit::expr::span::printable(&r.title));
    let _ = writeln!(out, "mass {} kg", show(r.mass));
    let _ = writeln!(out, "centre of mass {} m", vec_text(&r.centre_of_mass));
    let _ = writeln!(out, "inertia tensor about the centre of mass ({unit}):");
    out.push_str(&tensor_text(&r.inertia_cm, "  "));
    if r.about != r.centre_of_mass {
        let _ = writeln!(
            out,
            "inertia tensor about {} m ({unit}, parallel-axis theorem):",
            vec_text(&r.about)
        );
        out.push_str(&tensor_text(&r.inertia_about, "  "));
    }
    let _ = writeln!(
        out,
        "principal moments about the centre of mass ({unit}) and axes:"
    );
    for (k, (moment, axis)) in r
        .principal_moments
        .iter()
        .zip(&r.principal_axes)
        .enumerate()
    {
        let _ = writeln!(
            out,
            "  I{} = {:<14} along {}",
            k + 1,
            show(moment + 0.0),
            vec_text(axis)
        );
    }
    if let Some(a) = &r.axis {
        let _ = writeln!(
            out,
            "about the axis along {} through {} m: I = {} {unit}, radius of gyration {} m",
            vec_text(&a.direction),
            vec_text(&a.through),
            show(a.moment),
            show(a.radius_of_gyration)
        );
    }
    out.push_str(&parts_text(&r.parts));
    out
}
