//! `mechkit spin`: a free rigid body in 3-D or a heavy top, through `SpinningBody::report`:
//! the run's conservation of |L| and E, the flip period of ω about the intermediate axis
//! against the elliptic-function period, the top's nutation and precession; spin.csv and the
//! plots with `-o`.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::mass::Vec3;
use mechkit::ode::events::FALLBACK_SAMPLES;
use mechkit::ode::{AdaptiveConfig, Tableau};
use mechkit::report::Files;
use mechkit::rigid::Input;
use mechkit::rigid::free3d::{
    Formulation, Free3dError, FreeBody, Orientation, SpinIntegrator, SpinOptions, SpinReport,
    SpinningBody,
};

use super::body::{load, point};
use super::input::{quantity, show, split_top_level};
use super::outputs::{create_dir, write_plots, write_table};
use super::{Outcome, note, report};
use crate::args::SpinArgs;

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

/// The flag of an input of `mechkit spin` (the body file's name for its moments).
fn flag(input: Option<Input>, args: &SpinArgs) -> String {
    match input {
        Some(Input::Inertia) => args
            .file
            .as_ref()
            .map_or_else(|| "--moments".to_string(), |f| f.display().to_string()),
        Some(Input::Mass) => "--mass".into(),
        Some(Input::Gravity) => "--g".into(),
        Some(Input::AngularVelocity) => "--omega".into(),
        Some(Input::Pivot) => "--pivot".into(),
        Some(Input::Orientation) => "--tilt".into(),
        Some(Input::Duration) => "--t-max".into(),
        Some(Input::Step) => "--dt".into(),
        Some(Input::Method) => "--method".into(),
        Some(Input::Samples) => "--samples".into(),
        _ => "--rtol".into(),
    }
}

/// The body (principal frame), the rotation from the principal frame to the body's
/// coordinates, and the centre of mass in those coordinates.
fn body(args: &SpinArgs) -> Result<(FreeBody, Orientation, Vec3)> {
    let with_flag = |e: Free3dError| anyhow!("{}: {e}", flag(e.input(), args));
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
    let with_flag = |e: Free3dError| anyhow!("{}: {e}", flag(e.input(), args));
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
    let mut result = match spinning.report(&start, t_max, &options) {
        Ok(r) => r,
        Err(Free3dError::Integrate(e)) if !e.is_step_budget() => {
            eprintln!("error: the simulation failed: {e}");
            return Ok(Outcome::ComputationFailed);
        }
        Err(e) => return Err(with_flag(e)),
    };
    let mut wrote = None;
    if let Some(dir) = &args.out {
        create_dir(dir)?;
        let csv = write_table(dir, SpinReport::TABLE, &result.table())?;
        let plots = if args.no_plots {
            Vec::new()
        } else {
            let m = result.moments;
            let title = format!("I = ({}, {}, {}) kg·m²", show(m[0]), show(m[1]), show(m[2]));
            write_plots(dir, &result.plots(), &title, args.plots)?
        };
        wrote = Some(super::roll::written(&csv, &plots));
        result.files = Some(Files {
            csv: Some(csv),
            plots,
        });
    }
    report(args.report, &result, || text(&result))?;
    if let Some(w) = &wrote {
        note(args.report, w);
    }
    Ok(Outcome::Success)
}

fn text(r: &SpinReport) -> String {
    let e = |x: f64| format!("{x:.2e}");
    let opt = |x: Option<f64>| x.map_or_else(|| "-".to_string(), show);
    let opt_e = |x: Option<f64>| x.map_or_else(|| "-".to_string(), e);
    let mut out = String::new();
    let (m, w) = (r.moments, r.omega0);
    let _ = writeln!(
        out,
        "body: I = ({}, {}, {}) kg*m^2, m = {} kg; ω0 = ({}, {}, {}) rad/s (principal axes)",
        show(m[0]),
        show(m[1]),
        show(m[2]),
        show(r.mass),
        show(w[0]),
        show(w[1]),
        show(w[2])
    );
    let i = &r.integrator;
    let _ = writeln!(
        out,
        "integrated to t = {} s with {} (L in the {} frame): {} steps, {} evaluations",
        show(r.t_max),
        i.method,
        i.frame,
        i.steps,
        i.evaluations
    );
    let c = &r.conservation;
    let kept = if r.top.is_none() {
        format!("|L| {}, E {}", e(c.l_norm), e(c.energy))
    } else {
        format!("E {}, L_z {}, L_3 {}", e(c.energy), e(c.l_z), e(c.l_3))
    };
    let _ = writeln!(
        out,
        "conservation (largest relative deviation): {kept}; ||q| - 1| {} before renormalising",
        e(c.quaternion_norm)
    );
    if let Some(f) = &r.flip {
        let reference = match (f.period.elliptic, f.parameter_m, f.one_minus_m) {
            (Some(period), Some(m), Some(m1)) => format!(
                "4K(m)/λ = {} s ({}), relative difference {}; max |ω - ω_elliptic| = {} rad/s",
                show(period),
                if m >= 0.5 {
                    format!("m = 1 - {}", e(m1))
                } else if m == 0.0 || m >= 1e-3 {
                    format!("m = {}", show((m * 1e3).round() / 1e3))
                } else {
                    format!("m = {}", e(m))
                },
                opt_e(f.period.relative_difference),
                opt_e(f.omega_max_deviation)
            ),
            _ => "no elliptic reference: ω is constant (three equal moments, or a spin about a principal axis) or the start is on the separatrix".to_string(),
        };
        let _ = writeln!(
            out,
            "ω about the intermediate axis I{}: {} zeros; period {} s simulated; {reference}",
            f.axis,
            f.zeros,
            opt(f.period.simulated),
        );
        if f.unproven_steps > 0 {
            let _ = writeln!(
                out,
                "warning: in {} steps the zeros of ω about I{} could not be proven and ω was sampled at {FALLBACK_SAMPLES} points there, so a zero between two samples may be missed; shorter steps (a smaller --rtol or --dt) make the bounds tighter",
                f.unproven_steps, f.axis
            );
        }
    }
    if let Some(t) = &r.top {
        let _ = writeln!(
            out,
            "top: nutation θ from {}° to {}° (start {}°); mean precession {}, steady (slow root) {} rad/s, fast-top m g ℓ/(J3 ω3) {} rad/s",
            show(t.nutation_deg.min),
            show(t.nutation_deg.max),
            show(t.nutation_deg.start),
            t.precession_rate.mean.map_or_else(
                || "undefined (the axis is vertical at a sample, where φ has no value)".to_string(),
                |m| format!("{} rad/s", show(m))
            ),
            opt(t.precession_rate.steady_slow),
            opt(t.precession_rate.fast_top)
        );
    }
    out
}
