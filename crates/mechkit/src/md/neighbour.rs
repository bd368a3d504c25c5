//! Half Verlet neighbour lists with a skin, over slabs of a sorted cell list.
//!
//! The particles are sorted by cell ([`CellList`](super::cell_list)) and the x-layers of
//! cells are grouped into `S` slabs, each at least `REACH` layers (so at least `range`)
//! thick; `S` depends on the box and the range only, never on the threads. Every pair closer
//! than `range` is listed ONCE, by the slab of one partner, and its other partner lies in the
//! same slab or in the NEXT one (x + 1, periodically): a pair inside a slab belongs to the
//! partner with the lower sorted index, a pair across two slabs to the particle in the
//! earlier one. A particle's partners in its own slab come first, as offsets past it in the
//! slab, then those in the next slab, as indices into that one (16 bits each when they fit). So a slab's forces accumulate into
//! its own range of the sorted forces and into a buffer for the next slab, the slabs run in
//! parallel, and each slab's buffer is then added to the slab after it (see
//! [`compute_forces`](super::compute_forces)). Same slabs and order on one thread or many:
//! bit-identical results.
//!
//! The list stays valid until some particle has moved more than skin/2 since it was built
//! (then no pair can have come from beyond `r_c + skin` to within `r_c`).

use rayon::prelude::*;

use crate::Real;

use super::SimBox;
use super::cell_list::{CellList, REACH};
use super::list_build::SlabBuild;

/// Half the box length on periodic axes, ∞ on open ones.
pub(crate) fn half_lengths(sim_box: &SimBox) -> [Real; 3] {
    let (l, p) = (sim_box.lengths(), sim_box.is_periodic());
    std::array::from_fn(|a| if p[a] { 0.5 * l[a] } else { Real::INFINITY })
}

/// Minimum image for positions wrapped into the box (at most one box length apart, plus
/// half the skin moved since): one conditional shift is enough (`half` is ∞ on open axes).
#[inline]
pub(crate) fn near_image(d: Real, l: Real, half: Real) -> Real {
    let up = if d < -half { l } else { 0.0 };
    let down = if d > half { l } else { 0.0 };
    d + up - down
}

/// A partner's offset in a list: 16 bits where every offset of the slab fits, else 32.
pub(crate) trait Offset: Copy + Send + Sync {
    /// The largest offset the type holds.
    const MAX: usize;
    /// `v` (at most [`Offset::MAX`]).
    fn new(v: u32) -> Self;
    /// The offset.
    fn get(self) -> usize;
    /// The list of offsets of this width in `list`.
    fn of(list: &SlabList) -> &[Self];
    /// The same, to fill.
    fn of_mut(list: &mut SlabList) -> &mut Vec<Self>;
}

impl Offset for u16 {
    const MAX: usize = u16::MAX as usize;
    #[inline]
    fn new(v: u32) -> Self {
        v as u16
    }
    #[inline]
    fn get(self) -> usize {
        usize::from(self)
    }
    fn of(list: &SlabList) -> &[Self] {
        &list.narrow
    }
    fn of_mut(list: &mut SlabList) -> &mut Vec<Self> {
        &mut list.narrow
    }
}

impl Offset for u32 {
    const MAX: usize = u32::MAX as usize;
    #[inline]
    fn new(v: u32) -> Self {
        v
    }
    #[inline]
    fn get(self) -> usize {
        self as usize
    }
    fn of(list: &SlabList) -> &[Self] {
        &list.wide
    }
    fn of_mut(list: &mut SlabList) -> &mut Vec<Self> {
        &mut list.wide
    }
}

/// The half list of one slab. The partners of its particle `i` (index in the slab) are
/// `start[i]..mid[i]` of the offsets, in the slab at `i + 1 + offset`, and `mid[i]..start[i
/// + 1]`, in the next slab at `offset`. The offsets are 16 bits (`narrow`) when all of the
/// slab's fit (partners lie within about two layers of cells, so up to some 10⁶ particles),
/// else 32 (`wide`): half or all of a run's memory.
#[derive(Debug, Clone, Default)]
pub(crate) struct SlabList {
    pub(crate) start: Vec<u32>,
    pub(crate) mid: Vec<u32>,
    pub(crate) narrow: Vec<u16>,
    pub(crate) wide: Vec<u32>,
    /// Whether the offsets are in `wide`.
    pub(crate) is_wide: bool,
    /// Whether a particle may have partners across a periodic edge (its cell is within
    /// REACH cells of one, the x edge excepted when the next slab is taken shifted by
    /// L_x): only those need the minimum-image test per pair.
    pub(crate) wraps: Vec<bool>,
    /// Whether the next slab lies one box length further on in x (the last slab's next is
    /// the first, across the periodic x edge).
    pub(crate) shift_next: bool,
}

impl SlabList {
    /// The offsets of particle `i`'s partners in the slab and in the next slab.
    #[inline]
    pub(crate) fn partners<I: Offset>(&self, i: usize) -> (&[I], &[I]) {
        let (a, m, b) = (
            self.start[i] as usize,
            self.mid[i] as usize,
            self.start[i + 1] as usize,
        );
        let all = I::of(self);
        (&all[a..m], &all[m..b])
    }

    /// Particle `i`'s partners as indices in the slab (`true`) or the next slab.
    pub(crate) fn partner_indices(&self, i: usize) -> impl Iterator<Item = (bool, usize)> + '_ {
        let (a, m, b) = (
            self.start[i] as usize,
            self.mid[i] as usize,
            self.start[i + 1] as usize,
        );
        (a..b).map(move |k| {
            let offset = if self.is_wide {
                self.wide[k].get()
            } else {
                self.narrow[k].get()
            };
            if k < m {
                (true, i + 1 + offset)
            } else {
                (false, offset)
            }
        })
    }

    /// The number of pairs listed.
    pub(crate) fn pair_count(&self) -> usize {
        self.start.last().map_or(0, |&n| n as usize)
    }
}

/// A half neighbour list over slabs of particles sorted by cell.
#[derive(Debug, Clone, Default)]
pub struct NeighbourList {
    range: Real,
    pub(crate) cells: CellList,
    /// Slab s holds the sorted particles `bounds[s]..bounds[s + 1]`.
    pub(crate) bounds: Vec<usize>,
    /// The slab after each slab, if any.
    pub(crate) next: Vec<Option<usize>>,
    /// The slab before each slab, if any.
    pub(crate) prev: Vec<Option<usize>>,
    /// For the even (0) and the odd (1) slabs s: the bounds of the ranges of each with the
    /// slab after it, `bounds[s]..bounds[s + 2]` (the last slab's alone), which do not
    /// overlap.
    pub(crate) pair_bounds: [Vec<usize>; 2],
    pub(crate) slabs: Vec<SlabList>,
    /// Scratch: the slab of each x-layer of cells.
    layer_slab: Vec<usize>,
    /// Build every slab with 32-bit offsets (to test them on small systems).
    #[cfg(test)]
    pub(crate) wide_only: bool,
}

impl NeighbourList {
    /// The half list of pairs closer than `range` (minimum image on periodic axes), built
    /// through a cell list, on `pool` when given (same result either way). Positions must
    /// lie in the box on periodic axes ([`SimBox::wrap`]).
    pub fn build(
        sim_box: &SimBox,
        x: &[[Real; 3]],
        range: Real,
        pool: Option<&rayon::ThreadPool>,
    ) -> Self {
        let mut list = Self::default();
        list.rebuild(sim_box, x, range, pool);
        list
    }

    /// Rebuilds the list in place for new positions, reusing its buffers.
    pub fn rebuild(
        &mut self,
        sim_box: &SimBox,
        x: &[[Real; 3]],
        range: Real,
        pool: Option<&rayon::ThreadPool>,
    ) {
        self.sort(sim_box, x, range, pool);
        let mut sorted = std::mem::take(&mut self.cells.sorted);
        sorted.clear();
        sorted.extend(self.cells.order.iter().map(|&i| x[i as usize]));
        self.build_sorted(sim_box, &sorted, pool);
        self.cells.sorted = sorted;
    }

    /// Bins the particles at `x` into cells: [`NeighbourList::order`] is then the sorted
    /// order, and [`NeighbourList::build_sorted`] builds the lists from the positions in it.
    pub(crate) fn sort(
        &mut self,
        sim_box: &SimBox,
        x: &[[Real; 3]],
        range: Real,
        pool: Option<&rayon::ThreadPool>,
    ) {
        self.range = range;
        self.cells.rebuild(sim_box, x, range, pool);
        self.split_slabs(sim_box.is_periodic()[0]);
    }

    /// The lists, from `xs`: the positions [`NeighbourList::sort`] was given, in the sorted
    /// order.
    pub(crate) fn build_sorted(
        &mut self,
        sim_box: &SimBox,
        xs: &[[Real; 3]],
        pool: Option<&rayon::ThreadPool>,
    ) {
        let build = SlabBuild {
            cells: &self.cells,
            x: xs,
            bounds: &self.bounds,
            next: &self.next,
            layer_slab: &self.layer_slab,
            periodic: sim_box.is_periodic(),
            single: self.slabs.len() == 1,
            #[cfg(test)]
            wide_only: self.wide_only,
            box_: (sim_box.lengths(), half_lengths(sim_box)),
            r2: self.range * self.range,
        };
        let build_slab = |(s, list): (usize, &mut SlabList)| build.slab(s, list);
        match pool {
            Some(pool) => pool.install(|| {
                self.slabs.par_iter_mut().enumerate().for_each(build_slab);
            }),
            None => self.slabs.iter_mut().enumerate().for_each(build_slab),
        }
    }

    /// Groups the x-layers of cells into slabs at least REACH layers thick.
    fn split_slabs(&mut self, periodic_x: bool) {
        let layers = self.cells.n[0];
        let mut count = (layers / REACH).max(1);
        // Periodic: with two slabs each would be the other's next; use one.
        if periodic_x && count < 3 {
            count = 1;
        }
        self.layer_slab.clear();
        self.layer_slab
            .extend((0..layers).map(|l| l * count / layers));
        let per_layer = self.cells.n[1] * self.cells.n[2];
        self.bounds.clear();
        self.bounds.push(0);
        for l in 1..layers {
            if self.layer_slab[l] != self.layer_slab[l - 1] {
                self.bounds.push(self.cells.first[l * per_layer]);
            }
        }
        self.bounds.push(self.cells.order.len());
        self.next.clear();
        self.prev.clear();
        for s in 0..count {
            let next = if s + 1 < count {
                Some(s + 1)
            } else if periodic_x && count >= 3 {
                Some(0)
            } else {
                None
            };
            self.next.push(next);
            let prev = if s > 0 {
                Some(s - 1)
            } else if periodic_x && count >= 3 {
                Some(count - 1)
            } else {
                None
            };
            self.prev.push(prev);
        }
        self.slabs.resize_with(count, SlabList::default);
        for (c, pb) in self.pair_bounds.iter_mut().enumerate() {
            pb.clear();
            // bounds[c], bounds[c + 2], ..., bounds[count]: between two of them a slab and
            // the slab after it, or the last slab alone
            pb.extend((c..count).step_by(2).map(|i| self.bounds[i]));
            if c < count {
                pb.push(self.bounds[count]);
            }
        }
    }

    /// The number of particles of slab `s` and of its next slab.
    #[cfg(test)]
    pub(crate) fn slab_sizes(&self, s: usize) -> (usize, usize) {
        let own = self.bounds[s + 1] - self.bounds[s];
        let next = self.next[s].map_or(0, |t| self.bounds[t + 1] - self.bounds[t]);
        (own, next)
    }

    /// Every listed pair once, as original particle indices `(i, j)`.
    pub fn pairs(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.sorted_pairs()
            .map(|(i, j)| (self.cells.order[i] as usize, self.cells.order[j] as usize))
    }

    /// Every listed pair once, as sorted indices `(i, j)`.
    pub(crate) fn sorted_pairs(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.slabs.iter().enumerate().flat_map(move |(s, list)| {
            let (lo, own) = (self.bounds[s], self.bounds[s + 1] - self.bounds[s]);
            let lo_next = self.next[s].map_or(0, |t| self.bounds[t]);
            (0..own).flat_map(move |i| {
                list.partner_indices(i)
                    .map(move |(same, j)| (lo + i, if same { lo + j } else { lo_next + j }))
            })
        })
    }

    /// The number of particles listed.
    pub fn len(&self) -> usize {
        self.cells.order.len()
    }

    /// Whether no particle is listed.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of distinct pairs listed.
    pub fn pair_count(&self) -> usize {
        self.slabs.iter().map(SlabList::pair_count).sum()
    }

    /// The number of slabs the work is split into (set by the box and the range only).
    pub fn slab_count(&self) -> usize {
        self.slabs.len()
    }

    /// The range it was built for, `r_c + skin`.
    pub fn range(&self) -> Real {
        self.range
    }

    /// The sorted order: `order()[k]` is the original index of the k-th particle by cell.
    pub fn order(&self) -> &[u32] {
        &self.cells.order
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::md::forces::{ForceScratch, forces_summed};
    use crate::md::{Lattice, LennardJones, Xoshiro256};

    /// 32-bit offsets list the same pairs as 16-bit ones, and the forces come out the same
    /// bits from either.
    #[test]
    fn wide_and_narrow_offsets_list_the_same_pairs() {
        let (b, mut x) = Lattice::Fcc.build(7, 0.8442).unwrap();
        let mut rng = Xoshiro256::seed(11);
        for p in &mut x {
            for c in p.iter_mut() {
                *c += 0.3 * (rng.uniform() - 0.5);
            }
            b.wrap(p);
        }
        let narrow = NeighbourList::build(&b, &x, 2.8, None);
        let mut wide = NeighbourList {
            wide_only: true,
            ..NeighbourList::default()
        };
        wide.rebuild(&b, &x, 2.8, None);
        assert!(narrow.slab_count() > 1);
        assert!(narrow.slabs.iter().all(|s| !s.is_wide));
        assert!(wide.slabs.iter().all(|s| s.is_wide && s.narrow.is_empty()));
        let pairs = |l: &NeighbourList| l.pairs().collect::<Vec<_>>();
        assert_eq!(pairs(&narrow), pairs(&wide));
        let lj = LennardJones::reduced(2.5).unwrap();
        let xs = &narrow.cells.sorted;
        let forces = |l: &NeighbourList| {
            let mut f = vec![[0.0; 3]; x.len()];
            let mut scratch = ForceScratch::default();
            let sums = forces_summed(&lj, &b, l, xs, &mut f, None, &mut scratch, true);
            (f, sums)
        };
        assert_eq!(forces(&narrow), forces(&wide));
    }

    /// A periodic box thin in x is one slab whose pairs across the x edge lie most of the
    /// particles apart: 16 bits cannot hold them, and the 32-bit list has every pair. On a
    /// simple cubic lattice of spacing 1 each particle has 80 partners within 2.8 (40 listed
    /// with it), and every force is zero by symmetry.
    #[test]
    fn offsets_past_16_bits_are_listed_in_32() {
        let (lx, ly) = (6usize, 110usize);
        let b = SimBox::periodic(3, [lx as Real, ly as Real, ly as Real]).unwrap();
        let x: Vec<[Real; 3]> = (0..lx * ly * ly)
            .map(|k| {
                let (i, j, l) = (k / (ly * ly), (k / ly) % ly, k % ly);
                [i as Real + 0.5, j as Real + 0.5, l as Real + 0.5]
            })
            .collect();
        let list = NeighbourList::build(&b, &x, 2.8, None);
        assert_eq!(list.slab_count(), 1);
        assert!(list.slabs[0].is_wide);
        assert_eq!(list.pair_count(), 40 * x.len());
        let lj = LennardJones::reduced(2.5).unwrap();
        let mut f = vec![[0.0; 3]; x.len()];
        let mut scratch = ForceScratch::default();
        let xs = &list.cells.sorted;
        forces_summed(&lj, &b, &list, xs, &mut f, None, &mut scratch, true);
        let worst = f.iter().flatten().fold(0.0, |m: Real, c| m.max(c.abs()));
        assert!(worst < 1e-10, "{worst}");
    }
}
