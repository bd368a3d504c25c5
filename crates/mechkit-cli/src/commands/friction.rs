//! `mechkit friction`: a block on a flat or inclined surface with Coulomb friction (normal
//! force, static bound, sliding friction, marginal angle, whether it slides and how fast,
//! `Incline::report`), and with `--spring-k` the stick-slip spring-block model
//! (`SpringBlock::report`): the phases with their closed-form switch times, the energy ledger;
//! `stick_slip.csv` and plots with `-o`.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::report::Files;
use mechkit::rigid::Input;
use mechkit::rigid::friction::{
    Coulomb, FrictionError, FrictionReport, Incline, SpringBlock, StickSlipReport,
};

use super::input::{fixed, quantity, show};
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::FrictionArgs;

/// The most phases listed in the text report (all are in the JSON and the CSV).
const TABLE_ROWS: usize = 24;

/// The friction coefficients from `--mu` or `--mu-s`/`--mu-d`.
pub(super) fn coefficients(
    mu: Option<&str>,
    mu_s: Option<&str>,
    mu_d: Option<&str>,
) -> Result<Coulomb> {
    let coefficient = |text: &str, flag: &str| quantity(text, flag, Dimension::NONE);
    let (s, d, flags) = match (mu, mu_s, mu_d) {
        (Some(m), _, _) => {
            let m = coefficient(m, "--mu")?;
            (m, m, ("--mu", "--mu"))
        }
        (None, Some(s), Some(d)) => (
            coefficient(s, "--mu-s")?,
            coefficient(d, "--mu-d")?,
            ("--mu-s", "--mu-d"),
        ),
        _ => bail!("give the friction coefficients: --mu-s and --mu-d, or --mu for both"),
    };
    let c = Coulomb::new(s, d).map_err(|e| match e.input() {
        Some(Input::StaticFriction) => anyhow!("{}: {e}", flags.0),
        _ => anyhow!("{}: {e}", flags.1),
    })?;
    if let Some(w) = c.warning() {
        eprintln!("warning: {w}");
    }
    Ok(c)
}

/// An angle (a bare number is in radians), with a hint when it looks like degrees.
pub(super) fn angle(text: Option<&str>, flag: &str) -> Result<f64> {
    let Some(text) = text else { return Ok(0.0) };
    let a = quantity(text, flag, Dimension::NONE)?;
    if !(a.is_finite() && a.abs() <= std::f64::consts::FRAC_PI_2) {
        // the hint to write degrees only for a bare number: "100 deg" has its unit already
        let bare = text.trim().parse::<f64>().is_ok();
        bail!(
            "{flag} `{text}` is {}°; it must be between -90° and 90°{}",
            show(a.to_degrees()),
            if bare {
                format!(
                    " (a bare number is in radians: write \"{} deg\" for degrees)",
                    text.trim()
                )
            } else {
                String::new()
            }
        );
    }
    Ok(a)
}

/// A value for the text report, to 7 significant digits without trailing zeros (`-0` as
/// `0`); the JSON and the CSV keep every digit.
pub(super) fn sig(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return show(x + 0.0);
    }
    let magnitude = x.abs().log10().floor();
    if !(-4.0..9.0).contains(&magnitude) {
        return format!("{x:.6e}");
    }
    // 7 significant digits: magnitude 0 (1 ≤ |x| < 10) keeps 6 decimals
    let decimals = (6.0 - magnitude).max(0.0) as usize;
    let text = format!("{x:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        &text
    };
    if text == "-0" {
        "0".to_string()
    } else {
        text.to_string()
    }
}

fn optional(text: Option<&str>, flag: &str, dim: Dimension, default: f64) -> Result<f64> {
    text.map_or(Ok(default), |t| quantity(t, flag, dim))
}

/// The flag of an input of `mechkit friction`.
fn flag(input: Option<Input>, args: &FrictionArgs) -> &'static str {
    match input {
        Some(Input::Mass) => "--mass",
        Some(Input::SpringConstant) => "--spring-k",
        Some(Input::Duration) => "--t-max",
        Some(Input::NormalLoad) => "--normal-load",
        Some(Input::Angle) => "--angle",
        Some(Input::Gravity) => "--g",
        Some(Input::BeltSpeed) => "--belt-speed",
        Some(Input::AnchorSpeed) => "--anchor-speed",
        Some(Input::StartPosition) => "--x0",
        Some(Input::StartSpeed) => "--v0",
        Some(Input::Push) => "--push",
        Some(Input::StaticFriction) if args.mu.is_none() => "--mu-s",
        Some(Input::DynamicFriction) if args.mu.is_none() => "--mu-d",
        Some(Input::StaticFriction | Input::DynamicFriction) => "--mu",
        _ => "--rtol",
    }
}

pub fn friction(args: &FrictionArgs) -> Result<Outcome> {
    let c = coefficients(
        args.mu.as_deref(),
        args.mu_s.as_deref(),
        args.mu_d.as_deref(),
    )?;
    let mass = quantity(&args.mass, "--mass", Dimension::MASS)?;
    let g = optional(args.g.as_deref(), "--g", Dimension::ACCELERATION, 9.81)?;
    let alpha = angle(args.angle.as_deref(), "--angle")?;
    let with_flag = |e: FrictionError| anyhow!("{}: {e}", flag(e.input(), args));
    let mut result = Incline::new(mass, alpha, c)
        .map_err(with_flag)?
        .with_gravity(g)
        .with_loads(
            optional(
                args.normal_load.as_deref(),
                "--normal-load",
                Dimension::FORCE,
                0.0,
            )?,
            optional(args.push.as_deref(), "--push", Dimension::FORCE, 0.0)?,
        )
        .report()
        .map_err(with_flag)?;
    let mut wrote = None;
    if let Some(k_text) = &args.spring_k {
        if alpha != 0.0 || args.normal_load.is_some() || args.push.is_some() {
            bail!(
                "--spring-k: the stick-slip model is a block on a flat surface; leave out --angle, --normal-load and --push"
            );
        }
        let Some(t_max) = &args.t_max else {
            bail!("--spring-k needs --t-max, how long to simulate (e.g. --t-max \"10 s\")");
        };
        let t_max = quantity(t_max, "--t-max", Dimension::TIME)?;
        let k = quantity(k_text, "--spring-k", Dimension::STIFFNESS)?;
        let opt = |t: &Option<String>, f: &str, d: Dimension| optional(t.as_deref(), f, d, 0.0);
        let block = SpringBlock::new(mass, k, c)
            .map_err(with_flag)?
            .with_gravity(g)
            .on_belt(opt(&args.belt_speed, "--belt-speed", Dimension::VELOCITY)?)
            .driven(opt(
                &args.anchor_speed,
                "--anchor-speed",
                Dimension::VELOCITY,
            )?)
            .starting_at(
                opt(&args.x0, "--x0", Dimension::LENGTH)?,
                opt(&args.v0, "--v0", Dimension::VELOCITY)?,
            );
        let mut run = match block.report(t_max, args.rtol) {
            Ok(run) => run,
            Err(FrictionError::Integrate(e)) if !e.is_step_budget() => {
                eprintln!("error: the simulation failed: {e}");
                return Ok(Outcome::ComputationFailed);
            }
            Err(e @ FrictionError::TooManyPhases { .. }) => {
                eprintln!("error: the simulation failed: {e}");
                return Ok(Outcome::ComputationFailed);
            }
            Err(e) => return Err(with_flag(e)),
        };
        if let Some(dir) = &args.out {
            create_dir(dir)?;
            let csv = write_table(dir, StickSlipReport::TABLE, &run.table())?;
            let plots = if args.no_plots {
                Vec::new()
            } else {
                write_plots(dir, &run.plots(), &title(&run), args.plots)?
            };
            wrote = Some(super::roll::written(&csv, &plots));
            run.files = Some(Files {
                csv: Some(csv),
                plots,
            });
        }
        result.stick_slip = Some(run);
    }
    report(args.report, &result, || {
        let mut text = incline_text(&result);
        if let Some(run) = &result.stick_slip {
            stick_slip_text(&mut text, run, args);
        }
        text
    })?;
    if let Some(w) = &wrote {
        note(args.report, w);
    }
    Ok(Outcome::Success)
}

fn incline_text(r: &FrictionReport) -> String {
    let incline: &Incline = &r.incline;
    let deg = r.angle_deg;
    let surface = if deg == 0.0 {
        "a flat surface".to_string()
    } else {
        format!("a {}° incline", sig(deg))
    };
    let mut out = format!(
        "block: m = {} kg on {surface}, g = {} m/s², μs = {}, μd = {}\n",
        sig(r.mass),
        sig(r.g),
        sig(r.mu_static),
        sig(r.mu_dynamic)
    );
    let extra = if incline.extra_normal == 0.0 {
        String::new()
    } else {
        format!(" + {} N", sig(incline.extra_normal))
    };
    let rows = [
        (
            format!("normal force N = m g cos α{extra}"),
            r.normal_force,
            "N",
        ),
        ("pull along the slope".to_string(), r.driving_force, "N"),
        (
            "max static friction μs N".to_string(),
            r.max_static_friction,
            "N",
        ),
        ("dynamic friction μd N".to_string(), r.dynamic_friction, "N"),
        (
            "marginal angle atan μs".to_string(),
            r.marginal_angle_deg,
            "°",
        ),
    ];
    for (what, value, unit) in rows {
        let _ = writeln!(out, "  {what:<34} {} {unit}", sig(value));
    }
    if r.slides {
        let _ = writeln!(
            out,
            "  released at rest: slides, |pull| > μs N; friction {} N, acceleration {} m/s² (down the slope positive)",
            sig(r.friction),
            sig(r.acceleration)
        );
    } else {
        let _ = writeln!(
            out,
            "  released at rest: stays, static friction {} N balances the pull (|pull| ≤ μs N; down the slope positive)",
            sig(r.friction)
        );
    }
    out
}

fn stick_slip_text(out: &mut String, r: &StickSlipReport, args: &FrictionArgs) {
    let _ = writeln!(
        out,
        "stick-slip: k = {} N/m, belt u = {} m/s, anchor w = {} m/s, x0 = {} m, v0 = {} m/s; Ω = √(k/m) = {} rad/s",
        sig(r.spring_k),
        sig(r.belt_speed),
        sig(r.anchor_speed),
        sig(r.x0),
        sig(r.v0),
        sig(r.omega)
    );
    let _ = writeln!(
        out,
        "  sticks while |k (x - w t)| ≤ μs N = {} N; slips with friction μd N = {} N against v - u",
        sig(r.stick_bound),
        sig(r.dynamic_friction)
    );
    let _ = writeln!(
        out,
        "  {:<4} {:<6} {:>14} {:>14} {:>14} {:>10} {:>14}",
        "#", "regime", "t start [s]", "t end [s]", "closed form", "diff", "slid [m]"
    );
    for (i, p) in r.phases.iter().enumerate().take(TABLE_ROWS) {
        let (closed, diff) = match (p.ended_by, p.t_end_closed_form) {
            ("switch", Some(t)) => (fixed(t, 9), format!("{:+.1e}", p.t_end - t)),
            ("t_max", _) => ("(t_max)".to_string(), String::new()),
            _ => ("-".to_string(), String::new()),
        };
        let slid = if p.regime == "stick" {
            String::new()
        } else {
            format!("{:.6e}", p.slip_distance)
        };
        let _ = writeln!(
            out,
            "  {:<4} {:<6} {:>14} {:>14} {closed:>14} {diff:>10} {slid:>14}",
            i + 1,
            p.regime,
            fixed(p.t_start, 9),
            fixed(p.t_end, 9)
        );
    }
    if r.phases.len() > TABLE_ROWS {
        let _ = writeln!(
            out,
            "  … {} more phases (all in --json and the CSV)",
            r.phases.len() - TABLE_ROWS
        );
    }
    let e = &r.energy;
    let _ = writeln!(
        out,
        "energy: K {} → {} J, spring {} → {} J, heat {} J, work of the belt {} J, of the anchor {} J, of friction on the block {} J",
        sig(e.kinetic.start),
        sig(e.kinetic.end),
        sig(e.spring.start),
        sig(e.spring.end),
        sig(e.heat),
        sig(e.work_belt),
        sig(e.work_anchor),
        sig(e.work_friction)
    );
    let _ = writeln!(
        out,
        "  K + U + heat - W_belt - W_anchor is constant to {:.1e} J",
        e.residual
    );
    let s = &r.simulation;
    let _ = writeln!(
        out,
        "simulation: dop853 at rtol {:e}: {} steps ({} rejected), {} evaluations; switches located inside the steps",
        args.rtol, s.steps, s.rejected, s.evaluations
    );
}

fn title(r: &StickSlipReport) -> String {
    let block = &r.block;
    format!(
        "stick-slip: m = {} kg, k = {} N/m, μs = {}, μd = {}, u = {} m/s, w = {} m/s",
        sig(block.mass),
        sig(block.k),
        sig(block.friction.mu_static),
        sig(block.friction.mu_dynamic),
        sig(block.belt_speed),
        sig(block.anchor_speed)
    )
}
