//! `mechkit relative`: relative velocity and the Galilean transformation.

/// `mechkit relative`. Either steer through a moving medium (`--speed`, `--current`, `--track`):
/// the heading that keeps a plane or a boat on its track over the ground, and its ground
/// speed; or transform a velocity between frames (`--velocity` with `--frame-velocity` or
/// `--relative-to`). Directions are angles counter-clockwise from +x (east), e.g. "90 deg",
/// or compass words: east, north, west, south (also ne, nw, se, sw).
#[derive(Debug, clap::Args)]
pub struct RelativeArgs {
    /// The craft's speed relative to the medium (airspeed, speed through the water), e.g.
    /// "300 km/h".
    #[arg(long, allow_hyphen_values = true, requires_all = ["current", "track"])]
    pub speed: Option<String>,
    /// The medium's speed over the ground (wind, river current), e.g. "60 km/h".
    #[arg(long, allow_hyphen_values = true, requires = "speed")]
    pub current: Option<String>,
    /// The direction the medium moves towards, e.g. "east" or "0 deg" [default: east].
    #[arg(long, allow_hyphen_values = true, requires = "current")]
    pub current_direction: Option<String>,
    /// The direction to travel over the ground, e.g. "north" or "90 deg".
    #[arg(long, allow_hyphen_values = true, requires = "speed")]
    pub track: Option<String>,
    /// A velocity, components with a unit, e.g. "2, 1 m/s" (or a speed with --direction).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "speed")]
    pub velocity: Option<String>,
    /// The velocity of the frame --velocity is measured in, relative to the ground: the
    /// result is the velocity over the ground, v + u.
    #[arg(
        long,
        allow_hyphen_values = true,
        requires = "velocity",
        conflicts_with = "relative_to"
    )]
    pub frame_velocity: Option<String>,
    /// The velocity of an observer: the result is --velocity (measured on the ground) as the
    /// observer sees it, v − u.
    #[arg(long, allow_hyphen_values = true, requires = "velocity")]
    pub relative_to: Option<String>,
    /// Unit of the speeds in the output, e.g. "km/h" [default: m/s].
    #[arg(long = "in", value_name = "UNIT")]
    pub unit: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}
