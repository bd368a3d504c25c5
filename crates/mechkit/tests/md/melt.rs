//! The Lennard-Jones melt (LAMMPS `bench/in.lj`: fcc at ρ = 0.8442, T₀ = 1.44, r_c = 2.5σ
//! unshifted, skin 0.3σ, dt = 0.005τ) at small N: total energy conserved within a stated
//! bound, the lattice melts (T falls towards ~0.7 as kinetic energy turns into potential,
//! g(r) loses its lattice peaks), and runs on 1, 2 and 3 threads are bit-identical.

use mechkit::md::{Lattice, LennardJones, Md, MdConfig, maxwell_boltzmann};

fn melt(cells: usize, threads: usize) -> Md<LennardJones> {
    let (b, x) = Lattice::Fcc.build(cells, 0.8442).unwrap();
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 87287).unwrap();
    let config = MdConfig { threads, ..MdConfig::default() };
    Md::new(b, LennardJones::reduced(2.5).unwrap(), x, v, config).unwrap()
}

/// Largest |E(t) − E(0)| per atom over `steps` steps, and the final state.
fn drift(md: &mut Md<LennardJones>, steps: usize) -> f64 {
    let e0 = md.thermo().total;
    let mut worst = 0.0f64;
    for _ in 0..steps {
        md.run(1).unwrap();
        worst = worst.max((md.thermo().total - e0).abs());
    }
    worst / md.len() as f64
}

/// 500 atoms, 1000 steps (5τ). Measured: max |ΔE|/N = DRIFT_1000 (LAMMPS's own log of the
/// 32,000-atom melt shows |ΔE|/N ≈ 5.6e-4 after 100 steps, from the unshifted cut-off).
#[test]
fn lj_melt_500_atoms_1000_steps_conserves_energy() {
    let mut md = melt(5, 1);
    let t0 = md.thermo();
    assert!((t0.temperature - 1.44).abs() < 1e-12);
    assert!((t0.potential / 500.0 + 6.7733681).abs() < 1e-6, "U/N = {}", t0.potential / 500.0);
    let worst = drift(&mut md, 1000);
    eprintln!("500 atoms, 1000 steps: max |dE|/N = {worst:e}, rebuilds {}", md.rebuilds());
    assert!(worst < 2e-3, "max |dE|/N = {worst:e}");
    let t = md.thermo();
    assert!((0.5..1.0).contains(&t.temperature), "T = {}", t.temperature);
    assert!(md.mean_square_displacement() > 0.05, "msd {}", md.mean_square_displacement());
    // Melted: g(r) has its first peak near 1.1σ and no atoms closer than 0.8σ.
    let g = md.radial_distribution(56, 2.8);
    let (r_peak, g_peak) = g.iter().copied().fold((0.0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
    assert!((1.0..1.2).contains(&r_peak) && g_peak > 2.0, "peak {g_peak} at {r_peak}");
    assert!(g.iter().filter(|(r, _)| *r < 0.8).all(|(_, g)| *g == 0.0));
}

/// 10⁴ steps (50τ) of 500 atoms: release builds only (`cargo test --release -- --ignored`).
#[test]
#[ignore = "10^4 steps: run in release"]
fn lj_melt_500_atoms_10_000_steps_energy_drift() {
    let mut md = melt(5, 2);
    let worst = drift(&mut md, 10_000);
    eprintln!("500 atoms, 10^4 steps: max |dE|/N = {worst:e}");
    assert!(worst < 3e-3, "max |dE|/N = {worst:e}");
}

#[test]
fn serial_and_parallel_runs_are_bit_identical() {
    // 8 fcc cells = 2048 atoms = 4 chunks of 512: real work for every thread.
    let mut runs: Vec<Md<LennardJones>> = [1, 2, 3].iter().map(|&t| melt(8, t)).collect();
    for md in &mut runs {
        md.run(60).unwrap();
    }
    let bits = |md: &Md<LennardJones>| -> Vec<u64> {
        md.positions()
            .iter()
            .chain(md.velocities())
            .chain(md.forces())
            .flatten()
            .map(|c| c.to_bits())
            .chain([md.pair_sums().potential.to_bits(), md.pair_sums().virial.to_bits()])
            .collect()
    };
    let serial = bits(&runs[0]);
    assert!(runs[0].rebuilds() > 1);
    for md in &runs[1..] {
        assert!(bits(md) == serial, "{} threads differ", md.config().threads);
    }
}
