//! `mechkit rocket`: a rocket of variable mass. Δv by the rocket equation, the burn time,
//! burnout speed and height (and the apex of the coast) in closed form and simulated side by
//! side, and plots of v(t), x(t) and m(t).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::{Dimension, Quantity};
use mechkit::figure::{LineStyle, PlotData, Series};
use mechkit::ode::AdaptiveConfig;
use mechkit::rocket::{Rocket, RocketError, RocketRun};
use serde_json::{Value, json};

use super::input::{quantity, show};
use super::{Outcome, print};
use crate::args::RocketArgs;
use crate::plot::render;

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

/// The flag behind a rocket's error, for the message.
fn flag(e: &RocketError) -> &'static str {
    match e {
        RocketError::Mass { which, .. } if which.ends_with("m0") => "--m0",
        RocketError::Mass { .. } | RocketError::Burnout { .. } => "--m1",
        RocketError::MassRate { .. } => "--mass-rate",
        RocketError::ExhaustSpeed { .. } => "--exhaust-speed",
        RocketError::Gravity { .. } => "--g",
        RocketError::Drag { .. } => "--drag",
        _ => "--rtol",
    }
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
    let with_flag = |e: RocketError| anyhow!("{}: {e}", flag(&e));
    let mut rocket = Rocket::new(m0, m1, rate, u)
        .and_then(|r| r.with_gravity(g))
        .map_err(with_flag)?;
    if let Some(d) = drag {
        rocket = rocket.with_drag(d).map_err(with_flag)?;
    }
    Ok(rocket)
}

pub fn rocket(args: &RocketArgs) -> Result<Outcome> {
    let rocket = build(args)?;
    // steps sampled over the flight, so the plots follow the curves (a drag-free coast is a
    // parabola, which the method would cross in one step)
    let flight = rocket.apex().map_or(rocket.burn_time(), |(t, _)| t);
    let config = AdaptiveConfig::from_rtol(args.rtol).sampled_over(flight);
    config.validate(3).map_err(|e| anyhow!("--rtol: {e}"))?;
    let run = match rocket.simulate(&config, args.coast) {
        Ok(run) => run,
        Err(RocketError::Integrate(e)) => {
            eprintln!("error: the simulation failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => bail!("{}: {e}", flag(&e)),
    };
    let plots = if args.no_plots {
        None
    } else {
        let dir = args
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out/rocket"));
        plot(&rocket, &run, &dir, args.plots)?;
        Some(dir)
    };
    if args.json {
        print(&format!(
            "{:#}\n",
            to_json(&rocket, &run, &config, plots.as_deref())
        ))?;
    } else {
        print(&text(&rocket, &run, args, &config, plots.as_deref()))?;
    }
    Ok(Outcome::Success)
}

/// `{closed_form, simulated, difference}` of one quantity.
fn compare(closed: f64, simulated: f64) -> Value {
    json!({"closed_form": closed, "simulated": simulated, "difference": simulated - closed})
}

fn to_json(
    rocket: &Rocket,
    run: &RocketRun,
    config: &AdaptiveConfig,
    plots: Option<&Path>,
) -> Value {
    let (t1, x1, v1) = run.burnout;
    let (_, x_c, v_c) = rocket.burnout();
    let apex = match (run.apex, rocket.apex()) {
        (Some((t, x)), Some((t_c, x_c))) => json!({"t": compare(t_c, t), "x": compare(x_c, x)}),
        _ => Value::Null,
    };
    json!({
        "m0": rocket.m0, "m1": rocket.m1, "mass_rate": rocket.mass_rate,
        "exhaust_speed": rocket.exhaust_speed, "g": rocket.g, "drag": rocket.drag,
        "thrust": rocket.thrust(), "lifts_off": rocket.lifts_off(),
        "delta_v": rocket.delta_v(), "burn_time": rocket.burn_time(),
        "burnout": {"t": t1, "v": compare(v_c, v1), "x": compare(x_c, x1)},
        "apex": apex,
        "simulation": {
            "method": "dopri5", "rtol": config.rtol.as_scalar(),
            "atol": config.atol.as_scalar(), "h_max": config.h_max,
            "steps": run.stats.accepted, "rejected": run.stats.rejected,
            "evaluations": run.stats.evaluations, "samples": run.samples.len(),
        },
        "plots": plots.map(|d| d.display().to_string()),
    })
}

fn text(
    rocket: &Rocket,
    run: &RocketRun,
    args: &RocketArgs,
    config: &AdaptiveConfig,
    plots: Option<&Path>,
) -> String {
    let h_max = config.h_max;
    let r = rocket;
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
        show(r.thrust()),
        show(r.m0 * r.g)
    );
    if !r.lifts_off() {
        out.push_str(
            "  note: the thrust is below the weight; with no launch pad in the model the rocket sinks at first\n",
        );
    }
    let _ = writeln!(
        out,
        "  rocket equation (free space): Δv = u ln(m0/m1) = {} m/s",
        show(r.delta_v())
    );
    let _ = writeln!(
        out,
        "  burn time T = (m0 - m1)/ṁ = {} s",
        show(r.burn_time())
    );
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
    let row = |out: &mut String, what: &str, closed: f64, sim: f64| {
        let _ = writeln!(
            out,
            "  {what:<22} {:<22} {:<22} {:+.3e}",
            show(closed),
            show(sim),
            sim - closed
        );
    };
    let (_, x1, v1) = run.burnout;
    let (_, x_c, v_c) = r.burnout();
    row(&mut out, "burnout speed [m/s]", v_c, v1);
    row(&mut out, "burnout height [m]", x_c, x1);
    match (run.apex, r.apex()) {
        (Some((t, x)), Some((t_c, x_c))) => {
            row(&mut out, "apex time [s]", t_c, t);
            row(&mut out, "apex height [m]", x_c, x);
            if v1 <= 0.0 {
                out.push_str("  falling at burnout: the highest point of the coast is burnout\n");
            }
        }
        _ if args.coast => {
            out.push_str("  no apex: in free space (g = 0) the rocket coasts at v1 forever\n");
        }
        _ => {}
    }
    if r.drag.is_some() {
        out.push_str(
            "  the closed forms leave the drag out: the difference is the drag's effect\n",
        );
    }
    let s = run.stats;
    let _ = writeln!(
        out,
        "simulation: dopri5 at rtol {:e}, steps up to {} s: {} steps ({} rejected), {} evaluations",
        args.rtol,
        if h_max >= 0.01 {
            format!("{h_max:.3}")
        } else {
            format!("{h_max:.3e}")
        },
        s.accepted,
        s.rejected,
        s.evaluations
    );
    if let Some(d) = plots {
        let [v, x, m] = ["v(t)", "x(t)", "m(t)"].map(|s| args.plots.file(s));
        let _ = writeln!(out, "plots: {}/{v}, {x}, {m}", d.display());
    }
    out
}

/// v(t), x(t) and m(t) of the simulation, with the drag-free closed forms dashed.
fn plot(
    rocket: &Rocket,
    run: &RocketRun,
    dir: &Path,
    format: crate::args::PlotFormat,
) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| anyhow!("cannot create {}: {e}", dir.display()))?;
    let t_end = run.samples.last().map_or(0.0, |s| s.0);
    let grid: Vec<f64> = (0..=400).map(|i| t_end * f64::from(i) / 400.0).collect();
    let closed_label = if rocket.drag.is_some() {
        "closed form, no drag"
    } else {
        "closed form"
    };
    let curve = |f: fn(&(f64, f64, f64, f64)) -> f64| -> Vec<(f64, f64)> {
        run.samples.iter().map(|s| (s.0, f(s))).collect()
    };
    let drag = rocket
        .drag
        .map_or_else(String::new, |d| format!(", D = {} kg/m", show(d)));
    let title = format!(
        "rocket: m0 = {} kg, m1 = {} kg, ṁ = {} kg/s, u = {} m/s, g = {} m/s²{drag}",
        show(rocket.m0),
        show(rocket.m1),
        show(rocket.mass_rate),
        show(rocket.exhaust_speed),
        show(rocket.g)
    );
    let figures = [
        (
            "v(t)",
            "v [m/s]",
            curve(|s| s.2),
            Rocket::speed as fn(&Rocket, f64) -> f64,
        ),
        ("x(t)", "x [m]", curve(|s| s.1), Rocket::height),
        ("m(t)", "m [kg]", curve(|s| s.3), Rocket::mass),
    ];
    for (name, y_label, simulated, closed) in figures {
        let closed: Vec<(f64, f64)> = grid.iter().map(|&t| (t, closed(rocket, t))).collect();
        let mut data = PlotData::new(name, name, "t [s]", y_label)
            .with_series(Series::line("simulated", simulated));
        if name != "m(t)" {
            data = data.with_series(Series::line(closed_label, closed).styled(LineStyle::Dashed));
        }
        render(&data, &title, &dir.join(format.file(name)), format.dpi)?;
    }
    Ok(())
}
