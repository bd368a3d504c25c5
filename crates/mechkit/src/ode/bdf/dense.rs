//! The dense output of [`Bdf`]: the polynomial of degree `k` through the new state and the
//! `k` back values before it, in monomial form in `s = (t − t₀)/h`.

use super::Bdf;
use super::diff::newton_basis;
use crate::Real;
use crate::ode::StepPolynomial;

impl Bdf {
    /// The interpolating polynomial of the step from `t0` to `t1` in monomial form.
    pub(super) fn set_dense(&mut self, t0: Real, t1: Real) {
        let n = self.f.len();
        let k = self.order;
        let phi = newton_basis(k);
        self.last_t0 = t0;
        self.last_h = t1 - t0;
        self.width = k + 1;
        self.cont.clear();
        self.cont.resize(n * (k + 1), 0.0);
        for i in 0..n {
            for j in 0..=k {
                let dj = self.d[j * n + i];
                for p in 0..=j {
                    self.cont[i * (k + 1) + p] += dj * phi[j][p];
                }
            }
        }
    }

    /// The state at `t` inside the last accepted step, from its interpolating polynomial.
    pub fn dense_into(&self, t: Real, out: &mut [Real]) {
        let w = self.width;
        let s = if self.last_h == 0.0 {
            1.0
        } else {
            (t - self.last_t0) / self.last_h
        };
        for (i, o) in out.iter_mut().enumerate() {
            let c = &self.cont[i * w..(i + 1) * w];
            *o = c.iter().rev().fold(0.0, |acc, &q| acc * s + q);
        }
    }

    /// The last accepted step's interpolating polynomial, for proofs about the motion inside
    /// it.
    pub fn dense_polynomial_into(&self, out: &mut StepPolynomial) {
        let w = self.width;
        let n = self.cont.len() / w;
        out.reset(self.last_t0, self.last_h, n, w);
        for i in 0..n {
            out.coefficients_mut(i)
                .copy_from_slice(&self.cont[i * w..(i + 1) * w]);
        }
    }
}
