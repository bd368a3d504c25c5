//! The `command_line` target: a whole `mechkit` command line, run in-process by
//! [`mechkit_cli::main_with_args`] (clap's parse, the command's own value parsers, the
//! library calls, the files it writes and every error as the CLI prints it).
//!
//! The input is structured:
//! - byte 0 picks the subcommand ([`SUBCOMMANDS`], modulo its length);
//! - the bytes up to the first NUL are the arguments, one per line;
//! - the bytes after the first NUL, if any, are the content of an input file, written as
//!   `in.toml`, `in.csv` and `in.png` in the command's working directory, so that the
//!   arguments can name it.
//!
//! The command runs in a private working directory ([`Workdir`]); an argument that could
//! name a path outside it (absolute, `..`) skips the input. The target clamps the options
//! that set how much work a command does (steps, cells, samples, times, frames, resolution)
//! and a scenario's `[stop] max_steps` and `[output] max_size`, so that every input runs in
//! well under a second; the product's own bounds are much larger (10^9 steps).
//! The files a command writes are not checked for non-finite numbers: the CSV files of the
//! documentation's own command lines hold `NaN` and `inf` cells (`potential.csv`, `path.csv`,
//! `power.csv`, `work.csv`), so such a check needs a rule per file of which cells are
//! answers. What the target finds is a panic, a hang or an allocation above the bounds.

use std::ffi::OsString;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use mechkit::scenario::sweep::{Parameter, Sampling, SweepGrid};
use mechkit::units::Quantity;

/// The subcommands the first byte chooses from: every one but `serve` (a server that runs
/// until stopped; its handlers have their own target, [`crate::browser()`]).
pub const SUBCOMMANDS: &[&str] = &[
    "run",
    "check",
    "animate",
    "list-integrators",
    "diff",
    "integrate",
    "solve",
    "units",
    "potential",
    "power",
    "rocket",
    "derive",
    "spin",
    "md",
    "collide",
    "impulse",
    "com",
    "inertia",
    "rotation",
    "relative",
    "terminal",
    "bead",
    "rigid-collide",
    "work",
    "friction",
    "roll",
    "sweep",
    "sweep-merge",
    "gallery",
    "completions",
    "man",
];

/// The most arguments the target passes on (the subcommand included).
const MAX_ARGS: usize = 24;

/// Steps of a scenario run by the target (`[stop] max_steps` is lowered to this).
pub const COMMAND_STEPS: u64 = 200;

/// How an option's value is clamped: `(flag, lowest, highest)` of its value in SI (a bare
/// number, or a quantity with units); a value outside is replaced by the bound.
const CLAMPS: &[(&str, f64, f64)] = &[
    ("--steps", 0.0, 200.0),
    ("--cells", 0.0, 4.0),
    ("--threads", 0.0, 2.0),
    ("--samples", 0.0, 2000.0),
    ("--random", 0.0, 4.0),
    ("--t-max", f64::NEG_INFINITY, 100.0),
    ("--time", f64::NEG_INFINITY, 1e4),
    ("--dt", 1e-4, f64::INFINITY),
    ("--rtol", 1e-8, f64::INFINITY),
    ("--atol", 1e-12, f64::INFINITY),
    ("--fps", f64::NEG_INFINITY, 2.0),
    ("--width", 0.0, 96.0),
    ("--height", 0.0, 96.0),
    ("--dpi", 0.0, 48.0),
    ("--thermo-every", 1.0, f64::INFINITY),
    ("--xyz-every", 1.0, f64::INFINITY),
];

/// Options the target adds when they are not given, because their defaults take long:
/// `(subcommand, flag, value)`. `md` makes 20 cells (32,000 atoms) by default, `animate` 25
/// frames a second of 640 × 480.
const DEFAULTS: &[(&str, &str, &str)] = &[
    ("md", "--cells", "3"),
    ("animate", "--fps", "2"),
    ("animate", "--width", "96"),
    ("animate", "--height", "96"),
];

/// `integrate --n`: the most panels of one quadrature.
const MAX_PANELS: f64 = 10_000.0;

/// The most runs of a fuzzed `sweep`.
const MAX_SWEEP_RUNS: usize = 8;

/// The largest angle `|ω| t_max` (rad) a fuzzed `spin` turns through: its steps grow with it
/// (about 100 a radian at the default `rtol`), and `--t-max`'s clamp alone let a top at
/// 5,020 rad/s take 24 million steps (15 s).
const MAX_SPIN_ANGLE: f64 = 1000.0;

/// The largest angle `√(k/m) t_max` (rad) a fuzzed stick-slip `friction` run oscillates
/// through: its steps grow with it, and a spring of 3.2e19 N/m on 19 kg for 8 s used the
/// product's whole budget of 10⁶ steps (2 s in a release build, 10.7 s in the fuzz build).
const MAX_OSCILLATION_ANGLE: f64 = 1e4;

/// A command line of `mechkit`, built from the fuzzer's bytes; `None` when the bytes do not
/// make one the target runs (not UTF-8, a path outside the working directory, too much work).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CommandLine {
    /// The arguments after `mechkit`, the subcommand first.
    pub args: Vec<String>,
    /// The input file's content, written as `in.toml`, `in.csv` and `in.png`.
    pub file: Option<Vec<u8>>,
}

impl CommandLine {
    /// The command line that `data` encodes, clamped; see the module's documentation.
    #[must_use]
    pub fn from_bytes(data: &[u8]) -> Option<Self> {
        let (&pick, rest) = data.split_first()?;
        let command = SUBCOMMANDS[usize::from(pick) % SUBCOMMANDS.len()];
        let (argv, file) = match rest.iter().position(|&b| b == 0) {
            Some(i) => (&rest[..i], Some(rest[i + 1..].to_vec())),
            None => (rest, None),
        };
        let argv = std::str::from_utf8(argv).ok()?;
        let mut args = vec![command.to_string()];
        if !argv.is_empty() {
            args.extend(argv.split('\n').map(str::to_string));
        }
        if args.len() > MAX_ARGS || args.iter().any(|a| leaves_the_workdir(a)) {
            return None;
        }
        clamp(&mut args);
        for &(sub, flag, value) in DEFAULTS {
            let given = args
                .iter()
                .any(|a| a == flag || a.starts_with(&format!("{flag}=")));
            if command == sub && !given {
                args.push(flag.to_string());
                args.push(value.to_string());
            }
        }
        // an MP4 starts ffmpeg (when one is on the PATH): another process, not mechkit
        for a in &mut args {
            *a = a.replace("mp4", "gif");
        }
        if !bounded(&args) {
            return None;
        }
        let file = file.map(|f| {
            if matches!(command, "run" | "check" | "animate" | "sweep") {
                bound_scenario(&no_mp4(&f))
            } else {
                f
            }
        });
        Some(Self { args, file })
    }
}

/// Whether `arg` could name a file outside the working directory: an absolute path (also
/// after `=`, `,`, `:`, `;` or a space, or glued to a short option, `-o/x`), `..`, or `~`.
fn leaves_the_workdir(arg: &str) -> bool {
    if arg.contains("..") || arg.starts_with('~') || arg.contains('\\') {
        return true;
    }
    let bytes = arg.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        if b != b'/' {
            continue;
        }
        let before = if i == 0 { None } else { Some(bytes[i - 1]) };
        // `x/2`, `m/s`, `(a)/b`: a division; anything else may start a path
        let division = before.is_some_and(|c| c.is_ascii_alphanumeric() || b")]}_.^".contains(&c));
        if !division {
            return true;
        }
    }
    // a short option with its value glued on: `-o/x`, `-qo/x`
    let letters = arg
        .strip_prefix('-')
        .map_or(0, |r| r.bytes().take_while(u8::is_ascii_alphabetic).count());
    letters > 0 && bytes.get(1 + letters) == Some(&b'/')
}

/// Replaces the values of the options in [`CLAMPS`] (as `--flag VALUE` or `--flag=VALUE`)
/// that lie outside their bounds by the bound, and each of `--n`'s panel counts above
/// [`MAX_PANELS`].
fn clamp(args: &mut [String]) {
    for i in 0..args.len() {
        let (flag, value, glued) = match args[i].split_once('=') {
            Some((f, v)) if f.starts_with("--") => (f.to_string(), v.to_string(), true),
            _ if i + 1 < args.len() => (args[i].clone(), args[i + 1].clone(), false),
            _ => continue,
        };
        let new = if flag == "--n" {
            Some(
                value
                    .split(',')
                    .map(|n| match n.trim().parse::<f64>() {
                        Ok(x) if x > MAX_PANELS => MAX_PANELS.to_string(),
                        _ => n.to_string(),
                    })
                    .collect::<Vec<_>>()
                    .join(","),
            )
        } else {
            CLAMPS
                .iter()
                .find(|(f, _, _)| *f == flag)
                .and_then(|&(_, lo, hi)| clamped(&value, lo, hi))
        };
        if let Some(new) = new {
            if glued {
                args[i] = format!("{flag}={new}");
            } else {
                args[i + 1] = new;
            }
        }
    }
}

/// The SI value of a bare number or a quantity; `None` when it is neither.
fn si(value: &str) -> Option<f64> {
    match value.trim().parse::<f64>() {
        Ok(x) => Some(x),
        Err(_) => Some(Quantity::parse(value).ok()?.value),
    }
}

/// `value` clamped to `[lo, hi]` (its SI value) if it lies outside; `None` if it is inside or
/// is not a quantity (the command reports that).
fn clamped(value: &str, lo: f64, hi: f64) -> Option<String> {
    let si = si(value)?;
    if si > hi {
        Some(hi.to_string())
    } else if si < lo {
        Some(lo.to_string())
    } else if si.is_nan() {
        Some(hi.min(lo.max(1.0)).to_string())
    } else {
        None
    }
}

/// Whether the command's work is bounded by the clamps and stays in this process: `gallery`
/// runs only with `--list` (a case's script starts the current executable, here the fuzzer),
/// and sweeps of more than [`MAX_SWEEP_RUNS`] runs are skipped.
fn bounded(args: &[String]) -> bool {
    match args[0].as_str() {
        // a case runs its script by starting this program again (the fuzzer itself), and
        // `--all` runs every case: only the listing
        "gallery" => args.iter().any(|a| a == "--list"),
        "spin" => {
            let rate = option(args, "--omega").and_then(spin_rate);
            let t_max = option(args, "--t-max").and_then(si);
            rate.zip(t_max)
                .is_none_or(|(w, t)| w * t <= MAX_SPIN_ANGLE || (w * t).is_nan())
        }
        "friction" => {
            let k = option(args, "--spring-k").and_then(si);
            let m = option(args, "--mass").and_then(si);
            let t_max = option(args, "--t-max").and_then(si);
            match (k, m, t_max) {
                (Some(k), Some(m), Some(t)) => {
                    let angle = (k / m).abs().sqrt() * t.abs();
                    angle <= MAX_OSCILLATION_ANGLE || angle.is_nan()
                }
                // no spring, or a value the command refuses
                _ => true,
            }
        }
        "sweep" => {
            let mut sets = Vec::new();
            for (i, a) in args.iter().enumerate() {
                if let Some(v) = a.strip_prefix("--set=") {
                    sets.push(v.to_string());
                } else if a == "--set"
                    && let Some(v) = args.get(i + 1)
                {
                    sets.push(v.clone());
                }
            }
            let parameters: Option<Vec<Parameter>> =
                sets.iter().map(|s| Parameter::parse(s).ok()).collect();
            match parameters {
                Some(p) if !p.is_empty() => {
                    let grid = SweepGrid::new(p, Sampling::Grid);
                    grid.check().is_ok() && grid.len() <= MAX_SWEEP_RUNS
                }
                // the command refuses these before it runs anything
                _ => true,
            }
        }
        _ => true,
    }
}

/// The value of `--flag VALUE` or `--flag=VALUE` (the first given).
fn option<'a>(args: &'a [String], flag: &str) -> Option<&'a str> {
    args.iter().enumerate().find_map(|(i, a)| {
        if a == flag {
            args.get(i + 1).map(String::as_str)
        } else {
            a.strip_prefix(flag)?.strip_prefix('=')
        }
    })
}

/// `|ω|` in rad/s of `spin --omega "x, y, z [unit]"` (the unit after the last component
/// applies to the bare ones), an upper bound as the sum of the magnitudes; `None` when it
/// does not read (the command reports that).
fn spin_rate(value: &str) -> Option<f64> {
    let parts: Vec<&str> = value.split(',').map(str::trim).collect();
    let last = parts.last()?;
    let unit = last
        .trim_start_matches(|c: char| c.is_ascii_digit() || "+-.eE".contains(c))
        .trim();
    let factor = if unit.is_empty() {
        1.0
    } else {
        Quantity::parse(&format!("1 {unit}")).ok()?.value
    };
    let mut sum = 0.0;
    for p in parts {
        sum += match p.parse::<f64>() {
            Ok(x) => (x * factor).abs(),
            Err(_) => Quantity::parse(p).ok()?.value.abs(),
        };
    }
    Some(sum)
}

/// `file` with every `mp4` replaced by `gif` (`[output] animation` formats).
fn no_mp4(file: &[u8]) -> Vec<u8> {
    let mut out = file.to_vec();
    let mut i = 0;
    while i + 3 <= out.len() {
        if &out[i..i + 3] == b"mp4" {
            out[i..i + 3].copy_from_slice(b"gif");
            i += 3;
        } else {
            i += 1;
        }
    }
    out
}

/// A scenario's text with `[stop] max_steps = 200` ([`COMMAND_STEPS`]) and `[output]
/// max_size = "1 MB"`: lines that set those keys are dropped, and each key is set on the line
/// after its table's header, or in the table appended at the end. Text that is not UTF-8 is
/// passed on as it is (the command reports it); a scenario that sets the tables another way
/// (`stop = {…}`) becomes invalid, and the command reports that.
fn bound_scenario(file: &[u8]) -> Vec<u8> {
    let Ok(text) = std::str::from_utf8(file) else {
        return file.to_vec();
    };
    let key = |line: &str, name: &str| {
        line.trim_start()
            .trim_start_matches(['"', '\''])
            .strip_prefix(name)
            .is_some_and(|rest| {
                rest.trim_start_matches(['"', '\''])
                    .trim_start()
                    .starts_with('=')
            })
    };
    let header = |line: &str, name: &str| {
        line.trim()
            .strip_prefix('[')
            .and_then(|l| l.split('#').next())
            .is_some_and(|l| l.trim_end().strip_suffix(']').map(str::trim) == Some(name))
    };
    let (mut stop, mut output) = (false, false);
    let mut out = String::with_capacity(text.len() + 64);
    for line in text.lines() {
        if key(line, "max_steps") || key(line, "max_size") {
            continue;
        }
        out.push_str(line);
        out.push('\n');
        if header(line, "stop") {
            let _ = writeln!(out, "max_steps = {COMMAND_STEPS}");
            stop = true;
        } else if header(line, "output") {
            out.push_str("max_size = \"1 MB\"\n");
            output = true;
        }
    }
    if !stop {
        let _ = writeln!(out, "[stop]\nmax_steps = {COMMAND_STEPS}");
    }
    if !output {
        out.push_str("[output]\nmax_size = \"1 MB\"\n");
    }
    out.into_bytes()
}

/// The target's working directory: the process's current directory for the commands,
/// emptied before each input. Made once per process.
pub struct Workdir {
    dir: PathBuf,
}

impl Workdir {
    /// A fresh directory under the system's temporary directory, made the process's current
    /// one (the commands' relative paths resolve there).
    ///
    /// # Errors
    /// When the directory cannot be made or entered.
    pub fn enter() -> std::io::Result<Self> {
        let dir =
            std::env::temp_dir().join(format!("mechkit-fuzz-commands-{}", std::process::id()));
        std::fs::create_dir_all(&dir)?;
        std::env::set_current_dir(&dir)?;
        Ok(Self { dir })
    }

    /// Removes what the previous input left and writes this input's file.
    ///
    /// # Errors
    /// When the directory cannot be emptied or the file written.
    pub fn prepare(&self, file: Option<&[u8]>) -> std::io::Result<()> {
        for entry in std::fs::read_dir(&self.dir)? {
            let path = entry?.path();
            if path.is_dir() {
                std::fs::remove_dir_all(&path)?;
            } else {
                std::fs::remove_file(&path)?;
            }
        }
        if let Some(bytes) = file {
            for name in ["in.toml", "in.csv", "in.png"] {
                std::fs::write(self.dir.join(name), bytes)?;
            }
        }
        Ok(())
    }

    /// The directory.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.dir
    }
}

/// Runs `data` as a command line (see the module's documentation) in `workdir`: its exit
/// status, or `None` when the bytes make no command line the target runs.
pub fn run_in(workdir: &Workdir, data: &[u8]) -> Option<i32> {
    let line = CommandLine::from_bytes(data)?;
    workdir.prepare(line.file.as_deref()).ok()?;
    let mut argv: Vec<OsString> = vec!["mechkit".into()];
    argv.extend(line.args.iter().map(OsString::from));
    Some(mechkit_cli::main_with_args(argv))
}
