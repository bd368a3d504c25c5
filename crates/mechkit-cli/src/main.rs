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
    report_bugs_plainly();
    let cli = args::Cli::parse();
    // the commands whose loops look at the interrupt flag; the others end at Ctrl-C as usual
    if matches!(
        cli.command,
        args::Command::Run(_) | args::Command::Sweep(_) | args::Command::Md(_)
    ) {
        catch_interrupts();
    }
    match commands::dispatch(cli) {
        Ok(commands::Outcome::Success) => ExitCode::SUCCESS,
        Ok(commands::Outcome::ComputationFailed) => ExitCode::from(1),
        Ok(commands::Outcome::Interrupted) => ExitCode::from(EXIT_INTERRUPTED),
        Err(e) if is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// A panic is a bug in mechkit, never a fault of the input: it is reported as such in
/// mechkit's own error format, without Rust's panic message (the exit status stays 101).
fn report_bugs_plainly() {
    std::panic::set_hook(Box::new(|info| {
        let payload = info.payload();
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned());
        let at = info
            .location()
            .map(|l| format!("{}:{}", l.file(), l.line()));
        eprintln!("{}", bug_report(what.as_deref(), at.as_deref()));
    }));
}

/// The text of [`report_bugs_plainly`].
fn bug_report(what: Option<&str>, at: Option<&str>) -> String {
    format!(
        "error: internal error in mechkit {}: {}{}\n  = hint: this is a bug in mechkit, not a problem with your input; please report it with the command and the input files",
        env!("CARGO_PKG_VERSION"),
        what.unwrap_or("an unexpected failure"),
        at.map(|a| format!(" (at {a})")).unwrap_or_default()
    )
}

/// Exit status after Ctrl-C: 128 + SIGINT, as shells report a process killed by it.
const EXIT_INTERRUPTED: u8 = 130;

/// Ctrl-C (SIGINT) and SIGTERM ask the running simulation to stop after its current step
/// (`mechkit::simulate::interrupt`): it then finishes its outputs and exits with 130. A second
/// Ctrl-C exits at once.
fn catch_interrupts() {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let flag = mechkit::simulate::interrupt::flag();
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

#[cfg(test)]
mod tests {
    #[test]
    fn a_bug_is_reported_as_mechkits_error_not_as_a_rust_panic() {
        let text = super::bug_report(Some("index out of bounds"), Some("src/x.rs:3"));
        assert!(text.starts_with("error: internal error in mechkit 0."));
        assert!(text.contains("index out of bounds (at src/x.rs:3)"));
        assert!(text.contains("hint: this is a bug"));
        assert!(!text.contains("panicked"));
        assert!(super::bug_report(None, None).contains("an unexpected failure\n"));
    }
}
