//! The sums behind the sample rules, written so that LLVM vectorises them without `unsafe`.
//!
//! A sum `Σ_i term(a_i, b_i, …)` over equal-length columns runs in blocks of [`BLOCK`] terms;
//! inside a block, [`LANES`] independent accumulators (one per lane, which LLVM keeps in SIMD
//! registers) hide the latency of the additions, and the block sums are combined pairwise, as
//! in NumPy's `pairwise_sum` (blocks of 128, 8 accumulators). The rounding error is then
//! bounded by about `(BLOCK/LANES + log₂(n/BLOCK)) ε Σ|term|` instead of `n ε Σ|term|` for a
//! plain running sum (Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed.,
//! 2002, §4.2).
//!
//! A running (prefix) sum is inherently sequential; [`prefix_into`] shortens the dependency
//! chain to one addition per [`LANES`] terms by forming each chunk's local prefix sums first.

use std::ops::Range;

use crate::Real;

/// Independent accumulators per block.
pub(super) const LANES: usize = 8;
/// Terms per block: a block's columns stay in L1 while it is summed.
const BLOCK: usize = 1024;

/// Halves longer than this are summed on two threads (`rayon::join`); the tree of additions
/// is the same, so the result is the same bits on any number of threads. Long sums are bound
/// by memory bandwidth, which one core cannot use up.
const PARALLEL_MIN: usize = 1 << 17;

/// `Σ_{i < len} block(range)` over blocks of [`BLOCK`] indices, combined pairwise.
pub(super) fn pairwise(len: usize, block: &(impl Fn(Range<usize>) -> Real + Sync)) -> Real {
    fn split(r: Range<usize>, block: &(impl Fn(Range<usize>) -> Real + Sync)) -> Real {
        let len = r.end - r.start;
        if len <= BLOCK {
            return block(r);
        }
        let mid = r.start + len.div_ceil(BLOCK) / 2 * BLOCK;
        if len >= PARALLEL_MIN {
            let (a, b) = rayon::join(|| split(r.start..mid, block), || split(mid..r.end, block));
            a + b
        } else {
            split(r.start..mid, block) + split(mid..r.end, block)
        }
    }
    split(0..len, block)
}

/// `Σ_i term([c[i] for c in cols])` with [`LANES`] accumulators (one block of a sum). All
/// columns must have the same length.
#[inline]
pub(super) fn lanes<const K: usize>(cols: [&[Real]; K], term: impl Fn([Real; K]) -> Real) -> Real {
    let m = cols[0].len();
    for c in &cols {
        assert_eq!(c.len(), m, "columns of unequal length");
    }
    let full = m / LANES * LANES;
    let mut acc = [0.0; LANES];
    for i in (0..full).step_by(LANES) {
        // one bounds check per column and chunk; the lanes then index fixed-size arrays
        let chunk = cols.map(|c| lane_chunk(c, i));
        for (k, a) in acc.iter_mut().enumerate() {
            *a += term(chunk.map(|c| c[k]));
        }
    }
    let tail: Real = (full..m).map(|i| term(cols.map(|c| c[i]))).sum();
    // tree reduction of the lanes
    let mut width = LANES;
    while width > 1 {
        width /= 2;
        for k in 0..width {
            acc[k] += acc[k + width];
        }
    }
    acc[0] + tail
}

/// `c[i..i + LANES]` as an array.
#[inline]
fn lane_chunk(c: &[Real], i: usize) -> &[Real; LANES] {
    c[i..i + LANES].try_into().expect("a full chunk")
}

/// Blocked pairwise sum of `term` over columns of equal length.
pub(super) fn sum_columns<const K: usize>(
    cols: [&[Real]; K],
    term: impl Fn([Real; K]) -> Real + Copy + Sync,
) -> Real {
    pairwise(cols[0].len(), &|r: Range<usize>| {
        lanes(cols.map(|c| &c[r.clone()]), term)
    })
}

/// `out[0] = 0`, `out[i+1] = out[i] + term(column values at i)`: a running sum, so `out` has
/// one more element than the columns.
pub(super) fn prefix_into<const K: usize>(
    cols: [&[Real]; K],
    term: impl Fn([Real; K]) -> Real,
    out: &mut [Real],
) {
    let m = cols[0].len();
    for c in &cols {
        assert_eq!(c.len(), m, "columns of unequal length");
    }
    assert_eq!(
        out.len(),
        m + 1,
        "the output needs one more element than the columns"
    );
    out[0] = 0.0;
    let full = m / LANES * LANES;
    let (body, rest) = out[1..].split_at_mut(full);
    let mut carry = 0.0;
    for (chunk_index, chunk) in body.chunks_exact_mut(LANES).enumerate() {
        let i = chunk_index * LANES;
        let values = cols.map(|c| lane_chunk(c, i));
        let mut local: [Real; LANES] = std::array::from_fn(|k| term(values.map(|c| c[k])));
        // the chunk's own prefix sums in log₂(LANES) steps of independent additions
        let mut shift = 1;
        while shift < LANES {
            for k in (shift..LANES).rev() {
                local[k] += local[k - shift];
            }
            shift *= 2;
        }
        for (o, l) in chunk.iter_mut().zip(local) {
            *o = carry + l;
        }
        carry += local[LANES - 1];
    }
    for (k, o) in rest.iter_mut().enumerate() {
        carry += term(cols.map(|c| c[full + k]));
        *o = carry;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_every_term_once() {
        for n in [0_usize, 1, 7, 8, 9, 1023, 1024, 1025, 5000] {
            let v: Vec<Real> = (0..n).map(|i| i as Real).collect();
            let exact = (n * n.saturating_sub(1) / 2) as Real;
            assert_eq!(sum_columns([&v], |[a]| a), exact, "n = {n}");
            let mut out = vec![0.0; n + 1];
            prefix_into([&v], |[a]| a, &mut out);
            for (k, o) in out.iter().enumerate() {
                assert_eq!(
                    *o,
                    (k * k.saturating_sub(1) / 2) as Real,
                    "n = {n}, k = {k}"
                );
            }
        }
    }

    #[test]
    fn pairwise_is_more_accurate_than_a_running_sum() {
        // 10^6 copies of 0.1: a running sum drifts by 1.3e-6, the blocked pairwise sum by 2e-10
        let v = vec![0.1; 1_000_000];
        let exact = 1e5;
        let pairwise = sum_columns([&v], |[a]| a);
        let running: Real = v.iter().sum();
        assert!((pairwise - exact).abs() < 1e-9, "{pairwise}");
        assert!((running - exact).abs() > 1e-7, "{running}");
    }
}
