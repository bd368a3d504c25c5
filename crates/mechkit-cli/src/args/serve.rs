//! `mechkit serve`: the browser app on a loopback address.

use std::path::PathBuf;

/// `mechkit serve`.
#[derive(Debug, clap::Args)]
pub struct ServeArgs {
    /// The workspace: the directory whose scenario files the app lists, opens and runs (no
    /// file outside it is read). The runs' outputs go to a temporary directory of the server.
    #[arg(long, default_value = ".")]
    pub dir: PathBuf,
    /// The port to listen on; 0 picks a free one (the URL printed first says which).
    #[arg(long, default_value_t = 8000, allow_hyphen_values = true)]
    pub port: u16,
    /// The address to listen on: a loopback address (127.0.0.1, ::1 or localhost) unless
    /// --allow-remote is given.
    #[arg(long, default_value = "127.0.0.1")]
    pub host: String,
    /// Listen on an address other machines can reach: anyone who can reach it can read the
    /// workspace's scenario files and run them.
    #[arg(long)]
    pub allow_remote: bool,
    /// Stop a run after this many seconds of wall-clock time (its outputs hold the run up to
    /// there).
    #[arg(long, default_value_t = 60.0, allow_hyphen_values = true)]
    pub max_run_seconds: f64,
    /// The largest trajectory a run may write, e.g. `100MB` (a scenario's own `[output]
    /// max_size` may only lower it).
    #[arg(
        long,
        value_name = "SIZE",
        default_value = "100MB",
        allow_hyphen_values = true
    )]
    pub max_output: String,
    /// How many runs may go on at once; more are refused until one ends.
    #[arg(long, default_value_t = 2, allow_hyphen_values = true)]
    pub max_runs: usize,
    /// `--json` prints the address and the workspace as JSON (`url`, `workspace`) when the
    /// server is up; `-q` prints nothing but warnings and errors.
    #[command(flatten)]
    pub report: super::Report,
}
