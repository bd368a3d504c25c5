//! Cell lists and Verlet neighbour lists with a skin.
//!
//! Particles are binned into cells at least `r_c + skin` wide (the `CellList`); each
//! particle's neighbours within `r_c + skin` are then found in the cells at most two away
//! (cells half as wide: 5^d of them), instead of among all N. The list is FULL (every pair appears for both
//! partners, in a fixed order) so that each particle's force is a sum it owns, computed in the
//! same order whatever the number of threads: the price is twice the pair evaluations of a
//! half list, the gain is bit-identical serial and parallel runs without per-thread force
//! buffers. The list stays valid until some particle has moved more than skin/2 since it was
//! built (then no pair can have come from beyond `r_c + skin` to within `r_c`).

use rayon::prelude::*;

use crate::Real;

use super::SimBox;

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

/// Particles per work unit; fixed, so the order of every sum is independent of the threads.
pub(crate) const CHUNK: usize = 512;

/// Cells are at least range / REACH wide and a particle's neighbours are searched REACH
/// cells away: (2·REACH + 1)^d cells of volume (range/REACH)^d, closer to the sphere of
/// radius `range` than 3^d cells of width `range` (≈ 290 candidates instead of ≈ 500 at the
/// LJ melt's density).
const REACH: usize = 2;

/// A compressed full neighbour list: the neighbours of particle `i` are
/// `neighbours[start[i]..start[i + 1]]`.
#[derive(Debug, Clone, Default)]
pub struct NeighbourList {
    start: Vec<usize>,
    neighbours: Vec<u32>,
    range: Real,
}

/// Particles binned into cells of at least `range / REACH` along each axis.
struct CellList {
    n: [usize; 3],
    origin: [Real; 3],
    width: [Real; 3],
    /// Particles sorted by cell; those of cell c are `atoms[first[c]..first[c + 1]]`.
    first: Vec<usize>,
    atoms: Vec<u32>,
    /// Their positions in the same order, so a cell's atoms are read contiguously.
    sorted: Vec<[Real; 3]>,
    /// For each axis and each cell index along it, the distinct adjacent cell indices.
    adjacent: [Vec<Vec<usize>>; 3],
}

impl CellList {
    fn build(sim_box: &SimBox, x: &[[Real; 3]], range: Real) -> Self {
        let lengths = sim_box.lengths();
        let periodic = sim_box.is_periodic();
        let mut n = [1usize; 3];
        let mut origin = [0.0; 3];
        let mut width = [1.0; 3];
        for a in 0..3 {
            let (lo, extent) = if periodic[a] {
                (0.0, lengths[a])
            } else {
                let lo = x.iter().map(|p| p[a]).fold(Real::INFINITY, Real::min);
                let hi = x.iter().map(|p| p[a]).fold(Real::NEG_INFINITY, Real::max);
                if x.is_empty() {
                    (0.0, 0.0)
                } else {
                    (lo, hi - lo)
                }
            };
            n[a] = ((REACH as Real * extent / range).floor() as usize).clamp(1, 1 << 10);
            origin[a] = lo;
            width[a] = if extent > 0.0 {
                extent / n[a] as Real
            } else {
                1.0
            };
        }
        let adjacent = std::array::from_fn(|a| {
            (0..n[a])
                .map(|c| {
                    let mut v: Vec<usize> = Vec::with_capacity(2 * REACH + 1);
                    for d in -(REACH as i64)..=REACH as i64 {
                        let k = c as i64 + d;
                        let k = if periodic[a] {
                            k.rem_euclid(n[a] as i64)
                        } else if (0..n[a] as i64).contains(&k) {
                            k
                        } else {
                            continue;
                        };
                        if !v.contains(&(k as usize)) {
                            v.push(k as usize);
                        }
                    }
                    v
                })
                .collect()
        });
        let cell_of = |p: &[Real; 3]| {
            let mut c = 0;
            for a in 0..3 {
                let k = (((p[a] - origin[a]) / width[a]).floor() as i64).clamp(0, n[a] as i64 - 1);
                c = c * n[a] + k as usize;
            }
            c
        };
        let cells = n[0] * n[1] * n[2];
        let mut first = vec![0usize; cells + 1];
        let which: Vec<usize> = x.iter().map(cell_of).collect();
        for &c in &which {
            first[c + 1] += 1;
        }
        for c in 0..cells {
            first[c + 1] += first[c];
        }
        let mut fill = first.clone();
        let mut atoms = vec![0u32; x.len()];
        for (i, &c) in which.iter().enumerate() {
            atoms[fill[c]] = i as u32;
            fill[c] += 1;
        }
        let sorted = atoms.iter().map(|&i| x[i as usize]).collect();
        Self {
            n,
            origin,
            width,
            first,
            atoms,
            sorted,
            adjacent,
        }
    }

    fn coords(&self, p: &[Real; 3]) -> [usize; 3] {
        std::array::from_fn(|a| {
            (((p[a] - self.origin[a]) / self.width[a]).floor() as i64)
                .clamp(0, self.n[a] as i64 - 1) as usize
        })
    }
}

impl NeighbourList {
    /// The full list of pairs closer than `range` (minimum image on periodic axes), built
    /// through a cell list, on `pool` when given (same result either way). Positions must
    /// lie in the box on periodic axes ([`SimBox::wrap`]).
    pub fn build(
        sim_box: &SimBox,
        x: &[[Real; 3]],
        range: Real,
        pool: Option<&rayon::ThreadPool>,
    ) -> Self {
        let cells = CellList::build(sim_box, x, range);
        let r2 = range * range;
        let lengths = sim_box.lengths();
        let half = half_lengths(sim_box);
        let chunk_lists = |chunk: usize| -> (Vec<usize>, Vec<u32>) {
            let lo = chunk * CHUNK;
            let hi = (lo + CHUNK).min(x.len());
            let mut counts = Vec::with_capacity(hi - lo);
            let mut list = Vec::with_capacity((hi - lo) * 80);
            for (i, &xi) in x.iter().enumerate().take(hi).skip(lo) {
                let before = list.len();
                let c = cells.coords(&xi);
                for &cx in &cells.adjacent[0][c[0]] {
                    for &cy in &cells.adjacent[1][c[1]] {
                        for &cz in &cells.adjacent[2][c[2]] {
                            let cell = (cx * cells.n[1] + cy) * cells.n[2] + cz;
                            let (lo, hi) = (cells.first[cell], cells.first[cell + 1]);
                            for (xj, &j) in cells.sorted[lo..hi].iter().zip(&cells.atoms[lo..hi]) {
                                let dx = near_image(xi[0] - xj[0], lengths[0], half[0]);
                                let dy = near_image(xi[1] - xj[1], lengths[1], half[1]);
                                let dz = near_image(xi[2] - xj[2], lengths[2], half[2]);
                                if dx * dx + dy * dy + dz * dz < r2 && j as usize != i {
                                    list.push(j);
                                }
                            }
                        }
                    }
                }
                counts.push(list.len() - before);
            }
            (counts, list)
        };
        let chunks = x.len().div_ceil(CHUNK);
        let parts: Vec<(Vec<usize>, Vec<u32>)> = match pool {
            Some(pool) => pool.install(|| (0..chunks).into_par_iter().map(chunk_lists).collect()),
            None => (0..chunks).map(chunk_lists).collect(),
        };
        let total = parts.iter().map(|p| p.1.len()).sum();
        let mut start = Vec::with_capacity(x.len() + 1);
        let mut neighbours = Vec::with_capacity(total);
        start.push(0);
        for (counts, list) in parts {
            for c in counts {
                start.push(start.last().copied().unwrap_or(0) + c);
            }
            neighbours.extend_from_slice(&list);
        }
        Self {
            start,
            neighbours,
            range,
        }
    }

    /// The neighbours of particle `i`.
    #[inline]
    pub fn of(&self, i: usize) -> &[u32] {
        &self.neighbours[self.start[i]..self.start[i + 1]]
    }

    /// The number of particles listed.
    pub fn len(&self) -> usize {
        self.start.len().saturating_sub(1)
    }

    /// Whether no particle is listed.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of (ordered) pairs: twice the number of distinct pairs.
    pub fn pairs(&self) -> usize {
        self.neighbours.len()
    }

    /// The range it was built for, `r_c + skin`.
    pub fn range(&self) -> Real {
        self.range
    }
}
