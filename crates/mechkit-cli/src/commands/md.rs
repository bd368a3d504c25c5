//! `mechkit md`: the Lennard-Jones melt and its relatives (a pair, a spring chain, soft
//! spheres), through `mechkit::md`: the run is `Md::run_observed`, its result an `MdReport`;
//! here the files are streamed and the progress drawn.

use std::fmt::Write as _;
use std::io::IsTerminal as _;
use std::path::Path;

use anyhow::{Context, Result, anyhow};
use indicatif::{ProgressBar, ProgressStyle};
use mechkit::csv::{self, header_line, push_row, units_file_name, write_atomic};
use mechkit::md::{
    LAMMPS_INPUT, Md, MdConfig, MdObserver, MdOptions, MdReport, MdStop, PairPotential, Potential,
    RDF_BINS, RunPlan, Setup, Thermo, WithPotential,
};
use mechkit::scenario::{DEFAULT_MAX_OUTPUT, StreamFile, output_limit_message, parse_size};
use mechkit::simulate::Cancel;

use super::Outcome;
use super::input::fixed;
use super::md_setup::{options, with_flag};
use crate::args::MdArgs;

const LIMIT_HINT: &str =
    "raise the limit with --max-output 10GB, or write fewer frames with a larger --xyz-every";

/// The files written during the run: `thermo.csv` (with its units sidecar) and, with
/// `--xyz-every`, `trajectory.xyz`, streamed (see [`StreamFile`]).
struct Streams {
    thermo: StreamFile,
    xyz: Option<StreamFile>,
}

impl Streams {
    fn create(dir: &Path, dim: usize, xyz: bool, limit: u64) -> Result<Self> {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("--out: cannot create {}", dir.display()))?;
        let open = |name: &str| {
            let path = dir.join(name);
            StreamFile::create(&path, limit)
                .with_context(|| format!("cannot write {}", path.display()))
        };
        let columns = Thermo::columns(dim);
        let units = dir.join(units_file_name("thermo"));
        write_atomic(&units, csv::units_json(&columns).as_bytes())
            .with_context(|| format!("cannot write {}", units.display()))?;
        let mut thermo = open("thermo.csv")?;
        let header = header_line(columns.iter().map(|c| c.name.as_str()));
        thermo
            .append(header.as_bytes())
            .with_context(|| format!("cannot write {}", thermo.path().display()))?;
        Ok(Self {
            thermo,
            xyz: if xyz {
                Some(open("trajectory.xyz")?)
            } else {
                None
            },
        })
    }

    /// The file that reached its limit, if one did.
    fn full_file(&self) -> Option<&Path> {
        std::iter::once(&self.thermo)
            .chain(&self.xyz)
            .find(|f| f.is_full())
            .map(StreamFile::path)
    }

    /// Finishes every file (whole rows and frames, renamed into place, even after a failed
    /// write); the first error.
    fn finish(self) -> Result<()> {
        let mut first = Ok(());
        for f in std::iter::once(self.thermo).chain(self.xyz) {
            let path = f.path().to_path_buf();
            let done = f
                .finish()
                .with_context(|| format!("cannot write {}", path.display()));
            if first.is_ok() {
                first = done;
            }
        }
        first
    }

    /// How far each file got, for the message of a failed write: `thermo.csv keeps whole
    /// rows up to step 120, trajectory.xyz whole frames up to step 100`.
    fn kept(&self) -> String {
        let mut parts = Vec::new();
        for (f, what) in
            std::iter::once((&self.thermo, "rows")).chain(self.xyz.iter().map(|x| (x, "frames")))
        {
            let name = f
                .path()
                .file_name()
                .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
            let last = f.last_tag_on_disk();
            parts.push(if last.is_finite() {
                format!("{name} keeps whole {what} up to step {last}")
            } else {
                format!("{name} keeps no {what}")
            });
        }
        parts.join(", ")
    }
}

/// Appends a record tagged with its step; the first failed write is kept in `error` (the
/// run then stops: [`MdObserver::full`]) rather than ending the run without its files.
fn append(file: &mut StreamFile, bytes: &[u8], step: usize, error: &mut Option<String>) {
    if error.is_some() {
        return;
    }
    if let Err(e) = file.append_row(bytes, step as f64) {
        *error = Some(format!("cannot write {}: {e}", file.path().display()));
    }
}

/// What the run hands out: rows and frames to the files (with `--out`), steps to the bar.
struct Observer {
    files: Option<Streams>,
    bar: ProgressBar,
    /// The first write that failed (a full disk).
    error: Option<String>,
}

impl<P: PairPotential> MdObserver<P> for Observer {
    type Error = anyhow::Error;

    fn thermo(&mut self, row: &Thermo) -> Result<()> {
        if let Some(f) = &mut self.files {
            let mut line = String::new();
            push_row(&mut line, &row.values());
            append(&mut f.thermo, line.as_bytes(), row.step, &mut self.error);
        }
        Ok(())
    }

    fn frame(&mut self, md: &Md<P>) -> Result<()> {
        if let Some(xyz) = self.files.as_mut().and_then(|f| f.xyz.as_mut()) {
            let mut buf = Vec::new();
            md.write_xyz_frame(&mut buf, "Ar")
                .context("cannot format an XYZ frame")?;
            append(xyz, &buf, md.steps(), &mut self.error);
        }
        Ok(())
    }

    fn step(&mut self, done: usize) {
        self.bar.set_position(done as u64);
    }

    fn full(&self) -> bool {
        self.error.is_some() || self.files.as_ref().is_some_and(|f| f.full_file().is_some())
    }
}

/// A progress bar on a terminal for a run of `steps` steps; hidden with `-q` or when stderr
/// is not a terminal.
fn progress(args: &MdArgs) -> ProgressBar {
    if args.report.quiet || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    ProgressBar::new(args.steps as u64).with_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} steps {per_sec} eta {eta}")
            .expect("the template is valid"),
    )
}

/// Runs `mechkit md`; `cancel` (Ctrl-C) ends it after the current step.
pub fn md(args: &MdArgs, cancel: &Cancel) -> Result<Outcome> {
    let options = options(args)?;
    let plan = options.plan().map_err(with_flag)?;
    let potential = Potential::from_options(&options).map_err(with_flag)?;
    let setup = Setup::from_options(&options, potential.cutoff()).map_err(with_flag)?;
    potential.apply(Runner {
        args,
        options: &options,
        plan: &plan,
        setup,
        cancel,
    })
}

/// The run, for whichever potential.
struct Runner<'a> {
    args: &'a MdArgs,
    options: &'a MdOptions,
    plan: &'a RunPlan,
    setup: Setup,
    cancel: &'a Cancel,
}

impl WithPotential for Runner<'_> {
    type Output = Result<Outcome>;

    fn call<P: PairPotential>(self, potential: P) -> Result<Outcome> {
        run(self, potential)
    }
}

fn run<P: PairPotential>(r: Runner<'_>, potential: P) -> Result<Outcome> {
    let Runner {
        args,
        options,
        plan,
        setup: s,
        cancel,
    } = r;
    let cutoff = potential.cutoff();
    let dim = s.sim_box.dim();
    let mut md =
        Md::new(s.sim_box, potential, s.x, s.v, MdConfig::from(options)).map_err(with_flag)?;
    // the state the run starts from, written before the run so a stopped run keeps it
    let exported = match &args.export_lammps {
        Some(dir) => {
            md.lammps_export(plan).write(dir).map_err(|e| {
                anyhow!(
                    "--export-lammps: cannot write the LAMMPS files: {e}\n  = hint: give a \
                         directory (it is created if missing) where in.lammps and data.lammps \
                         can be written"
                )
            })?;
            Some(dir.display().to_string())
        }
        None => None,
    };
    let limit = match &args.max_output {
        Some(size) => parse_size(size).map_err(|e| anyhow!("--max-output: {e}"))?,
        None => DEFAULT_MAX_OUTPUT,
    };
    let files = match &args.out {
        Some(dir) => Some(Streams::create(dir, dim, args.xyz_every.is_some(), limit)?),
        None => None,
    };
    let mut observer = Observer {
        files,
        bar: progress(args),
        error: None,
    };
    let result = md.run_observed(plan, cancel, &mut observer);
    observer.bar.finish_and_clear();
    let run = result?;
    let full = observer
        .files
        .as_ref()
        .and_then(Streams::full_file)
        .map(|path| output_limit_message(path, limit, &format!("step {}", md.steps()), LIMIT_HINT));
    if let Some(error) = observer.error {
        // a full disk: the files keep whole rows and frames, renamed into place
        let mut kept = String::new();
        if let Some(mut f) = observer.files {
            // the rows still buffered reach the disk, where it has room
            for s in std::iter::once(&mut f.thermo).chain(f.xyz.as_mut()) {
                let _ = s.flush();
            }
            kept = f.kept();
            let _ = f.finish();
        }
        eprintln!(
            "error: {error}, so the run stopped at step {}; {kept}\n  = hint: free space or choose another --out",
            md.steps()
        );
        return Ok(Outcome::ComputationFailed);
    }
    if let (Some(f), Some(dir)) = (observer.files, &args.out) {
        if let Err(e) = f.finish() {
            // the last rows could not be written: the files keep whole rows, renamed
            eprintln!(
                "error: {}; the run had reached step {}\n  = hint: free space or choose another --out",
                crate::failure::message(&e),
                md.steps()
            );
            return Ok(Outcome::ComputationFailed);
        }
        md.rdf_table(RDF_BINS, cutoff + options.skin)
            .write(dir, "rdf")
            .with_context(|| format!("cannot write {}", dir.join("rdf.csv").display()))?;
    }
    let mut report = md.report(&run, &s.origin, &args.potential);
    report.lammps_export = exported;
    super::report(args.report, &report, || text(&report))?;
    if report.dangerous_builds > 0 {
        eprintln!(
            "warning: {} of the {} neighbour-list builds came after an atom had moved more than half the skin since the build before: pairs may have come within the cut-off unlisted\n  = hint: --neigh-every 1 (the default) checks after every step; or a larger --skin",
            report.dangerous_builds, report.list_builds
        );
    }
    match &report.stop {
        MdStop::Diverged(e) => {
            eprintln!("error: {e}");
            Ok(Outcome::ComputationFailed)
        }
        MdStop::Full => {
            let message = full.unwrap_or_else(|| "an output reached its size limit".into());
            eprintln!("error: {message}");
            Ok(Outcome::ComputationFailed)
        }
        MdStop::Cancelled => {
            eprintln!(
                "interrupted after {} steps: the outputs hold the run up to there",
                report.steps
            );
            Ok(Outcome::Interrupted)
        }
        MdStop::Completed => Ok(Outcome::Success),
    }
}

/// The text report: the thermo rows as LAMMPS prints them, then the run's cost.
fn text(r: &MdReport) -> String {
    let mut out = format!(
        "{} atoms ({}), {} potential; per-atom energies\n",
        r.atoms, r.start, r.potential
    );
    out.push_str("  Step         Temp       E_pair       TotEng        Press\n");
    for t in &r.thermo {
        let _ = writeln!(
            out,
            "{:>6} {:>12} {:>12} {:>12} {:>12}",
            t.step,
            fixed(t.temperature, 7),
            fixed(t.potential_per_atom, 7),
            fixed(t.total_per_atom, 7),
            fixed(t.pressure, 7)
        );
    }
    let _ = writeln!(
        out,
        "{} steps on {} thread(s) in {:.3} s: {:.3e} atom-steps/s, {} list builds, msd {}",
        r.steps,
        r.threads,
        r.seconds,
        r.atom_steps_per_second,
        r.list_builds,
        fixed(r.msd, 4)
    );
    // a cut that the energy jumps across: its drift is not the time step's
    if r.cutoff_jump != 0.0 {
        let remedy = if r.potential == "lj" {
            "--shift makes it continuous, to check conservation"
        } else {
            "a cut-off that no pair crosses (between the first and second neighbours of a solid) avoids it"
        };
        let _ = writeln!(
            out,
            "note: the pair energy is cut at r_c without a shift: it jumps by U(r_c) = {:.3e} each time a pair crosses the cut-off, so the total energy moves ({:.3e} per atom over this run) whatever the time step; {remedy}",
            r.cutoff_jump, r.energy_change_per_atom
        );
    }
    if let Some(dir) = &r.lammps_export {
        let _ = writeln!(
            out,
            "LAMMPS export of the start in {dir}: cd {dir} && lmp -in {LAMMPS_INPUT}"
        );
    }
    out
}
