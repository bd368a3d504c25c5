//! Putting the particles in the neighbour list's order at a build: arrays permuted by the
//! sort (`a[k] ← a[order[k]]`), through a buffer or in place.

use rayon::prelude::*;

use crate::Real;

use super::forces::CHUNK;

/// `a` reordered by `order` (`a[k] ← a[order[k]]`) through `buffer`, which is left holding
/// the old order.
pub(super) fn gather(
    a: &mut Vec<[Real; 3]>,
    buffer: &mut Vec<[Real; 3]>,
    order: &[u32],
    pool: Option<&rayon::ThreadPool>,
) {
    buffer.resize(a.len(), [0.0; 3]);
    let from: &[[Real; 3]] = a;
    let fill = |(c, out): (usize, &mut [[Real; 3]])| {
        for (k, o) in out.iter_mut().enumerate() {
            *o = from[order[c * CHUNK + k] as usize];
        }
    };
    match pool {
        Some(pool) => pool.install(|| buffer.par_chunks_mut(CHUNK).enumerate().for_each(fill)),
        None => buffer.chunks_mut(CHUNK).enumerate().for_each(fill),
    }
    std::mem::swap(a, buffer);
}

/// `a` reordered by `order` (`a[k] ← a[order[k]]`) in place, cycle by cycle (`done`: a
/// buffer of bits for the particles already placed).
pub(super) fn permute<T: Copy>(a: &mut [T], order: &[u32], done: &mut Vec<u64>) {
    done.clear();
    done.resize(a.len().div_ceil(64), 0);
    for k in 0..a.len() {
        if done[k / 64] >> (k % 64) & 1 == 1 {
            continue;
        }
        let first = a[k];
        let mut j = k;
        loop {
            done[j / 64] |= 1 << (j % 64);
            let from = order[j] as usize;
            if from == k {
                a[j] = first;
                break;
            }
            a[j] = a[from];
            j = from;
        }
    }
}
