//! `mechkit md --export-lammps DIR` continued in LAMMPS (issue 29): the data file and input
//! script start LAMMPS from the state mechkit's run starts from, with the same potential,
//! cut-off, time step and neighbour settings, so LAMMPS's velocity Verlet retraces mechkit's:
//! every thermo row agrees in potential and total energy per atom to 1e-6 (absolute, ε) and
//! in temperature, for the 3-D LJ melt, a shifted 2-D LJ crystal, an open LJ cluster, soft
//! spheres and a 1-D spring chain (the last two through a pair table).
//!
//! Needs Debian's LAMMPS (`apt-get install -y lammps`, binary `lmp`): without it on the PATH
//! a test prints a note and passes, unless `CI` is set, where it fails.

use std::fmt::Write as _;
use std::process::Command;

use crate::util::Dir;

/// One thermo row: step, temperature, potential, kinetic and total energy per atom.
type Row = [f64; 5];

/// Runs `lmp -in in.lammps -log none` in `dir`; None (after a note) when there is no `lmp`
/// and `CI` is not set.
fn lammps(dir: &std::path::Path) -> Option<String> {
    let out = match Command::new("lmp")
        .args(["-in", "in.lammps", "-log", "none", "-nocite"])
        .current_dir(dir)
        .output()
    {
        Ok(out) => out,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            assert!(
                std::env::var_os("CI").is_none(),
                "CI must install LAMMPS (apt-get install -y lammps): no `lmp` on the PATH"
            );
            eprintln!("note: no `lmp` on the PATH; the LAMMPS comparison is skipped");
            return None;
        }
        Err(e) => panic!("cannot run lmp: {e}"),
    };
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "lmp failed\n--- stdout\n{stdout}\n--- stderr\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    Some(stdout)
}

/// LAMMPS's thermo rows (`Step Temp PotEng KinEng TotEng Press`) from its screen output.
fn lammps_rows(screen: &str) -> Vec<Row> {
    screen
        .lines()
        .skip_while(|l| !l.trim_start().starts_with("Step Temp PotEng KinEng TotEng"))
        .skip(1)
        .take_while(|l| !l.starts_with("Loop time"))
        .map(|l| {
            let w: Vec<f64> = l.split_whitespace().map(|w| w.parse().unwrap()).collect();
            [w[0], w[1], w[2], w[3], w[4]]
        })
        .collect()
}

/// mechkit's thermo rows from its `--json`.
fn mechkit_rows(report: &serde_json::Value) -> Vec<Row> {
    let rows = report["thermo"].as_array().unwrap();
    rows.iter()
        .map(|r| {
            let f = |k: &str| r[k].as_f64().unwrap();
            [
                f("step"),
                f("temperature"),
                f("potential_per_atom"),
                f("kinetic_per_atom"),
                f("total_per_atom"),
            ]
        })
        .collect()
}

/// Runs `mechkit md ARGS --export-lammps lmp --json`, then LAMMPS on the export; checks every
/// row and returns the largest differences of PE/N and E/N (None without LAMMPS).
fn compare(dir: &Dir, args: &[&str]) -> Option<(f64, f64)> {
    let report = dir.json_with(&["md"], &[args, &["--export-lammps", "lmp"]].concat());
    assert_eq!(report["lammps_export"], "lmp");
    let screen = lammps(&dir.path().join("lmp"))?;
    let (ours, theirs) = (mechkit_rows(&report), lammps_rows(&screen));
    assert_eq!(ours.len(), theirs.len(), "thermo rows\n{screen}");
    let (mut pe, mut total) = (0.0_f64, 0.0_f64);
    for (a, b) in ours.iter().zip(&theirs) {
        assert_eq!(a[0], b[0], "steps");
        assert!((a[1] - b[1]).abs() < 1e-6, "temperature {a:?} vs {b:?}");
        assert!((a[3] - b[3]).abs() < 1e-6, "kinetic {a:?} vs {b:?}");
        pe = pe.max((a[2] - b[2]).abs());
        total = total.max((a[4] - b[4]).abs());
    }
    eprintln!("{args:?}: max |ΔPE/N| = {pe:.2e}, max |ΔE/N| = {total:.2e}");
    assert!(pe < 1e-6 && total < 1e-6, "PE/N {pe:e}, E/N {total:e}");
    Some((pe, total))
}

#[test]
fn lj_melt_256_atoms_continues_in_lammps() {
    let dir = Dir::new();
    let melt = [
        "--cells",
        "4",
        "--temperature",
        "1.44",
        "--steps",
        "50",
        "--thermo-every",
        "10",
    ];
    compare(&dir, &melt);
    // the run's start, whatever the run does afterwards
    assert!(dir.read("lmp/data.lammps").contains("\n256 atoms\n"));
    assert!(dir.read("lmp/in.lammps").contains("\nrun             50\n"));
}

#[test]
fn shifted_2d_lj_and_an_open_cluster_continue_in_lammps() {
    let dir = Dir::new();
    let hex = [
        "--lattice",
        "hexagonal",
        "--cells",
        "8",
        "--density",
        "0.8",
        "--temperature",
        "0.5",
        "--shift",
        "--steps",
        "50",
        "--thermo-every",
        "10",
    ];
    compare(&dir, &hex);
    // a 3-D cluster of 27 atoms 1.12σ apart in open space
    let mut csv = String::from("x,y,z\n");
    for i in 0..27_u8 {
        let [a, b, c] = [i % 3, (i / 3) % 3, i / 9].map(|k| 1.12 * f64::from(k));
        let _ = writeln!(csv, "{a},{b},{c}");
    }
    dir.create("cluster.csv", &csv);
    let open = [
        "--positions",
        "cluster.csv",
        "--boundary",
        "open",
        "--temperature",
        "0.8",
        "--steps",
        "50",
        "--thermo-every",
        "10",
    ];
    compare(&dir, &open);
}

#[test]
fn tabulated_soft_spheres_and_a_1d_spring_chain_continue_in_lammps() {
    let dir = Dir::new();
    let soft = [
        "--potential",
        "soft-sphere",
        "--sigma",
        "1.3",
        "--epsilon",
        "20",
        "--cells",
        "4",
        "--temperature",
        "1",
        "--steps",
        "50",
        "--thermo-every",
        "10",
    ];
    compare(&dir, &soft);
    assert!(
        dir.read("lmp/in.lammps")
            .contains("pair_style      table spline")
    );
    let chain = [
        "--lattice",
        "chain",
        "--cells",
        "30",
        "--density",
        "1",
        "--potential",
        "spring",
        "--k",
        "5",
        "--cutoff",
        "1.5",
        "--temperature",
        "0.1",
        "--steps",
        "50",
        "--thermo-every",
        "10",
    ];
    compare(&dir, &chain);
}

#[test]
fn export_into_a_file_is_refused_with_the_flag() {
    let dir = Dir::new();
    dir.create("taken", "not a directory");
    dir.run(&[
        "md",
        "--cells",
        "4",
        "--steps",
        "1",
        "--export-lammps",
        "taken",
    ])
    .assert_bad_input(&["--export-lammps", "taken"]);
}
