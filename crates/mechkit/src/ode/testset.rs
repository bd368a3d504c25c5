//! Problems of the standard ODE test sets (Hairer & Wanner, *Solving ODEs I and II*; Mazzia &
//! Magherini, *Test Set for IVP Solvers*), each with its exact Jacobian and its reference
//! solution as published: what the implicit methods are validated and benchmarked on (the
//! tests, `cargo bench -p mechkit --bench stiff`). The non-stiff classics are in
//! [`super::reference`].

use super::{OdeSystem, SecondOrderSystem};
use crate::Real;

/// Van der Pol's oscillator `x'' = μ (1 − x²) x' − x`, μ = 1000, from (2, 0).
#[derive(Debug, Clone, Copy)]
pub struct VanDerPol {
    /// The damping parameter μ.
    pub mu: Real,
}

impl SecondOrderSystem for VanDerPol {
    fn dof(&self) -> usize {
        1
    }
    fn accel_into(&self, _t: Real, q: &[Real], v: &[Real], a: &mut [Real]) {
        a[0] = self.mu * (1.0 - q[0] * q[0]) * v[0] - q[0];
    }
    fn accel_jacobian_into(
        &self,
        _t: Real,
        q: &[Real],
        v: &[Real],
        da_dq: &mut [Real],
        da_dv: &mut [Real],
    ) -> bool {
        da_dq[0] = -2.0 * self.mu * q[0] * v[0] - 1.0;
        da_dv[0] = self.mu * (1.0 - q[0] * q[0]);
        true
    }
}

/// Robertson's chemical kinetics (Hairer & Wanner II, Sec. IV.1); reference at t = 40 from
/// there (computed with RADAU5 at tolerance 1e-14).
#[derive(Debug, Clone, Copy)]
pub struct Robertson;

impl Robertson {
    /// `y(40)`.
    pub const REFERENCE_40: [Real; 3] = [
        0.715_827_068_719_397_4,
        9.185_534_764_557_192e-6,
        0.284_163_745_745_128,
    ];
}

impl OdeSystem for Robertson {
    fn dim(&self) -> usize {
        3
    }
    fn rhs_into(&self, _t: Real, y: &[Real], d: &mut [Real]) {
        d[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        d[2] = 3e7 * y[1] * y[1];
        d[1] = -d[0] - d[2];
    }
    fn jacobian_into(&self, _t: Real, y: &[Real], j: &mut [Real]) -> bool {
        j.copy_from_slice(&[
            -0.04,
            1e4 * y[2],
            1e4 * y[1],
            0.04,
            -1e4 * y[2] - 6e7 * y[1],
            -1e4 * y[1],
            0.0,
            6e7 * y[1],
            0.0,
        ]);
        true
    }
}

/// HIRES: eight reactions of plant physiology (Schäfer 1975; Hairer & Wanner II, Sec. IV.10),
/// from t = 0 to 321.8122; reference from the IVP test set (Mazzia & Magherini).
#[derive(Debug, Clone, Copy)]
pub struct Hires;

impl Hires {
    /// The end of the interval.
    pub const T_END: Real = 321.8122;
    /// `y(0)`.
    pub const INITIAL: [Real; 8] = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0057];
    /// `y(T_END)`.
    pub const REFERENCE: [Real; 8] = [
        0.737_131_257_332_566_8e-3,
        0.144_248_572_631_618_5e-3,
        0.588_872_974_096_757_5e-4,
        0.117_565_134_328_314_9e-2,
        0.238_635_619_883_133_1e-2,
        0.623_896_825_274_279_6e-2,
        0.284_999_839_518_576_9e-2,
        0.285_000_160_481_423_1e-2,
    ];
}

impl OdeSystem for Hires {
    fn dim(&self) -> usize {
        8
    }
    fn rhs_into(&self, _t: Real, y: &[Real], d: &mut [Real]) {
        d[0] = -1.71 * y[0] + 0.43 * y[1] + 8.32 * y[2] + 0.0007;
        d[1] = 1.71 * y[0] - 8.75 * y[1];
        d[2] = -10.03 * y[2] + 0.43 * y[3] + 0.035 * y[4];
        d[3] = 8.32 * y[1] + 1.71 * y[2] - 1.12 * y[3];
        d[4] = -1.745 * y[4] + 0.43 * y[5] + 0.43 * y[6];
        d[5] = -280.0 * y[5] * y[7] + 0.69 * y[3] + 1.71 * y[4] - 0.43 * y[5] + 0.69 * y[6];
        d[6] = 280.0 * y[5] * y[7] - 1.81 * y[6];
        d[7] = -d[6];
    }
    fn jacobian_into(&self, _t: Real, y: &[Real], j: &mut [Real]) -> bool {
        j.fill(0.0);
        let mut set = |r: usize, c: usize, v: Real| j[r * 8 + c] = v;
        set(0, 0, -1.71);
        set(0, 1, 0.43);
        set(0, 2, 8.32);
        set(1, 0, 1.71);
        set(1, 1, -8.75);
        set(2, 2, -10.03);
        set(2, 3, 0.43);
        set(2, 4, 0.035);
        set(3, 1, 8.32);
        set(3, 2, 1.71);
        set(3, 3, -1.12);
        set(4, 4, -1.745);
        set(4, 5, 0.43);
        set(4, 6, 0.43);
        set(5, 3, 0.69);
        set(5, 4, 1.71);
        set(5, 5, -280.0 * y[7] - 0.43);
        set(5, 6, 0.69);
        set(5, 7, -280.0 * y[5]);
        set(6, 5, 280.0 * y[7]);
        set(6, 6, -1.81);
        set(6, 7, 280.0 * y[5]);
        set(7, 5, -280.0 * y[7]);
        set(7, 6, 1.81);
        set(7, 7, -280.0 * y[5]);
        true
    }
}

/// The Pleiades: seven stars in a plane, masses 1 to 7, G = 1 (Hairer, Nørsett & Wanner I,
/// Sec. II.10), from t = 0 to 3; reference positions from there.
#[derive(Debug, Clone, Copy)]
pub struct Pleiades;

impl Pleiades {
    /// `[x (7), y (7), vx (7), vy (7)]`.
    pub fn initial() -> Vec<Real> {
        let x = [3.0, 3.0, -1.0, -3.0, 2.0, -2.0, 2.0];
        let y = [3.0, -3.0, 2.0, 0.0, 0.0, -4.0, 4.0];
        let vx = [0.0, 0.0, 0.0, 0.0, 0.0, 1.75, -1.5];
        let vy = [0.0, 0.0, 0.0, -1.25, 1.0, 0.0, 0.0];
        [x, y, vx, vy].concat()
    }

    /// Positions at t = 3: `[x (7), y (7)]`.
    pub const REFERENCE: [Real; 14] = [
        0.370_613_914_397_050_2,
        3.237_284_092_057_233,
        -3.222_559_032_418_324,
        0.659_709_145_577_531,
        0.342_558_170_715_658_4,
        1.562_172_101_400_631,
        -0.700_309_292_221_249_5,
        -3.943_437_585_517_392,
        -3.271_380_973_972_55,
        5.225_081_843_456_543,
        -2.590_612_434_977_47,
        1.198_213_693_392_275,
        -0.242_968_234_493_582_4,
        1.091_449_240_428_98,
    ];
}

impl SecondOrderSystem for Pleiades {
    fn dof(&self) -> usize {
        14
    }
    fn accel_into(&self, _t: Real, q: &[Real], _v: &[Real], a: &mut [Real]) {
        a.fill(0.0);
        for i in 0..7 {
            for j in 0..7 {
                if i == j {
                    continue;
                }
                let (dx, dy) = (q[j] - q[i], q[7 + j] - q[7 + i]);
                let r2 = dx * dx + dy * dy;
                let w = (j + 1) as Real / (r2 * r2.sqrt());
                a[i] += w * dx;
                a[7 + i] += w * dy;
            }
        }
    }
    fn velocity_dependent(&self) -> bool {
        false
    }
    /// `∂aᵢ/∂rⱼ = mⱼ (I − 3 d̂ d̂ᵀ) / r³` for `d = rⱼ − rᵢ`, and `∂aᵢ/∂rᵢ` minus their sum.
    fn accel_jacobian_into(
        &self,
        _t: Real,
        q: &[Real],
        _v: &[Real],
        da_dq: &mut [Real],
        da_dv: &mut [Real],
    ) -> bool {
        da_dq.fill(0.0);
        da_dv.fill(0.0);
        let n = 14;
        for i in 0..7 {
            for j in (0..7).filter(|&j| j != i) {
                let (dx, dy) = (q[j] - q[i], q[7 + j] - q[7 + i]);
                let r2 = dx * dx + dy * dy;
                let w = (j + 1) as Real / (r2 * r2.sqrt());
                let (kxx, kxy, kyy) = (
                    w * (1.0 - 3.0 * dx * dx / r2),
                    -3.0 * w * dx * dy / r2,
                    w * (1.0 - 3.0 * dy * dy / r2),
                );
                for (row, col, k) in [
                    (i, j, kxx),
                    (i, 7 + j, kxy),
                    (7 + i, j, kxy),
                    (7 + i, 7 + j, kyy),
                ] {
                    da_dq[row * n + col] += k;
                    // the same pull on rᵢ's own coordinates, the other way
                    da_dq[row * n + col - j + i] -= k;
                }
            }
        }
        true
    }
}

/// A chain of `n` unit masses joined by stiff damped springs (k, c), the first tied to a wall,
/// the last pulled by a constant force: the stiff modes die out in microseconds, the slow
/// ones set the steps.
#[derive(Debug, Clone, Copy)]
pub struct SpringChain {
    /// Number of masses (1 kg each).
    pub n: usize,
    /// Stiffness of each spring (N/m).
    pub k: Real,
    /// Damping of each spring (N·s/m).
    pub c: Real,
    /// The constant force on the last mass (N).
    pub pull: Real,
}

impl SecondOrderSystem for SpringChain {
    fn dof(&self) -> usize {
        self.n
    }
    fn accel_into(&self, _t: Real, q: &[Real], v: &[Real], a: &mut [Real]) {
        let n = self.n;
        for i in 0..n {
            let (ql, vl) = if i == 0 {
                (0.0, 0.0)
            } else {
                (q[i - 1], v[i - 1])
            };
            let mut f = -self.k * (q[i] - ql) - self.c * (v[i] - vl);
            if i + 1 < n {
                f += self.k * (q[i + 1] - q[i]) + self.c * (v[i + 1] - v[i]);
            } else {
                f += self.pull;
            }
            a[i] = f;
        }
    }
    fn accel_jacobian_into(
        &self,
        _t: Real,
        _q: &[Real],
        _v: &[Real],
        da_dq: &mut [Real],
        da_dv: &mut [Real],
    ) -> bool {
        let n = self.n;
        da_dq.fill(0.0);
        da_dv.fill(0.0);
        for i in 0..n {
            let last = i + 1 == n;
            da_dq[i * n + i] = if last { -self.k } else { -2.0 * self.k };
            da_dv[i * n + i] = if last { -self.c } else { -2.0 * self.c };
            if i > 0 {
                da_dq[i * n + i - 1] = self.k;
                da_dv[i * n + i - 1] = self.c;
            }
            if !last {
                da_dq[i * n + i + 1] = self.k;
                da_dv[i * n + i + 1] = self.c;
            }
        }
        true
    }
    /// Each mass pulled by its two neighbours: a tridiagonal coupling.
    fn accel_pattern(&self) -> Option<super::JacobianPattern> {
        let n = self.n;
        let mut p = super::JacobianPattern::new(n);
        for i in 0..n {
            for j in i.saturating_sub(1)..(i + 2).min(n) {
                p.insert(i, j);
            }
        }
        Some(p)
    }
}
