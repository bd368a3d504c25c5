//! `mechkit roll`: a sphere, cylinder or hoop launched on a slope (or a flat floor) with
//! speed and spin, through `RollingMotion::report`: the slipping and the rolling phase each
//! with its accelerations, when rolling starts (simulated and closed form side by side), the
//! regimes, the energy ledger; `roll.csv` and plots with `-o`.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::report::Files;
use mechkit::rigid::Input;
use mechkit::rigid::rolling::{PhaseMotion, RollReport, RollingBody, RollingError, RollingMotion};

use super::friction::{angle, coefficients, sig};
use super::input::{fixed, quantity};
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::RollArgs;

/// The flag of an input of `mechkit roll`.
fn flag(input: Option<Input>, args: &RollArgs) -> &'static str {
    match input {
        Some(Input::Radius) => "--radius",
        Some(Input::Mass) => "--mass",
        Some(Input::Body) => "--body",
        Some(Input::Angle) => "--slope",
        Some(Input::Gravity) => "--g",
        Some(Input::StartSpeed | Input::StartPosition) => "--v0",
        Some(Input::StartSpin) => "--omega0",
        Some(Input::Duration) => "--t-max",
        Some(Input::StaticFriction) if args.mu.is_none() => "--mu-s",
        Some(Input::DynamicFriction) if args.mu.is_none() => "--mu-d",
        Some(Input::StaticFriction | Input::DynamicFriction) => "--mu",
        _ => "--rtol",
    }
}

fn build(args: &RollArgs) -> Result<(RollingMotion, f64)> {
    let with_flag = |e: RollingError| anyhow!("{}: {e}", flag(e.input(), args));
    let mass = quantity(&args.mass, "--mass", Dimension::MASS)?;
    let Some(radius) = &args.radius else {
        bail!(
            "--radius is needed: rolling without slipping ties v = ω R to the radius of the body's contact circle (e.g. --radius \"11 cm\")"
        );
    };
    let radius = quantity(radius, "--radius", Dimension::LENGTH)?;
    let k = match RollingBody::preset_factor(&args.body) {
        Some(k) => k,
        None => quantity(&args.body, "--body", Dimension::NONE).map_err(|_| {
            anyhow!(
                "--body `{}` is not a body; use sphere, hollow-sphere, cylinder, hoop, or the factor k = I/(m R²) as a number (0.4 for a solid sphere)",
                args.body
            )
        })?,
    };
    let body = RollingBody::new(mass, radius, k).map_err(with_flag)?;
    if args.mu.is_none() && args.mu_s.is_none() {
        bail!("give the friction coefficient: --mu for both, or --mu-s and --mu-d");
    }
    let friction = coefficients(
        args.mu.as_deref(),
        args.mu_s.as_deref(),
        args.mu_d.as_deref(),
    )?;
    let slope = angle(args.slope.as_deref(), "--slope")?;
    let opt = |t: &Option<String>, f: &str, d: Dimension, default: f64| {
        t.as_deref().map_or(Ok(default), |t| quantity(t, f, d))
    };
    let motion = RollingMotion::new(body, slope, friction)
        .with_gravity(opt(&args.g, "--g", Dimension::ACCELERATION, 9.81)?)
        .launched(
            opt(&args.v0, "--v0", Dimension::VELOCITY, 0.0)?,
            opt(&args.omega0, "--omega0", Dimension::FREQUENCY, 0.0)?,
        );
    motion.validate().map_err(with_flag)?;
    let t_max = quantity(&args.t_max, "--t-max", Dimension::TIME)?;
    Ok((motion, t_max))
}

pub fn roll(args: &RollArgs) -> Result<Outcome> {
    let (motion, t_max) = build(args)?;
    let mut result = match motion.report(t_max, args.rtol) {
        Ok(r) => r,
        Err(RollingError::Integrate(e)) if !e.is_step_budget() => {
            eprintln!("error: the simulation failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => bail!("{}: {e}", flag(e.input(), args)),
    };
    let mut wrote = None;
    if let Some(dir) = &args.out {
        create_dir(dir)?;
        let csv = write_table(dir, RollReport::TABLE, &result.table())?;
        let plots = if args.no_plots {
            Vec::new()
        } else {
            write_plots(dir, &result.plots(), &title(&result), args.plots)?
        };
        wrote = Some(written(&csv, &plots));
        result.files = Some(Files {
            csv: Some(csv),
            plots,
        });
    }
    report(args.report, &result, || text(&result, args))?;
    if let Some(w) = &wrote {
        note(args.report, w);
    }
    Ok(Outcome::Success)
}

/// `wrote DIR/roll.csv, v_t.svg, energy_t.svg`.
pub(super) fn written(csv: &str, plots: &[String]) -> String {
    let mut line = format!("wrote {csv}");
    for p in plots {
        let name = std::path::Path::new(p)
            .file_name()
            .map_or_else(|| p.clone(), |n| n.to_string_lossy().into_owned());
        let _ = write!(line, ", {name}");
    }
    line
}

fn title(r: &RollReport) -> String {
    format!(
        "rolling: k = {}, R = {} m, slope {}°, μs = {}, μd = {}, v0 = {} m/s, ω0 = {} rad/s",
        sig(r.body.k),
        sig(r.body.radius),
        sig(r.slope_deg),
        sig(r.mu_static),
        sig(r.mu_dynamic),
        sig(r.v0),
        sig(r.omega0)
    )
}

/// The slipping phase from the launch, with its formulas.
fn slipping_text(out: &mut String, s: &PhaseMotion) {
    let forward = s.regime == "slipping forward";
    let (sign, opposite) = if forward { ("−", "") } else { ("+", "−") };
    let _ = writeln!(
        out,
        "{} from the launch: friction {} N ({sign}μd N along the slope), a = g sin α {sign} μd g cos α = {} m/s², α = {opposite}μd N R/I = {} rad/s²",
        s.regime,
        sig(s.friction),
        sig(s.acceleration),
        sig(s.angular_acceleration)
    );
}

fn text(r: &RollReport, args: &RollArgs) -> String {
    let b = &r.body;
    let mut out = format!(
        "body: k = I/(m R²) = {}, m = {} kg, R = {} m, I = {} kg m²\n",
        sig(b.k),
        sig(b.mass),
        sig(b.radius),
        sig(b.moment_of_inertia)
    );
    let _ = writeln!(
        out,
        "slope: {}°, g = {} m/s², μs = {}, μd = {}; N = m g cos α = {} N",
        sig(r.slope_deg),
        sig(r.g),
        sig(r.mu_static),
        sig(r.mu_dynamic),
        sig(r.normal_force)
    );
    let _ = writeln!(
        out,
        "launch: v0 = {} m/s, ω0 = {} rad/s, slip velocity v0 - ω0 R = {} m/s (x and ω positive down the slope)",
        sig(r.v0),
        sig(r.omega0),
        sig(r.slip_velocity0)
    );
    if let Some(s) = &r.slipping {
        slipping_text(&mut out, s);
    }
    let needed = -r.motion.rolling_friction();
    let bound = r.motion.friction.max_static(r.normal_force);
    match &r.rolling {
        Some(roll) => {
            let _ = writeln!(
                out,
                "rolling needs friction m g sin α k/(1+k) = {} N ≤ μs N = {} N: it can roll, with a = g sin α/(1+k) = {} m/s² and α = a/R = {} rad/s²",
                sig(needed),
                sig(bound),
                sig(roll.acceleration),
                sig(roll.angular_acceleration)
            );
        }
        None => {
            let _ = writeln!(
                out,
                "rolling would need friction {} N > μs N = {} N: too steep to roll (steepest {}°)",
                sig(needed),
                sig(bound),
                sig(r.steepest_rolling_angle_deg)
            );
        }
    }
    let start = &r.roll_start;
    let t_end = r.run.samples.last().map_or(0.0, |s| s.t);
    match (start.t.simulated, start.t.closed_form) {
        (Some(t), Some(tc)) => {
            let (v, vc) = (
                start.v.simulated.unwrap_or(f64::NAN),
                start.v.closed_form.unwrap_or(f64::NAN),
            );
            let _ = writeln!(
                out,
                "rolling starts      {:<22} {:<22} difference",
                "simulated", "closed form"
            );
            let _ = writeln!(
                out,
                "  time [s]          {:<22} {:<22} {:+.1e}",
                fixed(t, 15),
                fixed(tc, 15),
                t - tc
            );
            let _ = writeln!(
                out,
                "  speed [m/s]       {:<22} {:<22} {:+.1e}",
                fixed(v, 15),
                fixed(vc, 15),
                v - vc
            );
        }
        (Some(t), None) => {
            let _ = writeln!(
                out,
                "rolling starts at t = {} s with v = {} m/s",
                sig(t),
                sig(start.v.simulated.unwrap_or(f64::NAN))
            );
        }
        (None, Some(tc)) if tc > t_end => {
            let _ = writeln!(
                out,
                "rolling would start at t = {} s, after --t-max",
                sig(tc)
            );
        }
        _ => out.push_str("it never rolls\n"),
    }
    if let Some(f) = r.rolling_friction.simulated {
        let _ = writeln!(
            out,
            "friction while rolling: {} N (closed form -m g sin α k/(1+k) = {} N)",
            sig(f),
            sig(-needed)
        );
    }
    if let Some(v) = r.flat_floor_rolling_speed {
        let _ = writeln!(
            out,
            "flat floor: angular momentum about the contact point conserved, rolling speed (v0 + k R ω0)/(1+k) = {} m/s",
            sig(v)
        );
    }
    out.push_str("regimes:\n");
    for p in &r.phases {
        let _ = writeln!(
            out,
            "  {:<18} t = {} → {} s{}, a = {} m/s², α = {} rad/s²",
            p.regime,
            sig(p.t_start),
            sig(p.t_end),
            if p.ended_by == "switch" {
                ""
            } else {
                " (t_max)"
            },
            sig(p.acceleration),
            sig(p.angular_acceleration)
        );
    }
    let e = &r.energy;
    let _ = writeln!(
        out,
        "energy: K_trans {} → {} J, K_rot {} → {} J, U {} → {} J, work of friction {} J",
        sig(e.translational.start),
        sig(e.translational.end),
        sig(e.rotational.start),
        sig(e.rotational.end),
        sig(e.potential.start),
        sig(e.potential.end),
        sig(e.work_friction.unwrap_or(f64::NAN))
    );
    let _ = writeln!(
        out,
        "  K + U - W_friction is constant to {:.1e} J",
        e.residual
    );
    let s = &r.simulation;
    let _ = writeln!(
        out,
        "simulation: dop853 at rtol {:e}: {} steps ({} rejected), {} evaluations; the start of rolling located inside its step",
        args.rtol, s.steps, s.rejected, s.evaluations
    );
    out
}
