//! `mechkit roll`: a sphere, cylinder or hoop rolling and slipping on an incline.

use std::path::PathBuf;

/// `mechkit roll`.
#[derive(Debug, clap::Args)]
pub struct RollArgs {
    /// The body: sphere, hollow-sphere, cylinder, hoop, or the inertia factor k = I/(m R²)
    /// as a number (e.g. 0.4).
    #[arg(long, default_value = "sphere")]
    pub body: String,
    /// Radius of the body (its contact circle), e.g. "11 cm".
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<String>,
    /// Mass, e.g. "0.45 kg".
    #[arg(long, allow_hyphen_values = true)]
    pub mass: String,
    /// Slope angle, e.g. "20 deg" (a bare number is in radians) [default: 0, flat floor].
    #[arg(long, allow_hyphen_values = true)]
    pub slope: Option<String>,
    /// One friction coefficient for sticking and slipping, μs = μd.
    #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["mu_s", "mu_d"])]
    pub mu: Option<String>,
    /// Static friction coefficient μs (with --mu-d).
    #[arg(long = "mu-s", allow_hyphen_values = true, requires = "mu_d")]
    pub mu_s: Option<String>,
    /// Dynamic friction coefficient μd (with --mu-s).
    #[arg(long = "mu-d", allow_hyphen_values = true, requires = "mu_s")]
    pub mu_d: Option<String>,
    /// Start speed along the slope, down positive, e.g. "2 m/s" [default: 0].
    #[arg(long, allow_hyphen_values = true)]
    pub v0: Option<String>,
    /// Start angular velocity, forward (rolling down) positive; negative is backspin, e.g.
    /// "-30 rad/s" [default: 0].
    #[arg(long, allow_hyphen_values = true)]
    pub omega0: Option<String>,
    /// Gravity [default: 9.81 m/s^2].
    #[arg(long, allow_hyphen_values = true)]
    pub g: Option<String>,
    /// How long to simulate, e.g. "3 s".
    #[arg(long, allow_hyphen_values = true)]
    pub t_max: String,
    /// Relative tolerance of the simulation (DOP853); atol is 1000 times smaller.
    #[arg(long, default_value_t = 1e-10, allow_hyphen_values = true)]
    pub rtol: f64,
    /// Directory for roll.csv (with its units, roll.units.json) and the plots v_t (v and ωR)
    /// and energy_t (nothing is written without it).
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw plots (with --out, only the CSV).
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png` and `--dpi`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}
