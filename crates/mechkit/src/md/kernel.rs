//! The pair kernel: one slab's listed pairs, four partners at a time.
//!
//! A particle's partners are taken in groups of four lanes: their separations, the pair law
//! and the forces are computed lane by lane on arrays of four, which the compiler turns into
//! vector instructions (one 4-wide division for four `1/r²`); the reactions are then
//! subtracted from each partner in turn, and the particle's own force is kept in four lane
//! sums added in a fixed order at the end of its row. On x86-64 hosts with AVX2 the same code
//! is compiled a second time for 256-bit vectors and chosen at run time; both versions do the
//! same IEEE operations in the same order (no fused multiply-add is introduced), so the
//! results do not depend on which one runs, nor on the threads.
//!
//! Pairs beyond the cut-off (about 30 % of a list with a 0.3σ skin) are evaluated at
//! r = r_c and multiplied by 0: no branch to mispredict. The energy and the virial are summed
//! only when asked for (`ENERGY`); a step whose energy nobody reads skips them.

// The portable body is inlined into the AVX2 version so that it is compiled for AVX2 there:
// without `inline(always)` it could stay one out-of-line function compiled for the baseline.
#![allow(clippy::inline_always)]

use crate::Real;

use super::PairPotential;
use super::neighbour::{Offset, SlabList, near_image};

/// Lanes per group of partners.
const LANES: usize = 4;

/// The box for the minimum image: lengths and half-lengths (∞ on open axes).
pub(super) type BoxHalves = ([Real; 3], [Real; 3]);

/// A slab's positions and forces: its own particles' (sorted), and the next slab's.
pub(super) struct SlabData<'a> {
    pub(super) x_own: &'a [[Real; 3]],
    pub(super) x_next: &'a [[Real; 3]],
    /// The next slab lies this far on in x (one box length across the periodic x edge).
    pub(super) shift_next: Real,
    /// Forces on the own particles (added to).
    pub(super) f_own: &'a mut [[Real; 3]],
    /// Reactions on the next slab's particles (added to).
    pub(super) f_next: &'a mut [[Real; 3]],
}

/// One slab's pairs: forces added into `data`'s force slices, returning the slab's energy
/// and virial (zero unless `ENERGY`).
pub(super) fn pair_kernel<P: PairPotential, const ENERGY: bool>(
    potential: &P,
    box_: BoxHalves,
    rc2: Real,
    slab: &SlabList,
    data: SlabData<'_>,
) -> (Real, Real) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the host has AVX2, which is all `pair_kernel_avx2` is compiled for.
        #[allow(unsafe_code)]
        return unsafe { pair_kernel_avx2::<P, ENERGY>(potential, box_, rc2, slab, data) };
    }
    pair_kernel_lanes::<P, ENERGY>(potential, box_, rc2, slab, data)
}

/// [`pair_kernel_lanes`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn pair_kernel_avx2<P: PairPotential, const ENERGY: bool>(
    potential: &P,
    box_: BoxHalves,
    rc2: Real,
    slab: &SlabList,
    data: SlabData<'_>,
) -> (Real, Real) {
    pair_kernel_lanes::<P, ENERGY>(potential, box_, rc2, slab, data)
}

/// The kernel for any host; inlined into the AVX2 version.
#[inline(always)]
fn pair_kernel_lanes<P: PairPotential, const ENERGY: bool>(
    potential: &P,
    box_: BoxHalves,
    rc2: Real,
    slab: &SlabList,
    data: SlabData<'_>,
) -> (Real, Real) {
    if slab.is_wide {
        slab_rows::<P, ENERGY, u32>(potential, box_, rc2, slab, data)
    } else {
        slab_rows::<P, ENERGY, u16>(potential, box_, rc2, slab, data)
    }
}

/// The slab's rows, its partners' offsets of type `I`.
#[inline(always)]
fn slab_rows<P: PairPotential, const ENERGY: bool, I: Offset>(
    potential: &P,
    box_: BoxHalves,
    rc2: Real,
    slab: &SlabList,
    data: SlabData<'_>,
) -> (Real, Real) {
    let SlabData {
        x_own,
        x_next,
        shift_next,
        f_own,
        f_next,
    } = data;
    let (mut u_sum, mut w_sum) = (0.0, 0.0);
    for (i, &xi) in x_own.iter().enumerate() {
        let (same, next) = slab.partners::<I>(i);
        let xi_next = [xi[0] - shift_next, xi[1], xi[2]];
        let ((a, u, w), (b, u2, w2)) = if slab.wraps[i] {
            (
                row::<P, true, ENERGY, I>(potential, box_, rc2, xi, same, i + 1, x_own, f_own),
                row::<P, true, ENERGY, I>(potential, box_, rc2, xi_next, next, 0, x_next, f_next),
            )
        } else {
            (
                row::<P, false, ENERGY, I>(potential, box_, rc2, xi, same, i + 1, x_own, f_own),
                row::<P, false, ENERGY, I>(potential, box_, rc2, xi_next, next, 0, x_next, f_next),
            )
        };
        if ENERGY {
            u_sum += u + u2;
            w_sum += w + w2;
        }
        let fi = &mut f_own[i];
        fi[0] += a[0] + b[0];
        fi[1] += a[1] + b[1];
        fi[2] += a[2] + b[2];
    }
    (u_sum, w_sum)
}

/// Four-lane sums of a row: force components, energy, virial.
#[derive(Clone, Copy, Default)]
struct Sums {
    f: [[Real; LANES]; 3],
    u: [Real; LANES],
    w: [Real; LANES],
}

/// The pairs of one particle at `xi` with its listed partners, at `base` plus the offsets
/// `nb` in `xl`: their reactions go into `fl`, the particle's own force, the energy and the
/// virial are returned. `WRAP`: apply the minimum image, else the plain difference.
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the slab's state, passed to an inlined helper
fn row<P: PairPotential, const WRAP: bool, const ENERGY: bool, I: Offset>(
    potential: &P,
    box_: BoxHalves,
    rc2: Real,
    xi: [Real; 3],
    nb: &[I],
    base: usize,
    xl: &[[Real; 3]],
    fl: &mut [[Real; 3]],
) -> ([Real; 3], Real, Real) {
    let mut sums = Sums::default();
    let mut groups = nb.chunks_exact(LANES);
    for group in &mut groups {
        let idx: [usize; LANES] = std::array::from_fn(|l| base + group[l].get());
        lanes::<P, WRAP, ENERGY>(potential, box_, rc2, xi, idx, LANES, xl, fl, &mut sums);
    }
    let rest = groups.remainder();
    if let Some(&first) = rest.first() {
        // the missing lanes repeat the first partner, masked out, their reactions not applied
        let idx: [usize; LANES] =
            std::array::from_fn(|l| base + rest.get(l).copied().unwrap_or(first).get());
        lanes::<P, WRAP, ENERGY>(potential, box_, rc2, xi, idx, rest.len(), xl, fl, &mut sums);
    }
    let add = |s: [Real; LANES]| (s[0] + s[1]) + (s[2] + s[3]);
    (
        [add(sums.f[0]), add(sums.f[1]), add(sums.f[2])],
        add(sums.u),
        add(sums.w),
    )
}

/// One group: the partners `idx[..count]` of the particle at `xi` (lanes past `count` are
/// evaluated and masked out).
#[inline(always)]
#[allow(clippy::too_many_arguments)] // the row's state, passed to an inlined helper
fn lanes<P: PairPotential, const WRAP: bool, const ENERGY: bool>(
    potential: &P,
    (lengths, half): BoxHalves,
    rc2: Real,
    xi: [Real; 3],
    idx: [usize; LANES],
    count: usize,
    xl: &[[Real; 3]],
    fl: &mut [[Real; 3]],
    sums: &mut Sums,
) {
    let xj: [[Real; 3]; LANES] = std::array::from_fn(|l| xl[idx[l]]);
    let mut d = [[0.0; LANES]; 3];
    for a in 0..3 {
        for l in 0..LANES {
            d[a][l] = xi[a] - xj[l][a];
            if WRAP {
                d[a][l] = near_image(d[a][l], lengths[a], half[a]);
            }
        }
    }
    let mut r2 = [0.0; LANES];
    let mut mask = [0.0; LANES];
    let mut u = [0.0; LANES];
    let mut f_over_r = [0.0; LANES];
    for l in 0..LANES {
        r2[l] = d[0][l] * d[0][l] + d[1][l] * d[1][l] + d[2][l] * d[2][l];
        mask[l] = Real::from(u8::from(r2[l] < rc2 && l < count));
        let (ul, fl) = potential.energy_force(r2[l].min(rc2));
        u[l] = mask[l] * ul;
        f_over_r[l] = mask[l] * fl;
    }
    let mut f = [[0.0; LANES]; 3];
    for a in 0..3 {
        for l in 0..LANES {
            f[a][l] = f_over_r[l] * d[a][l];
            sums.f[a][l] += f[a][l];
        }
    }
    if ENERGY {
        for l in 0..LANES {
            sums.u[l] += u[l];
            sums.w[l] += f_over_r[l] * r2[l];
        }
    }
    for l in 0..count.min(LANES) {
        let fj = &mut fl[idx[l]];
        fj[0] -= f[0][l];
        fj[1] -= f[1][l];
        fj[2] -= f[2][l];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::md::neighbour::half_lengths;
    use crate::md::{Lattice, LennardJones, NeighbourList, Xoshiro256};

    /// The version chosen at run time (AVX2 here when the host has it) and the portable one
    /// give the same forces, energy and virial, bit for bit, rows of every length included.
    #[test]
    fn the_avx2_and_the_portable_kernels_agree_bit_for_bit() {
        let (b, mut x) = Lattice::Fcc.build(6, 0.8442).unwrap();
        let mut rng = Xoshiro256::seed(5);
        for p in &mut x {
            for c in p.iter_mut() {
                *c += 0.2 * (rng.uniform() - 0.5);
            }
            b.wrap(p);
        }
        let list = NeighbourList::build(&b, &x, 2.8, None);
        let lj = LennardJones::new(1.1, 0.95, 2.5, true).unwrap();
        let box_ = (b.lengths(), half_lengths(&b));
        let mut lengths = std::collections::BTreeSet::new();
        let xs = &list.cells.sorted;
        let range = |s: usize| list.bounds[s]..list.bounds[s + 1];
        for s in 0..list.slab_count() {
            let slab = &list.slabs[s];
            let (own, next) = list.slab_sizes(s);
            let x_next = list.next[s].map_or(&xs[..0], |t| &xs[range(t)]);
            let shift_next = if slab.shift_next { b.lengths()[0] } else { 0.0 };
            let run = |f: &mut Vec<[Real; 3]>, g: &mut Vec<[Real; 3]>, portable, energy| {
                f.clear();
                f.resize(own, [0.0; 3]);
                g.clear();
                g.resize(next, [0.0; 3]);
                let data = SlabData {
                    x_own: &xs[range(s)],
                    x_next,
                    shift_next,
                    f_own: f,
                    f_next: g,
                };
                match (portable, energy) {
                    (false, true) => pair_kernel::<_, true>(&lj, box_, 6.25, slab, data),
                    (true, true) => pair_kernel_lanes::<_, true>(&lj, box_, 6.25, slab, data),
                    (_, false) => pair_kernel::<_, false>(&lj, box_, 6.25, slab, data),
                }
            };
            let (mut f1, mut g1, mut f2, mut g2) = (vec![], vec![], vec![], vec![]);
            let a = run(&mut f1, &mut g1, false, true);
            let c = run(&mut f2, &mut g2, true, true);
            assert_eq!(a, c);
            assert_eq!((&f1, &g1), (&f2, &g2));
            assert_eq!(run(&mut f2, &mut g2, false, false), (0.0, 0.0));
            assert_eq!((&f1, &g1), (&f2, &g2));
            for i in 0..own {
                let (same, next) = slab.partners::<u16>(i);
                lengths.insert(same.len() % LANES);
                lengths.insert(next.len() % LANES);
            }
        }
        assert_eq!(lengths.len(), LANES, "rows of every remainder: {lengths:?}");
    }
}
