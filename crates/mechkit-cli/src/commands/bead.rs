//! `mechkit bead`: a body on a circle or a curve y(x) under gravity: the normal force, the
//! departure where it reaches zero, the flight to the landing; path.csv and path.svg.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::figure::{LineStyle, Marker, MarkerShape, PlotData, Series};
use mechkit::ode::AdaptiveConfig;
use mechkit::rigid::constrained::{
    BeadOnCurve, BeadRun, ConstrainedError, Curve, Side, Start, StopReason,
};
use mechkit::scenario::{push_number, write_atomic};
use serde_json::{Value, json};

use super::input::{params, quantity, show};
use super::{Outcome, print};
use crate::args::BeadArgs;
use crate::plot::render;

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

fn flag_of(e: &ConstrainedError) -> &'static str {
    match e {
        ConstrainedError::Value { what, .. } => match *what {
            "the radius" => "--circle",
            "the mass" => "--mass",
            "g" => "--g",
            "t_max" => "--t-max",
            _ => "--start",
        },
        ConstrainedError::Formula(_) => "--curve",
        ConstrainedError::Config(_) => "--rtol",
        _ => "--start",
    }
}

pub fn bead(args: &BeadArgs) -> Result<Outcome> {
    let err = |e: ConstrainedError| anyhow!("{}: {e}", flag_of(&e));
    let (curve, is_circle) = match (&args.circle, &args.curve) {
        (Some(r), _) => (
            Curve::circle(quantity(r, "--circle", Dimension::LENGTH)?).map_err(err)?,
            true,
        ),
        (None, Some(c)) => (
            Curve::graph(c, &params(args.set.as_deref())?).map_err(err)?,
            false,
        ),
        (None, None) => bail!("give the curve: --circle \"1 m\" or --curve \"x^2/2\""),
    };
    let side = side(&args.side, is_circle)?;
    let mass = quantity(&args.mass, "--mass", Dimension::MASS)?;
    let g = quantity(&args.g, "--g", Dimension::ACCELERATION)?;
    let model = BeadOnCurve::new(curve, side, mass, g).map_err(err)?;
    let coordinate = if is_circle {
        quantity(&args.start, "--start", Dimension::NONE)?
    } else {
        quantity(&args.start, "--start", Dimension::LENGTH)?
    };
    let speed = match &args.drop_height {
        Some(h) => {
            let h = quantity(h, "--drop-height", Dimension::LENGTH)?;
            if h < 0.0 || !h.is_finite() {
                bail!("--drop-height is {h} m; it must be zero or positive");
            }
            (2.0 * g * h).sqrt()
        }
        None => quantity(&args.speed, "--speed", Dimension::VELOCITY)?,
    };
    let t_max = quantity(&args.t_max, "--t-max", Dimension::TIME)?;
    if !(t_max > 0.0 && t_max.is_finite()) {
        bail!("--t-max is {t_max} s; give a positive time, e.g. --t-max \"5 s\"");
    }
    let config = AdaptiveConfig::from_rtol(args.rtol).sampled_over(t_max);
    config.validate(2).map_err(|e| anyhow!("--rtol: {e}"))?;
    let start = Start { coordinate, speed };
    let run = match model.simulate(start, t_max, &config) {
        Ok(run) => run,
        Err(ConstrainedError::Integrate(e)) => {
            eprintln!("error: the integration failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e @ ConstrainedError::Undefined { x, .. }) if x != coordinate => {
            // the start was fine: the motion reached a point the graph cannot carry
            eprintln!("error: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => return Err(err(e)),
    };
    let files = if args.no_plots {
        None
    } else {
        let dir = args
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out/bead"));
        write_outputs(&model, &run, &dir, args.plots)?;
        Some(dir)
    };
    let plot_name = args.plots.file("path");
    let files = files.as_deref().map(|d| (d, plot_name.as_str()));
    if args.json {
        print(&format!("{:#}\n", to_json(&model, start, &run, files)))?;
    } else {
        print(&text(&model, start, &run, files))?;
    }
    Ok(Outcome::Success)
}

/// An angle in degrees in (−180°, 180°].
fn wrapped_degrees(a: f64) -> f64 {
    a.sin().atan2(a.cos()).to_degrees()
}

fn stop_name(s: StopReason) -> &'static str {
    match s {
        StopReason::Landed => "landed",
        _ => "time-limit",
    }
}

fn side_name(s: Side, circle: bool) -> &'static str {
    match (s, circle) {
        (Side::Outer, true) => "outside",
        (Side::Outer, false) => "above",
        (Side::Inner, true) => "inside",
        (Side::Inner, false) => "below",
        (Side::Bead, _) => "bead",
    }
}

fn to_json(
    model: &BeadOnCurve,
    start: Start,
    run: &BeadRun,
    files: Option<(&Path, &str)>,
) -> Value {
    let circle = model.curve.radius().is_some();
    let departure = run.departure.map_or(Value::Null, |d| {
        let mut v = json!({
            "t": d.t, "coordinate": d.coordinate, "position": d.position,
            "velocity": d.velocity, "speed": d.velocity[0].hypot(d.velocity[1]),
            "normal_force": d.normal_force,
        });
        if circle {
            v["angle_from_top_deg"] = json!(wrapped_degrees(d.coordinate));
            v["cos_angle"] = json!(d.coordinate.cos());
        }
        v
    });
    let landing = run.landing.map_or(Value::Null, |l| {
        json!({
            "t": l.t, "coordinate": l.coordinate, "position": l.position,
            "velocity": l.velocity, "tangential_speed": l.tangential_speed,
            "normal_speed": l.normal_speed,
        })
    });
    json!({
        "curve": model.curve.describe(),
        "side": side_name(model.side, circle),
        "mass": model.mass, "g": model.g,
        "start": {"coordinate": start.coordinate, "speed": start.speed},
        "energy_per_mass": run.energy,
        "energy_drift_per_mass": run.energy_drift,
        "departure": departure,
        "landing": landing,
        "stop_reason": stop_name(run.stop),
        "turning_times": run.turning_times,
        "t_end": run.samples.last().map_or(0.0, |s| s.t),
        "steps": run.stats.accepted,
        "files": files.map(|(d, plot)| json!({
            "csv": d.join("path.csv").display().to_string(),
            "plot": d.join(plot).display().to_string(),
        })),
    })
}

fn text(model: &BeadOnCurve, start: Start, run: &BeadRun, files: Option<(&Path, &str)>) -> String {
    let circle = model.curve.radius().is_some();
    let mut out = format!(
        "{} on the {} of a {}, m = {} kg, g = {} m/s²\n",
        if model.side == Side::Bead {
            "bead threaded"
        } else {
            "body"
        },
        side_name(model.side, circle),
        model.curve.describe(),
        show(model.mass),
        show(model.g)
    );
    if let Some((d1, d2)) = model.curve.derivatives() {
        let _ = writeln!(out, "  y' = {d1}, y'' = {d2}");
    }
    let _ = writeln!(
        out,
        "start at {} = {}, speed {} m/s; energy per kg ½v² + g y = {} J/kg",
        if circle { "φ (from the top)" } else { "x" },
        show(start.coordinate),
        show(start.speed),
        show(run.energy)
    );
    match run.departure {
        Some(d) => {
            let _ = writeln!(
                out,
                "leaves the curve at t = {} s at ({}, {}) m, speed {} m/s (N = {:.1e} N)",
                show(d.t),
                show(d.position[0]),
                show(d.position[1]),
                show(d.velocity[0].hypot(d.velocity[1])),
                d.normal_force
            );
            if circle {
                let _ = writeln!(
                    out,
                    "  angle from the top {}°, cos φ = {}",
                    show(wrapped_degrees(d.coordinate)),
                    show(d.coordinate.cos())
                );
            }
        }
        None => out.push_str("stays on the curve\n"),
    }
    if let Some(l) = run.landing {
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
    if !run.turning_times.is_empty() {
        let list: Vec<String> = run.turning_times.iter().take(6).map(|t| show(*t)).collect();
        let _ = writeln!(out, "turning points at t = {} s", list.join(", "));
    }
    let _ = writeln!(
        out,
        "energy drift on the curve {:.1e} J/kg; {} steps (dopri5)",
        run.energy_drift, run.stats.accepted
    );
    if let Some((d, plot)) = files {
        let _ = writeln!(out, "wrote {}/path.csv and {plot}", d.display());
    }
    out
}

fn write_outputs(
    model: &BeadOnCurve,
    run: &BeadRun,
    dir: &Path,
    format: crate::args::PlotFormat,
) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| anyhow!("cannot create {}: {e}", dir.display()))?;
    let mut csv = String::from("t,x,y,vx,vy,normal_force,on_curve\n");
    for s in &run.samples {
        for v in [
            s.t,
            s.position[0],
            s.position[1],
            s.velocity[0],
            s.velocity[1],
        ] {
            push_number(&mut csv, v);
            csv.push(',');
        }
        match s.normal_force {
            Some(n) => push_number(&mut csv, n),
            None => csv.push_str("nan"),
        }
        csv.push_str(if s.normal_force.is_some() {
            ",1\n"
        } else {
            ",0\n"
        });
    }
    let path = dir.join("path.csv");
    write_atomic(&path, csv.as_bytes())
        .map_err(|e| anyhow!("cannot write {}: {e}", path.display()))?;
    let track: Vec<(f64, f64)> = if let Some(r) = model.curve.radius() {
        (0..=360)
            .map(|i| {
                let a = f64::from(i).to_radians();
                (r * a.sin(), r * a.cos())
            })
            .collect()
    } else {
        let (lo, hi) = run
            .samples
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), s| {
                (a.min(s.position[0]), b.max(s.position[0]))
            });
        let pad = 0.1 * (hi - lo).max(1e-3);
        (0..=400)
            .map(|i| {
                let x = lo - pad + (hi - lo + 2.0 * pad) * f64::from(i) / 400.0;
                (x, model.curve.point(x)[1])
            })
            .filter(|p| p.1.is_finite())
            .collect()
    };
    let on: Vec<(f64, f64)> = run
        .samples
        .iter()
        .filter(|s| s.normal_force.is_some())
        .map(|s| (s.position[0], s.position[1]))
        .collect();
    let free: Vec<(f64, f64)> = run
        .samples
        .iter()
        .filter(|s| s.normal_force.is_none())
        .map(|s| (s.position[0], s.position[1]))
        .collect();
    let mut plot = PlotData::new("path", "path", "x [m]", "y [m]")
        .with_series(Series::line("curve", track).styled(LineStyle::Dashed))
        .with_series(Series::line("on the curve", on));
    if !free.is_empty() {
        plot = plot.with_series(Series::line("free flight", free));
    }
    plot.equal_aspect = true;
    let first = &run.samples[0];
    plot.markers.push(Marker {
        at: (first.position[0], first.position[1]),
        label: "start".into(),
        shape: MarkerShape::Filled,
    });
    if let Some(d) = run.departure {
        plot.markers.push(Marker {
            at: (d.position[0], d.position[1]),
            label: "leaves (N = 0)".into(),
            shape: MarkerShape::Open,
        });
    }
    if let Some(l) = run.landing {
        plot.markers.push(Marker {
            at: (l.position[0], l.position[1]),
            label: "lands".into(),
            shape: MarkerShape::Cross,
        });
    }
    let title = format!(
        "{}: {}",
        side_name(model.side, model.curve.radius().is_some()),
        model.curve.describe()
    );
    render(&plot, &title, &dir.join(format.file("path")), format.dpi)
}
