//! `mechkit rotation`: angular kinematics from a formula, uniform angular acceleration,
//! circular motion, and a point of a body turning in 3-D, through
//! `mechkit::rigid::rotation` (the result is a `RotationReport`).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::mass::Vec3;
use mechkit::rigid::Input;
use mechkit::rigid::kinematics::{AngularMotion, KinematicsError, UniformAngularAcceleration};
use mechkit::rigid::rotation::{
    CircleGiven, CircleQuestion, CircleReport, FormulaReport, PointReport, RotationReport,
    UniformReport, circle, point_motion,
};

use super::body::point;
use super::input::{params, quantity, show, split_top_level};
use super::{Outcome, report};
use crate::args::RotationArgs;

fn angular_acceleration() -> Dimension {
    Dimension::FREQUENCY / Dimension::TIME
}

/// The flag of an input of `mechkit rotation`.
fn flag(input: Option<Input>) -> &'static str {
    match input {
        Some(Input::Period) => "--period",
        Some(Input::Speed) => "--speed",
        Some(Input::Latitude) => "--latitude",
        Some(Input::AngularAcceleration) => "--alpha",
        Some(Input::Centripetal) => "--centripetal",
        Some(Input::Turn) => "--turn",
        Some(Input::AngularSpeed) => "--angular-speed",
        Some(Input::InitialAngularVelocity) => "--omega0",
        Some(Input::FinalAngularVelocity) => "--omega1",
        Some(Input::Time) => "--time",
        Some(Input::InitialAngle) => "--theta0",
        _ => "--radius",
    }
}

fn with_flag(e: &KinematicsError) -> anyhow::Error {
    anyhow!("{}: {e}", flag(e.input()))
}

pub fn rotation(args: &RotationArgs) -> Result<Outcome> {
    let result = if args.theta.is_some() || args.omega.is_some() {
        RotationReport::Formula(formula(args)?)
    } else if args.omega0.is_some() {
        RotationReport::Uniform(uniform(args)?)
    } else if args.omega_vector.is_some() {
        RotationReport::Point(vector(args)?)
    } else if args.radius.is_some()
        || args.period.is_some()
        || args.angular_speed.is_some()
        || args.centripetal.is_some()
        || args.speed.is_some()
    {
        RotationReport::Circle(circle_motion(args)?)
    } else {
        bail!(
            "say what to compute: --theta or --omega (a formula, with --at), --omega0 --omega1 \
             --time (uniform angular acceleration), --radius with --speed, --angular-speed, \
             --period or --centripetal (circular motion), or --omega-vector with --point (3-D)"
        );
    };
    report(args.report, &result, || match &result {
        RotationReport::Formula(f) => formula_text(f),
        RotationReport::Uniform(u) => uniform_text(u),
        RotationReport::Circle(c) => circle_text(c),
        RotationReport::Point(p) => point_text(p),
    })?;
    Ok(Outcome::Success)
}

fn formula(args: &RotationArgs) -> Result<FormulaReport> {
    let p = params(args.set.as_deref())?;
    // θ is an angle and ω a rate, in the units the `--set` values were given in
    let set = mechkit::values::param_dimensions(args.set.as_deref().unwrap_or_default());
    let (text, what, want) = match (&args.theta, &args.omega) {
        (Some(theta), _) => (theta, "θ(t)", Dimension::NONE),
        (None, Some(omega)) => (omega, "ω(t)", Dimension::FREQUENCY),
        (None, None) => unreachable!("checked by the caller"),
    };
    mechkit::values::check_formula_units(
        text,
        what,
        ("t", Some(Dimension::TIME), None),
        &set,
        &p,
        Some(want),
    )?;
    let motion = match (&args.theta, &args.omega) {
        (Some(theta), _) => {
            AngularMotion::from_angle(theta, &p).map_err(|e| anyhow!("--theta: {e}"))?
        }
        (None, Some(omega)) => {
            let theta0 = args
                .theta0
                .as_deref()
                .map_or(Ok(0.0), |t| quantity(t, "--theta0", Dimension::NONE))?;
            AngularMotion::from_angular_velocity(omega, &p, theta0).map_err(|e| match e {
                KinematicsError::Formula(_) => anyhow!("--omega: {e}"),
                e => with_flag(&e),
            })?
        }
        (None, None) => unreachable!("checked by the caller"),
    };
    let times = match &args.at {
        Some(list) => split_top_level(list, ',')
            .into_iter()
            .map(|t| {
                let v = mechkit::values::value_of(t, "--at", &p, Dimension::TIME)?;
                if v.is_finite() {
                    Ok(v)
                } else {
                    bail!("--at: `{t}` is not a finite time")
                }
            })
            .collect::<Result<Vec<f64>>>()?,
        None => Vec::new(),
    };
    motion.report(&times).map_err(|e| anyhow!("--at: {e}"))
}

fn formula_text(f: &FormulaReport) -> String {
    let mut text = format!(
        "θ(t) = {}\nω(t) = dθ/dt = {}\nα(t) = dω/dt = {}\n",
        f.theta, f.omega, f.alpha
    );
    for s in &f.at {
        let _ = writeln!(
            text,
            "t = {} s: θ = {} rad, ω = {} rad/s, α = {} rad/s²",
            show(s.t),
            show(s.theta),
            show(s.omega),
            show(s.alpha)
        );
        let _ = writeln!(
            text,
            "  numerical check (Ridders): ω ≈ {}, α ≈ {}: {}",
            s.omega_numeric.map_or_else(|| "—".into(), show),
            show(s.alpha_numeric),
            if s.agree { "agree" } else { "DISAGREE" }
        );
    }
    if f.at.is_empty() {
        text.push_str("(give --at \"1 s\" to evaluate them)\n");
    }
    text
}

fn uniform(args: &RotationArgs) -> Result<UniformReport> {
    let get =
        |v: &Option<String>, flag: &str, dim| quantity(v.as_deref().unwrap_or_default(), flag, dim);
    let w0 = get(&args.omega0, "--omega0", Dimension::FREQUENCY)?;
    let w1 = get(&args.omega1, "--omega1", Dimension::FREQUENCY)?;
    let t = get(&args.time, "--time", Dimension::TIME)?;
    let u = UniformAngularAcceleration::new(w0, w1, t).map_err(|e| with_flag(&e))?;
    Ok(u.report())
}

fn uniform_text(u: &UniformReport) -> String {
    format!(
        "ω₀ = {} rad/s, ω₁ = {} rad/s in t = {} s\nα = (ω₁ − ω₀)/t = {} rad/s²\n\
         Δθ = (ω₀ + ω₁) t/2 = {} rad = {} revolutions\n",
        show(u.omega0),
        show(u.omega1),
        show(u.time),
        show(u.alpha),
        show(u.angle),
        show(u.revolutions)
    )
}

/// The question from the flags: what fixes the motion, checked to be one of the pairs the
/// circle takes (the library checks the values).
fn circle_question(args: &RotationArgs) -> Result<CircleQuestion> {
    let q = |text: &Option<String>, flag: &str, dim| {
        text.as_deref().map(|t| quantity(t, flag, dim)).transpose()
    };
    let radius = q(&args.radius, "--radius", Dimension::LENGTH)?;
    let speed = q(&args.speed, "--speed", Dimension::VELOCITY)?;
    let centripetal = q(&args.centripetal, "--centripetal", Dimension::ACCELERATION)?;
    let given = match (speed, centripetal) {
        (Some(_), Some(_)) if radius.is_some() => {
            bail!("--radius, --speed and --centripetal over-determine the circle: give two of them")
        }
        (Some(speed), Some(centripetal)) => CircleGiven::SpeedAndCentripetal { speed, centripetal },
        (Some(_), None) if radius.is_none() => bail!(
            "--speed needs --radius, or --centripetal (the acceleration allowed) for the smallest radius"
        ),
        (Some(v), None) => CircleGiven::Speed(v),
        (None, Some(_)) if radius.is_none() => bail!(
            "--centripetal needs --radius (ω = √(a/R)) or --speed (the smallest circle R = v²/a)"
        ),
        (None, Some(a)) => CircleGiven::Centripetal(a),
        (None, None) => {
            if let Some(w) = q(&args.angular_speed, "--angular-speed", Dimension::FREQUENCY)? {
                CircleGiven::AngularSpeed(w)
            } else if let Some(t) = q(&args.period, "--period", Dimension::TIME)? {
                CircleGiven::Period(t)
            } else {
                bail!(
                    "--radius needs the motion: --speed, --angular-speed, --period or --centripetal"
                )
            }
        }
    };
    Ok(CircleQuestion {
        given,
        radius,
        alpha: q(&args.alpha, "--alpha", angular_acceleration())?,
        turn: q(&args.turn, "--turn", Dimension::NONE)?,
        latitude: q(&args.latitude, "--latitude", Dimension::NONE)?,
    })
}

fn circle_motion(args: &RotationArgs) -> Result<CircleReport> {
    circle(&circle_question(args)?).map_err(|e| with_flag(&e))
}

fn circle_text(c: &CircleReport) -> String {
    let omega = format!("ω = {} rad/s = {} rpm", show(c.omega), show(c.omega_rpm));
    let mut text = match c.radius {
        Some(r) => {
            let opt = |x: Option<f64>| show(x.unwrap_or(f64::NAN));
            let limit = if c.smallest_radius {
                format!(
                    "smallest circle for a_c ≤ {} m/s²: R = v²/a_c = {} m\n",
                    opt(c.centripetal),
                    show(r)
                )
            } else {
                String::new()
            };
            format!(
                "{limit}circle of radius R = {} m: {omega} (period {} s), v = ωR = {} m/s\n\
                 α = {} rad/s², a_t = αR = {} m/s², a_c = ω²R = v²/R = {} m/s², |a| = {} m/s²\n",
                show(r),
                show(c.period),
                opt(c.speed),
                opt(c.alpha),
                opt(c.tangential),
                opt(c.centripetal),
                opt(c.acceleration)
            )
        }
        None => format!(
            "{omega} (period T = 2π/ω = {} s); give --radius for speeds and accelerations\n",
            show(c.period)
        ),
    };
    if let Some(t) = &c.turn {
        let arc = t
            .arc
            .map_or_else(String::new, |a| format!(", along an arc of {} m", show(a)));
        let _ = writeln!(
            text,
            "turning through {} rad ({}°) takes θ/ω = {} s{arc}",
            show(t.angle),
            show(t.angle.to_degrees()),
            show(t.time)
        );
    }
    if let Some(l) = &c.latitude {
        let _ = writeln!(
            text,
            "at latitude {}°: radius R cos λ = {} m, v = {} m/s, a_c = {} m/s²",
            show(l.latitude.to_degrees()),
            show(l.radius),
            show(l.speed),
            show(l.centripetal)
        );
    }
    text
}

fn vector(args: &RotationArgs) -> Result<PointReport> {
    let omega = point(
        args.omega_vector.as_deref().unwrap_or_default(),
        "--omega-vector",
        Dimension::FREQUENCY,
    )?;
    let alpha = match &args.alpha_vector {
        Some(a) => point(a, "--alpha-vector", angular_acceleration())?,
        None => Vec3::zeros(),
    };
    let r = point(
        args.point.as_deref().unwrap_or_default(),
        "--point",
        Dimension::LENGTH,
    )?;
    Ok(point_motion(&omega, &alpha, &r))
}

fn triple(v: [f64; 3]) -> String {
    format!("({}, {}, {})", show(v[0]), show(v[1]), show(v[2]))
}

fn point_text(p: &PointReport) -> String {
    let a = &p.acceleration;
    format!(
        "ω = {} rad/s, r = {} m (distance from the axis {} m)\nv = ω × r = {} m/s (|v| = {} m/s)\n\
         a = α × r + ω × (ω × r) = {} + {} = {} m/s²\n",
        triple(p.omega),
        triple(p.point),
        show(p.distance_from_axis),
        triple(p.velocity),
        show(p.speed),
        triple(a.tangential),
        triple(a.centripetal),
        triple(a.total)
    )
}
