//! `mechkit relative`: steering through a moving medium and the Galilean transformation of
//! velocities, through `mechkit::relative`.

use std::fmt::Write as _;

use anyhow::{Result, anyhow, bail};
use mechkit::relative::{RelativeError, steer, velocity_in_a, velocity_in_b};
use mechkit::units::Dimension;
use serde_json::{Value, json};

use super::input::{output_unit, quantity, show, split_top_level};
use super::{Outcome, print};
use crate::args::RelativeArgs;

pub fn relative(args: &RelativeArgs) -> Result<Outcome> {
    let (scale, unit) = output_unit(
        args.unit.as_deref(),
        Dimension::VELOCITY,
        ("m/s", "a unit of speed", "--in km/h or --in knot"),
        false,
    )?;
    let (body, text) = if args.speed.is_some() {
        match steering(args, scale, &unit)? {
            Ok(found) => found,
            Err(e) => {
                // a well-posed question without an answer: the computation fails
                eprintln!("error: {e}");
                return Ok(Outcome::ComputationFailed);
            }
        }
    } else if let Some(v) = &args.velocity {
        transform(args, v, scale, &unit)?
    } else {
        bail!(
            "say what to compute: --speed with --current and --track (the heading through a wind or a current), or --velocity with --frame-velocity or --relative-to (a velocity in another frame)"
        );
    };
    if args.json {
        print(&format!("{body:#}\n"))?;
    } else {
        print(&text)?;
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

fn unit_vector(angle: f64) -> [f64; 2] {
    // exact for the compass directions
    let (s, c) = angle.sin_cos();
    let clean = |x: f64| if x.abs() < 1e-15 { 0.0 } else { x };
    [clean(c), clean(s)]
}

fn speed(text: &str, flag: &str) -> Result<f64> {
    let v = quantity(text, flag, Dimension::VELOCITY)?;
    if !v.is_finite() {
        bail!("{flag} `{text}` is not a finite speed");
    }
    Ok(v)
}

/// Bearing in degrees counter-clockwise from east, in [0, 360).
fn angle_of(v: [f64; 2]) -> f64 {
    let a = v[1].atan2(v[0]).to_degrees();
    if a < 0.0 { a + 360.0 } else { a }
}

/// The steering answer, or why there is none (the outer error is bad input).
fn steering(
    args: &RelativeArgs,
    scale: f64,
    unit: &str,
) -> Result<Result<(Value, String), RelativeError>> {
    let s = speed(args.speed.as_deref().unwrap_or_default(), "--speed")?;
    let c = speed(args.current.as_deref().unwrap_or_default(), "--current")?;
    let c_dir = match &args.current_direction {
        Some(d) => direction(d, "--current-direction")?,
        None => 0.0,
    };
    let track = direction(args.track.as_deref().unwrap_or_default(), "--track")?;
    let current = unit_vector(c_dir).map(|x| x * c);
    let st = match steer(s, current, unit_vector(track)) {
        Ok(st) => st,
        Err(e) => return Ok(Err(e)),
    };
    let heading_deg = angle_of(st.heading);
    let upstream = st.angle_to_upstream.to_degrees();
    let body = json!({
        "unit": unit,
        "speed": s / scale,
        "current": current.map(|x| x / scale),
        "heading": st.heading,
        "heading_deg": heading_deg,
        "correction_deg": st.correction.to_degrees(),
        "angle_to_upstream_deg": if upstream.is_finite() { json!(upstream) } else { Value::Null },
        "ground_velocity": st.ground_velocity.map(|x| x / scale),
        "ground_speed": st.ground_speed / scale,
        "current_along_track": st.along / scale,
        "current_across_track": st.across / scale,
    });
    let mut text = String::new();
    let _ = writeln!(
        text,
        "heading {} deg from east ({} deg {} of the track)",
        show(round(heading_deg)),
        show(round(st.correction.to_degrees().abs())),
        if st.correction >= 0.0 {
            "left"
        } else {
            "right"
        }
    );
    if upstream.is_finite() {
        let _ = writeln!(
            text,
            "  angle between the heading and upstream: {} deg",
            show(round(upstream))
        );
    }
    let _ = writeln!(
        text,
        "ground speed {} {unit} along the track (current: {} {unit} along, {} {unit} across)",
        show(round(st.ground_speed / scale)),
        show(round(st.along / scale)),
        show(round(st.across / scale))
    );
    Ok(Ok((body, text)))
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

fn transform(args: &RelativeArgs, v_text: &str, scale: f64, unit: &str) -> Result<(Value, String)> {
    let v = vector(v_text, "--velocity")?;
    let (u_text, flag, forward) = match (&args.frame_velocity, &args.relative_to) {
        (Some(u), _) => (u, "--frame-velocity", true),
        (None, Some(u)) => (u, "--relative-to", false),
        (None, None) => bail!(
            "--velocity needs --frame-velocity (it was measured in a moving frame: the result is over the ground) or --relative-to (an observer's velocity: the result is as the observer sees it)"
        ),
    };
    let u = vector(u_text, flag)?;
    if u.len() != v.len() {
        bail!(
            "--velocity has {} components and {flag} {}: give both in the same dimensions",
            v.len(),
            u.len()
        );
    }
    let mut a = [0.0; 3];
    let mut b = [0.0; 3];
    a[..v.len()].copy_from_slice(&v);
    b[..u.len()].copy_from_slice(&u);
    let r = if forward {
        velocity_in_b(a, b)
    } else {
        velocity_in_a(a, b)
    };
    let r = &r[..v.len()];
    let magnitude = r.iter().map(|x| x * x).sum::<f64>().sqrt();
    let scaled: Vec<f64> = r.iter().map(|x| x / scale).collect();
    let mut body = json!({
        "unit": unit,
        "velocity": scaled,
        "speed": magnitude / scale,
        "frame": if forward { "ground" } else { "observer" },
    });
    let words: Vec<String> = scaled.iter().map(|&x| show(round(x))).collect();
    let mut text = format!(
        "velocity {} ({}): ({}) {unit}, speed {} {unit}",
        if forward {
            "over the ground"
        } else {
            "relative to the observer"
        },
        if forward { "v + u" } else { "v − u" },
        words.join(", "),
        show(round(magnitude / scale))
    );
    if r.len() >= 2 {
        let angle = angle_of([r[0], r[1]]);
        body["angle_deg"] = json!(angle);
        let _ = write!(text, ", direction {} deg from +x", show(round(angle)));
    }
    text.push('\n');
    Ok((body, text))
}
