//! `mechkit`: the command-line front end of the mechkit library.
//!
//! Exit codes:
//! - 0: success;
//! - 1: the computation failed (the simulation diverged; the output so far is kept);
//! - 2: bad input (usage, unreadable or invalid file, units, unwritable output directory).
//!
//! Errors go to stderr with their location and a hint.

mod args;
mod commands;
mod plot;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let cli = args::Cli::parse();
    match commands::dispatch(cli) {
        Ok(commands::Outcome::Success) => ExitCode::SUCCESS,
        Ok(commands::Outcome::ComputationFailed) => ExitCode::from(1),
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Whether the error is stdout closed by the reader (`mechkit … | head`): not a failure.
fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.downcast_ref::<std::io::Error>()
        .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
}
