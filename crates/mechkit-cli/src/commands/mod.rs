//! One module per subcommand; each is glue around a library call.

mod check;
mod run;

use crate::args::{Cli, Command};

/// How a command ended, when it did not fail on its input.
pub enum Outcome {
    /// Exit 0.
    Success,
    /// Exit 1: the computation failed; its diagnosis was already printed.
    ComputationFailed,
}

/// Runs the chosen subcommand.
pub fn dispatch(cli: Cli) -> anyhow::Result<Outcome> {
    match cli.command {
        Command::Run(args) => run::run(&args),
        Command::Check(args) => check::check(&args),
        Command::ListIntegrators => {
            for m in mechkit::ode::Method::ALL {
                println!("{:<14} {}", m.name(), m.description());
            }
            Ok(Outcome::Success)
        }
    }
}
