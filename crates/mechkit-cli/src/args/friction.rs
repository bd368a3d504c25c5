//! `mechkit friction`: Coulomb friction on a flat or inclined surface, and the stick-slip
//! spring-block model.

use std::path::PathBuf;

/// `mechkit friction`.
#[derive(Debug, clap::Args)]
pub struct FrictionArgs {
    /// Mass of the block, e.g. "2 kg".
    #[arg(long, allow_hyphen_values = true)]
    pub mass: String,
    /// Static friction coefficient μs.
    #[arg(
        long = "mu-s",
        allow_hyphen_values = true,
        required_unless_present = "mu"
    )]
    pub mu_s: Option<String>,
    /// Dynamic (kinetic) friction coefficient μd.
    #[arg(
        long = "mu-d",
        allow_hyphen_values = true,
        required_unless_present = "mu"
    )]
    pub mu_d: Option<String>,
    /// One coefficient for both, μs = μd.
    #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["mu_s", "mu_d"])]
    pub mu: Option<String>,
    /// Incline angle, e.g. "20 deg" (a bare number is in radians) [default: 0, flat].
    #[arg(long, allow_hyphen_values = true)]
    pub angle: Option<String>,
    /// Gravity [default: 9.81 m/s^2].
    #[arg(long, allow_hyphen_values = true)]
    pub g: Option<String>,
    /// An extra load pressing the block into the surface, e.g. "10 N" (negative pulls away).
    #[arg(long, allow_hyphen_values = true)]
    pub normal_load: Option<String>,
    /// An extra load along the surface, down the slope positive, e.g. "5 N".
    #[arg(long, allow_hyphen_values = true)]
    pub push: Option<String>,
    /// Stick-slip mode: the spring constant of a spring from the block to an anchor, e.g.
    /// "100 N/m" (the block on a flat surface).
    #[arg(long, allow_hyphen_values = true)]
    pub spring_k: Option<String>,
    /// Stick-slip: speed of the surface (a belt) under the block, e.g. "0.1 m/s" [default: 0].
    #[arg(long, allow_hyphen_values = true, requires = "spring_k")]
    pub belt_speed: Option<String>,
    /// Stick-slip: speed of the spring's anchor (the earthquake model pulls it slowly), e.g.
    /// "1 cm/s" [default: 0].
    #[arg(long, allow_hyphen_values = true, requires = "spring_k")]
    pub anchor_speed: Option<String>,
    /// Stick-slip: start position of the block (the spring's extension) [default: 0].
    #[arg(long, allow_hyphen_values = true, requires = "spring_k")]
    pub x0: Option<String>,
    /// Stick-slip: start velocity of the block [default: 0].
    #[arg(long, allow_hyphen_values = true, requires = "spring_k")]
    pub v0: Option<String>,
    /// Stick-slip: how long to simulate, e.g. "10 s".
    #[arg(long, allow_hyphen_values = true, requires = "spring_k")]
    pub t_max: Option<String>,
    /// Relative tolerance of the simulation (DOP853); atol is 1000 times smaller.
    #[arg(long, default_value_t = 1e-10, allow_hyphen_values = true)]
    pub rtol: f64,
    /// Stick-slip: directory for stick_slip.csv (with its units, stick_slip.units.json) and
    /// the plots x_t, v_t and forces_t (nothing is written without it).
    #[arg(long, short, requires = "spring_k")]
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
