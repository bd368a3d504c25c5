//! Neighbour-list forces, energy and virial equal the all-pairs sums (minimum image) to
//! 1e-12 relative, on seeded random configurations: periodic and open boxes, 1-D, 2-D, 3-D,
//! each pair law, one slab or many; and they still do after the particles have moved (a list
//! kept valid by the skin rule). The half list holds each pair within range exactly once,
//! and the per-slab reduction gives the same bits on 1, 2 and 3 threads.

use mechkit::md::{
    Lattice, LennardJones, LinearSpring, Md, MdConfig, NeighbourList, PairPotential, SimBox,
    SoftSphere, Xoshiro256, all_pairs_forces, compute_forces, maxwell_boltzmann,
};

/// Compares the list sums with the all-pairs sums; returns the largest relative difference.
fn compare<P: PairPotential>(law: &P, sim_box: &SimBox, x: &[[f64; 3]]) -> f64 {
    let list = NeighbourList::build(sim_box, x, law.cutoff() + 0.3, None);
    let (mut f, mut g) = (vec![[0.0; 3]; x.len()], vec![[0.0; 3]; x.len()]);
    let a = compute_forces(law, sim_box, &list, x, &mut f, None);
    let b = all_pairs_forces(law, sim_box, x, &mut g);
    let scale = g.iter().flatten().fold(1.0f64, |m, v| m.max(v.abs()));
    let mut worst = ((a.potential - b.potential) / b.potential.abs().max(1.0)).abs();
    worst = worst.max(((a.virial - b.virial) / b.virial.abs().max(1.0)).abs());
    for (fi, gi) in f.iter().zip(&g) {
        for k in 0..3 {
            worst = worst.max((fi[k] - gi[k]).abs() / scale);
        }
    }
    worst
}

/// A lattice with every atom displaced by up to ±`jitter` per axis (seeded).
fn jittered(
    lattice: Lattice,
    cells: usize,
    density: f64,
    jitter: f64,
    seed: u64,
) -> (SimBox, Vec<[f64; 3]>) {
    let (b, mut x) = lattice.build(cells, density).unwrap();
    let mut rng = Xoshiro256::seed(seed);
    for p in &mut x {
        for c in p.iter_mut().take(lattice.dim()) {
            *c += jitter * (2.0 * rng.uniform() - 1.0);
        }
        b.wrap(p);
    }
    (b, x)
}

#[test]
fn periodic_lattices_with_jitter_match_all_pairs_to_1e_12() {
    let lj = LennardJones::new(1.0, 1.0, 2.5, true).unwrap();
    for seed in 0..4 {
        let cases = [
            jittered(Lattice::Fcc, 4, 0.8442, 0.15, seed),
            // 3 and 4 slabs: the smallest periodic split, where the last slab's next is
            // the first.
            jittered(Lattice::Fcc, 6, 0.8442, 0.15, seed),
            jittered(Lattice::Fcc, 8, 0.8442, 0.15, seed),
            jittered(Lattice::SimpleCubic, 7, 0.6, 0.2, seed),
            jittered(Lattice::Hexagonal, 8, 0.8, 0.15, seed),
            jittered(Lattice::Square, 9, 0.7, 0.2, seed),
            jittered(Lattice::Chain, 40, 1.0, 0.2, seed),
        ];
        for (b, x) in &cases {
            let worst = compare(&lj, b, x);
            assert!(
                worst < 1e-12,
                "dim {} n {} seed {seed}: {worst:e}",
                b.dim(),
                x.len()
            );
        }
    }
}

#[test]
fn open_boxes_with_random_soft_spheres_and_springs_match_all_pairs_to_1e_12() {
    let soft = SoftSphere::new(5.0, 1.0).unwrap();
    let spring = LinearSpring::new(3.0, 1.0, 1.3).unwrap();
    for dim in 1..=3 {
        let b = SimBox::new(dim, [20.0; 3], [false; 3]).unwrap();
        let mut rng = Xoshiro256::seed(dim as u64);
        let n = [40, 200, 400][dim - 1];
        let size = [20.0, 8.0, 5.0][dim - 1]; // beyond the box on purpose: open axes
        let x: Vec<[f64; 3]> = (0..n)
            .map(|_| {
                std::array::from_fn(|k| {
                    if k < dim {
                        size * rng.uniform() - 1.0
                    } else {
                        0.0
                    }
                })
            })
            .collect();
        assert!(compare(&soft, &b, &x) < 1e-12, "soft spheres, dim {dim}");
        assert!(compare(&spring, &b, &x) < 1e-12, "springs, dim {dim}");
    }
    // Mixed: periodic in x only.
    let b = SimBox::new(2, [7.0, 7.0, 0.0], [true, false, false]).unwrap();
    let mut rng = Xoshiro256::seed(9);
    let x: Vec<[f64; 3]> = (0..150)
        .map(|_| [7.0 * rng.uniform(), 9.0 * rng.uniform(), 0.0])
        .collect();
    assert!(compare(&soft, &b, &x) < 1e-12);
}

/// After 60 steps of the melt (the list rebuilt and then reused while atoms move less than
/// half the skin), the forces of the run equal all-pairs forces at its positions.
#[test]
fn forces_during_a_run_equal_all_pairs() {
    let (b, x) = Lattice::Fcc.build(4, 0.8442).unwrap();
    let v = maxwell_boltzmann(1.44, 1.0, 3, x.len(), 5).unwrap();
    let lj = LennardJones::reduced(2.5).unwrap();
    let mut md = Md::new(b, lj, x, v, MdConfig::default()).unwrap();
    md.run(60).unwrap();
    assert!(
        md.rebuilds() > 1,
        "the list was rebuilt {} times",
        md.rebuilds()
    );
    let mut g = vec![[0.0; 3]; md.len()];
    let sums = all_pairs_forces(&lj, md.sim_box(), &md.positions(), &mut g);
    let scale = g.iter().flatten().fold(1.0f64, |m, v| m.max(v.abs()));
    for (f, g) in md.forces().iter().zip(&g) {
        for k in 0..3 {
            assert!((f[k] - g[k]).abs() < 1e-12 * scale);
        }
    }
    assert!((md.pair_sums().potential - sums.potential).abs() < 1e-12 * sums.potential.abs());
}

/// The half list holds every pair closer than the range exactly once (as all-pairs
/// minimum-image distances say), whatever the number of slabs, periodic or open.
#[test]
fn half_list_holds_each_pair_within_range_once() {
    let open = SimBox::new(3, [20.0; 3], [false; 3]).unwrap();
    let mut rng = Xoshiro256::seed(11);
    let scattered: Vec<[f64; 3]> = (0..300)
        .map(|_| std::array::from_fn(|_| 9.0 * rng.uniform()))
        .collect();
    let cases = [
        (jittered(Lattice::Fcc, 4, 0.8442, 0.15, 1), 1),
        (jittered(Lattice::Fcc, 6, 0.8442, 0.15, 2), 3),
        (jittered(Lattice::Fcc, 8, 0.8442, 0.15, 3), 4),
        (jittered(Lattice::Chain, 40, 1.0, 0.2, 4), 14),
        ((open, scattered), 3),
    ];
    for ((b, x), slabs) in &cases {
        let range = 2.8;
        let list = NeighbourList::build(b, x, range, None);
        assert_eq!(list.slab_count(), *slabs, "dim {}", b.dim());
        let mut listed: Vec<(usize, usize)> =
            list.pairs().map(|(i, j)| (i.min(j), i.max(j))).collect();
        listed.sort_unstable();
        let mut expected = Vec::new();
        for i in 0..x.len() {
            for j in i + 1..x.len() {
                let d = b.separation(&x[i], &x[j]);
                if d.iter().map(|c| c * c).sum::<f64>() < range * range {
                    expected.push((i, j));
                }
            }
        }
        assert_eq!(list.pair_count(), expected.len());
        assert!(listed == expected, "dim {} with {slabs} slabs", b.dim());
    }
}

/// The slab count and the bits of the forces, energy and virial on `pool`.
fn force_bits<P: PairPotential>(
    law: &P,
    b: &SimBox,
    x: &[[f64; 3]],
    pool: Option<&rayon::ThreadPool>,
) -> (usize, Vec<u64>) {
    let list = NeighbourList::build(b, x, law.cutoff() + 0.3, pool);
    let mut f = vec![[0.0; 3]; x.len()];
    let s = compute_forces(law, b, &list, x, &mut f, pool);
    let bits = f
        .iter()
        .flatten()
        .chain([&s.potential, &s.virial])
        .map(|c| c.to_bits())
        .collect();
    (list.slab_count(), bits)
}

/// The list and the per-slab reduction give the same bits on 1, 2 and 3 threads, with many
/// slabs (periodic fcc, 7 slabs; open box of soft spheres, 3 slabs).
#[test]
fn forces_are_bit_identical_on_1_2_3_threads_for_many_slabs() {
    let pools: Vec<rayon::ThreadPool> = [2, 3]
        .iter()
        .map(|&t| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(t)
                .build()
                .unwrap()
        })
        .collect();
    let lj = LennardJones::reduced(2.5).unwrap();
    let (fcc_box, fcc) = jittered(Lattice::Fcc, 12, 0.8442, 0.15, 7);
    let serial = force_bits(&lj, &fcc_box, &fcc, None);
    assert_eq!(serial.0, 7);
    for pool in &pools {
        assert!(force_bits(&lj, &fcc_box, &fcc, Some(pool)) == serial);
    }
    let soft = SoftSphere::new(5.0, 1.0).unwrap();
    let open = SimBox::new(3, [20.0; 3], [false; 3]).unwrap();
    let mut rng = Xoshiro256::seed(8);
    let cloud: Vec<[f64; 3]> = (0..400)
        .map(|_| std::array::from_fn(|_| 5.0 * rng.uniform()))
        .collect();
    let serial = force_bits(&soft, &open, &cloud, None);
    assert_eq!(serial.0, 3);
    for pool in &pools {
        assert!(force_bits(&soft, &open, &cloud, Some(pool)) == serial);
    }
}
