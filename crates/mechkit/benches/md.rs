//! The hot kernels of the many-particle module on the LJ melt (fcc, ρ = 0.8442, 32,000
//! atoms, r_c = 2.5σ, skin 0.3σ, T₀ = 1.44): one force evaluation over the neighbour list,
//! one neighbour-list build (cell list included) and one velocity-Verlet step, each on 1 and
//! 2 threads, reported per atom (`Throughput::Elements`).
//!
//! Run with `cargo bench -p mechkit --bench md`; the whole 100-step melt with atom-steps per
//! second is `cargo run --release -p mechkit --example lj_melt`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use mechkit::md::{
    Lattice, LennardJones, Md, MdConfig, NeighbourList, compute_forces, maxwell_boltzmann,
};

fn melt(threads: usize) -> Md<LennardJones> {
    let (sim_box, x) = Lattice::Fcc.build(20, 0.8442).unwrap();
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 87287).unwrap();
    let config = MdConfig {
        threads,
        ..MdConfig::default()
    };
    Md::new(sim_box, LennardJones::reduced(2.5).unwrap(), x, v, config).unwrap()
}

fn md(c: &mut Criterion) {
    let mut group = c.benchmark_group("md LJ melt, 32000 atoms");
    group
        .throughput(Throughput::Elements(32_000))
        .sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    for threads in [1, 2] {
        let mut md = melt(threads);
        md.run(20).unwrap(); // leave the perfect lattice
        let pool = (threads > 1).then(|| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
        });
        let x = md.positions();
        let mut f = vec![[0.0; 3]; x.len()];
        let lj = LennardJones::reduced(2.5).unwrap();
        let list = md.neighbour_list().clone();
        group.bench_function(format!("forces, {threads} thread(s)"), |b| {
            b.iter(|| {
                compute_forces(
                    &lj,
                    md.sim_box(),
                    black_box(&list),
                    black_box(&x),
                    &mut f,
                    pool.as_ref(),
                )
            });
        });
        group.bench_function(format!("neighbour-list build, {threads} thread(s)"), |b| {
            b.iter(|| NeighbourList::build(md.sim_box(), black_box(&x), 2.8, pool.as_ref()));
        });
        group.bench_function(format!("velocity-Verlet step, {threads} thread(s)"), |b| {
            b.iter(|| md.step());
        });
    }
    group.finish();
}

criterion_group!(benches, md);
criterion_main!(benches);
