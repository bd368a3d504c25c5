//! `mechkit rotation`: angular kinematics from a formula, uniform angular acceleration,
//! circular motion, and a point of a body turning in 3-D.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::mass::Vec3;
use mechkit::rigid::kinematics::{
    AngularMotion, CircularMotion, Given, KinematicsError, UniformAngularAcceleration,
    distance_from_axis, point_acceleration, point_velocity,
};
use serde_json::{Value, json};

use super::body::{point, vec_json, vec_text};
use super::input::{params, quantity, show, split_top_level, value};
use super::{Outcome, print};
use crate::args::RotationArgs;

fn angular_acceleration() -> Dimension {
    Dimension::FREQUENCY / Dimension::TIME
}

pub fn rotation(args: &RotationArgs) -> Result<Outcome> {
    let (body, text) = if args.theta.is_some() || args.omega.is_some() {
        formula(args)?
    } else if args.omega0.is_some() {
        uniform(args)?
    } else if args.omega_vector.is_some() {
        vector(args)?
    } else if args.radius.is_some()
        || args.period.is_some()
        || args.angular_speed.is_some()
        || args.centripetal.is_some()
        || args.speed.is_some()
    {
        circle(args)?
    } else {
        bail!(
            "say what to compute: --theta or --omega (a formula, with --at), --omega0 --omega1 \
             --time (uniform angular acceleration), --radius with --speed, --angular-speed or \
             --period (circular motion), or --omega-vector with --point (3-D)"
        );
    };
    if args.json {
        print(&format!("{body:#}\n"))?;
    } else {
        print(&text)?;
    }
    Ok(Outcome::Success)
}

fn formula(args: &RotationArgs) -> Result<(Value, String)> {
    let p = params(args.set.as_deref())?;
    let motion = match (&args.theta, &args.omega) {
        (Some(theta), _) => {
            AngularMotion::from_angle(theta, &p).map_err(|e| anyhow!("--theta: {e}"))?
        }
        (None, Some(omega)) => {
            let theta0 = args
                .theta0
                .as_deref()
                .map_or(Ok(0.0), |t| quantity(t, "--theta0", Dimension::NONE))?;
            AngularMotion::from_angular_velocity(omega, &p, theta0)
                .map_err(|e| anyhow!("--omega: {e}"))?
        }
        (None, None) => unreachable!("checked by the caller"),
    };
    let times = match &args.at {
        Some(list) => split_top_level(list, ',')
            .into_iter()
            .map(|t| {
                let v = value(t, "--at", &p)?;
                if v.is_finite() {
                    Ok(v)
                } else {
                    bail!("--at: `{t}` is not a finite time")
                }
            })
            .collect::<Result<Vec<f64>>>()?,
        None => Vec::new(),
    };
    let theta_text = match motion.theta_formula() {
        Some(f) if motion.given() == Given::AngularVelocity && motion.theta0() != 0.0 => {
            format!("{} + {f}", show(motion.theta0()))
        }
        Some(f) => f.to_string(),
        None => format!(
            "{} + ∫₀ᵗ ω dt (no closed form: adaptive quadrature)",
            show(motion.theta0())
        ),
    };
    let states: Vec<_> = times.iter().map(|&t| motion.at(t)).collect();
    let given = match motion.given() {
        Given::Angle => "theta",
        Given::AngularVelocity => "omega",
    };
    let body = json!({
        "mode": "formula",
        "given": given,
        "theta": theta_text,
        "theta_closed_form": motion.theta_formula().is_some(),
        "omega": motion.omega_formula().to_string(),
        "alpha": motion.alpha_formula().to_string(),
        "at": states.iter().map(|s| json!({
            "t": s.t, "theta": s.theta, "omega": s.omega, "alpha": s.alpha,
            "omega_numeric": s.omega_numeric, "alpha_numeric": s.alpha_numeric,
            "agree": s.agree,
        })).collect::<Vec<_>>(),
    });
    let mut text = format!(
        "θ(t) = {theta_text}\nω(t) = dθ/dt = {}\nα(t) = dω/dt = {}\n",
        motion.omega_formula(),
        motion.alpha_formula()
    );
    for s in &states {
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
    if states.is_empty() {
        text.push_str("(give --at \"1 s\" to evaluate them)\n");
    }
    Ok((body, text))
}

fn uniform(args: &RotationArgs) -> Result<(Value, String)> {
    let get =
        |v: &Option<String>, flag: &str, dim| quantity(v.as_deref().unwrap_or_default(), flag, dim);
    let w0 = get(&args.omega0, "--omega0", Dimension::FREQUENCY)?;
    let w1 = get(&args.omega1, "--omega1", Dimension::FREQUENCY)?;
    let t = get(&args.time, "--time", Dimension::TIME)?;
    let u = UniformAngularAcceleration::new(w0, w1, t).map_err(|e| anyhow!("--time: {e}"))?;
    let body = json!({
        "mode": "uniform",
        "omega0": w0, "omega1": w1, "time": t,
        "alpha": u.alpha(), "angle": u.angle(), "revolutions": u.revolutions(),
    });
    let text = format!(
        "ω₀ = {} rad/s, ω₁ = {} rad/s in t = {} s\nα = (ω₁ − ω₀)/t = {} rad/s²\n\
         Δθ = (ω₀ + ω₁) t/2 = {} rad = {} revolutions\n",
        show(w0),
        show(w1),
        show(t),
        show(u.alpha()),
        show(u.angle()),
        show(u.revolutions())
    );
    Ok((body, text))
}

fn flag_of(e: &KinematicsError) -> &'static str {
    match e {
        KinematicsError::Value { what, .. } => match *what {
            "the radius" => "--radius",
            "the period" => "--period",
            "the speed" => "--speed",
            "the latitude" => "--latitude",
            "α" => "--alpha",
            _ => "--angular-speed",
        },
        _ => "--radius",
    }
}

fn circle(args: &RotationArgs) -> Result<(Value, String)> {
    let mut radius = args
        .radius
        .as_deref()
        .map(|r| quantity(r, "--radius", Dimension::LENGTH))
        .transpose()?;
    if let (Some(a), Some(v)) = (&args.centripetal, &args.speed) {
        let a = quantity(a, "--centripetal", Dimension::ACCELERATION)?;
        let v = quantity(v, "--speed", Dimension::VELOCITY)?;
        if !(a > 0.0 && a.is_finite()) {
            bail!("--centripetal must be a positive acceleration, e.g. \"0.1 gn\" or \"1 m/s^2\"");
        }
        radius = Some(v * v / a);
    }
    if args.speed.is_some() && radius.is_none() {
        bail!(
            "--speed needs --radius, or --centripetal (the acceleration allowed) for the smallest radius"
        );
    }
    let err = |e: KinematicsError| anyhow!("{}: {e}", flag_of(&e));
    let motion = if let Some(v) = &args.speed {
        let v = quantity(v, "--speed", Dimension::VELOCITY)?;
        CircularMotion::from_speed(v, radius.unwrap_or_default()).map_err(err)?
    } else if let Some(w) = &args.angular_speed {
        let w = quantity(w, "--angular-speed", Dimension::FREQUENCY)?;
        CircularMotion::new(radius.unwrap_or_default(), w).map_err(err)?
    } else if let Some(t) = &args.period {
        let t = quantity(t, "--period", Dimension::TIME)?;
        CircularMotion::from_period(t, radius.unwrap_or_default()).map_err(err)?
    } else {
        bail!("--radius needs the motion: --speed, --angular-speed or --period");
    };
    let motion = match &args.alpha {
        Some(a) => motion
            .with_alpha(quantity(a, "--alpha", angular_acceleration())?)
            .map_err(err)?,
        None => motion,
    };
    let (mut body, mut text) = if radius.is_some() {
        let c = &motion;
        (
            json!({
                "mode": "circle", "radius": c.radius, "omega": c.omega, "period": c.period(),
                "speed": c.speed(), "alpha": c.alpha, "centripetal": c.centripetal(),
                "tangential": c.tangential(), "acceleration": c.acceleration(),
            }),
            format!(
                "circle of radius R = {} m: ω = {} rad/s (period {} s), v = ωR = {} m/s\n\
                 α = {} rad/s², a_t = αR = {} m/s², a_c = ω²R = v²/R = {} m/s², |a| = {} m/s²\n",
                show(c.radius),
                show(c.omega),
                show(c.period()),
                show(c.speed()),
                show(c.alpha),
                show(c.tangential()),
                show(c.centripetal()),
                show(c.acceleration())
            ),
        )
    } else {
        (
            json!({"mode": "circle", "omega": motion.omega, "period": motion.period()}),
            format!(
                "ω = 2π/T = {} rad/s (period {} s); give --radius for speeds and accelerations\n",
                show(motion.omega),
                show(motion.period())
            ),
        )
    };
    if let Some(turn) = &args.turn {
        let angle = quantity(turn, "--turn", Dimension::NONE)?;
        if motion.omega == 0.0 {
            bail!("--turn: the body does not turn (ω = 0)");
        }
        let time = (angle / motion.omega).abs();
        body["turn"] =
            json!({"angle": angle, "time": time, "arc": radius.map(|r| angle.abs() * r)});
        let arc = radius.map_or_else(String::new, |r| {
            format!(", along an arc of {} m", show(angle.abs() * r))
        });
        let _ = writeln!(
            text,
            "turning through {} rad ({}°) takes θ/ω = {} s{arc}",
            show(angle),
            show(angle.to_degrees()),
            show(time)
        );
    }
    if let Some(lat) = &args.latitude {
        let lambda = quantity(lat, "--latitude", Dimension::NONE)?;
        let at = motion.at_latitude(lambda).map_err(err)?;
        body["latitude"] = json!({
            "latitude": lambda, "radius": at.radius, "speed": at.speed(),
            "centripetal": at.centripetal(), "tangential": at.tangential(),
        });
        let _ = writeln!(
            text,
            "at latitude {}°: radius R cos λ = {} m, v = {} m/s, a_c = {} m/s²",
            show(lambda.to_degrees()),
            show(at.radius),
            show(at.speed()),
            show(at.centripetal())
        );
    }
    Ok((body, text))
}

fn vector(args: &RotationArgs) -> Result<(Value, String)> {
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
    let v = point_velocity(&omega, &r);
    let a = point_acceleration(&alpha, &omega, &r);
    let rho = distance_from_axis(&omega, &r);
    let body = json!({
        "mode": "point", "omega": vec_json(&omega), "alpha": vec_json(&alpha),
        "point": vec_json(&r), "velocity": vec_json(&v), "speed": v.norm(),
        "distance_from_axis": rho,
        "acceleration": {
            "tangential": vec_json(&a.tangential), "centripetal": vec_json(&a.centripetal),
            "total": vec_json(&a.total()),
        },
    });
    let text = format!(
        "ω = {} rad/s, r = {} m (distance from the axis {} m)\nv = ω × r = {} m/s (|v| = {} m/s)\n\
         a = α × r + ω × (ω × r) = {} + {} = {} m/s²\n",
        vec_text(&omega),
        vec_text(&r),
        show(rho),
        vec_text(&v),
        show(v.norm()),
        vec_text(&a.tangential),
        vec_text(&a.centripetal),
        vec_text(&a.total())
    );
    Ok((body, text))
}
