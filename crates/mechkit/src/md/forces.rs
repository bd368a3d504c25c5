//! Forces, potential energy and virial in one pass over a half neighbour list.
//!
//! Each listed pair is evaluated once and, by Newton's third law, adds (F/r)(r_ij) (xᵢ − xⱼ)
//! to particle i and its opposite to j, its energy U(r_ij) and its virial (F/r) r_ij² to
//! the sums. The particles are taken in the list's sorted order. The even slabs of the list
//! ([`NeighbourList`]) take their pairs in parallel, then the odd ones: a slab writes the
//! forces of its particles and of the next slab's, which no other slab of its parity
//! touches. The last slab's reactions on the first, across the periodic x edge, go into a
//! buffer added to the first slab at the end. In each pass the
//! slabs are split in halves, recursively, into a fixed tree whose halves run in parallel,
//! and the energies are added up that tree. Neither the slabs nor any order depends on the
//! number of threads: serial and parallel runs are bit-identical.

use crate::Real;

use super::kernel::{SlabData, pair_kernel};
use super::neighbour::half_lengths;
use super::{NeighbourList, PairPotential, SimBox};

/// The potential energy and the virial W = Σ_pairs r_ij · F_ij of a force evaluation.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct PairSums {
    /// Potential energy U.
    pub potential: Real,
    /// Virial W = Σ over pairs of r_ij · F_ij (pressure P = (N k T + W / d) / V).
    pub virial: Real,
}

/// Buffers of [`compute_forces_with`], kept between calls so a step allocates nothing: the
/// reactions on the first slab of the pairs across the periodic x edge, and the positions
/// and forces in sorted order when the particles are not stored sorted.
#[derive(Debug, Clone, Default)]
pub struct ForceScratch {
    wrap: Vec<[Real; 3]>,
    xs: Vec<[Real; 3]>,
    fs: Vec<[Real; 3]>,
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

/// [`compute_forces`] with buffers kept in `scratch`. The particles are in the order the
/// list was built from; they are sorted into `scratch` and their forces put back.
pub fn compute_forces_with<P: PairPotential>(
    potential: &P,
    sim_box: &SimBox,
    list: &NeighbourList,
    x: &[[Real; 3]],
    f: &mut [[Real; 3]],
    pool: Option<&rayon::ThreadPool>,
    scratch: &mut ForceScratch,
) -> PairSums {
    check_lengths(list, x, f);
    let order = list.order();
    let (mut xs, mut fs) = (
        std::mem::take(&mut scratch.xs),
        std::mem::take(&mut scratch.fs),
    );
    xs.clear();
    xs.extend(order.iter().map(|&i| x[i as usize]));
    fs.resize(x.len(), [0.0; 3]);
    let sums = forces_summed(potential, sim_box, list, &xs, &mut fs, pool, scratch, true);
    for (&i, fk) in order.iter().zip(&fs) {
        f[i as usize] = *fk;
    }
    (scratch.xs, scratch.fs) = (xs, fs);
    sums
}

/// The forces on particles stored in the list's sorted order (`xs`, `fs`), the energy and
/// the virial summed only when `energy` (else the sums are zero; the forces are the same
/// bits either way: a step whose energy nobody reads skips them).
#[allow(clippy::too_many_arguments)] // compute_forces_with's, and the choice
pub(crate) fn forces_summed<P: PairPotential>(
    potential: &P,
    sim_box: &SimBox,
    list: &NeighbourList,
    xs: &[[Real; 3]],
    fs: &mut [[Real; 3]],
    pool: Option<&rayon::ThreadPool>,
    scratch: &mut ForceScratch,
    energy: bool,
) -> PairSums {
    check_lengths(list, xs, fs);
    let (u, w) = match pool {
        Some(pool) => {
            pool.install(|| forces(potential, sim_box, list, xs, fs, true, scratch, energy))
        }
        None => forces(potential, sim_box, list, xs, fs, false, scratch, energy),
    };
    PairSums {
        potential: u,
        virial: w,
    }
}

/// Panics unless there is a position and a force for each particle of the list (a caller's
/// bug, not an input's).
fn check_lengths(list: &NeighbourList, x: &[[Real; 3]], f: &[[Real; 3]]) {
    assert!(
        x.len() == list.len() && f.len() == list.len(),
        "compute_forces: {} positions and {} forces for a list of {} particles",
        x.len(),
        f.len(),
        list.len()
    );
}

/// The two passes: the even slabs, then the odd ones, each slab with all its pairs (a
/// slab and the slab after it do not overlap those of another slab of the same parity); the
/// last slab's reactions across the periodic x edge into a buffer added to the first slab
/// at the end.
#[allow(clippy::too_many_arguments)] // forces_summed's, resolved
fn forces<P: PairPotential>(
    potential: &P,
    sim_box: &SimBox,
    list: &NeighbourList,
    xs: &[[Real; 3]],
    fs: &mut [[Real; 3]],
    par: bool,
    scratch: &mut ForceScratch,
    energy: bool,
) -> (Real, Real) {
    let lengths = sim_box.lengths();
    let box_ = (lengths, half_lengths(sim_box));
    let rc2 = potential.cutoff() * potential.cutoff();
    let bounds = &list.bounds;
    let range = |s: usize| bounds[s]..bounds[s + 1];
    let kernel = |s: usize, f_own: &mut [[Real; 3]], f_next: &mut [[Real; 3]]| {
        let slab = &list.slabs[s];
        let data = SlabData {
            x_own: &xs[range(s)],
            x_next: list.next[s].map_or(&xs[..0], |t| &xs[range(t)]),
            shift_next: if slab.shift_next { lengths[0] } else { 0.0 },
            f_own,
            f_next,
        };
        if energy {
            pair_kernel::<P, true>(potential, box_, rc2, slab, data)
        } else {
            pair_kernel::<P, false>(potential, box_, rc2, slab, data)
        }
    };
    // the slab whose next is the first, across the periodic x edge
    let wrap = (0..list.slab_count()).find(|&s| list.next[s].is_some_and(|t| t < s));
    let buffer = &mut scratch.wrap;
    buffer.clear();
    buffer.resize(wrap.map_or(0, |_| bounds[1]), [0.0; 3]);
    let buffer = std::sync::Mutex::new(buffer);
    let mut sums = (0.0, 0.0);
    let mut units = vec![(); list.slab_count()];
    for (c, pair_bounds) in list.pair_bounds.iter().enumerate() {
        if pair_bounds.len() < 2 {
            continue;
        }
        let pairs = |k: usize, f: &mut [[Real; 3]], (): &mut ()| {
            let s = c + 2 * k;
            if c == 0 {
                // the even slabs come first: theirs and the odd slabs' forces start at zero
                f.fill([0.0; 3]);
            }
            let (f_own, f_next) = f.split_at_mut(bounds[s + 1] - bounds[s]);
            if Some(s) == wrap {
                let mut g = buffer
                    .lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner);
                kernel(s, f_own, &mut g)
            } else {
                kernel(s, f_own, f_next)
            }
        };
        let (lo, hi) = (pair_bounds[0], pair_bounds[pair_bounds.len() - 1]);
        let (u, w) = slab_tree(&mut fs[lo..hi], pair_bounds, &mut units, 0, par, &pairs);
        sums = (sums.0 + u, sums.1 + w);
    }
    if wrap.is_some() {
        let g = buffer
            .into_inner()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        for (fk, gk) in fs[range(0)].iter_mut().zip(g.iter()) {
            for a in 0..3 {
                fk[a] += gk[a];
            }
        }
    }
    sums
}

/// `task` on every slab (numbered from `first`) with its own range of `f` and its entry of
/// `extra`, the slabs split in halves into a fixed tree (the halves on two threads of the
/// current pool when `par`); returns the sum of the tasks' pairs up that tree.
fn slab_tree<T: Send, F>(
    f: &mut [[Real; 3]],
    bounds: &[usize],
    extra: &mut [T],
    first: usize,
    par: bool,
    task: &F,
) -> (Real, Real)
where
    F: Fn(usize, &mut [[Real; 3]], &mut T) -> (Real, Real) + Sync,
{
    let count = bounds.len() - 1;
    if count == 1 {
        return task(first, f, &mut extra[0]);
    }
    let mid = count / 2;
    let (fa, fb) = f.split_at_mut(bounds[mid] - bounds[0]);
    let (ea, eb) = extra.split_at_mut(mid);
    let (ba, bb) = (&bounds[..=mid], &bounds[mid..]);
    let mut left = move || slab_tree(fa, ba, ea, first, par, task);
    let mut right = move || slab_tree(fb, bb, eb, first + mid, par, task);
    let (a, b) = if par && f_len_worth(bounds) {
        rayon::join(left, right)
    } else {
        (left(), right())
    };
    (a.0 + b.0, a.1 + b.1)
}

/// Whether the particles between `bounds`' ends are enough to split over two threads.
fn f_len_worth(bounds: &[usize]) -> bool {
    bounds[bounds.len() - 1] - bounds[0] >= CHUNK
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
