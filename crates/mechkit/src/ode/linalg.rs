//! Dense LU factorisation with partial pivoting, for the Newton iterations of the implicit
//! methods: real `n × n` systems and the complex one of Radau IIA.
//!
//! The matrices are small (the state of a mechanical system) and refactored often, so the
//! factorisation works in place in buffers kept between steps: no allocation once sized.

use std::ops::{Add, Div, Mul, Neg, Sub};

use nalgebra::Complex;

use crate::Real;

/// The numbers an [`Lu`] works with: `f64` and `Complex<f64>`.
pub(crate) trait Scalar:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The size used to choose a pivot (`|x|`, or `|re| + |im|`).
    fn size(self) -> Real;
    /// `1 / self`.
    fn recip(self) -> Self;
    /// `x` as this kind of number.
    fn from_real(x: Real) -> Self;
}

impl Scalar for Real {
    fn size(self) -> Real {
        self.abs()
    }
    fn recip(self) -> Self {
        1.0 / self
    }
    fn from_real(x: Real) -> Self {
        x
    }
}

impl Scalar for Complex<Real> {
    fn size(self) -> Real {
        self.re.abs() + self.im.abs()
    }
    fn recip(self) -> Self {
        self.inv()
    }
    fn from_real(x: Real) -> Self {
        Complex::new(x, 0.0)
    }
}

/// The matrix is singular to working precision: a zero (or non-finite) pivot in column `col`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Singular {
    pub col: usize,
}

/// An `n × n` matrix factored as `P A = L U` (row-major, `L` unit lower, both in `a`).
#[derive(Debug, Clone, Default)]
pub(crate) struct Lu<T> {
    n: usize,
    a: Vec<T>,
    pivot: Vec<usize>,
    /// `1 / U_kk`: the solves multiply rather than divide.
    inv_diag: Vec<T>,
}

impl<T: Scalar> Lu<T> {
    /// Factors the matrix `fill(r, c)` of size `n`.
    pub fn factor(&mut self, n: usize, fill: impl Fn(usize, usize) -> T) -> Result<(), Singular> {
        self.n = n;
        self.a.clear();
        for r in 0..n {
            self.a.extend((0..n).map(|c| fill(r, c)));
        }
        self.pivot.clear();
        self.pivot.resize(n, 0);
        self.inv_diag.clear();
        let a = &mut self.a;
        for k in 0..n {
            let (mut p, mut best) = (k, a[k * n + k].size());
            for r in k + 1..n {
                let s = a[r * n + k].size();
                if s > best {
                    (p, best) = (r, s);
                }
            }
            if !(best > 0.0 && best.is_finite()) {
                return Err(Singular { col: k });
            }
            self.pivot[k] = p;
            if p != k {
                for c in 0..n {
                    a.swap(k * n + c, p * n + c);
                }
            }
            let inv = a[k * n + k].recip();
            self.inv_diag.push(inv);
            // rows below k, each less m times row k right of the diagonal
            let (above, below) = a.split_at_mut((k + 1) * n);
            let pivot_row = &above[k * n + k + 1..];
            for row in below.chunks_exact_mut(n) {
                let m = row[k] * inv;
                row[k] = m;
                if m.size() != 0.0 {
                    for (x, &v) in row[k + 1..].iter_mut().zip(pivot_row) {
                        *x = *x - m * v;
                    }
                }
            }
        }
        Ok(())
    }

    /// Solves `A x = b` in place.
    pub fn solve(&self, b: &mut [T]) {
        let (n, a) = (self.n, &self.a);
        for k in 0..n {
            b.swap(k, self.pivot[k]);
        }
        for r in 1..n {
            let row = &a[r * n..r * n + r];
            let mut s = b[r];
            for (&x, &y) in row.iter().zip(&b[..r]) {
                s = s - x * y;
            }
            b[r] = s;
        }
        for r in (0..n).rev() {
            let row = &a[r * n + r..(r + 1) * n];
            let mut s = b[r];
            for (&x, &y) in row[1..].iter().zip(&b[r + 1..n]) {
                s = s - x * y;
            }
            b[r] = s * self.inv_diag[r];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_real_system_that_needs_pivoting() {
        // [[0, 2, 1], [1, 1, 1], [4, 0, -1]] x = b with x = (1, -2, 3)
        let m = [[0.0, 2.0, 1.0], [1.0, 1.0, 1.0], [4.0, 0.0, -1.0]];
        let mut lu = Lu::default();
        lu.factor(3, |r, c| m[r][c]).unwrap();
        let x = [1.0, -2.0, 3.0];
        let mut b: Vec<Real> = (0..3)
            .map(|r| (0..3).map(|c| m[r][c] * x[c]).sum())
            .collect();
        lu.solve(&mut b);
        for (got, want) in b.iter().zip(x) {
            assert!((got - want).abs() < 1e-14, "{b:?}");
        }
        assert_eq!(
            lu.factor(2, |r, _| if r == 0 { 1.0 } else { 2.0 }),
            Err(Singular { col: 1 })
        );
    }

    #[test]
    fn solves_a_complex_system() {
        let i = Complex::new(0.0, 1.0);
        let one = Complex::new(1.0, 0.0);
        let m = [[one + i, 2.0 * one], [-i, 3.0 * one - i]];
        let x = [Complex::new(0.5, -1.0), Complex::new(2.0, 0.25)];
        let mut b: Vec<Complex<Real>> = (0..2).map(|r| m[r][0] * x[0] + m[r][1] * x[1]).collect();
        let mut lu = Lu::default();
        lu.factor(2, |r, c| m[r][c]).unwrap();
        lu.solve(&mut b);
        for (got, want) in b.iter().zip(x) {
            assert!((got - want).norm() < 1e-14, "{b:?}");
        }
    }
}
