//! The error scale of [`Radau5`]: the weights `atol + rtol |y|`, the RMS norm over the
//! controlled components, and the first step.

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use super::Radau5;
use crate::Real;
use crate::ode::OdeSystem;
use crate::ode::weights::{controlled, first_step, set_weights, trial_step, weighted_rms};

impl Radau5 {
    pub(super) fn norm(&self, v: &[Real]) -> Real {
        weighted_rms(&self.scale, self.controlled(v.len()), |i| v[i])
    }

    pub(super) fn controlled(&self, n: usize) -> usize {
        controlled(&self.config, n)
    }

    pub(super) fn set_scale(&mut self, y0: &[Real], y1: Option<&[Real]>) {
        set_weights(&self.config, y0, y1, &mut self.scale);
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
        let h0 = trial_step(&self.config, d0, d1, span);
        for i in 0..n {
            self.y_stage[i] = y[i] + h0 * f0[i];
        }
        let ys = std::mem::take(&mut self.y_stage);
        self.eval(sys, t + h0, &ys, 0);
        self.y_stage = ys;
        let diff: Vec<Real> = (0..n).map(|i| self.f[0][i] - f0[i]).collect();
        let d2 = self.norm(&diff) / h0;
        first_step(&self.config, h0, d1, d2, span, 3)
    }
}
