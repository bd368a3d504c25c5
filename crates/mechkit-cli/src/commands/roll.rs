//! `mechkit roll`: a sphere, cylinder or hoop launched on a slope (or a flat floor) with
//! speed and spin: when slipping turns into rolling, simulated and in closed form side by
//! side, the regimes, the friction while rolling, the energy ledger, `roll.csv` and plots.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::energy::{EnergyBalance, EnergyPart, EnergyTerm};
use mechkit::expr::units::Dimension;
use mechkit::figure::{Band, LineStyle, PlotData, Series};
use mechkit::ode::AdaptiveConfig;
use mechkit::rigid::rolling::{Contact, RollingBody, RollingError, RollingMotion, RollingRun};
use mechkit::scenario::{push_number, write_atomic};
use serde_json::{Value, json};

use super::friction::{angle, coefficients, sig};
use super::input::quantity;
use super::{Outcome, print};
use crate::args::RollArgs;
use crate::plot::render;

/// The flag behind a rolling error, for the message.
fn flag(e: &RollingError) -> &'static str {
    match e {
        RollingError::NoRadius { .. } => "--radius",
        RollingError::Mass { .. } => "--mass",
        RollingError::InertiaFactor { .. }
        | RollingError::UnknownBody { .. }
        | RollingError::ShapeCannotRoll { .. } => "--body",
        RollingError::Angle { .. } => "--slope",
        RollingError::Gravity { .. } => "--g",
        RollingError::Invalid { what, .. } if what.contains("v0") => "--v0",
        RollingError::Invalid { what, .. } if what.contains("ω0") => "--omega0",
        RollingError::Invalid { .. } => "--t-max",
        RollingError::Friction(_) => "--mu",
        _ => "--rtol",
    }
}

fn build(args: &RollArgs) -> Result<(RollingMotion, f64)> {
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
    let with_flag = |e: RollingError| anyhow!("{}: {e}", flag(&e));
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
    if !(t_max.is_finite() && t_max > 0.0) {
        bail!("--t-max `{}` must be a positive time", args.t_max);
    }
    Ok((motion, t_max))
}

pub fn roll(args: &RollArgs) -> Result<Outcome> {
    let (motion, t_max) = build(args)?;
    let config = AdaptiveConfig::from_rtol(args.rtol).sampled_over(t_max);
    config.validate(4).map_err(|e| anyhow!("--rtol: {e}"))?;
    let run = match motion.simulate(t_max, &config) {
        Ok(run) => run,
        Err(RollingError::Integrate(e)) => {
            eprintln!("error: the simulation failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => bail!("{}: {e}", flag(&e)),
    };
    if let Some(dir) = &args.out {
        write_outputs(&motion, &run, dir, args.plots)?;
    }
    if args.json {
        print(&format!("{:#}\n", to_json(&motion, &run, args, &config)))?;
    } else {
        print(&text(&motion, &run, args))?;
    }
    Ok(Outcome::Success)
}

/// The translational and rotational parts of `K`, and `U`, of a rolling run's balance.
fn energy_parts(b: &EnergyBalance) -> (&EnergyPart, &EnergyPart, &EnergyTerm) {
    let part = |name| b.kinetic.part(name).expect("rolling splits K");
    let u = b.potential.as_ref().expect("gravity has a potential");
    (part("translational"), part("rotational"), u)
}

fn contact_name(c: Contact) -> &'static str {
    match c {
        Contact::Rolling => "rolling",
        Contact::Slipping { direction } if direction > 0.0 => "slipping forward",
        Contact::Slipping { .. } => "slipping backward",
    }
}

fn compare(closed: Option<f64>, simulated: Option<f64>) -> Value {
    json!({
        "closed_form": closed, "simulated": simulated,
        "difference": closed.zip(simulated).map(|(c, s)| s - c),
    })
}

fn to_json(m: &RollingMotion, run: &RollingRun, args: &RollArgs, config: &AdaptiveConfig) -> Value {
    let b = &m.body;
    let closed = m.roll_start();
    let sim = run.roll_start;
    let balance = &run.balance;
    let (kt, kr, u) = energy_parts(balance);
    let flat = m.angle == 0.0;
    json!({
        "body": {"k": b.k, "mass": b.mass, "radius": b.radius, "moment_of_inertia": b.moment_of_inertia()},
        "slope_deg": m.angle.to_degrees(), "g": m.g,
        "mu_static": m.friction.mu_static, "mu_dynamic": m.friction.mu_dynamic,
        "warnings": m.friction.warning().map(|w| vec![w.to_string()]).unwrap_or_default(),
        "v0": m.v0, "omega0": m.omega0,
        "slip_velocity0": m.slip_velocity(m.v0, m.omega0),
        "normal_force": m.normal(),
        "can_roll": m.can_roll(),
        "steepest_rolling_angle_deg": m.steepest_rolling_angle().to_degrees(),
        "rolling_acceleration": m.rolling_acceleration(),
        "roll_start": {
            "t": compare(closed.map(|c| c.0), sim.map(|s| s.0)),
            "v": compare(closed.map(|c| c.1), sim.map(|s| s.2)),
            "omega": sim.map(|s| s.3),
            "x": sim.map(|s| s.1),
        },
        "rolling_friction": compare(m.can_roll().then(|| m.rolling_friction()), run.rolling_friction),
        "flat_floor_rolling_speed": flat.then(|| m.flat_floor_rolling_speed()),
        "phases": run.phases.iter().map(|p| json!({
            "regime": contact_name(p.contact),
            "t_start": p.start.0, "t_end": p.end.0,
            "v_end": p.end.2, "omega_end": p.end.3,
            "ended_by": if p.switched { "switch" } else { "t_max" },
        })).collect::<Vec<_>>(),
        "energy": {
            "translational": {"start": kt.start, "end": kt.end},
            "rotational": {"start": kr.start, "end": kr.end},
            "potential": {"start": u.start, "end": u.end},
            "work_friction": balance.work_of("friction"), "residual": balance.residual(),
        },
        "simulation": {
            "method": "dop853", "rtol": config.rtol.as_scalar(),
            "atol": config.atol.as_scalar(), "h_max": config.h_max,
            "steps": run.stats.accepted, "rejected": run.stats.rejected,
            "evaluations": run.stats.evaluations, "samples": run.samples.len(),
        },
        "files": args.out.as_ref().map(|d| json!({
            "csv": d.join("roll.csv").display().to_string(),
            "plots": (["v(t)", "energy(t)"].map(|p| d.join(args.plots.file(p)).display().to_string())),
        })),
    })
}

fn text(m: &RollingMotion, run: &RollingRun, args: &RollArgs) -> String {
    let b = &m.body;
    let mut out = format!(
        "body: k = I/(m R²) = {}, m = {} kg, R = {} m, I = {} kg m²\n",
        sig(b.k),
        sig(b.mass),
        sig(b.radius),
        sig(b.moment_of_inertia())
    );
    let _ = writeln!(
        out,
        "slope: {}°, g = {} m/s², μs = {}, μd = {}; N = m g cos α = {} N",
        sig(m.angle.to_degrees()),
        sig(m.g),
        sig(m.friction.mu_static),
        sig(m.friction.mu_dynamic),
        sig(m.normal())
    );
    let _ = writeln!(
        out,
        "launch: v0 = {} m/s, ω0 = {} rad/s, slip velocity v0 - ω0 R = {} m/s (x and ω positive down the slope)",
        sig(m.v0),
        sig(m.omega0),
        sig(m.slip_velocity(m.v0, m.omega0))
    );
    if m.can_roll() {
        let _ = writeln!(
            out,
            "rolling needs friction m g sin α k/(1+k) = {} N ≤ μs N = {} N: it can roll (a = g sin α/(1+k) = {} m/s²)",
            sig(-m.rolling_friction()),
            sig(m.friction.max_static(m.normal())),
            sig(m.rolling_acceleration())
        );
    } else {
        let _ = writeln!(
            out,
            "rolling would need friction {} N > μs N = {} N: too steep to roll (steepest {}°)",
            sig(-m.rolling_friction()),
            sig(m.friction.max_static(m.normal())),
            sig(m.steepest_rolling_angle().to_degrees())
        );
    }
    match (run.roll_start, m.roll_start()) {
        (Some((t, _, v, _)), Some((tc, vc))) => {
            let _ = writeln!(
                out,
                "rolling starts      {:<22} {:<22} difference",
                "simulated", "closed form"
            );
            let _ = writeln!(
                out,
                "  time [s]          {t:<22.15} {tc:<22.15} {:+.1e}",
                t - tc
            );
            let _ = writeln!(
                out,
                "  speed [m/s]       {v:<22.15} {vc:<22.15} {:+.1e}",
                v - vc
            );
        }
        (Some((t, _, v, _)), None) => {
            let _ = writeln!(
                out,
                "rolling starts at t = {} s with v = {} m/s",
                sig(t),
                sig(v)
            );
        }
        (None, Some((tc, _))) if tc > run.samples.last().map_or(0.0, |s| s.t) => {
            let _ = writeln!(
                out,
                "rolling would start at t = {} s, after --t-max",
                sig(tc)
            );
        }
        _ => out.push_str("it never rolls\n"),
    }
    if let Some(f) = run.rolling_friction {
        let _ = writeln!(
            out,
            "friction while rolling: {} N (closed form -m g sin α k/(1+k) = {} N)",
            sig(f),
            sig(m.rolling_friction())
        );
    }
    if m.angle == 0.0 {
        let _ = writeln!(
            out,
            "flat floor: angular momentum about the contact point conserved, rolling speed (v0 + k R ω0)/(1+k) = {} m/s",
            sig(m.flat_floor_rolling_speed())
        );
    }
    out.push_str("regimes:\n");
    for p in &run.phases {
        let _ = writeln!(
            out,
            "  {:<18} t = {} → {} s{}",
            contact_name(p.contact),
            sig(p.start.0),
            sig(p.end.0),
            if p.switched { "" } else { " (t_max)" }
        );
    }
    let balance = &run.balance;
    let (kt, kr, u) = energy_parts(balance);
    let _ = writeln!(
        out,
        "energy: K_trans {} → {} J, K_rot {} → {} J, U {} → {} J, work of friction {} J",
        sig(kt.start),
        sig(kt.end),
        sig(kr.start),
        sig(kr.end),
        sig(u.start),
        sig(u.end),
        sig(balance.work_of("friction").expect("rolling books friction"))
    );
    let _ = writeln!(
        out,
        "  K + U - W_friction is constant to {:.1e} J",
        balance.residual()
    );
    let s = run.stats;
    let _ = writeln!(
        out,
        "simulation: dop853 at rtol {:e}: {} steps ({} rejected), {} evaluations; the start of rolling located inside its step",
        args.rtol, s.accepted, s.rejected, s.evaluations
    );
    if let Some(d) = &args.out {
        let _ = writeln!(
            out,
            "files: {}/roll.csv, {}",
            d.display(),
            ["v(t)", "energy(t)"].map(|p| args.plots.file(p)).join(", ")
        );
    }
    out
}

fn write_outputs(
    m: &RollingMotion,
    run: &RollingRun,
    dir: &Path,
    format: crate::args::PlotFormat,
) -> Result<()> {
    std::fs::create_dir_all(dir)
        .map_err(|e| anyhow!("--out: cannot create {}: {e}", dir.display()))?;
    let r = m.body.radius;
    let energies = |s: &mechkit::rigid::rolling::RollSample| {
        let (kt, kr) = m.kinetic(s.v, s.omega);
        (kt, kr, m.potential(s.x))
    };
    let mut csv = String::from(
        "t,x,v,theta,omega,omega_R,slip_velocity,friction,rolling,work_friction,K_trans,K_rot,U\n",
    );
    for s in &run.samples {
        let (kt, kr, u) = energies(s);
        let row = [
            s.t,
            s.x,
            s.v,
            s.theta,
            s.omega,
            s.omega * r,
            s.slip_velocity,
            s.friction,
            if s.rolling { 1.0 } else { 0.0 },
            s.work_friction,
            kt,
            kr,
            u,
        ];
        for (i, v) in row.into_iter().enumerate() {
            if i > 0 {
                csv.push(',');
            }
            push_number(&mut csv, v);
        }
        csv.push('\n');
    }
    let path = dir.join("roll.csv");
    write_atomic(&path, csv.as_bytes())
        .map_err(|e| anyhow!("cannot write {}: {e}", path.display()))?;
    let bands: Vec<Band> = run
        .phases
        .iter()
        .filter(|p| p.contact == Contact::Rolling)
        .map(|p| Band {
            from: p.start.0,
            to: p.end.0,
            label: "rolling".to_string(),
        })
        .collect();
    let curve = |f: &dyn Fn(&mechkit::rigid::rolling::RollSample) -> f64| -> Vec<(f64, f64)> {
        run.samples.iter().map(|s| (s.t, f(s))).collect()
    };
    let e0 = run.balance.energy().0;
    let plots = [
        PlotData::new("v and ωR", "v(t)", "t [s]", "[m/s]")
            .with_series(Series::line("v", curve(&|s| s.v)))
            .with_series(Series::line("ω R", curve(&|s| s.omega * r)).styled(LineStyle::Dashed)),
        PlotData::new("energy", "energy(t)", "t [s]", "E [J]")
            .with_series(Series::line("K_trans", curve(&|s| energies(s).0)))
            .with_series(Series::line("K_rot", curve(&|s| energies(s).1)))
            .with_series(Series::line("U", curve(&|s| energies(s).2)))
            .with_series(Series::line(
                "K + U",
                curve(&|s| {
                    let (kt, kr, u) = energies(s);
                    kt + kr + u
                }),
            ))
            .with_series(
                Series::line("E0 + W_friction", curve(&|s| e0 + s.work_friction))
                    .styled(LineStyle::Dashed),
            ),
    ];
    let title = format!(
        "rolling: k = {}, R = {} m, slope {}°, μs = {}, μd = {}, v0 = {} m/s, ω0 = {} rad/s",
        sig(m.body.k),
        sig(r),
        sig(m.angle.to_degrees()),
        sig(m.friction.mu_static),
        sig(m.friction.mu_dynamic),
        sig(m.v0),
        sig(m.omega0)
    );
    for mut plot in plots {
        plot.bands.clone_from(&bands);
        let path = dir.join(format.file(&plot.file_stem));
        render(&plot, &title, &path, format.dpi)?;
    }
    Ok(())
}
