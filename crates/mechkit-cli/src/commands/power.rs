//! `mechkit power`: motion at constant engine power (v, a, x at given times, the time to reach
//! a speed; with `-o DIR` the curves as CSV and the plots v_t and x_t), or the average power of
//! a work done over a time (`mechkit::energy::{constant_power_motion, average_power}`).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::energy::{PowerAnswer, PowerMotion, average_power, constant_power_motion};
use mechkit::expr::units::Dimension;
use mechkit::inputs::{Input, InputError};

use super::input::{quantity, show, split_top_level};
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::PowerArgs;

/// An input's error with its flag.
fn flagged(InputError { input, message }: InputError) -> anyhow::Error {
    let flag = match input {
        Input::Power => "--power",
        Input::Mass => "--mass",
        Input::StartSpeed => "--v0",
        Input::At => "--at",
        Input::TargetSpeed => "--until-speed",
        Input::Work => "--work",
        _ => "--time",
    };
    anyhow!("{flag}: {message}")
}

pub fn power(args: &PowerArgs) -> Result<Outcome> {
    let mut answer = if let (Some(w), Some(t)) = (&args.work, &args.time) {
        let (w, t) = (
            quantity(w, "--work", Dimension::ENERGY)?,
            quantity(t, "--time", Dimension::TIME)?,
        );
        PowerAnswer::Average(average_power(w, t).map_err(flagged)?)
    } else {
        let (Some(power), Some(mass)) = (&args.power, &args.mass) else {
            bail!(
                "give --power and --mass for motion at constant power (e.g. --power \"20 kW\" --mass \"200 kg\" --at \"5 s\"), or --work and --time for an average power"
            );
        };
        let times: Vec<f64> = match &args.at {
            Some(list) => split_top_level(list, ',')
                .into_iter()
                .map(|t| quantity(t, "--at", Dimension::TIME))
                .collect::<Result<_>>()?,
            None => Vec::new(),
        };
        let motion = constant_power_motion(
            quantity(power, "--power", Dimension::POWER)?,
            quantity(mass, "--mass", Dimension::MASS)?,
            args.v0
                .as_deref()
                .map_or(Ok(0.0), |v| quantity(v, "--v0", Dimension::VELOCITY))?,
            &times,
            args.until_speed
                .as_deref()
                .map(|v| quantity(v, "--until-speed", Dimension::VELOCITY))
                .transpose()?,
        )
        .map_err(flagged)?;
        PowerAnswer::Motion(motion)
    };
    // the finiteness rule before any file is written, not only before the answer is printed
    mechkit::finite::check_finite(&answer)?;
    if let (Some(dir), PowerAnswer::Motion(m)) = (&args.out, &mut answer) {
        write_files(args, dir, m)?;
    }
    report(args.report, &answer, || match &answer {
        PowerAnswer::Average(p) => format!(
            "average power P = W/t = {} J / {} s = {} W\n",
            show(p.work),
            show(p.time),
            show(p.average_power)
        ),
        PowerAnswer::Motion(m) => text(m),
        _ => String::new(),
    })?;
    Ok(Outcome::Success)
}

/// With `-o DIR`: `power.csv` up to the last time asked, and the plots `v_t` and `x_t`.
fn write_files(args: &PowerArgs, dir: &Path, m: &mut PowerMotion) -> Result<()> {
    if m.t_end() <= 0.0 {
        note(
            args.report,
            "nothing to write: give --at times or --until-speed for the curves",
        );
        return Ok(());
    }
    create_dir(dir)?;
    let csv = write_table(dir, "power", &m.table(400))?;
    note(args.report, &format!("wrote {csv}"));
    if !args.no_plots {
        let title = format!(
            "constant power P = {} W, m = {} kg",
            show(m.power),
            show(m.mass)
        );
        for path in write_plots(dir, &m.plots(), &title, args.plots)? {
            note(args.report, &format!("wrote {path}"));
        }
    }
    m.plots = Some(dir.display().to_string());
    Ok(())
}

fn text(m: &PowerMotion) -> String {
    let mut out = format!(
        "constant power P = {} W on m = {} kg from v0 = {} m/s:\n  v = sqrt(v0² + 2Pt/m), a = P/(m v), x = m (v³ - v0³)/(3P)\n",
        show(m.power),
        show(m.mass),
        show(m.v0)
    );
    for s in &m.at {
        let _ = writeln!(
            out,
            "  t = {} s: v = {} m/s, a = {} m/s², x = {} m, work = {} J",
            show(s.t),
            show(s.v),
            show(s.a),
            show(s.x),
            show(s.work)
        );
    }
    if let Some(r) = m.until_speed {
        let _ = writeln!(
            out,
            "  reaches {} m/s at t = {} s, x = {} m",
            show(r.v),
            show(r.t),
            show(r.x)
        );
    }
    out
}
