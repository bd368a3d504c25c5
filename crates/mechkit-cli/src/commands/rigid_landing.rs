//! `mechkit rigid-collide --landing`: a free rod landing on its lower end on the ground (a
//! frictionless impulse at the end, with restitution): its velocity and angular velocity after,
//! the impulse, the energy lost, and the angular momentum about the contact point (conserved,
//! since the only impulse acts there).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::expr::units::Dimension;
use mechkit::rigid::impact::{Contact, FreeImpact, PlanarBody, impact};
use serde_json::json;

use super::input::{quantity, show};
use super::rigid_collide::{planar, restitution};
use super::{Outcome, print};
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
    if !(0.0..=std::f64::consts::FRAC_PI_2).contains(&tilt) {
        bail!(
            "--tilt is {} rad; the rod's angle above the horizontal is 0 to 90 deg (a bare number is radians)",
            show(tilt)
        );
    }
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
    let rod = PlanarBody::new(m, m * l * l / 12.0, [0.0, 0.0], v, omega)
        .map_err(|err| anyhow!("--mass/--length: {err}"))?;
    // the lower end touches the ground; the ground pushes up
    let end = [-0.5 * l * tilt.cos(), -0.5 * l * tilt.sin()];
    let contact = Contact {
        point: end,
        normal: [0.0, 1.0],
        restitution: e,
    };
    let r = impact(&PlanarBody::fixed(end), &rod, &contact).map_err(|err| {
        anyhow!("--velocity/--omega: {err} (the lower end must be moving down into the ground)")
    })?;
    if args.json {
        print(&format!("{:#}\n", to_json(&rod, end, tilt, e, &r)))?;
    } else {
        print(&text(&rod, l, tilt, e, &r))?;
    }
    Ok(Outcome::Success)
}

fn to_json(
    rod: &PlanarBody,
    end: [f64; 2],
    tilt: f64,
    e: f64,
    r: &FreeImpact,
) -> serde_json::Value {
    let after = &r.b;
    json!({
        "rod": {"mass": rod.mass, "inertia_cm": rod.inertia, "tilt": tilt},
        "restitution": e,
        "contact": end,
        "before": {"velocity": rod.velocity, "omega": rod.omega, "end_velocity": rod.velocity_at(end)},
        "after": {"velocity": after.velocity, "omega": after.omega, "end_velocity": after.velocity_at(end)},
        "impulse": r.impulse,
        "effective_mass": r.effective_mass,
        "kinetic_energy": {"before": r.kinetic.0, "after": r.kinetic.1,
            "change": r.kinetic.1 - r.kinetic.0, "change_closed_form": r.kinetic_change_exact},
        "angular_momentum_contact": {"before": r.angular_momentum_contact.0, "after": r.angular_momentum_contact.1},
    })
}

fn text(rod: &PlanarBody, l: f64, tilt: f64, e: f64, r: &FreeImpact) -> String {
    let after = &r.b;
    let v2 = |v: [f64; 2]| format!("({}, {})", show(v[0] + 0.0), show(v[1] + 0.0));
    let mut s = String::new();
    let _ = writeln!(
        s,
        "rod m = {} kg, L = {} m, landing on its lower end at {} deg above the horizontal, e = {}",
        show(rod.mass),
        show(l),
        show(tilt.to_degrees()),
        show(e)
    );
    let _ = writeln!(
        s,
        "before: v_cm = {} m/s, ω = {} rad/s\nafter:  v_cm = {} m/s, ω = {} rad/s",
        v2(rod.velocity),
        show(rod.omega + 0.0),
        v2(after.velocity),
        show(after.omega + 0.0)
    );
    let _ = writeln!(
        s,
        "impulse from the ground {} N s (effective mass {} kg)",
        show(r.impulse),
        show(r.effective_mass)
    );
    let _ = writeln!(
        s,
        "kinetic energy {} → {} J (lost {} J; closed form ½(1 − e²) m_eff u² = {} J)",
        show(r.kinetic.0),
        show(r.kinetic.1),
        show(r.kinetic.0 - r.kinetic.1),
        show(-r.kinetic_change_exact)
    );
    let _ = writeln!(
        s,
        "angular momentum about the contact {} → {} kg m²/s",
        show(r.angular_momentum_contact.0),
        show(r.angular_momentum_contact.1)
    );
    s
}
