//! `mechkit`: the command-line front end of the mechkit library; the command itself is
//! [`mechkit_cli::main_with_args`], which documents the exit codes (0 ok, 1 the computation
//! failed, 2 usage or I/O, 101 a bug, 130 Ctrl-C).

use std::process::ExitCode;

fn main() -> ExitCode {
    let code = mechkit_cli::main_with_args(std::env::args_os().collect());
    ExitCode::from(u8::try_from(code).unwrap_or(u8::MAX))
}
