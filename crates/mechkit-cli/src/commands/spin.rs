//! `mechkit spin`: a free rigid body in 3-D or a heavy top. The run's conservation of |L| and
//! E, the flip period of ω about the intermediate axis against the elliptic-function period,
//! the top's nutation and precession; spin.csv and plots of ω(t) (and θ(t), φ(t)).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::figure::{LineStyle, PlotData, Series};
use mechkit::mass::{Mat3, Vec3};
use mechkit::ode::{AdaptiveConfig, Tableau};
use mechkit::rigid::free3d::{
    Formulation, Free3dError, FreeBody, Orientation, Poinsot, SpinIntegrator, SpinOptions, SpinRun,
    SpinningBody,
};
use mechkit::scenario::{push_number, write_atomic};
use serde_json::{Value, json};

use super::body::{load, point, vec_json};
use super::input::{quantity, show, split_top_level};
use super::{Outcome, print};
use crate::args::SpinArgs;
use crate::plot::render;

/// "a, b, c": exactly three quantities of dimension `dim` (plain numbers are SI).
fn triple(text: &str, flag: &str, dim: Dimension) -> Result<Vec3> {
    let items = split_top_level(text, ',');
    if items.len() != 3 {
        bail!(
            "{flag} `{text}` needs 3 comma-separated components, e.g. {flag} \"1, 2, 3\"; it has {}",
            items.len()
        );
    }
    let mut v = Vec3::zeros();
    for (k, c) in items.iter().enumerate() {
        v[k] = quantity(c, flag, dim)?;
        if !v[k].is_finite() {
            bail!("{flag}: `{c}` is not a finite number");
        }
    }
    Ok(v)
}

/// The flag behind a library error.
fn flag(e: &Free3dError, args: &SpinArgs) -> String {
    match e {
        Free3dError::Moment { .. } | Free3dError::Triangle { .. } => args
            .file
            .as_ref()
            .map_or_else(|| "--moments".to_string(), |f| f.display().to_string()),
        Free3dError::Mass { .. } => "--mass".into(),
        Free3dError::Gravity { .. } => "--g".into(),
        Free3dError::NonFinite { .. } => "--omega".into(),
        Free3dError::Duration { .. } => "--t-max".into(),
        Free3dError::Step { .. } | Free3dError::TooManySteps { .. } => "--dt".into(),
        Free3dError::SplittingOffAxis { .. } => "--method".into(),
        _ => "--rtol".into(),
    }
}

/// The body (principal frame), the rotation from the principal frame to the body's
/// coordinates, and the centre of mass in those coordinates.
fn body(args: &SpinArgs) -> Result<(FreeBody, Orientation, Vec3)> {
    let with_flag = |e: Free3dError| anyhow!("{}: {e}", flag(&e, args));
    if let Some(file) = &args.file {
        let loaded = load(file, args.mass.as_deref())?;
        let (body, axes) = FreeBody::from_mass_properties(&loaded.whole).map_err(with_flag)?;
        return Ok((body, axes, loaded.whole.centre_of_mass));
    }
    let Some(moments) = &args.moments else {
        bail!("give the body: a body file, or --moments \"I1, I2, I3\" (kg*m^2)");
    };
    let i = triple(moments, "--moments", Dimension::MOMENT_OF_INERTIA)?;
    let mass = args
        .mass
        .as_deref()
        .map_or(Ok(1.0), |m| quantity(m, "--mass", Dimension::MASS))?;
    let body = FreeBody::new(i.into(), mass).map_err(with_flag)?;
    Ok((body, Orientation::identity(), Vec3::zeros()))
}

fn integrator(args: &SpinArgs) -> Result<SpinIntegrator> {
    let dt = || -> Result<f64> {
        let Some(dt) = &args.dt else {
            bail!(
                "--method {} takes a fixed step: give --dt, e.g. --dt \"1 ms\"",
                args.method
            );
        };
        quantity(dt, "--dt", Dimension::TIME)
    };
    Ok(match args.method.as_str() {
        "dop853" | "dopri5" => {
            // no step limit: the samples are taken on their own grid by the interpolant
            let config = AdaptiveConfig::from_rtol(args.rtol);
            config.validate(7).map_err(|e| anyhow!("--rtol: {e}"))?;
            let tableau = Tableau::by_name(&args.method).expect("a known pair");
            SpinIntegrator::Adaptive { tableau, config }
        }
        "rk4" => SpinIntegrator::Fixed {
            tableau: Tableau::rk4(),
            dt: dt()?,
        },
        "splitting" => SpinIntegrator::Splitting { dt: dt()? },
        other => bail!("--method `{other}` is not one of dop853, dopri5, rk4, splitting"),
    })
}

pub fn spin(args: &SpinArgs) -> Result<Outcome> {
    let (free, axes, cm) = body(args)?;
    let with_flag = |e: Free3dError| anyhow!("{}: {e}", flag(&e, args));
    let omega = triple(&args.omega, "--omega", Dimension::FREQUENCY).map_err(|e| {
        anyhow!(
            "{}",
            e.to_string().replace("is taken in Hz", "is taken in rad/s")
        )
    })?;
    let omega = axes.inverse_transform_vector(&omega);
    let t_max = quantity(&args.t_max, "--t-max", Dimension::TIME)?;
    if !(t_max > 0.0 && t_max.is_finite()) {
        bail!("--t-max must be a positive duration, e.g. --t-max \"100 s\"");
    }
    let tilt = args
        .tilt
        .as_deref()
        .map_or(Ok(0.0), |t| quantity(t, "--tilt", Dimension::NONE))?;
    let spinning = if args.top {
        let pivot = point(
            args.pivot.as_deref().unwrap_or_default(),
            "--pivot",
            Dimension::LENGTH,
        )?;
        let g = args
            .g
            .as_deref()
            .map_or(Ok(9.81), |g| quantity(g, "--g", Dimension::ACCELERATION))?;
        SpinningBody::on_pivot(free, axes.inverse_transform_vector(&(cm - pivot)), g)
            .map_err(with_flag)?
    } else {
        if omega.norm() == 0.0 {
            bail!(
                "--omega is zero: a free body at rest stays at rest; give a non-zero angular velocity, e.g. --omega \"0.01, 1, 0.01\""
            );
        }
        SpinningBody::free(free)
    };
    let tilt_q = Orientation::from_scaled_axis(Vec3::new(tilt, 0.0, 0.0));
    let start = if args.steady {
        let Some((slow, _)) = spinning.steady_precession(tilt, omega.z) else {
            bail!(
                "--steady: no steady precession: it needs a symmetric top (I1 = I2, the pivot on the third principal axis) spinning fast enough at this --tilt (ω3 = {} rad/s)",
                show(omega.z)
            );
        };
        spinning.tilted(tilt, omega.z, slow)
    } else {
        spinning.attitude(tilt_q * axes, omega).map_err(with_flag)?
    };
    let options = SpinOptions {
        integrator: integrator(args)?,
        formulation: if args.frame == "body" {
            Formulation::Body
        } else {
            Formulation::World
        },
        renormalise: true,
        samples: args.samples.max(1),
    };
    let run = match spinning.simulate(&start, t_max, &options) {
        Ok(run) => run,
        Err(Free3dError::Integrate(e)) => {
            eprintln!("error: the simulation failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => return Err(with_flag(e)),
    };
    let files = match &args.out {
        Some(dir) => Some(write_files(&spinning, &run, dir, args.plots)?),
        None => None,
    };
    let summary = to_json(&spinning, &run, &options, t_max, files.as_ref());
    if args.json {
        print(&format!("{summary:#}\n"))?;
    } else {
        print(&text(&summary))?;
    }
    Ok(Outcome::Success)
}

fn tensor_json(m: &Mat3) -> Value {
    (0..3)
        .map(|r| (0..3).map(|c| m[(r, c)] + 0.0).collect::<Vec<_>>())
        .collect()
}

fn to_json(
    body: &SpinningBody,
    run: &SpinRun,
    options: &SpinOptions,
    t_max: f64,
    files: Option<&Value>,
) -> Value {
    let first = &run.samples[0];
    let last = &run.samples[run.samples.len() - 1];
    let c = run.conservation;
    let flip = body.pivot().is_none().then(|| {
        let exact = Poinsot::new(body.body().moments(), first.omega_body);
        let measured = run.crossing_period();
        let reference = exact.map(|p| p.period());
        let deviation = exact.map(|p| {
            run.samples
                .iter()
                .map(|s| (s.omega_body - p.omega(s.t)).norm())
                .fold(0.0, f64::max)
        });
        json!({
            "axis": body.body().intermediate_axis() + 1,
            "zeros": run.crossings.len(),
            "zero_times": run.crossings.iter().map(|z| z.t).collect::<Vec<_>>(),
            "period": {
                "simulated": measured,
                "elliptic": reference,
                "relative_difference": measured.zip(reference).map(|(m, r)| (m - r) / r),
            },
            "parameter_m": exact.map(|p| p.parameter()),
            "one_minus_m": exact.map(|p| p.complementary_parameter()),
            "omega_max_deviation": deviation,
        })
    });
    let top = body.pivot().map(|(d, g)| {
        let thetas: Vec<f64> = run.samples.iter().map(|s| s.attitude.euler_angles().1).collect();
        let (lo, hi) = thetas
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &t| (a.min(t), b.max(t)));
        let theta0 = thetas[0];
        let spin = first.omega_body.z;
        let steady = body.steady_precession(theta0, spin);
        json!({
            "cm_offset": vec_json(&d), "g": g,
            "inertia_about_pivot": tensor_json(body.inertia()),
            "nutation_deg": {"start": theta0.to_degrees(), "min": lo.to_degrees(), "max": hi.to_degrees()},
            "precession_rate": {
                "mean": (last.precession - first.precession) / (last.t - first.t),
                "steady_slow": steady.map(|s| s.0),
                "steady_fast": steady.map(|s| s.1),
                "fast_top": body.fast_top_precession(spin),
            },
        })
    });
    let step = match &options.integrator {
        SpinIntegrator::Adaptive { config, .. } => {
            json!({"rtol": config.rtol.as_scalar(), "atol": config.atol.as_scalar()})
        }
        SpinIntegrator::Fixed { dt, .. } | SpinIntegrator::Splitting { dt } => json!({"dt": dt}),
    };
    let b = body.body();
    json!({
        "moments": b.moments(), "mass": b.mass(),
        "omega0": vec_json(&first.omega_body),
        "t_max": t_max,
        "integrator": {
            "method": options.integrator.name(), "frame": options.formulation.name(),
            "step": step, "steps": run.steps, "rejected": run.rejected,
            "evaluations": run.evaluations,
        },
        "angular_momentum": {
            "start": vec_json(&first.attitude.l), "end": vec_json(&run.end.l),
            "norm": first.attitude.l.norm(),
        },
        "energy": {
            "start": first.kinetic + first.potential, "end": last.kinetic + last.potential,
            "kinetic_start": first.kinetic,
        },
        "conservation": {
            "angular_momentum_norm": c.l_norm, "energy": c.energy, "l_z": c.l_z, "l_3": c.l_3,
            "quaternion_norm": c.quaternion_norm,
        },
        "flip": flip,
        "top": top,
        "files": files,
    })
}

fn text(j: &Value) -> String {
    let num = |p: &str| j.pointer(p).and_then(Value::as_f64);
    let f = |p: &str| num(p).map_or_else(|| "-".to_string(), show);
    let e = |p: &str| num(p).map_or_else(|| "-".to_string(), |x| format!("{x:.2e}"));
    let mut out = String::new();
    let _ = writeln!(
        out,
        "body: I = ({}, {}, {}) kg*m^2, m = {} kg; ω0 = ({}, {}, {}) rad/s (principal axes)",
        f("/moments/0"),
        f("/moments/1"),
        f("/moments/2"),
        f("/mass"),
        f("/omega0/0"),
        f("/omega0/1"),
        f("/omega0/2")
    );
    let _ = writeln!(
        out,
        "integrated to t = {} s with {} (L in the {} frame): {} steps, {} evaluations",
        f("/t_max"),
        j["integrator"]["method"].as_str().unwrap_or("?"),
        j["integrator"]["frame"].as_str().unwrap_or("?"),
        j["integrator"]["steps"],
        j["integrator"]["evaluations"]
    );
    let kept = if j["top"].is_null() {
        format!(
            "|L| {}, E {}",
            e("/conservation/angular_momentum_norm"),
            e("/conservation/energy")
        )
    } else {
        format!(
            "E {}, L_z {}, L_3 {}",
            e("/conservation/energy"),
            e("/conservation/l_z"),
            e("/conservation/l_3")
        )
    };
    let _ = writeln!(
        out,
        "conservation (largest relative deviation): {kept}; ||q| - 1| {} before renormalising",
        e("/conservation/quaternion_norm")
    );
    if !j["flip"].is_null() {
        let _ = writeln!(
            out,
            "ω about the intermediate axis I{}: {} zeros; period {} s simulated, 4K(m)/λ = {} s (m = 1 - {}), relative difference {}; max |ω - ω_elliptic| = {} rad/s",
            j["flip"]["axis"],
            j["flip"]["zeros"],
            f("/flip/period/simulated"),
            f("/flip/period/elliptic"),
            e("/flip/one_minus_m"),
            e("/flip/period/relative_difference"),
            e("/flip/omega_max_deviation")
        );
    }
    if !j["top"].is_null() {
        let _ = writeln!(
            out,
            "top: nutation θ from {}° to {}° (start {}°); mean precession {} rad/s, steady (slow root) {} rad/s, fast-top m g ℓ/(J3 ω3) {} rad/s",
            f("/top/nutation_deg/min"),
            f("/top/nutation_deg/max"),
            f("/top/nutation_deg/start"),
            f("/top/precession_rate/mean"),
            f("/top/precession_rate/steady_slow"),
            f("/top/precession_rate/fast_top")
        );
    }
    if let Some(csv) = j.pointer("/files/csv").and_then(Value::as_str) {
        let _ = writeln!(out, "wrote {csv} and the plots");
    }
    out
}

/// spin.csv and the plots; returns their paths.
fn write_files(
    body: &SpinningBody,
    run: &SpinRun,
    dir: &Path,
    format: crate::args::PlotFormat,
) -> Result<Value> {
    std::fs::create_dir_all(dir).map_err(|e| anyhow!("cannot create {}: {e}", dir.display()))?;
    let top = body.pivot().is_some();
    let mut csv = String::from("t,qw,qx,qy,qz,w1,w2,w3,Lx,Ly,Lz,L,T,U,E");
    csv.push_str(if top { ",theta,phi\n" } else { "\n" });
    for s in &run.samples {
        let q = s.attitude.q.quaternion();
        let l = s.attitude.l;
        let mut row = vec![s.t, q.w, q.i, q.j, q.k];
        row.extend(s.omega_body.iter());
        row.extend([
            l.x,
            l.y,
            l.z,
            l.norm(),
            s.kinetic,
            s.potential,
            s.kinetic + s.potential,
        ]);
        if top {
            row.extend([s.attitude.euler_angles().1, s.precession]);
        }
        for (k, x) in row.iter().enumerate() {
            if k > 0 {
                csv.push(',');
            }
            push_number(&mut csv, *x);
        }
        csv.push('\n');
    }
    let csv_path = dir.join("spin.csv");
    write_atomic(&csv_path, csv.as_bytes())
        .map_err(|e| anyhow!("cannot write {}: {e}", csv_path.display()))?;
    let series = |f: &dyn Fn(&mechkit::rigid::free3d::SpinSample) -> f64| -> Vec<(f64, f64)> {
        run.samples.iter().map(|s| (s.t, f(s))).collect()
    };
    let m = body.body().moments();
    let title = format!("I = ({}, {}, {}) kg·m²", show(m[0]), show(m[1]), show(m[2]));
    let mut omega = PlotData::new("omega(t)", "ω in the body frame", "t [s]", "ω [rad/s]");
    for k in 0..3 {
        omega = omega.with_series(Series::line(
            format!("ω{}", k + 1),
            series(&|s| s.omega_body[k]),
        ));
    }
    if let Some(exact) = Poinsot::new(m, run.samples[0].omega_body).filter(|_| !top) {
        let axis = body.body().intermediate_axis();
        omega = omega.with_series(
            Series::line(
                format!("ω{} elliptic", axis + 1),
                series(&|s| exact.omega(s.t)[axis]),
            )
            .styled(LineStyle::Dashed),
        );
    }
    let mut plots = vec![("omega(t)", omega)];
    if top {
        plots.push((
            "nutation(t)",
            PlotData::new("nutation(t)", "nutation", "t [s]", "θ [deg]").with_series(Series::line(
                "θ",
                series(&|s| s.attitude.euler_angles().1.to_degrees()),
            )),
        ));
        plots.push((
            "precession(t)",
            PlotData::new("precession(t)", "precession", "t [s]", "φ [deg]")
                .with_series(Series::line("φ", series(&|s| s.precession.to_degrees()))),
        ));
    }
    let mut names = Vec::new();
    for (name, data) in &plots {
        let path = dir.join(format.file(name));
        render(data, &title, &path, format.dpi)?;
        names.push(path.display().to_string());
    }
    Ok(json!({"csv": csv_path.display().to_string(), "plots": names}))
}
