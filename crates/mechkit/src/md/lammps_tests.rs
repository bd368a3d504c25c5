//! The export's texts: header counts, box, every atom and velocity once and exactly, the
//! settings of the input script, and a pair table that is the law itself.

use super::super::lammps_data::num;
use super::super::{
    Lattice, LennardJones, LinearSpring, Md, MdConfig, RunPlan, SimBox, SoftSphere,
    maxwell_boltzmann,
};
use super::*;

fn melt(cells: usize, shift: bool) -> Md<LennardJones> {
    let (sim_box, x) = Lattice::Fcc.build(cells, 0.8442).unwrap();
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 7).unwrap();
    let lj = LennardJones::new(1.0, 1.0, 2.5, shift).unwrap();
    Md::new(sim_box, lj, x, v, MdConfig::default()).unwrap()
}

/// The lines of a section (`Atoms # atomic`, `Velocities`) of a data file, as numbers.
fn section(data: &str, title: &str) -> Vec<Vec<f64>> {
    let mut lines = data.lines().skip_while(|l| *l != title).skip(2);
    let mut rows = Vec::new();
    for l in lines.by_ref() {
        if l.is_empty() {
            break;
        }
        rows.push(l.split(' ').map(|w| w.parse().unwrap()).collect());
    }
    rows
}

/// The value of the input line that starts with `key`.
fn setting<'a>(input: &'a str, key: &str) -> Vec<&'a str> {
    input
        .lines()
        .filter(|l| l.split_whitespace().next() == Some(key))
        .map(|l| l[15..].trim())
        .collect()
}

#[test]
fn data_file_holds_every_atom_once_with_its_exact_state() {
    let md = melt(4, false);
    let e = md.lammps_export(&RunPlan::new(50, 10, None).unwrap());
    assert!(e.data.contains("\n256 atoms\n1 atom types\n"));
    let l = md.sim_box().lengths()[0];
    for axis in ["x", "y", "z"] {
        assert!(
            e.data
                .contains(&format!("\n0 {} {axis}lo {axis}hi\n", num(l)))
        );
    }
    assert!(e.data.contains("\nMasses\n\n1 1\n"));
    let atoms = section(&e.data, "Atoms # atomic");
    let vels = section(&e.data, "Velocities");
    assert_eq!((atoms.len(), vels.len()), (256, 256));
    for (i, (a, v)) in atoms.iter().zip(&vels).enumerate() {
        assert_eq!((a[0], a[1], v[0]), ((i + 1) as f64, 1.0, (i + 1) as f64));
        // bit for bit: the numbers read back to the state
        assert_eq!(&a[2..], &md.positions()[i][..]);
        assert_eq!(&v[1..], &md.velocities()[i][..]);
        assert!(a[2..].iter().all(|&c| (0.0..l).contains(&c)));
    }
}

#[test]
fn input_script_has_the_runs_settings() {
    let e = melt(4, true).lammps_export(&RunPlan::new(40, 8, None).unwrap());
    let want = [
        ("units", "lj"),
        ("dimension", "3"),
        ("boundary", "p p p"),
        ("read_data", LAMMPS_DATA),
        ("mass", "1 1"),
        ("pair_style", "lj/cut 2.5"),
        ("pair_coeff", "1 1 1 1"),
        ("pair_modify", "shift yes"),
        ("neighbor", "0.3 bin"),
        ("neigh_modify", "every 1 delay 0 check yes"),
        ("timestep", "0.005"),
        ("thermo_style", "custom step temp pe ke etotal press"),
        ("thermo", "8"),
        ("run", "40"),
    ];
    for (key, value) in want {
        assert_eq!(setting(&e.input, key), [value], "{key}");
    }
    assert_eq!(setting(&e.input, "fix"), ["1 all nve"]);
    assert!(e.table.is_none());
    let unshifted = melt(4, false).lammps_export(&RunPlan::new(40, 8, None).unwrap());
    assert_eq!(setting(&unshifted.input, "pair_modify"), ["shift no"]);
    // the list policy of the run (LAMMPS's bench/in.lj: every 20 check no)
    let (sim_box, x) = Lattice::Fcc.build(4, 0.8442).unwrap();
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 7).unwrap();
    let config = MdConfig {
        neigh_every: 20,
        neigh_check: false,
        ..MdConfig::default()
    };
    let lj = LennardJones::reduced(2.5).unwrap();
    let md = Md::new(sim_box, lj, x, v, config).unwrap();
    let e = md.lammps_export(&RunPlan::new(40, 8, None).unwrap());
    assert_eq!(
        setting(&e.input, "neigh_modify"),
        ["every 20 delay 0 check no"]
    );
}

#[test]
fn open_and_low_dimensional_boxes() {
    // 2-D, open: shrink-wrapped x and y, periodic z
    let b = SimBox::new(2, [4.0, 3.0, 0.0], [false; 3]).unwrap();
    let x = vec![[-0.5, 1.0, 0.0], [1.0, 1.0, 0.0]];
    let v = vec![[0.1, 0.0, 0.0], [-0.1, 0.0, 0.0]];
    let md = Md::new(
        b,
        SoftSphere::new(1.0, 1.2).unwrap(),
        x,
        v,
        MdConfig::default(),
    )
    .unwrap();
    let e = md.lammps_export(&RunPlan::new(5, 1, None).unwrap());
    assert_eq!(setting(&e.input, "dimension"), ["2"]);
    assert_eq!(setting(&e.input, "boundary"), ["s s p"]);
    assert_eq!(setting(&e.input, "fix"), ["1 all nve", "2 all enforce2d"]);
    // the box covers the atom at x = −0.5 with the cut-off as margin
    assert!(
        e.data
            .contains("\n-1.7 5.2 xlo xhi\n-1.2 4.2 ylo yhi\n-1.2 1.2 zlo zhi\n")
    );
    // 1-D, periodic: y fixed, the temperature over N − 1 degrees of freedom
    let b = SimBox::periodic(1, [10.0, 0.0, 0.0]).unwrap();
    let x: Vec<_> = (0..10_u8).map(|i| [f64::from(i), 0.0, 0.0]).collect();
    let v = maxwell_boltzmann(0.1, 1.0, 1, 10, 3).unwrap();
    let spring = LinearSpring::new(2.0, 1.0, 1.5).unwrap();
    let md = Md::new(b, spring, x, v, MdConfig::default()).unwrap();
    let e = md.lammps_export(&RunPlan::new(5, 1, None).unwrap());
    assert_eq!(setting(&e.input, "boundary"), ["p f p"]);
    assert_eq!(
        setting(&e.input, "compute_modify"),
        ["thermo_temp extra/dof 11"]
    );
    assert_eq!(
        setting(&e.input, "pair_coeff"),
        [format!("1 1 {LAMMPS_TABLE} MECHKIT 1.5").as_str()]
    );
}

#[test]
fn pair_table_is_the_law_at_radii_lammps_recomputes() {
    let spring = LinearSpring::new(2.0, 1.0, 1.5).unwrap();
    let table = super::super::lammps_data::pair_table(&spring);
    assert!(table.contains(&format!("\nMECHKIT\nN {TABLE_POINTS} RSQ 0.015 1.5\n\n")));
    let rows: Vec<Vec<f64>> = table
        .lines()
        .skip_while(|l| !l.starts_with("N "))
        .skip(2)
        .map(|l| l.split(' ').map(|w| w.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), TABLE_POINTS);
    assert_eq!((rows[0][1], rows[TABLE_POINTS - 1][1]), (0.015, 1.5));
    for row in rows.iter().step_by(997) {
        let r: f64 = row[1];
        assert!((row[2] - (r - 1.0) * (r - 1.0)).abs() < 1e-14);
        assert!((row[3] + 2.0 * (r - 1.0)).abs() < 1e-13);
    }
}

#[test]
fn numbers_read_back_exactly() {
    for x in [
        0.0,
        -0.0,
        1.0,
        0.005,
        1.0 / 3.0,
        1e-7,
        6.02e23,
        -2.5e-300,
        123_456.789,
    ] {
        let s = num(x);
        assert_eq!(s.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{s}");
        assert!(s.len() < 26, "{s}");
    }
}

#[test]
fn files_are_written_into_the_directory() {
    let dir = tempfile::tempdir().unwrap();
    let e = melt(4, false).lammps_export(&RunPlan::new(1, 1, None).unwrap());
    let out = dir.path().join("a/b");
    let written = e.write(&out).unwrap();
    assert_eq!(written, [out.join(LAMMPS_DATA), out.join(LAMMPS_INPUT)]);
    assert_eq!(std::fs::read_to_string(&written[1]).unwrap(), e.input);
    // a directory where the data file would go: an error naming it
    std::fs::remove_file(&written[0]).unwrap();
    std::fs::create_dir(&written[0]).unwrap();
    let err = e.write(&out).unwrap_err().to_string();
    assert!(err.contains(LAMMPS_DATA), "{err}");
}
