//! `mechkit md`: the Lennard-Jones melt and its relatives (a pair, a spring chain, soft
//! spheres), through `mechkit::md`.

use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result, anyhow, bail};
use mechkit::md::{Md, MdConfig, PairPotential, Thermo};
use mechkit::scenario::{
    DEFAULT_MAX_OUTPUT, StreamFile, output_limit_message, parse_size, write_atomic,
};
use mechkit::simulate::Cancel;
use serde_json::json;

use super::Outcome;
use super::md_setup::{Potential, Setup, flag, setup};
use crate::args::MdArgs;

fn thermo_json(t: &Thermo, n: f64) -> serde_json::Value {
    json!({
        "step": t.step, "t": t.t, "temperature": t.temperature,
        "potential_per_atom": t.potential / n, "total_per_atom": t.total / n,
        "kinetic_per_atom": t.kinetic / n, "pressure": t.pressure,
    })
}

const LIMIT_HINT: &str =
    "raise the limit with --max-output 10GB, or write fewer frames with a larger --xyz-every";

/// The files written during the run: `thermo.csv` and, with `--xyz-every`,
/// `trajectory.xyz`, streamed (see [`StreamFile`]).
struct Streams {
    thermo: StreamFile,
    xyz: Option<StreamFile>,
}

impl Streams {
    fn create(dir: &Path, xyz: bool, limit: u64) -> Result<Self> {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("--out: cannot create {}", dir.display()))?;
        let open = |name: &str| {
            let path = dir.join(name);
            StreamFile::create(&path, limit)
                .with_context(|| format!("cannot write {}", path.display()))
        };
        let mut thermo = open("thermo.csv")?;
        let header = format!("{}\n", Thermo::CSV_HEADER);
        append(&mut thermo, header.as_bytes())?;
        Ok(Self {
            thermo,
            xyz: if xyz {
                Some(open("trajectory.xyz")?)
            } else {
                None
            },
        })
    }

    fn thermo(&mut self, row: &Thermo) -> Result<()> {
        append(&mut self.thermo, format!("{}\n", row.csv_row()).as_bytes())
    }

    fn frame<P: PairPotential>(&mut self, md: &Md<P>) -> Result<()> {
        if let Some(xyz) = &mut self.xyz {
            let mut buf = Vec::new();
            md.write_xyz_frame(&mut buf, "Ar")
                .context("cannot format an XYZ frame")?;
            append(xyz, &buf)?;
        }
        Ok(())
    }

    /// The file that reached its limit, if one did.
    fn full(&self) -> Option<&Path> {
        std::iter::once(&self.thermo)
            .chain(&self.xyz)
            .find(|f| f.is_full())
            .map(StreamFile::path)
    }

    fn finish(self) -> Result<()> {
        for f in std::iter::once(self.thermo).chain(self.xyz) {
            let path = f.path().to_path_buf();
            f.finish()
                .with_context(|| format!("cannot write {}", path.display()))?;
        }
        Ok(())
    }
}

fn append(file: &mut StreamFile, bytes: &[u8]) -> Result<()> {
    file.append(bytes)
        .map(|_| ())
        .with_context(|| format!("cannot write {}", file.partial_path().display()))
}

/// Runs `mechkit md`; `cancel` (Ctrl-C) ends it after the current step.
pub fn md(args: &MdArgs, cancel: &Cancel) -> Result<Outcome> {
    if args.thermo_every == 0 || args.xyz_every == Some(0) {
        bail!("--thermo-every and --xyz-every must be at least 1 (a step count)");
    }
    let (s, potential) = setup(args)?;
    match potential {
        Potential::Lj(p) => run(args, s, p, cancel),
        Potential::Soft(p) => run(args, s, p, cancel),
        Potential::Spring(p) => run(args, s, p, cancel),
    }
}

fn run<P: PairPotential>(
    args: &MdArgs,
    s: Setup,
    potential: P,
    cancel: &Cancel,
) -> Result<Outcome> {
    let config = MdConfig {
        dt: args.dt,
        skin: args.skin,
        mass: args.mass,
        threads: args.threads,
    };
    let cutoff = potential.cutoff();
    let mut md = Md::new(s.sim_box, potential, s.x, s.v, config)
        .map_err(|e| anyhow::anyhow!("{}: {e}", flag(&e)))?;
    let n = md.len() as f64;
    let limit = match &args.max_output {
        Some(size) => parse_size(size).map_err(|e| anyhow!("--max-output: {e}"))?,
        None => DEFAULT_MAX_OUTPUT,
    };
    let mut files = match &args.out {
        Some(dir) => Some(Streams::create(dir, args.xyz_every.is_some(), limit)?),
        None => None,
    };
    let mut rows = vec![md.thermo()];
    if let Some(f) = &mut files {
        f.thermo(&rows[0])?;
        f.frame(&md)?;
    }
    let start = Instant::now();
    let mut failure = None;
    let mut interrupted = false;
    let mut full = None;
    for step in 1..=args.steps {
        if cancel.is_cancelled() {
            // Ctrl-C: the thermo row of the state reached, then the outputs as usual
            interrupted = true;
            break;
        }
        if let Some(f) = &files
            && let Some(path) = f.full()
        {
            full = Some(output_limit_message(
                path,
                limit,
                &format!("step {}", md.steps()),
                LIMIT_HINT,
            ));
            break;
        }
        if let Err(e) = md.run(1) {
            failure = Some(e);
            break;
        }
        if step % args.thermo_every == 0 || step == args.steps {
            rows.push(md.thermo());
            if let Some(f) = &mut files {
                f.thermo(rows.last().expect("a row was pushed"))?;
            }
        }
        if let Some(f) = &mut files
            && args.xyz_every.is_some_and(|k| step % k == 0)
        {
            f.frame(&md)?;
        }
    }
    if full.is_none()
        && let Some(path) = files.as_ref().and_then(Streams::full)
    {
        full = Some(output_limit_message(
            path,
            limit,
            &format!("step {}", md.steps()),
            LIMIT_HINT,
        ));
    }
    if (interrupted || full.is_some() || failure.is_some())
        && rows.last().is_none_or(|r| r.step != md.steps())
    {
        rows.push(md.thermo());
        if let Some(f) = &mut files {
            f.thermo(rows.last().expect("a row was pushed"))?;
        }
    }
    let seconds = start.elapsed().as_secs_f64();
    let rate = n * md.steps() as f64 / seconds.max(1e-12);
    if let (Some(f), Some(dir)) = (files, &args.out) {
        f.finish()?;
        let mut rdf = String::from("r,g\n");
        for (r, g) in md.radial_distribution(100, cutoff + args.skin) {
            let _ = writeln!(rdf, "{r},{g}");
        }
        let path = dir.join("rdf.csv");
        write_atomic(&path, rdf.as_bytes())
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    let last = md.thermo();
    if args.json {
        let body = json!({
            "atoms": md.len(), "start": s.origin, "potential": args.potential,
            "steps": md.steps(),
            "threads": args.threads, "seconds": seconds, "atom_steps_per_second": rate,
            "list_builds": md.rebuilds(),
            "energy_change_per_atom": (last.total - rows[0].total) / n,
            "msd": md.mean_square_displacement(),
            "thermo": rows.iter().map(|t| thermo_json(t, n)).collect::<Vec<_>>(),
        });
        println!("{}", serde_json::to_string_pretty(&body)?);
    } else {
        println!(
            "{} atoms ({}), {} potential; per-atom energies",
            md.len(),
            s.origin,
            args.potential
        );
        println!("  Step         Temp       E_pair       TotEng        Press");
        for t in &rows {
            println!(
                "{:>6} {:>12.7} {:>12.7} {:>12.7} {:>12.7}",
                t.step,
                t.temperature,
                t.potential / n,
                t.total / n,
                t.pressure
            );
        }
        println!(
            "{} steps on {} thread(s) in {seconds:.3} s: {rate:.3e} atom-steps/s, {} list builds, msd {:.4}",
            md.steps(),
            args.threads,
            md.rebuilds(),
            md.mean_square_displacement()
        );
    }
    if let Some(e) = failure {
        eprintln!("error: {e}");
        return Ok(Outcome::ComputationFailed);
    }
    if let Some(message) = full {
        eprintln!("error: {message}");
        return Ok(Outcome::ComputationFailed);
    }
    if interrupted {
        eprintln!(
            "interrupted after {} steps: the outputs hold the run up to there",
            md.steps()
        );
        return Ok(Outcome::Interrupted);
    }
    Ok(Outcome::Success)
}
