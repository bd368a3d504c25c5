//! `mechkit run` and `mechkit check`: a scenario file.

use std::path::PathBuf;

use super::Report;

/// `mechkit run`.
#[derive(Debug, clap::Args)]
pub struct RunArgs {
    /// The scenario file (TOML).
    pub file: PathBuf,
    /// Output directory for trajectory.csv (with trajectory.units.json), summary.json and the
    /// plots; without it the run writes no file and prints its summary.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Give constants of the scenario other values, e.g. "v0=12 m/s, th=pi/6" (a quantity
    /// with units, a bare number in SI, or a formula of pi, e and the names before it).
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// `--json` prints the summary as JSON; `-q` prints nothing but warnings and errors.
    #[command(flatten)]
    pub report: Report,
    /// Do not draw plots (nor the animations of `[output] animation`).
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png` and `--dpi`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// Largest trajectory file to write, e.g. `10GB` or `500MB` (default: `[output] max_size`
    /// of the scenario, else 1 GB); the run stops cleanly with `output_limit` when it is
    /// reached.
    #[arg(long, value_name = "SIZE", allow_hyphen_values = true)]
    pub max_output: Option<String>,
    /// Instead of one run: run with each of these methods (comma-separated, e.g.
    /// "euler,euler-cromer,rk4,dopri5") and compare them with a reference solution (DOP853 at
    /// rtol 1e-12): errors, energy drift, cost; writes compare.json and plots.
    #[arg(long, value_delimiter = ',')]
    pub compare_methods: Option<Vec<String>>,
    /// With --compare-methods: the step of fixed-step methods (default: the scenario's dt),
    /// e.g. "1 ms".
    #[arg(long, requires = "compare_methods", allow_hyphen_values = true)]
    pub dt: Option<String>,
    /// With --compare-methods: rtol of adaptive methods (default: the scenario's, else 1e-6).
    #[arg(long, requires = "compare_methods", allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// With --compare-methods: atol of adaptive methods (default: the scenario's, else 1e-9).
    #[arg(long, requires = "compare_methods", allow_hyphen_values = true)]
    pub atol: Option<f64>,
}

/// `mechkit check`.
#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// The scenario file (TOML).
    pub file: PathBuf,
    /// Give constants of the scenario other values, as `run --set` does.
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// `--json` prints what the scenario sets up as JSON.
    #[command(flatten)]
    pub report: Report,
}
