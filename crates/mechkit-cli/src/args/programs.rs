//! The commands about the program itself: `list-integrators`, `completions` and `man`.

use std::path::PathBuf;

use super::Report;

/// `mechkit list-integrators`.
#[derive(Debug, clap::Args)]
pub struct ListArgs {
    /// `--json`, `-q`.
    #[command(flatten)]
    pub report: Report,
}

/// `mechkit completions`.
#[derive(Debug, clap::Args)]
pub struct CompletionsArgs {
    /// The shell.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
    /// `--json` prints `{"shell": …, "script": …}`; the script is printed even with `-q`.
    #[command(flatten)]
    pub report: Report,
}

/// `mechkit man`.
#[derive(Debug, clap::Args)]
pub struct ManArgs {
    /// Directory for `mechkit.1` and the commands' pages (default: print `mechkit.1` on stdout).
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// `--json`, `-q`.
    #[command(flatten)]
    pub report: Report,
}
