//! The Lennard-Jones melt (LAMMPS `bench/in.lj`: fcc at ρ = 0.8442, T₀ = 1.44, r_c = 2.5σ
//! unshifted, skin 0.3σ, dt = 0.005τ) at small N: total energy conserved within a stated
//! bound, the lattice melts (T falls towards ~0.7 as kinetic energy turns into potential,
//! g(r) loses its lattice peaks), and runs on 1, 2 and 3 threads are bit-identical.

use mechkit::md::{Lattice, LennardJones, Md, MdConfig, maxwell_boltzmann};

fn melt(cells: usize, threads: usize) -> Md<LennardJones> {
    let (b, x) = Lattice::Fcc.build(cells, 0.8442).unwrap();
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 87287).unwrap();
    let config = MdConfig {
        threads,
        ..MdConfig::default()
    };
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

/// 500 atoms, 1000 steps (5τ). Measured: max |ΔE|/N = 1.07e-2 ε over the first 100 steps,
/// almost all of it while the perfect lattice at T = 1.44 melts (the 32,000-atom run:
/// E/N = −4.6134, −4.6213, −4.6225 at steps 0, 50, 100), then 6.0e-3 ε from step 100 to
/// 1000: the O(dt²) error of Verlet at dt = 0.005 and the jumps of the unshifted cut-off.
/// Bounds: 1.5e-2 over the first 100 steps, 8e-3 from step 100 to 1000.
#[test]
fn lj_melt_500_atoms_1000_steps_conserves_energy() {
    let mut md = melt(5, 1);
    let t0 = md.thermo();
    assert!((t0.temperature - 1.44).abs() < 1e-12);
    assert!(
        (t0.potential / 500.0 + 6.773_368_1).abs() < 1e-6,
        "U/N = {}",
        t0.potential / 500.0
    );
    let worst = drift(&mut md, 100);
    let later = drift(&mut md, 900);
    eprintln!("500 atoms: max |dE|/N = {worst:e} (steps 0-100), {later:e} (100-1000)");
    assert!(worst < 1.5e-2, "max |dE|/N = {worst:e}");
    assert!(later < 8e-3, "max |dE|/N after step 100 = {later:e}");
    let t = md.thermo();
    assert!((0.5..1.0).contains(&t.temperature), "T = {}", t.temperature);
    assert!(
        md.mean_square_displacement() > 0.05,
        "msd {}",
        md.mean_square_displacement()
    );
    // Melted: g(r) has its first peak near 1.1σ and no atoms closer than 0.8σ.
    let g = md.radial_distribution(56, 2.8);
    let (r_peak, g_peak) = g
        .iter()
        .copied()
        .fold((0.0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
    assert!(
        (1.0..1.2).contains(&r_peak) && g_peak > 2.0,
        "peak {g_peak} at {r_peak}"
    );
    assert!(g.iter().filter(|(r, _)| *r < 0.8).all(|(_, g)| *g == 0.0));
}

/// 10⁴ steps (50τ) of 500 atoms after the first 100: release builds only (`cargo test --release -- --ignored`).
#[test]
#[ignore = "10^4 steps: run in release"]
fn lj_melt_500_atoms_10_000_steps_energy_drift() {
    let mut md = melt(5, 2);
    md.run(100).unwrap();
    let worst = drift(&mut md, 10_000);
    eprintln!("500 atoms, steps 100 to 10100: max |dE|/N = {worst:e}");
    assert!(worst < 1e-2, "max |dE|/N = {worst:e}"); // measured 7.27e-3 (6.96e-3 with the full list)
}

#[test]
fn serial_and_parallel_runs_are_bit_identical() {
    // 8 fcc cells = 2048 atoms = 4 slabs of the half list: real work for every thread.
    let mut runs: Vec<Md<LennardJones>> = [1, 2, 3].iter().map(|&t| melt(8, t)).collect();
    for md in &mut runs {
        md.run(60).unwrap();
    }
    let bits = |md: &Md<LennardJones>| -> Vec<u64> {
        md.positions()
            .into_iter()
            .chain(md.velocities())
            .chain(md.forces())
            .flatten()
            .map(f64::to_bits)
            .chain([
                md.pair_sums().potential.to_bits(),
                md.pair_sums().virial.to_bits(),
            ])
            .collect()
    };
    let serial = bits(&runs[0]);
    assert!(runs[0].rebuilds() > 1);
    for md in &runs[1..] {
        assert!(bits(md) == serial, "{} threads differ", md.config().threads);
    }
}
