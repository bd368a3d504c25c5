//! `mechkit rocket`: a rocket of variable mass, through `Rocket::report`. Δv by the rocket
//! equation, the burn time, burnout speed and height (and the apex of the coast) in closed
//! form and simulated side by side; with `-o`, rocket.csv and the plots v_t, x_t and m_t.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::{Dimension, Quantity};
use mechkit::rocket::{Input, Rocket, RocketError, RocketReport};

use super::input::{quantity, show};
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::RocketArgs;

/// A mass rate in kg/s (a plain number is taken in kg/s).
fn mass_rate(text: &str) -> Result<f64> {
    let q = Quantity::parse(text).map_err(|e| anyhow!("--mass-rate: {e}"))?;
    if !q.dim.is_none() && q.dim != Dimension::MASS / Dimension::TIME {
        bail!(
            "--mass-rate `{text}` has the dimension {}, but a mass rate (kg/s, mass per time) is needed (a plain number is taken in kg/s)",
            q.dim.describe()
        );
    }
    Ok(q.value)
}

/// The flag of an input of `mechkit rocket`.
fn flag(input: Option<Input>) -> &'static str {
    match input {
        Some(Input::IgnitionMass) => "--m0",
        Some(Input::BurnoutMass) => "--m1",
        Some(Input::MassRate) => "--mass-rate",
        Some(Input::ExhaustSpeed) => "--exhaust-speed",
        Some(Input::Gravity) => "--g",
        Some(Input::Drag) => "--drag",
        _ => "--rtol",
    }
}

fn with_flag(e: &RocketError) -> anyhow::Error {
    anyhow!("{}: {e}", flag(e.input()))
}

fn build(args: &RocketArgs) -> Result<Rocket> {
    let m0 = quantity(&args.m0, "--m0", Dimension::MASS)?;
    let m1 = quantity(&args.m1, "--m1", Dimension::MASS)?;
    let rate = mass_rate(&args.mass_rate)?;
    let u = quantity(&args.exhaust_speed, "--exhaust-speed", Dimension::VELOCITY)?;
    let g = args
        .g
        .as_deref()
        .map_or(Ok(0.0), |g| quantity(g, "--g", Dimension::ACCELERATION))?;
    let drag = args
        .drag
        .as_deref()
        .map(|d| quantity(d, "--drag", Dimension::QUADRATIC_DRAG))
        .transpose()?;
    let mut rocket = Rocket::new(m0, m1, rate, u)
        .and_then(|r| r.with_gravity(g))
        .map_err(|e| with_flag(&e))?;
    if let Some(d) = drag {
        rocket = rocket.with_drag(d).map_err(|e| with_flag(&e))?;
    }
    Ok(rocket)
}

pub fn rocket(args: &RocketArgs) -> Result<Outcome> {
    let rocket = build(args)?;
    let mut result = match rocket.report(args.rtol, args.coast) {
        Ok(r) => r,
        Err(RocketError::Integrate(e)) => {
            eprintln!("error: the simulation failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => return Err(with_flag(&e)),
    };
    let mut wrote = None;
    if let Some(dir) = &args.out {
        create_dir(dir)?;
        let csv = write_table(dir, "rocket", &result.table())?;
        let plots = if args.no_plots {
            Vec::new()
        } else {
            write_plots(dir, &result.plots(), &title(&result), args.plots)?
        };
        wrote = Some(super::roll::written(&csv, &plots));
        if !plots.is_empty() {
            result.plots = Some(dir.display().to_string());
        }
    }
    report(args.report, &result, || text(&result, args))?;
    if let Some(w) = &wrote {
        note(args.report, w);
    }
    Ok(Outcome::Success)
}

fn title(r: &RocketReport) -> String {
    let drag = r
        .drag
        .map_or_else(String::new, |d| format!(", D = {} kg/m", show(d)));
    format!(
        "rocket: m0 = {} kg, m1 = {} kg, ṁ = {} kg/s, u = {} m/s, g = {} m/s²{drag}",
        show(r.m0),
        show(r.m1),
        show(r.mass_rate),
        show(r.exhaust_speed),
        show(r.g)
    )
}

fn text(r: &RocketReport, args: &RocketArgs) -> String {
    let drag = r.drag.map_or_else(
        || "no drag".to_string(),
        |d| format!("drag D = {} kg/m", show(d)),
    );
    let mut out = format!(
        "rocket: m0 = {} kg, m1 = {} kg, ṁ = {} kg/s, u = {} m/s, g = {} m/s², {drag}\n",
        show(r.m0),
        show(r.m1),
        show(r.mass_rate),
        show(r.exhaust_speed),
        show(r.g)
    );
    let _ = writeln!(
        out,
        "  thrust u ṁ = {} N, weight at ignition m0 g = {} N",
        show(r.thrust),
        show(r.m0 * r.g)
    );
    if !r.lifts_off {
        out.push_str(
            "  note: the thrust is below the weight; with no launch pad in the model the rocket sinks at first\n",
        );
    }
    let _ = writeln!(
        out,
        "  rocket equation (free space): Δv = u ln(m0/m1) = {} m/s",
        show(r.delta_v)
    );
    let _ = writeln!(out, "  burn time T = (m0 - m1)/ṁ = {} s", show(r.burn_time));
    let head = if r.drag.is_some() {
        "closed form, no drag"
    } else {
        "closed form"
    };
    let _ = writeln!(
        out,
        "  {:<22} {head:<22} {:<22} difference",
        "", "simulated"
    );
    let row = |out: &mut String, what: &str, c: &mechkit::report::Comparison| {
        let _ = writeln!(
            out,
            "  {what:<22} {:<22} {:<22} {:+.3e}",
            show(c.closed_form),
            show(c.simulated),
            c.difference
        );
    };
    row(&mut out, "burnout speed [m/s]", &r.burnout.v);
    row(&mut out, "burnout height [m]", &r.burnout.x);
    match &r.apex {
        Some(apex) => {
            row(&mut out, "apex time [s]", &apex.t);
            row(&mut out, "apex height [m]", &apex.x);
            if r.burnout.v.simulated <= 0.0 {
                out.push_str("  falling at burnout: the highest point of the coast is burnout\n");
            }
        }
        None if args.coast => {
            out.push_str("  no apex: in free space (g = 0) the rocket coasts at v1 forever\n");
        }
        None => {}
    }
    if r.drag.is_some() {
        out.push_str(
            "  the closed forms leave the drag out: the difference is the drag's effect\n",
        );
    }
    let s = &r.simulation;
    let h_max = s.h_max;
    let _ = writeln!(
        out,
        "simulation: dopri5 at rtol {:e}, steps up to {} s: {} steps ({} rejected), {} evaluations",
        args.rtol,
        if h_max >= 0.01 {
            mechkit::expr::short_fixed(h_max, 3)
        } else {
            format!("{h_max:.3e}")
        },
        s.steps,
        s.rejected,
        s.evaluations
    );
    out
}
