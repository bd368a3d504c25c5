//! `mechkit power`: motion at constant engine power (v, a, x at given times, the time to reach
//! a speed, and plots of v(t) and x(t)), or the average power of a work done over a time.

use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::{Result, anyhow, bail};
use mechkit::energy::ConstantPower;
use mechkit::figure::{PlotData, Series};
use serde_json::json;

use mechkit::expr::units::Dimension;

use super::input::{quantity, split_top_level};
use super::{Outcome, print};
use crate::args::PowerArgs;
use crate::plot::render;

pub fn power(args: &PowerArgs) -> Result<Outcome> {
    if let (Some(w), Some(t)) = (&args.work, &args.time) {
        let (w, t) = (
            quantity(w, "--work", Dimension::ENERGY)?,
            quantity(t, "--time", Dimension::TIME)?,
        );
        if t <= 0.0 {
            bail!("--time must be positive, not {t}");
        }
        let p = w / t;
        if args.json {
            print(&format!(
                "{:#}\n",
                json!({"work": w, "time": t, "average_power": p})
            ))?;
        } else {
            print(&format!("average power P = W/t = {w} J / {t} s = {p} W\n"))?;
        }
        return Ok(Outcome::Success);
    }
    let (Some(power), Some(mass)) = (&args.power, &args.mass) else {
        bail!(
            "give --power and --mass for motion at constant power (e.g. --power \"20 kW\" --mass \"200 kg\" --at \"5 s\"), or --work and --time for an average power"
        );
    };
    let (power, mass) = (
        quantity(power, "--power", Dimension::POWER)?,
        quantity(mass, "--mass", Dimension::MASS)?,
    );
    let v0 = args
        .v0
        .as_deref()
        .map_or(Ok(0.0), |v| quantity(v, "--v0", Dimension::VELOCITY))?;
    let motion = ConstantPower::new(power, mass, v0, 0.0).ok_or_else(|| {
        anyhow!("--power and --mass must be positive and --v0 not negative (got P = {power} W, m = {mass} kg, v0 = {v0} m/s)")
    })?;
    let times: Vec<f64> = match &args.at {
        Some(list) => split_top_level(list, ',')
            .into_iter()
            .map(|t| quantity(t, "--at", Dimension::TIME))
            .collect::<Result<_>>()?,
        None => Vec::new(),
    };
    if let Some(t) = times.iter().find(|t| **t < 0.0) {
        bail!("--at {t}: times must not be negative");
    }
    let speed_target = args
        .until_speed
        .as_deref()
        .map(|v| quantity(v, "--until-speed", Dimension::VELOCITY))
        .transpose()?;
    let t_speed =
        match speed_target {
            Some(v) => Some(motion.time_to_speed(v).ok_or_else(|| {
                anyhow!("--until-speed {v} m/s is below the start speed {v0} m/s")
            })?),
            None => None,
        };
    let t_end = times.iter().copied().chain(t_speed).fold(0.0, f64::max);
    let rows: Vec<_> = times
        .iter()
        .map(|&t| {
            json!({"t": t, "v": motion.speed(t), "a": motion.acceleration(t), "x": motion.position(t), "work": motion.work(t)})
        })
        .collect();
    let plot = if args.no_plots || t_end <= 0.0 {
        None
    } else {
        let dir = args
            .out
            .clone()
            .unwrap_or_else(|| PathBuf::from("out/power"));
        std::fs::create_dir_all(&dir)
            .map_err(|e| anyhow!("cannot create {}: {e}", dir.display()))?;
        let ts: Vec<f64> = (0..=400).map(|i| t_end * f64::from(i) / 400.0).collect();
        let title = format!("constant power P = {power} W, m = {mass} kg");
        let v = PlotData::new("v(t)", "v(t)", "t [s]", "v [m/s]").with_series(Series::line(
            "v(t)",
            ts.iter().map(|&t| (t, motion.speed(t))).collect(),
        ));
        let x = PlotData::new("x(t)", "x(t)", "t [s]", "x [m]").with_series(Series::line(
            "x(t)",
            ts.iter().map(|&t| (t, motion.position(t))).collect(),
        ));
        render(
            &v,
            &title,
            &dir.join(args.plots.file("v(t)")),
            args.plots.dpi,
        )?;
        render(
            &x,
            &title,
            &dir.join(args.plots.file("x(t)")),
            args.plots.dpi,
        )?;
        Some(dir)
    };
    if args.json {
        let j = json!({
            "power": power, "mass": mass, "v0": v0,
            "at": rows,
            "until_speed": speed_target.map(|v| json!({"v": v, "t": t_speed, "x": t_speed.map(|t| motion.position(t))})),
            "plots": plot.as_ref().map(|d| d.display().to_string()),
        });
        print(&format!("{j:#}\n"))?;
    } else {
        let mut out = format!(
            "constant power P = {power} W on m = {mass} kg from v0 = {v0} m/s:\n  v = sqrt(v0² + 2Pt/m), a = P/(m v), x = m (v³ - v0³)/(3P)\n"
        );
        for &t in &times {
            let _ = writeln!(
                out,
                "  t = {t} s: v = {} m/s, a = {} m/s², x = {} m, work = {} J",
                motion.speed(t),
                motion.acceleration(t),
                motion.position(t),
                motion.work(t)
            );
        }
        if let (Some(v), Some(t)) = (speed_target, t_speed) {
            let _ = writeln!(
                out,
                "  reaches {v} m/s at t = {t} s, x = {} m",
                motion.position(t)
            );
        }
        if let Some(d) = &plot {
            let [v, x] = ["v(t)", "x(t)"].map(|s| args.plots.file(s));
            let _ = writeln!(out, "plots: {}/{v}, {x}", d.display());
        }
        print(&out)?;
    }
    Ok(Outcome::Success)
}
