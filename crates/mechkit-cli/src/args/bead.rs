//! `mechkit bead`: a body constrained to a curve.

use std::path::PathBuf;

/// `mechkit bead`.
#[derive(Debug, clap::Args)]
pub struct BeadArgs {
    /// A circle of this radius about the origin, e.g. "1 m".
    #[arg(long, allow_hyphen_values = true, conflicts_with = "curve")]
    pub circle: Option<String>,
    /// A curve y(x), e.g. "x^2/2" or "sqrt(R^2 - x^2)" (with --set R=1).
    #[arg(long, allow_hyphen_values = true)]
    pub curve: Option<String>,
    /// Values of the curve's other names, e.g. "R=1 m".
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// Which side the body is on: outside/above (it can leave upward or outward), inside/below,
    /// or bead (threaded: never leaves).
    #[arg(long, default_value = "bead")]
    pub side: String,
    /// Start: the angle from the top of the circle, clockwise (e.g. "0 deg", "180 deg" for the
    /// bottom), or x on the curve (e.g. "1 m").
    #[arg(long, allow_hyphen_values = true, default_value = "0")]
    pub start: String,
    /// Initial speed along the curve, positive towards increasing x (clockwise on a circle),
    /// e.g. "2 m/s".
    #[arg(long, allow_hyphen_values = true, default_value = "0")]
    pub speed: String,
    /// Instead of --speed: the height above the start from which the body was released at
    /// rest, v = √(2 g h) towards increasing x (use --speed for the other direction).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "speed")]
    pub drop_height: Option<String>,
    /// Mass (only the normal force depends on it).
    #[arg(long, allow_hyphen_values = true, default_value = "1 kg")]
    pub mass: String,
    /// Gravitational acceleration.
    #[arg(long, allow_hyphen_values = true, default_value = "9.81 m/s^2")]
    pub g: String,
    /// How long to follow the motion, e.g. "5 s".
    #[arg(long, allow_hyphen_values = true)]
    pub t_max: String,
    /// Relative tolerance of the integration (Dormand-Prince 5(4)).
    #[arg(long, default_value_t = 1e-10, allow_hyphen_values = true)]
    pub rtol: f64,
    /// Directory for path.csv (with its units, path.units.json) and the plot path.svg
    /// (nothing is written without it).
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw the plot (with --out, only the CSV).
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png` and `--dpi`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}
