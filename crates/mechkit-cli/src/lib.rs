//! `mechkit`: the command-line front end of the mechkit library, as a library so that other
//! fronts (the Python package's `mechkit` console script) run the same command in-process,
//! and draw plots as the command does ([`plot_svg`], [`plot_png`]: the Python package's
//! `Run.plot`), and draws animations ([`animate`]: SVG frames, GIF, MP4, an HTML player).
//!
//! Exit codes:
//! - 0: success;
//! - 1: the computation failed (the simulation diverged; the output so far is kept; an
//!   answer that is not a finite number, which is never printed);
//! - 2: bad input (usage, unreadable or invalid file, units, unwritable output directory);
//! - 101: an internal error (a bug), reported as `error: internal error, …`;
//! - 130: stopped by Ctrl-C (SIGINT) or SIGTERM after finishing the outputs (`serve` ends
//!   with 0 then: it is how a server ends).
//!
//! Errors go to stderr with their location and a hint (`failure.rs`).

pub mod animate;
mod args;
mod commands;
mod failure;
mod gallery;
mod plot;
mod serve;
mod xml;

use std::ffi::OsString;
use std::io::Write as _;

use clap::Parser;
use mechkit::simulate::Cancel;

pub use args::PlotStyle;
pub use plot::PNG_DPI;
pub use serve::routes as serve_routes;

/// The SVG text of `plot` as `mechkit` draws it into a file (`mechkit run -o DIR` writes the
/// same bytes to `DIR/v_x.svg`): titled `title` (a run's plots: the scenario's title), in
/// `style` (`--style`). Fails only if drawing fails (a bug).
pub fn plot_svg(
    plot: &mechkit::figure::PlotData,
    title: &str,
    style: PlotStyle,
) -> anyhow::Result<String> {
    plot::svg(plot, title, style)
}

/// The PNG of `plot` as `mechkit` writes it with `--format png --dpi DPI`: [`plot_svg`]'s
/// drawing rasterised at `dpi` dots per inch (96: the SVG's own 900x600 pixels), which must
/// be within [`PNG_DPI`].
pub fn plot_png(
    plot: &mechkit::figure::PlotData,
    title: &str,
    style: PlotStyle,
    dpi: u32,
) -> anyhow::Result<Vec<u8>> {
    plot::png(plot, title, style, dpi)
}

/// Runs the command line `args` (the program name first, as [`std::env::args_os`] gives it)
/// and returns the exit status. Everything is printed as the `mechkit` binary prints it; a
/// panic (a bug) is reported by a panic hook as `error: internal error, …` and unwinds to the
/// caller, which exits with 101.
///
/// For `run`, `sweep`, `md` and `serve`, Ctrl-C and SIGTERM are caught while the command runs
/// (by a thread; the handlers chain to those installed before, and are removed on return):
/// see `Interrupts`.
pub fn main_with_args(args: Vec<OsString>) -> i32 {
    failure::install_panic_hook();
    let cli = match args::Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            // what clap's `exit` does, without ending the process: help and version on
            // stdout (status 0), usage errors on stderr (status 2)
            let _ = e.print();
            flush();
            return e.exit_code();
        }
    };
    // no output of the command replaces a file it read (`-o DIR` holding a fixed name); the
    // server writes only into its own directories, and would note every file it ever read
    let _inputs =
        (!matches!(cli.command, args::Command::Serve(_))).then(mechkit::csv::InputGuard::hold);
    let cancel = Cancel::new();
    // the commands whose loops look at the handle; the others end at Ctrl-C as usual
    let interrupts = if matches!(
        cli.command,
        args::Command::Run(_)
            | args::Command::Sweep(_)
            | args::Command::Md(_)
            | args::Command::Serve(_)
    ) {
        Interrupts::catch(&cancel)
    } else {
        None
    };
    let code = match commands::dispatch(cli, &cancel) {
        Ok(commands::Outcome::Success) => 0,
        Ok(commands::Outcome::ComputationFailed) => 1,
        Ok(commands::Outcome::Interrupted) => EXIT_INTERRUPTED,
        Err(e) if is_broken_pipe(&e) => 0,
        Err(e) if e.downcast_ref::<mechkit::finite::NonFinite>().is_some() => {
            // the computation ran, and its answer is not a number: exit 1 (the finiteness
            // rule), not 2 (bad input)
            eprintln!(
                "error: {}\n  = hint: the inputs are too large or too close to a singularity \
                 for a finite answer in double precision; rescale them (other units) or move \
                 away from the singular point",
                failure::message(&e)
            );
            1
        }
        Err(e) => {
            eprintln!("error: {}", failure::message(&e));
            2
        }
    };
    if let Some(i) = interrupts {
        i.release();
    }
    flush();
    code
}

/// Hands what is buffered for stdout to the operating system: a process ends by returning
/// from `main`, which does this, but a caller in another language may not.
fn flush() {
    let _ = std::io::stdout().flush();
}

/// Exit status after Ctrl-C: 128 + SIGINT, as shells report a process killed by it.
const EXIT_INTERRUPTED: i32 = 130;

/// Ctrl-C (SIGINT) and SIGTERM, caught by a thread while a command runs:
/// - the first Ctrl-C raises `cancel`: the running simulation stops after its current step,
///   then finishes its outputs (streamed files, summary, plots) and exits with 130;
/// - a second Ctrl-C, or SIGTERM, raises it urgently ([`Cancel::cancel_urgently`]): the
///   streamed files are still closed at a whole row and renamed, and the summary written,
///   but plots and animations are skipped, so the process ends at once;
/// - a third signal exits at once (130), finishing nothing.
struct Interrupts {
    handle: signal_hook::iterator::Handle,
    thread: std::thread::JoinHandle<()>,
}

impl Interrupts {
    fn catch(cancel: &Cancel) -> Option<Self> {
        use signal_hook::consts::{SIGINT, SIGTERM};
        let mut signals = match signal_hook::iterator::Signals::new([SIGINT, SIGTERM]) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("warning: Ctrl-C will end mechkit without finishing its outputs ({e})");
                return None;
            }
        };
        let handle = signals.handle();
        let cancel = cancel.clone();
        let thread = std::thread::spawn(move || {
            let mut urgent = false;
            for signal in signals.forever() {
                if urgent {
                    std::process::exit(EXIT_INTERRUPTED);
                }
                if signal == SIGTERM || cancel.is_cancelled() {
                    urgent = true;
                    cancel.cancel_urgently();
                } else {
                    cancel.cancel();
                }
            }
        });
        Some(Self { handle, thread })
    }

    /// Stops catching the signals (the handlers installed before are in force again).
    fn release(self) {
        self.handle.close();
        let _ = self.thread.join();
    }
}

/// Whether the error is stdout closed by the reader (`mechkit … | head`): not a failure.
fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.downcast_ref::<std::io::Error>()
        .is_some_and(|io| io.kind() == std::io::ErrorKind::BrokenPipe)
}
