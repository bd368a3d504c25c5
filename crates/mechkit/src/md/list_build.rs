//! Building one slab's half list: for each of its particles, the candidates of the cells
//! within reach, kept when closer than the range.
//!
//! The candidates of a run of cells are contiguous in sorted order; their distances are
//! computed four at a time and the indices of those in range written all four at once (see
//! `scan`). On x86-64 hosts with AVX2 the build is compiled a second time for it and chosen at
//! run time; both give the same list.

// The portable body is inlined into the AVX2 version so that it is compiled for AVX2 there:
// without `inline(always)` it could stay one out-of-line function compiled for the baseline.
#![allow(clippy::inline_always)]

use crate::Real;

use super::cell_list::{CellList, REACH};
use super::neighbour::{Offset, SlabList, near_image};

/// What every slab's build reads.
pub(super) struct SlabBuild<'a> {
    pub(super) cells: &'a CellList,
    /// The positions in sorted order.
    pub(super) x: &'a [[Real; 3]],
    /// Slab s holds the sorted particles `bounds[s]..bounds[s + 1]`.
    pub(super) bounds: &'a [usize],
    /// The slab after each slab, if any.
    pub(super) next: &'a [Option<usize>],
    /// The slab of each x-layer of cells.
    pub(super) layer_slab: &'a [usize],
    pub(super) periodic: [bool; 3],
    /// Whether there is one slab (then it is its own neighbour across the x edge).
    pub(super) single: bool,
    /// Build with 32-bit offsets only.
    #[cfg(test)]
    pub(super) wide_only: bool,
    /// Lengths and half-lengths of the box (∞ on open axes).
    pub(super) box_: ([Real; 3], [Real; 3]),
    /// The range squared.
    pub(super) r2: Real,
}

impl SlabBuild<'_> {
    /// Builds slab `s`'s list into `list`, reusing its buffers.
    pub(super) fn slab(&self, s: usize, list: &mut SlabList) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the host has AVX2, which is all `slab_avx2` is compiled for.
            #[allow(unsafe_code)]
            return unsafe { self.slab_avx2(s, list) };
        }
        self.slab_any(s, list);
    }

    /// [`SlabBuild::slab_any`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn slab_avx2(&self, s: usize, list: &mut SlabList) {
        self.slab_any(s, list);
    }

    /// The build for any host; inlined into the AVX2 version: 16-bit offsets, or 32-bit
    /// ones when some offset does not fit 16 bits.
    #[inline(always)]
    fn slab_any(&self, s: usize, list: &mut SlabList) {
        #[cfg(test)]
        if self.wide_only {
            list.narrow = Vec::new();
            list.is_wide = self.fill::<u32>(s, list);
            return;
        }
        list.is_wide = !self.fill::<u16>(s, list);
        if list.is_wide {
            list.narrow = Vec::new();
            let filled = self.fill::<u32>(s, list);
            debug_assert!(filled, "a slab of more than 2^32 particles");
        } else {
            // (a build before may have needed them)
            list.wide = Vec::new();
        }
    }

    /// Fills slab `s`'s list with offsets of type `I`; false, with the list empty, if some
    /// offset does not fit.
    #[inline(always)]
    fn fill<I: Offset>(&self, s: usize, list: &mut SlabList) -> bool {
        let (cells, next, lengths, xs) = (self.cells, self.next, self.box_.0, self.x);
        let (lo, hi) = (self.bounds[s], self.bounds[s + 1]);
        let lo_next = next[s].map_or(0, |t| self.bounds[t]);
        let mut out = std::mem::take(I::of_mut(list));
        out.clear();
        list.start.clear();
        list.mid.clear();
        list.wraps.clear();
        list.shift_next = next[s].is_some_and(|t| t < s);
        // Across the periodic x edge the next slab lies one box length further on.
        let shift = if list.shift_next { lengths[0] } else { 0.0 };
        list.start.push(0);
        let mut fits = true;
        'particles: for i in lo..hi {
            let xi = xs[i];
            let c = cells.coords(cells.cell_of(&xi));
            let edge = |a: usize| self.periodic[a] && (c[a] < REACH || c[a] + REACH >= cells.n[a]);
            let wraps = (self.single && edge(0)) || edge(1) || edge(2);
            list.wraps.push(wraps);
            // Partners in the slab first, then those in the next slab.
            for same in [true, false] {
                if !same && next[s].is_none() {
                    break;
                }
                let xi = if same {
                    xi
                } else {
                    [xi[0] - shift, xi[1], xi[2]]
                };
                for &cx in cells.adjacent[0][c[0]].as_slice() {
                    let t = self.layer_slab[cx as usize];
                    if (t == s) != same || (!same && next[s] != Some(t)) {
                        continue;
                    }
                    for &cy in cells.adjacent[1][c[1]].as_slice() {
                        // The z-adjacent cells in runs: each run is one range of atoms.
                        for &(z0, z1) in cells.adjacent[2][c[2]].runs() {
                            let row = (cx as usize * cells.n[1] + cy as usize) * cells.n[2];
                            let (mut a, b) = (
                                cells.first[row + z0 as usize],
                                cells.first[row + z1 as usize + 1],
                            );
                            // Inside the slab the lower sorted index owns the pair; its
                            // partners are counted from the particle after it.
                            let base = if same {
                                a = a.max(i + 1);
                                i + 1
                            } else {
                                lo_next
                            };
                            if a >= b {
                                continue;
                            }
                            if b - 1 - base > I::MAX {
                                fits = false;
                                break 'particles;
                            }
                            let first = (a - base) as u32;
                            let candidates = &xs[a..b];
                            if wraps {
                                scan::<I, true>(
                                    xi, candidates, first, self.r2, self.box_, &mut out,
                                );
                            } else {
                                scan::<I, false>(
                                    xi, candidates, first, self.r2, self.box_, &mut out,
                                );
                            }
                        }
                    }
                }
                if same {
                    list.mid.push(out.len() as u32);
                }
            }
            list.start.push(out.len() as u32);
        }
        if !fits {
            out.clear();
        }
        *I::of_mut(list) = out;
        fits
    }
}

/// For each 4-bit mask of candidates in range: the lanes in range, in order (the rest
/// padded), and how many there are.
const COMPACT: [([u32; 4], usize); 16] = {
    let mut table = [([0u32; 4], 0usize); 16];
    let mut m = 0;
    while m < 16 {
        let mut lanes = [0u32; 4];
        let mut n = 0;
        let mut l = 0;
        while l < 4 {
            if m & (1 << l) != 0 {
                lanes[n] = l as u32;
                n += 1;
            }
            l += 1;
        }
        table[m] = (lanes, n);
        m += 1;
    }
    table
};

/// Appends `first + k` for each candidate k closer to `xi` than √r2 (minimum image if
/// `WRAP`), four candidates at a time: their distances lane by lane (vector instructions),
/// then all four indices written at once in the order a table gives for the mask of those
/// in range, and the count advanced by how many were (no branch to mispredict).
#[inline(always)]
fn scan<I: Offset, const WRAP: bool>(
    xi: [Real; 3],
    candidates: &[[Real; 3]],
    first: u32,
    r2: Real,
    (lengths, half): ([Real; 3], [Real; 3]),
    out: &mut Vec<I>,
) {
    let mut k = out.len();
    let needed = k + candidates.len() + 4;
    if needed > out.capacity() {
        // grown by an eighth, not doubled: the list is most of a run's memory
        out.reserve_exact((needed - k).max(out.capacity() / 8));
    }
    out.resize(needed, I::new(0));
    let within = |xj: &[Real; 3]| -> bool {
        let (mut dx, mut dy, mut dz) = (xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]);
        if WRAP {
            dx = near_image(dx, lengths[0], half[0]);
            dy = near_image(dy, lengths[1], half[1]);
            dz = near_image(dz, lengths[2], half[2]);
        }
        dx * dx + dy * dy + dz * dz < r2
    };
    let mut groups = candidates.chunks_exact(4);
    let mut j = first;
    for group in &mut groups {
        let mut mask = 0;
        for (l, xj) in group.iter().enumerate() {
            mask |= usize::from(within(xj)) << l;
        }
        let (lanes, n) = COMPACT[mask];
        let slot = &mut out[k..k + 4];
        for l in 0..4 {
            slot[l] = I::new(j + lanes[l]);
        }
        k += n;
        j += 4;
    }
    for xj in groups.remainder() {
        out[k] = I::new(j);
        k += usize::from(within(xj));
        j += 1;
    }
    out.truncate(k);
}
