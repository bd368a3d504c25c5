//! `mechkit terminal`: drag from a measured terminal velocity.

use std::path::PathBuf;

/// `mechkit terminal`. The terminal speed from a value (`--velocity`), a distance fallen at
/// steady speed in a time (`--distance`, `--time`), or position samples (`--data`, a line
/// fitted from `--from` on); then the drag that balances the weight: D/(m g) = 1/v_T²
/// (quadratic) or b/(m g) = 1/v_T (linear), D/m, with `--mass` the coefficient, and with
/// `--density` and `--area` (or `--radius`) the drag coefficient C_d = 2D/(ρA).
#[derive(Debug, clap::Args)]
pub struct TerminalArgs {
    /// The terminal speed, e.g. "9 m/s".
    #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["distance", "data"])]
    pub velocity: Option<String>,
    /// Distance fallen at terminal speed, e.g. "2.4 m" (with --time).
    #[arg(
        long,
        allow_hyphen_values = true,
        requires = "time",
        conflicts_with = "data"
    )]
    pub distance: Option<String>,
    /// The time of that fall, e.g. "4.8 s".
    #[arg(long, allow_hyphen_values = true, requires = "distance")]
    pub time: Option<String>,
    /// A data file of positions: time and height columns (CSV or whitespace).
    #[arg(long)]
    pub data: Option<PathBuf>,
    /// The time column of --data (name or 1-based number) [default: the first].
    #[arg(long, allow_hyphen_values = true, requires = "data")]
    pub t: Option<String>,
    /// The position column of --data [default: the second].
    #[arg(long, allow_hyphen_values = true, requires = "data")]
    pub y: Option<String>,
    /// Fit the line from this time on, once the speed is steady, e.g. "1.5 s" [default: the
    /// second half of the samples].
    #[arg(long, allow_hyphen_values = true, requires = "data")]
    pub from: Option<String>,
    /// The drag law: quadratic (F = D v²) or linear (F = b v).
    #[arg(long, default_value = "quadratic")]
    pub law: String,
    /// The body's mass, e.g. "0.057 kg": gives D (kg/m) or b (kg/s).
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Gravitational acceleration.
    #[arg(long, allow_hyphen_values = true, default_value = "9.81 m/s^2")]
    pub g: String,
    /// Density of the fluid, e.g. "1.2 kg/m^3" (with --mass and --area or --radius: C_d).
    #[arg(long, allow_hyphen_values = true, requires = "mass")]
    pub density: Option<String>,
    /// Frontal area of the body, e.g. "3.4 cm^2".
    #[arg(
        long,
        allow_hyphen_values = true,
        requires = "density",
        conflicts_with = "radius"
    )]
    pub area: Option<String>,
    /// Radius of a round body (area πr²), e.g. "3.3 cm".
    #[arg(long, allow_hyphen_values = true, requires = "density")]
    pub radius: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}
