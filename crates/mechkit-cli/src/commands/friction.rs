//! `mechkit friction`: a block on a flat or inclined surface with Coulomb friction (normal
//! force, static bound, sliding friction, marginal angle, whether it slides and how fast), and
//! with `--spring-k` the stick-slip spring-block model: the phases with their closed-form
//! switch times, the energy ledger, `stick_slip.csv` and plots.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::figure::{Band, LineStyle, PlotData, Series};
use mechkit::ode::AdaptiveConfig;
use mechkit::rigid::friction::{
    Coulomb, FrictionError, Incline, InclineReport, PhaseEnd, Regime, SpringBlock, StickSlipRun,
};
use mechkit::scenario::{push_number, write_atomic};
use serde_json::{Value, json};

use super::input::{quantity, show};
use super::{Outcome, print};
use crate::args::FrictionArgs;
use crate::plot::render;

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
    let c = Coulomb::new(s, d).map_err(|e| match &e {
        FrictionError::Coefficient {
            which: "static", ..
        } => anyhow!("{}: {e}", flags.0),
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
        bail!(
            "{flag} `{text}` is {}°; it must be between -90° and 90° (a bare number is in radians: write \"{text} deg\" for degrees)",
            show(a.to_degrees())
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

/// The flag behind a friction error, for the message.
fn flag(e: &FrictionError) -> &'static str {
    match e {
        FrictionError::NotPositive { what, .. } if what.contains("mass") => "--mass",
        FrictionError::NotPositive { what, .. } if what.contains("spring") => "--spring-k",
        FrictionError::NotPositive { .. } => "--t-max",
        FrictionError::NoContact { .. } => "--normal-load",
        FrictionError::Angle { .. } => "--angle",
        FrictionError::Invalid { what, .. } if what.starts_with('g') => "--g",
        FrictionError::Invalid { what, .. } if what.contains("belt") => "--belt-speed",
        FrictionError::Invalid { what, .. } if what.contains("anchor") => "--anchor-speed",
        FrictionError::Invalid { what, .. } if what.contains("x0") => "--x0",
        FrictionError::Invalid { what, .. } if what.contains("v0") => "--v0",
        FrictionError::Invalid { .. } => "--push",
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
    let with_flag = |e: FrictionError| anyhow!("{}: {e}", flag(&e));
    let incline = Incline::new(mass, alpha, c)
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
        );
    let report = incline.at_rest().map_err(with_flag)?;
    let mut j = json!({
        "mass": mass, "g": g, "angle_deg": alpha.to_degrees(),
        "mu_static": c.mu_static, "mu_dynamic": c.mu_dynamic,
        "warnings": c.warning().map(|w| vec![w.to_string()]).unwrap_or_default(),
        "normal_force": report.normal, "driving_force": report.driving,
        "max_static_friction": report.max_static, "dynamic_friction": report.dynamic,
        "marginal_angle_deg": report.marginal_angle.to_degrees(),
        "slides": report.slides, "friction": report.friction,
        "acceleration": report.acceleration,
        "stick_slip": Value::Null,
    });
    let mut text = incline_text(&incline, &report);
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
        let config = AdaptiveConfig::from_rtol(args.rtol).sampled_over(t_max);
        config.validate(2).map_err(|e| anyhow!("--rtol: {e}"))?;
        let run = match block.simulate(t_max, &config) {
            Ok(run) => run,
            Err(e @ (FrictionError::Integrate(_) | FrictionError::TooManyPhases { .. })) => {
                eprintln!("error: the simulation failed: {e}");
                return Ok(Outcome::ComputationFailed);
            }
            Err(e) => return Err(with_flag(e)),
        };
        if let Some(dir) = &args.out {
            write_outputs(&block, &run, dir, args.plots)?;
        }
        j["stick_slip"] = stick_slip_json(&block, &run, args, &config);
        stick_slip_text(&mut text, &block, &run, args);
    }
    if args.json {
        print(&format!("{j:#}\n"))?;
    } else {
        print(&text)?;
    }
    Ok(Outcome::Success)
}

fn incline_text(incline: &Incline, r: &InclineReport) -> String {
    let c = incline.friction;
    let deg = incline.angle.to_degrees();
    let surface = if deg == 0.0 {
        "a flat surface".to_string()
    } else {
        format!("a {}° incline", sig(deg))
    };
    let mut out = format!(
        "block: m = {} kg on {surface}, g = {} m/s², μs = {}, μd = {}\n",
        sig(incline.mass),
        sig(incline.g),
        sig(c.mu_static),
        sig(c.mu_dynamic)
    );
    let extra = if incline.extra_normal == 0.0 {
        String::new()
    } else {
        format!(" + {} N", sig(incline.extra_normal))
    };
    let rows = [
        (format!("normal force N = m g cos α{extra}"), r.normal, "N"),
        ("pull along the slope".to_string(), r.driving, "N"),
        ("max static friction μs N".to_string(), r.max_static, "N"),
        ("dynamic friction μd N".to_string(), r.dynamic, "N"),
        (
            "marginal angle atan μs".to_string(),
            r.marginal_angle.to_degrees(),
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

/// The closed-form end of a phase, for comparison.
fn closed_end(block: &SpringBlock, p: &mechkit::rigid::friction::Phase) -> Option<f64> {
    match p.regime {
        Regime::Stick => block.exact_stick_end(p.start.0, p.start.1),
        Regime::Slip { direction } => block.exact_slip_end(p.start, direction),
    }
}

fn regime_name(r: Regime) -> &'static str {
    match r {
        Regime::Stick => "stick",
        Regime::Slip { direction } if direction > 0.0 => "slip+",
        Regime::Slip { .. } => "slip-",
    }
}

fn stick_slip_json(
    block: &SpringBlock,
    run: &StickSlipRun,
    args: &FrictionArgs,
    config: &AdaptiveConfig,
) -> Value {
    let phases: Vec<Value> = run
        .phases
        .iter()
        .map(|p| {
            let end = (p.ended == PhaseEnd::Switch).then_some(p.end.0);
            json!({
                "regime": regime_name(p.regime),
                "t_start": p.start.0, "t_end": p.end.0,
                "x_start": p.start.1, "x_end": p.end.1,
                "ended_by": if end.is_some() { "switch" } else { "t_max" },
                "t_end_closed_form": end.and(closed_end(block, p)),
                "slip_distance": p.slip_distance,
            })
        })
        .collect();
    let b = &run.balance;
    let spring = b.potential.as_ref().expect("the spring has a potential");
    let count = |f: fn(&Regime) -> bool| run.phases.iter().filter(|p| f(&p.regime)).count();
    json!({
        "spring_k": block.k, "belt_speed": block.belt_speed,
        "anchor_speed": block.anchor_speed, "x0": block.x0, "v0": block.v0,
        "omega": block.omega(), "stick_bound": block.stick_bound(),
        "dynamic_friction": block.friction.dynamic(block.normal()),
        "phases": phases,
        "stick_phases": count(|r| *r == Regime::Stick),
        "slip_phases": count(|r| *r != Regime::Stick),
        "energy": {
            "kinetic": {"start": b.kinetic.start, "end": b.kinetic.end},
            "spring": {"start": spring.start, "end": spring.end},
            "heat": run.heat(), "work_friction": run.work_friction(),
            "work_belt": run.work_belt(), "work_anchor": run.work_anchor(),
            "residual": b.residual(),
        },
        "simulation": {
            "method": "dop853", "rtol": config.rtol.as_scalar(),
            "atol": config.atol.as_scalar(), "h_max": config.h_max,
            "steps": run.stats.accepted, "rejected": run.stats.rejected,
            "evaluations": run.stats.evaluations, "samples": run.samples.len(),
        },
        "files": args.out.as_ref().map(|d| json!({
            "csv": d.join("stick_slip.csv").display().to_string(),
            "plots": (["x(t)", "v(t)", "forces(t)"].map(|p| d.join(args.plots.file(p)).display().to_string())),
        })),
    })
}

fn stick_slip_text(out: &mut String, block: &SpringBlock, run: &StickSlipRun, args: &FrictionArgs) {
    let _ = writeln!(
        out,
        "stick-slip: k = {} N/m, belt u = {} m/s, anchor w = {} m/s, x0 = {} m, v0 = {} m/s; Ω = √(k/m) = {} rad/s",
        sig(block.k),
        sig(block.belt_speed),
        sig(block.anchor_speed),
        sig(block.x0),
        sig(block.v0),
        sig(block.omega())
    );
    let _ = writeln!(
        out,
        "  sticks while |k (x - w t)| ≤ μs N = {} N; slips with friction μd N = {} N against v - u",
        sig(block.stick_bound()),
        sig(block.friction.dynamic(block.normal()))
    );
    let _ = writeln!(
        out,
        "  {:<4} {:<6} {:>14} {:>14} {:>14} {:>10} {:>14}",
        "#", "regime", "t start [s]", "t end [s]", "closed form", "diff", "slid [m]"
    );
    for (i, p) in run.phases.iter().enumerate().take(TABLE_ROWS) {
        let (closed, diff) = match (p.ended, closed_end(block, p)) {
            (PhaseEnd::Switch, Some(t)) => (format!("{t:.9}"), format!("{:+.1e}", p.end.0 - t)),
            (PhaseEnd::TimeLimit, _) => ("(t_max)".to_string(), String::new()),
            _ => ("-".to_string(), String::new()),
        };
        let slid = match p.regime {
            Regime::Stick => String::new(),
            Regime::Slip { .. } => format!("{:.6e}", p.slip_distance),
        };
        let _ = writeln!(
            out,
            "  {:<4} {:<6} {:>14.9} {:>14.9} {closed:>14} {diff:>10} {slid:>14}",
            i + 1,
            regime_name(p.regime),
            p.start.0,
            p.end.0
        );
    }
    if run.phases.len() > TABLE_ROWS {
        let _ = writeln!(
            out,
            "  … {} more phases (all in --json and the CSV)",
            run.phases.len() - TABLE_ROWS
        );
    }
    let b = &run.balance;
    let spring = b.potential.as_ref().expect("the spring has a potential");
    let _ = writeln!(
        out,
        "energy: K {} → {} J, spring {} → {} J, heat {} J, work of the belt {} J, of the anchor {} J, of friction on the block {} J",
        sig(b.kinetic.start),
        sig(b.kinetic.end),
        sig(spring.start),
        sig(spring.end),
        sig(run.heat()),
        sig(run.work_belt()),
        sig(run.work_anchor()),
        sig(run.work_friction())
    );
    let _ = writeln!(
        out,
        "  K + U + heat - W_belt - W_anchor is constant to {:.1e} J",
        b.residual()
    );
    let s = run.stats;
    let _ = writeln!(
        out,
        "simulation: dop853 at rtol {:e}: {} steps ({} rejected), {} evaluations; switches located inside the steps",
        args.rtol, s.accepted, s.rejected, s.evaluations
    );
    if let Some(d) = &args.out {
        let _ = writeln!(
            out,
            "files: {}/stick_slip.csv, {}",
            d.display(),
            ["x(t)", "v(t)", "forces(t)"]
                .map(|p| args.plots.file(p))
                .join(", ")
        );
    }
}

fn write_outputs(
    block: &SpringBlock,
    run: &StickSlipRun,
    dir: &Path,
    format: crate::args::PlotFormat,
) -> Result<()> {
    std::fs::create_dir_all(dir)
        .map_err(|e| anyhow!("--out: cannot create {}: {e}", dir.display()))?;
    let mut csv =
        String::from("t,x,v,anchor,spring_force,friction,stuck,heat,work_belt,work_anchor\n");
    for s in &run.samples {
        for (i, v) in [s.t, s.x, s.v, block.anchor(s.t), s.spring_force, s.friction]
            .into_iter()
            .enumerate()
        {
            if i > 0 {
                csv.push(',');
            }
            push_number(&mut csv, v);
        }
        csv.push_str(if s.stuck { ",1" } else { ",0" });
        for v in [s.heat, s.work_belt, s.work_anchor] {
            csv.push(',');
            push_number(&mut csv, v);
        }
        csv.push('\n');
    }
    let path = dir.join("stick_slip.csv");
    write_atomic(&path, csv.as_bytes())
        .map_err(|e| anyhow!("cannot write {}: {e}", path.display()))?;
    let bands: Vec<Band> = run
        .phases
        .iter()
        .filter(|p| p.regime == Regime::Stick)
        .map(|p| Band {
            from: p.start.0,
            to: p.end.0,
            label: "stick".to_string(),
        })
        .collect();
    let curve = |f: &dyn Fn(&mechkit::rigid::friction::StickSlipSample) -> f64| -> Vec<(f64, f64)> {
        run.samples.iter().map(|s| (s.t, f(s))).collect()
    };
    let t_end = run.samples.last().map_or(0.0, |s| s.t);
    let flat = |y: f64| vec![(0.0, y), (t_end, y)];
    let bound = block.stick_bound();
    let plots = [
        PlotData::new("x(t)", "x(t)", "t [s]", "x [m]")
            .with_series(Series::line("block", curve(&|s| s.x)))
            .with_series(
                Series::line("anchor", curve(&|s| block.anchor(s.t))).styled(LineStyle::Dashed),
            ),
        PlotData::new("v(t)", "v(t)", "t [s]", "v [m/s]")
            .with_series(Series::line("block", curve(&|s| s.v)))
            .with_series(Series::line("belt", flat(block.belt_speed)).styled(LineStyle::Dashed)),
        PlotData::new("forces(t)", "forces(t)", "t [s]", "F [N]")
            .with_series(Series::line("spring", curve(&|s| s.spring_force)))
            .with_series(Series::line("friction", curve(&|s| s.friction)))
            .with_series(Series::line("±μs N", flat(bound)).styled(LineStyle::Dashed))
            .with_series(Series::line("±μs N", flat(-bound)).styled(LineStyle::Dashed)),
    ];
    let title = format!(
        "stick-slip: m = {} kg, k = {} N/m, μs = {}, μd = {}, u = {} m/s, w = {} m/s",
        sig(block.mass),
        sig(block.k),
        sig(block.friction.mu_static),
        sig(block.friction.mu_dynamic),
        sig(block.belt_speed),
        sig(block.anchor_speed)
    );
    for mut plot in plots {
        plot.bands.clone_from(&bands);
        let path = dir.join(format.file(&plot.file_stem));
        render(&plot, &title, &path, format.dpi)?;
    }
    Ok(())
}
