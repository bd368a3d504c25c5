//! Cell lists: particles binned into cells and sorted by cell.
//!
//! Cells are at least `range / REACH` wide along each axis and numbered x-major
//! (`c = (cx · n_y + cy) · n_z + cz`). A counting sort, stable in the original index,
//! orders the particles by cell: the `order` permutation (sorted index → original index)
//! makes every cell's particles, and every x-layer of cells, a contiguous run, so a
//! neighbour search reads memory that is close together. All buffers are kept between
//! builds: a rebuild allocates nothing once they have grown to size.

use rayon::prelude::*;

use crate::Real;

use super::SimBox;

/// Cells are at least range / REACH wide and a particle's neighbours are searched REACH
/// cells away: (2·REACH + 1)^d cells of volume (range/REACH)^d, closer to the sphere of
/// radius `range` than 3^d cells of width `range`.
pub(crate) const REACH: usize = 2;

/// The cell grid holds at most this many cells per particle (and at least one cell). A
/// sparse system in a large box (256 atoms at density 10^-9) would otherwise get 1024 cells
/// on each axis, 10^9 cells and an 8.6 GB index, for cells that are nearly all empty: past
/// the bound the cells are made wider, which only adds candidate pairs. A liquid or a
/// crystal (ρ ≈ 0.8, a cut-off of 2.5σ) has about one cell for two particles, far below it.
pub(crate) const MAX_CELLS_PER_PARTICLE: usize = 4;

/// Cell indices within REACH of one cell index along an axis, without repeats, and the
/// same cells as runs of consecutive indices (at most two: a periodic wrap splits one).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Adjacent {
    pub(crate) cells: [u32; 2 * REACH + 1],
    pub(crate) len: usize,
    /// `(first, last)` cell index of each run, inclusive.
    pub(crate) runs: [(u32, u32); 2 * REACH + 1],
    pub(crate) run_count: usize,
}

impl Adjacent {
    /// The adjacent cell indices.
    #[inline]
    pub(crate) fn as_slice(&self) -> &[u32] {
        &self.cells[..self.len]
    }

    /// The adjacent cells as runs of consecutive indices.
    #[inline]
    pub(crate) fn runs(&self) -> &[(u32, u32)] {
        &self.runs[..self.run_count]
    }

    /// Groups the (distinct) cells into runs of consecutive indices.
    fn find_runs(&mut self) {
        let mut sorted = self.cells;
        sorted[..self.len].sort_unstable();
        self.run_count = 0;
        for &c in &sorted[..self.len] {
            if self.run_count > 0 && self.runs[self.run_count - 1].1 + 1 == c {
                self.runs[self.run_count - 1].1 = c;
            } else {
                self.runs[self.run_count] = (c, c);
                self.run_count += 1;
            }
        }
    }
}

/// Fewer cells per axis `n` until there are at most [`MAX_CELLS_PER_PARTICLE`] per particle:
/// the axis with the most cells has them halved, so the cells stay at least as wide as they
/// were and a neighbour search `REACH` cells away still covers the range. Grids within the
/// bound are left as they are.
fn bound_cells(n: &mut [usize; 3], particles: usize) {
    let most = MAX_CELLS_PER_PARTICLE.saturating_mul(particles).max(1);
    while n.iter().product::<usize>() > most {
        let a = (0..3)
            .max_by_key(|&a| (n[a], usize::MAX - a))
            .expect("three axes");
        n[a] = (n[a] / 2).max(1);
    }
}

/// The cell of a particle at `p` in a grid of `n` cells per axis from `origin`, each
/// `width` wide (clamped to the grid).
#[inline]
fn cell_in((n, origin, width): ([usize; 3], [Real; 3], [Real; 3]), p: &[Real; 3]) -> u32 {
    let mut c = 0;
    for a in 0..3 {
        let k = (((p[a] - origin[a]) / width[a]).floor() as i64).clamp(0, n[a] as i64 - 1);
        c = c * n[a] + k as usize;
    }
    c as u32
}

/// Particles binned into cells and sorted by cell.
#[derive(Debug, Clone, Default)]
pub(crate) struct CellList {
    /// Cells per axis.
    pub(crate) n: [usize; 3],
    origin: [Real; 3],
    width: [Real; 3],
    /// The sorted particles of cell c are `first[c]..first[c + 1]`.
    pub(crate) first: Vec<usize>,
    /// Sorted index → original index.
    pub(crate) order: Vec<u32>,
    /// Positions in sorted order, for lists built from positions in their original order
    /// ([`NeighbourList::rebuild`](super::NeighbourList::rebuild)); a run keeps its
    /// particles sorted and leaves this empty.
    pub(crate) sorted: Vec<[Real; 3]>,
    /// For each axis and each cell index along it, the distinct adjacent cell indices.
    pub(crate) adjacent: [Vec<Adjacent>; 3],
    /// Scratch: the cell of each particle in original order.
    which: Vec<u32>,
}

impl CellList {
    /// Bins and sorts the particles at `x` (wrapped into the box on periodic axes) into
    /// cells at least `range / REACH` wide.
    pub(crate) fn rebuild(
        &mut self,
        sim_box: &SimBox,
        x: &[[Real; 3]],
        range: Real,
        pool: Option<&rayon::ThreadPool>,
    ) {
        let lengths = sim_box.lengths();
        let periodic = sim_box.is_periodic();
        for a in 0..3 {
            let (lo, extent) = if periodic[a] {
                (0.0, lengths[a])
            } else if x.is_empty() {
                (0.0, 0.0)
            } else {
                let lo = x.iter().map(|p| p[a]).fold(Real::INFINITY, Real::min);
                let hi = x.iter().map(|p| p[a]).fold(Real::NEG_INFINITY, Real::max);
                (lo, hi - lo)
            };
            self.n[a] = ((REACH as Real * extent / range).floor() as usize).clamp(1, 1 << 10);
            self.origin[a] = lo;
            self.width[a] = extent;
        }
        bound_cells(&mut self.n, x.len());
        for (a, &wraps) in periodic.iter().enumerate() {
            self.width[a] = if self.width[a] > 0.0 {
                self.width[a] / self.n[a] as Real
            } else {
                1.0
            };
            let n = self.n[a] as i64;
            self.adjacent[a].clear();
            for c in 0..n {
                let mut adj = Adjacent::default();
                for d in -(REACH as i64)..=REACH as i64 {
                    let k = if wraps {
                        (c + d).rem_euclid(n)
                    } else if (0..n).contains(&(c + d)) {
                        c + d
                    } else {
                        continue;
                    };
                    if !adj.as_slice().contains(&(k as u32)) {
                        adj.cells[adj.len] = k as u32;
                        adj.len += 1;
                    }
                }
                adj.find_runs();
                self.adjacent[a].push(adj);
            }
        }
        let cells = self.n[0] * self.n[1] * self.n[2];
        let grid = (self.n, self.origin, self.width);
        let cell_of = |p: &[Real; 3]| cell_in(grid, p);
        if let Some(pool) = pool {
            pool.install(|| x.par_iter().map(cell_of).collect_into_vec(&mut self.which));
        } else {
            self.which.clear();
            self.which.extend(x.iter().map(cell_of));
        }
        self.first.clear();
        self.first.resize(cells + 1, 0);
        for &c in &self.which {
            self.first[c as usize + 1] += 1;
        }
        for c in 0..cells {
            self.first[c + 1] += self.first[c];
        }
        self.order.clear();
        self.order.resize(x.len(), 0);
        // Each cell's start serves as its fill pointer, then is shifted back.
        for (i, &c) in self.which.iter().enumerate() {
            let k = &mut self.first[c as usize];
            self.order[*k] = i as u32;
            *k += 1;
        }
        for c in (1..=cells).rev() {
            self.first[c] = self.first[c - 1];
        }
        self.first[0] = 0;
    }

    /// The cell of a particle at `p` (as the sort put it there).
    #[inline]
    pub(crate) fn cell_of(&self, p: &[Real; 3]) -> u32 {
        cell_in((self.n, self.origin, self.width), p)
    }

    /// The cell coordinates of cell `c`.
    #[inline]
    pub(crate) fn coords(&self, c: u32) -> [usize; 3] {
        let c = c as usize;
        let cz = c % self.n[2];
        let cy = (c / self.n[2]) % self.n[1];
        [c / (self.n[1] * self.n[2]), cy, cz]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::md::{Lattice, Xoshiro256};

    /// 256 atoms at density 10^-9 (a box 6350σ on a side) used to get 1024^3 cells and an
    /// 8.6 GB index; the grid is now bounded by the atom count, with every cell at least as
    /// wide as the rule asks.
    #[test]
    fn issue_026_a_sparse_box_gets_cells_by_its_atoms_not_its_size() {
        let (b, x) = Lattice::Fcc.build(4, 1e-9).unwrap();
        let mut cells = CellList::default();
        cells.rebuild(&b, &x, 2.8, None);
        let count: usize = cells.n.iter().product();
        assert!(count <= MAX_CELLS_PER_PARTICLE * x.len(), "{:?}", cells.n);
        assert_eq!(cells.first.len(), count + 1);
        for a in 0..3 {
            assert!(cells.width[a] >= 2.8 / REACH as Real, "{:?}", cells.width);
        }
        // a liquid keeps the grid the rule gives it
        let (b, x) = Lattice::Fcc.build(6, 0.8442).unwrap();
        cells.rebuild(&b, &x, 2.8, None);
        let edge = b.lengths()[0];
        let n = (REACH as Real * edge / 2.8).floor() as usize;
        assert_eq!(cells.n, [n; 3]);
        let mut n = [1024, 1024, 1024];
        bound_cells(&mut n, 256);
        assert_eq!(n, [8, 8, 16]);
        let mut n = [7, 1, 1];
        bound_cells(&mut n, 0);
        assert_eq!(n, [1, 1, 1]);
    }

    /// The sort is a permutation, and cells come in order with every particle in the cell
    /// that contains it.
    #[test]
    fn sorting_permutation_round_trips() {
        let (b, mut x) = Lattice::Fcc.build(4, 0.8442).unwrap();
        let mut rng = Xoshiro256::seed(3);
        for p in &mut x {
            for c in p.iter_mut() {
                *c += 0.3 * (rng.uniform() - 0.5);
            }
            b.wrap(p);
        }
        let mut cells = CellList::default();
        cells.rebuild(&b, &x, 2.8, None);
        let mut seen = vec![false; x.len()];
        for &i in &cells.order {
            assert!(!seen[i as usize]);
            seen[i as usize] = true;
        }
        let cell = |k: usize| cells.cell_of(&x[cells.order[k] as usize]);
        assert!((1..x.len()).all(|k| cell(k - 1) <= cell(k)));
        for c in 0..cells.first.len() - 1 {
            for k in cells.first[c]..cells.first[c + 1] {
                assert_eq!(cell(k) as usize, c);
                let cc = cells.coords(c as u32);
                for (a, &ca) in cc.iter().enumerate() {
                    let lo = ca as Real * cells.width[a];
                    let p = x[cells.order[k] as usize][a];
                    assert!(p >= lo - 1e-12 && p < lo + cells.width[a] + 1e-12);
                }
            }
        }
    }
}
