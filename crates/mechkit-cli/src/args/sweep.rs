//! `mechkit sweep` and `mechkit sweep-merge`.

use std::path::PathBuf;

/// `mechkit sweep`.
#[derive(Debug, clap::Args)]
pub struct SweepArgs {
    /// The scenario file; the swept parameters are entries of its [constants].
    pub file: PathBuf,
    /// A swept constant: "v0=0:5:51" (51 values from 0 to 5, SI), "v0=0 km/h:18 km/h:51"
    /// (with units), "k=1,2,4" (a list) or "k=2 N/m" (one value). Repeat for a grid of all
    /// combinations (the last --set varies fastest).
    #[arg(long = "set", required = true, allow_hyphen_values = true)]
    pub set: Vec<String>,
    /// Instead of the grid, N points drawn uniformly (between a range's bounds, among a
    /// list's values) from a seeded generator.
    #[arg(value_parser = super::whole_count, long, value_name = "N", allow_hyphen_values = true)]
    pub random: Option<usize>,
    /// Seed of --random.
    #[arg(value_parser = super::whole_u64, long, default_value_t = 1, requires = "random", allow_hyphen_values = true)]
    pub seed: u64,
    /// Run only the K-th of N slices (runs with index % N == K - 1) and write
    /// sweep.partK.csv; join the parts with `mechkit sweep-merge`.
    #[arg(long, value_name = "K/N", allow_hyphen_values = true)]
    pub shard: Option<String>,
    /// Worker threads [default: all cores]; the table does not depend on it.
    #[arg(value_parser = super::whole_count, long, allow_hyphen_values = true)]
    pub threads: Option<usize>,
    /// The plot of every run drawn in one figure, e.g. "v(x)" [default: the scenario's first
    /// plot].
    #[arg(long)]
    pub plot: Option<String>,
    /// No overlay plot.
    #[arg(long, conflicts_with = "plot")]
    pub no_plots: bool,
    /// Plot files: `--format svg|png` and `--dpi`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// Output directory for sweep.csv (with sweep.units.json and sweep.manifest.json) and
    /// the plot; without it the table is printed on stdout as CSV and no file is written.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// `--json` prints what was done as JSON; `-q` hides the progress bar and the report.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit sweep-merge`.
#[derive(Debug, clap::Args)]
pub struct SweepMergeArgs {
    /// The parts: sweep.partK.csv files, or directories holding them.
    #[arg(required = true)]
    pub parts: Vec<PathBuf>,
    /// The merged table [default: sweep.csv beside the first part].
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// `--json` prints what was done as JSON.
    #[command(flatten)]
    pub report: crate::args::Report,
}
