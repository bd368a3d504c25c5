//! `mechkit spin`: a free rigid body in 3-D, or a heavy top.

use std::path::PathBuf;

/// `mechkit spin`.
#[derive(Debug, clap::Args)]
pub struct SpinArgs {
    /// A body file (shapes, composites with holes): its principal moments about the centre of
    /// mass and its mass are used (or give --moments).
    pub file: Option<PathBuf>,
    /// Principal moments of inertia about the centre of mass "I1, I2, I3", each a number in
    /// kg*m^2 or with units, e.g. "1, 2, 3" or "2 g*cm^2, 3 g*cm^2, 4 g*cm^2".
    #[arg(long, allow_hyphen_values = true, conflicts_with = "file")]
    pub moments: Option<String>,
    /// The mass [default: 1 kg with --moments]; with a body file, rescales it to this mass.
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Initial angular velocity "w1, w2, w3" in the body's coordinates (the principal axes
    /// with --moments, the file's axes with a body file), e.g. "0.01, 1, 0.01" (rad/s) or
    /// "0, 0, 3000 rpm".
    #[arg(long, allow_hyphen_values = true)]
    pub omega: String,
    /// Duration, e.g. "100 s".
    #[arg(long, allow_hyphen_values = true)]
    pub t_max: String,
    /// A heavy top: the body on a fixed pivot in uniform gravity along −z (needs --pivot).
    #[arg(long, requires = "pivot")]
    pub top: bool,
    /// The pivot "x, y, z" in the body's coordinates (from the centre of mass with --moments),
    /// e.g. "0, 0, -4 cm" for a top standing on a tip 4 cm below its centre of mass.
    #[arg(long, allow_hyphen_values = true, requires = "top")]
    pub pivot: Option<String>,
    /// Gravity along −z for --top [default: 9.81 m/s^2].
    #[arg(long, allow_hyphen_values = true, requires = "top")]
    pub g: Option<String>,
    /// Initial tilt of the body about the world x axis, e.g. "20 deg" (a number is radians).
    #[arg(long, allow_hyphen_values = true)]
    pub tilt: Option<String>,
    /// Start a symmetric top (I1 = I2, pivot on the third axis) in steady precession at --tilt:
    /// its spin is the third component of --omega, its precession rate the slow root of
    /// J1 cos θ Ω² − J3 ω3 Ω + m g ℓ = 0.
    #[arg(long, requires = "top")]
    pub steady: bool,
    /// Integration method: dop853 or dopri5 (adaptive), rk4 (fixed step, needs --dt), or
    /// splitting (exact rotations about the body axes, fixed step, needs --dt).
    #[arg(long, default_value = "dop853")]
    pub method: String,
    /// Step of rk4 and splitting, e.g. "1 ms".
    #[arg(long, allow_hyphen_values = true)]
    pub dt: Option<String>,
    /// Relative tolerance of the adaptive methods; atol is 1000 times smaller.
    #[arg(long, default_value_t = 1e-10, allow_hyphen_values = true)]
    pub rtol: f64,
    /// The frame of the angular momentum in the integrated state: world (dL/dt = τ) or body
    /// (Euler's equations).
    #[arg(long, value_parser = ["world", "body"], default_value = "world")]
    pub frame: String,
    /// Number of output intervals (CSV rows and plot points).
    #[arg(value_parser = super::whole_count, long, default_value_t = 2000, allow_hyphen_values = true)]
    pub samples: usize,
    /// Directory for spin.csv (with its units, spin.units.json) and the plots omega_t, and for
    /// a top nutation_t and precession_t (nothing is written without it).
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
