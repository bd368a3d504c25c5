//! `mechkit rigid-collide --landing`: a free rod landing on its lower end on the ground,
//! through `mechkit::rigid::impact::rod_landing`: its velocity and angular velocity after, the
//! impulse, the energy lost, and the angular momentum about the contact point.

use std::fmt::Write as _;

use anyhow::{Result, anyhow};
use mechkit::expr::units::Dimension;
use mechkit::rigid::impact::{ImpactError, LandingReport, rod_landing};

use super::input::{quantity, show};
use super::rigid_collide::{flag, planar, restitution};
use super::{Outcome, report};
use crate::args::RigidCollideArgs;

pub fn landing(args: &RigidCollideArgs) -> Result<Outcome> {
    let need = |v: &Option<String>, flag: &str, example: &str| {
        v.clone()
            .ok_or_else(|| anyhow!("--landing needs {flag}, e.g. {flag} {example}"))
    };
    let m = quantity(
        &need(&args.mass, "--mass", "\"1 kg\"")?,
        "--mass",
        Dimension::MASS,
    )?;
    let l = quantity(
        &need(&args.length, "--length", "\"1 m\"")?,
        "--length",
        Dimension::LENGTH,
    )?;
    let tilt = quantity(
        &need(&args.tilt, "--tilt", "\"30 deg\"")?,
        "--tilt",
        Dimension::NONE,
    )?;
    let v = planar(
        &need(&args.velocity, "--velocity", "\"0, -3 m/s\"")?,
        "--velocity",
        Dimension::VELOCITY,
    )?;
    let omega = args
        .omega
        .as_deref()
        .map_or(Ok(0.0), |w| quantity(w, "--omega", Dimension::FREQUENCY))?;
    let e = restitution(&args.restitution)?;
    let result = rod_landing(m, l, tilt, v, omega, e).map_err(|err| match err {
        ImpactError::Separating { .. } => {
            anyhow!("--velocity/--omega: {err} (the lower end must be moving down into the ground)")
        }
        err => anyhow!("{}: {err}", flag(err.input(), args)),
    })?;
    report(args.report, &result, || text(&result))?;
    Ok(Outcome::Success)
}

fn text(r: &LandingReport) -> String {
    let v2 = |v: [f64; 2]| format!("({}, {})", show(v[0] + 0.0), show(v[1] + 0.0));
    let mut s = String::new();
    let _ = writeln!(
        s,
        "rod m = {} kg, L = {} m, landing on its lower end at {} deg above the horizontal, e = {}",
        show(r.rod.mass),
        show(r.rod.length),
        show(r.rod.tilt.to_degrees()),
        show(r.restitution)
    );
    let _ = writeln!(
        s,
        "before: v_cm = {} m/s, ω = {} rad/s\nafter:  v_cm = {} m/s, ω = {} rad/s",
        v2(r.before.velocity),
        show(r.before.omega + 0.0),
        v2(r.after.velocity),
        show(r.after.omega + 0.0)
    );
    let _ = writeln!(
        s,
        "impulse from the ground {} N s (effective mass {} kg)",
        show(r.impulse),
        show(r.effective_mass)
    );
    let k = &r.kinetic_energy;
    let _ = writeln!(
        s,
        "kinetic energy {} → {} J (lost {} J; closed form ½(1 − e²) m_eff u² = {} J)",
        show(k.before),
        show(k.after),
        show(k.before - k.after),
        show(-k.change_closed_form)
    );
    let _ = writeln!(
        s,
        "angular momentum about the contact {} → {} kg m²/s",
        show(r.angular_momentum_contact.before),
        show(r.angular_momentum_contact.after)
    );
    s
}
