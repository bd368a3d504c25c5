//! `mechkit md`: the LJ melt at 500 atoms (the starting potential energy per atom of LAMMPS's
//! `bench/in.lj`, T₀ exact, energy kept within the library's measured bound), its files
//! (thermo.csv, rdf.csv, extended XYZ), bit-identical results on 1 and 2 threads, bad input.

use crate::util::Dir;

fn json(dir: &Dir, args: &[&str]) -> serde_json::Value {
    let small = [
        "md",
        "--cells",
        "5",
        "--steps",
        "100",
        "--thermo-every",
        "10",
    ];
    dir.json_with(&small, args)
}

#[test]
fn lj_melt_500_atoms_energy_temperature_and_threads() {
    let dir = Dir::new();
    let one = json(&dir, &["--threads", "1"]);
    assert_eq!(one["atoms"], 500);
    let t = one["thermo"].as_array().unwrap();
    assert_eq!(t.len(), 11);
    assert!((t[0]["temperature"].as_f64().unwrap() - 1.44).abs() < 1e-12);
    assert!((t[0]["potential_per_atom"].as_f64().unwrap() + 6.773_368_1).abs() < 1e-6);
    let de = one["energy_change_per_atom"].as_f64().unwrap();
    assert!(de.abs() < 1.5e-2, "dE/N = {de}");
    // Bit-identical on two threads: every thermo row equal.
    let two = json(&dir, &["--threads", "2"]);
    assert_eq!(one["thermo"], two["thermo"]);
}

/// An unshifted cut-off is named with the jump it puts in the energy (the drift a user sees
/// is not the time step's); a shifted one, and a soft sphere, continuous at its cut-off, are
/// not.
#[test]
fn an_unshifted_cut_off_is_named_with_its_jump() {
    let dir = Dir::new();
    let j = json(&dir, &[]);
    let jump = j["cutoff_jump"].as_f64().unwrap();
    let want = 4.0 * (2.5f64.powi(-12) - 2.5f64.powi(-6));
    assert!((jump - want).abs() < 1e-12, "{jump}");
    let small = ["md", "--cells", "4", "--steps", "20"];
    let text = |extra: &[&str]| dir.run_with(&small, extra).stdout;
    let unshifted = text(&[]);
    assert!(
        unshifted.contains("jumps by U(r_c) = -1.632e-2 each time a pair crosses the cut-off")
            && unshifted.contains("--shift makes it continuous"),
        "{unshifted}"
    );
    for extra in [&["--shift"][..], &["--potential", "soft-sphere"]] {
        assert!(!text(extra).contains("note: the pair energy"), "{extra:?}");
    }
    assert_eq!(json(&dir, &["--shift"])["cutoff_jump"], 0.0);
}

#[test]
fn files_thermo_rdf_and_extended_xyz() {
    let dir = Dir::new();
    dir.run(&[
        "md",
        "--cells",
        "4",
        "--steps",
        "20",
        "--thermo-every",
        "5",
        "--xyz-every",
        "10",
        "--out",
        "out",
    ])
    .assert_code(0);
    let thermo = dir.read("out/thermo.csv");
    let lines: Vec<&str> = thermo.lines().collect();
    assert_eq!(
        lines[0],
        "step,t,kinetic,potential,total,temperature,pressure"
    );
    assert_eq!(lines.len(), 1 + 5);
    let rdf = dir.read("out/rdf.csv");
    assert_eq!(rdf.lines().count(), 101);
    let xyz = dir.read("out/trajectory.xyz");
    let frames: Vec<&str> = xyz.lines().filter(|l| l.starts_with("Lattice=")).collect();
    assert_eq!(frames.len(), 3); // steps 0, 10, 20
    assert!(frames[0].contains("Properties=species:S:1:pos:R:3:velo:R:3"));
    assert!(frames[0].contains("pbc=\"T T T\""));
    assert_eq!(xyz.lines().next(), Some("256"));
    assert_eq!(xyz.lines().count(), 3 * (256 + 2));
}

#[test]
fn bad_input_names_the_flag() {
    let dir = Dir::new();
    dir.run(&["md", "--lattice", "bcc"])
        .assert_bad_input(&["--lattice", "fcc"]);
    dir.run(&["md", "--cells", "2"])
        .assert_bad_input(&["--cells", "twice the cut-off"]);
    dir.run(&["md", "--cells", "4", "--density=-1"])
        .assert_bad_input(&["--density"]);
    dir.run(&["md", "--cells", "4", "--dt", "0"])
        .assert_bad_input(&["--dt"]);
    dir.run(&["md", "--cells", "4", "--threads", "0"])
        .assert_bad_input(&["--threads"]);
    // A 2-D lattice at a density where atoms overlap hard and a huge step: diverges (exit 1).
    dir.run(&[
        "md",
        "--lattice",
        "square",
        "--cells",
        "12",
        "--density",
        "3",
        "--dt",
        "1",
        "--steps",
        "50",
    ])
    .assert_code(1);
}
