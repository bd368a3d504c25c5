//! `mechkit`: the command-line front end of the mechkit library.
//!
//! Exit codes:
//! - 0: success;
//! - 1: the computation failed (the simulation diverged; the output so far is kept);
//! - 2: bad input (usage, unreadable or invalid file, units, unwritable output directory);
//! - 101: an internal error (a bug), reported as `error: internal error, …`.
//!
//! Errors go to stderr with their location and a hint (`failure.rs`).

mod args;
mod commands;
mod failure;
mod gallery;
mod plot;

use std::process::ExitCode;

use clap::Parser;
use mechkit::simulate::Cancel;

fn main() -> ExitCode {
    failure::install_panic_hook();
    let cli = args::Cli::parse();
    let cancel = Cancel::new();
    // the commands whose loops look at the handle; the others end at Ctrl-C as usual
    if matches!(
        cli.command,
        args::Command::Run(_) | args::Command::Sweep(_) | args::Command::Md(_)
    ) {
        catch_interrupts(&cancel);
    }
    match commands::dispatch(cli, &cancel) {
        Ok(commands::Outcome::Success) => ExitCode::SUCCESS,
        Ok(commands::Outcome::ComputationFailed) => ExitCode::from(1),
        Ok(commands::Outcome::Interrupted) => ExitCode::from(EXIT_INTERRUPTED),
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", failure::message(&e));
            ExitCode::from(2)
        }
    }
}

/// Exit status after Ctrl-C: 128 + SIGINT, as shells report a process killed by it.
const EXIT_INTERRUPTED: u8 = 130;

/// Ctrl-C (SIGINT) and SIGTERM raise `cancel`, which asks the running simulation to stop
/// after its current step: it then finishes its outputs and exits with 130. A second Ctrl-C
/// exits at once.
fn catch_interrupts(cancel: &Cancel) {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let flag = cancel.flag();
    for signal in [SIGINT, SIGTERM] {
        // the conditional exit first: it sees the flag as the previous signal left it
        let registered = signal_hook::flag::register_conditional_shutdown(
            signal,
            i32::from(EXIT_INTERRUPTED),
            std::sync::Arc::clone(&flag),
        )
        .and_then(|_| signal_hook::flag::register(signal, std::sync::Arc::clone(&flag)));
        if let Err(e) = registered {
            eprintln!("warning: Ctrl-C will end mechkit without finishing its outputs ({e})");
        }
    }
}

/// Whether the error is stdout closed by the reader (`mechkit … | head`): not a failure.
fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.downcast_ref::<std::io::Error>()
        .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
}
