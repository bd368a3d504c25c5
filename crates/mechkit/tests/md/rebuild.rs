//! The neighbour-list policy: checked after every step by default (no build ever late),
//! LAMMPS's `every N` with or without the check, late builds counted; and steps that skip
//! the energy move the atoms exactly as steps that sum it.

use mechkit::md::{Lattice, LennardJones, Md, MdConfig, MdError, MdInput, maxwell_boltzmann};

fn melt(neigh_every: usize, neigh_check: bool) -> Result<Md<LennardJones>, MdError> {
    let (sim_box, x) = Lattice::Fcc.build(5, 0.8442).unwrap();
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 87287).unwrap();
    let config = MdConfig {
        neigh_every,
        neigh_check,
        ..MdConfig::default()
    };
    Md::new(sim_box, LennardJones::reduced(2.5).unwrap(), x, v, config)
}

#[test]
fn every_step_checked_is_never_late_and_every_n_unchecked_builds_on_schedule() {
    let mut checked = melt(1, true).unwrap();
    checked.run(200).unwrap();
    assert_eq!(checked.dangerous_builds(), 0);
    assert!(checked.rebuilds() > 10, "{}", checked.rebuilds());

    // LAMMPS's bench/in.lj: every 20 check no: a build at 0, 20, 40, ...
    let mut scheduled = melt(20, false).unwrap();
    scheduled.run(200).unwrap();
    assert_eq!(scheduled.rebuilds(), 1 + 200 / 20);
    // at T = 1.44 some atom moves half the skin in fewer than 20 steps: late builds
    assert!(scheduled.dangerous_builds() > 0);
    assert!(scheduled.dangerous_builds() < scheduled.rebuilds());

    // every 5 with the check: builds only when needed, at most one per 5 steps
    let mut every5 = melt(5, true).unwrap();
    every5.run(200).unwrap();
    assert!(every5.rebuilds() <= 1 + 200 / 5);
    assert!(every5.rebuilds() <= checked.rebuilds() + 1);
    // the energies stay those of the every-step list closely (missed pairs are rare)
    let (a, b) = (checked.thermo().total, every5.thermo().total);
    assert!((a - b).abs() < 1e-3 * a.abs(), "{a} vs {b}");

    let e = melt(0, true).err().unwrap();
    assert_eq!(e.input(), Some(MdInput::NeighEvery));
}

/// A run sums the energy at its last step only; its atoms end bit for bit where steps that
/// each sum it take them, and its energy is theirs.
#[test]
fn steps_without_the_energy_move_the_atoms_as_steps_with_it() {
    let mut fast = melt(1, true).unwrap();
    let mut full = melt(1, true).unwrap();
    fast.run(60).unwrap();
    for _ in 0..60 {
        full.step();
    }
    assert_eq!(fast.positions(), full.positions());
    assert_eq!(fast.velocities(), full.velocities());
    assert_eq!(fast.pair_sums(), full.pair_sums());
    assert_eq!(fast.thermo(), full.thermo());
}
