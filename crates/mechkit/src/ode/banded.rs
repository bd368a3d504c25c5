//! Banded LU factorisation with partial pivoting, for Newton matrices whose unknowns couple
//! only to near neighbours (chains of springs, once `q` and `v` are interleaved).
//!
//! The matrix has `kl` sub- and `ku` super-diagonals. As in LAPACK's `dgbtrf` (Golub & Van
//! Loan, *Matrix Computations*, Sec. 4.3.5), the pivot of column `k` is chosen among the `kl`
//! rows below the diagonal and a row swap can push entries of `U` up to `kl + ku` places
//! right of the diagonal, so each row keeps room for `kl` extra super-diagonals:
//! `w = 2 kl + ku + 1` entries per row, row `r` holding the columns `r − kl ..= r + kl + ku`
//! (row-major, the transpose of LAPACK's column storage, so that eliminations run along
//! contiguous memory). The multipliers of `L` stay in the sub-diagonal places of the column
//! they eliminate and the row swaps are applied to `b` one column at a time when solving
//! (`dgbtrs`'s order). Cost: about `n kl (kl + ku)` multiply-adds to factor, against `n³/3`
//! dense, and `n (2 kl + ku)` to solve. Buffers are kept between factorisations: no
//! allocation once sized.

#![allow(clippy::needless_range_loop)] // row and column loops over the band

use super::linalg::{Scalar, Singular};

/// An `n × n` band matrix with `kl` sub- and `ku` super-diagonals, factored as `L U` with row
/// interchanges.
#[derive(Debug, Clone, Default)]
pub(crate) struct BandedLu<T> {
    n: usize,
    kl: usize,
    ku: usize,
    a: Vec<T>,
    pivot: Vec<usize>,
    /// `1 / U_kk`: the solves multiply rather than divide.
    inv_diag: Vec<T>,
}

impl<T: Scalar + Default> BandedLu<T> {
    /// Width of a stored row.
    fn width(&self) -> usize {
        2 * self.kl + self.ku + 1
    }

    /// Index of the entry `(r, c)` (`r − kl ≤ c ≤ r + kl + ku`).
    #[inline]
    fn at(&self, r: usize, c: usize) -> usize {
        r * (self.width() - 1) + c + self.kl
    }

    /// Factors the matrix of size `n` whose entries inside the band are `fill(r, c)`
    /// (`r − kl ≤ c ≤ r + ku`; those outside are zero and never asked for).
    pub fn factor(
        &mut self,
        n: usize,
        kl: usize,
        ku: usize,
        fill: impl Fn(usize, usize) -> T,
    ) -> Result<(), Singular> {
        (self.n, self.kl, self.ku) = (n, kl, ku);
        let w = self.width();
        self.a.clear();
        self.a.resize(n * w, T::default());
        for r in 0..n {
            for c in r.saturating_sub(kl)..(r + ku + 1).min(n) {
                let i = self.at(r, c);
                self.a[i] = fill(r, c);
            }
        }
        self.pivot.clear();
        self.pivot.resize(n, 0);
        self.inv_diag.clear();
        for k in 0..n {
            let last = (k + kl).min(n - 1);
            let (mut p, mut best) = (k, self.a[self.at(k, k)].size());
            for r in k + 1..=last {
                let s = self.a[self.at(r, k)].size();
                if s > best {
                    (p, best) = (r, s);
                }
            }
            if !(best > 0.0 && best.is_finite()) {
                return Err(Singular { col: k });
            }
            self.pivot[k] = p;
            let right = (k + kl + ku).min(n - 1);
            if p != k {
                for c in k..=right {
                    let (i, j) = (self.at(k, c), self.at(p, c));
                    self.a.swap(i, j);
                }
            }
            let inv = self.a[self.at(k, k)].recip();
            self.inv_diag.push(inv);
            let len = right - k;
            for r in k + 1..=last {
                let i = self.at(r, k);
                let m = self.a[i] * inv;
                self.a[i] = m;
                if m.size() != 0.0 {
                    // row k's entries right of the diagonal lie before row r's (r > k)
                    let (row_k, row_r) = (self.at(k, k + 1), self.at(r, k + 1));
                    let (above, below) = self.a.split_at_mut(row_r);
                    let source = &above[row_k..row_k + len];
                    for (x, &v) in below[..len].iter_mut().zip(source) {
                        *x = *x - m * v;
                    }
                }
            }
        }
        Ok(())
    }

    /// Solves `A x = b` in place.
    pub fn solve(&self, b: &mut [T]) {
        let (n, kl, ku) = (self.n, self.kl, self.ku);
        if n == 0 {
            return;
        }
        // row r's band, columns r − kl ..= r + kl + ku, is `a[r w .. (r + 1) w]`
        let (w, a, b) = (self.width(), &self.a[..], &mut b[..n]);
        for k in 0..n {
            b.swap(k, self.pivot[k]);
            let bk = b[k];
            let last = (k + kl).min(n - 1);
            // entry (r, k) lies at r w + k − r + kl
            for (j, r) in (k + 1..=last).enumerate() {
                b[r] = b[r] - a[r * w + kl - 1 - j] * bk;
            }
        }
        for r in (0..n).rev() {
            let row = &a[r * w + kl..(r + 1) * w];
            let m = (kl + ku).min(n - 1 - r);
            let mut s = b[r];
            for (&x, &y) in row[1..=m].iter().zip(&b[r + 1..=r + m]) {
                s = s - x * y;
            }
            b[r] = s * self.inv_diag[r];
        }
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::Complex;

    use super::super::linalg::Lu;
    use super::*;
    use crate::Real;

    /// A deterministic generator in [-1, 1) (SplitMix64).
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> Real {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            (z >> 11) as Real / (1u64 << 52) as Real - 1.0
        }
    }

    /// A random band matrix (dense, row-major), with diagonals smaller than the other entries
    /// so that pivoting is needed (large ones when there is no sub-diagonal to pivot on).
    fn band_matrix(rng: &mut Rng, n: usize, kl: usize, ku: usize) -> Vec<Real> {
        let mut m = vec![0.0; n * n];
        let diagonal = if kl == 0 { 3.0 } else { 0.25 };
        for r in 0..n {
            for c in r.saturating_sub(kl)..(r + ku + 1).min(n) {
                m[r * n + c] = if r == c {
                    (diagonal + 0.05 * rng.next()).copysign(rng.next())
                } else {
                    rng.next()
                };
            }
        }
        m
    }

    #[test]
    fn real_band_systems_match_the_dense_lu() {
        let mut rng = Rng(7);
        let mut banded = BandedLu::default();
        let mut dense = Lu::default();
        for (n, kl, ku) in [
            (1, 0, 0),
            (5, 1, 1),
            (12, 3, 2),
            (30, 2, 5),
            (9, 0, 3),
            (9, 4, 0),
        ] {
            for _ in 0..5 {
                let m = band_matrix(&mut rng, n, kl, ku);
                let x: Vec<Real> = (0..n).map(|_| rng.next()).collect();
                let b: Vec<Real> = (0..n)
                    .map(|r| (0..n).map(|c| m[r * n + c] * x[c]).sum())
                    .collect();
                banded.factor(n, kl, ku, |r, c| m[r * n + c]).unwrap();
                dense.factor(n, |r, c| m[r * n + c]).unwrap();
                let (mut xb, mut xd) = (b.clone(), b.clone());
                banded.solve(&mut xb);
                dense.solve(&mut xd);
                for i in 0..n {
                    assert!(
                        (xb[i] - x[i]).abs() < 1e-8,
                        "n {n} kl {kl} ku {ku}: {xb:?} {x:?}"
                    );
                    assert!((xb[i] - xd[i]).abs() < 1e-8 * (1.0 + xd[i].abs()));
                }
            }
        }
    }

    #[test]
    fn complex_band_systems_match_the_dense_lu() {
        let mut rng = Rng(11);
        let (n, kl, ku) = (16, 3, 2);
        let re = band_matrix(&mut rng, n, kl, ku);
        let im = band_matrix(&mut rng, n, kl, ku);
        let m = |r: usize, c: usize| Complex::new(re[r * n + c], im[r * n + c]);
        let x: Vec<Complex<Real>> = (0..n)
            .map(|_| Complex::new(rng.next(), rng.next()))
            .collect();
        let b: Vec<Complex<Real>> = (0..n)
            .map(|r| (0..n).map(|c| m(r, c) * x[c]).sum())
            .collect();
        let mut banded = BandedLu::default();
        banded.factor(n, kl, ku, m).unwrap();
        let mut dense = Lu::default();
        dense.factor(n, m).unwrap();
        let (mut xb, mut xd) = (b.clone(), b);
        banded.solve(&mut xb);
        dense.solve(&mut xd);
        for i in 0..n {
            assert!((xb[i] - x[i]).norm() < 1e-9, "{xb:?}");
            assert!((xb[i] - xd[i]).norm() < 1e-9);
        }
    }

    #[test]
    fn singular_band_matrices_are_refused_like_dense_ones() {
        // a tridiagonal matrix whose third row is the sum of the second and the fourth
        // within the band is awkward to build; a zero column is simplest and exact
        let n = 6;
        let f = |r: usize, c: usize| {
            if c == 3 {
                0.0
            } else if r == c {
                2.0
            } else {
                -1.0
            }
        };
        let mut banded = BandedLu::default();
        let mut dense = Lu::default();
        assert_eq!(banded.factor(n, 1, 1, f), Err(Singular { col: 3 }));
        assert_eq!(
            dense.factor(n, |r, c| if r.abs_diff(c) <= 1 { f(r, c) } else { 0.0 }),
            Err(Singular { col: 3 })
        );
        // rank one inside the band: rows 0 and 1 equal in a 2 × 2 block
        assert_eq!(banded.factor(2, 1, 1, |_, _| 1.5), Err(Singular { col: 1 }));
        assert_eq!(
            banded.factor(3, 1, 0, |r, c| if r == c { Real::NAN } else { 1.0 }),
            Err(Singular { col: 0 })
        );
    }
}
