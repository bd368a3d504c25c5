//! The LJ melt benchmark (LAMMPS `bench/in.lj`): fcc at ρ = 0.8442, 32,000 atoms (20 cells),
//! r_c = 2.5σ, skin 0.3σ, dt = 0.005τ, T₀ = 1.44, 100 steps NVE; prints the thermo every
//! 50 steps as LAMMPS does (per atom) and atom-steps per second.
//!
//! `cargo run --release -p mechkit --example lj_melt -- [threads] [cells] [steps]`

use std::time::Instant;

use mechkit::md::{Lattice, LennardJones, Md, MdConfig, maxwell_boltzmann};

fn main() {
    let arg = |k: usize, default: usize| {
        std::env::args()
            .nth(k)
            .and_then(|s| s.parse().ok())
            .unwrap_or(default)
    };
    let (threads, cells, steps) = (arg(1, 1), arg(2, 20), arg(3, 100));
    let (sim_box, x) = Lattice::Fcc.build(cells, 0.8442).expect("lattice");
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 87287).expect("velocities");
    let config = MdConfig {
        threads,
        ..MdConfig::default()
    };
    let lj = LennardJones::reduced(2.5).expect("potential");
    let mut md = Md::new(sim_box, lj, x, v, config).expect("system");
    let n = md.len() as f64;
    let print = |md: &Md<LennardJones>| {
        let t = md.thermo();
        println!(
            "{:>6} {:>12.7} {:>12.7} {:>12.7} {:>12.7}",
            t.step,
            t.temperature,
            t.potential / n,
            t.total / n,
            t.pressure
        );
    };
    println!("  Step         Temp       E_pair       TotEng        Press");
    print(&md);
    let start = Instant::now();
    for _ in 0..steps / 50 {
        md.run(50).expect("run");
        print(&md);
    }
    md.run(steps % 50).expect("run");
    let secs = start.elapsed().as_secs_f64();
    println!(
        "{} atoms, {steps} steps, {threads} thread(s): {secs:.3} s, {:.3e} atom-steps/s, {} list builds",
        md.len(),
        n * steps as f64 / secs,
        md.rebuilds()
    );
}
