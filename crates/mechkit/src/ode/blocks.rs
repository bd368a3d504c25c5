//! Blocks of [`LANES`] components, the storage of [`super::stages::Stages`], and the loops
//! over them: a combination `Σ c_l k_l` of stage vectors by block (the coefficients in the
//! inner loop, the accumulator in registers) or by coefficient (plain passes over the
//! components, for long states with the rows given as data), and copies of one block without
//! calls to `memcpy`.

use crate::Real;

/// Components per block.
pub(super) const LANES: usize = 4;

/// One block of components.
pub(super) type Block = [Real; LANES];

/// `Σ_{(l, c) in row} c k_l` over block `b` (zero for an empty row).
// Inlined into every combination (callgrind on bench/ode_compare: 5 % fewer instructions
// per step than with `#[inline]`).
#[allow(clippy::inline_always)]
#[inline(always)]
pub(super) fn block_sum(k: &[Block], nb: usize, row: &[(usize, Real)], b: usize) -> Block {
    let mut acc = [0.0; LANES];
    if let Some((&(l0, c0), rest)) = row.split_first() {
        let kb = &k[l0 * nb + b];
        for j in 0..LANES {
            acc[j] = c0 * kb[j];
        }
        for &(l, c) in rest {
            let kb = &k[l * nb + b];
            for j in 0..LANES {
                acc[j] += c * kb[j];
            }
        }
    }
    acc
}

/// `acc = Σ_{(l, c) in row} c k_l` over the first `acc.len()` components, one coefficient
/// at a time: for states of several blocks with the rows given as data, each pass is a plain
/// loop over the components that the compiler vectorises (the same sums in the same order as
/// [`block_sum`]).
pub(super) fn sum_by_rows(k: &[Block], nb: usize, row: &[(usize, Real)], acc: &mut [Real]) {
    let (k, np) = (k.as_flattened(), nb * LANES);
    let Some((&(l0, c0), rest)) = row.split_first() else {
        acc.fill(0.0);
        return;
    };
    // indexed loops over slices of one length: the form the vectoriser handles best
    let m = acc.len();
    let kl = &k[l0 * np..l0 * np + m];
    for i in 0..m {
        acc[i] = c0 * kl[i];
    }
    for &(l, c) in rest {
        let kl = &k[l * np..l * np + m];
        for i in 0..m {
            acc[i] += c * kl[i];
        }
    }
}

/// Writes `y` (at most [`LANES`] components) into the block `b`.
#[allow(clippy::inline_always)] // as `block_sum`
#[inline(always)]
pub(super) fn store_block(y: &[Real], b: &mut Block) {
    // element by element: a copy of unknown length would be a call to `memcpy`
    if let Ok(y) = <&Block>::try_from(y) {
        *b = *y;
    } else {
        for (b, y) in b.iter_mut().zip(y) {
            *b = *y;
        }
    }
}

/// `dst = src` (same lengths), without a call to `memcpy` for one block.
#[inline]
pub(crate) fn copy_small(dst: &mut [Real], src: &[Real]) {
    match (<&mut Block>::try_from(&mut *dst), <&Block>::try_from(src)) {
        (Ok(d), Ok(s)) => *d = *s,
        _ => dst.copy_from_slice(src),
    }
}

/// The number of blocks: `NB` when it is fixed at compile time (not 0), else `nb`.
#[allow(clippy::inline_always)] // as `block_sum`
#[inline(always)]
pub(super) fn blocks<const NB: usize>(nb: usize) -> usize {
    if NB == 0 { nb } else { NB }
}

/// Writes the first `out.len()` (at most [`LANES`]) components of `b` into `out`.
#[allow(clippy::inline_always)] // as `block_sum`
#[inline(always)]
pub(super) fn store(b: Block, out: &mut [Real]) {
    // element by element: a copy of unknown length would be a call to `memcpy`
    if let Ok(o) = <&mut Block>::try_from(&mut *out) {
        *o = b;
    } else {
        for (o, b) in out.iter_mut().zip(b) {
            *o = b;
        }
    }
}
