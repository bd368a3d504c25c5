//! Half Verlet neighbour lists with a skin, over slabs of a sorted cell list.
//!
//! The particles are sorted by cell ([`CellList`](super::cell_list)) and the x-layers of
//! cells are grouped into `S` slabs, each at least `REACH` layers (so at least `range`)
//! thick; `S` depends on the box and the range only, never on the threads. Every pair closer
//! than `range` is listed ONCE, by the slab of one partner, and its other partner lies in the
//! same slab or in the NEXT one (x + 1, periodically): a pair inside a slab belongs to the
//! partner with the lower sorted index, a pair across two slabs to the particle in the
//! earlier one. A particle's partners in its own slab come first, as indices into the slab,
//! then those in the next slab, as indices into that one. So a slab's forces accumulate into
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

/// The half list of one slab: the partners of its particle `i` (index in the slab) are
/// `neighbours[start[i]..mid[i]]`, indices into the slab, and `neighbours[mid[i]..start[i +
/// 1]]`, indices into the next slab.
#[derive(Debug, Clone, Default)]
pub(crate) struct SlabList {
    pub(crate) start: Vec<u32>,
    pub(crate) mid: Vec<u32>,
    pub(crate) neighbours: Vec<u32>,
    /// Whether a particle may have partners across a periodic edge (its cell is within
    /// REACH cells of one, the x edge excepted when the next slab is taken shifted by
    /// L_x): only those need the minimum-image test per pair.
    pub(crate) wraps: Vec<bool>,
    /// Whether the next slab lies one box length further on in x (the last slab's next is
    /// the first, across the periodic x edge).
    pub(crate) shift_next: bool,
}

impl SlabList {
    /// The partners of particle `i` in the slab and in the next slab.
    #[inline]
    pub(crate) fn partners(&self, i: usize) -> (&[u32], &[u32]) {
        let (a, m, b) = (
            self.start[i] as usize,
            self.mid[i] as usize,
            self.start[i + 1] as usize,
        );
        (&self.neighbours[a..m], &self.neighbours[m..b])
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
    pub(crate) slabs: Vec<SlabList>,
    /// Scratch: the slab of each x-layer of cells.
    layer_slab: Vec<usize>,
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
    }

    /// The number of particles of slab `s` and of its next slab.
    #[inline]
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
                let (same, next) = list.partners(i);
                let same = same.iter().map(move |&j| (lo + i, lo + j as usize));
                let next = next.iter().map(move |&j| (lo + i, lo_next + j as usize));
                same.chain(next)
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
        self.slabs.iter().map(|s| s.neighbours.len()).sum()
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
