//! Forces, potential energy and virial in one pass over a half neighbour list.
//!
//! Each listed pair is evaluated once and, by Newton's third law, adds (F/r)(r_ij) (xᵢ − xⱼ)
//! to particle i and its opposite to j, its energy U(r_ij) and its virial (F/r) r_ij² to
//! the sums. The slabs of the list ([`NeighbourList`]) run independently, each into its
//! own buffer `[own particles | next slab's particles]`; then particle k's force is its own
//! slab's entry plus the previous slab's entry for it, in that fixed order, and the
//! energies are added in slab order. Neither the slabs nor any order depends on the number
//! of threads: serial and parallel runs are bit-identical.

use rayon::prelude::*;

use crate::Real;

use super::kernel::pair_kernel;
use super::neighbour::{SlabList, half_lengths};
use super::{NeighbourList, PairPotential, SimBox};

/// The potential energy and the virial W = Σ_pairs r_ij · F_ij of a force evaluation.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PairSums {
    /// Potential energy U.
    pub potential: Real,
    /// Virial W = Σ over pairs of r_ij · F_ij (pressure P = (N k T + W / d) / V).
    pub virial: Real,
}

/// One slab's local positions and forces: its own particles, then the next slab's.
type SlabBuffers = (Vec<[Real; 3]>, Vec<[Real; 3]>);

/// Per-slab position and force buffers of [`compute_forces_with`], kept between calls so a
/// step allocates nothing.
#[derive(Debug, Clone, Default)]
pub struct ForceScratch {
    slabs: Vec<SlabBuffers>,
}

/// Particles per work unit of the per-particle loops (gathers, integrator).
pub(crate) const CHUNK: usize = 1024;

/// Forces into `f` from the pairs of `list` closer than the potential's cut-off; on `pool`
/// when given, with the same result bit for bit. Allocates its buffers: a run uses
/// [`compute_forces_with`].
pub fn compute_forces<P: PairPotential>(
    potential: &P,
    sim_box: &SimBox,
    list: &NeighbourList,
    x: &[[Real; 3]],
    f: &mut [[Real; 3]],
    pool: Option<&rayon::ThreadPool>,
) -> PairSums {
    let mut scratch = ForceScratch::default();
    compute_forces_with(potential, sim_box, list, x, f, pool, &mut scratch)
}

/// [`compute_forces`] with buffers kept in `scratch`.
pub fn compute_forces_with<P: PairPotential>(
    potential: &P,
    sim_box: &SimBox,
    list: &NeighbourList,
    x: &[[Real; 3]],
    f: &mut [[Real; 3]],
    pool: Option<&rayon::ThreadPool>,
    scratch: &mut ForceScratch,
) -> PairSums {
    forces_summed(potential, sim_box, list, x, f, pool, scratch, true)
}

/// [`compute_forces_with`], the energy and the virial summed only when `energy` (else the
/// sums are zero; the forces are the same bits either way: a step whose energy nobody reads
/// skips them).
#[allow(clippy::too_many_arguments)] // compute_forces_with's, and the choice
pub(crate) fn forces_summed<P: PairPotential>(
    potential: &P,
    sim_box: &SimBox,
    list: &NeighbourList,
    x: &[[Real; 3]],
    f: &mut [[Real; 3]],
    pool: Option<&rayon::ThreadPool>,
    scratch: &mut ForceScratch,
    energy: bool,
) -> PairSums {
    if energy {
        forces::<P, true>(potential, sim_box, list, x, f, pool, scratch)
    } else {
        forces::<P, false>(potential, sim_box, list, x, f, pool, scratch)
    }
}

/// The forces, and the sums when `ENERGY`.
fn forces<P: PairPotential, const ENERGY: bool>(
    potential: &P,
    sim_box: &SimBox,
    list: &NeighbourList,
    x: &[[Real; 3]],
    f: &mut [[Real; 3]],
    pool: Option<&rayon::ThreadPool>,
    scratch: &mut ForceScratch,
) -> PairSums {
    assert!(
        x.len() == list.len() && f.len() == list.len(),
        "compute_forces: {} positions and {} forces for a list of {} particles",
        x.len(),
        f.len(),
        list.len()
    );
    let lengths = sim_box.lengths();
    let half = half_lengths(sim_box);
    let rc2 = potential.cutoff() * potential.cutoff();
    let order = list.order();
    scratch
        .slabs
        .resize_with(list.slab_count(), Default::default);
    let slab_task =
        |(s, (slab, (xl, fl))): (usize, (&SlabList, &mut SlabBuffers))| -> (Real, Real) {
            let (own, next) = list.slab_sizes(s);
            let lo = list.bounds[s];
            xl.clear();
            xl.extend(order[lo..lo + own].iter().map(|&i| x[i as usize]));
            if let Some(t) = list.next[s] {
                let lo_next = list.bounds[t];
                // Across the periodic x edge: shifted so no pair needs the x minimum image.
                let shift = if slab.shift_next { lengths[0] } else { 0.0 };
                xl.extend(order[lo_next..lo_next + next].iter().map(|&i| {
                    let p = x[i as usize];
                    [p[0] + shift, p[1], p[2]]
                }));
            }
            fl.clear();
            fl.resize(own + next, [0.0; 3]);
            pair_kernel::<P, ENERGY>(potential, (lengths, half), rc2, slab, own, xl, fl)
        };
    let partial: Vec<(Real, Real)> = match pool {
        Some(pool) => pool.install(|| {
            list.slabs
                .par_iter()
                .zip(scratch.slabs.par_iter_mut())
                .enumerate()
                .map(slab_task)
                .collect()
        }),
        None => list
            .slabs
            .iter()
            .zip(scratch.slabs.iter_mut())
            .enumerate()
            .map(slab_task)
            .collect(),
    };
    let slabs = &scratch.slabs;
    let gather = |(c, out): (usize, &mut [[Real; 3]])| {
        for (k, fi) in out.iter_mut().enumerate() {
            let r = list.cells.rank[c * CHUNK + k] as usize;
            let s = list.slab_of[r] as usize;
            let local = r - list.bounds[s];
            let mut sum = slabs[s].1[local];
            if let Some(p) = list.prev[s] {
                let other = slabs[p].1[list.slab_sizes(p).0 + local];
                for a in 0..3 {
                    sum[a] += other[a];
                }
            }
            *fi = sum;
        }
    };
    match pool {
        Some(pool) => pool.install(|| f.par_chunks_mut(CHUNK).enumerate().for_each(gather)),
        None => f.chunks_mut(CHUNK).enumerate().for_each(gather),
    }
    let mut sums = PairSums::default();
    for (u, w) in partial {
        sums.potential += u;
        sums.virial += w;
    }
    sums
}

/// The same sums over all pairs (minimum image, no list): the O(N²) reference the
/// neighbour-list forces are checked against.
pub fn all_pairs_forces<P: PairPotential>(
    potential: &P,
    sim_box: &SimBox,
    x: &[[Real; 3]],
    f: &mut [[Real; 3]],
) -> PairSums {
    let rc2 = potential.cutoff() * potential.cutoff();
    let mut sums = PairSums::default();
    f.fill([0.0; 3]);
    for i in 0..x.len() {
        for j in i + 1..x.len() {
            let d = sim_box.separation(&x[i], &x[j]);
            let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if r2 < rc2 {
                let (u, f_over_r) = potential.energy_force(r2);
                for a in 0..3 {
                    f[i][a] += f_over_r * d[a];
                    f[j][a] -= f_over_r * d[a];
                }
                sums.potential += u;
                sums.virial += f_over_r * r2;
            }
        }
    }
    sums
}
