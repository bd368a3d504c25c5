//! The error scale of [`Radau5`]: the weights `atol + rtol |y|`, the RMS norm over the
//! controlled components, and the first step.

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use super::Radau5;
use crate::Real;
use crate::ode::OdeSystem;

impl Radau5 {
    pub(super) fn norm(&self, v: &[Real]) -> Real {
        let n = self.controlled(v.len());
        if n == 0 {
            return 0.0;
        }
        let sum: Real = (0..n)
            .map(|i| {
                let r = v[i] / self.scale[i];
                if self.scale[i] > 0.0 {
                    r * r
                } else if v[i] == 0.0 {
                    0.0
                } else {
                    Real::INFINITY
                }
            })
            .sum();
        (sum / n as Real).sqrt()
    }

    pub(super) fn controlled(&self, n: usize) -> usize {
        self.config.error_components.unwrap_or(n).min(n)
    }

    pub(super) fn set_scale(&mut self, y0: &[Real], y1: Option<&[Real]>) {
        for i in 0..y0.len() {
            let size = match y1 {
                Some(y1) => y0[i].abs().max(y1[i].abs()),
                None => y0[i].abs(),
            };
            self.scale[i] = self.config.atol.at(i) + self.config.rtol.at(i) * size;
        }
    }

    /// A first step from the sizes of `y` and `f` (Hairer, *Solving ODEs I*, Sec. II.4, for
    /// an error of order 3).
    pub(super) fn initial_step<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: Real,
        y: &[Real],
        span: Real,
    ) -> Real {
        let n = y.len();
        self.set_scale(y, None);
        let d0 = self.norm(y);
        let f0 = self.f0.clone();
        let d1 = self.norm(&f0);
        let mut h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6
        } else {
            0.01 * d0 / d1
        };
        h0 = h0.min(self.config.h_max).min(span);
        for i in 0..n {
            self.y_stage[i] = y[i] + h0 * f0[i];
        }
        let ys = std::mem::take(&mut self.y_stage);
        self.eval(sys, t + h0, &ys, 0);
        self.y_stage = ys;
        let diff: Vec<Real> = (0..n).map(|i| self.f[0][i] - f0[i]).collect();
        let d2 = self.norm(&diff) / h0;
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6)
        } else {
            (0.01 / d1.max(d2)).powf(1.0 / 4.0)
        };
        let h = (100.0 * h0).min(h1).min(self.config.h_max).min(span);
        if h > 0.0 && h.is_finite() {
            h
        } else {
            Real::min(1e-6, self.config.h_max).min(span)
        }
    }
}
