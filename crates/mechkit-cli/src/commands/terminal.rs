//! `mechkit terminal`: the drag that balances the weight at a measured terminal speed, through
//! `mechkit::forces::terminal`.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::data::{ColumnRef, Table};
use mechkit::forces::terminal::{DragLaw, SteadyFit, TerminalDrag, steady_fit};
use mechkit::units::Dimension;
use serde_json::{Value, json};

use super::input::{quantity, show};
use super::{Outcome, print};
use crate::args::TerminalArgs;

pub fn terminal(args: &TerminalArgs) -> Result<Outcome> {
    let law = DragLaw::parse(&args.law).ok_or_else(|| {
        anyhow!(
            "--law `{}`: expected quadratic (F = D v²) or linear (F = b v)",
            args.law
        )
    })?;
    let g = positive(&args.g, "--g", Dimension::ACCELERATION)?;
    let (drag, fit) = if let Some(v) = &args.velocity {
        let v = quantity(v, "--velocity", Dimension::VELOCITY)?;
        (TerminalDrag::new(v, law), None)
    } else if let (Some(d), Some(t)) = (&args.distance, &args.time) {
        let d = quantity(d, "--distance", Dimension::LENGTH)?;
        let t = quantity(t, "--time", Dimension::TIME)?;
        (TerminalDrag::from_fall(d, t, law), None)
    } else if args.data.is_some() {
        let fit = fit_data(args)?;
        (TerminalDrag::new(fit.velocity, law), Some(fit))
    } else {
        bail!(
            "give the terminal speed: --velocity, --distance with --time, or --data with a position column"
        );
    };
    let drag = drag.map_err(|e| anyhow!("{e}"))?;
    let mass = args
        .mass
        .as_deref()
        .map(|m| positive(m, "--mass", Dimension::MASS))
        .transpose()?;
    let area = match (&args.area, &args.radius) {
        (Some(a), _) => Some(positive(
            a,
            "--area",
            Dimension::LENGTH * Dimension::LENGTH,
        )?),
        (None, Some(r)) => {
            let r = positive(r, "--radius", Dimension::LENGTH)?;
            Some(std::f64::consts::PI * r * r)
        }
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
    if density.is_some() && area.is_none() {
        bail!(
            "--density needs the body's frontal --area (or --radius for a round body) to give C_d"
        );
    }
    let coefficient = mass
        .map(|m| drag.coefficient(m, g))
        .transpose()
        .map_err(|e| anyhow!("{e}"))?;
    let cd = match (mass, density, area) {
        (Some(m), Some(rho), Some(a)) => drag
            .drag_coefficient(m, g, rho, a)
            .map_err(|e| anyhow!("{e}"))?,
        _ => None,
    };
    let (name, per_weight_unit, per_mass_unit, coeff_unit) = match law {
        DragLaw::Quadratic => ("D", "s^2/m^2", "1/m", "kg/m"),
        DragLaw::Linear => ("b", "s/m", "1/s", "kg/s"),
    };
    let mut body = json!({
        "law": law.name(),
        "terminal_speed": drag.terminal_speed,
        "per_weight": drag.per_weight,
        "per_weight_unit": per_weight_unit,
        "per_mass": drag.per_weight * g,
        "per_mass_unit": per_mass_unit,
        "g": g,
    });
    let mut text = format!(
        "terminal speed {} m/s ({} drag)\n  {name}/(m g) = {} {per_weight_unit}\n  {name}/m = {} {per_mass_unit} (the course's a = -g - {name}/m {})\n",
        show(drag.terminal_speed),
        law.name(),
        show(drag.per_weight),
        show(drag.per_weight * g),
        match law {
            DragLaw::Quadratic => "v|v|",
            DragLaw::Linear => "v",
        }
    );
    if let Some(c) = coefficient {
        body["coefficient"] = json!(c);
        body["coefficient_unit"] = json!(coeff_unit);
        let _ = writeln!(text, "  {name} = {} {coeff_unit}", show(c));
    }
    if let Some(cd) = cd {
        body["drag_coefficient"] = json!(cd);
        let _ = writeln!(text, "  C_d = 2{name}/(rho A) = {}", show(cd));
    }
    if let Some(fit) = fit {
        body["fit"] = fit_json(&fit);
        let _ = writeln!(
            text,
            "  from a line through {} samples: rms residual {} m; slopes of the two halves {} and {} m/s",
            fit.samples,
            show(fit.rms_residual),
            show(fit.half_slopes.0),
            show(fit.half_slopes.1)
        );
        if let Some(w) = unsteady(&fit) {
            eprintln!("warning: {w}");
            body["warning"] = json!(w);
        }
    }
    if args.json {
        print(&format!("{body:#}\n"))?;
    } else {
        print(&text)?;
    }
    Ok(Outcome::Success)
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
    let from = match &args.from {
        Some(text) => {
            let t0 = quantity(text, "--from", Dimension::TIME)?;
            t.iter().position(|&ti| ti >= t0).ok_or_else(|| {
                anyhow!(
                    "--from {text}: no sample at or after it (the data end at t = {} s)",
                    show(t[t.len() - 1])
                )
            })?
        }
        None => t.len() / 2,
    };
    steady_fit(t, y, from).map_err(|e| anyhow!("{}: {e}", table.source()))
}

fn fit_json(fit: &SteadyFit) -> Value {
    json!({
        "velocity": fit.velocity, "intercept": fit.intercept, "rms_residual": fit.rms_residual,
        "half_slopes": [fit.half_slopes.0, fit.half_slopes.1], "samples": fit.samples,
    })
}

/// A warning when the two halves of the fitted part fall at different speeds.
fn unsteady(fit: &SteadyFit) -> Option<String> {
    let (a, b) = fit.half_slopes;
    let spread = (a - b).abs() / a.abs().max(b.abs());
    (spread > 0.05).then(|| {
        format!(
            "the speed is not steady in the fitted part: its halves fall at {} and {} m/s ({:.0}% apart); fit a later part with --from",
            show(a),
            show(b),
            100.0 * spread
        )
    })
}
