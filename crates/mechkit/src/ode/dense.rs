//! Dense output of the adaptive Runge-Kutta methods: the solution anywhere inside the last
//! accepted step, without affecting the steps.
//!
//! | method | interpolant | order |
//! |---|---|---|
//! | Dormand-Prince 5(4) | Shampine's quartic from the stages | 4 |
//! | Bogacki-Shampine 3(2) | cubic from the stages | 3 |
//! | DOP853 | Hairer's, from three extra stages (computed once per step, when first asked) | 7 |
//! | Heun | cubic Hermite from the values and derivatives at both ends | 3 |

#![allow(clippy::needless_range_loop)] // component loops over several parallel arrays

use super::adaptive::AdaptiveRk;
use super::polynomial::{MAX_COEFFICIENTS, StepPolynomial};
use super::stages::sparse;
use super::system::OdeSystem;
use super::tableau::DenseKind;
use crate::Real;

impl AdaptiveRk {
    /// The state at time `t` inside the last accepted step, by the method's dense output.
    pub fn dense_into<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: Real, out: &mut [Real]) {
        let h = self.last_h;
        let theta = if h == 0.0 {
            1.0
        } else {
            (t - self.last_t0) / h
        };
        let n = out.len();
        let s = self.tableau.stages();
        match &self.tableau.dense {
            DenseKind::Polynomial(p) => {
                // y0 + h Σ_l k_l Σ_j p_lj θ^(j+1)
                let mut w = [0.0; 16];
                for (wl, row) in w.iter_mut().zip(p) {
                    let mut x = theta;
                    for c in row {
                        *wl += c * x;
                        x *= theta;
                    }
                }
                for i in 0..n {
                    let mut acc = 0.0;
                    for (l, wl) in w.iter().enumerate().take(p.len()) {
                        acc += wl * self.stages.at(l, i);
                    }
                    out[i] = self.last_y0[i] + h * acc;
                }
            }
            DenseKind::Hermite => {
                for i in 0..n {
                    out[i] = super::hermite::hermite(
                        self.last_y0[i],
                        self.stages.at(0, i),
                        self.last_y1[i],
                        self.stages.at(s, i),
                        h,
                        theta,
                    );
                }
            }
            DenseKind::Dop853 => {
                if !self.dense_ready {
                    self.prepare_dop853(sys);
                }
                // y0 + θ(F0 + (1-θ)(F1 + θ(F2 + (1-θ)(F3 + θ(F4 + (1-θ)(F5 + θ F6))))))
                for i in 0..n {
                    let mut acc = 0.0;
                    for m in (0..7).rev() {
                        acc += self.dense[m * n + i];
                        acc *= if m % 2 == 0 { theta } else { 1.0 - theta };
                    }
                    out[i] = self.last_y0[i] + acc;
                }
            }
        }
    }

    /// The dense output of the last accepted step as a polynomial per component in the
    /// fraction of the step (for enclosures: [`StepPolynomial::enclose`]).
    pub fn dense_polynomial_into<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        out: &mut StepPolynomial,
    ) {
        let h = self.last_h;
        let n = self.last_y0.len();
        let s = self.tableau.stages();
        match &self.tableau.dense {
            DenseKind::Polynomial(p) => {
                // y0 + h Σ_l k_l Σ_j p_lj θ^(j+1)
                let width = 1 + p.iter().map(Vec::len).max().unwrap_or(0);
                out.reset(self.last_t0, h, n, width);
                // h p_lj, once per step (the same products as `h * p_lj * k`)
                let mut hp = [[0.0; MAX_COEFFICIENTS]; 16];
                for (row, pr) in hp.iter_mut().zip(p) {
                    for (x, pj) in row.iter_mut().zip(pr) {
                        *x = h * pj;
                    }
                }
                for i in 0..n {
                    let c = out.coefficients_mut(i);
                    c[0] = self.last_y0[i];
                    for (l, (row, pr)) in hp.iter().zip(p).enumerate() {
                        let k = self.stages.at(l, i);
                        for (cj, hpj) in c[1..].iter_mut().zip(&row[..pr.len()]) {
                            *cj += hpj * k;
                        }
                    }
                }
            }
            DenseKind::Hermite => {
                out.reset(self.last_t0, h, n, 4);
                for i in 0..n {
                    out.set_hermite(
                        i,
                        (self.last_y0[i], self.stages.at(0, i)),
                        (self.last_y1[i], self.stages.at(s, i)),
                    );
                }
            }
            DenseKind::Dop853 => {
                if !self.dense_ready {
                    self.prepare_dop853(sys);
                }
                out.reset(self.last_t0, h, n, 8);
                // y0 + θ(F0 + (1-θ)(F1 + θ(F2 + (1-θ)(F3 + θ(F4 + (1-θ)(F5 + θ F6)))))),
                // expanded from the inside out
                for i in 0..n {
                    let mut acc = [0.0; 8];
                    for m in (0..7).rev() {
                        acc[0] += self.dense[m * n + i];
                        // times θ: shift up; times (1 - θ): subtract the shifted copy
                        let mut shifted = [0.0; 8];
                        shifted[1..].copy_from_slice(&acc[..7]);
                        if m % 2 == 0 {
                            acc = shifted;
                        } else {
                            for (a, sh) in acc.iter_mut().zip(shifted) {
                                *a -= sh;
                            }
                        }
                    }
                    acc[0] += self.last_y0[i];
                    out.coefficients_mut(i).copy_from_slice(&acc);
                }
            }
        }
    }

    /// DOP853's three extra stages and interpolation coefficients for the last step.
    fn prepare_dop853<S: OdeSystem + ?Sized>(&mut self, sys: &S) {
        let d = &super::dop853::DOP853;
        let n = self.last_y0.len();
        let h = self.last_h;
        let t0 = self.last_t0;
        let y0 = std::mem::take(&mut self.last_y0);
        for s in 13..16 {
            let row = sparse(&d.a[s][..s]);
            self.stages
                .stage_from(sys, &row, t0 + d.c[s] * h, &y0, h, s);
            self.stats.evaluations += 1;
        }
        self.last_y0 = y0;
        let k = &self.stages;
        self.dense.resize(7 * n, 0.0);
        let rows: Vec<_> = d.d.iter().map(|r| sparse(r)).collect();
        for i in 0..n {
            let dy = self.last_y1[i] - self.last_y0[i];
            self.dense[i] = dy;
            self.dense[n + i] = h * k.at(0, i) - dy;
            self.dense[2 * n + i] = 2.0 * dy - h * (k.at(12, i) + k.at(0, i));
            for (m, row) in rows.iter().enumerate() {
                self.dense[(3 + m) * n + i] =
                    h * row.iter().map(|&(l, c)| c * k.at(l, i)).sum::<Real>();
            }
        }
        self.dense_ready = true;
    }
}
