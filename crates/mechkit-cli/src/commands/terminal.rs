//! `mechkit terminal`: the drag that balances the weight at a measured terminal speed, through
//! `mechkit::forces::terminal` (`TerminalDrag::report`).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::data::{ColumnRef, Table};
use mechkit::forces::terminal::{
    Area, DragLaw, SteadyFit, TerminalDrag, TerminalError, TerminalReport, steady_fit_from,
};
use mechkit::units::Dimension;

use super::input::{quantity, show};
use super::{Outcome, report};
use crate::args::TerminalArgs;

pub fn terminal(args: &TerminalArgs) -> Result<Outcome> {
    let law = DragLaw::parse(&args.law).ok_or_else(|| {
        anyhow!(
            "--law `{}`: expected quadratic (F = D v²) or linear (F = b v)",
            args.law
        )
    })?;
    let g = positive(&args.g, "--g", Dimension::ACCELERATION)?;
    let (drag, fit, source) = if let Some(v) = &args.velocity {
        let v = quantity(v, "--velocity", Dimension::VELOCITY)?;
        (TerminalDrag::new(v, law), None, "--velocity")
    } else if let (Some(d), Some(t)) = (&args.distance, &args.time) {
        let d = quantity(d, "--distance", Dimension::LENGTH)?;
        let t = quantity(t, "--time", Dimension::TIME)?;
        (
            TerminalDrag::from_fall(d, t, law),
            None,
            "--distance/--time",
        )
    } else if args.data.is_some() {
        let fit = fit_data(args)?;
        (TerminalDrag::new(fit.velocity, law), Some(fit), "--data")
    } else {
        bail!(
            "give the terminal speed: --velocity, --distance with --time, or --data with a position column"
        );
    };
    let drag = drag.map_err(|e| anyhow!("{source}: {e}"))?;
    let mass = args
        .mass
        .as_deref()
        .map(|m| positive(m, "--mass", Dimension::MASS))
        .transpose()?;
    let area = match (&args.area, &args.radius) {
        (Some(a), _) => Some(Area::Given(positive(
            a,
            "--area",
            Dimension::LENGTH * Dimension::LENGTH,
        )?)),
        (None, Some(r)) => Some(Area::Radius(positive(r, "--radius", Dimension::LENGTH)?)),
        (None, None) => None,
    };
    let density = args
        .density
        .as_deref()
        .map(|d| {
            positive(
                d,
                "--density",
                Dimension::MASS / (Dimension::LENGTH * Dimension::LENGTH * Dimension::LENGTH),
            )
        })
        .transpose()?;
    let fluid = match (density, area) {
        (Some(rho), Some(a)) => Some((rho, a)),
        (Some(_), None) => bail!(
            "--density needs the body's frontal --area (or --radius for a round body) to give C_d"
        ),
        _ => None,
    };
    let result = drag
        .report(g, mass, fluid, fit)
        .map_err(|e| anyhow!("{e}"))?;
    if let Some(w) = &result.warning {
        eprintln!("warning: {w}");
    }
    report(args.report, &result, || text(&result))?;
    Ok(Outcome::Success)
}

fn text(r: &TerminalReport) -> String {
    let name = r.drag_law.symbol();
    let mut text = format!(
        "terminal speed {} m/s ({} drag)\n  {name}/(m g) = {} {}\n  {name}/m = {} {} (the course's a = -g - {name}/m {})\n",
        show(r.terminal_speed),
        r.law,
        show(r.per_weight),
        r.per_weight_unit,
        show(r.per_mass),
        r.per_mass_unit,
        match r.drag_law {
            DragLaw::Quadratic => "v|v|",
            DragLaw::Linear => "v",
        }
    );
    if let (Some(c), Some(unit)) = (r.coefficient, r.coefficient_unit) {
        let _ = writeln!(text, "  {name} = {} {unit}", show(c));
    }
    if let Some(cd) = r.drag_coefficient {
        let _ = writeln!(text, "  C_d = 2{name}/(rho A) = {}", show(cd));
    }
    if let Some(fit) = &r.fit {
        let _ = writeln!(
            text,
            "  from a line through {} samples: rms residual {} m; slopes of the two halves {} and {} m/s",
            fit.samples,
            show(fit.rms_residual),
            show(fit.half_slopes.0),
            show(fit.half_slopes.1)
        );
    }
    text
}

fn positive(text: &str, flag: &str, dim: Dimension) -> Result<f64> {
    let x = quantity(text, flag, dim)?;
    if !(x > 0.0 && x.is_finite()) {
        bail!("{flag} must be positive, not `{text}`");
    }
    Ok(x)
}

fn fit_data(args: &TerminalArgs) -> Result<SteadyFit> {
    let path = args.data.as_ref().expect("checked by the caller");
    let table = Table::read(path).map_err(|e| anyhow!("{e}"))?;
    let column = |text: Option<&str>, default: &str, flag: &str| {
        ColumnRef::parse(text.unwrap_or(default)).map_err(|e| anyhow!("{flag}: {e}"))
    };
    let t_ref = column(args.t.as_deref(), "1", "--t")?;
    let y_ref = column(args.y.as_deref(), "2", "--y")?;
    let (t, _) = table
        .abscissa(&t_ref, "the fit")
        .map_err(|e| anyhow!("--t: {e}"))?;
    let y = table.column(&y_ref).map_err(|e| anyhow!("--y: {e}"))?;
    let from = args
        .from
        .as_deref()
        .map(|text| quantity(text, "--from", Dimension::TIME))
        .transpose()?;
    steady_fit_from(t, y, from).map_err(|e| match e {
        TerminalError::NothingAfter { .. } => anyhow!("--from: {e}"),
        e => anyhow!("{}: {e}", table.source()),
    })
}
