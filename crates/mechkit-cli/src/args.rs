//! Command-line arguments, parsed into plain data (no library objects are built here).

use std::path::PathBuf;

use clap::{Parser, Subcommand};

const EXAMPLES: &str = "\
Examples:
  mechkit run examples/feather.toml --out out/feather
      simulate, write out/feather/trajectory.csv, summary.json and SVG plots
  mechkit run examples/kepler.toml --json
      print the summary as JSON
  mechkit check examples/projectile_drag.toml
      validate a scenario without running it
  mechkit list-integrators

Exit codes: 0 success, 1 the computation failed (e.g. diverged), 2 bad input.
Scenario format: docs/scenario.md. Commands: docs/cli.md.";

/// Computational classical mechanics: simulate scenario files with units and formulas, and
/// report trajectories, plots and the energy ledger.
#[derive(Debug, Parser)]
#[command(
    name = "mechkit",
    version,
    about = "Computational classical mechanics: simulate scenario files with units and formulas, and report trajectories, plots and the energy ledger.",
    after_help = EXAMPLES
)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Simulate a scenario: trajectory.csv, summary.json and plots in the output directory.
    Run(RunArgs),
    /// Check a scenario file without running it.
    Check(CheckArgs),
    /// List the integration methods.
    ListIntegrators,
}

/// `mechkit run`.
#[derive(Debug, clap::Args)]
pub struct RunArgs {
    /// The scenario file (TOML).
    pub file: PathBuf,
    /// Output directory [default: out/<file name without .toml>].
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Print the summary as JSON on stdout (instead of the human summary).
    #[arg(long)]
    pub json: bool,
    /// Do not draw plots.
    #[arg(long)]
    pub no_plots: bool,
}

/// `mechkit check`.
#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// The scenario file (TOML).
    pub file: PathBuf,
}
