//! The exact torque-free motion in the body frame (Euler-Poinsot), by Jacobi's elliptic
//! functions (Landau & Lifshitz, *Mechanics*, §37): the independent reference for the
//! integrated ω(t) and for the period of the tennis-racket flip.
//!
//! With `I₁ < I₂ < I₃` and the combinations (each computed without cancellation from ω)
//! `D₁ = L² − 2EI₁ = Σ I_i (I_i − I₁) ω_i²`, `D₂ = L² − 2EI₂`, `D₃ = 2EI₃ − L²`:
//!
//! - if `D₂ > 0` (ω circulates about the axis of the largest moment):
//!   `ω₁ = s A₁ cn u`, `ω₂ = A₂ sn u`, `ω₃ = s A₃ dn u`, with `λ² = (I₃ − I₂) D₁/(I₁I₂I₃)`,
//!   `m = (I₂ − I₁) D₃ / ((I₃ − I₂) D₁)`, `1 − m = (I₃ − I₁) D₂ / ((I₃ − I₂) D₁)`;
//! - if `D₂ < 0` (about the axis of the smallest moment): `ω₁ = s A₁ dn u`, `ω₂ = A₂ sn u`,
//!   `ω₃ = s A₃ cn u`, with `λ² = (I₂ − I₁) D₃/(I₁I₂I₃)`, `m = (I₃ − I₂) D₁/((I₂ − I₁) D₃)`;
//!
//! where `u = u₀ + λt`, `A₁² = D₃/(I₁(I₃ − I₁))`, `A₃² = D₁/(I₃(I₃ − I₁))`,
//! `A₂² = D₃/(I₂(I₃ − I₂))` (first case) or `D₁/(I₂(I₂ − I₁))` (second), `s` the sign of the
//! `dn` component, and `u₀ = F(φ₀ | m)` from the phase of the initial `(cn, sn)`. ω is periodic
//! with `T = 4K(m)/λ`; `ω₂` changes sign twice per period: near the intermediate axis these
//! are the flips of the tennis racket, and `T → ∞` logarithmically on the separatrix `D₂ = 0`.
//!
//! Moments in any order are sorted first; an odd permutation of the axes reverses the sign of
//! Euler's equations, which is undone by solving for `−ω`.

use crate::Real;
use crate::elliptic::{complete_k_complement, incomplete_f_complement, jacobi_complement};
use crate::mass::Vec3;

/// The exact torque-free ω(t) of a body with distinct extreme moments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Poinsot {
    /// `order[k]`: the axis of the `k`-th smallest moment.
    order: [usize; 3],
    /// `−1` for an odd permutation `order`, else `1`.
    parity: Real,
    /// Signed amplitudes of the (sorted) components.
    amplitude: [Real; 3],
    /// Whether ω circulates about the axis of the largest moment (`D₂ > 0`).
    about_largest: bool,
    lambda: Real,
    m: Real,
    m1: Real,
    u0: Real,
}

impl Poinsot {
    /// The motion of a free body with principal moments `moments` (any order) starting at
    /// `omega` (body frame). `None` when ω(t) is constant or not periodic: a sphere, a rotation
    /// about a principal axis, or a start on the separatrix `L² = 2EI₂`.
    ///
    /// ```
    /// use mechkit::mass::Vec3;
    /// use mechkit::rigid::free3d::Poinsot;
    /// // an axisymmetric body (I₁ = I₂): ω⊥ turns at Ω = (I₃ − I₁) ω₃ / I₁ in the body
    /// let p = Poinsot::new([1.0, 1.0, 2.0], Vec3::new(0.1, 0.0, 3.0)).unwrap();
    /// assert!((p.period() - 2.0 * std::f64::consts::PI / 3.0).abs() < 1e-14);
    /// ```
    pub fn new(moments: [Real; 3], omega: Vec3) -> Option<Self> {
        let mut order = [0usize, 1, 2];
        order.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
        let inversions = usize::from(order[0] > order[1])
            + usize::from(order[0] > order[2])
            + usize::from(order[1] > order[2]);
        let parity = if inversions % 2 == 1 { -1.0 } else { 1.0 };
        let [i1, i2, i3] = order.map(|k| moments[k]);
        let [w1, w2, w3] = order.map(|k| parity * omega[k]);
        let d1 = i2 * (i2 - i1) * w2 * w2 + i3 * (i3 - i1) * w3 * w3;
        let d2 = i1 * (i1 - i2) * w1 * w1 + i3 * (i3 - i2) * w3 * w3;
        let d3 = i1 * (i3 - i1) * w1 * w1 + i2 * (i3 - i2) * w2 * w2;
        if !(d1 > 0.0 && d3 > 0.0 && d2 != 0.0 && i3 > i1) {
            return None;
        }
        let a1 = (d3 / (i1 * (i3 - i1))).sqrt();
        let a3 = (d1 / (i3 * (i3 - i1))).sqrt();
        let about_largest = d2 > 0.0;
        let (lambda, m, m1, a2, s, cn0) = if about_largest {
            let s = w3.signum();
            (
                ((i3 - i2) * d1 / (i1 * i2 * i3)).sqrt(),
                (i2 - i1) * d3 / ((i3 - i2) * d1),
                (i3 - i1) * d2 / ((i3 - i2) * d1),
                (d3 / (i2 * (i3 - i2))).sqrt(),
                s,
                w1 / (s * a1),
            )
        } else {
            let s = w1.signum();
            (
                ((i2 - i1) * d3 / (i1 * i2 * i3)).sqrt(),
                (i3 - i2) * d1 / ((i2 - i1) * d3),
                (i3 - i1) * (-d2) / ((i2 - i1) * d3),
                (d1 / (i2 * (i2 - i1))).sqrt(),
                s,
                w3 / (s * a3),
            )
        };
        if !(lambda > 0.0 && a2 > 0.0 && lambda.is_finite()) {
            return None;
        }
        let phi0 = (w2 / a2).atan2(cn0);
        let u0 = incomplete_f_complement(phi0, m1);
        Some(Self {
            order,
            parity,
            amplitude: [s * a1, a2, s * a3],
            about_largest,
            lambda,
            m,
            m1,
            u0,
        })
    }

    /// The period of ω(t), `4K(m)/λ` (s).
    pub fn period(&self) -> Real {
        4.0 * complete_k_complement(self.m1) / self.lambda
    }

    /// The parameter `m = k²` of the elliptic functions.
    pub fn parameter(&self) -> Real {
        self.m
    }

    /// `1 − m`, computed without cancellation (small near the separatrix).
    pub fn complementary_parameter(&self) -> Real {
        self.m1
    }

    /// The frequency `λ` of the argument `u = u₀ + λt` (1/s).
    pub fn lambda(&self) -> Real {
        self.lambda
    }

    /// Whether ω circulates about the axis of the largest moment (`L² > 2EI₂`), else about
    /// that of the smallest.
    pub fn about_largest(&self) -> bool {
        self.about_largest
    }

    /// ω at time `t`, body frame, in the axes' original order (rad/s).
    pub fn omega(&self, t: Real) -> Vec3 {
        let (sn, cn, dn) = jacobi_complement(self.u0 + self.lambda * t, self.m, self.m1);
        let [a1, a2, a3] = self.amplitude;
        let sorted = if self.about_largest {
            [a1 * cn, a2 * sn, a3 * dn]
        } else {
            [a1 * dn, a2 * sn, a3 * cn]
        };
        let mut w = Vec3::zeros();
        for (k, &axis) in self.order.iter().enumerate() {
            w[axis] = self.parity * sorted[k];
        }
        w
    }
}
