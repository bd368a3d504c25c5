//! The terms and factors `Sym::sum` and `Sym::product` collect: a term's numeric coefficient
//! split off, and a quick hash that tells deep terms apart before they are compared node by
//! node.

use super::Sym;
use crate::number::Number;

/// Splits a term into its numeric coefficient and the rest (`None` for a bare number).
pub(crate) fn split_coefficient(t: &Sym) -> (Number, Option<Sym>) {
    match t {
        Sym::Num(n) => (*n, None),
        Sym::Mul(xs) => match xs.first() {
            Some(Sym::Num(n)) => {
                let rest = if xs.len() == 2 {
                    xs[1].clone()
                } else {
                    Sym::Mul(xs[1..].to_vec())
                };
                (*n, Some(rest))
            }
            _ => (Number::ONE, Some(t.clone())),
        },
        other => (Number::ONE, Some(other.clone())),
    }
}

/// [`split_coefficient`] of a term given away: nothing cloned.
pub(super) fn split_coefficient_owned(t: Sym) -> (Number, Option<Sym>) {
    match t {
        Sym::Num(n) => (n, None),
        Sym::Mul(mut xs) => match xs.first() {
            Some(Sym::Num(n)) => {
                let n = *n;
                xs.remove(0);
                let rest = if xs.len() == 1 {
                    xs.pop().expect("one factor")
                } else {
                    Sym::Mul(xs)
                };
                (n, Some(rest))
            }
            _ => (Number::ONE, Some(Sym::Mul(xs))),
        },
        other => (Number::ONE, Some(other)),
    }
}

/// A hash of `s` (equal expressions hash alike), by a fast multiplicative hasher: it only
/// tells deep expressions apart before they are compared node by node.
pub(crate) fn hash_of(s: &Sym) -> u64 {
    use std::hash::{Hash, Hasher};
    struct Quick(u64);
    impl Hasher for Quick {
        fn write(&mut self, bytes: &[u8]) {
            for chunk in bytes.chunks(8) {
                let mut word = [0u8; 8];
                word[..chunk.len()].copy_from_slice(chunk);
                self.write_u64(u64::from_le_bytes(word));
            }
        }
        fn write_u64(&mut self, n: u64) {
            self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x517c_c1b7_2722_0a95);
        }
        fn finish(&self) -> u64 {
            self.0
        }
    }
    let mut h = Quick(0);
    s.hash(&mut h);
    h.finish()
}

/// Whether `a` and `b` may be equal, by their kinds and then their hashes, each hash computed
/// once (`ka`, `kb` keep them): false only when they differ.
pub(super) fn may_equal(a: &Sym, ka: &mut Option<u64>, b: &Sym, kb: &mut Option<u64>) -> bool {
    if std::mem::discriminant(a) != std::mem::discriminant(b) {
        return false;
    }
    if matches!(a, Sym::Num(_) | Sym::Var(_)) {
        return true;
    }
    *ka.get_or_insert_with(|| hash_of(a)) == *kb.get_or_insert_with(|| hash_of(b))
}
