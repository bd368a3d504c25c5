//! `mechkit relative`: steering through a moving medium and the Galilean transformation of
//! velocities, through `mechkit::relative` (`steering_report`, `transform`).

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::relative::{
    Frame, RelativeError, SpeedUnit, SteeringReport, VelocityReport, components, steering_report,
    transform,
};
use mechkit::units::Dimension;

use super::input::{output_unit, quantity, show, split_top_level};
use super::{Outcome, report};
use crate::args::RelativeArgs;

pub fn relative(args: &RelativeArgs) -> Result<Outcome> {
    let (size, name) = output_unit(
        args.unit.as_deref(),
        Dimension::VELOCITY,
        ("m/s", "a unit of speed", "--in km/h or --in knot"),
        false,
    )?;
    let unit = SpeedUnit { name, size };
    if args.speed.is_some() {
        match steering(args, &unit)? {
            Ok(result) => report(args.report, &result, || steering_text(&result))?,
            Err(e) => {
                // a well-posed question without an answer: the computation fails
                eprintln!("error: {e}");
                return Ok(Outcome::ComputationFailed);
            }
        }
    } else if let Some(v) = &args.velocity {
        let result = velocity(args, v, &unit)?;
        report(args.report, &result, || velocity_text(&result))?;
    } else {
        bail!(
            "say what to compute: --speed with --current and --track (the heading through a wind or a current), or --velocity with --frame-velocity or --relative-to (a velocity in another frame)"
        );
    }
    Ok(Outcome::Success)
}

/// A direction in the plane: an angle counter-clockwise from +x (east), or a compass word.
fn direction(text: &str, flag: &str) -> Result<f64> {
    let word = text.trim().to_ascii_lowercase();
    let degrees = match word.as_str() {
        "east" | "e" => Some(0.0),
        "northeast" | "ne" => Some(45.0),
        "north" | "n" => Some(90.0),
        "northwest" | "nw" => Some(135.0),
        "west" | "w" => Some(180.0),
        "southwest" | "sw" => Some(225.0),
        "south" | "s" => Some(270.0),
        "southeast" | "se" => Some(315.0),
        _ => None,
    };
    if let Some(d) = degrees {
        return Ok(f64::to_radians(d));
    }
    let angle = quantity(text, flag, Dimension::NONE).map_err(|_| {
        anyhow!("{flag} `{text}` is not a direction: give an angle from east, counter-clockwise, such as \"90 deg\", or a compass word (north, east, south, west, ne, nw, se, sw)")
    })?;
    if !angle.is_finite() {
        bail!("{flag} `{text}` is not a finite angle");
    }
    Ok(angle)
}

fn speed(text: &str, flag: &str) -> Result<f64> {
    let v = quantity(text, flag, Dimension::VELOCITY)?;
    if !v.is_finite() {
        bail!("{flag} `{text}` is not a finite speed");
    }
    Ok(v)
}

/// The steering answer, or why there is none (the outer error is bad input).
fn steering(
    args: &RelativeArgs,
    unit: &SpeedUnit,
) -> Result<Result<SteeringReport, RelativeError>> {
    let s = speed(args.speed.as_deref().unwrap_or_default(), "--speed")?;
    let c = speed(args.current.as_deref().unwrap_or_default(), "--current")?;
    let c_dir = match &args.current_direction {
        Some(d) => direction(d, "--current-direction")?,
        None => 0.0,
    };
    let track = direction(args.track.as_deref().unwrap_or_default(), "--track")?;
    Ok(steering_report(s, c, c_dir, track, unit))
}

fn steering_text(r: &SteeringReport) -> String {
    let unit = &r.unit;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "heading {} deg from east ({} deg {} of the track)",
        show(round(r.heading_deg)),
        show(round(r.correction_deg.abs())),
        if r.correction_deg >= 0.0 {
            "left"
        } else {
            "right"
        }
    );
    if let Some(upstream) = r.angle_to_upstream_deg {
        let _ = writeln!(
            text,
            "  angle between the heading and upstream: {} deg",
            show(round(upstream))
        );
    }
    let _ = writeln!(
        text,
        "ground speed {} {unit} along the track (current: {} {unit} along, {} {unit} across)",
        show(round(r.ground_speed)),
        show(round(r.current_along_track)),
        show(round(r.current_across_track))
    );
    text
}

fn round(x: f64) -> f64 {
    let p = 10f64.powi(6 - x.abs().max(1e-300).log10().ceil() as i32);
    (x * p).round() / p
}

/// Components with one unit written after the last (`"2, 1 m/s"`), or each with its own.
fn vector(text: &str, flag: &str) -> Result<Vec<f64>> {
    let items = split_top_level(text, ',');
    if !(1..=3).contains(&items.len()) {
        bail!("{flag} `{text}` needs 1 to 3 components, e.g. \"2, 1 m/s\"");
    }
    let unit = items[items.len() - 1]
        .trim_start_matches(|c: char| c.is_ascii_digit() || "+-.eE ".contains(c))
        .trim();
    items
        .iter()
        .map(|c| {
            if c.parse::<f64>().is_ok() && !unit.is_empty() {
                speed(&format!("{c} {unit}"), flag)
            } else {
                speed(c, flag)
            }
        })
        .collect()
}

fn velocity(args: &RelativeArgs, v_text: &str, unit: &SpeedUnit) -> Result<VelocityReport> {
    let v = vector(v_text, "--velocity")?;
    let (u_text, flag, frame) = match (&args.frame_velocity, &args.relative_to) {
        (Some(u), _) => (u, "--frame-velocity", Frame::Ground),
        (None, Some(u)) => (u, "--relative-to", Frame::Observer),
        (None, None) => bail!(
            "--velocity needs --frame-velocity (it was measured in a moving frame: the result is over the ground) or --relative-to (an observer's velocity: the result is as the observer sees it)"
        ),
    };
    let u = vector(u_text, flag)?;
    transform(&v, &u, frame, unit).map_err(|e| match e {
        RelativeError::Components { velocity, frame } => anyhow!(
            "--velocity has {} and {flag} {}: give both in the same dimensions",
            components(velocity),
            components(frame)
        ),
        e => anyhow!("{flag}: {e}"),
    })
}

fn velocity_text(r: &VelocityReport) -> String {
    let unit = &r.unit;
    let ground = r.frame == "ground";
    let words: Vec<String> = r.velocity.iter().map(|&x| show(round(x))).collect();
    let mut text = format!(
        "velocity {} ({}): ({}) {unit}, speed {} {unit}",
        if ground {
            "over the ground"
        } else {
            "relative to the observer"
        },
        if ground { "v + u" } else { "v − u" },
        words.join(", "),
        show(round(r.speed))
    );
    if let Some(angle) = r.angle_deg {
        let _ = write!(text, ", direction {} deg from +x", show(round(angle)));
    }
    text.push('\n');
    text
}
