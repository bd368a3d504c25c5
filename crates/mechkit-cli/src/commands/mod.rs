//! One module per subcommand; each is glue around a library call.

pub(crate) mod animate;
mod bead;
mod body;
mod calculus;
mod check;
mod collide;
mod com;
mod com_image;
mod derive;
mod dsolve;
mod friction;
mod gallery;
pub(crate) mod gallery_run;
mod inertia;
mod input;
mod md;
mod md_setup;
mod outputs;
mod potential;
mod power;
mod relative;
mod rigid_collide;
mod rigid_landing;
mod rocket;
mod roll;
mod rotation;
mod run;
mod spin;
mod sweep;
mod terminal;
mod work;
mod work_field;

use std::fmt::Write as _;

use mechkit::simulate::Cancel;

use crate::args::{Cli, Command};

/// How a command ended, when it did not fail on its input.
pub enum Outcome {
    /// Exit 0.
    Success,
    /// Exit 1: the computation failed; its diagnosis was already printed.
    ComputationFailed,
    /// Exit 130: stopped by Ctrl-C after writing what was computed.
    Interrupted,
}

/// Runs the chosen subcommand; `cancel` (raised by Ctrl-C) stops the loops of `run`, `sweep`
/// and `md`, and ends `serve`.
pub fn dispatch(cli: Cli, cancel: &Cancel) -> anyhow::Result<Outcome> {
    match cli.command {
        Command::Run(args) => run::run(&args, cancel),
        Command::Check(args) => check::check(&args),
        Command::Animate(args) => animate::animate(&args),
        Command::Serve(args) => crate::serve::serve(&args, cancel),
        Command::Diff(args) => calculus::diff(&args),
        Command::Integrate(args) => calculus::integrate(&args),
        Command::Solve(args) => calculus::solve(&args),
        Command::Dsolve(args) => dsolve::dsolve(&args),
        Command::Units(args) => calculus::units(&args),
        Command::Potential(args) => potential::potential(&args),
        Command::Power(args) => power::power(&args),
        Command::Rocket(args) => rocket::rocket(&args),
        Command::Spin(args) => spin::spin(&args),
        Command::Md(args) => md::md(&args, cancel),
        Command::Work(args) => work::work(&args),
        Command::Derive(args) => derive::derive(&args),
        Command::Collide(args) => collide::collide(&args),
        Command::Com(args) => com::com(&args),
        Command::Inertia(args) => inertia::inertia(&args),
        Command::Impulse(args) => work::impulse(&args),
        Command::Friction(args) => friction::friction(&args),
        Command::Roll(args) => roll::roll(&args),
        Command::Rotation(args) => rotation::rotation(&args),
        Command::Relative(args) => relative::relative(&args),
        Command::Terminal(args) => terminal::terminal(&args),
        Command::Bead(args) => bead::bead(&args),
        Command::RigidCollide(args) => rigid_collide::rigid_collide(&args),
        Command::Sweep(args) => sweep::sweep(&args, cancel),
        Command::SweepMerge(args) => sweep::sweep_merge(&args),
        Command::Gallery(args) => gallery::gallery(&args),
        Command::ListIntegrators(args) => {
            let methods = mechkit::ode::Method::catalogue();
            report(args.report, &methods, || {
                let mut text = String::new();
                for m in &methods {
                    let _ = writeln!(
                        text,
                        "{:<12} {:<10} order {}  {}",
                        m.name, m.kind, m.order, m.description
                    );
                }
                text.push_str(
                    "\nadaptive methods take rtol/atol (or a fixed dt); symplectic ones need forces of position and time only; implicit ones (stiff systems) take rtol/atol only\n",
                );
                text
            })?;
            Ok(Outcome::Success)
        }
        Command::Completions(args) => {
            let mut cmd = <Cli as clap::CommandFactory>::command();
            let mut out = Vec::new();
            clap_complete::generate(args.shell, &mut cmd, "mechkit", &mut out);
            let script = String::from_utf8_lossy(&out).into_owned();
            if args.report.json {
                report(
                    args.report,
                    &Completion {
                        shell: args.shell.to_string(),
                        script,
                    },
                    String::new,
                )?;
            } else {
                print(&script)?;
            }
            Ok(Outcome::Success)
        }
        Command::Man(args) => man(&args),
    }
}

/// What `mechkit completions SHELL --json` prints.
#[derive(serde::Serialize)]
struct Completion {
    shell: String,
    script: String,
}

/// `mechkit man`: the manual page on stdout, or `mechkit.1` and a page per command in `-o DIR`.
fn man(args: &crate::args::ManArgs) -> anyhow::Result<Outcome> {
    use anyhow::Context as _;
    let cmd = <Cli as clap::CommandFactory>::command();
    let page = |c: clap::Command, title: &str| -> anyhow::Result<Vec<u8>> {
        let mut out = Vec::new();
        clap_mangen::Man::new(c)
            .title(title.to_string())
            .render(&mut out)?;
        Ok(out)
    };
    let Some(dir) = &args.out else {
        print(&String::from_utf8_lossy(&page(cmd, "mechkit")?))?;
        return Ok(Outcome::Success);
    };
    std::fs::create_dir_all(dir)
        .with_context(|| format!("cannot create the output directory {}", dir.display()))?;
    let mut written = vec![dir.join("mechkit.1")];
    mechkit::csv::write_atomic(&written[0], &page(cmd.clone(), "mechkit")?)
        .with_context(|| format!("cannot write {}", written[0].display()))?;
    for sub in cmd.get_subcommands() {
        let name = format!("mechkit-{}", sub.get_name());
        let path = dir.join(format!("{name}.1"));
        mechkit::csv::write_atomic(&path, &page(sub.clone(), &name)?)
            .with_context(|| format!("cannot write {}", path.display()))?;
        written.push(path);
    }
    note(
        args.report,
        &format!(
            "wrote {} manual pages into {}",
            written.len(),
            dir.display()
        ),
    );
    Ok(Outcome::Success)
}

/// Prints a command's result: its JSON with `--json`, else the text report unless `--quiet`.
/// `value` is the library's result type; its JSON shape is defined there.
///
/// The finiteness rule: a result that holds an infinity or NaN is not printed at all (in
/// either form); the error ([`mechkit::finite::NonFinite`], exit 1) names the quantity.
pub fn report<T: serde::Serialize>(
    flags: crate::args::Report,
    value: &T,
    text: impl FnOnce() -> String,
) -> anyhow::Result<()> {
    mechkit::finite::check_finite(value)?;
    report_summary(flags, value, text)
}

/// [`report`] for a scenario run's summary, the documented exception to the finiteness rule:
/// a summary value that is NaN or infinite (the work of a force on a run that diverged, an
/// observable of an empty run) is written as `null` (docs/scenario.md, "summary.json"), and a
/// run that failed says so itself (exit 1).
pub fn report_summary<T: serde::Serialize>(
    flags: crate::args::Report,
    value: &T,
    text: impl FnOnce() -> String,
) -> anyhow::Result<()> {
    if flags.json {
        let mut json = serde_json::to_string_pretty(value)?;
        json.push('\n');
        print(&json)?;
    } else if !flags.quiet {
        print(&text())?;
    }
    Ok(())
}

/// Prints a note for the user on stderr (where files went, what was skipped), unless
/// `--quiet`. Warnings are not notes: they always print.
pub fn note(flags: crate::args::Report, text: &str) {
    if !flags.quiet {
        eprintln!("{text}");
    }
}

/// Writes to stdout. A closed pipe (`mechkit … | head`) is an `io::Error` of kind
/// `BrokenPipe`, which `main` treats as a quiet success.
pub fn print(text: &str) -> std::io::Result<()> {
    use std::io::Write as _;
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.flush()
}
