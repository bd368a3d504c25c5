//! `mechkit md`: the Lennard-Jones melt and its relatives (a pair, a spring chain, soft
//! spheres), through `mechkit::md`.

use std::fmt::Write as _;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use mechkit::md::{Md, MdConfig, PairPotential, Thermo};
use mechkit::scenario::write_atomic;
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

/// Runs `mechkit md`.
pub fn md(args: &MdArgs) -> Result<Outcome> {
    if args.thermo_every == 0 || args.xyz_every == Some(0) {
        bail!("--thermo-every and --xyz-every must be at least 1 (a step count)");
    }
    let (s, potential) = setup(args)?;
    match potential {
        Potential::Lj(p) => run(args, s, p),
        Potential::Soft(p) => run(args, s, p),
        Potential::Spring(p) => run(args, s, p),
    }
}

fn run<P: PairPotential>(args: &MdArgs, s: Setup, potential: P) -> Result<Outcome> {
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
    if let Some(dir) = &args.out {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("--out: cannot create {}", dir.display()))?;
    }
    let mut rows = vec![md.thermo()];
    let mut xyz = String::new();
    let frame = |md: &Md<P>, xyz: &mut String| {
        let mut buf = Vec::new();
        md.write_xyz_frame(&mut buf, "Ar")
            .expect("writing to memory");
        xyz.push_str(&String::from_utf8_lossy(&buf));
    };
    if args.xyz_every.is_some() {
        frame(&md, &mut xyz);
    }
    let start = Instant::now();
    let mut failure = None;
    let mut interrupted = false;
    for step in 1..=args.steps {
        if mechkit::simulate::interrupt::requested() {
            // Ctrl-C: the thermo row of the state reached, then the outputs as usual
            interrupted = true;
            if rows.last().is_none_or(|r| r.step != md.steps()) {
                rows.push(md.thermo());
            }
            break;
        }
        if let Err(e) = md.run(1) {
            failure = Some(e);
            break;
        }
        if step % args.thermo_every == 0 || step == args.steps {
            rows.push(md.thermo());
        }
        if args.xyz_every.is_some_and(|k| step % k == 0) {
            frame(&md, &mut xyz);
        }
    }
    let seconds = start.elapsed().as_secs_f64();
    let rate = n * md.steps() as f64 / seconds.max(1e-12);
    if let Some(dir) = &args.out {
        let mut csv = format!("{}\n", Thermo::CSV_HEADER);
        for r in &rows {
            let _ = writeln!(csv, "{}", r.csv_row());
        }
        let path = dir.join("thermo.csv");
        write_atomic(&path, csv.as_bytes())
            .with_context(|| format!("cannot write {}", path.display()))?;
        let mut rdf = String::from("r,g\n");
        for (r, g) in md.radial_distribution(100, cutoff + args.skin) {
            let _ = writeln!(rdf, "{r},{g}");
        }
        let path = dir.join("rdf.csv");
        write_atomic(&path, rdf.as_bytes())
            .with_context(|| format!("cannot write {}", path.display()))?;
        if !xyz.is_empty() {
            let path = dir.join("trajectory.xyz");
            write_atomic(&path, xyz.as_bytes())
                .with_context(|| format!("cannot write {}", path.display()))?;
        }
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
    if interrupted {
        eprintln!(
            "interrupted after {} steps: the outputs hold the run up to there",
            md.steps()
        );
        return Ok(Outcome::Interrupted);
    }
    Ok(Outcome::Success)
}
