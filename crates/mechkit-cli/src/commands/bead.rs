//! `mechkit bead`: a body on a circle or a curve y(x) under gravity, through
//! `BeadOnCurve::report`: the normal force, the departure where it reaches zero, the flight to
//! the landing, an equilibrium at the start and where a push would take it off; path.csv and
//! the plot with `-o`.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::rigid::Input;
use mechkit::rigid::constrained::{
    BeadFiles, BeadOnCurve, BeadReport, ConstrainedError, Curve, Equilibrium, Side, Start,
};

use super::input::{params, quantity, show};
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::BeadArgs;

fn side(text: &str, circle: bool) -> Result<Side> {
    Ok(match text.trim().to_ascii_lowercase().as_str() {
        "outside" | "above" | "outer" | "on-top" => Side::Outer,
        "inside" | "below" | "inner" => Side::Inner,
        "bead" | "threaded" | "wire" => Side::Bead,
        other => {
            let names = if circle {
                "outside, inside"
            } else {
                "above, below"
            };
            bail!("--side `{other}` is not a side: use {names}, or bead (threaded on the curve)")
        }
    })
}

/// The flag of an input of `mechkit bead`.
fn flag(input: Option<Input>) -> &'static str {
    match input {
        Some(Input::Radius) => "--circle",
        Some(Input::Mass) => "--mass",
        Some(Input::Gravity) => "--g",
        Some(Input::Duration) => "--t-max",
        Some(Input::Curve) => "--curve",
        Some(Input::Tolerance) => "--rtol",
        Some(Input::DropHeight) => "--drop-height",
        _ => "--start",
    }
}

fn with_flag(e: &ConstrainedError) -> anyhow::Error {
    anyhow!("{}: {e}", flag(e.input()))
}

pub fn bead(args: &BeadArgs) -> Result<Outcome> {
    let (curve, is_circle) = match (&args.circle, &args.curve) {
        (Some(r), _) => (
            Curve::circle(quantity(r, "--circle", Dimension::LENGTH)?)
                .map_err(|e| with_flag(&e))?,
            true,
        ),
        (None, Some(c)) => (
            Curve::graph(c, &params(args.set.as_deref())?).map_err(|e| with_flag(&e))?,
            false,
        ),
        (None, None) => bail!("give the curve: --circle \"1 m\" or --curve \"x^2/2\""),
    };
    let side = side(&args.side, is_circle)?;
    let mass = quantity(&args.mass, "--mass", Dimension::MASS)?;
    let g = quantity(&args.g, "--g", Dimension::ACCELERATION)?;
    let model = BeadOnCurve::new(curve, side, mass, g).map_err(|e| with_flag(&e))?;
    let coordinate = if is_circle {
        quantity(&args.start, "--start", Dimension::NONE)?
    } else {
        quantity(&args.start, "--start", Dimension::LENGTH)?
    };
    let start = match &args.drop_height {
        Some(h) => Start::dropped(
            coordinate,
            quantity(h, "--drop-height", Dimension::LENGTH)?,
            g,
        )
        .map_err(|e| with_flag(&e))?,
        None => Start {
            coordinate,
            speed: quantity(&args.speed, "--speed", Dimension::VELOCITY)?,
        },
    };
    let t_max = quantity(&args.t_max, "--t-max", Dimension::TIME)?;
    let mut result = match model.report(start, t_max, args.rtol) {
        Ok(r) => r,
        Err(ConstrainedError::Integrate(e)) if !e.is_step_budget() => {
            eprintln!("error: the integration failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e @ ConstrainedError::Undefined { x, .. }) if x != coordinate => {
            // the start was fine: the motion reached a point the graph cannot carry
            eprintln!("error: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => return Err(with_flag(&e)),
    };
    let mut wrote = None;
    if let Some(dir) = &args.out {
        create_dir(dir)?;
        let csv = write_table(dir, BeadReport::NAME, &result.table())?;
        let plot = if args.no_plots {
            None
        } else {
            let title = format!("{}: {}", result.side, result.curve);
            write_plots(dir, &[result.plot()], &title, args.plots)?.pop()
        };
        wrote = Some(super::roll::written(&csv, plot.as_slice()));
        result.files = Some(BeadFiles {
            csv: Some(csv),
            plot,
        });
    }
    report(args.report, &result, || text(&result))?;
    if let Some(w) = &wrote {
        note(args.report, w);
    }
    Ok(Outcome::Success)
}

/// Where the body would leave, in words.
fn leaving_text(r: &BeadReport, eq: &Equilibrium) -> String {
    match eq.leaves_at {
        Some(at) => match (at.angle_from_top_deg, at.cos_angle) {
            (Some(deg), Some(cos)) => format!(
                "leaving the curve at φ = {}° from the top (cos φ = {})",
                show(deg),
                show(cos)
            ),
            _ => format!(
                "leaving the curve at x = {} m ({}, {}) m",
                show(at.coordinate),
                show(at.position[0]),
                show(at.position[1])
            ),
        },
        None if r.model.side == Side::Bead => {
            "sliding down; threaded, it never leaves the curve".to_string()
        }
        None => "sliding down; it never leaves the curve".to_string(),
    }
}

/// "stays on the curve", with what its start means when it is an equilibrium.
fn stays_text(r: &BeadReport) -> String {
    let Some(eq) = &r.equilibrium else {
        return "stays on the curve\n".to_string();
    };
    match (eq.stability, eq.at_rest, eq.stayed) {
        ("unstable", true, _) => format!(
            "stays on the curve: it sits at rest at an unstable equilibrium (a top, where the curve is level), where nothing pushes it; any disturbance (a small --speed) makes it slide off, {}\n",
            leaving_text(r, eq)
        ),
        ("unstable", false, true) => format!(
            "stays on the curve until --t-max: it starts at an unstable equilibrium (a top, where the curve is level) too slowly to get away in that time; followed longer it slides off, {}\n",
            leaving_text(r, eq)
        ),
        ("stable", true, _) => {
            "stays on the curve: at rest at a stable equilibrium (a bottom, where the curve is level)\n"
                .to_string()
        }
        _ => "stays on the curve\n".to_string(),
    }
}

fn text(r: &BeadReport) -> String {
    let circle = r.model.curve.radius().is_some();
    let mut out = format!(
        "{} on the {} of a {}, m = {} kg, g = {} m/s²\n",
        if r.model.side == Side::Bead {
            "bead threaded"
        } else {
            "body"
        },
        r.side,
        r.curve,
        show(r.mass),
        show(r.g)
    );
    if let Some((d1, d2)) = r.model.curve.derivatives() {
        let _ = writeln!(out, "  y' = {d1}, y'' = {d2}");
    }
    let _ = writeln!(
        out,
        "start at {} = {}, speed {} m/s; energy per kg ½v² + g y = {} J/kg",
        if circle { "φ (from the top)" } else { "x" },
        show(r.start.coordinate),
        show(r.start.speed),
        show(r.energy_per_mass)
    );
    match &r.departure {
        Some(d) => {
            let _ = writeln!(
                out,
                "leaves the curve at t = {} s at ({}, {}) m, speed {} m/s (N = {:.1e} N)",
                show(d.t),
                show(d.position[0]),
                show(d.position[1]),
                show(d.speed),
                d.normal_force
            );
            if let (Some(deg), Some(cos)) = (d.angle_from_top_deg, d.cos_angle) {
                let _ = writeln!(
                    out,
                    "  angle from the top {}°, cos φ = {}",
                    show(deg),
                    show(cos)
                );
            }
        }
        None => out.push_str(&stays_text(r)),
    }
    if let Some(l) = &r.landing {
        let _ = writeln!(
            out,
            "lands on the curve at t = {} s at ({}, {}) m: {} m/s along it, {} m/s into it",
            show(l.t),
            show(l.position[0]),
            show(l.position[1]),
            show(l.tangential_speed),
            show(l.normal_speed)
        );
    }
    if !r.turning_times.is_empty() {
        let list: Vec<String> = r.turning_times.iter().take(6).map(|t| show(*t)).collect();
        let _ = writeln!(out, "turning points at t = {} s", list.join(", "));
    }
    let _ = writeln!(
        out,
        "energy drift on the curve {:.1e} J/kg; {} steps (dopri5)",
        r.energy_drift_per_mass, r.steps
    );
    out
}
